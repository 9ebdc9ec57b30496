//! The scenes of the board firmwares: a lit torus spinning on a 240x240 colour display, drawn
//! in bands of one prepared frame, and a flat-shaded torus dithered to one bit on a 128x64
//! display. Also compiled into the host's tests (`tests/firmware.rs`), which hash the same
//! frames as the `boards` preset of bench/mcu does under QEMU.

use embedded_graphics::pixelcolor::{BinaryColor, IntoStorage, Rgb565, Rgb888, RgbColor};
use fixed3d::buffer::{BufferError, ColorDepth, DepthBuffer, FrameBuffer};
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{torus, torus_counts, Mesh, Object, Triangle};
use fixed3d::pipeline::{Bin, Cull, Frame, ScreenVertex};
use fixed3d::projection::Viewport;
use fixed3d::render::{Model, PreparedFrame, RenderError};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::Flat;
use fixed3d::{Camera, Light};

/// The colour display's width and height (an ST7789 240x240 module).
pub const LCD_SIZE: u32 = 240;
/// Rows of the colour display a band holds: its buffers are a sixteenth of the frame's.
pub const LCD_BAND_ROWS: u32 = 16;
/// Cells of a band's colour and depth buffers.
pub const LCD_BAND_CELLS: usize = (LCD_SIZE * LCD_BAND_ROWS) as usize;
/// Bands in a frame of the colour display.
pub const LCD_BANDS: u32 = LCD_SIZE.div_ceil(LCD_BAND_ROWS);

/// The colour display's torus: rings around and around the tube.
pub const TORUS_RING: u16 = 32;
/// See [`TORUS_RING`].
pub const TORUS_TUBE: u16 = 16;
/// Vertices of the colour display's torus.
pub const TORUS_VERTICES: usize = torus_counts(TORUS_RING, TORUS_TUBE).0;
/// Triangles of the colour display's torus.
pub const TORUS_TRIANGLES: usize = torus_counts(TORUS_RING, TORUS_TUBE).1;
/// Bins for the colour display's frames: the triangles that can face the camera at once
/// (about half of a closed mesh's), with room to spare.
pub const LCD_BINS: usize = TORUS_TRIANGLES / 2 + 64;

/// The one-bit display's width (an SSD1306 module).
pub const OLED_WIDTH: u32 = 128;
/// The one-bit display's height.
pub const OLED_HEIGHT: u32 = 64;
/// Cells of the one-bit frame's buffers.
pub const OLED_CELLS: usize = (OLED_WIDTH * OLED_HEIGHT) as usize;
/// The one-bit display's torus: a coarser one (the STM32F411 has 128 KiB of RAM).
pub const SMALL_RING: u16 = 20;
/// See [`SMALL_RING`].
pub const SMALL_TUBE: u16 = 10;
/// Vertices of the one-bit display's torus.
pub const SMALL_VERTICES: usize = torus_counts(SMALL_RING, SMALL_TUBE).0;
/// Triangles of the one-bit display's torus.
pub const SMALL_TRIANGLES: usize = torus_counts(SMALL_RING, SMALL_TUBE).1;

/// A torus of `ring` x `tube` quads (radii 1 and 0.4) into the given storage; empty if the
/// storage does not fit it.
pub fn torus_mesh<'a>(
    ring: u16,
    tube: u16,
    positions: &'a mut [Vec3],
    normals: &'a mut [Vec3],
    triangles: &'a mut [Triangle],
) -> Mesh<'a> {
    let minor = Scalar::from_num(2) / Scalar::from_num(5);
    torus(
        Scalar::ONE,
        minor,
        ring,
        tube,
        positions,
        normals,
        triangles,
    )
    .unwrap_or(Mesh::EMPTY)
}

/// The torus turned for frame `frame`: three degrees a frame about y, tilted 20 about x.
pub fn spinning(frame: u32) -> Mat4 {
    let degrees = (frame % 120) as i32 * 3;
    Mat4::rotation_y(Angle::from_degrees(degrees)) * Mat4::rotation_x(Angle::from_degrees(20))
}

/// Where the colour display's camera stands, above and in front of the torus.
pub const LCD_EYE: [i32; 3] = [0, 2, 5];
/// Where the one-bit display's camera stands: nearer, for its 64 rows.
pub const OLED_EYE: [i32; 3] = [0, 1, 3];

/// A camera of 50 degrees at `eye`, looking at the torus.
pub fn camera(eye: [i32; 3]) -> Camera {
    Camera::perspective(50, 1, 10).looking_at(eye, [0, 0, 0])
}

/// The colour display's models for frame `frame`: the torus, orange.
pub fn lcd_models<'a>(mesh: &'a Mesh<'a>, frame: u32) -> [Model<'a>; 1] {
    [Model::new(mesh, Rgb888::new(255, 140, 40)).with_matrix(spinning(frame))]
}

/// Runs the vertex stage of the colour display's `models` and bins their triangles: any band
/// of the frame can then be drawn by [`draw_lcd_band`], on either core.
pub fn prepare_lcd<'f>(
    models: &'f [Model<'f>],
    vertices: &'f mut [ScreenVertex],
    bins: &'f mut [Bin],
) -> Result<PreparedFrame<'f>, RenderError<core::convert::Infallible>> {
    let lights = [
        Light::ambient(Scalar::from_num(1) / Scalar::from_num(5)),
        Light::directional(
            Vec3::from_int(-1, 1, 1),
            Scalar::from_num(4) / Scalar::from_num(5),
        ),
    ];
    let camera = camera(LCD_EYE);
    let viewport = Viewport::new(LCD_SIZE, LCD_SIZE).map_err(RenderError::Viewport)?;
    PreparedFrame::new(
        models,
        &lights,
        &camera,
        viewport,
        Cull::Back,
        vertices,
        bins,
    )
}

/// Draws band `band` of `frame` into `color` and `depth` ([`LCD_BAND_ROWS`] rows from row
/// `band · LCD_BAND_ROWS`; each buffer holds that many rows of [`LCD_SIZE`]), clearing them
/// first (black, the far depth) unless `clean` says they hold nothing else, as after a band
/// that drew nothing. Returns whether they still do: true when this band drew nothing. The
/// clears are the library's buffers' own, which take fewer instructions on a Cortex-M than
/// `slice::fill` (a call to `memset` for black and the far depth).
pub fn draw_lcd_band(
    frame: &PreparedFrame<'_>,
    band: u32,
    color: &mut [Rgb565],
    depth: &mut [u16],
    clean: bool,
) -> Result<bool, BufferError> {
    if !clean {
        FrameBuffer::new(&mut *color, LCD_SIZE, LCD_BAND_ROWS)?.fill(Rgb565::BLACK);
        DepthBuffer::new(&mut *depth, LCD_SIZE, LCD_BAND_ROWS)?.clear();
    }
    let drawn = frame.draw_band(band.saturating_mul(LCD_BAND_ROWS), color, depth)?;
    Ok(drawn.drawn == 0)
}

/// Draws every band of `frame` in order through one set of buffers, and hands each band's
/// bytes (see [`lcd_bytes`]) to `send`: the whole frame on one core.
pub fn send_lcd_frame(
    frame: &PreparedFrame<'_>,
    color: &mut [Rgb565],
    depth: &mut [u16],
    bytes: &mut [u8],
    mut send: impl FnMut(&[u8]),
) -> Result<(), BufferError> {
    let mut clean = false;
    for band in 0..LCD_BANDS {
        clean = draw_lcd_band(frame, band, color, depth, clean)?;
        lcd_bytes(color, bytes);
        send(bytes);
    }
    Ok(())
}

/// The band's pixels as an ST7789 takes them over SPI: two bytes each, high byte first.
/// `out` holds two bytes a cell of `color` (extra bytes are left as they are).
pub fn lcd_bytes(color: &[Rgb565], out: &mut [u8]) {
    for (bytes, c) in out.chunks_exact_mut(2).zip(color) {
        bytes.copy_from_slice(&c.into_storage().to_be_bytes());
    }
}

/// Draws frame `frame` of the one-bit display: the small torus lit flat by one light, each
/// face's grey dithered (4x4 ordered dither) into `pixels`, depth-tested in `depth`.
pub fn draw_oled(
    mesh: &Mesh<'_>,
    frame: u32,
    vertices: &mut [ScreenVertex],
    pixels: &mut [BinaryColor],
    depth: &mut [u16],
) -> Option<()> {
    let objects = [Object::new(mesh, spinning(frame), Rgb888::WHITE)];
    let mut lighting =
        Lighting::<1>::new(LightColor::gray(Scalar::from_num(1) / Scalar::from_num(10)));
    lighting
        .push(DirectionalLight::new(
            Vec3::from_int(-1, 1, 1),
            LightColor::gray(Scalar::from_num(9) / Scalar::from_num(10)),
        ))
        .ok()?;
    let scene = Scene::new(&objects, lighting);
    let camera = camera(OLED_EYE);
    let viewport = Viewport::new(OLED_WIDTH, OLED_HEIGHT).ok()?;
    let (view, projection) = (camera.view().ok()?, camera.projection(&viewport).ok()?);
    let prepared = Frame::new(&view, &projection, viewport)
        .prepare(&scene, vertices, Flat)
        .ok()?;
    let mut color = FrameBuffer::new(pixels, OLED_WIDTH, OLED_HEIGHT).ok()?;
    let mut depth = DepthBuffer::new(depth, OLED_WIDTH, OLED_HEIGHT).ok()?;
    color.fill(BinaryColor::Off);
    depth.clear();
    let mut target = ColorDepth::new(&mut color, &mut depth)
        .ok()?
        .dithered()
        .uncounted();
    prepared.draw(&mut target).ok().map(|_| ())
}

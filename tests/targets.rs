//! Targets: direct filling of any DrawTarget with one call per span, presenting a framebuffer in
//! one `fill_contiguous`, and ordered dithering on one-bit displays.

mod common;

use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use fixed3d::buffer::{ColorDepth, DepthBuffer, Direct, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Scalar, Vec3};
use fixed3d::mesh::{uv_sphere, Mesh, Object, Transform, CUBE};
use fixed3d::pipeline::{Frame, ScreenVertex};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::{Flat, Gouraud};

/// Records how a target was called.
#[derive(Default)]
struct Calls {
    draw_iter: u32,
    fill_solid: u32,
    fill_contiguous: u32,
    pixels: u32,
}

struct Recorder(Calls);

impl OriginDimensions for Recorder {
    fn size(&self) -> Size {
        Size::new(96, 64)
    }
}

impl DrawTarget for Recorder {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        p: I,
    ) -> Result<(), Self::Error> {
        self.0.draw_iter += 1;
        self.0.pixels += p.into_iter().count() as u32;
        Ok(())
    }
    fn fill_solid(&mut self, area: &Rectangle, _: Rgb565) -> Result<(), Self::Error> {
        self.0.fill_solid += 1;
        self.0.pixels += area.size.width * area.size.height;
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        c: I,
    ) -> Result<(), Self::Error> {
        self.0.fill_contiguous += 1;
        assert_eq!(
            c.into_iter().count() as u32,
            area.size.width * area.size.height
        );
        self.0.pixels += area.size.width * area.size.height;
        Ok(())
    }
}

fn frame(w: u32, h: u32) -> Frame {
    let viewport = Viewport::new(w, h).unwrap();
    let view = LookAt::new(Vec3::from_int(3, 2, 4), Vec3::ZERO, Vec3::Y)
        .view()
        .unwrap();
    let p = Projection::perspective(
        Angle::from_degrees(50),
        viewport.aspect(),
        Scalar::from_num(1),
        Scalar::from_num(20),
    )
    .unwrap();
    Frame::new(&view, &p, viewport)
}

fn lighting() -> Lighting<1> {
    let mut l = Lighting::new(LightColor::gray(Scalar::from_num(0.1)));
    l.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(Scalar::from_num(0.9)),
    ))
    .unwrap();
    l
}

/// Storage for a UV sphere of radius 1.6 (32 x 16).
struct Sphere {
    p: Vec<Vec3>,
    n: Vec<Vec3>,
    t: Vec<[u16; 3]>,
}

impl Sphere {
    fn new() -> Self {
        Sphere {
            p: vec![Vec3::ZERO; 1000],
            n: vec![Vec3::ZERO; 1000],
            t: vec![[0u16; 3]; 2000],
        }
    }

    fn mesh(&mut self) -> Mesh<'_> {
        let (p, n, t) = (&mut self.p, &mut self.n, &mut self.t);
        uv_sphere(Scalar::from_num(1.6), 32, 16, p, n, t).unwrap()
    }
}

/// Depth-less flat filling sends each span as one `fill_solid`, never pixel by pixel.
#[test]
fn direct_flat_fill_is_one_fill_solid_per_span() {
    let objects = [Object::new(
        &CUBE,
        Transform::new().matrix(),
        Rgb888::new(200, 100, 50),
    )];
    let scene = Scene::new(&objects, lighting());
    let mut cache = [ScreenVertex::DEFAULT; 8];
    let prepared = frame(96, 64).prepare(&scene, &mut cache, Flat).unwrap();
    let mut rec = Recorder(Calls::default());
    let stats = prepared.draw(&mut Direct::new(&mut rec)).unwrap();
    let c = rec.0;
    assert_eq!((c.draw_iter, c.fill_contiguous), (0, 0));
    assert!(c.fill_solid > 20);
    assert_eq!(c.pixels, stats.written);
    // Gouraud without depth: one fill_contiguous per span.
    let mut rec = Recorder(Calls::default());
    let mut cache = [ScreenVertex::DEFAULT; 8];
    frame(96, 64)
        .prepare(&scene, &mut cache, Gouraud)
        .unwrap()
        .draw(&mut Direct::new(&mut rec))
        .unwrap();
    // The cube has no normals: Gouraud falls back to flat spans.
    assert!(rec.0.fill_solid > 20 && rec.0.draw_iter == 0);
}

/// A framebuffer presents itself in a single `fill_contiguous` (and a band at its offset).
#[test]
fn present_is_one_fill_contiguous() {
    let mut px = [Rgb565::RED; 96 * 16];
    let fb = FrameBuffer::new(&mut px, 96, 16).unwrap();
    let mut rec = Recorder(Calls::default());
    fb.present_at(&mut rec, Point::new(0, 48)).unwrap();
    assert_eq!(
        (rec.0.fill_contiguous, rec.0.draw_iter, rec.0.pixels),
        (1, 0, 96 * 16)
    );
}

/// Ordered dithering on a one-bit display: the share of lit pixels follows the Lambert
/// intensity, so shading stays visible (without dithering, a threshold turns it into two flat
/// regions).
#[test]
fn dithered_gouraud_on_one_bit_display() {
    let mut sphere = Sphere::new();
    let mesh = sphere.mesh();
    let objects = [Object::new(&mesh, Transform::new().matrix(), Rgb888::WHITE)];
    let scene = Scene::new(&objects, lighting());
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let prepared = frame(128, 64).prepare(&scene, &mut cache, Gouraud).unwrap();
    let render = |dither: bool| {
        let (mut c, mut d) = (vec![BinaryColor::Off; 128 * 64], vec![0u16; 128 * 64]);
        let mut color = FrameBuffer::new(&mut c, 128, 64).unwrap();
        let mut depth = DepthBuffer::new(&mut d, 128, 64).unwrap();
        depth.clear();
        let t = ColorDepth::new(&mut color, &mut depth).unwrap();
        if dither {
            prepared.draw(&mut t.dithered()).unwrap();
        } else {
            prepared.draw(&mut { t }).unwrap();
        }
        c
    };
    let (plain, dithered) = (render(false), render(true));
    // Lit share per 8x8 block inside the disc: the dithered image has intermediate densities.
    let share = |img: &[BinaryColor], bx: usize, by: usize| {
        (0..8)
            .flat_map(|y| (0..8).map(move |x| (x, y)))
            .filter(|&(x, y)| img[(by * 8 + y) * 128 + bx * 8 + x].is_on())
            .count()
    };
    let blocks: Vec<(usize, usize)> = (0..16)
        .flat_map(|bx| (0..8).map(move |by| (bx, by)))
        .collect();
    let intermediate = |img: &[BinaryColor]| {
        blocks
            .iter()
            .filter(|&&(bx, by)| (8..=56).contains(&share(img, bx, by)))
            .count()
    };
    assert!(
        intermediate(&dithered) > intermediate(&plain) + 5,
        "{} vs {}",
        intermediate(&dithered),
        intermediate(&plain)
    );
    // The lit side (towards the light, upper left) is denser than the dark side.
    let lit: usize = (0..64)
        .flat_map(|y| (0..64).map(move |x| (x, y)))
        .filter(|&(x, y)| dithered[y * 128 + x].is_on())
        .count();
    let dark: usize = (0..64)
        .flat_map(|y| (64..128).map(move |x| (x, y)))
        .filter(|&(x, y)| dithered[y * 128 + x].is_on())
        .count();
    assert!(lit > dark, "{lit} vs {dark}");
}

/// Smooth shading into a colour of channels (RGB565, BGR565) rounds each channel once,
/// straight to the colour's depth: every channel is a rounding of a value the 24-bit image of
/// the same frame allows (its 8-bit channel, give or take half a step, and the vertex
/// channels' scaling to the depth, within 2/64 of a step), the channels land in their places
/// in both layouts, and some pixels differ from converting the 24-bit image (which rounds
/// twice), none by more than one step.
#[test]
fn gouraud_into_rgb565_rounds_each_channel_once() {
    let mut sphere = Sphere::new();
    let mesh = sphere.mesh();
    let color = Rgb888::new(255, 200, 120);
    let objects = [Object::new(&mesh, Transform::new().matrix(), color)];
    let scene = Scene::new(&objects, lighting());
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let (w, h) = (128u32, 96u32);
    let prepared = frame(w, h).prepare(&scene, &mut cache, Gouraud).unwrap();
    fn render<C: fixed3d::buffer::TargetColor>(
        prepared: &fixed3d::pipeline::Prepared<'_, '_, 1, Gouraud>,
        background: C,
        (w, h): (u32, u32),
    ) -> Vec<C> {
        let cells = (w * h) as usize;
        let (mut c, mut d) = (vec![background; cells], vec![0u16; cells]);
        let mut color = FrameBuffer::new(&mut c, w, h).unwrap();
        let mut depth = DepthBuffer::new(&mut d, w, h).unwrap();
        depth.clear();
        prepared
            .draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
            .unwrap();
        c
    }
    use embedded_graphics::pixelcolor::Bgr565;
    let wide = render(&prepared, Rgb888::new(0, 0, 1), (w, h));
    let rgb = render(&prepared, Rgb565::new(0, 0, 1), (w, h));
    let bgr = render(&prepared, Bgr565::new(0, 0, 1), (w, h));
    let (mut covered, mut differ) = (0, 0);
    for ((&c8, &c), &b) in wide.iter().zip(&rgb).zip(&bgr) {
        if c8 == Rgb888::new(0, 0, 1) {
            continue;
        }
        covered += 1;
        assert_eq!([c.r(), c.g(), c.b()], [b.r(), b.g(), b.b()]);
        let allowed = |v: u8, max: u8, got: u8| {
            let scaling = 2.0 / 64.0;
            let lo = ((v as f64 - 0.5) * max as f64 / 255.0 - scaling + 0.5).floor();
            let hi = ((v as f64 + 0.5) * max as f64 / 255.0 + scaling + 0.5).floor();
            (lo..=hi).contains(&(got as f64))
        };
        assert!(allowed(c8.r(), 31, c.r()), "{c8:?} {c:?}");
        assert!(allowed(c8.g(), 63, c.g()), "{c8:?} {c:?}");
        assert!(allowed(c8.b(), 31, c.b()), "{c8:?} {c:?}");
        let twice = Rgb565::from(c8);
        let steps = [
            c.r().abs_diff(twice.r()),
            c.g().abs_diff(twice.g()),
            c.b().abs_diff(twice.b()),
        ];
        assert!(steps.iter().all(|&s| s <= 1), "{c8:?} {c:?}");
        differ += usize::from(steps.iter().any(|&s| s != 0));
    }
    assert!(covered > 3000 && differ > 0, "{covered} {differ}");
}

/// A framebuffer's `fill_solid` fills exactly the area's pixels inside the buffer, as pixel by
/// pixel drawing would: areas inside, across every side, outside, empty, and reaching to the
/// ends of the coordinate range (cut there, without overflow).
#[test]
fn framebuffer_fill_solid_fills_the_area_inside_the_buffer() {
    let (w, h) = (24u32, 16u32);
    let mut rng = 0x2545_F491u32;
    let mut next = move |n: u32| {
        rng ^= rng << 13;
        rng ^= rng >> 17;
        rng ^= rng << 5;
        rng % n
    };
    let mut areas: Vec<Rectangle> = (0..2000)
        .map(|_| {
            let at = Point::new(next(60) as i32 - 20, next(50) as i32 - 20);
            Rectangle::new(at, Size::new(next(45), next(35)))
        })
        .collect();
    areas.extend([
        Rectangle::new(
            Point::new(i32::MIN, i32::MIN),
            Size::new(u32::MAX, u32::MAX),
        ),
        Rectangle::new(Point::new(-3, 5), Size::new(u32::MAX, 2)),
        Rectangle::new(Point::new(5, -7), Size::new(3, u32::MAX)),
        Rectangle::new(Point::new(i32::MAX, 2), Size::new(u32::MAX, 4)),
        Rectangle::new(Point::new(2, 2), Size::new(0, 9)),
    ]);
    for area in areas {
        let mut cells = vec![Rgb565::BLACK; (w * h) as usize];
        let mut fb = FrameBuffer::new(&mut cells, w, h).unwrap();
        fb.fill_solid(&area, Rgb565::RED).unwrap();
        let (x0, y0) = (i64::from(area.top_left.x), i64::from(area.top_left.y));
        let (x1, y1) = (
            x0 + i64::from(area.size.width),
            y0 + i64::from(area.size.height),
        );
        for y in 0..h as i64 {
            for x in 0..w as i64 {
                let inside = (x0..x1).contains(&x) && (y0..y1).contains(&y);
                let expected = if inside { Rgb565::RED } else { Rgb565::BLACK };
                assert_eq!(
                    cells[(y * w as i64 + x) as usize],
                    expected,
                    "{area:?} ({x}, {y})"
                );
            }
        }
    }
}

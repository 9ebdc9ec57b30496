//! A model in flash: Suzanne is parsed from `include_bytes!` by the compiler (a `const fn`), so
//! the firmware holds only the arrays and does no parsing at run time. Its vertex normals are
//! computed once at start-up (area-weighted), then it is drawn with Gouraud shading.
//!
//! ```text
//! cargo run --release --example flash_model -- [OUT.png]
//! ```
//!
//! Without an argument the PNG goes to `target/flash_model.png` in the checkout.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};
use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
use fixed3d::camera::Framing;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{vertex_normals, Object};
use fixed3d::obj::StaticObj;
use fixed3d::pipeline::{Frame, ScreenVertex};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::Gouraud;

/// Parsed at compile time; an invalid file is a build error.
static SUZANNE: StaticObj<507, 968> =
    match StaticObj::parse(include_bytes!("../models/suzanne.obj")) {
        Ok(m) => m,
        Err(_) => panic!("models/suzanne.obj does not parse"),
    };

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| concat!(env!("CARGO_MANIFEST_DIR"), "/target/flash_model.png").into());
    let counts = SUZANNE.counts();
    let mut normals = [Vec3::ZERO; 507];
    vertex_normals(
        SUZANNE.mesh().positions(),
        SUZANNE.mesh().triangles(),
        &mut normals,
    )?;
    let mesh = SUZANNE.mesh().with_normals(&normals)?;

    let viewport = Viewport::new(240, 240)?;
    let b = counts.bounds;
    let fov = Angle::from_degrees(50);
    // The file is y-up with Suzanne facing +z: view her from the front, a little above.
    let framing = Framing::of_box(
        b.min,
        b.max,
        Vec3::from_int(0, 1, 3),
        fov,
        viewport.aspect(),
    )?;
    let projection = Projection::perspective(fov, viewport.aspect(), framing.near, framing.far)?;
    let frame = Frame::new(&framing.look_at.view()?, &projection, viewport);

    let objects = [Object::new(
        &mesh,
        Mat4::IDENTITY,
        Rgb888::new(230, 200, 120),
    )];
    let mut lighting = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.15)));
    lighting.push(DirectionalLight::new(
        Vec3::from_int(-1, 2, 2),
        LightColor::gray(Scalar::from_num(0.75)),
    ))?;
    lighting.push(DirectionalLight::new(
        Vec3::from_int(2, -1, 1),
        LightColor::new(
            Scalar::from_num(0.1),
            Scalar::from_num(0.2),
            Scalar::from_num(0.5),
        ),
    ))?;
    let scene = Scene::new(&objects, lighting);

    let mut cache = [ScreenVertex::DEFAULT; 507];
    let (mut c, mut d) = (vec![Rgb565::BLACK; 240 * 240], vec![0u16; 240 * 240]);
    let mut color = FrameBuffer::new(&mut c, 240, 240)?;
    let mut depth = DepthBuffer::new(&mut d, 240, 240)?;
    depth.clear();
    let started = std::time::Instant::now();
    let stats = frame
        .prepare(&scene, &mut cache, Gouraud)?
        .draw(&mut ColorDepth::new(&mut color, &mut depth)?)?;
    println!(
        "suzanne: {} vertices, {} triangles from flash; rendered in {} us, {} triangles drawn",
        counts.positions,
        counts.triangles,
        started.elapsed().as_micros(),
        stats.drawn
    );
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(240, 240));
    color.present(&mut display)?;
    display
        .to_rgb_output_image(&OutputSettingsBuilder::new().build())
        .save_png(&out)?;
    println!("wrote {out}");
    Ok(())
}

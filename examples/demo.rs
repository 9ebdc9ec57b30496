//! The main demo: renders the reference torus of the benchmarks four ways and writes PNGs:
//! flat Lambert with a 16-bit depth buffer, Gouraud with three coloured lights, a wireframe,
//! and a dithered 128x64 one-bit frame as an SSD1306 would show it.
//!
//! ```text
//! cargo run --release --example demo -- [--out DIR]
//! ```
//!
//! Without `--out` the PNGs go to `target/demo/` in the checkout.
//!
//! Each image goes through a simulated display (embedded-graphics-simulator, headless), the
//! way a firmware presents its framebuffer; the render time of each frame is printed.

use std::time::Instant;

use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics_simulator::{BinaryColorTheme, OutputSettingsBuilder, SimulatorDisplay};
use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{torus, torus_counts, FaceNormal, Object};
use fixed3d::pipeline::{Frame, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::{Flat, Gouraud, Unlit};

const RING: u16 = 48;
const TUBE: u16 = 24;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut out = std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/target/demo"));
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = args.next().ok_or("--out needs a directory")?.into(),
            _ => return Err(format!("unknown argument {a}; usage: demo [--out DIR]").into()),
        }
    }
    std::fs::create_dir_all(&out)?;

    // The torus of docs/reference-scene.md: R = 1, r = 0.4, 48 x 24, turned 20 degrees about x, then 30
    // about y, seen from (0, 0, 2.6).
    let (nv, nt) = torus_counts(RING, TUBE);
    let (mut p, mut n, mut t) = (
        vec![Vec3::ZERO; nv],
        vec![Vec3::ZERO; nv],
        vec![[0u16; 3]; nt],
    );
    let mesh = torus(
        Scalar::ONE,
        Scalar::from_num(0.4),
        RING,
        TUBE,
        &mut p,
        &mut n,
        &mut t,
    )?;
    // Flat shading lights each face from the normal the mesh keeps, found here once.
    let mut faces = vec![FaceNormal::ZERO; nt];
    let mesh = mesh.with_face_normals(&mut faces)?;
    let model =
        Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::rotation_x(Angle::from_degrees(20));
    let objects = [Object::new(&mesh, model, Rgb888::new(255, 160, 64))];

    let view = LookAt::new(Vec3::new(s(0.0), s(0.0), s(2.6)), Vec3::ZERO, Vec3::Y).view()?;
    let mut cache = vec![ScreenVertex::DEFAULT; nv];

    // 1. Flat Lambert from the kept face normals, one white light, u16 depth: the benchmark
    // frame.
    let mut sun = Lighting::<1>::new(LightColor::gray(s(0.2)));
    sun.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(s(0.8)),
    ))?;
    let scene = Scene::new(&objects, sun);
    let viewport = Viewport::new(320, 240)?;
    let frame = Frame::new(
        &view,
        &Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(1.0), s(10.0))?,
        viewport,
    );
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(320, 240));
    let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 240], vec![0u16; 320 * 240]);
    let started = Instant::now();
    let mut color = FrameBuffer::new(&mut c, 320, 240)?;
    let mut depth = DepthBuffer::new(&mut d, 320, 240)?;
    color.fill(Rgb565::BLACK);
    depth.clear();
    let stats = frame
        .prepare(&scene, &mut cache, Flat)?
        .draw(&mut ColorDepth::new(&mut color, &mut depth)?)?;
    report("flat", started, &stats);
    color.present(&mut display)?;
    save(&display, &out.join("demo-flat.png"))?;

    // 2. Gouraud, three coloured lights.
    let mut rgb = Lighting::<3>::new(LightColor::gray(s(0.15)));
    rgb.push(DirectionalLight::new(
        Vec3::from_int(-1, 0, 1),
        LightColor::new(s(0.9), s(0.2), s(0.2)),
    ))?;
    rgb.push(DirectionalLight::new(
        Vec3::from_int(0, 1, 1),
        LightColor::new(s(0.2), s(0.9), s(0.3)),
    ))?;
    rgb.push(DirectionalLight::new(
        Vec3::from_int(1, -1, 1),
        LightColor::new(s(0.2), s(0.3), s(0.9)),
    ))?;
    let white = [Object::new(&mesh, model, Rgb888::WHITE)];
    let scene = Scene::new(&white, rgb);
    let started = Instant::now();
    color.fill(Rgb565::BLACK);
    depth.clear();
    let stats = frame
        .prepare(&scene, &mut cache, Gouraud)?
        .draw(&mut ColorDepth::new(&mut color, &mut depth)?)?;
    report("gouraud", started, &stats);
    color.present(&mut display)?;
    save(&display, &out.join("demo-gouraud.png"))?;

    // 3. Wireframe straight into the display: no framebuffer, no depth, no lighting.
    let scene = Scene::new(&white, Lighting::<0>::new(LightColor::WHITE));
    display.clear(Rgb565::BLACK)?;
    let started = Instant::now();
    let stats = frame
        .prepare(&scene, &mut cache, Unlit)?
        .draw_wireframe(&mut display)?;
    report("wireframe", started, &stats);
    save(&display, &out.join("demo-wire.png"))?;

    // 4. An SSD1306: 128x64, one bit per pixel, Gouraud shading as an ordered dither.
    let mut sun = Lighting::<1>::new(LightColor::gray(s(0.05)));
    sun.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(s(0.95)),
    ))?;
    let scene = Scene::new(&white, sun);
    let small = Viewport::new(128, 64)?;
    let frame = Frame::new(
        &view,
        &Projection::perspective(Angle::from_degrees(60), small.aspect(), s(1.0), s(10.0))?,
        small,
    );
    let (mut c1, mut d1) = (vec![BinaryColor::Off; 128 * 64], vec![0u16; 128 * 64]);
    let mut mono = FrameBuffer::new(&mut c1, 128, 64)?;
    let mut mono_depth = DepthBuffer::new(&mut d1, 128, 64)?;
    mono_depth.clear();
    let started = Instant::now();
    let stats = frame
        .prepare(&scene, &mut cache, Gouraud)?
        .draw(&mut ColorDepth::new(&mut mono, &mut mono_depth)?.dithered())?;
    report("ssd1306", started, &stats);
    let mut oled = SimulatorDisplay::<BinaryColor>::new(Size::new(128, 64));
    mono.present(&mut oled)?;
    let settings = OutputSettingsBuilder::new()
        .scale(2)
        .theme(BinaryColorTheme::OledWhite)
        .build();
    oled.to_rgb_output_image(&settings)
        .save_png(out.join("demo-ssd1306.png"))?;
    println!(
        "wrote demo-flat.png, demo-gouraud.png, demo-wire.png and demo-ssd1306.png to {}",
        out.display()
    );
    Ok(())
}

/// A scalar from a float literal (built once, outside the pipeline).
fn s(v: f64) -> Scalar {
    Scalar::from_num(v)
}

fn report(name: &str, started: Instant, stats: &Stats) {
    let drawn = if name == "wireframe" {
        "lines"
    } else {
        "triangles"
    };
    println!(
        "{name:>9}: rendered in {:>6} us: {} triangles in, {} {drawn} drawn, {} pixels written",
        started.elapsed().as_micros(),
        stats.primitives,
        stats.drawn,
        stats.written
    );
}

fn save(
    display: &SimulatorDisplay<Rgb565>,
    path: &std::path::Path,
) -> Result<(), Box<dyn std::error::Error>> {
    display
        .to_rgb_output_image(&OutputSettingsBuilder::new().build())
        .save_png(path)?;
    Ok(())
}

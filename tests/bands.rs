//! Band rendering: a frame drawn band by band into small buffers equals the frame drawn at
//! once, bit for bit, for the reference torus and for a scene crossing the near plane.

mod common;

use common::scene::*;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{Mesh, Object, Transform, CUBE};
use fixed3d::pipeline::{Cull, Frame, Prepared, ScreenVertex};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::Scene;
use fixed3d::shade::{Flat, Gouraud, Shading};

fn full<const N: usize, S: Shading>(p: &Prepared<'_, '_, N, S>, w: u32, h: u32) -> Vec<Rgb565> {
    let (mut c, mut d) = (
        vec![Rgb565::BLACK; (w * h) as usize],
        vec![u16::MAX; (w * h) as usize],
    );
    let mut color = FrameBuffer::new(&mut c, w, h).unwrap();
    let mut depth = DepthBuffer::new(&mut d, w, h).unwrap();
    p.draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
        .unwrap();
    c
}

/// Renders in bands of `rows` rows through one pair of small buffers, reused for every band,
/// as firmware does (`present_at` stands for sending the band to the display).
fn banded<const N: usize, S: Shading>(
    p: &Prepared<'_, '_, N, S>,
    w: u32,
    h: u32,
    rows: u32,
) -> Vec<Rgb565> {
    let mut out = vec![Rgb565::BLACK; (w * h) as usize];
    let (mut c, mut d) = (
        vec![Rgb565::BLACK; (w * rows) as usize],
        vec![0u16; (w * rows) as usize],
    );
    let mut y0 = 0;
    while y0 < h {
        let n = rows.min(h - y0);
        let mut color = FrameBuffer::new(&mut c, w, n).unwrap();
        let mut depth = DepthBuffer::new(&mut d, w, n).unwrap();
        color.fill(Rgb565::BLACK);
        depth.clear();
        p.draw(&mut ColorDepth::band(&mut color, &mut depth, y0).unwrap())
            .unwrap();
        let start = (y0 * w) as usize;
        out[start..start + (n * w) as usize].copy_from_slice(color.pixels());
        y0 += n;
    }
    out
}

#[test]
fn torus_in_bands_equals_full_frame() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles)
        .unwrap()
        .with_normals(&data.normals)
        .unwrap();
    let objects = [Object::new(&mesh, identity(), BASE)];
    let scene = Scene::new(&objects, lighting());
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let flat = frame().prepare(&scene, &mut cache, Flat).unwrap();
    let reference = full(&flat, 320, 240);
    for rows in [16, 7, 1, 240] {
        assert!(
            banded(&flat, 320, 240, rows) == reference,
            "flat, bands of {rows}"
        );
    }
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let smooth = frame().prepare(&scene, &mut cache, Gouraud).unwrap();
    let reference = full(&smooth, 320, 240);
    assert!(reference.iter().filter(|&&p| p != Rgb565::BLACK).count() > 28_000);
    for rows in [16, 13] {
        assert!(
            banded(&smooth, 320, 240, rows) == reference,
            "gouraud, bands of {rows}"
        );
    }
}

#[test]
fn near_plane_scene_in_bands_equals_full_frame() {
    let viewport = Viewport::new(320, 240).unwrap();
    let s = Scalar::from_num;
    let proj =
        Projection::perspective(Angle::from_degrees(75), viewport.aspect(), s(0.25), s(40.0))
            .unwrap();
    // The camera sits inside a big cube and just outside a small one it nearly touches.
    let view = LookAt::new(
        Vec3::from_f32(0.3, 0.2, 1.2).unwrap(),
        Vec3::from_f32(-0.4, -0.1, -1.0).unwrap(),
        Vec3::Y,
    )
    .view()
    .unwrap();
    let objects = [
        Object::new(
            &CUBE,
            Transform::new().scaled(Vec3::from_int(6, 6, 6)).matrix(),
            Rgb888::new(90, 140, 220),
        ),
        Object::new(
            &CUBE,
            Transform::new()
                .rotated_y(Angle::from_degrees(30))
                .translated(Vec3::from_f32(0.0, 0.0, 0.2).unwrap())
                .matrix(),
            Rgb888::new(240, 200, 60),
        ),
        Object::new(
            &CUBE,
            Mat4::translation(Vec3::from_int(-2, -1, -4)),
            Rgb888::WHITE,
        ),
    ];
    let scene = Scene::new(&objects, lighting());
    let frame = Frame::new(&view, &proj, viewport).with_cull(Cull::None);
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let prepared = frame.prepare(&scene, &mut cache, Flat).unwrap();
    let reference = full(&prepared, 320, 240);
    assert!(
        reference.iter().all(|&p| p != Rgb565::BLACK),
        "the enclosing cube fills the view"
    );
    for rows in [16, 5] {
        assert!(
            banded(&prepared, 320, 240, rows) == reference,
            "bands of {rows}"
        );
    }
}

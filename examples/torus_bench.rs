//! The reference scene of the benchmarks (a tilted torus, 320x240, flat Lambert, u16 depth)
//! rendered N times, for timing and for instruction counts under callgrind (`bench/host.sh`).
//!
//! ```text
//! cargo run --release --example torus_bench -- [N]
//! ```
//!
//! One frame is `clear_buffers` (colour and depth) then `draw_scene` (vertex stage, culling,
//! shading, rasterising); both are `#[inline(never)]` so that a profiler can count them apart.
//! The mesh keeps its face normals (`Mesh::with_face_normals`, found once before the frames)
//! and `Flat` lights each face from them, unless the example is built with
//! `TORUS_BENCH_PER_FRAME_NORMALS` set (see [`PER_FRAME_NORMALS`]).
//! The target counts no fragments (the scene needs no counts) unless the example is built with
//! `TORUS_BENCH_COUNTED` set (see [`COUNTED`]).
//! The same scene is then drawn by the crate's f64 reference renderer, timed side by side.

#[path = "common/reference.rs"]
mod reference;

use std::time::Instant;

use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{torus, torus_counts, FaceNormal, Mesh, Object};
use fixed3d::pipeline::{Frame, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::{Flat, Shading};

const W: u32 = 320;
const H: u32 = 240;

#[inline(never)]
fn clear_buffers(color: &mut [Rgb565], depth: &mut [u16]) {
    color.fill(Rgb565::BLACK);
    depth.fill(u16::MAX);
}

/// Built with `TORUS_BENCH_COUNTED` set in the environment, the frames are drawn into a target
/// that counts fragments and writes (`bench/host.sh` measures what the counts cost); otherwise
/// into one that does not, as the scene needs none. A constant, not a run-time switch: a binary
/// with both targets' code would inline differently.
const COUNTED: bool = option_env!("TORUS_BENCH_COUNTED").is_some();

/// Built with `TORUS_BENCH_PER_FRAME_NORMALS` set, the mesh keeps no face normals and `Flat`
/// finds each face's normal from its positions every frame (`bench/host.sh` measures the
/// difference); otherwise it reads the normals the mesh keeps. The same colours.
const PER_FRAME_NORMALS: bool = option_env!("TORUS_BENCH_PER_FRAME_NORMALS").is_some();

/// One frame's drawing: what docs/reference-scene.md times.
#[inline(never)]
fn draw_scene(
    frame: &Frame,
    scene: &Scene<'_, 1>,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Stats {
    draw_by(Flat, frame, scene, cache, color, depth)
}

/// [`draw_scene`] by one shading type.
#[inline(always)]
fn draw_by<S: Shading>(
    shading: S,
    frame: &Frame,
    scene: &Scene<'_, 1>,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Stats {
    let (Ok(prepared), Ok(mut c), Ok(mut d)) = (
        frame.prepare(scene, cache, shading),
        FrameBuffer::new(color, W, H),
        DepthBuffer::new(depth, W, H),
    ) else {
        return Stats::default();
    };
    let Ok(mut target) = ColorDepth::new(&mut c, &mut d) else {
        return Stats::default();
    };
    let stats = if COUNTED {
        prepared.draw(&mut target)
    } else {
        prepared.draw(&mut target.uncounted())
    };
    stats.unwrap_or_default()
}

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(100)
        .max(1);
    let s = |v: f64| Scalar::from_num(v);
    let (nv, nt) = torus_counts(48, 24);
    let (mut p, mut nrm, mut t) = (
        vec![Vec3::ZERO; nv],
        vec![Vec3::ZERO; nv],
        vec![[0u16; 3]; nt],
    );
    let mesh: Mesh<'_> =
        torus(Scalar::ONE, s(0.4), 48, 24, &mut p, &mut nrm, &mut t).expect("torus");
    let mut faces = vec![FaceNormal::ZERO; nt];
    let mesh = if PER_FRAME_NORMALS {
        mesh
    } else {
        mesh.with_face_normals(&mut faces).expect("face normals")
    };
    let model =
        Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::rotation_x(Angle::from_degrees(20));
    let objects = [Object::new(&mesh, model, Rgb888::new(255, 160, 64))];
    let mut lighting = Lighting::<1>::new(LightColor::gray(s(0.2)));
    lighting
        .push(DirectionalLight::new(
            Vec3::from_int(-1, 1, 1),
            LightColor::gray(s(0.8)),
        ))
        .expect("light");
    let scene = Scene::new(&objects, lighting);
    let viewport = Viewport::new(W, H).expect("viewport");
    let view = LookAt::new(Vec3::new(s(0.0), s(0.0), s(2.6)), Vec3::ZERO, Vec3::Y)
        .view()
        .expect("camera");
    let projection =
        Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(1.0), s(10.0))
            .expect("projection");
    let frame = Frame::new(&view, &projection, viewport);

    let mut cache = vec![ScreenVertex::DEFAULT; nv];
    let mut color = vec![Rgb565::BLACK; (W * H) as usize];
    let mut depth = vec![0u16; (W * H) as usize];
    let mut times = Vec::with_capacity(n);
    let mut stats = Stats::default();
    for _ in 0..n {
        clear_buffers(&mut color, &mut depth);
        let started = Instant::now();
        stats = draw_scene(&frame, &scene, &mut cache, &mut color, &mut depth);
        times.push(started.elapsed());
    }
    times.sort();
    let covered = color.iter().filter(|&&c| c != Rgb565::BLACK).count();
    let fragments = if COUNTED {
        format!(
            ", {} fragments tested, {} written",
            stats.fragments, stats.written
        )
    } else {
        String::from(" (fragments not counted)")
    };
    println!(
        "torus 320x240: {n} frames, median {} us per frame; covered {covered} pixels, {} triangles drawn{fragments}",
        times[n / 2].as_micros(),
        stats.drawn,
    );
    if std::env::var_os("NO_REFERENCE").is_none() {
        reference_side_by_side(&p, &t, model, n.min(20), times[n / 2]);
    }
}

/// The same frame drawn by the f64 reference (same vertices, model matrix applied in f64).
fn reference_side_by_side(
    positions: &[Vec3],
    triangles: &[[u16; 3]],
    model: Mat4,
    n: usize,
    ours: std::time::Duration,
) {
    let m = model.to_bits().map(|r| r.map(|c| c as f64 / 65536.0));
    let world: Vec<[f64; 3]> = positions
        .iter()
        .map(|p| {
            let v = p.to_bits().map(|c| c as f64 / 65536.0);
            [0, 1, 2].map(|i| m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] + m[i][3])
        })
        .collect();
    let tris: Vec<[[f64; 3]; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| world[i as usize]))
        .collect();
    let cam = reference::Camera::new(
        [0.0, 0.0, 2.6],
        [0.0; 3],
        [0.0, 1.0, 0.0],
        60.0,
        1.0,
        10.0,
        W,
        H,
    );
    let mut times = Vec::with_capacity(n);
    let mut covered = 0;
    for _ in 0..n {
        let started = Instant::now();
        let img =
            reference::render_flat(&cam, &tris, [255, 160, 64], 0.2, &[([-1.0, 1.0, 1.0], 0.8)]);
        times.push(started.elapsed());
        covered = img.color.iter().filter(|c| c.is_some()).count();
    }
    times.sort();
    let median = times[n / 2];
    println!(
        "f64 reference, same scene: median {} us per frame ({:.1}x the fixed-point time); covered {covered} pixels",
        median.as_micros(),
        median.as_secs_f64() / ours.as_secs_f64().max(1e-9)
    );
}

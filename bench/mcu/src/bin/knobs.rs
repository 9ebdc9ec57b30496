//! Preset `knobs`: the reference torus of `full` once per configuration of the accuracy report
//! (`docs/accuracy.md`), one line each, so that every precision knob has its Cortex-M cost; the
//! texture knobs draw the `textured` preset's torus instead.
//! The names are the report's; `examples/accuracy.rs --mcu` runs this preset and reads them.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use fixed3d::math::{Angle, Normalize, Scalar, Trig, Vec3};
use fixed3d::mesh::{Mesh, Object, Transform, Triangle, Uv};
use fixed3d::pipeline::{MatrixFormat, Precision, ScreenVertex};
use fixed3d::scene::Scene;
use fixed3d::shade::{Flat, Gouraud, PerspectiveGouraud};
use fixed3d::texture::{Mapping, Texture};
use mcu_bench::scenes::*;
use mcu_bench::{storage, torus_storage, Op};
use panic_semihosting as _;

const KNOBS: [&str; 17] = [
    "default",
    "subpixel-2",
    "subpixel-0",
    "matrix-q16.16",
    "matrix-q24.8",
    "depth-u32",
    "trig-table",
    "trig-micromath",
    "normalize-exact",
    "normalize-micromath",
    "gouraud-affine",
    "gouraud-perspective",
    "texture-affine",
    "texture-run-1",
    "texture-run-4",
    "texture-run-16",
    "texture-run-64",
];

const N: usize = (W * H) as usize;

#[entry]
fn main() -> ! {
    let (cache, pos, nor, tri) = torus_storage!();
    let (fb, d16, d32) = storage!(
        FB: [Rgb565; N] = [Rgb565::BLACK; N],
        D16: [u16; N] = [0; N],
        D32: [u32; N] = [0; N],
    );
    let mesh = torus_mesh(pos, nor, tri);
    let (tcache, tp, tn, tuv, tt) = storage!(
        TCACHE: [ScreenVertex; TEXTURED_VERTICES] = [ScreenVertex::DEFAULT; TEXTURED_VERTICES],
        TP: [Vec3; TEXTURED_VERTICES] = [Vec3::ZERO; TEXTURED_VERTICES],
        TN: [Vec3; TEXTURED_VERTICES] = [Vec3::ZERO; TEXTURED_VERTICES],
        TUV: [Uv; TEXTURED_VERTICES] = [[Scalar::ZERO; 2]; TEXTURED_VERTICES],
        TT: [Triangle; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES],
    );
    let textured_torus = textured_torus_mesh(tp, tn, tuv, tt);
    mcu_bench::run_each(&KNOBS, |knob, op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            d16.fill(u16::MAX);
            d32.fill(u32::MAX);
            0
        }
        Op::Draw(f) => match knob.strip_prefix("texture-") {
            Some(mapping) => {
                // "affine", or "run-N": an exact division every N pixels.
                let run = mapping.strip_prefix("run-").and_then(|n| n.parse().ok());
                let configure = |t: Texture<'static>| match run {
                    Some(n) => t.with_run(n),
                    None => t.with_mapping(Mapping::Affine),
                };
                textured_by(&textured_torus, f, tcache, fb, d16, configure).is_some() as u32
            }
            None => draw(knob, &mesh, f, cache, fb, d16, d32).is_some() as u32,
        },
        Op::Hash => frame_hash(fb),
    })
}

/// The `full` frame with the knob `knob` moved.
fn draw(
    knob: &str,
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    fb: &mut [Rgb565],
    d16: &mut [u16],
    d32: &mut [u32],
) -> Option<()> {
    let p = Precision::DEFAULT;
    let precision = match knob {
        "subpixel-2" => p.with_subpixel_bits(2),
        "subpixel-0" => p.with_subpixel_bits(0),
        "matrix-q16.16" => p.with_matrix(MatrixFormat::Fixed(16)),
        "matrix-q24.8" => p.with_matrix(MatrixFormat::Fixed(8)),
        "normalize-exact" => p.with_normalize(Normalize::Exact),
        "normalize-micromath" => p.with_normalize(Normalize::Micromath),
        _ => p,
    };
    let trig = match knob {
        "trig-table" => Trig::Table,
        "trig-micromath" => Trig::Micromath,
        _ => Trig::Polynomial,
    };
    let turn = Angle::from_degrees(30).wrapping_add(Angle::from_degrees(f as i32));
    let model = Transform::new().rotated_y(turn).matrix_by(trig)
        * Transform::new()
            .rotated_x(Angle::from_degrees(20))
            .matrix_by(trig);
    let objects = [Object::new(mesh, model, ORANGE)];
    let scene = Scene::new(&objects, sun());
    let frame = frame(W, H)?.with_precision(precision);
    match knob {
        "depth-u32" => depth_frame(frame, &scene, Flat, cache, fb, d32),
        "gouraud-affine" => depth_frame(frame, &scene, Gouraud, cache, fb, d16),
        "gouraud-perspective" => depth_frame(frame, &scene, PerspectiveGouraud, cache, fb, d16),
        _ => depth_frame(frame, &scene, Flat, cache, fb, d16),
    }
}

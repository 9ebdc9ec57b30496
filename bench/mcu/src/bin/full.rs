//! Preset `full`: the reference torus, flat Lambert, u16 depth buffer, 320x240 framebuffer.
//! The mesh keeps its face normals, found once at start-up (12 bytes a triangle, 27 KiB), and
//! `Flat` lights each face from them, as a firmware that draws a rigid mesh every frame
//! would; built with the feature `per-frame-normals` (`NORMALS=per-frame bench/mcu/run.sh`),
//! `Flat` finds each face's normal from its positions every frame instead.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
#[cfg(not(feature = "per-frame-normals"))]
use fixed3d::mesh::FaceNormal;
use mcu_bench::scenes::*;
use mcu_bench::{storage, torus_storage, Op};
use panic_semihosting as _;
#[entry]
fn main() -> ! {
    let (cache, pos, nor, tri) = torus_storage!();
    let (fb, depth) = storage!(
        FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize],
        DEPTH: [u16; (W * H) as usize] = [0; (W * H) as usize],
    );
    let mesh = torus_mesh(pos, nor, tri);
    #[cfg(not(feature = "per-frame-normals"))]
    let mesh = {
        let faces =
            storage!(FACES: [FaceNormal; TORUS_TRIANGLES] = [FaceNormal::ZERO; TORUS_TRIANGLES]);
        mesh.with_face_normals(faces).unwrap_or(mesh)
    };
    mcu_bench::run("full", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => full(&mesh, f, cache, fb, depth).is_some() as u32,
        Op::Hash => frame_hash(fb),
    })
}

//! Preset `variants`: `full`'s torus drawn twice at the same depths (see `scenes::variant`)
//! through each depth test and count of `ColorDepth`, one line each, with the counts folded
//! into each frame's hash, then once more from so near (`clipped`) that the near plane cuts
//! triangles and spans reach every side of the screen, and last 600 random triangles of every
//! row set-up case into a band (`triangles`, see `scenes::random_mesh`): every u16 row and
//! pixel loop each core compiles, checked against the host's (`tests/firmware.rs`); and the
//! same random triangles shrunk inside every clip plane and culled to their front faces
//! (`front`, every count in its hash); `full`'s vertex stage alone (`vertices`, a hash of
//! every vertex's position and depth); and a floor receding from 1.1 to 32.6 away, textured
//! (`floor-textured`) and smooth (`floor-gouraud`), both perspective-correct: the exact
//! divisions of their spans, which the torus presets' nearly affine triangles skip; and the
//! torus solid with a second one through it as a wireframe, depth-tested against it by the
//! `Renderer` (`wire-depth`: built with the library's `wireframe` feature, so alone). Not in
//! footprint.md's table.
#![no_std]
#![no_main]

use core::cell::Cell;

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use fixed3d::math::Vec3;
use fixed3d::pipeline::ScreenVertex;
use mcu_bench::scenes::*;
use mcu_bench::{storage, torus_storage, Op};
use panic_semihosting as _;

// `wire-depth`: outside the library every preset links (see the file).
#[path = "../wire_depth.rs"]
mod wire_depth;
mod scenes {
    pub use mcu_bench::scenes::*;
}

#[entry]
fn main() -> ! {
    let (_, pos, nor, tri) = torus_storage!();
    let (cache, fb, depth, random_pos, random_tri) = storage!(
        // The torus twice.
        CACHE2: [ScreenVertex; 2 * TORUS_VERTICES] = [ScreenVertex::DEFAULT; 2 * TORUS_VERTICES],
        FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize],
        DEPTH: [u16; (W * H) as usize] = [0; (W * H) as usize],
        RANDOM_POS: [Vec3; 3 * RANDOM_TRIANGLES] = [Vec3::ZERO; 3 * RANDOM_TRIANGLES],
        RANDOM_TRI: [[u16; 3]; RANDOM_TRIANGLES] = [[0; 3]; RANDOM_TRIANGLES],
    );
    let mesh = torus_mesh(pos, nor, tri);
    let random = random_mesh(random_pos, random_tri);
    let counts = Cell::new(0);
    mcu_bench::run_each(&VARIANTS, |name, op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => {
            let word = if name == "wire-depth" {
                wire_depth::wire_depth(&mesh, f, true, cache, fb, depth)
            } else {
                variant(name, &mesh, &random, f, cache, fb, depth)
            };
            counts.set(word.unwrap_or(0));
            word.is_some() as u32
        }
        Op::Hash => frame_hash(fb) ^ counts.get(),
    })
}

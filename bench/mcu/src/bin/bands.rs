//! Preset `bands`: the `full` frame at 320x240 drawn by the `Renderer` band by band through
//! 15 KiB of colour and depth buffers, each band sent to a display stand-in whose work (a
//! hash of what it is sent) is left out of the count, as a display's DMA would take it. The
//! mesh keeps its face normals as `full`'s does (and finds them every frame with the feature
//! `per-frame-normals`).
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use fixed3d::buffer::Carried;
#[cfg(not(feature = "per-frame-normals"))]
use fixed3d::mesh::FaceNormal;
use fixed3d::pipeline::Bin;
use mcu_bench::scenes::*;
use mcu_bench::{storage, torus_storage, Op};
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    let (cache, pos, nor, tri) = torus_storage!();
    let (band, band_depth, bins, carried) = storage!(
        BAND: [Rgb565; (W * BAND_ROWS) as usize] = [Rgb565::BLACK; (W * BAND_ROWS) as usize],
        BAND_DEPTH: [u16; (W * BAND_ROWS) as usize] = [0; (W * BAND_ROWS) as usize],
        BINS: [Bin; BAND_BINS] = [Bin::EMPTY; BAND_BINS],
        CARRIED: [Carried; BAND_CARRIED] = [Carried::EMPTY; BAND_CARRIED],
    );
    let mesh = torus_mesh(pos, nor, tri);
    #[cfg(not(feature = "per-frame-normals"))]
    let mesh = {
        let faces =
            storage!(FACES: [FaceNormal; TORUS_TRIANGLES] = [FaceNormal::ZERO; TORUS_TRIANGLES]);
        mesh.with_face_normals(faces).unwrap_or(mesh)
    };
    let mut last = 0;
    mcu_bench::run("bands", |op| match op {
        Op::Clear => 0,
        Op::Draw(f) => {
            let exclude = &mut mcu_bench::excluded;
            last = bands(
                &mesh,
                f,
                cache,
                (&mut *bins, &mut *carried),
                band,
                band_depth,
                &mut NoDisplay,
                exclude,
            )
            .unwrap_or(0);
            last
        }
        Op::Hash => last,
    })
}

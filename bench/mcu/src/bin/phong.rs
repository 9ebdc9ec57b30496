//! Preset `phong`: `gouraud`'s torus, glossy (white highlights, shininess 32), under ambient
//! light and one point light, Gouraud shading, u16 depth.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
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
    mcu_bench::run("phong", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => phong(&mesh, f, cache, fb, depth).is_some() as u32,
        Op::Hash => frame_hash(fb),
    })
}

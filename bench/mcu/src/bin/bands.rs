//! Preset `bands`: the `full` frame at 320x240 drawn band by band through 15 KiB of colour and depth buffers.
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
    let (band, band_depth) = storage!(
        BAND: [Rgb565; (W * BAND_ROWS) as usize] = [Rgb565::BLACK; (W * BAND_ROWS) as usize],
        BAND_DEPTH: [u16; (W * BAND_ROWS) as usize] = [0; (W * BAND_ROWS) as usize],
    );
    let mesh = torus_mesh(pos, nor, tri);
    let mut last = 0;
    mcu_bench::run("bands", |op| match op {
        Op::Clear => 0,
        Op::Draw(f) => {
            last = bands(&mesh, f, cache, band, band_depth).unwrap_or(0);
            last
        }
        Op::Hash => last,
    })
}

//! Preset `flat`: a convex mesh (the cube) filled flat with back-face culling only: no depth buffer.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use mcu_bench::scenes::*;
use mcu_bench::{storage, Op};
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    let (cache, fb) = storage!(
        CACHE: [fixed3d::pipeline::ScreenVertex; 8] = [fixed3d::pipeline::ScreenVertex::DEFAULT; 8],
        FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize],
    );
    mcu_bench::run("flat", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            0
        }
        Op::Draw(f) => flat(f, cache, fb).is_some() as u32,
        Op::Hash => frame_hash(fb),
    })
}

//! Preset `obj`: a small OBJ model in flash parsed at start-up (allocation-free), then drawn flat with a u16 depth buffer.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use mcu_bench::scenes::*;
use mcu_bench::{storage, Op};
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    let (cache, pos, tri) = storage!(
        CACHE: [fixed3d::pipeline::ScreenVertex; 16] = [fixed3d::pipeline::ScreenVertex::DEFAULT; 16],
        POS: [fixed3d::math::Vec3; 16] = [fixed3d::math::Vec3::ZERO; 16],
        TRI: [[u16; 3]; 16] = [[0; 3]; 16],
    );
    let (fb, depth) = storage!(
        FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize],
        DEPTH: [u16; (W * H) as usize] = [0; (W * H) as usize],
    );
    let mesh = obj_mesh(pos, tri);
    mcu_bench::run("obj", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => obj(&mesh, f, cache, fb, depth).is_some() as u32,
        Op::Hash => frame_hash(fb),
    })
}

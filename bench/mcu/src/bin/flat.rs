//! Preset `flat`: a convex mesh (the cube) filled flat with back-face culling only: no depth buffer.
#![no_std]
#![no_main]

use core::ptr::addr_of_mut;

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
#[allow(unused_imports)]
use fixed3d::{math::Vec3, pipeline::ScreenVertex};
use mcu_bench::scenes::*;
use mcu_bench::Op;
use panic_semihosting as _;

static mut CACHE: [ScreenVertex; 8] = [ScreenVertex::DEFAULT; 8];
static mut FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize];

#[entry]
fn main() -> ! {
    // SAFETY: the only references to these statics, each taken once here.
    let (cache, fb) = unsafe { (&mut *addr_of_mut!(CACHE), &mut *addr_of_mut!(FB)) };
    mcu_bench::run("flat", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            0
        }
        Op::Draw(f) => flat(f, cache, fb).is_some() as u32,
        Op::Hash => {
            let mut h = Fnv::new();
            h.pixels(fb);
            h.0
        }
    })
}

//! Preset `obj`: a small OBJ model in flash parsed at start-up (allocation-free), then drawn flat with a u16 depth buffer.
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

static mut CACHE: [ScreenVertex; 16] = [ScreenVertex::DEFAULT; 16];
static mut POS: [Vec3; 16] = [Vec3::ZERO; 16];
static mut TRI: [[u16; 3]; 16] = [[0; 3]; 16];
static mut FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize];
static mut DEPTH: [u16; (W * H) as usize] = [0; (W * H) as usize];

#[entry]
fn main() -> ! {
    // SAFETY: the only references to these statics, each taken once here.
    let (cache, pos, tri, fb, depth) = unsafe {
        (
            &mut *addr_of_mut!(CACHE),
            &mut *addr_of_mut!(POS),
            &mut *addr_of_mut!(TRI),
            &mut *addr_of_mut!(FB),
            &mut *addr_of_mut!(DEPTH),
        )
    };
    let mesh = obj_mesh(pos, tri);
    mcu_bench::run("obj", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => obj(&mesh, f, cache, fb, depth).is_some() as u32,
        Op::Hash => {
            let mut h = Fnv::new();
            h.pixels(fb);
            h.0
        }
    })
}

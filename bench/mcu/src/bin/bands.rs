//! Preset `bands`: the `full` frame at 320x240 drawn band by band through 15 KiB of colour and depth buffers.
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

static mut CACHE: [ScreenVertex; TORUS_VERTICES] = [ScreenVertex::DEFAULT; TORUS_VERTICES];
static mut POS: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES];
static mut NOR: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES];
static mut TRI: [[u16; 3]; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES];
static mut BAND: [Rgb565; (W * BAND_ROWS) as usize] = [Rgb565::BLACK; (W * BAND_ROWS) as usize];
static mut BAND_DEPTH: [u16; (W * BAND_ROWS) as usize] = [0; (W * BAND_ROWS) as usize];

#[entry]
fn main() -> ! {
    // SAFETY: the only references to these statics, each taken once here.
    let (cache, pos, nor, tri, band, band_depth) = unsafe {
        (
            &mut *addr_of_mut!(CACHE),
            &mut *addr_of_mut!(POS),
            &mut *addr_of_mut!(NOR),
            &mut *addr_of_mut!(TRI),
            &mut *addr_of_mut!(BAND),
            &mut *addr_of_mut!(BAND_DEPTH),
        )
    };
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

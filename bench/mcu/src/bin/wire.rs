//! Preset `wire`: the torus wireframe straight into a display (a hashing stand-in): no
//! framebuffer, no depth, no lighting. On the micro:bit (16 KiB of RAM) a 16 x 8 torus on a
//! 64x48 display.
#![no_std]
#![no_main]

use core::ptr::addr_of_mut;

use cortex_m_rt::entry;
use embedded_graphics::geometry::Size;
use fixed3d::{math::Vec3, pipeline::ScreenVertex};
use mcu_bench::scenes::*;
use mcu_bench::Op;
use panic_semihosting as _;

#[cfg(not(feature = "board-microbit"))]
mod size {
    pub const VERTICES: usize = super::TORUS_VERTICES;
    pub const TRIANGLES: usize = super::TORUS_TRIANGLES;
    pub const DISPLAY: (u32, u32) = (super::W, super::H);
    pub use mcu_bench::scenes::torus_mesh as mesh;
}

#[cfg(feature = "board-microbit")]
mod size {
    pub const VERTICES: usize = super::SMALL_VERTICES;
    pub const TRIANGLES: usize = super::SMALL_TRIANGLES;
    pub const DISPLAY: (u32, u32) = (super::SMALL_W, super::SMALL_H);
    pub use mcu_bench::scenes::small_torus_mesh as mesh;
}

static mut CACHE: [ScreenVertex; size::VERTICES] = [ScreenVertex::DEFAULT; size::VERTICES];
static mut POS: [Vec3; size::VERTICES] = [Vec3::ZERO; size::VERTICES];
static mut NOR: [Vec3; size::VERTICES] = [Vec3::ZERO; size::VERTICES];
static mut TRI: [[u16; 3]; size::TRIANGLES] = [[0; 3]; size::TRIANGLES];

#[entry]
fn main() -> ! {
    // SAFETY: the only references to these statics, each taken once here.
    let (cache, pos, nor, tri) = unsafe {
        (
            &mut *addr_of_mut!(CACHE),
            &mut *addr_of_mut!(POS),
            &mut *addr_of_mut!(NOR),
            &mut *addr_of_mut!(TRI),
        )
    };
    let mesh = size::mesh(pos, nor, tri);
    let (w, h) = size::DISPLAY;
    let mut display = HashDisplay {
        hash: Fnv::new(),
        size: Size::new(w, h),
    };
    mcu_bench::run("wire", |op| match op {
        Op::Clear => {
            display.hash = Fnv::new();
            0
        }
        Op::Draw(f) => wire(&mesh, f, cache, &mut display).is_some() as u32,
        Op::Hash => display.hash.0,
    })
}

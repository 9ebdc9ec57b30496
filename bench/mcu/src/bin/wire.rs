//! Preset `wire`: the torus wireframe straight into a display (a hashing stand-in): no framebuffer, no depth, no lighting.
#![no_std]
#![no_main]

use core::ptr::addr_of_mut;

use cortex_m_rt::entry;

#[allow(unused_imports)]
use fixed3d::{math::Vec3, pipeline::ScreenVertex};
use mcu_bench::scenes::*;
use mcu_bench::Op;
use panic_semihosting as _;

static mut CACHE: [ScreenVertex; TORUS_VERTICES] = [ScreenVertex::DEFAULT; TORUS_VERTICES];
static mut POS: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES];
static mut NOR: [Vec3; TORUS_VERTICES] = [Vec3::ZERO; TORUS_VERTICES];
static mut TRI: [[u16; 3]; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES];

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
    let mesh = torus_mesh(pos, nor, tri);
    let mut display = HashDisplay {
        hash: Fnv::new(),
        size: embedded_graphics::geometry::Size::new(W, H),
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

//! Preset `textured`: the reference torus with a 64x64 Rgb565 texture in flash (its UVs from
//! the torus, the seams' vertices doubled), perspective-correct, flat Lambert from the face
//! normals the mesh keeps, u16 depth buffer, 320x240 framebuffer.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::FaceNormal;
use fixed3d::pipeline::ScreenVertex;
use mcu_bench::scenes::*;
use mcu_bench::{storage, Op};
use panic_semihosting as _;

#[entry]
fn main() -> ! {
    const V: usize = TEXTURED_VERTICES;
    let (cache, pos, nor, uv, tri, faces) = storage!(
        CACHE: [ScreenVertex; V] = [ScreenVertex::DEFAULT; V],
        POS: [Vec3; V] = [Vec3::ZERO; V],
        NOR: [Vec3; V] = [Vec3::ZERO; V],
        UV: [[Scalar; 2]; V] = [[Scalar::ZERO; 2]; V],
        TRI: [[u16; 3]; TORUS_TRIANGLES] = [[0; 3]; TORUS_TRIANGLES],
        FACES: [FaceNormal; TORUS_TRIANGLES] = [FaceNormal::ZERO; TORUS_TRIANGLES],
    );
    let (fb, depth) = storage!(
        FB: [Rgb565; (W * H) as usize] = [Rgb565::BLACK; (W * H) as usize],
        DEPTH: [u16; (W * H) as usize] = [0; (W * H) as usize],
    );
    let mesh = textured_torus_mesh(pos, nor, uv, tri);
    let mesh = mesh.with_face_normals(faces).unwrap_or(mesh);
    mcu_bench::run("textured", |op| match op {
        Op::Clear => {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            0
        }
        Op::Draw(f) => textured(&mesh, f, cache, fb, depth).is_some() as u32,
        Op::Hash => frame_hash(fb),
    })
}

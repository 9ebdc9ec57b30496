//! The reference scene of docs/reference-scene.md, built exactly as written there (f64 vertices, rounded
//! to Q16.16 once).
#![allow(dead_code)]

use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::Triangle;
use fixed3d::pipeline::Frame;
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting};

pub struct TorusData {
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub triangles: Vec<Triangle>,
}

pub fn torus_f64() -> TorusData {
    let (r_big, r_small, u_n, v_n) = (1.0f64, 0.4f64, 48usize, 24usize);
    let (a, b) = (20f64.to_radians(), 30f64.to_radians());
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    for i in 0..u_n {
        for j in 0..v_n {
            let u = 2.0 * std::f64::consts::PI * i as f64 / u_n as f64;
            let w = 2.0 * std::f64::consts::PI * j as f64 / v_n as f64;
            let x = (r_big + r_small * w.cos()) * u.cos();
            let y = r_small * w.sin();
            let z = (r_big + r_small * w.cos()) * u.sin();
            let y1 = y * a.cos() - z * a.sin();
            let z1 = y * a.sin() + z * a.cos();
            let x2 = x * b.cos() + z1 * b.sin();
            let z2 = -x * b.sin() + z1 * b.cos();
            positions.push(Vec3::from_f32(x2 as f32, y1 as f32, z2 as f32).unwrap());
            // The normal, rotated the same way.
            let (nx, ny, nz) = (w.cos() * u.cos(), w.sin(), w.cos() * u.sin());
            let ny1 = ny * a.cos() - nz * a.sin();
            let nz1 = ny * a.sin() + nz * a.cos();
            let nx2 = nx * b.cos() + nz1 * b.sin();
            let nz2 = -nx * b.sin() + nz1 * b.cos();
            normals.push(Vec3::from_f32(nx2 as f32, ny1 as f32, nz2 as f32).unwrap());
        }
    }
    let mut triangles = Vec::new();
    for i in 0..u_n {
        for j in 0..v_n {
            let (i1, j1) = ((i + 1) % u_n, (j + 1) % v_n);
            let p = |i: usize, j: usize| (i * v_n + j) as u16;
            triangles.push([p(i, j), p(i, j1), p(i1, j1)]);
            triangles.push([p(i, j), p(i1, j1), p(i1, j)]);
        }
    }
    TorusData {
        positions,
        normals,
        triangles,
    }
}

pub const BASE: Rgb888 = Rgb888::new(255, 160, 64);

pub fn frame() -> Frame {
    let viewport = Viewport::new(320, 240).unwrap();
    let view = LookAt::new(Vec3::from_f32(0.0, 0.0, 2.6).unwrap(), Vec3::ZERO, Vec3::Y)
        .view()
        .unwrap();
    let s = Scalar::from_num;
    let projection =
        Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(1), s(10)).unwrap();
    Frame::new(&view, &projection, viewport)
}

pub fn lighting() -> Lighting<1> {
    let mut l = Lighting::new(LightColor::gray(Scalar::from_num(0.2)));
    l.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(Scalar::from_num(0.8)),
    ))
    .unwrap();
    l
}

pub fn identity() -> Mat4 {
    Mat4::IDENTITY
}

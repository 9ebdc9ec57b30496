//! The textured floor of tests/texture.rs and tests/cli.rs: its mesh, camera and texture,
//! and an exact f64 ray cast of which texel each pixel shows.
#![allow(dead_code)]

use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::Uv;

/// A 64x64 texture whose every texel differs from its neighbours in every channel step.
pub fn texels() -> Vec<Rgb888> {
    (0..64 * 64)
        .map(|i| {
            let (x, y) = ((i % 64) as u8, (i / 64) as u8);
            Rgb888::new(x * 4, y * 4, (x ^ y) * 4 + 1)
        })
        .collect()
}

pub const W: u32 = 320;
pub const H: u32 = 240;
pub const EYE: [f64; 3] = [0.3, 1.0, 2.0];
pub const TARGET: [f64; 3] = [0.0, 0.0, -6.0];
pub const FOV: f64 = 60.0;

/// The floor y = 0 from x = −20 to 20, z = 4 (behind the eye: the near plane cuts it) to
/// z = −60, with u = (x + 20)/4 and v = (4 − z)/4: ten repeats across, sixteen away.
pub fn floor_positions() -> [Vec3; 4] {
    let p = |x: i32, z: i32| Vec3::from_int(x as i16, 0, z as i16);
    [p(-20, 4), p(20, 4), p(20, -60), p(-20, -60)]
}

pub fn floor_uvs() -> [Uv; 4] {
    let s = |v: i32| Scalar::from_num(v);
    [[s(0), s(0)], [s(10), s(0)], [s(10), s(16)], [s(0), s(16)]]
}

pub const FLOOR_TRIANGLES: [[u16; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

/// The texel coordinates (s, t) = (u·64, (1 − v)·64) where the ray through screen point
/// (x, y) meets the floor, in f64; `None` above the horizon.
pub fn cast(x: f64, y: f64) -> Option<(f64, f64)> {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let norm = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|c| c / l)
    };
    let forward = norm(sub(TARGET, EYE));
    let right = norm(cross(forward, [0.0, 1.0, 0.0]));
    let up = cross(right, forward);
    let f = (FOV.to_radians() / 2.0).tan();
    let nx = (2.0 * x / W as f64 - 1.0) * f * W as f64 / H as f64;
    let ny = (1.0 - 2.0 * y / H as f64) * f;
    let d: [f64; 3] = [0, 1, 2].map(|k| forward[k] + nx * right[k] + ny * up[k]);
    if d[1] >= 0.0 {
        return None;
    }
    let t = -EYE[1] / d[1];
    let (px, pz) = (EYE[0] + t * d[0], EYE[2] + t * d[2]);
    if !(-19.0..19.0).contains(&px) || !(-58.0..3.0).contains(&pz) {
        return None;
    }
    let (u, v) = ((px + 20.0) / 4.0, (4.0 - pz) / 4.0);
    Some((u * 64.0, (1.0 - v) * 64.0))
}

/// The texel the exact map gives pixel (px, py) where it is unambiguous: the same for the
/// pixel's centre moved by an eighth of a pixel each way, and for the texel coordinates moved
/// by a sixteenth of a texel (the snapping of vertices, the error allowed the map).
pub fn reference_texel(px: u32, py: u32) -> Option<(i64, i64)> {
    let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
    let mut texel = None;
    for (dx, dy) in [
        (0.0, 0.0),
        (-0.125, 0.0),
        (0.125, 0.0),
        (0.0, -0.125),
        (0.0, 0.125),
    ] {
        let (s, t) = cast(cx + dx, cy + dy)?;
        for (ds, dt) in [(0.0, 0.0), (-0.0625, -0.0625), (0.0625, 0.0625)] {
            let here = (
                ((s + ds).floor() as i64).rem_euclid(64),
                ((t + dt).floor() as i64).rem_euclid(64),
            );
            if texel.is_some_and(|t| t != here) {
                return None;
            }
            texel = Some(here);
        }
    }
    texel
}

/// (pixels compared, pixels that differ from the exact map's texel).
pub fn compare_with_reference(pixels: &[Rgb888], texels: &[Rgb888]) -> (usize, usize) {
    let (mut compared, mut differ) = (0, 0);
    for py in 0..H {
        for px in 0..W {
            let Some((s, t)) = reference_texel(px, py) else {
                continue;
            };
            compared += 1;
            if pixels[(py * W + px) as usize] != texels[(t * 64 + s) as usize] {
                differ += 1;
            }
        }
    }
    (compared, differ)
}

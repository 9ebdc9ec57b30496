//! Lambert's law in fixed point, and the normals it needs.

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use crate::math::{dot_unit, normalize, UNIT_ONE};
use crate::scene::Lighting;

/// Lit colour of `base` for unit normal `n` (Q2.30), or ambient only when there is no normal.
/// Per channel: `floor(base · clamp(ambient + Σ light · max(0, n·l), 0, 1))`.
pub(crate) fn lambert<const N: usize>(
    base: Rgb888,
    n: Option<[i32; 3]>,
    lighting: &Lighting<N>,
) -> Rgb888 {
    let mut sum = lighting.ambient().channels();
    if let Some(n) = n {
        for light in lighting.lights() {
            let d = dot_unit(n, light.direction).max(0) as i64;
            for (s, c) in sum.iter_mut().zip(light.color.iter()) {
                // Q16.16 · Q2.30 → Q16.16
                *s = s.saturating_add((c * d) >> 30);
            }
        }
    }
    let one = 1i64 << 16;
    let ch = |b: u8, s: i64| ((b as i64 * s.clamp(0, one)) >> 16) as u8;
    Rgb888::new(
        ch(base.r(), sum[0]),
        ch(base.g(), sum[1]),
        ch(base.b(), sum[2]),
    )
}

/// Shifts a vector so that its largest component is below 2³⁰ (no division, no sqrt): enough
/// headroom for one more product with Q16.16 before normalising.
fn shrink(v: [i64; 3]) -> [i64; 3] {
    let max = v.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    let bits = 64 - max.leading_zeros();
    if bits > 30 {
        let s = bits - 30;
        v.map(|c| c >> s)
    } else {
        v
    }
}

/// `m · v` for a Q16.16 matrix and a vector below 2³⁰.
fn apply(m: &[[i32; 3]; 3], v: [i64; 3]) -> [i64; 3] {
    m.map(|r| {
        (r[0] as i64 * v[0])
            .saturating_add(r[1] as i64 * v[1])
            .saturating_add(r[2] as i64 * v[2])
    })
}

/// Unit world-space face normal (Q2.30) of a model-space triangle, counter-clockwise front; `None`
/// for a zero-area triangle. Edges of any length: the cross product is exact in i64 after the
/// edges are shifted below 2³⁰ (case T33).
pub(crate) fn face_normal(p: [[i32; 3]; 3], normal_matrix: &[[i32; 3]; 3]) -> Option<[i32; 3]> {
    let [a, b, c] = p.map(|v| v.map(i64::from));
    let e1 = shrink([b[0] - a[0], b[1] - a[1], b[2] - a[2]]);
    let e2 = shrink([c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    normalize(apply(normal_matrix, shrink(n)))
}

/// Unit world-space vertex normal (Q2.30) from a model-space normal (raw Q16.16); `None` for a
/// zero normal (lit by ambient only, case T34).
pub(crate) fn vertex_normal(n: [i32; 3], normal_matrix: &[[i32; 3]; 3]) -> Option<[i32; 3]> {
    let v = shrink(n.map(i64::from));
    let w = normalize(apply(normal_matrix, v))?;
    debug_assert!(w.iter().all(|c| c.abs() <= UNIT_ONE));
    Some(w)
}

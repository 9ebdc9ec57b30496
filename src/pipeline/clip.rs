//! Homogeneous clipping (Sutherland–Hodgman) against the near and far planes and the guard
//! band, before any division. A triangle becomes a convex polygon of at most 9 vertices, drawn
//! as a fan; a segment stays a segment.
//!
//! Every new vertex is computed from its edge's endpoints taken in one canonical order (sorted
//! by their coordinates), so two triangles that share an edge get bit-identical new vertices on
//! it and stay watertight (case T19).

use heapless::Vec;

use super::vertex::{distance, inside, reduce, reduce_pair, ScreenMap, PLANES};
use crate::math::{div_round, magnitude_bits, shr_round};

/// A vertex during clipping: raw Q16.16 clip coordinates and what is interpolated with them:
/// a colour (Gouraud), channels `0..=255 << 8`, then a UV (textures, raw Q16.16).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct ClipVertex {
    pub(crate) c: [i64; 4],
    pub(crate) varying: [i32; 5],
}

impl ClipVertex {
    /// The colour, whole channels (the varyings carry 8 fraction bits through the clip,
    /// rounded off here).
    pub(crate) fn rgb(&self) -> [i32; 3] {
        let [r, g, b, _, _] = self.varying;
        [r, g, b].map(|c| (c.saturating_add(1 << 7) >> 8).clamp(0, 255))
    }

    /// The UV.
    pub(crate) fn uv(&self) -> [i32; 2] {
        let [_, _, _, u, v] = self.varying;
        [u, v]
    }
}

/// A clipped polygon: 3 vertices plus at most one per plane.
pub(crate) type Polygon = Vec<ClipVertex, 9>;

fn is_inside(k: u32, v: &ClipVertex, m: &ScreenMap) -> bool {
    inside(k, distance(k, &reduce(v.c), m))
}

/// The point where edge `a`–`b` crosses plane `k` (one endpoint inside, one outside).
fn intersect(a: &ClipVertex, b: &ClipVertex, k: u32, m: &ScreenMap) -> ClipVertex {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    let (rl, rh, shift) = reduce_pair(lo.c, hi.c);
    let (mut dl, mut dh) = (distance(k, &rl, m), distance(k, &rh, m));
    // Distances below 2³¹ so that dl·2³⁰ fits.
    let ds = magnitude_bits(&[dl, dh]).saturating_sub(31);
    dl = shr_round(dl, ds);
    dh = shr_round(dh, ds);
    let den = dl - dh;
    let t = if den > 0 {
        div_round(dl << 30, den)
    } else if den < 0 {
        div_round(-(dl << 30), -den)
    } else {
        0
    }
    .clamp(0, 1 << 30);
    let lerp = |p: i64, q: i64| p + shr_round((q - p) * t, 30);
    let mut c = [0i64; 4];
    for ((out, p), q) in c.iter_mut().zip(rl.iter()).zip(rh.iter()) {
        *out = lerp(*p, *q) << shift;
    }
    let mut varying = [0i32; 5];
    for ((out, p), q) in varying.iter_mut().zip(lo.varying).zip(hi.varying) {
        // Between p and q: an i32.
        *out = lerp(p as i64, q as i64) as i32;
    }
    ClipVertex { c, varying }
}

/// Clips a triangle against the planes in `planes` (outcode bits); an empty polygon when
/// nothing is left.
pub(crate) fn clip_polygon(tri: [ClipVertex; 3], planes: u8, m: &ScreenMap) -> Polygon {
    let mut poly: Polygon = tri.into_iter().collect();
    for k in 0..PLANES {
        if planes & (1 << k) == 0 {
            continue;
        }
        let mut out = Polygon::new();
        let n = poly.len();
        for (i, cur) in poly.iter().enumerate() {
            let Some(next) = poly.get((i + 1) % n) else {
                break;
            };
            let (ci, ni) = (is_inside(k, cur, m), is_inside(k, next, m));
            if ci {
                let _ = out.push(*cur);
            }
            if ci != ni {
                let _ = out.push(intersect(cur, next, k, m));
            }
        }
        if out.len() < 3 {
            return Polygon::new();
        }
        poly = out;
    }
    poly
}

/// Clips a segment; `None` when nothing is left.
pub(crate) fn clip_segment(
    a: ClipVertex,
    b: ClipVertex,
    planes: u8,
    m: &ScreenMap,
) -> Option<(ClipVertex, ClipVertex)> {
    let (mut a, mut b) = (a, b);
    for k in 0..PLANES {
        if planes & (1 << k) == 0 {
            continue;
        }
        match (is_inside(k, &a, m), is_inside(k, &b, m)) {
            (true, true) => {}
            (false, false) => return None,
            (true, false) => b = intersect(&a, &b, k, m),
            (false, true) => a = intersect(&a, &b, k, m),
        }
    }
    Some((a, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Clipped colours reach shading as whole channels: rounded to nearest (ties up) and kept
    /// in 0..=255, so that Gouraud's range argument (whole vertex channels) holds for them.
    #[test]
    fn clipped_colours_are_whole_channels() {
        let v = |r: i32, g: i32, b: i32| ClipVertex {
            c: Default::default(),
            varying: [r, g, b, 0, 0],
        };
        assert_eq!(v(200 << 8 | 128, 100 << 8 | 127, 0).rgb(), [201, 100, 0]);
        assert_eq!(v(255 << 8 | 200, -3, 7 << 8).rgb(), [255, 0, 7]);
    }
}

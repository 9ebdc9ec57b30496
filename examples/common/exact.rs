//! The exact integer model of the triangle rules (shared by the tests and the accuracy report):
//! a different algorithm from the crate's scanline filler, per-pixel edge functions over the
//! bounding box in i128. It is REF_EXACT of `docs/accuracy.md`: the crate must equal it.
#![allow(dead_code)]

use fixed3d::raster::{PixelRect, ScreenPoint};
use std::collections::BTreeSet;

pub const S: i128 = 16;

/// The exact model of rule R1/R3/R4: pixel centres inside the triangle, edges by the top-left
/// rule, zero area covers nothing.
pub fn model_triangle(v: [ScreenPoint; 3], clip: PixelRect) -> BTreeSet<(i32, i32)> {
    let mut out = BTreeSet::new();
    let p = v.map(|q| (q.x as i128, q.y as i128));
    let e = |a: (i128, i128), b: (i128, i128), x: i128, y: i128| {
        (b.0 - a.0) * (y - a.1) - (b.1 - a.1) * (x - a.0)
    };
    let (a, mut b, mut c) = (p[0], p[1], p[2]);
    let area = e(a, b, c.0, c.1);
    if area == 0 {
        return out;
    }
    if area < 0 {
        std::mem::swap(&mut b, &mut c);
    }
    let top_left = |a: (i128, i128), b: (i128, i128)| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        dy < 0 || (dy == 0 && dx > 0)
    };
    let inside = |a, b, x, y| {
        let v = e(a, b, x, y);
        v > 0 || (v == 0 && top_left(a, b))
    };
    let xmin = p.iter().map(|q| q.0).min().unwrap().div_euclid(S) - 1;
    let xmax = p.iter().map(|q| q.0).max().unwrap().div_euclid(S) + 1;
    let ymin = p.iter().map(|q| q.1).min().unwrap().div_euclid(S) - 1;
    let ymax = p.iter().map(|q| q.1).max().unwrap().div_euclid(S) + 1;
    let xs = xmin.max(clip.x0 as i128)..=xmax.min(clip.x1 as i128 - 1);
    let ys = ymin.max(clip.y0 as i128)..=ymax.min(clip.y1 as i128 - 1);
    for py in ys {
        for px in xs.clone() {
            let (x, y) = (px * S + S / 2, py * S + S / 2);
            if inside(a, b, x, y) && inside(b, c, x, y) && inside(c, a, x, y) {
                out.insert((px as i32, py as i32));
            }
        }
    }
    out
}

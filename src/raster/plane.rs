//! Attribute planes: depth and colour as linear functions of screen position through the three
//! snapped vertices (affine in screen space, which is exact for depth after projection).

use super::ScreenPoint;
use crate::math::{DivideBy, SUBPIXEL_SCALE};

/// `v(x, y) = v0 + gx·(x − x0) + gy·(y − y0)` with x, y in sub-pixels.
///
/// Vertex values are scaled so that they stay below 2⁴⁵ in magnitude and vertex coordinates
/// within ±2¹⁵ (the guard band): the gradient numerators then stay below 2⁶², and the gradients
/// are rounded to the values' own unit. Evaluating at any pixel centre inside the triangle
/// errs by at most 2¹⁷ units (distance below 2¹⁷ sub-pixels times half a unit each way); the
/// products may wrap in between, but the sum is exact modulo 2⁶⁴ and the true result fits, so
/// wrapping arithmetic returns it exactly.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Plane {
    x0: i32,
    y0: i32,
    v0: i64,
    gx: i64,
    gy: i64,
}

impl Plane {
    /// The plane through `(p[i], v[i])`; `area2` is the triangle's doubled signed area
    /// `(x1−x0)(y2−y0) − (x2−x0)(y1−y0)`, non-zero.
    #[inline]
    pub(crate) fn new(p: &[ScreenPoint; 3], v: [i64; 3], area2: i64) -> Plane {
        let [a, b, c] = *p;
        let (dx1, dy1) = (b.x as i64 - a.x as i64, b.y as i64 - a.y as i64);
        let (dx2, dy2) = (c.x as i64 - a.x as i64, c.y as i64 - a.y as i64);
        let (dv1, dv2) = (v[1].wrapping_sub(v[0]), v[2].wrapping_sub(v[0]));
        let nx = dv1.wrapping_mul(dy2).wrapping_sub(dv2.wrapping_mul(dy1));
        let ny = dx1.wrapping_mul(dv2).wrapping_sub(dx2.wrapping_mul(dv1));
        let (nx, ny, den) = if area2 < 0 {
            (nx.wrapping_neg(), ny.wrapping_neg(), area2.wrapping_neg())
        } else {
            (nx, ny, area2)
        };
        let by_area = DivideBy::new(den);
        let (gx, gy) = (by_area.round(nx), by_area.round(ny));
        Plane {
            x0: a.x,
            y0: a.y,
            v0: v[0],
            gx,
            gy,
        }
    }

    /// The value at the centre of pixel `(px, py)`.
    #[inline]
    pub(crate) fn at(&self, px: i32, py: i32) -> i64 {
        let half = SUBPIXEL_SCALE as i64 / 2;
        let dx = (px as i64 * SUBPIXEL_SCALE as i64 + half).wrapping_sub(self.x0 as i64);
        let dy = (py as i64 * SUBPIXEL_SCALE as i64 + half).wrapping_sub(self.y0 as i64);
        self.v0
            .wrapping_add(self.gx.wrapping_mul(dx))
            .wrapping_add(self.gy.wrapping_mul(dy))
    }

    /// The exact changes of [`at`](Self::at) from one pixel to the next along a row and down a
    /// column (modulo 2⁶⁴, like `at` itself): walking by them reproduces `at` bit for bit.
    #[inline]
    pub(crate) fn pixel_steps(&self) -> (i64, i64) {
        let s = SUBPIXEL_SCALE as i64;
        (self.gx.wrapping_mul(s), self.gy.wrapping_mul(s))
    }

    /// The change from one pixel to the next along a row. Saturated: a gradient too steep to
    /// represent belongs to a triangle no row of which is two pixels wide.
    #[inline]
    pub(crate) fn step_x(&self) -> i64 {
        self.gx.saturating_mul(SUBPIXEL_SCALE as i64)
    }
}

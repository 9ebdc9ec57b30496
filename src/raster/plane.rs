//! Attribute planes: depth and colour as linear functions of screen position through the three
//! snapped vertices (affine in screen space, which is exact for depth after projection).

use super::ScreenPoint;
use crate::math::{is_short, mul_short, mul_wide, DivideBy, NARROW_CORE, SUBPIXEL_SCALE};

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
        Plane::from_numerators(a, v[0], nx, ny, area2)
    }

    /// [`new`](Self::new) for values `v[i] << shift` with every `v[i]` in [0, 2³⁰] (depth in
    /// Q1.30, colour channels): the numerators from 32-bit differences and products, shifted
    /// once, the same values (exact, as their true values fit).
    #[inline]
    pub(crate) fn scaled(p: &[ScreenPoint; 3], v: [i32; 3], shift: u32, area2: i64) -> Plane {
        let [a, b, c] = *p;
        // Coordinates within ±2¹⁵ and values in [0, 2³⁰]: every difference fits i32.
        let (dx1, dy1) = (b.x.wrapping_sub(a.x), b.y.wrapping_sub(a.y));
        let (dx2, dy2) = (c.x.wrapping_sub(a.x), c.y.wrapping_sub(a.y));
        let (dv1, dv2) = (v[1].wrapping_sub(v[0]), v[2].wrapping_sub(v[0]));
        // On Cortex-M0 a side within ±2¹⁵ (every side of an on-screen triangle) takes the
        // two-multiply product.
        let times = |v: i32, side: i32| {
            if NARROW_CORE && is_short(side) {
                mul_short(v, side)
            } else {
                mul_wide(v, side)
            }
        };
        let nx = times(dv1, dy2).wrapping_sub(times(dv2, dy1));
        let ny = times(dv2, dx1).wrapping_sub(times(dv1, dx2));
        let v0 = (v[0] as i64) << shift;
        Plane::from_numerators(a, v0, nx << shift, ny << shift, area2)
    }

    /// The plane through `a` (value `v0`) with gradient numerators `nx`, `ny` over `area2`.
    #[inline(always)]
    fn from_numerators(a: ScreenPoint, v0: i64, nx: i64, ny: i64, area2: i64) -> Plane {
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
            v0,
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

    /// The plane at the first pixel of each row's span, row after row from row `y`, for spans
    /// starting at or right of column `x_base`: see [`PlaneRows`].
    #[inline]
    pub(crate) fn rows(&self, x_base: i32, y: i32) -> PlaneRows {
        let (gx, gy) = self.pixel_steps();
        PlaneRows {
            at_row: self.at(x_base, y),
            gx,
            gy,
            x_base,
        }
    }

    /// The change from one pixel to the next along a row. Saturated: a gradient too steep to
    /// represent belongs to a triangle no row of which is two pixels wide.
    #[inline]
    pub(crate) fn step_x(&self) -> i64 {
        self.gx.saturating_mul(SUBPIXEL_SCALE as i64)
    }
}

/// Walks a [`Plane`] down the rows: [`at`](RowStarts::at) is [`Plane::at`] on the current row,
/// bit for bit (modulo 2⁶⁴), [`next_row`](RowStarts::next_row) moves down one row.
pub(crate) trait RowStarts {
    /// What the span loop starts from.
    type Start: Copy;
    /// The value at column `x` (at or right of the base column) of the current row.
    fn at(&self, x: i32) -> Self::Start;
    /// Moves to the next row.
    fn next_row(&mut self);
}

/// [`RowStarts`] in 64 bits: the plane's own value.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PlaneRows {
    /// The plane at the base column of the current row.
    at_row: i64,
    gx: i64,
    gy: i64,
    x_base: i32,
}

impl RowStarts for PlaneRows {
    type Start = i64;

    #[inline(always)]
    fn at(&self, x: i32) -> i64 {
        let dx = x.wrapping_sub(self.x_base) as i64;
        self.at_row.wrapping_add(self.gx.wrapping_mul(dx))
    }

    #[inline(always)]
    fn next_row(&mut self) {
        self.at_row = self.at_row.wrapping_add(self.gy);
    }
}

/// Fraction bits the u16 depth loop drops from the plane's values: it keeps 15 of their 28.
const DROPPED: u32 = 13;

/// The u16 depth loop's 32-bit start `⌊(v + 2²⁷) / 2¹³⌋` row after row: [`WideRows`] where
/// 64-bit arithmetic is native, [`ShortRows`] (32-bit words only) elsewhere.
#[cfg(target_pointer_width = "64")]
pub(crate) type DepthRows = WideRows;
/// The u16 depth loop's 32-bit start `⌊(v + 2²⁷) / 2¹³⌋` row after row: [`WideRows`] where
/// 64-bit arithmetic is native, [`ShortRows`] (32-bit words only) elsewhere.
#[cfg(not(target_pointer_width = "64"))]
pub(crate) type DepthRows = ShortRows;

/// [`RowStarts`] of `⌊(v + 2²⁷) / 2¹³⌋` (modulo 2³²) in 64-bit arithmetic: one product and a
/// shift per row.
#[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
#[derive(Clone, Copy, Debug)]
pub(crate) struct WideRows(PlaneRows);

#[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
impl WideRows {
    /// Starts at row `y`, for columns from `x_base` on.
    #[inline]
    pub(crate) fn new(plane: &Plane, x_base: i32, y: i32) -> WideRows {
        let mut rows = plane.rows(x_base, y);
        rows.at_row = rows.at_row.wrapping_add(1 << 27);
        WideRows(rows)
    }
}

impl RowStarts for WideRows {
    type Start = i32;

    #[inline(always)]
    fn at(&self, x: i32) -> i32 {
        (self.0.at(x) >> DROPPED) as i32
    }

    #[inline(always)]
    fn next_row(&mut self) {
        self.0.next_row();
    }
}

/// `v` as `(⌊v / 2¹³⌋ mod 2³², v mod 2¹³)`: exact pieces of a 64-bit value in 32-bit words.
#[cfg_attr(target_pointer_width = "64", allow(dead_code))]
#[inline(always)]
const fn split(v: i64) -> (i32, u32) {
    ((v >> DROPPED) as i32, v as u32 & ((1 << DROPPED) - 1))
}

/// [`RowStarts`] of `⌊(v + 2²⁷) / 2¹³⌋`, the u16 depth loop's 32-bit start, in 32-bit
/// arithmetic only (no 64-bit product or sum per row, which Cortex-M0 lacks).
///
/// With the row's value `A = a·2¹³ + α` and the pixel step `G = g·2¹³ + γ` (`0 ≤ α, γ < 2¹³`)
/// the value `dx` pixels along is `⌊(A + G·dx) / 2¹³⌋ = a + g·dx + ⌊(α + γ·dx) / 2¹³⌋`, and the
/// last term's sum stays below 2³² for `dx < 2¹⁹` (the caller's columns lie within 2¹⁶ of the
/// base). Every term is exact modulo 2³², so wherever the true value fits 31 bits (the u16
/// loop's precondition) the result is that value, bit for bit. Rows advance the same way.
#[cfg_attr(target_pointer_width = "64", allow(dead_code))]
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShortRows {
    a: i32,
    alpha: u32,
    g: i32,
    gamma: u32,
    row: i32,
    row_frac: u32,
    x_base: i32,
}

#[cfg_attr(target_pointer_width = "64", allow(dead_code))]
impl ShortRows {
    /// Starts `⌊(plane + 2²⁷) / 2¹³⌋` at row `y`, for columns from `x_base` to less than
    /// `x_base + 2¹⁹`.
    #[inline]
    pub(crate) fn new(plane: &Plane, x_base: i32, y: i32) -> ShortRows {
        let (gx, gy) = plane.pixel_steps();
        let (a, alpha) = split(plane.at(x_base, y).wrapping_add(1 << 27));
        let (g, gamma) = split(gx);
        let (row, row_frac) = split(gy);
        ShortRows {
            a,
            alpha,
            g,
            gamma,
            row,
            row_frac,
            x_base,
        }
    }
}

impl RowStarts for ShortRows {
    type Start = i32;

    #[inline(always)]
    fn at(&self, x: i32) -> i32 {
        let dx = x.wrapping_sub(self.x_base);
        let carry = self.alpha.wrapping_add(self.gamma.wrapping_mul(dx as u32)) >> DROPPED;
        self.a
            .wrapping_add(self.g.wrapping_mul(dx))
            .wrapping_add(carry as i32)
    }

    #[inline(always)]
    fn next_row(&mut self) {
        let sum = self.alpha.wrapping_add(self.row_frac);
        self.a = self
            .a
            .wrapping_add(self.row)
            .wrapping_add((sum >> DROPPED) as i32);
        self.alpha = sum & ((1 << DROPPED) - 1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `scaled` is `new` of the shifted values, bit for bit: coordinates across ±2¹⁵, values
    /// across [0, 2³⁰], both signs of area, the shifts the pipeline uses.
    #[test]
    fn scaled_equals_new() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let mut next = |range: i32| rng.within(range);
        let mut planes = 0;
        for _ in 0..200_000 {
            let scale = [1 << 5, 1 << 10, 1 << 15][next(1).unsigned_abs() as usize];
            let p = [(); 3].map(|_| ScreenPoint::new(next(scale), next(scale)));
            let area = crate::raster::doubled_area(p[0], p[1], p[2]);
            if area == 0 {
                continue;
            }
            let v = [(); 3].map(|_| next(1 << 29) + (1 << 29));
            for shift in [14, 28] {
                let wide = Plane::new(&p, v.map(|v| (v as i64) << shift), area);
                let short = Plane::scaled(&p, v, shift, area);
                assert_eq!(
                    (short.v0, short.gx, short.gy),
                    (wide.v0, wide.gx, wide.gy),
                    "{p:?} {v:?} {shift}"
                );
            }
            planes += 1;
        }
        assert!(planes > 190_000);
    }
}

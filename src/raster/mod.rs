//! Rasterisation: snapped sub-pixel geometry to pixels, by exact integer rules.
//!
//! Everything here works on screen coordinates in sub-pixels ([`SUBPIXEL_SCALE`] per pixel,
//! x right, y down). A pixel `(px, py)` covers `[px, px+1) × [py, py+1)` and is sampled at its
//! centre. The rules, each exact (no rounding happens after snapping):
//!
//! - **Triangles** ([`triangle_spans`]): a pixel is covered when its centre is inside the
//!   triangle; a centre exactly on an edge belongs to the triangle only if that edge is a *left*
//!   edge or a *top* edge (the Direct3D/Vulkan top-left rule). Triangles that share an edge with
//!   identical endpoints therefore cover every pixel along it exactly once, and a triangle of
//!   zero area covers nothing.
//! - **Lines** ([`line_pixels`]): a line whose run along x is at least its run along y is
//!   x-major; it draws, in each pixel column whose centre lies in `[start, end)` along x, the
//!   pixel of the row `floor(y)` at that centre (y-major lines swap the axes). The start is
//!   included and the end excluded, so a closed polygon draws each vertex pixel once. Clipping
//!   to the target never changes which pixels are drawn.
//! - **Attributes**: depth and colour are planes through the three snapped vertices, sampled at
//!   pixel centres. The span loops walk them in 32-bit words, with steps rounded once per
//!   triangle and a start found from the triangle's own first vertex: each value lies within a
//!   small stated bound of the exact plane, and depends on nothing but the triangle, so bands
//!   draw what a whole frame draws. The general forms (clamped depth, perspective) take the
//!   exact plane in 64-bit arithmetic.
//!
//! Coordinates must lie within ±[`COORD_LIMIT`] sub-pixels; the pipeline's guard band keeps them
//! far inside it. Work is proportional to the visible rows and pixels, never to the size of the
//! primitive off screen.

mod edge;
mod line;
mod plane;
mod triangle;

pub(crate) use edge::PipelineEdge;
pub use line::{line_pixels, LinePixels};
pub(crate) use plane::{AreaWalks, Plane, RowStarts, WordPlane};
pub(crate) use triangle::{rows_in_range, spans_in_range, StoppedWalk, TriangleWalk};
pub use triangle::{triangle_spans, Span, TriangleSpans};

use embedded_graphics::primitives::Rectangle;

use crate::math::{mul_wide, short_sides_cross, NARROW_CORE, SUBPIXEL_SCALE};

/// The largest magnitude of a sub-pixel coordinate the rasterisers accept (2²⁴, a million
/// pixels); anything further is rejected as a whole.
pub const COORD_LIMIT: i32 = 1 << 24;

/// The largest magnitude of the pipeline's projected coordinates, 2¹⁵ − 16 sub-pixels: the guard
/// band reaches 2¹⁴ − 16 from a screen centre at most 2¹⁴ from the origin (viewports up to 2048
/// pixels), and the projection clamps to it. The pipeline's edge walks rely on it: see
/// [`PipelineEdge`].
pub(crate) const PIPELINE_LIMIT: i32 = (1 << 15) - 16;

/// A point on the screen in sub-pixels: `x` right, `y` down, [`SUBPIXEL_SCALE`] per pixel.
///
/// ```
/// use fixed3d::raster::ScreenPoint;
/// // The centre of pixel (2, 3):
/// assert_eq!(ScreenPoint::pixel_center(2, 3), ScreenPoint::new(40, 56));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ScreenPoint {
    /// Sub-pixels to the right of the screen's left edge.
    pub x: i32,
    /// Sub-pixels below the screen's top edge.
    pub y: i32,
}

impl ScreenPoint {
    /// From sub-pixel coordinates.
    #[must_use]
    pub const fn new(x: i32, y: i32) -> Self {
        ScreenPoint { x, y }
    }

    /// The centre of pixel `(px, py)` (saturating for pixels beyond the coordinate range).
    #[must_use]
    pub const fn pixel_center(px: i32, py: i32) -> Self {
        let h = SUBPIXEL_SCALE / 2;
        ScreenPoint {
            x: px.saturating_mul(SUBPIXEL_SCALE).saturating_add(h),
            y: py.saturating_mul(SUBPIXEL_SCALE).saturating_add(h),
        }
    }

    pub(crate) const fn in_range(self) -> bool {
        self.x.unsigned_abs() <= COORD_LIMIT as u32 && self.y.unsigned_abs() <= COORD_LIMIT as u32
    }
}

/// A rectangle of whole pixels, `[x0, x1) × [y0, y1)`: where a rasteriser may draw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct PixelRect {
    /// First column.
    pub x0: i32,
    /// First row.
    pub y0: i32,
    /// One past the last column.
    pub x1: i32,
    /// One past the last row.
    pub y1: i32,
}

impl PixelRect {
    /// The rectangle `[x0, x1) × [y0, y1)`.
    #[must_use]
    pub const fn new(x0: i32, y0: i32, x1: i32, y1: i32) -> Self {
        PixelRect { x0, y0, x1, y1 }
    }

    /// `[0, width) × [0, height)`.
    #[must_use]
    pub const fn of_size(width: u32, height: u32) -> Self {
        let w = if width > i32::MAX as u32 {
            i32::MAX
        } else {
            width as i32
        };
        let h = if height > i32::MAX as u32 {
            i32::MAX
        } else {
            height as i32
        };
        PixelRect::new(0, 0, w, h)
    }

    /// The pixels of an embedded-graphics rectangle (saturated at the ends of the i32 range).
    #[must_use]
    pub fn from_rectangle(r: &Rectangle) -> Self {
        let (x, y) = (r.top_left.x, r.top_left.y);
        let w = r.size.width.min(i32::MAX as u32) as i32;
        let h = r.size.height.min(i32::MAX as u32) as i32;
        PixelRect::new(x, y, x.saturating_add(w), y.saturating_add(h))
    }

    /// True when the rectangle holds no pixel.
    #[must_use]
    pub const fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }

    /// True when pixel `(x, y)` lies inside.
    #[must_use]
    pub const fn contains(&self, x: i32, y: i32) -> bool {
        x >= self.x0 && x < self.x1 && y >= self.y0 && y < self.y1
    }
}

/// [`doubled_area`] of a triangle whose sides are known to lie within ±2¹⁵, in 32-bit words
/// without testing them (which `doubled_area` does first on cores without a long multiply).
#[inline(always)]
pub(crate) fn short_sides_area(a: ScreenPoint, b: ScreenPoint, c: ScreenPoint) -> i64 {
    let (ux, uy) = (b.x.wrapping_sub(a.x), b.y.wrapping_sub(a.y));
    let (vx, vy) = (c.x.wrapping_sub(a.x), c.y.wrapping_sub(a.y));
    short_sides_cross(ux, uy, vx, vy)
}

/// Twice the signed area of triangle `a b c` (y down: negative when counter-clockwise on
/// screen), exactly. Coordinates must lie within ±[`COORD_LIMIT`].
#[inline]
pub(crate) fn doubled_area(a: ScreenPoint, b: ScreenPoint, c: ScreenPoint) -> i64 {
    area_in_words(a, b, c)
}

/// [`doubled_area`] from 32-bit sides (coordinates within ±2²⁴), as 32-bit cores take it: the
/// second product accumulated onto the first with one side negated, one widening multiply and
/// one multiply-accumulate on Cortex-M3/M4 where a difference of products takes two
/// instructions more. Tested on every host.
#[inline(always)]
fn area_in_words(a: ScreenPoint, b: ScreenPoint, c: ScreenPoint) -> i64 {
    let (ux, vy) = (b.x.wrapping_sub(a.x), c.y.wrapping_sub(a.y));
    let (vx, neg_uy) = (c.x.wrapping_sub(a.x), a.y.wrapping_sub(b.y));
    mul_wide(ux, vy).wrapping_add(mul_wide(vx, neg_uy))
}

/// The first pixel whose centre lies at or right of (below) sub-pixel coordinate `v`:
/// `ceil((v − 8) / 16)`, by a shift.
#[inline]
pub(crate) const fn first_centre_from(v: i64) -> i64 {
    (v + (SUBPIXEL_SCALE as i64 / 2 - 1)) >> crate::math::SUBPIXEL_BITS
}

/// [`first_centre_from`] in 32-bit words, for coordinates within ±2²⁴ (where a 64-bit sum and
/// shift take twice the instructions).
#[inline(always)]
pub(crate) const fn first_centre_from32(v: i32) -> i32 {
    v.wrapping_add(SUBPIXEL_SCALE / 2 - 1) >> crate::math::SUBPIXEL_BITS
}

/// `ceil(n / d)` for `d > 0`: [`floor_div`] of `n + d − 1` (`−floor(−n / d)` where that
/// would overflow).
pub(crate) fn ceil_div(n: i64, d: i64) -> i64 {
    match n.checked_add(d - 1) {
        Some(m) => floor_div(m, d),
        None => floor_div(n.saturating_neg(), d).saturating_neg(),
    }
}

/// `floor(n / d)` for `d > 0`: in words where both fit 32 bits (a 64-bit division is a long
/// library routine on 32-bit cores).
pub(crate) fn floor_div(n: i64, d: i64) -> i64 {
    if let (Ok(n32), Ok(d32)) = (i32::try_from(n), i32::try_from(d)) {
        return i64::from(n32.div_euclid(d32));
    }
    n.div_euclid(d)
}

/// `(floor(n / d), n mod d)` for `d > 0`, the remainder in `[0, d)`: [`floor_divmod32`] where
/// the operands fit 32 bits.
#[inline]
pub(crate) fn floor_divmod(n: i64, d: i64) -> (i64, i64) {
    // In words where the operands fit: a 64-bit division is a long library routine on 32-bit
    // cores.
    if let (Ok(n32), Ok(d32)) = (i32::try_from(n), i32::try_from(d)) {
        let (q, r) = floor_divmod32::<SHORT_QUOTIENT>(n32, d32);
        return (q as i64, r as i64);
    }
    let (q, r) = (n / d, n % d);
    if r < 0 {
        (q - 1, r + d)
    } else {
        (q, r)
    }
}

/// Quotients [`small_floor_divmod32`] finds by subtraction before a library division, for lines:
/// many lines are flat, and the turns a larger quotient takes before the division are lost.
const SHORT_QUOTIENT: i32 = 2;

/// [`SHORT_QUOTIENT`] for a triangle's edges, whose quotients are the pixels a row steps and
/// the first row's offset (16 measured best there; lines, many of them flatter, keep 2).
const EDGE_SHORT_QUOTIENT: i32 = 16;

/// [`floor_divmod`] of 32-bit operands (`d > 0`) for quotients in `[−SHORT, SHORT)` (shallow
/// edges), by repeated subtraction; `None` otherwise. A negative `n` counts the subtractions
/// of `⌈−n / d⌉ = ⌊(−n + d − 1) / d⌋` instead, so that both signs take [`subtract_below`]'s
/// loop of a test, a subtraction and a count a turn (one loop telling the signs apart took
/// half as many again; a loop adding `d` back to a negative `n` the compiler turned into a
/// library division).
#[inline(always)]
fn small_floor_divmod32<const SHORT: i32>(n: i32, d: i32) -> Option<(i32, i32)> {
    let d = d as u32;
    if n >= 0 {
        let (q, r) = subtract_below(n as u32, d, SHORT as u32)?;
        return Some((q as i32, r as i32));
    }
    // −n ≤ 2³¹ and d − 1 < 2³¹: no overflow. k ≤ SHORT, r in [0, d).
    let m = (n as u32).wrapping_neg().wrapping_add(d.wrapping_sub(1));
    let (k, rem) = subtract_below(m, d, SHORT as u32 + 1)?;
    Some((
        (k as i32).wrapping_neg(),
        d.wrapping_sub(1).wrapping_sub(rem) as i32,
    ))
}

/// `(⌊m / d⌋, m mod d)` for `d > 0` and quotients below `turns`, by repeated subtraction;
/// `None` otherwise.
#[inline(always)]
fn subtract_below(mut m: u32, d: u32, turns: u32) -> Option<(u32, u32)> {
    for q in 0..turns {
        if m < d {
            return Some((q, m));
        }
        m = m.wrapping_sub(d);
    }
    None
}

/// [`floor_divmod`] of 32-bit operands (`d > 0`), quotients in `[−SHORT, SHORT)` found by
/// subtraction where division is a library routine.
#[inline]
fn floor_divmod32<const SHORT: i32>(n: i32, d: i32) -> (i32, i32) {
    if NARROW_CORE {
        if let Some(qr) = small_floor_divmod32::<SHORT>(n, d) {
            return qr;
        }
    }
    let (q, r) = (n.wrapping_div(d), n.wrapping_rem(d));
    if r < 0 {
        (q.wrapping_sub(1), r.wrapping_add(d))
    } else {
        (q, r)
    }
}

/// Walks `ceil(N(k) / D)` or `floor(N(k) / D)` for `N(k) = N0 + k·step` over consecutive
/// integers `k`, exactly, with an i32 quotient and remainder (Bresenham's error term). Used for
/// triangle edges (ceil) and lines (floor).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RationalStepper<const CEIL: bool> {
    /// The current value.
    pub value: i32,
    /// `value·D − N` for ceil (in `[0, D)`), `N − value·D` for floor (in `[0, D)`).
    rem: i32,
    den: i32,
    step_q: i32,
    step_r: i32,
}

/// Steps `ceil(N(k) / D)` (triangle edges).
pub(crate) type CeilStepper = RationalStepper<true>;
/// Steps `floor(N(k) / D)` (lines).
pub(crate) type FloorStepper = RationalStepper<false>;

impl<const CEIL: bool> RationalStepper<CEIL> {
    /// The constant 0 (for iterators that yield nothing, which never step it). A ceiling
    /// walk's is all zero bytes, so that memory holding some is cleared rather than copied
    /// from a constant; a floor walk's keeps a denominator of 1.
    pub(crate) const ZERO: Self = RationalStepper {
        value: 0,
        rem: 0,
        den: if CEIL { 0 } else { 1 },
        step_q: 0,
        step_r: 0,
    };

    /// Starts at `n0 / den` (den > 0, den < 2³¹; the quotient and `step / den` must fit i32).
    pub(crate) fn new(n0: i64, den: i64, step: i64) -> Self {
        // Callers pass den ≥ 1; the guard keeps a wrong call from dividing by zero.
        let den = den.max(1);
        let (q, r) = floor_divmod(n0, den);
        // Callers keep coordinates within ±COORD_LIMIT (2²⁴ sub-pixels): the denominator is
        // below 2²⁹, remainders below it, quotients (pixel coordinates) below 2²¹ and steps below
        // 2²⁹, so every value fits i32 and the casts are exact.
        Self::from_quotient(q as i32, r as i32, den as i32, step as i32)
    }

    /// [`new`](Self::new) of 32-bit operands (where 64-bit division is a library routine, the
    /// numerator of an edge started within its top pixel fits 32 bits).
    pub(crate) fn new32(n0: i32, den: i32, step: i32) -> Self {
        let den = den.max(1);
        let (q, r) = floor_divmod32::<EDGE_SHORT_QUOTIENT>(n0, den);
        Self::from_quotient(q, r, den, step)
    }

    /// The stepper at `n0 = q·den + r` (`0 ≤ r < den`).
    #[inline(always)]
    fn from_quotient(q: i32, r: i32, den: i32, step: i32) -> Self {
        let (value, rem) = if CEIL && r != 0 {
            (q.wrapping_add(1), den.wrapping_sub(r))
        } else {
            (q, r)
        };
        // For ceil the step subtracts from rem (rem = qD − N), for floor it adds. Ceiling
        // walks are a triangle's edges, floor walks lines.
        let (step_q, step_r) = if CEIL {
            floor_divmod32::<EDGE_SHORT_QUOTIENT>(step, den)
        } else {
            floor_divmod32::<SHORT_QUOTIENT>(step, den)
        };
        RationalStepper {
            value,
            rem,
            den,
            step_q,
            step_r,
        }
    }

    /// Advances `k` by one: the value moves by the whole part of the step, or by one more when
    /// the remainder wraps.
    #[inline(always)]
    pub(crate) fn step(&mut self) {
        self.value = self.value.wrapping_add(self.step_q);
        let carry = if CEIL {
            // rem = value·D − N stays in [0, D): a negative rem borrows one more.
            self.rem = self.rem.wrapping_sub(self.step_r);
            self.rem < 0
        } else {
            // rem = N − value·D stays in [0, D): a rem of D or more carries one more.
            self.rem = self.rem.wrapping_add(self.step_r);
            self.rem >= self.den
        };
        if carry {
            self.rem = if CEIL {
                self.rem.wrapping_add(self.den)
            } else {
                self.rem.wrapping_sub(self.den)
            };
            self.value = self.value.wrapping_add(1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 32-bit cores' area equals the 64-bit one: at the corners of the coordinate range
    /// (sides up to 2²⁵, products up to 2⁵⁰) and at random.
    #[test]
    fn area_in_words_equals_wide() {
        let wide = |a: ScreenPoint, b: ScreenPoint, c: ScreenPoint| {
            let d = |p: i32, q: i32| p as i64 - q as i64;
            d(b.x, a.x) * d(c.y, a.y) - d(c.x, a.x) * d(b.y, a.y)
        };
        let ends = [-COORD_LIMIT, COORD_LIMIT, 0, 1, -1];
        let end = |k: usize| ends[k % ends.len()];
        for k in 0..5usize.pow(6) {
            let p = |j: u32| {
                ScreenPoint::new(end(k / 5usize.pow(2 * j)), end(k / 5usize.pow(2 * j + 1)))
            };
            let (a, b, c) = (p(0), p(1), p(2));
            assert_eq!(area_in_words(a, b, c), wide(a, b, c), "{a:?} {b:?} {c:?}");
        }
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..100_000 {
            let mut p = || ScreenPoint::new(rng.within(COORD_LIMIT), rng.within(COORD_LIMIT));
            let (a, b, c) = (p(), p(), p());
            assert_eq!(area_in_words(a, b, c), wide(a, b, c), "{a:?} {b:?} {c:?}");
        }
    }

    /// The 32-bit stepper set-up (of an edge started within its top pixel) starts where the
    /// 64-bit one does, and both step alike: numerators and steps within ±2²⁹, every
    /// denominator size.
    #[test]
    fn stepper_set_up_in_32_bits_equals_64() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let fields = |s: &CeilStepper| (s.value, s.rem, s.den, s.step_q, s.step_r);
        for _ in 0..200_000 {
            let x = rng.next_u64();
            let den = (((x >> 40) as i32) >> (x % 24)).max(1);
            let (n0, step) = (rng.within(1 << 29), rng.within(1 << 29));
            let (mut a, mut b) = (
                CeilStepper::new32(n0, den, step),
                CeilStepper::new(n0 as i64, den as i64, step as i64),
            );
            assert_eq!(fields(&a), fields(&b), "{n0} {den} {step}");
            a.step();
            b.step();
            assert_eq!(fields(&a), fields(&b), "{n0} {den} {step}");
        }
    }

    /// Floor and ceiling quotients, in words and in 64 bits, equal the definitions at the
    /// edges of 32 bits, at the ends of i64 and at random.
    #[test]
    fn floor_and_ceiling_quotients() {
        let by_i128 = |n: i64, d: i64| {
            let (n, d) = (i128::from(n), i128::from(d));
            (n.div_euclid(d), -(-n).div_euclid(d))
        };
        let mut rng = crate::testing::XorShift(0x1234_5678_9ABC_DEF1);
        let edges = [
            0,
            1,
            2,
            15,
            16,
            17,
            i64::from(i32::MAX),
            i64::from(i32::MAX) + 1,
            i64::MAX,
        ];
        let mut values: std::vec::Vec<i64> =
            edges.iter().flat_map(|&e| [e, -e, e - 1, -e + 1]).collect();
        values.extend((0..2_000).map(|k| (rng.next_u64() as i64) >> (k % 64)));
        values.push(i64::MIN);
        let mut checked = 0;
        for &n in &values {
            for &d in &values {
                if d <= 0 {
                    continue;
                }
                let (floor, ceil) = by_i128(n, d);
                assert_eq!(i128::from(floor_div(n, d)), floor, "{n} / {d}");
                assert_eq!(i128::from(ceil_div(n, d)), ceil, "{n} / {d}");
                checked += 1;
            }
        }
        assert!(checked > 1_000_000, "{checked}");
    }

    /// `floor_divmod` is floor division, and the division-free quotients of 32-bit operands
    /// (used where division is a library routine, so not on the host) equal it wherever they
    /// answer, and answer for quotients from −SHORT to SHORT − 1: at random, and at the ends of
    /// i32 for both operands.
    #[test]
    fn small_quotients_equal_floor_division() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let ends = [i32::MIN, i32::MIN + 1, -17, -16, -1, 0, 1, 15, 16, i32::MAX];
        let ends = ends.iter().flat_map(|&n| {
            [1, 2, 3, 1 << 27, (1 << 27) + 1, 1 << 30, i32::MAX].map(|d| (n as i64, d as i64))
        });
        let random = (0..200_000).map(|_| {
            let x = rng.next_u64();
            let d = ((x >> 40) as i64 >> (x % 24)).max(1);
            (((x as i64) >> (x % 64)) % (20 * d + 1), d)
        });
        for (n, d) in ends.collect::<std::vec::Vec<_>>().into_iter().chain(random) {
            assert_eq!(floor_divmod(n, d), (n.div_euclid(d), n.rem_euclid(d)));
            if let (Ok(n), Ok(d)) = (i32::try_from(n), i32::try_from(d)) {
                let expected = (n.div_euclid(d), n.rem_euclid(d));
                for (found, short) in [
                    (small_floor_divmod32::<SHORT_QUOTIENT>(n, d), SHORT_QUOTIENT),
                    (
                        small_floor_divmod32::<EDGE_SHORT_QUOTIENT>(n, d),
                        EDGE_SHORT_QUOTIENT,
                    ),
                ] {
                    // An answer for every quotient in range, none outside it.
                    let in_range = (-short..short).contains(&expected.0);
                    assert_eq!(found, in_range.then_some(expected), "{n} / {d}");
                }
                assert_eq!(floor_divmod32::<SHORT_QUOTIENT>(n, d), expected);
            }
        }
    }
}

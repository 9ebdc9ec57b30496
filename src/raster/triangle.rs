//! Scanline triangle fill with the top-left rule.
//!
//! Vertices are sorted by y and the triangle is split at the middle vertex. Each row's sample
//! line `y = 16·py + 8` meets the long edge (top to bottom vertex) and one short edge. An edge
//! from `p` to `q` (`p.y < q.y`) crosses it at `x(y) = p.x + (q.x − p.x)(y − p.y)/(q.y − p.y)`,
//! and pixel `px` lies right of that crossing when `16·px + 8 ≥ x(y)`. So both span ends are
//! `ceil((x(y) − 8) / 16)`: on the left edge the bound is inclusive (a centre on a left edge is
//! covered), on the right edge exclusive (a centre on a right edge is not). Rows are those with
//! `y0 ≤ 16·py + 8 < y2`, which makes a flat top edge inclusive and a flat bottom edge
//! exclusive: the top-left rule, exactly. The crossings are rationals stepped from row to row
//! with an integer quotient and remainder, so no precision is lost however long the edge (on
//! 64-bit hosts the remainder is a rounded-up fraction of 2³² beside the quotient, one
//! addition a row, and its proven bound decides how often an edge is set up again; on 32-bit
//! cores with a divide instruction the numerator itself steps, in one word whose bound decides
//! the same, and each row divides it once).

#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
use super::floor_div;
#[cfg(not(any(
    target_pointer_width = "64",
    all(target_pointer_width = "32", target_has_atomic = "32")
)))]
use super::CeilStepper;
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
use super::DivideStepper;
#[cfg(test)]
use super::Plane;
use super::{doubled_area, first_centre_from32, PixelRect, ScreenPoint};
#[cfg(any(doc, target_pointer_width = "64"))]
use super::{fraction_rows, FractionStepper};
#[cfg(not(any(
    target_pointer_width = "64",
    all(target_pointer_width = "32", target_has_atomic = "32")
)))]
use crate::math::NARROW_CORE;
#[cfg(any(test, not(target_pointer_width = "64")))]
use crate::math::SUBPIXEL_BITS;
use crate::math::{mul_wide, SUBPIXEL_SCALE};

const S: i64 = SUBPIXEL_SCALE as i64;
const HALF: i64 = S / 2;

/// The walk of an edge's span ends: on 64-bit hosts [`FractionStepper`], one addition a row,
/// which a triangle re-seeds from its vertices every [`fraction_rows`] rows (triangles the
/// pipeline draws never need it: at most 2¹² rows of edges below 2¹⁶ sub-pixels); on 32-bit
/// cores that divide words in one instruction (Cortex-M3/M4; told apart as in
/// [`NARROW_CORE`](crate::math::NARROW_CORE)) [`DivideStepper`], one addition and one division
/// a row, re-seeded every [`division_rows`] rows (never for triangles the pipeline draws);
/// elsewhere the exact [`CeilStepper`](super::CeilStepper), whose set-up needs no 64-bit
/// division (a library routine on 32-bit cores).
#[cfg(target_pointer_width = "64")]
pub(crate) type EdgeWalk = FractionStepper;
/// The walk of an edge's span ends: see the 64-bit definition.
#[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
pub(crate) type EdgeWalk = DivideStepper;
/// The walk of an edge's span ends: see the 64-bit definition.
#[cfg(not(any(
    target_pointer_width = "64",
    all(target_pointer_width = "32", target_has_atomic = "32")
)))]
pub(crate) type EdgeWalk = CeilStepper;

/// One row of covered pixels: `x0..x1` (exclusive) on row `y`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Span {
    /// The pixel row.
    pub y: i32,
    /// First covered pixel.
    pub x0: i32,
    /// One past the last covered pixel (`x1 > x0`).
    pub x1: i32,
}

/// The spans of one triangle, top to bottom, clipped to a rectangle: see [`triangle_spans`].
#[derive(Clone, Debug)]
pub struct TriangleSpans {
    v: [ScreenPoint; 3],
    y: i32,
    y_end: i32,
    /// The row where the short edge switches to the lower one (`i32::MIN` once switched).
    y_split: i32,
    /// The row where both edges are set up again from the vertices (`i32::MAX`: never; see
    /// [`EdgeWalk`]).
    #[cfg(any(
        target_pointer_width = "64",
        all(target_pointer_width = "32", target_has_atomic = "32")
    ))]
    y_reseed: i32,
    /// Rows from one seeding to the next (`u32::MAX`: one seeding serves the triangle), which
    /// each edge's set-up needs: see [`division_rows`].
    #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
    seed_rows: u32,
    left: EdgeWalk,
    right: EdgeWalk,
    long_is_left: bool,
    x_min: i32,
    x_max: i32,
}

/// The pixels a triangle covers, as spans clipped to `clip`, by the top-left rule (see the
/// [module documentation](super)). Either winding is accepted; a triangle of zero area, or one
/// with a coordinate beyond [`COORD_LIMIT`](super::COORD_LIMIT), yields nothing.
///
/// Work is proportional to the rows of `clip` the triangle spans, whatever its size.
///
/// ```
/// use fixed3d::raster::{triangle_spans, PixelRect, ScreenPoint, Span};
/// // A 4x4 pixel square's lower-left half, corners on pixel corners (16 sub-pixels per pixel).
/// let p = |x, y| ScreenPoint::new(x * 16, y * 16);
/// let spans: Vec<Span> =
///     triangle_spans([p(0, 0), p(4, 4), p(0, 4)], PixelRect::of_size(8, 8)).collect();
/// // Centres on the diagonal lie on this triangle's right edge: not covered, so row 0 is empty.
/// assert_eq!(spans[0], Span { y: 1, x0: 0, x1: 1 });
/// assert_eq!(spans.iter().map(|s| s.x1 - s.x0).sum::<i32>(), 6);
/// ```
#[must_use]
pub fn triangle_spans(v: [ScreenPoint; 3], clip: PixelRect) -> TriangleSpans {
    if !v.iter().all(|p| p.in_range()) {
        return TriangleSpans::empty(v);
    }
    let [a, b, c] = v;
    let area = doubled_area(a, b, c);
    // Zero area covers nothing (rule R4).
    if area == 0 || clip.is_empty() {
        return TriangleSpans::empty(v);
    }
    // Larger triangles than the pipeline's may need their edges set up again on the way down.
    #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
    let seed_rows = division_rows(&v);
    #[cfg(not(all(target_pointer_width = "32", target_has_atomic = "32")))]
    let seed_rows = u32::MAX;
    spans_in_range(v, clip, area, seed_rows)
}

/// [`triangle_spans`] of points within ±[`COORD_LIMIT`](super::COORD_LIMIT) whose doubled
/// signed area (in the given order, see `doubled_area`) the caller has, not zero, and whose
/// edges walk `seed_rows` rows from each set-up ([`division_rows`]; only [`DivideStepper`]
/// edges need it, others take `u32::MAX`). The pipeline's triangles, whose vertices lie within
/// ±[`PIPELINE_LIMIT`](super::PIPELINE_LIMIT), pass `u32::MAX` on every core: that is their
/// `division_rows` (their width and height are at most 2¹⁶ − 32), and in line it is a constant,
/// so that the row loop carries no check. Neither the area nor `clip` is tested here: the
/// pipeline draws no triangle of zero area, and a `clip` without rows or columns holds no span
/// of any triangle.
#[cfg_attr(
    all(target_pointer_width = "32", target_has_atomic = "32"),
    inline(always)
)]
pub(crate) fn spans_in_range(
    v: [ScreenPoint; 3],
    clip: PixelRect,
    area: i64,
    seed_rows: u32,
) -> TriangleSpans {
    match rows_in_range(v, clip, area) {
        Some(rows) => rows.spans((clip.x0, clip.x1), seed_rows),
        None => TriangleSpans::empty(v),
    }
}

/// A triangle's rows in a clip rectangle before any edge is set up ([`rows_in_range`]): its
/// vertices sorted by y, its first row and the row past its last, the middle vertex's row
/// clamped to them, and the side of the long edge. Its spans come from [`spans`](Self::spans);
/// for a target's own row loop its runs from `runs`, each edge set up where the loop reads it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TriangleRows {
    v: [ScreenPoint; 3],
    y: i32,
    y_end: i32,
    y_split: i32,
    long_is_left: bool,
}

/// The rows of `clip` that the triangle `v` covers (see [`spans_in_range`], whose arguments
/// these are); `None` where it covers none.
#[cfg_attr(
    all(target_pointer_width = "32", target_has_atomic = "32"),
    inline(always)
)]
pub(crate) fn rows_in_range(
    v: [ScreenPoint; 3],
    clip: PixelRect,
    area: i64,
) -> Option<TriangleRows> {
    let ([a, b, c], odd) = sort_by_y(v);
    // Coordinates within ±2²⁴: the first row at or below each in 32-bit words.
    let first_row = first_centre_from32;
    let y = first_row(a.y).max(clip.y0);
    let y_end = first_row(c.y).min(clip.y1);
    if y >= y_end {
        return None;
    }
    // The middle vertex lies right of the long edge when the sorted triangle's doubled area
    // is positive (y down; an odd permutation turns the sign): the long edge is then the left
    // one.
    Some(TriangleRows {
        v: [a, b, c],
        y,
        y_end,
        y_split: first_row(b.y).clamp(y, y_end),
        long_is_left: (area > 0) != odd,
    })
}

impl TriangleRows {
    /// The first row.
    #[inline(always)]
    pub(crate) fn row(&self) -> i32 {
        self.y
    }

    /// The spans of these rows clipped to the columns `x_min..x_max`, their edges walking
    /// `seed_rows` rows from each set-up (see [`spans_in_range`]).
    #[inline(always)]
    pub(crate) fn spans(self, (x_min, x_max): (i32, i32), seed_rows: u32) -> TriangleSpans {
        let TriangleRows {
            v: [a, b, c],
            y,
            y_end,
            y_split,
            long_is_left,
        } = self;
        #[cfg(target_pointer_width = "64")]
        let y_reseed = reseed_row(y, y_end, c.y.wrapping_sub(a.y));
        #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
        let y_reseed = after_rows(y, seed_rows);
        let long = edge(a, c, y, seed_rows);
        let (short, y_split) = if y < y_split {
            (edge(a, b, y, seed_rows), y_split)
        } else {
            (edge(b, c, y, seed_rows), i32::MIN)
        };
        let (left, right) = if long_is_left {
            (long, short)
        } else {
            (short, long)
        };
        TriangleSpans {
            v: [a, b, c],
            y,
            y_end,
            y_split,
            #[cfg(any(
                target_pointer_width = "64",
                all(target_pointer_width = "32", target_has_atomic = "32")
            ))]
            y_reseed,
            #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
            seed_rows,
            left,
            right,
            long_is_left,
            x_min,
            x_max,
        }
    }
}

/// The stepper for `ceil((x(16·py + 8) − 8) / 16)` along edge `p → q` (`p.y < q.y`), at row `py`
/// (one of the edge's rows), for `rows` rows from there (`u32::MAX`: to the edge's end; only
/// [`DivideStepper`] edges need it). With coordinates within ±2²⁴ every difference below is a
/// 32-bit factor, the numerator stays below 2⁵⁴ and the denominator below 2²⁹.
#[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
#[inline(always)]
fn edge(p: ScreenPoint, q: ScreenPoint, py: i32, rows: u32) -> EdgeWalk {
    if rows == u32::MAX {
        edge_by_division_call(p, q, py)
    } else {
        edge_by_division_for(p, q, py, rows)
    }
}

/// [`edge_by_division`] as a call: the edges of the spans and the lower edge of the runs.
#[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
#[inline(never)]
fn edge_by_division_call(p: ScreenPoint, q: ScreenPoint, py: i32) -> DivideStepper {
    edge_by_division(p, q, py)
}

/// [`edge`] where the walk is not a [`DivideStepper`] (which alone needs `rows`).
#[cfg(not(all(target_pointer_width = "32", target_has_atomic = "32")))]
// On x86-64 in line, as the runs that call it are (see `TriangleRows::runs`).
#[cfg_attr(target_pointer_width = "64", inline(always))]
fn edge(p: ScreenPoint, q: ScreenPoint, py: i32, _rows: u32) -> EdgeWalk {
    // Without a hardware divide, the whole pixels of p.x − 8 come out by a shift:
    // ceil(((16k + m)·dy + …) / 16dy) = k + ceil((m·dy + …) / 16dy), a small quotient for
    // steep edges started at their top, found without dividing (see `floor_divmod`).
    let (dx, dy, x, t) = edge_terms(p, q, py);
    let dy = dy.max(1);
    let (den, step) = (S * dy as i64, S * dx as i64);
    // (Narrow cores are 32-bit: their edge walk is the exact stepper.)
    #[cfg(not(any(
        target_pointer_width = "64",
        all(target_pointer_width = "32", target_has_atomic = "32")
    )))]
    if NARROW_CORE {
        let (k, m) = (x >> SUBPIXEL_BITS, x & (S as i32 - 1));
        // Started within its top pixel (0 ≤ t < 16, the usual case) both products are below
        // 2²⁹ (sides below 2²⁵), and so is the denominator: 32-bit operands throughout, where
        // 64-bit products and divisions are library calls.
        let mut e = if (0..S as i32).contains(&t) {
            CeilStepper::new32(m * dy + dx * t, den as i32, step as i32)
        } else {
            CeilStepper::new(mul_wide(m, dy) + mul_wide(dx, t), den, step)
        };
        e.value = e.value.wrapping_add(k);
        return e;
    }
    EdgeWalk::new(mul_wide(x, dy) + mul_wide(dx, t), den, step)
}

/// An edge `p → q` at row `py` as the numerator `N = (p.x − 8)·dy + dx·t` over `D = 16·dy` (`t
/// = 16·py + 8 − p.y`, the sample line's offset from `p`), whose ceiling is the span end
/// `ceil((x(y) − 8) / 16)`: `(dx, dy, N's first term's factor p.x − 8, t)`. Every edge walk
/// starts from these. `dy` is positive for every edge with rows (a row's sample line lies in
/// `[p.y, q.y)`); a caller that divides by it keeps it so itself.
#[inline(always)]
fn edge_terms(p: ScreenPoint, q: ScreenPoint, py: i32) -> (i32, i32, i32, i32) {
    let dx = q.x.wrapping_sub(p.x);
    let dy = q.y.wrapping_sub(p.y);
    let x = p.x.wrapping_sub(HALF as i32);
    // The row lies within the edge's rows: |16·py| below 2²⁵.
    let t = py
        .wrapping_mul(S as i32)
        .wrapping_add(HALF as i32)
        .wrapping_sub(p.y);
    (dx, dy, x, t)
}

/// The [`DivideStepper`] of an edge from `base`: `N − base·D` is `(x − 16·base)·dy + dx·t` modulo
/// 2³², which the caller's base keeps in `[0, 2³² − D]`.
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
#[inline(always)]
fn stepper_from(dx: i32, dy: i32, x: i32, t: i32, base: i32) -> DivideStepper {
    let above = (x.wrapping_sub(base.wrapping_mul(S as i32)) as u32)
        .wrapping_mul(dy as u32)
        .wrapping_add(dx.wrapping_mul(t) as u32);
    let den = dy.wrapping_mul(S as i32) as u32;
    DivideStepper::new(above, den, dx.wrapping_mul(S as i32) as u32, base)
}

/// [`edge`] as a [`DivideStepper`] for all of the edge's rows, from the base
/// `b = ⌊(min(p.x, q.x) − 8) / 16⌋`, no division. On the edge's rows (`0 ≤ t < dy`) the crossing
/// `N / dy = p.x − 8 + dx·t / dy` lies between `min − 8` and `max − 8`, and `min − 8 − 16b` in
/// `[0, 15]`, so `0 ≤ N − b·D ≤ 15·dy + |dx|·(dy − 1)`, and with the ceiling's `D − 1` the
/// stepper's word is at most `(|dx| + 31)·dy − 1`: below 2³² wherever [`division_rows`] is
/// `u32::MAX`.
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
#[inline(always)]
fn edge_by_division(p: ScreenPoint, q: ScreenPoint, py: i32) -> DivideStepper {
    let (dx, dy, x, t) = edge_terms(p, q, py);
    let base = p.x.min(q.x).wrapping_sub(HALF as i32) >> SUBPIXEL_BITS;
    stepper_from(dx, dy, x, t, base)
}

/// [`edge`] as a [`DivideStepper`] for `rows` rows from `py` (any
/// `rows` from 1 to [`division_rows`]' quotient), from the row's own quotient: the base
/// `b = ⌊N / D⌋`, less `⌈|dx|·rows / dy⌉` for an edge that runs left. Over `k < rows` steps
/// `N + 16·dx·k − b·D` then lies in `[0, 2·D + 16·|dx|·rows)`, and with the ceiling's `D − 1`
/// the stepper's word is below `48·dy + 16·|dx|·rows < 2³²` (`dy ≤ 2²⁵`, `|dx|·rows < 2²⁷`).
/// One 64-bit division: only triangles far larger than the pipeline's take this.
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
#[inline(never)]
fn edge_by_division_for(p: ScreenPoint, q: ScreenPoint, py: i32, rows: u32) -> DivideStepper {
    let (dx, dy, x, t) = edge_terms(p, q, py);
    let dy = dy.max(1);
    let n = mul_wide(x, dy).wrapping_add(mul_wide(dx, t));
    let back = if dx < 0 {
        // |dx|·rows < 2²⁷ and dy ≤ 2²⁵: no overflow.
        dx.unsigned_abs().wrapping_mul(rows).div_ceil(dy as u32) as i32
    } else {
        0
    };
    // The quotient is a pixel column within ±2²¹; the denominator is at least 16.
    let den = S.wrapping_mul(dy as i64).max(1);
    let base = (floor_div(n, den) as i32).wrapping_sub(back);
    stepper_from(dx, dy, x, t, base)
}

/// The rows a triangle's [`DivideStepper`] edges walk from one set-up:
/// with `W` its width and `H` its height in sub-pixels, `u32::MAX` (all of them, see
/// [`edge_by_division`]) where `(W + 31)·H ≤ 2³²`, which holds for every triangle within
/// ±[`PIPELINE_LIMIT`](super::PIPELINE_LIMIT) (`W, H ≤ 2¹⁶ − 32`); otherwise
/// `⌊(2²⁷ − 1) / W⌋`, at least 3 within ±[`COORD_LIMIT`](super::COORD_LIMIT) (see
/// [`edge_by_division_for`]).
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
fn division_rows(v: &[ScreenPoint; 3]) -> u32 {
    let [a, b, c] = *v;
    let (x_min, x_max) = (a.x.min(b.x).min(c.x), a.x.max(b.x).max(c.x));
    let (y_min, y_max) = (a.y.min(b.y).min(c.y), a.y.max(b.y).max(c.y));
    // Within ±2²⁴: both below 2²⁶.
    let w = x_max.wrapping_sub(x_min) as u32;
    let h = y_max.wrapping_sub(y_min) as u32;
    if (w as u64 + 31) * h as u64 <= 1 << 32 {
        u32::MAX
    } else {
        ((1 << 27) - 1) / w.max(1)
    }
}

/// The row `rows` rows after `y` (`i32::MAX` for `u32::MAX`, or past `i32::MAX`).
#[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
#[inline(always)]
fn after_rows(y: i32, rows: u32) -> i32 {
    if rows == u32::MAX {
        return i32::MAX;
    }
    y.saturating_add(rows.min(i32::MAX as u32) as i32)
}

/// The row after the last one that edges set up at row `y` walk exactly, for a triangle whose
/// rows end at `y_end` and whose long edge is `dy` sub-pixels tall (the others are shorter, so
/// their denominators smaller): `i32::MAX` when that is beyond the triangle.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn reseed_row(y: i32, y_end: i32, dy: i32) -> i32 {
    // An edge at most 2¹⁵ sub-pixels tall, by one comparison: its rows (at most dy/16 + 1 pixel
    // centres lie in its dy sub-pixels) times its denominator less one stay below (dy/16 +
    // 1)·16·dy = dy² + 16·dy ≤ 2³⁰ + 2¹⁹, within 2³².
    if (dy as u32) <= 1 << 15 {
        return i32::MAX;
    }
    // Sorted and within ±2²⁴: 0 ≤ dy ≤ 2²⁵, so the denominator fits i32, and y < y_end.
    let den = dy.wrapping_mul(S as i32);
    let rows = y_end.wrapping_sub(y) as u32 as u64;
    // The usual case by a product, not `fraction_rows`' division.
    if rows * (den.max(1) as u64 - 1) < 1 << 32 {
        return i32::MAX;
    }
    y.saturating_add(fraction_rows(den).min(i32::MAX as u32) as i32)
}

/// The points sorted by y, and whether the sort was an odd permutation (one or three swaps).
fn sort_by_y(v: [ScreenPoint; 3]) -> ([ScreenPoint; 3], bool) {
    let [mut a, mut b, mut c] = v;
    let mut odd = false;
    if b.y < a.y {
        core::mem::swap(&mut a, &mut b);
        odd = !odd;
    }
    if c.y < b.y {
        core::mem::swap(&mut b, &mut c);
        odd = !odd;
    }
    if b.y < a.y {
        core::mem::swap(&mut a, &mut b);
        odd = !odd;
    }
    ([a, b, c], odd)
}

impl TriangleSpans {
    /// Spans of nothing.
    fn empty(v: [ScreenPoint; 3]) -> Self {
        TriangleSpans {
            v,
            y: 0,
            y_end: 0,
            y_split: 0,
            #[cfg(any(
                target_pointer_width = "64",
                all(target_pointer_width = "32", target_has_atomic = "32")
            ))]
            y_reseed: i32::MAX,
            #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
            seed_rows: u32::MAX,
            left: EdgeWalk::ZERO,
            right: EdgeWalk::ZERO,
            long_is_left: true,
            x_min: 0,
            x_max: 0,
        }
    }

    /// Switches the short edge to the lower one at the middle vertex's row; true if the left
    /// edge changed.
    #[inline(always)]
    fn switch_at_split(&mut self) -> bool {
        if self.y != self.y_split {
            return false;
        }
        let [_, b, c] = self.v;
        let rows = self.seed_rows();
        // The split row is never reached again.
        self.y_split = i32::MIN;
        let (short, left_changed) = if self.long_is_left {
            (&mut self.right, false)
        } else {
            (&mut self.left, true)
        };
        *short = edge(b, c, self.y, rows);
        left_changed
    }

    /// Sets both edges up again from the vertices at the row where their walks stop being
    /// exact (see [`EdgeWalk`]); after [`switch_at_split`](Self::switch_at_split) on the same
    /// row.
    #[cfg(any(
        target_pointer_width = "64",
        all(target_pointer_width = "32", target_has_atomic = "32")
    ))]
    #[inline(always)]
    fn reseed_when_due(&mut self) {
        if self.y != self.y_reseed {
            return;
        }
        let [a, b, c] = self.v;
        let rows = self.seed_rows();
        let long = edge(a, c, self.y, rows);
        // The lower short edge once past the split (`i32::MIN`), the upper one before.
        let short = if self.y_split == i32::MIN {
            edge(b, c, self.y, rows)
        } else {
            edge(a, b, self.y, rows)
        };
        (self.left, self.right) = if self.long_is_left {
            (long, short)
        } else {
            (short, long)
        };
        #[cfg(target_pointer_width = "64")]
        {
            self.y_reseed = reseed_row(self.y, self.y_end, c.y.wrapping_sub(a.y));
        }
        #[cfg(not(target_pointer_width = "64"))]
        {
            self.y_reseed = after_rows(self.y, rows);
        }
    }

    /// Rows from one seeding to the next (see [`division_rows`]).
    #[inline(always)]
    fn seed_rows(&self) -> u32 {
        #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
        return self.seed_rows;
        #[cfg(not(all(target_pointer_width = "32", target_has_atomic = "32")))]
        u32::MAX
    }

    /// The row the next span lies on.
    pub(crate) fn row(&self) -> i32 {
        self.y
    }

    /// Calls `f(x0, x1)` for every row left, top to bottom, with the row's pixels `x0..x1`
    /// clipped to the clip rectangle's columns: empty (`x0 ≥ x1`) where it covers none of them.
    #[inline(always)]
    #[cfg_attr(
        not(all(target_pointer_width = "32", target_has_atomic = "32")),
        allow(unused_mut)
    )]
    pub(crate) fn for_each_row(self, mut f: impl FnMut(i32, i32)) {
        if cfg!(target_pointer_width = "64") {
            self.rows_in_runs(f);
            return;
        }
        // A constant `u32::MAX` for the pipeline's triangles (see `spans_in_range`).
        #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
        if self.seed_rows != u32::MAX {
            return self.rows_reseeding(&mut f);
        }
        self.rows_one_by_one(f);
    }

    /// [`rows_one_by_one`](Self::rows_one_by_one) for triangles whose edges are set up again
    /// on the way down (see [`division_rows`]: none of the pipeline's), out of line so that
    /// the row loop of every other triangle carries no check for it.
    #[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
    #[inline(never)]
    fn rows_reseeding(mut self, f: &mut dyn FnMut(i32, i32)) {
        while self.y < self.y_end {
            self.switch_at_split();
            self.reseed_when_due();
            let (x0, x1) = self.ends();
            f(x0, x1);
            self.step_edges();
        }
    }

    /// [`for_each_row`](Self::for_each_row) in two runs of rows, above and below the middle
    /// vertex's row, with no per-row check for the switch of the short edge: on 64-bit hosts.
    #[inline(always)]
    fn rows_in_runs(mut self, mut f: impl FnMut(i32, i32)) {
        loop {
            // Up to the split while it lies ahead (`i32::MIN` once switched), then to the end
            // (or to the next re-seeding).
            let end = if self.y_split > self.y {
                self.y_split
            } else {
                self.y_end
            };
            #[cfg(target_pointer_width = "64")]
            let end = end.min(self.y_reseed);
            while self.y < end {
                let (x0, x1) = self.ends();
                f(x0, x1);
                self.step_edges();
            }
            if self.y >= self.y_end {
                return;
            }
            self.switch_at_split();
            #[cfg(any(
                target_pointer_width = "64",
                all(target_pointer_width = "32", target_has_atomic = "32")
            ))]
            self.reseed_when_due();
        }
    }

    /// [`for_each_row`](Self::for_each_row) in one loop that checks for the split on every row:
    /// on 32-bit cores, where entering each of two runs moves the row loop's state between
    /// stack slots.
    #[inline(always)]
    fn rows_one_by_one(mut self, mut f: impl FnMut(i32, i32)) {
        while self.y < self.y_end {
            self.switch_at_split();
            #[cfg(target_pointer_width = "64")]
            self.reseed_when_due();
            let (x0, x1) = self.ends();
            // Where edges divide (Cortex-M3/M4), stepped before the row's span: the span loop
            // then keeps its colour in a register, where the edges' words would stay live
            // across it.
            if cfg!(all(target_pointer_width = "32", target_has_atomic = "32")) {
                self.step_edges();
                f(x0, x1);
            } else {
                f(x0, x1);
                self.step_edges();
            }
        }
    }

    /// The current row's pixels `x0..x1`, clipped to the clip rectangle's columns.
    #[inline(always)]
    fn ends(&self) -> (i32, i32) {
        (
            self.left.value().max(self.x_min),
            self.right.value().min(self.x_max),
        )
    }

    /// Moves both edges down one row. Out of line on 64-bit hosts: the row loop's edges then
    /// live in memory across the pixel loop, which keeps its step and colour in registers; in
    /// line on 32-bit cores, where the call costs more than it frees.
    #[cfg_attr(target_pointer_width = "64", inline(never))]
    #[cfg_attr(not(target_pointer_width = "64"), inline(always))]
    fn step_edges(&mut self) {
        self.left.step();
        self.right.step();
        self.y += 1;
    }

    /// Rows still to visit: the work left is proportional to this (it never exceeds the clip
    /// rectangle's height).
    #[must_use]
    pub fn rows_left(&self) -> u32 {
        self.y_end.saturating_sub(self.y).max(0) as u32
    }
}

impl Iterator for TriangleSpans {
    type Item = Span;

    #[inline]
    fn next(&mut self) -> Option<Span> {
        while self.y < self.y_end {
            self.switch_at_split();
            #[cfg(any(
                target_pointer_width = "64",
                all(target_pointer_width = "32", target_has_atomic = "32")
            ))]
            self.reseed_when_due();
            let (y, (x0, x1)) = (self.y, self.ends());
            self.step_edges();
            if x0 < x1 {
                return Some(Span { y, x0, x1 });
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// The rows of all of `for_each_row`'s loops (in runs, one by one, and one by one with
    /// re-seeding out of line), which must agree: each target compiles one or two of them.
    fn rows_both_ways(spans: &TriangleSpans) -> Vec<(i32, i32)> {
        let (mut in_runs, mut one_by_one, mut reseeding) = (Vec::new(), Vec::new(), Vec::new());
        spans.clone().rows_in_runs(|x0, x1| in_runs.push((x0, x1)));
        spans
            .clone()
            .rows_one_by_one(|x0, x1| one_by_one.push((x0, x1)));
        spans
            .clone()
            .rows_reseeding(&mut |x0, x1| reseeding.push((x0, x1)));
        assert_eq!(in_runs, one_by_one);
        assert_eq!(in_runs, reseeding);
        in_runs
    }

    /// The span end of edge `p → q` on row `py`, `ceil((x(16·py + 8) − 8) / 16)`, from its
    /// definition in 64-bit arithmetic.
    fn edge_end(p: ScreenPoint, q: ScreenPoint, py: i32) -> i32 {
        let (dx, dy) = (q.x as i64 - p.x as i64, q.y as i64 - p.y as i64);
        let t = 16 * py as i64 + 8 - p.y as i64;
        crate::raster::ceil_div((p.x as i64 - 8) * dy + dx * t, 16 * dy) as i32
    }

    /// An edge `p → q` (`p.y < q.y`) with some rows, and one of them.
    fn edge_with_rows(rng: &mut crate::testing::XorShift, lim: i32) -> (ScreenPoint, ScreenPoint) {
        loop {
            let extreme = |rng: &mut crate::testing::XorShift| {
                if rng.next_u64().is_multiple_of(4) {
                    rng.pick(&[-lim, lim, -lim + 1, lim - 1])
                } else {
                    rng.within(lim)
                }
            };
            let p = ScreenPoint::new(extreme(rng), extreme(rng));
            let q = ScreenPoint::new(extreme(rng), extreme(rng));
            let (p, q) = if p.y <= q.y { (p, q) } else { (q, p) };
            if first_centre_from32(p.y) < first_centre_from32(q.y) {
                return (p, q);
            }
        }
    }

    /// R1: `reseed_row`'s comparison of the long edge's height with 2¹⁵ takes only what its
    /// product shows: for every height up to 2¹⁵ sub-pixels and every start within a pixel,
    /// the rows of pixel centres it holds times its denominator less one stay below 2³², so
    /// the [`FractionStepper`] walks them all from one set-up.
    #[cfg(target_pointer_width = "64")]
    #[test]
    fn r1_edges_of_2_15_sub_pixels_walk_without_reseeding() {
        for dy in 1..=1i64 << 15 {
            for top in 0..16i64 {
                // Rows py with top ≤ 16·py + 8 < top + dy.
                let (first, end) = (
                    (top - 8 + 15).div_euclid(16),
                    (top + dy - 8 + 15).div_euclid(16),
                );
                let rows = (end - first).max(0) as u64;
                assert!(rows * (16 * dy as u64 - 1) < 1 << 32, "{dy} {top}");
                assert_eq!(reseed_row(first as i32, end as i32, dy as i32), i32::MAX);
            }
        }
        // Taller edges whose product reaches 2³² are set up again on the way down.
        let mut tall = 0;
        for dy in (1i64 << 16)..(1 << 16) + 64 {
            let (first, end) = (0, (dy + 7).div_euclid(16));
            if end as u64 * (16 * dy as u64 - 1) >= 1 << 32 {
                assert_ne!(reseed_row(first, end as i32, dy as i32), i32::MAX, "{dy}");
                tall += 1;
            }
        }
        assert!(tall > 0);
    }

    /// The Cortex-M4's whole-edge `DivideStepper` (`edge_by_division`) walks every row of
    /// every edge within ±PIPELINE_LIMIT exactly, started at any of its rows: edges across
    /// the whole bound, corner to corner included, where its word nearly fills 32 bits, and
    /// small edges at every scale.
    #[test]
    fn division_edges_within_the_pipeline_limit_are_exact() {
        use crate::raster::PIPELINE_LIMIT;
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let corner = |x, y| ScreenPoint::new(x, y);
        let l = PIPELINE_LIMIT;
        let mut edges = std::vec![
            (corner(-l, -l), corner(l, l)),
            (corner(l, -l), corner(-l, l)),
            (corner(-l, -l), corner(l, -l + 16)),
            (corner(l, -l), corner(-l, l - 7)),
        ];
        edges.extend((0..3000).map(|_| edge_with_rows(&mut rng, l)));
        edges.extend((0..3000).map(|_| {
            let (p, q) = edge_with_rows(&mut rng, 300);
            // Whole pixels down, so that the edge keeps its rows.
            let off = ScreenPoint::new(rng.within(l - 300), rng.within((l - 300) / 16) * 16);
            let at = |v: ScreenPoint| ScreenPoint::new(v.x + off.x, v.y + off.y);
            (at(p), at(q))
        }));
        let mut rows = 0u64;
        for (p, q) in edges {
            let (first, end) = (first_centre_from32(p.y), first_centre_from32(q.y));
            assert!(first < end, "{p:?} {q:?}");
            let start =
                first + i32::from(rng.next_u64().is_multiple_of(3)) * rng.within(end - first).abs();
            let start = start.min(end - 1);
            let mut e = edge_by_division(p, q, start);
            for py in start..end {
                assert_eq!(e.value(), edge_end(p, q, py), "{p:?} {q:?} row {py}");
                e.step();
                rows += 1;
            }
        }
        assert!(rows > 3_000_000, "{rows}");
    }

    /// `division_rows` is `u32::MAX` (one set-up per edge) for every triangle within
    /// ±PIPELINE_LIMIT, which `spans_in_range` takes for granted, and not beyond it; and
    /// the edges of triangles anywhere within ±COORD_LIMIT walk exactly for the rows it
    /// gives from any of their rows (`edge_by_division_for`), or for all of them.
    #[test]
    fn division_rows_bound_the_walks() {
        use crate::raster::{COORD_LIMIT, PIPELINE_LIMIT};
        let l = PIPELINE_LIMIT;
        let p = |x, y| ScreenPoint::new(x, y);
        assert_eq!(division_rows(&[p(-l, -l), p(l, -l), p(-l, l)]), u32::MAX);
        assert_eq!(division_rows(&[p(-l, -l), p(l, l), p(l, -l)]), u32::MAX);
        assert_ne!(
            division_rows(&[p(-l - 16, -l - 16), p(l + 16, l + 16), p(l, -l)]),
            u32::MAX
        );
        let c = COORD_LIMIT;
        assert_eq!(division_rows(&[p(-c, -c), p(c, c), p(c, -c)]), 3);
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let (mut chunked, mut rows) = (0, 0u64);
        for i in 0..6000 {
            let (a, b) = edge_with_rows(&mut rng, COORD_LIMIT);
            let third = if i % 2 == 0 {
                ScreenPoint::new(rng.within(c), rng.within(c))
            } else {
                a
            };
            let n = division_rows(&[a, b, third]);
            let (first, end) = (first_centre_from32(a.y), first_centre_from32(b.y));
            let start = first + rng.within(end - first).abs().min(end - first - 1);
            let (mut e, walk) = if n == u32::MAX {
                (edge_by_division(a, b, start), end - start)
            } else {
                chunked += 1;
                let walk = (n.min(4000) as i32).min(end - start);
                (edge_by_division_for(a, b, start, n), walk)
            };
            for py in start..start + walk {
                assert_eq!(e.value(), edge_end(a, b, py), "{a:?} {b:?} {n} row {py}");
                e.step();
                rows += 1;
            }
        }
        assert!(chunked > 4000 && rows > 1_000_000, "{chunked} {rows}");
    }

    /// The Cortex-M4's triangle walk, modelled from its parts (`division_rows`, the two
    /// `DivideStepper` set-ups, re-seeding every `division_rows` rows and at the split, as
    /// `spans_in_range` and `rows_reseeding` do there), yields the iterator's spans: the
    /// pipeline's triangles, and triangles millions of pixels across, partly off every side.
    #[test]
    fn division_walk_equals_the_iterator() {
        fn division_walk(v: [ScreenPoint; 3], clip: PixelRect) -> Vec<Span> {
            let area = doubled_area(v[0], v[1], v[2]);
            let ([a, b, c], odd) = sort_by_y(v);
            let y_start = first_centre_from32(a.y).max(clip.y0);
            let y_end = first_centre_from32(c.y).min(clip.y1);
            if area == 0 || y_start >= y_end {
                return Vec::new();
            }
            let y_split = first_centre_from32(b.y).clamp(y_start, y_end);
            let rows = division_rows(&[a, b, c]);
            let set = |p, q, y| {
                if rows == u32::MAX {
                    edge_by_division(p, q, y)
                } else {
                    edge_by_division_for(p, q, y, rows)
                }
            };
            let short_at = |y| {
                if y < y_split {
                    set(a, b, y)
                } else {
                    set(b, c, y)
                }
            };
            let (mut long, mut short) = (set(a, c, y_start), short_at(y_start));
            let mut spans = Vec::new();
            for y in y_start..y_end {
                if rows != u32::MAX && y > y_start && ((y - y_start) as u32).is_multiple_of(rows) {
                    long = set(a, c, y);
                    short = short_at(y);
                } else if y == y_split {
                    short = short_at(y);
                }
                let (left, right) = if (area > 0) != odd {
                    (long, short)
                } else {
                    (short, long)
                };
                let (x0, x1) = (left.value().max(clip.x0), right.value().min(clip.x1));
                if x0 < x1 {
                    spans.push(Span { y, x0, x1 });
                }
                long.step();
                short.step();
            }
            spans
        }
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let lim = crate::raster::COORD_LIMIT;
        let mut seen = 0;
        for i in 0..3000 {
            let (p, clip) = match i % 3 {
                0 => (
                    rng.triangle(ScreenPoint::new(2560, 1920), 600),
                    PixelRect::new(0, 0, 320, 240),
                ),
                1 => (
                    rng.triangle(ScreenPoint::new(0, 0), crate::raster::PIPELINE_LIMIT),
                    PixelRect::new(-50, -40, 70, 90),
                ),
                _ => (
                    rng.triangle(ScreenPoint::new(0, 0), lim),
                    PixelRect::new(-3, -900, 5, 900),
                ),
            };
            let expected: Vec<Span> = triangle_spans(p, clip).collect();
            seen += expected.len();
            assert_eq!(division_walk(p, clip), expected, "{p:?}");
        }
        assert!(seen > 100_000, "{seen}");
    }

    /// `for_each_row` (both its loops) re-seeds its edges where the iterator does (64-bit
    /// hosts: triangles the pipeline draws never need it, so only these reach it): rows of
    /// triangles millions of pixels tall equal the iterator's, which tests/clipping.rs checks
    /// against the model (the first two are built there to drift without re-seeding).
    #[test]
    fn for_each_row_re_seeds_like_the_iterator() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let lim = crate::raster::COORD_LIMIT;
        let (dy, bottom) = (257 * 65537, 16 * 526_343 + 9);
        let crafted = [-1, 1].map(|side| {
            let p = [
                ScreenPoint::new(39, bottom - dy),
                ScreenPoint::new(side * lim, 0),
                ScreenPoint::new(40, bottom),
            ];
            (p, PixelRect::new(0, 526_344 - 300, 6, 526_346))
        });
        let random = (0..200).map(|_| {
            let p = rng.triangle(ScreenPoint::new(0, 0), lim);
            (p, PixelRect::new(-3, -800, 5, 800))
        });
        let mut reseeded = 0;
        for (p, clip) in crafted.into_iter().chain(random) {
            let spans = triangle_spans(p, clip);
            reseeded += usize::from(spans.y_reseed != i32::MAX);
            let expected: Vec<Span> = spans.clone().collect();
            let (mut walked, mut y) = (Vec::new(), spans.row());
            for (x0, x1) in rows_both_ways(&spans) {
                if x0 < x1 {
                    walked.push(Span { y, x0, x1 });
                }
                y += 1;
            }
            assert_eq!(walked, expected, "{p:?}");
        }
        assert!(reseeded > 150, "{reseeded}");
    }

    /// `for_each_row` (both its loops) visits the rows the iterator yields (and the empty ones
    /// between), and the row walk of a plane (`PlaneRows`, the general span loop's) gives
    /// `Plane::at` at each first pixel, bit for bit. Triangles of every shape and size, partly
    /// off every side of the clip rectangle, steep and flat gradients.
    #[test]
    fn row_walks_equal_the_iterator_and_plane_at() {
        use crate::raster::RowStarts;
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let clip = PixelRect::new(3, 5, 60, 144);
        let mut spans_seen = 0;
        for _ in 0..20_000 {
            let scale = rng.pick(&[40, 400, 1200, 16_000]);
            let p = rng.triangle(ScreenPoint::new(500, 1200), scale);
            let area = doubled_area(p[0], p[1], p[2]);
            if area == 0 {
                continue;
            }
            let z = [(); 3].map(|_| (rng.within(1 << 30) as i64) << 14);
            let plane = Plane::new(&p, z, area);
            let expected: Vec<(Span, i64)> = triangle_spans(p, clip)
                .map(|s| (s, plane.at(s.x0, s.y)))
                .collect();
            let spans = triangle_spans(p, clip);
            let y0 = spans.row();
            let mut wide = plane.rows(clip.x0, y0);
            let (mut walked, mut y) = (Vec::new(), y0);
            for (x0, x1) in rows_both_ways(&spans) {
                if x0 < x1 {
                    walked.push((Span { y, x0, x1 }, wide.at(x0)));
                }
                wide.next_row();
                y += 1;
            }
            assert_eq!(walked, expected, "{p:?}");
            spans_seen += walked.len();
        }
        assert!(spans_seen > 100_000, "{spans_seen}");
    }

    /// `spans_in_range` tests neither the clip rectangle nor the area: a rectangle without
    /// columns (rows still walked) or without rows holds no span, by every loop, for triangles
    /// that cover pixels of the full rectangle.
    #[test]
    fn r4_spans_in_range_of_an_empty_clip_hold_no_span() {
        let mut rng = crate::testing::XorShift(0x6A09_E667_F3BC_C909u64);
        let full = PixelRect::new(0, 0, 64, 64);
        let empties = [
            PixelRect::new(20, 0, 20, 64),
            PixelRect::new(30, 0, 10, 64),
            PixelRect::new(0, 20, 64, 20),
            PixelRect::new(0, 40, 64, 10),
        ];
        let mut covering = 0;
        for _ in 0..2_000 {
            let p = rng.triangle(ScreenPoint::new(32 * 16, 32 * 16), 600);
            let area = doubled_area(p[0], p[1], p[2]);
            if area == 0 {
                continue;
            }
            covering += usize::from(spans_in_range(p, full, area, u32::MAX).next().is_some());
            for clip in empties {
                let spans = spans_in_range(p, clip, area, u32::MAX);
                assert!(rows_both_ways(&spans).iter().all(|(x0, x1)| x0 >= x1));
                assert_eq!(spans.count(), 0, "{p:?} {clip:?}");
            }
        }
        assert!(covering > 1_000, "{covering}");
    }
}

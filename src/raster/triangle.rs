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
//! addition a row, and its proven bound decides how often an edge is set up again).

#[cfg(not(target_pointer_width = "64"))]
use super::CeilStepper;
#[cfg(test)]
use super::Plane;
use super::{doubled_area, first_centre_from32, PixelRect, ScreenPoint};
#[cfg(target_pointer_width = "64")]
use super::{fraction_rows, FractionStepper};
use crate::math::{mul_wide, SUBPIXEL_SCALE};
#[cfg(not(target_pointer_width = "64"))]
use crate::math::{NARROW_CORE, SUBPIXEL_BITS};

const S: i64 = SUBPIXEL_SCALE as i64;
const HALF: i64 = S / 2;

/// The walk of an edge's span ends: on 64-bit hosts [`FractionStepper`](super::FractionStepper),
/// one addition a row (x86-64: 5% fewer instructions per frame), which a triangle re-seeds
/// from its vertices every [`fraction_rows`](super::fraction_rows) rows (triangles the pipeline
/// draws never need it: at most 2¹² rows of edges below 2¹⁶ sub-pixels); elsewhere the exact
/// [`CeilStepper`](super::CeilStepper), whose set-up needs no 64-bit division (a library
/// routine on 32-bit cores).
#[cfg(target_pointer_width = "64")]
type EdgeWalk = FractionStepper;
/// The walk of an edge's span ends: see the 64-bit definition.
#[cfg(not(target_pointer_width = "64"))]
type EdgeWalk = CeilStepper;

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
    #[cfg(target_pointer_width = "64")]
    y_reseed: i32,
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
    spans_in_range(v, clip, doubled_area(a, b, c))
}

/// [`triangle_spans`] of points already known to lie within ±[`COORD_LIMIT`](super::COORD_LIMIT)
/// (the pipeline's projected vertices lie within ±2¹⁵), whose doubled signed area (in the
/// given order, see `doubled_area`) the caller has.
pub(crate) fn spans_in_range(v: [ScreenPoint; 3], clip: PixelRect, area: i64) -> TriangleSpans {
    let empty = || TriangleSpans::empty(v);
    // Zero area covers nothing (rule R4).
    if clip.is_empty() || area == 0 {
        return empty();
    }
    let ([a, b, c], odd) = sort_by_y(v);
    // Coordinates within ±2²⁴: the first row at or below each in 32-bit words.
    let first_row = first_centre_from32;
    let y_start = first_row(a.y).max(clip.y0);
    let y_end = first_row(c.y).min(clip.y1);
    if y_start >= y_end {
        return empty();
    }
    let y_split = first_row(b.y).clamp(y_start, y_end);
    #[cfg(target_pointer_width = "64")]
    let y_reseed = reseed_row(y_start, y_end, c.y.wrapping_sub(a.y));
    // The middle vertex lies right of the long edge when the sorted triangle's doubled area
    // is positive (y down; an odd permutation turns the sign): the long edge is then the left
    // one.
    let long_is_left = (area > 0) != odd;
    let long = edge(a, c, y_start);
    let (short, y_split) = if y_start < y_split {
        (edge(a, b, y_start), y_split)
    } else {
        (edge(b, c, y_start), i32::MIN)
    };
    let (left, right) = if long_is_left {
        (long, short)
    } else {
        (short, long)
    };
    TriangleSpans {
        v: [a, b, c],
        y: y_start,
        y_end,
        y_split,
        #[cfg(target_pointer_width = "64")]
        y_reseed,
        left,
        right,
        long_is_left,
        x_min: clip.x0,
        x_max: clip.x1,
    }
}

/// The stepper for `ceil((x(16·py + 8) − 8) / 16)` along edge `p → q` (`p.y < q.y`), at row
/// `py` (one of the edge's rows). With coordinates within ±2²⁴ every difference below is a
/// 32-bit factor, the numerator stays below 2⁵⁴ and the denominator below 2²⁹.
fn edge(p: ScreenPoint, q: ScreenPoint, py: i32) -> EdgeWalk {
    let dx = q.x.wrapping_sub(p.x);
    let dy = q.y.wrapping_sub(p.y).max(1);
    // Without a hardware divide, the whole pixels of p.x − 8 come out by a shift:
    // ceil(((16k + m)·dy + …) / 16dy) = k + ceil((m·dy + …) / 16dy), a small quotient for
    // steep edges started at their top, found without dividing (see `floor_divmod`).
    let x = p.x.wrapping_sub(HALF as i32);
    // The row lies within the edge's rows: |16·py| below 2²⁵.
    let t = py
        .wrapping_mul(S as i32)
        .wrapping_add(HALF as i32)
        .wrapping_sub(p.y);
    let (den, step) = (S * dy as i64, S * dx as i64);
    // (Narrow cores are 32-bit: their edge walk is the exact stepper.)
    #[cfg(not(target_pointer_width = "64"))]
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

/// The row after the last one that edges set up at row `y` walk exactly, for a triangle whose
/// rows end at `y_end` and whose long edge is `dy` sub-pixels tall (the others are shorter, so
/// their denominators smaller): `i32::MAX` when that is beyond the triangle.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn reseed_row(y: i32, y_end: i32, dy: i32) -> i32 {
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
            #[cfg(target_pointer_width = "64")]
            y_reseed: i32::MAX,
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
        // The split row is never reached again.
        self.y_split = i32::MIN;
        let (short, left_changed) = if self.long_is_left {
            (&mut self.right, false)
        } else {
            (&mut self.left, true)
        };
        *short = edge(b, c, self.y);
        left_changed
    }

    /// Sets both edges up again from the vertices at the row where their walks stop being
    /// exact (see [`EdgeWalk`]); after [`switch_at_split`](Self::switch_at_split) on the same
    /// row.
    #[cfg(target_pointer_width = "64")]
    #[inline(always)]
    fn reseed_when_due(&mut self) {
        if self.y != self.y_reseed {
            return;
        }
        let [a, b, c] = self.v;
        let long = edge(a, c, self.y);
        // The lower short edge once past the split (`i32::MIN`), the upper one before.
        let short = if self.y_split == i32::MIN {
            edge(b, c, self.y)
        } else {
            edge(a, b, self.y)
        };
        (self.left, self.right) = if self.long_is_left {
            (long, short)
        } else {
            (short, long)
        };
        self.y_reseed = reseed_row(self.y, self.y_end, c.y.wrapping_sub(a.y));
    }

    /// The row the next span lies on.
    pub(crate) fn row(&self) -> i32 {
        self.y
    }

    /// Calls `f(x0, x1)` for every row left, top to bottom, with the row's pixels `x0..x1`
    /// clipped to the clip rectangle's columns: empty (`x0 ≥ x1`) where it covers none of them.
    #[inline(always)]
    pub(crate) fn for_each_row(self, f: impl FnMut(i32, i32)) {
        if cfg!(target_pointer_width = "64") {
            self.rows_in_runs(f);
        } else {
            self.rows_one_by_one(f);
        }
    }

    /// [`for_each_row`](Self::for_each_row) in two runs of rows, above and below the middle
    /// vertex's row, with no per-row check for the switch of the short edge: on 64-bit hosts
    /// (x86-64: 6% fewer instructions per frame than one by one).
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
            #[cfg(target_pointer_width = "64")]
            self.reseed_when_due();
        }
    }

    /// [`for_each_row`](Self::for_each_row) in one loop that checks for the split on every
    /// row: on 32-bit cores, where entering each of two runs moves the row loop's state
    /// between stack slots (Cortex-M0: 0.7% fewer instructions per frame than in runs, the
    /// M4 1.3%).
    #[inline(always)]
    fn rows_one_by_one(mut self, mut f: impl FnMut(i32, i32)) {
        while self.y < self.y_end {
            self.switch_at_split();
            #[cfg(target_pointer_width = "64")]
            self.reseed_when_due();
            let (x0, x1) = self.ends();
            f(x0, x1);
            self.step_edges();
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
    /// live in memory across the pixel loop, which keeps its step and colour in registers
    /// (x86-64: 3.3% fewer instructions per frame, 4.8% in the default build); in line on
    /// 32-bit cores, where the call costs more than it frees (Cortex-M0 and M4: 1% more out of
    /// line).
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
            #[cfg(target_pointer_width = "64")]
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

    /// The rows of both of `for_each_row`'s loops (in runs, and one by one), which must agree:
    /// each target compiles one of them.
    fn rows_both_ways(spans: &TriangleSpans) -> Vec<(i32, i32)> {
        let (mut in_runs, mut one_by_one) = (Vec::new(), Vec::new());
        spans.clone().rows_in_runs(|x0, x1| in_runs.push((x0, x1)));
        spans
            .clone()
            .rows_one_by_one(|x0, x1| one_by_one.push((x0, x1)));
        assert_eq!(in_runs, one_by_one);
        in_runs
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
    /// between), and the row walks of a plane give `Plane::at` at each first pixel:
    /// `PlaneRows` bit for bit, `ShortRows` the u16 loop's start `⌊(v + 2²⁷) / 2¹³⌋` wherever
    /// that fits 31 bits.
    /// Triangles of every shape and size, partly off every side of the clip rectangle, steep
    /// and flat gradients.
    #[test]
    fn row_walks_equal_the_iterator_and_plane_at() {
        use crate::raster::RowStarts;
        use crate::target::{ShortRows, WideRows};
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let clip = PixelRect::new(3, 5, 60, 144);
        let (mut spans_seen, mut short_seen) = (0, 0);
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
            let mut short = ShortRows::new(&plane, clip.x0, y0);
            let mut start64 = WideRows::new(&plane, clip.x0, y0);
            let (mut walked, mut y) = (Vec::new(), y0);
            for (x0, x1) in rows_both_ways(&spans) {
                if x0 < x1 {
                    let v = wide.at(x0);
                    walked.push((Span { y, x0, x1 }, v));
                    let start = v.wrapping_add(1 << 27) >> 13;
                    if (0..1 << 31).contains(&start) {
                        assert_eq!(short.at(x0) as i64, start, "{p:?}");
                        assert_eq!(start64.at(x0) as i64, start, "{p:?}");
                        short_seen += 1;
                    }
                }
                wide.next_row();
                short.next_row();
                start64.next_row();
                y += 1;
            }
            assert_eq!(walked, expected, "{p:?}");
            spans_seen += walked.len();
        }
        assert!(
            spans_seen > 100_000 && short_seen > 50_000,
            "{spans_seen} {short_seen}"
        );
    }
}

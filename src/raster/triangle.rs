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
//! exactly (see [`edge`](super::edge)), so no precision is lost however long the edge.

use super::edge::EdgeWalk;
#[cfg(test)]
use super::Plane;
use super::{doubled_area, first_centre_from32, CeilStepper, PixelRect, ScreenPoint};

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
pub struct TriangleSpans(TriangleWalk<CeilStepper>);

/// A triangle's rows walked down its edges by `W`: [`TriangleSpans`]' exact walk for any
/// triangle, the core's [`PipelineEdge`](super::edge::PipelineEdge) for the pipeline's.
#[derive(Clone, Debug)]
pub(crate) struct TriangleWalk<W> {
    v: [ScreenPoint; 3],
    y: i32,
    y_end: i32,
    /// The row where the short edge switches to the lower one (`i32::MIN` once switched).
    y_split: i32,
    left: W,
    right: W,
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
        return TriangleSpans(TriangleWalk::empty(v));
    }
    let [a, b, c] = v;
    let area = doubled_area(a, b, c);
    // Zero area covers nothing (rule R4).
    if area == 0 || clip.is_empty() {
        return TriangleSpans(TriangleWalk::empty(v));
    }
    TriangleSpans(spans_in_range(v, clip, area))
}

/// [`triangle_spans`] of points within ±[`COORD_LIMIT`](super::COORD_LIMIT) whose doubled
/// signed area (in the given order, see `doubled_area`) the caller has, not zero. Neither the
/// area nor `clip` is tested here: the pipeline draws no triangle of zero area, and a `clip`
/// without rows or columns holds no span of any triangle.
pub(crate) fn spans_in_range<W: EdgeWalk>(
    v: [ScreenPoint; 3],
    clip: PixelRect,
    area: i64,
) -> TriangleWalk<W> {
    match rows_in_range(v, clip, area) {
        Some(rows) => rows.spans((clip.x0, clip.x1)),
        None => TriangleWalk::empty(v),
    }
}

/// A triangle's rows in a clip rectangle before any edge is set up ([`rows_in_range`]): its
/// vertices sorted by y, its first row and the row past its last, the middle vertex's row
/// clamped to them, and the side of the long edge. Its spans come from [`spans`](Self::spans).
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
#[inline(always)]
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
        // Clamped to the last row, the row loop has a known bound (see `stopped` for a walk
        // that goes on past it).
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

    /// The spans of these rows clipped to the columns `x_min..x_max`.
    #[inline(always)]
    pub(crate) fn spans<W: EdgeWalk>(self, (x_min, x_max): (i32, i32)) -> TriangleWalk<W> {
        let TriangleRows {
            v: [a, b, c],
            y,
            y_end,
            y_split,
            long_is_left,
        } = self;
        let long = W::at_row(a, c, y);
        let (short, y_split) = if y < y_split {
            (W::at_row(a, b, y), y_split)
        } else {
            (W::at_row(b, c, y), i32::MIN)
        };
        let (left, right) = if long_is_left {
            (long, short)
        } else {
            (short, long)
        };
        TriangleWalk {
            v: [a, b, c],
            y,
            y_end,
            y_split,
            left,
            right,
            long_is_left,
            x_min,
            x_max,
        }
    }
}

/// A [`TriangleWalk`] stopped on a row (see [`TriangleWalk::stopped`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct StoppedWalk<W> {
    lower: [ScreenPoint; 2],
    y_split: i32,
    left: W,
    right: W,
    /// A byte, not a `bool`: `None` of an `Option` of this is then all zeros (a `static` of
    /// them is held in no flash).
    long_is_left: u8,
}

impl<W: EdgeWalk> StoppedWalk<W> {
    /// The walk going on from row `y` (the row it stopped on) up to row `y_end` (exclusive)
    /// or its own last, its spans clipped to the columns `x_min..x_max`.
    #[inline(always)]
    pub(crate) fn resume(self, y: i32, y_end: i32, (x_min, x_max): (i32, i32)) -> TriangleWalk<W> {
        let [b, c] = self.lower;
        let y_end = first_centre_from32(c.y).min(y_end);
        TriangleWalk {
            v: [b, b, c],
            y,
            y_end,
            y_split: self.y_split.min(y_end),
            left: self.left,
            right: self.right,
            long_is_left: self.long_is_left != 0,
            x_min,
            x_max,
        }
    }
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

impl<W: EdgeWalk> TriangleWalk<W> {
    /// Spans of nothing.
    fn empty(v: [ScreenPoint; 3]) -> Self {
        TriangleWalk {
            v,
            y: 0,
            y_end: 0,
            y_split: 0,
            left: W::ZERO,
            right: W::ZERO,
            long_is_left: true,
            x_min: 0,
            x_max: 0,
        }
    }

    /// Switches the short edge to the lower one at the middle vertex's row.
    #[inline(always)]
    fn switch_at_split(&mut self) {
        if self.y != self.y_split {
            return;
        }
        let [_, b, c] = self.v;
        // The split row is never reached again.
        self.y_split = i32::MIN;
        let short = if self.long_is_left {
            &mut self.right
        } else {
            &mut self.left
        };
        *short = W::at_row(b, c, self.y);
    }

    /// The row the next span lies on.
    pub(crate) fn row(&self) -> i32 {
        self.y
    }

    /// The row past the triangle's last, whatever the clip rectangle's rows.
    #[inline(always)]
    pub(crate) fn past(&self) -> i32 {
        first_centre_from32(self.v[2].y)
    }

    /// What the walk needs to go on from its current row in a later call: its edges there,
    /// the middle vertex's row and the vertices below it.
    #[inline(always)]
    pub(crate) fn stopped(&self) -> StoppedWalk<W> {
        let [_, b, c] = self.v;
        StoppedWalk {
            lower: [b, c],
            // The split row itself where the walk has not switched yet (its own is clamped to
            // the rows it was set up for).
            y_split: if self.y_split == i32::MIN {
                i32::MIN
            } else {
                first_centre_from32(b.y)
            },
            left: self.left,
            right: self.right,
            long_is_left: u8::from(self.long_is_left),
        }
    }

    /// Calls `f(x0, x1)` for every row left, top to bottom, with the row's pixels `x0..x1`
    /// clipped to the clip rectangle's columns: empty (`x0 ≥ x1`) where it covers none of them.
    /// The walk is left on the row past the last.
    #[inline(always)]
    pub(crate) fn for_each_row(&mut self, mut f: impl FnMut(i32, i32)) {
        while self.y < self.y_end {
            self.switch_at_split();
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

    /// Moves both edges down one row.
    #[inline(always)]
    fn step_edges(&mut self) {
        self.left.step();
        self.right.step();
        self.y += 1;
    }
}

impl TriangleSpans {
    /// Rows still to visit: the work left is proportional to this (it never exceeds the clip
    /// rectangle's height).
    #[must_use]
    pub fn rows_left(&self) -> u32 {
        self.0.y_end.saturating_sub(self.0.y).max(0) as u32
    }
}

impl Iterator for TriangleSpans {
    type Item = Span;

    #[inline]
    fn next(&mut self) -> Option<Span> {
        self.0.next()
    }
}

impl<W: EdgeWalk> Iterator for TriangleWalk<W> {
    type Item = Span;

    #[inline]
    fn next(&mut self) -> Option<Span> {
        while self.y < self.y_end {
            self.switch_at_split();
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
    use super::super::edge::{DivideStepper, PipelineEdge};
    use super::*;
    use std::vec::Vec;

    /// The rows `for_each_row` visits, empty ones included.
    fn rows<W: EdgeWalk>(spans: &TriangleWalk<W>) -> Vec<(i32, i32)> {
        let mut rows = Vec::new();
        spans.clone().for_each_row(|x0, x1| rows.push((x0, x1)));
        rows
    }

    /// `for_each_row` visits the rows the iterator yields for triangles millions of pixels
    /// tall, partly off every side (tests/clipping.rs checks the iterator against the model).
    #[test]
    fn for_each_row_equals_the_iterator_on_huge_triangles() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let lim = crate::raster::COORD_LIMIT;
        let mut seen = 0;
        for _ in 0..200 {
            let p = rng.triangle(ScreenPoint::new(0, 0), lim);
            let spans = triangle_spans(p, PixelRect::new(-3, -800, 5, 800)).0;
            let expected: Vec<Span> = spans.clone().collect();
            let (mut walked, mut y) = (Vec::new(), spans.row());
            for (x0, x1) in rows(&spans) {
                if x0 < x1 {
                    walked.push(Span { y, x0, x1 });
                }
                y += 1;
            }
            assert_eq!(walked, expected, "{p:?}");
            seen += walked.len();
        }
        assert!(seen > 10_000, "{seen}");
    }

    /// `for_each_row` visits the rows the iterator yields (and the empty ones
    /// between), and the row walk of a plane (`PlaneRows`, the general span loop's) gives
    /// `Plane::at` at each first pixel, bit for bit. Triangles of every shape and size, partly
    /// off every side of the clip rectangle, steep and flat gradients.
    #[test]
    fn row_walks_equal_the_iterator_and_plane_at() {
        row_walks_of::<CeilStepper>();
        row_walks_of::<DivideStepper>();
    }

    /// [`row_walks_equal_the_iterator_and_plane_at`] for the edge walk `W`.
    fn row_walks_of<W: EdgeWalk>() {
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
            let spans = spans_in_range::<W>(p, clip, area);
            let y0 = spans.row();
            let mut wide = plane.rows(clip.x0, y0);
            let (mut walked, mut y) = (Vec::new(), y0);
            for (x0, x1) in rows(&spans) {
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
    /// columns (rows still walked) or without rows holds no span, by either walk, for triangles
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
            let walk = spans_in_range::<CeilStepper>(p, full, area);
            covering += usize::from(walk.clone().next().is_some());
            for clip in empties {
                let spans = spans_in_range::<PipelineEdge>(p, clip, area);
                assert!(rows(&spans).iter().all(|(x0, x1)| x0 >= x1));
                assert_eq!(spans.count(), 0, "{p:?} {clip:?}");
            }
        }
        assert!(covering > 1_000, "{covering}");
    }
}

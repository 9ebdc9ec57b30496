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
//! with an integer quotient and remainder, so no precision is lost however long the edge.

use super::{ceil_div, PixelRect, RationalStepper, ScreenPoint};
use crate::math::SUBPIXEL_SCALE;

const S: i64 = SUBPIXEL_SCALE as i64;
const HALF: i64 = S / 2;

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
    y_split: i32,
    long: RationalStepper,
    short: RationalStepper,
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
    let empty = TriangleSpans {
        v,
        y: 0,
        y_end: 0,
        y_split: 0,
        long: RationalStepper::new(0, 1, 0, true),
        short: RationalStepper::new(0, 1, 0, true),
        long_is_left: true,
        x_min: 0,
        x_max: 0,
    };
    if !v.iter().all(|p| p.in_range()) || clip.is_empty() {
        return empty;
    }
    let [a, b, c] = sort_by_y(v);
    let (ax, ay, bx, by, cx, cy) = (
        a.x as i64, a.y as i64, b.x as i64, b.y as i64, c.x as i64, c.y as i64,
    );
    // Twice the signed area; zero covers nothing (rule R4).
    let cross = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
    if cross == 0 {
        return empty;
    }
    let first_row = |y: i64| ceil_div(y - HALF, S);
    let y_start = first_row(ay).max(clip.y0 as i64);
    let y_end = first_row(cy).min(clip.y1 as i64);
    if y_start >= y_end {
        return empty;
    }
    let y_split = first_row(by).clamp(y_start, y_end);
    // The middle vertex lies right of the long edge when cross > 0 (y down): the long edge is
    // then the left one.
    let long_is_left = cross > 0;
    let long = edge(a, c, y_start);
    let short = if y_start < y_split {
        edge(a, b, y_start)
    } else {
        edge(b, c, y_start)
    };
    TriangleSpans {
        v: [a, b, c],
        y: y_start as i32,
        y_end: y_end as i32,
        y_split: y_split as i32,
        long,
        short,
        long_is_left,
        x_min: clip.x0,
        x_max: clip.x1,
    }
}

/// The stepper for `ceil((x(16·py + 8) − 8) / 16)` along edge `p → q` (`p.y < q.y`), at row
/// `py`. With coordinates within ±2²⁴ the numerator stays below 2⁵⁴ and the denominator below
/// 2²⁹.
fn edge(p: ScreenPoint, q: ScreenPoint, py: i64) -> RationalStepper {
    let dx = q.x as i64 - p.x as i64;
    let dy = (q.y as i64 - p.y as i64).max(1);
    let n0 = (p.x as i64 - HALF) * dy + dx * (S * py + HALF - p.y as i64);
    RationalStepper::new(n0, S * dy, S * dx, true)
}

fn sort_by_y(v: [ScreenPoint; 3]) -> [ScreenPoint; 3] {
    let [mut a, mut b, mut c] = v;
    if b.y < a.y {
        core::mem::swap(&mut a, &mut b);
    }
    if c.y < b.y {
        core::mem::swap(&mut b, &mut c);
    }
    if b.y < a.y {
        core::mem::swap(&mut a, &mut b);
    }
    [a, b, c]
}

impl TriangleSpans {
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
            if self.y == self.y_split {
                let [_, b, c] = self.v;
                self.short = edge(b, c, self.y as i64);
                // Switch once: the split row is never reached again.
                self.y_split = i32::MIN;
            }
            let (l, r) = if self.long_is_left {
                (self.long.value, self.short.value)
            } else {
                (self.short.value, self.long.value)
            };
            let y = self.y;
            self.long.step();
            self.short.step();
            self.y += 1;
            let x0 = l.max(self.x_min);
            let x1 = r.min(self.x_max);
            if x0 < x1 {
                return Some(Span { y, x0, x1 });
            }
        }
        None
    }
}

//! Depth buffers: per-pixel depth in a caller-supplied `&mut [u16]` or `&mut [u32]`.

use super::grid::{BufferError, Grid};
use crate::raster::{AreaWalks, RowStarts, ScreenPoint};

/// The interpolator's fraction bits below one u16 step (its Q1.44 value has 2¹⁶ steps).
const U16_STEP_BITS: u32 = 28;
/// Of those, the u16 span loop drops these and keeps the other 15: depth is bits 15 to 30 of
/// its 32-bit value.
const DROPPED: u32 = 13;
/// Half a u16 step in the interpolator's units: added once, truncation then rounds to nearest.
const HALF_STEP: i64 = 1 << (U16_STEP_BITS - 1);
/// Half a u16 step in the 32-bit loop's unit.
pub(super) const LOOP_HALF_STEP: i32 = 1 << (U16_STEP_BITS - DROPPED - 1);

mod sealed {
    pub trait Sealed {}
}

mod colors {
    /// The colours of a span's pixels, one per pixel in order (stored where a fragment
    /// passes): a closure, or a paint's cursor whose step the span loop takes in line.
    pub trait SpanColors<C> {
        /// The next pixel's colour.
        fn next_color(&mut self) -> C;
        /// Moves past a pixel whose fragment failed. In line, a source whose colour has no
        /// side effects leaves it uncomputed (a textured pixel unread).
        #[inline(always)]
        fn skip(&mut self) {
            let _ = self.next_color();
        }
    }
}
pub(crate) use colors::SpanColors;

impl<C, F: FnMut() -> C> SpanColors<C> for F {
    #[inline(always)]
    fn next_color(&mut self) -> C {
        self()
    }
}

/// A stored depth format: 0 is the near plane, `FAR` the far plane (and the cleared value).
///
/// Depth reaches the buffer through one conversion from the interpolator (a Q1.44 value where
/// 2⁴⁴ is the far plane), rounded to nearest and saturated, never wrapped (rule R7); u16 spans
/// of triangles that need no clamping take it from a 32-bit walk of the plane instead
/// (within 2⁻³ of a step of the plane), rounded to nearest.
pub trait DepthFormat: Copy + Ord + sealed::Sealed + core::fmt::Debug {
    /// The far plane, and the value a cleared buffer holds.
    const FAR: Self;
    /// Depth from the interpolator's Q1.44 value, rounded and clamped to `[0, FAR]`.
    #[doc(hidden)]
    fn from_interpolated(acc: i64) -> Self;

    /// True when every pixel of a triangle whose vertex depths (Q1.30) are at most `max` can
    /// take [`test_span_unclamped`](Self::test_span_unclamped), whose values a
    /// [`RoundedRows`] walk gives.
    #[doc(hidden)]
    #[inline(always)]
    fn unclamped(max: i32) -> bool {
        let _ = max;
        false
    }

    /// [`test_span`](Self::test_span) for a span of a triangle that
    /// [`unclamped`](Self::unclamped) accepted: `start` and `step` in the 32-bit loop's unit,
    /// 2⁻³¹ of the depth range (2⁻¹³ of the interpolator's), half a u16 step added.
    #[doc(hidden)]
    #[inline(always)]
    fn test_span_unclamped<C: Copy, T: DepthTest, K: FragmentCount>(
        depths: &mut [Self],
        colors: &mut [C],
        start: i32,
        step: i32,
        colors_in: impl SpanColors<C>,
        failed: u32,
    ) -> u32 {
        // Formats without a fast path never hand out a step; this only keeps the contract.
        let start = ((start as i64) << DROPPED).wrapping_sub(HALF_STEP);
        Self::test_span::<C, T, K>(
            depths,
            colors,
            start,
            (step as i64) << DROPPED,
            colors_in,
            failed,
        )
    }

    /// Depth-tests one span: `start` and `step` are the interpolator's values at the first
    /// pixel and from pixel to pixel. `colors_in` gives a colour per pixel, in order; its
    /// colour is stored where the fragment passes. Returns `failed` (the count so far) plus
    /// how many failed: the pixel loop counts on from it, so the count needs no sum per span
    /// (and counts the fragments that fail, fewer than those that pass).
    #[doc(hidden)]
    #[inline(always)]
    fn test_span<C: Copy, T: DepthTest, K: FragmentCount>(
        depths: &mut [Self],
        colors: &mut [C],
        start: i64,
        step: i64,
        colors_in: impl SpanColors<C>,
        failed: u32,
    ) -> u32 {
        clamped_span::<Self, C, T, K>(depths, colors, start, step, colors_in, failed)
    }
}

/// The general span loop: every pixel's depth converted (rounded and clamped) on its own.
#[inline(always)]
fn clamped_span<D: DepthFormat, C: Copy, T: DepthTest, K: FragmentCount>(
    depths: &mut [D],
    colors: &mut [C],
    start: i64,
    step: i64,
    mut colors_in: impl SpanColors<C>,
    mut failed: u32,
) -> u32 {
    let mut acc = start;
    let le = T::OR_EQUAL;
    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {
        let z = D::from_interpolated(acc);
        acc = acc.wrapping_add(step);
        if z < *d || (le && z == *d) {
            *d = z;
            *c = colors_in.next_color();
        } else {
            colors_in.skip();
            if K::COUNTED {
                failed = failed.wrapping_add(1);
            }
        }
    }
    failed
}

impl sealed::Sealed for u16 {}
impl sealed::Sealed for u32 {}

/// 16-bit depth: `round(z · 65536)`, clamped to 65535.
impl DepthFormat for u16 {
    const FAR: u16 = u16::MAX;
    #[inline(always)]
    fn from_interpolated(acc: i64) -> u16 {
        (acc.saturating_add(HALF_STEP) >> U16_STEP_BITS).clamp(0, u16::MAX as i64) as u16
    }

    /// The span loop in 32 bits: depth in u16 units with 15 fraction bits. The start is rounded
    /// once (so truncating each pixel rounds to nearest) and the step to 2⁻¹⁵ of a unit, which
    /// drifts less than 2⁻⁴ of a unit over 2048 pixels. Spans whose ends are both inside the
    /// range need no clamp at all (depth is linear along a span); others take the general loop.
    #[inline(always)]
    fn test_span<C: Copy, T: DepthTest, K: FragmentCount>(
        depths: &mut [u16],
        colors: &mut [C],
        start: i64,
        step: i64,
        colors_in: impl SpanColors<C>,
        failed: u32,
    ) -> u32 {
        let n = depths.len().min(colors.len());
        let a = start.saturating_add(HALF_STEP) >> DROPPED;
        let st = loop_step(step);
        let last = a.saturating_add(st.saturating_mul(n.saturating_sub(1) as i64));
        let in_range = |v: i64| (0..=i32::MAX as i64).contains(&v);
        if !(in_range(a) && in_range(last) && i32::try_from(st).is_ok()) {
            // Ends outside [0, 65536): clamp pixel by pixel.
            return clamped_span::<u16, C, T, K>(depths, colors, start, step, colors_in, failed);
        }
        Self::test_span_unclamped::<C, T, K>(depths, colors, a as i32, st as i32, colors_in, failed)
    }

    /// Pixel centres inside a triangle have depths between its vertices': with every vertex
    /// at most 2³⁰ − 2¹⁴ (Q1.30), the loop's exact values (twice the depth, plus half a u16
    /// step, 2¹⁴) lie in [2¹⁴, 2³¹ − 2¹⁴], and a [`RoundedRows`] walk errs from them by
    /// less than 2¹² + 2 (the pipeline's pixels lie within 2¹² of a triangle's vertices):
    /// every value of the loop lies in [0, 2³¹).
    #[inline(always)]
    fn unclamped(max: i32) -> bool {
        max <= (1 << 30) - (1 << 14)
    }

    #[inline(always)]
    fn test_span_unclamped<C: Copy, T: DepthTest, K: FragmentCount>(
        depths: &mut [u16],
        colors: &mut [C],
        acc: i32,
        st: i32,
        colors_in: impl SpanColors<C>,
        failed: u32,
    ) -> u32 {
        // Every value lies in [0, 2³¹) (the start too): no overflow, no clamp.
        unclamped_u16::<C, T, K>(depths, colors, acc, st, colors_in, failed)
    }
}

/// The u16 span loop without clamping: depth in u16 units with 15 fraction bits from `acc`,
/// stepped by `st`; the test is `T`'s.
#[inline(always)]
fn unclamped_u16<C: Copy, T: DepthTest, K: FragmentCount>(
    depths: &mut [u16],
    colors: &mut [C],
    acc: i32,
    st: i32,
    mut colors_in: impl SpanColors<C>,
    mut failed: u32,
) -> u32 {
    // Every value lies in [0, 2³¹): the depth is its bits 15 to 30.
    let (mut acc, st) = (acc as u32, st as u32);
    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {
        let z = acc >> (U16_STEP_BITS - DROPPED);
        acc = acc.wrapping_add(st);
        let old = u32::from(*d);
        if z < old || (T::OR_EQUAL && z == old) {
            *d = z as u16;
            *c = colors_in.next_color();
        } else {
            colors_in.skip();
            if K::COUNTED {
                failed = failed.wrapping_add(1);
            }
        }
    }
    failed
}

/// The u16 span loop's step from the interpolator's, rounded to its unit.
#[inline(always)]
fn loop_step(step: i64) -> i64 {
    step.saturating_add(1 << (DROPPED - 1)) >> DROPPED
}

/// The u16 depth loop's values in 32-bit words, in its unit (2⁻³¹ of the depth range, 2⁻¹⁵ of
/// a u16 step, half a step added so that truncation rounds), row by row: the triangle's
/// [`WordPlane`](crate::raster::WordPlane) of its vertex depths (whose error bound, below
/// 2¹² + 2 units, is a fraction of a step), started on a row and moved down one row at a time.
/// The span loop starts from it with one multiply and one addition a span, and steps by `sx`.
/// Every core takes the same words, so every core draws the same depths (rule R10).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RoundedRows {
    /// The start at column 0 on the current row.
    pub(super) row: i32,
    pub(super) step_x: i32,
    pub(super) step_y: i32,
}

impl RoundedRows {
    /// A walk that is never read.
    pub(crate) const NONE: Self = RoundedRows {
        row: 0,
        step_x: 0,
        step_y: 0,
    };

    /// The walk of the plane through `(p[i], z[i])` (depths in Q1.30, at most 2³⁰; `area` the
    /// doubled signed area, non-zero; coordinates within the pipeline's range) on row `y`,
    /// with the loop's step along a row; `None` where a step does not fit 32 bits (a triangle
    /// nearly edge-on, which the general loop takes).
    #[inline(always)]
    pub(crate) fn new(p: &[ScreenPoint; 3], z: [i32; 3], area: i64, y: i32) -> Option<(Self, i32)> {
        let walk = AreaWalks::new(area).walk(p, z, 0, LOOP_HALF_STEP)?;
        let rows = RoundedRows {
            row: walk.at(0, y),
            step_x: walk.sx,
            step_y: walk.sy,
        };
        Some((rows, walk.sx))
    }
}

impl RowStarts for RoundedRows {
    type Start = i32;

    #[inline(always)]
    fn at(&self, x: i32) -> i32 {
        self.row.wrapping_add(self.step_x.wrapping_mul(x))
    }

    #[inline(always)]
    fn next_row(&mut self) {
        self.row = self.row.wrapping_add(self.step_y);
    }
}

/// 32-bit depth: `round(z · 2³²)`, clamped to `u32::MAX`; its resolution is that of the
/// pipeline's Q1.30 depth (30 significant bits).
impl DepthFormat for u32 {
    const FAR: u32 = u32::MAX;
    #[inline(always)]
    fn from_interpolated(acc: i64) -> u32 {
        (acc.saturating_add(1 << 11) >> 12).clamp(0, u32::MAX as i64) as u32
    }
}

/// Which fragment wins the depth test: [`Less`] (the default) or [`LessOrEqual`].
///
/// The test is a type, chosen when the target is built
/// ([`ColorDepth::with_test`](super::ColorDepth::with_test)), so a firmware links the one pixel
/// loop it uses, and that loop tests no flag.
pub trait DepthTest: sealed::Sealed + Copy + Default + core::fmt::Debug {
    /// True when a fragment at the same depth as the stored one wins too.
    const OR_EQUAL: bool;
}

/// Strictly nearer wins (the default): the first of two equal depths stays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Less;

/// Nearer or equal wins: the last of two equal depths stays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct LessOrEqual;

impl sealed::Sealed for Less {}
impl sealed::Sealed for LessOrEqual {}

impl DepthTest for Less {
    const OR_EQUAL: bool = false;
}

impl DepthTest for LessOrEqual {
    const OR_EQUAL: bool = true;
}

/// Whether a target counts the fragments it depth-tests and writes
/// ([`Stats::fragments`](crate::stats::Stats::fragments) and
/// [`written`](crate::stats::Stats::written)): [`Counted`] (the default) or [`Uncounted`].
///
/// A type, chosen when the target is built
/// ([`ColorDepth::uncounted`](super::ColorDepth::uncounted)): a frame that does not need the
/// counts does not pay for them (a count per span and one per failed fragment, and the
/// registers they hold in the row loop; docs/performance.md gives the cost).
pub trait FragmentCount: sealed::Sealed + Copy + Default + core::fmt::Debug {
    /// True when fragments and writes are counted.
    const COUNTED: bool;
}

/// Fragments and writes are counted into [`Stats`](crate::stats::Stats) (the default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Counted;

/// Fragments and writes are not counted: [`Stats::fragments`](crate::stats::Stats::fragments)
/// and [`written`](crate::stats::Stats::written) stay 0 (the other statistics are kept).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Uncounted;

impl sealed::Sealed for Counted {}
impl sealed::Sealed for Uncounted {}

impl FragmentCount for Counted {
    const COUNTED: bool = true;
}

impl FragmentCount for Uncounted {
    const COUNTED: bool = false;
}

/// A `width × height` depth buffer over a caller-supplied slice.
///
/// ```
/// use fixed3d::buffer::{DepthBuffer, DepthFormat};
/// let mut values = [0u16; 320 * 16];
/// let mut depth = DepthBuffer::new(&mut values, 320, 16).unwrap();
/// depth.clear();
/// assert_eq!(depth.get(5, 5), Some(u16::FAR));
/// ```
#[derive(Debug)]
pub struct DepthBuffer<'a, D> {
    grid: Grid<'a, D>,
}

impl<'a, D: DepthFormat> DepthBuffer<'a, D> {
    /// Wraps `values` (at least `width · height` long; only that prefix is used).
    pub fn new(values: &'a mut [D], width: u32, height: u32) -> Result<Self, BufferError> {
        Ok(DepthBuffer {
            grid: Grid::new(values, width, height)?,
        })
    }

    /// Sets every value to the far plane.
    pub fn clear(&mut self) {
        self.grid.fill(D::FAR);
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.grid.width()
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.grid.height()
    }

    /// The values, row-major.
    #[must_use]
    pub fn values(&self) -> &[D] {
        self.grid.cells()
    }

    /// The depth at `(x, y)`, `None` outside.
    #[must_use]
    pub fn get(&self, x: i32, y: i32) -> Option<D> {
        self.grid.get(x, y)
    }

    /// Every depth, row-major (`width · height` of them).
    #[inline]
    pub(crate) fn cells_all_mut(&mut self) -> &mut [D] {
        self.grid.cells_all_mut()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{
        doubled_area, first_centre_from32, spans_in_range, PipelineEdge, PixelRect, Plane,
        PIPELINE_LIMIT,
    };

    /// Every value of a `RoundedRows` walk lies within its bound,
    /// `(|x − x_r| + |y − y_r|) / 2 + 5/4`, of the exact plane's (in rationals: twice the
    /// depth plus half a u16 step), and the stored depth is the exact one's at nearly every
    /// pixel; a walk set up at a later row (a band's first) is the walk from an earlier one.
    /// Triangles of every size within the pipeline's range, depths across [0,
    /// 2³⁰ − 2¹⁴], cut by the clip rectangle's top.
    #[test]
    fn rounded_rows_stay_within_their_bound() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let clip = PixelRect::new(0, 40, 2040, 2040);
        let (mut pixels, mut same_depth, mut cut) = (0u64, 0u64, 0u32);
        for _ in 0..3_000 {
            let scale = rng.pick(&[40, 400, 4000, PIPELINE_LIMIT / 2]);
            let centre = ScreenPoint::new(16 * 1000, 16 * 600);
            let p = rng.triangle(centre, scale).map(|q| {
                ScreenPoint::new(q.x.clamp(0, PIPELINE_LIMIT), q.y.clamp(0, PIPELINE_LIMIT))
            });
            let area = doubled_area(p[0], p[1], p[2]);
            let z = [(); 3].map(|_| (rng.within(1 << 29) + (1 << 29) - (1 << 14)).max(0));
            if area == 0 || !u16::unclamped(z[0].max(z[1]).max(z[2])) {
                continue;
            }
            let spans = spans_in_range::<PipelineEdge>(p, clip, area);
            let y0 = spans.row();
            let (Some((mut narrow, st)), Some((mut early, _))) = (
                RoundedRows::new(&p, z, area, y0),
                RoundedRows::new(&p, z, area, y0 - 7),
            ) else {
                continue;
            };
            for _ in 0..7 {
                early.next_row();
            }
            cut += u32::from(y0 > p.iter().map(|q| q.y).min().unwrap_or(0) / 16 + 1);
            // The exact value at (x, y), in units of 1 / (16 · |area|).
            let (nx, ny) = Plane::numerators(&p, z);
            let (nx, ny, den) = if area < 0 {
                (-nx, -ny, -area)
            } else {
                (nx, ny, area)
            };
            let (nx, ny, den) = (nx as i128, ny as i128, den as i128);
            let a = p[0];
            let (x_r, y_r) = (a.x >> 4, first_centre_from32(a.y));
            let mut row = y0;
            for span in spans {
                while row < span.y {
                    narrow.next_row();
                    early.next_row();
                    row += 1;
                }
                let y = span.y;
                assert_eq!(narrow.at(span.x0), early.at(span.x0), "{p:?} row {y}");
                for x in span.x0..span.x1.min(span.x0 + 64) {
                    let walk = narrow.at(x);
                    assert_eq!(narrow.at(span.x0).wrapping_add(st * (x - span.x0)), walk);
                    let (dx, dy) = ((16 * x + 8 - a.x) as i128, (16 * y + 8 - a.y) as i128);
                    let num = (2 * z[0] as i128 + (1 << 14)) * 16 * den + 32 * (nx * dx + ny * dy);
                    let diff = (walk as i128 * 16 * den - num).abs();
                    let far = ((x - x_r).abs() + (y - y_r).abs()) as i128;
                    assert!(diff <= 8 * den * far + 20 * den, "{p:?} ({x}, {y})");
                    let exact = num.div_euclid(16 * den);
                    same_depth += u64::from(walk as i128 >> 15 == exact >> 15);
                    pixels += 1;
                }
            }
        }
        assert!(pixels > 1_000_000 && cut > 100, "{pixels} {cut}");
        assert!(
            same_depth > pixels - pixels / 100,
            "{same_depth} of {pixels}"
        );
    }
}

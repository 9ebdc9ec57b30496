//! Depth buffers: per-pixel depth in a caller-supplied `&mut [u16]` or `&mut [u32]`.

use super::grid::{BufferError, Grid};
use crate::raster::{Plane, RowStarts};

/// The interpolator's fraction bits below one u16 step (its Q1.44 value has 2¹⁶ steps).
const U16_STEP_BITS: u32 = 28;
/// Of those, the u16 span loop drops these and keeps the other 15: depth is bits 15 to 30 of
/// its 32-bit value.
const DROPPED: u32 = 13;
/// Half a u16 step in the interpolator's units: added once, truncation then rounds to nearest.
const HALF_STEP: i64 = 1 << (U16_STEP_BITS - 1);

mod sealed {
    pub trait Sealed {}
}

/// A stored depth format: 0 is the near plane, `FAR` the far plane (and the cleared value).
///
/// Depth reaches the buffer through one conversion from the interpolator (a Q1.44 value where
/// 2⁴⁴ is the far plane), rounded to nearest and saturated, never wrapped (rule R7).
pub trait DepthFormat: Copy + Ord + sealed::Sealed + core::fmt::Debug {
    /// The far plane, and the value a cleared buffer holds.
    const FAR: Self;
    /// Depth from the interpolator's Q1.44 value, rounded and clamped to `[0, FAR]`.
    #[doc(hidden)]
    fn from_interpolated(acc: i64) -> Self;

    /// For a triangle whose vertex depths are at most `max` (Q1.44), the per-pixel step of
    /// [`test_span_unclamped`](Self::test_span_unclamped) if every pixel it covers can skip
    /// the clamp, from the interpolator's step.
    #[doc(hidden)]
    #[inline(always)]
    fn unclamped_step(max: i64, step: i64) -> Option<i32> {
        let _ = (max, step);
        None
    }

    /// [`test_span`](Self::test_span) for a span of a triangle that
    /// [`unclamped_step`](Self::unclamped_step) accepted, with the step it returned; `start`
    /// is the interpolator's value `v` at the first pixel as the 32-bit loop holds it,
    /// `⌊(v + 2²⁷) / 2¹³⌋`.
    #[doc(hidden)]
    #[inline(always)]
    fn test_span_unclamped<C: Copy>(
        depths: &mut [Self],
        colors: &mut [C],
        start: i32,
        step: i32,
        test: DepthTest,
        next_color: impl FnMut() -> C,
        failed: u32,
    ) -> u32 {
        // Formats without a fast path never hand out a step; this only keeps the contract.
        let start = ((start as i64) << DROPPED).wrapping_sub(HALF_STEP);
        Self::test_span(
            depths,
            colors,
            start,
            (step as i64) << DROPPED,
            test,
            next_color,
            failed,
        )
    }

    /// Depth-tests one span: `start` and `step` are the interpolator's values at the first
    /// pixel and from pixel to pixel. `next_color` is called once per pixel, in order; its
    /// colour is stored where the fragment passes. Returns `failed` (the count so far) plus
    /// how many failed: the pixel loop counts on from it, so the count needs no sum per span
    /// (and counts the fragments that fail, fewer than those that pass).
    #[doc(hidden)]
    #[inline(always)]
    fn test_span<C: Copy>(
        depths: &mut [Self],
        colors: &mut [C],
        start: i64,
        step: i64,
        test: DepthTest,
        next_color: impl FnMut() -> C,
        failed: u32,
    ) -> u32 {
        clamped_span(depths, colors, start, step, test, next_color, failed)
    }
}

/// The general span loop: every pixel's depth converted (rounded and clamped) on its own.
#[inline(always)]
fn clamped_span<D: DepthFormat, C: Copy>(
    depths: &mut [D],
    colors: &mut [C],
    start: i64,
    step: i64,
    test: DepthTest,
    mut next_color: impl FnMut() -> C,
    mut failed: u32,
) -> u32 {
    let mut acc = start;
    let le = test == DepthTest::LessOrEqual;
    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {
        let z = D::from_interpolated(acc);
        acc = acc.wrapping_add(step);
        let color = next_color();
        if z < *d || (le && z == *d) {
            *d = z;
            *c = color;
        } else {
            failed = failed.wrapping_add(1);
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
    fn test_span<C: Copy>(
        depths: &mut [u16],
        colors: &mut [C],
        start: i64,
        step: i64,
        test: DepthTest,
        next_color: impl FnMut() -> C,
        failed: u32,
    ) -> u32 {
        let n = depths.len().min(colors.len());
        let a = start.saturating_add(HALF_STEP) >> DROPPED;
        let st = loop_step(step);
        let last = a.saturating_add(st.saturating_mul(n.saturating_sub(1) as i64));
        let in_range = |v: i64| (0..=i32::MAX as i64).contains(&v);
        if !(in_range(a) && in_range(last) && i32::try_from(st).is_ok()) {
            // Ends outside [0, 65536): clamp pixel by pixel.
            return clamped_span(depths, colors, start, step, test, next_color, failed);
        }
        Self::test_span_unclamped(
            depths, colors, a as i32, st as i32, test, next_color, failed,
        )
    }

    /// Pixel centres inside a triangle have depths between its vertices', and the plane errs
    /// by at most 2¹⁷ units there (see `Plane`): the loop's exact start `⌊(v + 2²⁷) / 2¹³⌋`
    /// lies in `[2¹⁴ − 16, 2³¹ − 2¹⁴ + 16]` with every vertex at most 2⁴⁴ − 2²⁸. The
    /// [`RoundedRows`] start errs from it by at most 2¹² (the pipeline's pixels lie within
    /// ±2¹¹ of the origin), and the 32-bit step by less than 2¹⁰ over a span: every value of
    /// the loop lies in [0, 2³¹).
    #[inline(always)]
    fn unclamped_step(max: i64, step: i64) -> Option<i32> {
        (max <= (1 << 44) - (1 << U16_STEP_BITS))
            .then(|| i32::try_from(loop_step(step)).ok())
            .flatten()
    }

    #[inline(always)]
    fn test_span_unclamped<C: Copy>(
        depths: &mut [u16],
        colors: &mut [C],
        acc: i32,
        st: i32,
        test: DepthTest,
        next_color: impl FnMut() -> C,
        failed: u32,
    ) -> u32 {
        // Every value lies in [0, 2³¹) (the start too): no overflow, no clamp.
        match test {
            DepthTest::Less => {
                unclamped_u16::<C, false>(depths, colors, acc, st, next_color, failed)
            }
            DepthTest::LessOrEqual => {
                unclamped_u16::<C, true>(depths, colors, acc, st, next_color, failed)
            }
        }
    }
}

/// The u16 span loop without clamping: depth in u16 units with 15 fraction bits from `acc`,
/// stepped by `st`; the test is fixed at compile time (`LE`: nearer or equal wins).
#[inline(always)]
fn unclamped_u16<C: Copy, const LE: bool>(
    depths: &mut [u16],
    colors: &mut [C],
    acc: i32,
    st: i32,
    mut next_color: impl FnMut() -> C,
    mut failed: u32,
) -> u32 {
    // Every value lies in [0, 2³¹): the depth is its bits 15 to 30.
    let (mut acc, st) = (acc as u32, st as u32);
    for (d, c) in depths.iter_mut().zip(colors.iter_mut()) {
        let z = (acc >> (U16_STEP_BITS - DROPPED)) as Compared;
        acc = acc.wrapping_add(st);
        let color = next_color();
        let old = Compared::from(*d);
        if z < old || (LE && z == old) {
            *d = z as u16;
            *c = color;
        } else {
            failed = failed.wrapping_add(1);
        }
    }
    failed
}

/// The width the u16 loop compares depths in: 16 bits on x86-64, where a compare takes the
/// stored halfword straight from memory, and 32 on 32-bit cores, where the halfword is loaded
/// into a register anyway and a 16-bit value would cost a masking instruction (measured:
/// 16 bits everywhere costs Cortex-M0 2% and the M4 0.6%, 32 bits everywhere x86-64 1.7%).
#[cfg(target_pointer_width = "64")]
type Compared = u16;
/// The width the u16 loop compares depths in (see the 64-bit definition).
#[cfg(not(target_pointer_width = "64"))]
type Compared = u32;

/// The u16 span loop's step from the interpolator's, rounded to its unit.
#[inline(always)]
fn loop_step(step: i64) -> i64 {
    step.saturating_add(1 << (DROPPED - 1)) >> DROPPED
}

/// The u16 depth loop's start at the first pixel of each span, row after row, in 32-bit words:
/// the loop's value `⌊(v + 2²⁷) / 2¹³⌋` of the plane `v` at column 0 of the triangle's first
/// row, exactly, then stepped by the plane's gradients rounded to the loop's unit (2⁻¹⁵ of a
/// u16 step), `sx` per column and `sy` per row: the start at column `x`, `dy` rows down, is
/// `s₀ + sx·x + sy·dy` modulo 2³².
///
/// Each rounded gradient errs by at most half a unit, so a start errs by at most
/// `(|x| + |dy|) / 2 + 1` units from the exact value: below 2¹² units, 2⁻³ of a u16 step,
/// for the pipeline's pixels within ±2¹¹ of the origin (the stored depth is the exact
/// start's at 99% of the spans of the test below, triangles up to a thousand pixels across;
/// it stays within one step of the plane, rule R7), and the start depends on nothing but the
/// triangle, so a band draws what the whole frame draws. One multiply and one addition a span and one
/// addition a row, where the exact start took a 64-bit product and shift, or, without a long
/// multiply, six words of quotients and remainders: the torus of bench/SCENE.md 2.0% fewer
/// instructions per frame on Cortex-M4 (its pixel loop now keeps its colour in a register),
/// 1.2% on Cortex-M0, 0.6% more on x86-64 (the seed at the first row); the same image.
///
/// 64-bit hosts hold the same values shifted up by 13 bits in 64-bit words, so that their
/// loop takes the form of a 64-bit product and shift (in 32-bit words it kept its colour and
/// step on the stack: 4.2% more instructions on x86-64). The sums stay far below 2⁶³, so
/// shifting back and truncating to 32 bits gives the same starts on every core (rule R10).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RoundedRows<W: LoopWord = NativeWord> {
    /// The start at column 0 on the current row (as `W` holds values).
    row: W,
    step_x: W,
    step_y: W,
}

/// The word [`RoundedRows`] walks in: 64-bit words on 64-bit hosts, 32-bit ones elsewhere.
#[cfg(target_pointer_width = "64")]
pub(crate) type NativeWord = i64;
/// The word [`RoundedRows`] walks in (see the 64-bit definition).
#[cfg(not(target_pointer_width = "64"))]
pub(crate) type NativeWord = i32;

/// A word for [`RoundedRows`]: the loop's 32-bit values, as they are (`i32`) or shifted up by
/// 13 bits (`i64`).
pub(crate) trait LoopWord: Copy + core::fmt::Debug {
    /// A 32-bit value, scaled.
    fn from_i32(v: i32) -> Self;
    /// The 32-bit value (modulo 2³²).
    fn to_i32(self) -> i32;
    /// `self + a · b` for a scaled `a` and an unscaled `b`, wrapping.
    fn add_times(self, a: Self, b: i32) -> Self;
    /// `self + a`, wrapping.
    fn add(self, a: Self) -> Self;
}

impl LoopWord for i32 {
    #[inline(always)]
    fn from_i32(v: i32) -> i32 {
        v
    }
    #[inline(always)]
    fn to_i32(self) -> i32 {
        self
    }
    #[inline(always)]
    fn add_times(self, a: i32, b: i32) -> i32 {
        self.wrapping_add(a.wrapping_mul(b))
    }
    #[inline(always)]
    fn add(self, a: i32) -> i32 {
        self.wrapping_add(a)
    }
}

impl LoopWord for i64 {
    #[inline(always)]
    fn from_i32(v: i32) -> i64 {
        (v as i64) << DROPPED
    }
    #[inline(always)]
    fn to_i32(self) -> i32 {
        (self >> DROPPED) as i32
    }
    #[inline(always)]
    fn add_times(self, a: i64, b: i32) -> i64 {
        self.wrapping_add(a.wrapping_mul(b as i64))
    }
    #[inline(always)]
    fn add(self, a: i64) -> i64 {
        self.wrapping_add(a)
    }
}

impl<W: LoopWord> RoundedRows<W> {
    /// The walk of `plane` from column 0 of row `y_ref` (the triangle's first row), on row
    /// `y`, with the loop's per-column step `step_x` (the
    /// [`unclamped_step`](DepthFormat::unclamped_step)); `None` where the per-row step does
    /// not fit 32 bits (a triangle nearly edge-on along y, which the general loop takes).
    #[inline]
    pub(crate) fn new(plane: &Plane, y_ref: i32, y: i32, step_x: i32) -> Option<Self> {
        let (_, gy) = plane.pixel_steps();
        let step_y = i32::try_from(loop_step(gy)).ok()?;
        let start = (plane.at_near(0, y_ref).wrapping_add(HALF_STEP) >> DROPPED) as i32;
        let row = start.wrapping_add(step_y.wrapping_mul(y.wrapping_sub(y_ref)));
        Some(RoundedRows {
            row: W::from_i32(row),
            step_x: W::from_i32(step_x),
            step_y: W::from_i32(step_y),
        })
    }
}

impl<W: LoopWord> RowStarts for RoundedRows<W> {
    type Start = i32;

    #[inline(always)]
    fn at(&self, x: i32) -> i32 {
        self.row.add_times(self.step_x, x).to_i32()
    }

    #[inline(always)]
    fn next_row(&mut self) {
        self.row = self.row.add(self.step_y);
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

/// Which fragment wins the depth test.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DepthTest {
    /// Strictly nearer wins (the default): the first of two equal depths stays.
    #[default]
    Less,
    /// Nearer or equal wins: the last of two equal depths stays.
    LessOrEqual,
}

/// A `width × height` depth buffer over a caller-supplied slice.
///
/// ```
/// use fixed3d::target::{DepthBuffer, DepthFormat};
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
    use crate::raster::{triangle_spans, PixelRect, ScreenPoint, PIPELINE_LIMIT};

    /// `RoundedRows` in 32-bit words (Cortex-M's) and in 64-bit ones (the host's) give the
    /// same start at every span; each lies within `(|x| + |y − y_ref|) / 2 + 1` of the exact
    /// start `⌊(v + 2²⁷) / 2¹³⌋` (`y_ref` the triangle's first row), and a walk set up at a
    /// later row (a band's first) is the walk from the triangle's first row. Triangles of
    /// every size within the pipeline's range, cut by the clip rectangle's top.
    #[test]
    fn rounded_rows_stay_within_their_bound_on_every_core() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let clip = PixelRect::new(0, 40, 2040, 2040);
        let (mut starts, mut exact, mut cut) = (0u32, 0u32, 0u32);
        for _ in 0..20_000 {
            let scale = rng.pick(&[40, 400, 4000, PIPELINE_LIMIT / 2]);
            let centre = ScreenPoint::new(16 * 1000, 16 * 600);
            let p = rng.triangle(centre, scale).map(|q| {
                ScreenPoint::new(q.x.clamp(0, PIPELINE_LIMIT), q.y.clamp(0, PIPELINE_LIMIT))
            });
            let area = crate::raster::doubled_area(p[0], p[1], p[2]);
            if area == 0 {
                continue;
            }
            let z = [(); 3].map(|_| rng.within(1 << 29) + (1 << 29));
            let plane = Plane::scaled(&p, z, 14, area);
            let max = (*z.iter().max().unwrap_or(&0) as i64) << 14;
            let Some(st) = u16::unclamped_step(max, plane.step_x()) else {
                continue;
            };
            let spans = triangle_spans(p, clip);
            let (y_ref, y0) = (spans.first_row(), spans.row());
            let (Some(mut narrow), Some(mut wide), Some(mut from_top)) = (
                RoundedRows::<i32>::new(&plane, y_ref, y0, st),
                RoundedRows::<i64>::new(&plane, y_ref, y0, st),
                RoundedRows::<i32>::new(&plane, y_ref, y_ref, st),
            ) else {
                continue;
            };
            for _ in y_ref..y0 {
                from_top.next_row();
            }
            cut += u32::from(y0 > y_ref);
            let mut row = y0;
            for span in spans {
                let (x, y) = (span.x0, span.y);
                while row < y {
                    narrow.next_row();
                    wide.next_row();
                    from_top.next_row();
                    row += 1;
                }
                let walk = narrow.at(x);
                assert_eq!(wide.at(x), walk, "{p:?} row {y}");
                assert_eq!(from_top.at(x), walk, "{p:?} row {y}");
                let truth = plane.at(x, y).wrapping_add(HALF_STEP) >> DROPPED;
                let bound = (x.abs() + (y - y_ref).abs()) as i64 / 2 + 1;
                assert!(
                    (walk as i64 - truth).abs() <= bound,
                    "{p:?} ({x}, {y}): {walk} {truth}"
                );
                exact += u32::from(walk as i64 >> 15 == truth >> 15);
                starts += 1;
            }
        }
        assert!(starts > 1_000_000 && cut > 1000, "{starts} {cut}");
        // And the depth stored at a span's first pixel is nearly always the exact start's.
        assert!(exact > starts - starts / 100, "{exact} of {starts}");
    }
}

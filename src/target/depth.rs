//! Depth buffers: per-pixel depth in a caller-supplied `&mut [u16]` or `&mut [u32]`.

use super::grid::{BufferError, Grid};
use crate::raster::{Plane, PlaneRows, RowStarts};

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
    /// by at most 2¹⁷ units there (see `Plane`), the 32-bit step by less than 2²³ over a span:
    /// with every vertex at most 2⁴⁴ − 2²⁸, every value of the loop lies in [0, 2³¹).
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

/// The u16 depth loop's 32-bit start `⌊(v + 2²⁷) / 2¹³⌋` row after row: [`WideRows`] where
/// 64-bit products are one or two instructions (64-bit hosts, Cortex-M3/M4: on the M4 it
/// measured 0.3% to 0.7% fewer instructions per frame than [`ShortRows`]), [`ShortRows`]
/// (32-bit words only) on the cores of [`NARROW_CORE`](crate::math::NARROW_CORE), which
/// lack a long multiply. (The `cfg` is that constant's, negated.)
#[cfg(any(target_pointer_width = "64", target_has_atomic = "32"))]
pub(crate) type DepthRows = WideRows;
/// The u16 depth loop's 32-bit start row after row: see the other definition.
#[cfg(not(any(target_pointer_width = "64", target_has_atomic = "32")))]
pub(crate) type DepthRows = ShortRows;

/// [`RowStarts`] of `⌊(v + 2²⁷) / 2¹³⌋` (modulo 2³²) in 64-bit arithmetic: one product and a
/// shift per row.
#[cfg_attr(
    not(any(target_pointer_width = "64", target_has_atomic = "32")),
    allow(dead_code)
)]
#[derive(Clone, Copy, Debug)]
pub(crate) struct WideRows(PlaneRows);

#[cfg_attr(
    not(any(target_pointer_width = "64", target_has_atomic = "32")),
    allow(dead_code)
)]
impl WideRows {
    /// Starts at row `y`, for columns from `x_base` on.
    #[inline]
    pub(crate) fn new(plane: &Plane, x_base: i32, y: i32) -> WideRows {
        WideRows(plane.rows(x_base, y).plus(HALF_STEP))
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
#[cfg_attr(
    any(target_pointer_width = "64", target_has_atomic = "32"),
    allow(dead_code)
)]
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
#[cfg_attr(
    any(target_pointer_width = "64", target_has_atomic = "32"),
    allow(dead_code)
)]
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

#[cfg_attr(
    any(target_pointer_width = "64", target_has_atomic = "32"),
    allow(dead_code)
)]
impl ShortRows {
    /// Starts `⌊(plane + 2²⁷) / 2¹³⌋` at row `y`, for columns from `x_base` to less than
    /// `x_base + 2¹⁹`.
    #[inline]
    pub(crate) fn new(plane: &Plane, x_base: i32, y: i32) -> ShortRows {
        let (gx, gy) = plane.pixel_steps();
        let (a, alpha) = split(plane.at_near(x_base, y).wrapping_add(HALF_STEP));
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

//! Depth buffers: per-pixel depth in a caller-supplied `&mut [u16]` or `&mut [u32]`.

use super::grid::{BufferError, Grid};

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
}

impl sealed::Sealed for u16 {}
impl sealed::Sealed for u32 {}

/// 16-bit depth: `round(z · 65536)`, clamped to 65535.
impl DepthFormat for u16 {
    const FAR: u16 = u16::MAX;
    #[inline(always)]
    fn from_interpolated(acc: i64) -> u16 {
        (acc.saturating_add(1 << 27) >> 28).clamp(0, u16::MAX as i64) as u16
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

    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [D]> {
        self.grid.row_mut(y)
    }
}

//! The storage under both buffers: a `width × height` grid over a caller-supplied slice.

use core::fmt;
use core::ops::Range;

/// Why a buffer could not be wrapped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum BufferError {
    /// The slice holds fewer than `width · height` elements.
    TooShort {
        /// Elements needed.
        needed: usize,
        /// Elements given.
        len: usize,
    },
    /// `width · height` overflows, or a dimension exceeds `i32::MAX`.
    TooLarge,
    /// A colour buffer and a depth buffer paired for one target differ in size.
    SizeMismatch,
}

impl fmt::Display for BufferError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BufferError::TooShort { needed, len } => {
                write!(f, "buffer holds {len} elements, {needed} needed")
            }
            BufferError::TooLarge => f.write_str("buffer dimensions too large"),
            BufferError::SizeMismatch => f.write_str("colour and depth buffers differ in size"),
        }
    }
}

impl core::error::Error for BufferError {}

/// Row-major cells, top row first; every access is checked.
#[derive(Debug)]
pub(crate) struct Grid<'a, T> {
    cells: &'a mut [T],
    width: u32,
    height: u32,
}

impl<'a, T: Copy> Grid<'a, T> {
    /// Wraps the first `width · height` cells of `cells`.
    pub(crate) fn new(cells: &'a mut [T], width: u32, height: u32) -> Result<Self, BufferError> {
        if width > i32::MAX as u32 || height > i32::MAX as u32 {
            return Err(BufferError::TooLarge);
        }
        let needed = (width as usize)
            .checked_mul(height as usize)
            .ok_or(BufferError::TooLarge)?;
        let len = cells.len();
        let cells = cells
            .get_mut(..needed)
            .ok_or(BufferError::TooShort { needed, len })?;
        Ok(Grid {
            cells,
            width,
            height,
        })
    }

    pub(crate) fn width(&self) -> u32 {
        self.width
    }

    pub(crate) fn height(&self) -> u32 {
        self.height
    }

    pub(crate) fn cells(&self) -> &[T] {
        self.cells
    }

    pub(crate) fn fill(&mut self, value: T) {
        self.cells.fill(value);
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
        if x >= self.width || y >= self.height {
            return None;
        }
        Some(y as usize * self.width as usize + x as usize)
    }

    pub(crate) fn get(&self, x: i32, y: i32) -> Option<T> {
        self.index(x, y).and_then(|i| self.cells.get(i)).copied()
    }

    pub(crate) fn get_mut(&mut self, x: i32, y: i32) -> Option<&mut T> {
        self.index(x, y).and_then(|i| self.cells.get_mut(i))
    }

    /// The indices of cells `x0..x1` of row `y` (`None` unless the whole range lies in the
    /// grid): the same for every grid of this size.
    #[inline]
    pub(crate) fn span_range(&self, y: i32, x0: i32, x1: i32) -> Option<Range<usize>> {
        let (y, x0, x1) = (
            u32::try_from(y).ok()?,
            u32::try_from(x0).ok()?,
            u32::try_from(x1).ok()?,
        );
        if y >= self.height || x1 > self.width || x0 > x1 {
            return None;
        }
        // y < height and x1 ≤ width: the range lies within width · height ≤ len.
        let base = y as usize * self.width as usize;
        Some(base + x0 as usize..base + x1 as usize)
    }

    /// The cells of `range` (from [`span_range`](Self::span_range)).
    #[inline]
    pub(crate) fn cells_mut(&mut self, range: Range<usize>) -> Option<&mut [T]> {
        self.cells.get_mut(range)
    }

    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [T]> {
        let w = self.width as usize;
        let start = usize::try_from(y).ok()?.checked_mul(w)?;
        self.cells.get_mut(start..start.checked_add(w)?)
    }
}

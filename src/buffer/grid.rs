//! The storage under both buffers: a `width × height` grid over a caller-supplied slice.

use core::fmt;

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

    /// Every cell, row-major: exactly `width · height` of them.
    pub(crate) fn cells_all_mut(&mut self) -> &mut [T] {
        self.cells
    }

    pub(crate) fn fill(&mut self, value: T) {
        fill(self.cells, value);
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

    /// Row `y`'s cells; `None` outside the grid.
    pub(crate) fn row_mut(&mut self, y: i32) -> Option<&mut [T]> {
        // A negative row lies past the height too, as a word: one test. Below the height the
        // row lies within the `width · height` cells, which `new` checked fit: its start is a
        // word product that never wraps (a checked product is a 64-bit one on cores without a
        // long multiply).
        let y = y as u32;
        if y >= self.height {
            return None;
        }
        let w = self.width as usize;
        let start = (y as usize).wrapping_mul(w);
        self.cells.get_mut(start..start.wrapping_add(w))
    }
}

/// Sets every cell to `value`, sixteen cells a turn written out as sixteen stores. A loop of
/// one store a turn (which the compiler keeps rolled when optimising for size) or block copies
/// of the first cells through the copy routine take about twice the instructions; `value` is
/// hidden from the optimiser so that a background whose bytes are all equal (black, or the
/// far depth) is not turned into a call to the set routine, slower still on Cortex-M0.
pub(crate) fn fill<T: Copy>(cells: &mut [T], value: T) {
    let v = core::hint::black_box(value);
    let (blocks, rest) = cells.as_chunks_mut::<16>();
    for [c0, c1, c2, c3, c4, c5, c6, c7, c8, c9, c10, c11, c12, c13, c14, c15] in blocks {
        (*c0, *c1, *c2, *c3, *c4, *c5, *c6, *c7) = (v, v, v, v, v, v, v, v);
        (*c8, *c9, *c10, *c11, *c12, *c13, *c14, *c15) = (v, v, v, v, v, v, v, v);
    }
    rest.fill(v);
}

#[cfg(test)]
mod tests {
    /// `fill` sets every cell and nothing else, for every length around its blocks of 16 and
    /// for cells whose bytes are all equal (the values it hides from the optimiser).
    #[test]
    fn fill_sets_every_cell() {
        for len in 0..70 {
            for value in [0u16, 0xFFFF, 0x1234] {
                let mut cells = [7u16; 72];
                let (inside, after) = cells.split_at_mut(len);
                super::fill(inside, value);
                assert!(inside.iter().all(|&c| c == value), "{len} {value}");
                assert!(after.iter().all(|&c| c == 7), "{len} {value}");
            }
        }
    }
}

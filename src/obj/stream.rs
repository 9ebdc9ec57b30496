//! Parsing a file that arrives in pieces.

use super::statement::parse_line;
use super::{ObjBuffers, ObjCounts, ObjError, ObjErrorKind, Placement};

/// An OBJ parser fed in chunks of any size, holding at most one line of `N` bytes: a firmware
/// can read a model from an SD card block by block without ever holding the file. The result
/// (storage contents, counts, errors and their line numbers) is exactly that of
/// [`parse`](super::parse) over the whole file.
///
/// ```
/// use fixed3d::math::Vec3;
/// use fixed3d::obj::{ObjBuffers, ObjStream, Placement};
/// let (mut p, mut t) = ([Vec3::ZERO; 3], [[0u16; 3]; 1]);
/// let mut out = ObjBuffers::new(&mut p, &mut t);
/// let mut stream = ObjStream::<64>::new(Placement::AsIs);
/// for block in [&b"v 0 0 0\nv 1 0"[..], b" 0\r", b"\nv 0 1 0\nf 1 2", b" 3"] {
///     stream.push(block, &mut out).unwrap();
/// }
/// let counts = stream.finish(&mut out).unwrap();
/// assert_eq!((counts.positions, counts.triangles, counts.lines), (3, 1, 4));
/// ```
#[derive(Debug)]
pub struct ObjStream<const N: usize> {
    line: heapless::Vec<u8, N>,
    counts: ObjCounts,
    placement: Placement,
    /// The previous chunk ended with `\r`: a `\n` first in the next one belongs to it.
    after_cr: bool,
    failed: Option<ObjError>,
}

impl<const N: usize> ObjStream<N> {
    /// A parser with an `N`-byte line buffer.
    #[must_use]
    pub const fn new(placement: Placement) -> Self {
        ObjStream {
            line: heapless::Vec::new(),
            counts: ObjCounts::EMPTY,
            placement,
            after_cr: false,
            failed: None,
        }
    }

    /// What the lines parsed so far read: a caller that grows its storage between pieces can
    /// size it from these (a piece of `n` bytes ends at most `n` lines more).
    ///
    /// ```
    /// use fixed3d::math::Vec3;
    /// use fixed3d::obj::{ObjBuffers, ObjStream, Placement};
    /// let (mut p, mut t) = ([Vec3::ZERO; 4], [[0u16; 3]; 1]);
    /// let mut stream = ObjStream::<64>::new(Placement::AsIs);
    /// stream.push(b"v 0 0 0\nv 1 0 0\nv 0", &mut ObjBuffers::new(&mut p, &mut t)).unwrap();
    /// assert_eq!((stream.counts().positions, stream.counts().lines), (2, 2));
    /// ```
    #[must_use]
    pub fn counts(&self) -> ObjCounts {
        self.counts
    }

    /// Feeds the next piece of the file. After an error every call returns that error.
    pub fn push(&mut self, chunk: &[u8], out: &mut ObjBuffers<'_>) -> Result<(), ObjError> {
        if let Some(e) = self.failed {
            return Err(e);
        }
        for &b in chunk {
            if self.after_cr {
                self.after_cr = false;
                if b == b'\n' {
                    continue;
                }
            }
            if b == b'\n' || b == b'\r' {
                self.after_cr = b == b'\r';
                self.end_line(out, false)?;
            } else if self.line.push(b).is_err() {
                // The line cannot fit: that is its error whatever follows, reported now rather
                // than at its end, so that a file without line breaks is not read to its end.
                return self.end_line(out, true);
            }
        }
        Ok(())
    }

    /// Ends the file (a last line without a line break is parsed) and returns what was read.
    pub fn finish(mut self, out: &mut ObjBuffers<'_>) -> Result<ObjCounts, ObjError> {
        if let Some(e) = self.failed {
            return Err(e);
        }
        // A last line without a line break; a file that is only a byte-order mark has none.
        let bom_only = self.counts.lines == 0 && self.line[..] == [0xEF, 0xBB, 0xBF];
        if !(self.line.is_empty() || bom_only) {
            self.end_line(out, false)?;
        }
        Ok(self.counts)
    }

    /// Parses the line held, or fails it as longer than the buffer (`too_long`).
    fn end_line(&mut self, out: &mut ObjBuffers<'_>, too_long: bool) -> Result<(), ObjError> {
        let result = if too_long {
            Err(ObjError {
                line: self.counts.lines.saturating_add(1),
                column: u32::try_from(N).unwrap_or(u32::MAX).saturating_add(1),
                kind: ObjErrorKind::LineTooLong,
            })
        } else {
            let mut bytes: &[u8] = &self.line;
            // A byte-order mark before the first line, as `parse` skips it.
            if self.counts.lines == 0 {
                if let Some(rest) = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]) {
                    bytes = rest;
                }
            }
            parse_line(bytes, &mut self.counts, out, &self.placement)
        };
        self.line.clear();
        if let Err(e) = result {
            self.failed = Some(e);
        }
        result
    }
}

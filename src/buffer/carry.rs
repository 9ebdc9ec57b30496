//! Solid triangles carried from one band into the next.
//!
//! A frame drawn band after band, top to bottom, meets a triangle that crosses a band's last
//! row again in the next band. Set up afresh there, it would pay its fetch, culling and
//! shading, its edges and its depth walk once more; carried, it goes on from the row where the
//! band before stopped, in the colour it was given there. A carried walk is the walk the
//! triangle would set up on that row, bit for bit (every walk is exact), so a carried triangle
//! draws the pixels it would have drawn anyway.
//!
//! Triangles of one colour whose depths take the word walk are carried (most of a flat-shaded
//! frame's); the others are set up again in each band. The bands of a frame meet their
//! triangles in one order (the bins'), and the triangles one band carries are met again in the
//! same order in the next: [`Carries`] is a queue, read from its front and written at its back,
//! each entry under its bin. A triangle that was not carried (the queue was full) is set up
//! again.

use embedded_graphics::pixelcolor::Rgb888;

use super::depth::RoundedRows;
use crate::raster::{PipelineEdge, StoppedWalk};

/// A solid triangle stopped at a band's last row (see [`Carries`]): storage for a renderer.
#[derive(Clone, Copy, Debug)]
pub struct Carried {
    /// The triangle's bin: its object's tag and its index in the mesh.
    object: u16,
    triangle: u32,
    /// Its colour.
    pub(super) rgb: Rgb888,
    /// `None` in an unused entry only: an entry of zeros, which a `static` holds in no
    /// flash.
    pub(super) walk: Option<StoppedWalk<PipelineEdge>>,
    pub(super) depth: RoundedRows,
}

impl Carried {
    /// An unused entry (entries are written before they are read).
    pub const EMPTY: Carried = Carried {
        object: 0,
        triangle: 0,
        rgb: Rgb888::new(0, 0, 0),
        walk: None,
        depth: RoundedRows::NONE,
    };
}

impl Default for Carried {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// The solid triangles one band stopped at its last row, for the next band to go on with: a
/// queue over storage of the caller's (with none, nothing is carried, and every band sets up
/// every triangle it meets).
#[derive(Debug)]
pub struct Carries<'c> {
    slots: &'c mut [Carried],
    /// The first entry the band being drawn has not met yet, and how many are left.
    head: usize,
    unread: usize,
    /// Entries the band being drawn has written, after the unread ones.
    written: usize,
    /// The row the entries being written stopped on (the band's end).
    row: i32,
    /// The bin of the triangle being drawn, if it is one that can be carried, and its colour.
    current: Option<(u16, u32)>,
    rgb: Rgb888,
}

impl<'c> Carries<'c> {
    /// An empty queue over `slots`.
    pub fn new(slots: &'c mut [Carried]) -> Self {
        Carries {
            slots,
            head: 0,
            unread: 0,
            written: 0,
            row: i32::MIN,
            current: None,
            rgb: Rgb888::new(0, 0, 0),
        }
    }

    /// `i` taken back into the slots: below twice their number, as every index here is.
    #[inline(always)]
    fn wrap(&self, i: usize) -> usize {
        if i >= self.slots.len() {
            i - self.slots.len()
        } else {
            i
        }
    }

    /// Starts a band of rows `y0..y1`: what the band before carried is kept if it ended at
    /// `y0`, and dropped otherwise.
    pub(crate) fn begin_band(&mut self, y0: i32, y1: i32) {
        self.head = self.wrap(self.head + self.unread);
        self.unread = if self.row == y0 { self.written } else { 0 };
        self.written = 0;
        self.row = y1;
    }

    /// Meets the triangle binned as `key` (its object's tag, its index in the mesh; `None`: one
    /// that is not carried, as the pieces of a clipped triangle are not): true if the band
    /// before carried it, for [`take`](Self::take) to give back.
    #[inline]
    pub(crate) fn meet(&mut self, key: Option<(u16, u32)>) -> bool {
        self.current = key;
        match self.slots.get(self.head) {
            Some(c) if self.unread > 0 => Some((c.object, c.triangle)) == key,
            _ => false,
        }
    }

    /// The entry [`meet`](Self::meet) found, taken off the queue.
    #[inline]
    pub(crate) fn take(&mut self) -> Option<Carried> {
        let c = *self.slots.get(self.head)?;
        self.head = self.wrap(self.head + 1);
        self.unread = self.unread.saturating_sub(1);
        Some(c)
    }

    /// The current triangle is solid, in colour `rgb` (what [`keep`](Self::keep) carries).
    #[inline(always)]
    pub(crate) fn solid(&mut self, rgb: Rgb888) {
        self.rgb = rgb;
    }

    /// Carries the current triangle, stopped on the band's last row with `walk` and `depth`,
    /// into the next band, unless the storage is full.
    #[inline]
    pub(crate) fn keep(&mut self, walk: StoppedWalk<PipelineEdge>, depth: RoundedRows) {
        let Some((object, triangle)) = self.current else {
            return;
        };
        if self.unread + self.written >= self.slots.len() {
            return;
        }
        let at = self.wrap(self.head + self.unread + self.written);
        if let Some(slot) = self.slots.get_mut(at) {
            *slot = Carried {
                object,
                triangle,
                rgb: self.rgb,
                walk: Some(walk),
                depth,
            };
            self.written += 1;
        }
    }
}

/// What a frame's triangle walk hands solid triangles to: [`Carries`] for bands drawn top to
/// bottom, `()` for a walk that carries none (whose code then holds nothing of it).
pub(crate) trait Carrier {
    /// `f` of the queue, if there is one.
    fn with_carries<R>(&mut self, f: impl FnOnce(&mut Carries<'_>) -> R) -> Option<R>;

    /// Starts a band of rows `y0..y1` (see [`Carries::begin_band`]).
    #[inline(always)]
    fn begin_band(&mut self, y0: i32, y1: i32) {
        self.with_carries(|c| c.begin_band(y0, y1));
    }

    /// Meets the triangle binned as `key` (see [`Carries::meet`]).
    #[inline(always)]
    fn meet(&mut self, key: Option<(u16, u32)>) -> bool {
        self.with_carries(|c| c.meet(key)).unwrap_or(false)
    }
}

impl Carrier for () {
    #[inline(always)]
    fn with_carries<R>(&mut self, _: impl FnOnce(&mut Carries<'_>) -> R) -> Option<R> {
        None
    }
}

impl Carrier for Carries<'_> {
    #[inline(always)]
    fn with_carries<R>(&mut self, f: impl FnOnce(&mut Carries<'_>) -> R) -> Option<R> {
        Some(f(self))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::{spans_in_range, PixelRect, ScreenPoint, TriangleWalk};
    use std::vec::Vec;

    /// A walk stopped on row `row` (the queue keeps it as it is).
    fn walk(row: i32) -> StoppedWalk<PipelineEdge> {
        let p = |x: i32, y: i32| ScreenPoint::new(16 * x, 16 * y);
        let v = [p(0, 0), p(10, 100), p(-10, 100)];
        let area = -16 * 16 * 2000;
        let clip = PixelRect::new(-20, row, 20, row + 1);
        let w: TriangleWalk<PipelineEdge> = spans_in_range(v, clip, area);
        w.stopped()
    }

    /// Draws bins `keys` of a band of rows `y0..y1`: each met (true where it was carried
    /// into it, and then taken), kept if `keep` says so.
    fn band(
        q: &mut Carries<'_>,
        (y0, y1): (i32, i32),
        keys: &[u32],
        keep: impl Fn(u32) -> bool,
    ) -> Vec<bool> {
        q.begin_band(y0, y1);
        keys.iter()
            .map(|&k| {
                let carried = q.meet(Some((0, k)));
                if carried {
                    assert!(q.take().is_some());
                }
                if keep(k) {
                    q.solid(Rgb888::new(k as u8, 0, 0));
                    q.keep(walk(y1), RoundedRows::NONE);
                }
                carried
            })
            .collect()
    }

    /// A band meets what the band above it carried, in order, each once; bands that do not
    /// follow one another carry nothing across; the pieces of a clipped triangle (met as
    /// `None`) are never kept; the ring wraps around its slots.
    #[test]
    fn a_band_meets_what_the_band_above_carried() {
        let mut slots = [Carried::EMPTY; 3];
        let mut q = Carries::new(&mut slots);
        assert_eq!(band(&mut q, (0, 4), &[1, 2, 3], |k| k != 2), [false; 3]);
        // 1 and 3 were carried (2 was not); a bin met between them is set up.
        assert_eq!(
            band(&mut q, (4, 8), &[1, 2, 3], |_| true),
            [true, false, true]
        );
        // All three were carried, but only into a band starting at row 8.
        assert_eq!(band(&mut q, (9, 12), &[1, 2, 3], |_| true), [false; 3]);
        assert_eq!(band(&mut q, (12, 16), &[1, 2, 3], |_| false), [true; 3]);
        // Room for three: the fourth is not carried; many bands wrap the ring around.
        for y in 4..40 {
            let got = band(&mut q, (4 * y, 4 * y + 4), &[5, 6, 7, 8], |_| true);
            let want = if y == 4 {
                [false; 4]
            } else {
                [true, true, true, false]
            };
            assert_eq!(got, want, "band {y}");
        }
        // Pieces are not kept.
        q.begin_band(160, 164);
        q.meet(None);
        q.keep(walk(164), RoundedRows::NONE);
        q.begin_band(164, 168);
        assert!(!q.meet(Some((0, 5))));
    }
}

//! Lines by the column-centre rule: Bresenham's algorithm generalised to sub-pixel endpoints,
//! with an exact start anywhere along the line so that clipping changes nothing.

use embedded_graphics::prelude::Point;

use super::{ceil_div, first_centre_from, floor_div, FloorStepper, PixelRect, ScreenPoint};
use crate::math::{mul_wide, SUBPIXEL_BITS, SUBPIXEL_SCALE};

const S: i64 = SUBPIXEL_SCALE as i64;
const HALF: i64 = S / 2;

/// The pixels of one line, clipped to a rectangle: see [`line_pixels`].
#[derive(Clone, Debug)]
pub struct LinePixels {
    minor: FloorStepper,
    major: i32,
    major_end: i32,
    swapped: bool,
}

/// The pixels of the line from `a` to `b` inside `clip` (see the [module
/// documentation](super) for the rule): the start is drawn, the end is not, and the pixels
/// inside `clip` are exactly those of the unclipped line. Work is proportional to the pixels
/// drawn, however far the endpoints lie off screen. Endpoints beyond
/// [`COORD_LIMIT`](super::COORD_LIMIT) yield nothing.
///
/// ```
/// use fixed3d::raster::{line_pixels, PixelRect, ScreenPoint};
/// use embedded_graphics::prelude::Point;
/// let c = ScreenPoint::pixel_center;
/// let pixels: Vec<Point> = line_pixels(c(0, 0), c(5, 2), PixelRect::of_size(8, 8)).collect();
/// let expect = [(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)].map(|(x, y)| Point::new(x, y));
/// assert_eq!(pixels, expect);
/// ```
#[must_use]
pub fn line_pixels(a: ScreenPoint, b: ScreenPoint, clip: PixelRect) -> LinePixels {
    let empty = LinePixels {
        minor: FloorStepper::ZERO,
        major: 0,
        major_end: 0,
        swapped: false,
    };
    if !a.in_range() || !b.in_range() || clip.is_empty() {
        return empty;
    }
    let (dx, dy) = (b.x as i64 - a.x as i64, b.y as i64 - a.y as i64);
    if dx == 0 && dy == 0 {
        return empty;
    }
    // Work in (major, minor) coordinates.
    let swapped = dx.abs() < dy.abs();
    let (a, b, lo, hi) = if swapped {
        (
            (a.y as i64, a.x as i64),
            (b.y as i64, b.x as i64),
            (clip.y0, clip.x0),
            (clip.y1, clip.x1),
        )
    } else {
        (
            (a.x as i64, a.y as i64),
            (b.x as i64, b.y as i64),
            (clip.x0, clip.y0),
            (clip.x1, clip.y1),
        )
    };
    let (dmaj, dmin) = (b.0 - a.0, b.1 - a.1);
    // Columns whose centre lies in [a, b) along the major axis (or (b, a] going backwards).
    let (mut i0, mut i1) = if dmaj > 0 {
        (first_centre_from(a.0), first_centre_from(b.0))
    } else {
        // ⌊v / S⌋ by a shift (S is a power of two).
        (
            ((b.0 - HALF) >> SUBPIXEL_BITS) + 1,
            ((a.0 - HALF) >> SUBPIXEL_BITS) + 1,
        )
    };
    i0 = i0.max(lo.0 as i64);
    i1 = i1.min(hi.0 as i64);
    // minor(i) = floor(N(i) / den), N(i) = c + i·step (signs folded so that den > 0).
    // The sign folded in by negation, not by a product (a library routine on some cores).
    let signed = |v: i64| if dmaj < 0 { -v } else { v };
    let den = S * dmaj.abs();
    // Coordinates within ±COORD_LIMIT: every factor fits a word.
    let wide = |x: i64, y: i64| mul_wide(x as i32, y as i32);
    let c = signed(wide(a.1, dmaj) + wide(HALF - a.0, dmin));
    let step = signed(S * dmin);
    // Keep the columns whose minor coordinate lies in [lo.1, hi.1); minor(i) is monotonic.
    // It is ⌊y / S⌋ for the line's y at a column centre between the endpoints, so it lies
    // between their rows: where those lie in [lo.1, hi.1), every column is kept, without the
    // divisions that find where the line leaves.
    let rows = (a.1.min(b.1) >> SUBPIXEL_BITS, a.1.max(b.1) >> SUBPIXEL_BITS);
    if rows.0 < lo.1 as i64 || rows.1 >= hi.1 as i64 {
        let n_lo = (lo.1 as i64).saturating_mul(den);
        let n_hi = (hi.1 as i64).saturating_mul(den);
        if step > 0 {
            i0 = i0.max(ceil_div(n_lo.saturating_sub(c), step));
            i1 = i1.min(ceil_div(n_hi.saturating_sub(c), step));
        } else if step < 0 {
            let p = -step;
            i0 = i0.max(floor_div(c.saturating_sub(n_hi), p) + 1);
            i1 = i1.min(floor_div(c.saturating_sub(n_lo), p) + 1);
        } else {
            let m = floor_div(c, den);
            if m < lo.1 as i64 || m >= hi.1 as i64 {
                return empty;
            }
        }
    }
    if i0 >= i1 {
        return empty;
    }
    LinePixels {
        minor: FloorStepper::new(c + i0 * step, den, step),
        major: i0 as i32,
        major_end: i1 as i32,
        swapped,
    }
}

impl Iterator for LinePixels {
    type Item = Point;

    #[inline]
    fn next(&mut self) -> Option<Point> {
        if self.major >= self.major_end {
            return None;
        }
        let (i, m) = (self.major, self.minor.value);
        self.major += 1;
        self.minor.step();
        Some(if self.swapped {
            Point::new(m, i)
        } else {
            Point::new(i, m)
        })
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.major_end.saturating_sub(self.major).max(0) as usize;
        (n, Some(n))
    }
}

impl ExactSizeIterator for LinePixels {}

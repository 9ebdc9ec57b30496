//! Lines by the column-centre rule: Bresenham's algorithm generalised to sub-pixel endpoints,
//! with an exact start anywhere along the line so that clipping changes nothing.

use embedded_graphics::prelude::Point;

use super::{
    ceil_div, first_centre_from, floor_div, floor_divmod, FloorStepper, PixelRect, ScreenPoint,
};
use crate::math::{mul_wide, NARROW_CORE, SUBPIXEL_BITS, SUBPIXEL_SCALE};

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
    line_pixels_with::<NARROW_CORE>(a, b, clip)
}

/// [`line_pixels`], a line's first column set up in words where `WORDS` and that column is its
/// start's (see [`first_column_in_words`]): what cores without a divide instruction take
/// (`NARROW_CORE`); elsewhere the general set-up costs no more, and the test would cost each
/// line. Both are tested on every host.
#[inline(always)]
fn line_pixels_with<const WORDS: bool>(
    a: ScreenPoint,
    b: ScreenPoint,
    clip: PixelRect,
) -> LinePixels {
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
    let at_zero = || signed(wide(a.1, dmaj) + wide(HALF - a.0, dmin));
    // N(0): found here where products are cheap; where they are not, only for the lines that
    // need it (those cut at the clip's rows, or not set up in words; see below).
    let early = if WORDS { None } else { Some(at_zero()) };
    let c = || early.unwrap_or_else(at_zero);
    let step = signed(S * dmin);
    // Keep the columns whose minor coordinate lies in [lo.1, hi.1); minor(i) is monotonic.
    // It is ⌊y / S⌋ for the line's y at a column centre between the endpoints, so it lies
    // between their rows: where those lie in [lo.1, hi.1), every column is kept, without the
    // divisions that find where the line leaves.
    let rows = (a.1.min(b.1) >> SUBPIXEL_BITS, a.1.max(b.1) >> SUBPIXEL_BITS);
    if rows.0 < lo.1 as i64 || rows.1 >= hi.1 as i64 {
        let c = c();
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
    let minor = if WORDS {
        // den ≥ 16 (|dmaj| ≥ 1); quotients and remainders within words, as in
        // `RationalStepper::new`.
        let (q, r) = first_column_in_words((a, b), i0, (dmaj, dmin), den).unwrap_or_else(|| {
            let (q, r) = floor_divmod(c() + wide(i0, step), den);
            (q as i32, r as i32)
        });
        FloorStepper::from_quotient(q, r, den as i32, step as i32)
    } else {
        FloorStepper::new(c() + wide(i0, step), den, step)
    };
    LinePixels {
        minor,
        major: i0 as i32,
        major_end: i1 as i32,
        swapped,
    }
}

/// `⌊N(i0) / den⌋` and its remainder for the line from `a` to `b` ((major, minor) sub-pixel
/// coordinates, `dmaj` and `dmin` their differences, `den` its denominator as `line_pixels`
/// folds the signs), in words, where `i0` is the first column of the endpoint the walk starts
/// by (a going forward, b backward: every line but those a clip cuts at their start); `None`
/// at another column.
///
/// `N(i0)` is `signed(p.1·dmaj + t·dmin)` for either endpoint p (both lie on the line) with
/// `t = S·i0 + HALF − p.0`. With p.1 = S·k + m it is k·den plus `signed(m·dmaj + t·dmin)`, and
/// for `0 ≤ t ≤ S` that second term lies within ±2·den (|dmin| ≤ |dmaj|): a word whose
/// quotient lies in [−2, 2), found by comparisons, without a 64-bit product or a library
/// division.
#[inline(always)]
fn first_column_in_words(
    (a, b): ((i64, i64), (i64, i64)),
    i0: i64,
    (dmaj, dmin): (i64, i64),
    den: i64,
) -> Option<(i32, i32)> {
    let (p, t) = if dmaj > 0 {
        (a, S * i0 + HALF - a.0)
    } else {
        (b, S * i0 + HALF - b.0)
    };
    if !(0..=S).contains(&t) {
        return None;
    }
    let (k, m) = (p.1 >> SUBPIXEL_BITS, p.1 & (S - 1));
    // Within ±2·den < 2³¹: no product or sum wraps.
    let n = (m as i32)
        .wrapping_mul(dmaj as i32)
        .wrapping_add((t as i32).wrapping_mul(dmin as i32));
    let n = if dmaj < 0 { n.wrapping_neg() } else { n };
    // ⌊n / den⌋ in [−2, 2), and the remainder.
    let den = den as i32;
    let (q, r) = if n >= den {
        (1, n.wrapping_sub(den))
    } else if n >= 0 {
        (0, n)
    } else if n >= den.wrapping_neg() {
        (-1, n.wrapping_add(den))
    } else {
        (-2, n.wrapping_add(den).wrapping_add(den))
    };
    Some(((k as i32).wrapping_add(q), r))
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::XorShift;

    /// R9: both set-ups of a line's first column (in words, as cores without a divide take it,
    /// and the general one) give the same pixels: lines of every length and direction, from
    /// inside and outside clip rectangles (started at their own first column or cut), out to
    /// the coordinate limit.
    #[test]
    fn r9_lines_set_up_in_words_equal_the_general_set_up() {
        let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
        let limit = crate::raster::COORD_LIMIT;
        let mut words = 0u32;
        for k in 0..200_000u32 {
            let mut coordinate = || match k % 4 {
                0 => rng.within(limit),
                1 => rng.within(1 << 12),
                _ => rng.within(30 * 16) + 30 * 16,
            };
            let (a, b) = (
                ScreenPoint::new(coordinate(), coordinate()),
                ScreenPoint::new(coordinate(), coordinate()),
            );
            let (x0, y0) = (rng.within(8), rng.within(8));
            let (w, h) = (1 + rng.within(80).abs(), 1 + rng.within(80).abs());
            let clip = PixelRect::new(x0, y0, x0 + w, y0 + h);
            let fast: std::vec::Vec<Point> = line_pixels_with::<true>(a, b, clip).collect();
            let general: std::vec::Vec<Point> = line_pixels_with::<false>(a, b, clip).collect();
            assert_eq!(fast, general, "{a:?} {b:?} {clip:?}");
            // Both ends inside: the line starts at its own first column, set up in words.
            let inside = |p: ScreenPoint| {
                let (x, y) = (p.x >> SUBPIXEL_BITS, p.y >> SUBPIXEL_BITS);
                (clip.x0..clip.x1).contains(&x) && (clip.y0..clip.y1).contains(&y)
            };
            words += u32::from(inside(a) && inside(b) && !fast.is_empty());
        }
        assert!(words > 10_000, "{words}");
    }
}

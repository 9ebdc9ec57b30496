//! Paints: the colour sources a target reads along a span.

use embedded_graphics::pixelcolor::Rgb888;
#[cfg(test)]
use embedded_graphics::pixelcolor::RgbColor;

use crate::math::{magnitude_bits, DivideBy};
use crate::raster::{Plane, ScreenPoint, Span};

/// A source of colours along a span, started at its first pixel.
pub trait Paint: core::fmt::Debug {
    /// The running colour along one span.
    type Cursor: Iterator<Item = Rgb888>;
    /// `Some` when the colour is the same at every pixel (spans can then be filled at once).
    fn solid(&self) -> Option<Rgb888>;
    /// The colours of `span`'s pixels, left to right.
    fn cursor(&self, span: Span) -> Self::Cursor;
}

/// One colour for the whole triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SolidPaint(pub Rgb888);

impl Paint for SolidPaint {
    type Cursor = core::iter::Repeat<Rgb888>;
    #[inline]
    fn solid(&self) -> Option<Rgb888> {
        Some(self.0)
    }
    #[inline]
    fn cursor(&self, _: Span) -> Self::Cursor {
        core::iter::repeat(self.0)
    }
}

/// Channel values carry this many fraction bits in the planes (values below 2⁴⁴).
const FRAC: u32 = 36;
/// Vertex colours arrive with this many fraction bits (0..=255 << 8).
pub(crate) const RGB_FRAC: u32 = 8;

/// Per channel, the smallest and largest of the three vertex values `channel(k)`.
fn channel_ranges(channel: impl Fn(usize) -> [i64; 3]) -> ([i64; 3], [i64; 3]) {
    let lo = [0, 1, 2].map(|k| channel(k).into_iter().min().unwrap_or(0));
    let hi = [0, 1, 2].map(|k| channel(k).into_iter().max().unwrap_or(0));
    (lo, hi)
}

/// Vertex colours interpolated across the triangle, each channel clamped to the range of its
/// vertex values (so every pixel is a convex combination, rule R8).
#[derive(Clone, Copy, Debug)]
pub struct SmoothPaint {
    /// Per channel, the plane at pixel (0, 0) and its changes from one pixel to the next
    /// along a row and down a column, modulo 2⁶⁴ as [`Plane::at`] is: a span's start is
    /// [`Plane::at`] itself, bit for bit.
    origin: [i64; 3],
    along: [i64; 3],
    down: [i64; 3],
    /// Per channel, the step a span takes ([`Plane::step_x`]).
    step: [i64; 3],
    range: ChannelRange,
}

impl SmoothPaint {
    /// From vertex colours (channels `0..=255 << RGB_FRAC`) at snapped screen positions.
    pub(crate) fn new(p: &[ScreenPoint; 3], rgb: [[i32; 3]; 3], area2: i64) -> Self {
        let [a, b, c] = rgb;
        let channels = [[a[0], b[0], c[0]], [a[1], b[1], c[1]], [a[2], b[2], c[2]]];
        let planes = Plane::scaled_each(p, channels, FRAC - RGB_FRAC, area2);
        // The range of each channel's vertex values, rounded as the pixels are.
        let round = |v: i32| round_channel((v as i64) << (FRAC - RGB_FRAC));
        let range = |k: usize| {
            let [a, b, c] = channels[k];
            (round(a.min(b).min(c)), round(a.max(b).max(c)))
        };
        let (r, g, b) = (range(0), range(1), range(2));
        SmoothPaint {
            origin: planes.map(|p| p.at(0, 0)),
            along: planes.map(|p| p.pixel_steps().0),
            down: planes.map(|p| p.pixel_steps().1),
            step: planes.map(|p| p.step_x()),
            range: ChannelRange {
                lo: [r.0, g.0, b.0],
                hi: [r.1, g.1, b.1],
            },
        }
    }
}

/// A value with [`FRAC`] fraction bits rounded to an 8-bit channel (ties up), clamped to
/// [0, 255], as each pixel's channel is (see [`SmoothCursor::next`]).
fn round_channel(v: i64) -> u8 {
    (v.saturating_add(1 << (FRAC - 1)) >> FRAC).clamp(0, 255) as u8
}

/// Per channel, the rounded smallest and largest vertex values: rounding is monotone, so
/// rounding a value clamped to the vertex range equals clamping the rounded value to the
/// rounded range.
#[derive(Clone, Copy, Debug)]
struct ChannelRange {
    lo: [u8; 3],
    hi: [u8; 3],
}

/// The running colour of a [`SmoothPaint`] along a span.
#[derive(Clone, Copy, Debug)]
pub struct SmoothCursor {
    acc: [i64; 3],
    step: [i64; 3],
    range: ChannelRange,
}

impl Iterator for SmoothCursor {
    type Item = Rgb888;
    /// Each channel is `(v + 2³⁵) >> 36` of its running value `v = H·2³² + L` (`0 ≤ L < 2³²`),
    /// which is `(H + 8) >> 4`: with `H + 8 = 16q + r`, `0 ≤ r < 16`, it is
    /// `q + ⌊(r·2³² + L) / 2³⁶⌋` and the second term is 0. The pipeline's values lie below 2⁴⁴
    /// (a pixel inside the triangle, its rounding drift far below one unit): `H + 8` cannot
    /// wrap.
    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        let ChannelRange { lo, hi } = self.range;
        let ch = |k: usize| {
            let rounded = ((self.acc[k] >> 32) as i32).wrapping_add(8) >> 4;
            // max then min: the range is never empty, and no test of it is made per pixel.
            rounded.max(lo[k] as i32).min(hi[k] as i32) as u8
        };
        let c = Rgb888::new(ch(0), ch(1), ch(2));
        let [a0, a1, a2] = self.acc;
        let [s0, s1, s2] = self.step;
        self.acc = [
            a0.wrapping_add(s0),
            a1.wrapping_add(s1),
            a2.wrapping_add(s2),
        ];
        Some(c)
    }
}

impl Paint for SmoothPaint {
    type Cursor = SmoothCursor;
    fn solid(&self) -> Option<Rgb888> {
        None
    }
    #[inline(always)]
    fn cursor(&self, span: Span) -> SmoothCursor {
        let (x, y) = (span.x0, span.y);
        let at = |k: usize| {
            self.origin[k]
                .wrapping_add(self.along[k].wrapping_mul(x as i64))
                .wrapping_add(self.down[k].wrapping_mul(y as i64))
        };
        SmoothCursor {
            acc: [at(0), at(1), at(2)],
            step: self.step,
            range: self.range,
        }
    }
}

/// Vertex colours interpolated perspective-correctly: each channel is `Σλᵢcᵢqᵢ / Σλᵢqᵢ` with
/// screen-space weights `λᵢ` and `qᵢ ∝ 1/wᵢ`, one division per channel and pixel, clamped to
/// the range of the vertex values like [`SmoothPaint`].
#[derive(Clone, Copy, Debug)]
pub struct PerspectivePaint {
    /// `cₖ·q` per channel, then `q`.
    planes: [Plane; 4],
    lo: [i64; 3],
    hi: [i64; 3],
}

/// Weights `q` are scaled so that the largest of a triangle's is this: numerators `c·q` with
/// `c < 2¹⁶` stay below 2⁴⁴, and the denominator plane (`q·2¹⁶`) too.
const Q_BITS: u32 = 28;

impl PerspectivePaint {
    /// From vertex colours (channels `0..=255 << RGB_FRAC`) and weights `q` proportional to
    /// `1/w` (positive; any common scale).
    pub(crate) fn new(p: &[ScreenPoint; 3], rgb: [[i32; 3]; 3], q: [i64; 3], area2: i64) -> Self {
        let shift = magnitude_bits(&q.map(|v| v.max(1))) as i32 - Q_BITS as i32;
        let q = q.map(|v| {
            let v = if shift > 0 {
                v >> shift
            } else {
                v << (-shift) as u32
            };
            v.max(1)
        });
        let channel = |k: usize| rgb.map(|c| c.get(k).copied().unwrap_or(0) as i64);
        let num = |k: usize| {
            let mut n = channel(k);
            for (c, q) in n.iter_mut().zip(q) {
                *c *= q;
            }
            n
        };
        let den = q.map(|v| v << 16);
        let planes = Plane::new_each(p, [num(0), num(1), num(2), den], area2);
        let (lo, hi) = channel_ranges(channel);
        PerspectivePaint { planes, lo, hi }
    }
}

/// The running colour of a [`PerspectivePaint`] along a span.
#[derive(Clone, Copy, Debug)]
pub struct PerspectiveCursor {
    acc: [i64; 4],
    step: [i64; 4],
    lo: [i64; 3],
    hi: [i64; 3],
}

impl Iterator for PerspectiveCursor {
    type Item = Rgb888;
    #[inline]
    fn next(&mut self) -> Option<Rgb888> {
        // One divisor for the three channels (one reciprocal on cores without a divide).
        let by_q = DivideBy::new(self.acc[3].max(1));
        let ch = |k: usize| {
            // c·q / (q·2¹⁶) · 2¹⁶ = c with RGB_FRAC fraction bits.
            let c = by_q.round(self.acc[k].max(0) << 16);
            let c = c.clamp(self.lo[k], self.hi[k]);
            ((c + (1 << (RGB_FRAC - 1))) >> RGB_FRAC).clamp(0, 255) as u8
        };
        let c = Rgb888::new(ch(0), ch(1), ch(2));
        let [a0, a1, a2, a3] = self.acc;
        let [s0, s1, s2, s3] = self.step;
        self.acc = [
            a0.wrapping_add(s0),
            a1.wrapping_add(s1),
            a2.wrapping_add(s2),
            a3.wrapping_add(s3),
        ];
        Some(c)
    }
}

impl Paint for PerspectivePaint {
    type Cursor = PerspectiveCursor;
    fn solid(&self) -> Option<Rgb888> {
        None
    }
    fn cursor(&self, span: Span) -> PerspectiveCursor {
        let (x, y) = (span.x0, span.y);
        PerspectiveCursor {
            acc: self.planes.map(|p| p.at(x, y)),
            step: self.planes.map(|p| p.step_x()),
            lo: self.lo,
            hi: self.hi,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// T36 and R8: a colour ramp along a 2048-pixel span stays within 1 LSB of the exact plane
    /// at every pixel and never leaves the range of the vertex colours.
    #[test]
    fn t36_long_span_ramp_has_no_drift() {
        for width in [64i32, 320, 1024, 2048] {
            let p = [
                ScreenPoint::new(0, 0),
                ScreenPoint::new(width * 16, 3),
                ScreenPoint::new(5, 40 * 16),
            ];
            let rgb = [
                [0, 128 << 8, 255 << 8],
                [255 << 8, 7 << 8, 0],
                [31 << 8, 255 << 8, 99 << 8],
            ];
            let area = {
                let [a, b, c] = p.map(|q| (q.x as i64, q.y as i64));
                (b.0 - a.0) * (c.1 - a.1) - (c.0 - a.0) * (b.1 - a.1)
            };
            let paint = SmoothPaint::new(&p, rgb, area);
            let y = 1;
            let mut cursor = paint.cursor(Span {
                y,
                x0: 0,
                x1: width,
            });
            for x in 0..width - 2 {
                let c = cursor.next().unwrap_or_default();
                // Exact barycentric plane at the pixel centre.
                let (px, py) = (x as f64 * 16.0 + 8.0, y as f64 * 16.0 + 8.0);
                let f = p.map(|q| (q.x as f64, q.y as f64));
                let det =
                    (f[1].0 - f[0].0) * (f[2].1 - f[0].1) - (f[2].0 - f[0].0) * (f[1].1 - f[0].1);
                let l1 =
                    ((px - f[0].0) * (f[2].1 - f[0].1) - (f[2].0 - f[0].0) * (py - f[0].1)) / det;
                let l2 =
                    ((f[1].0 - f[0].0) * (py - f[0].1) - (px - f[0].0) * (f[1].1 - f[0].1)) / det;
                for (k, got) in [c.r(), c.g(), c.b()].into_iter().enumerate() {
                    let v = rgb.map(|v| v[k] as f64 / 256.0);
                    let exact = v[0] + l1 * (v[1] - v[0]) + l2 * (v[2] - v[0]);
                    let lo = v.iter().cloned().fold(f64::INFINITY, f64::min);
                    let hi = v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
                    assert!(
                        (got as f64 - exact.clamp(lo, hi)).abs() <= 1.0,
                        "width {width} x {x}: {got} vs {exact}"
                    );
                    assert!(got as f64 >= lo.floor() && got as f64 <= hi.ceil());
                }
            }
        }
    }
}

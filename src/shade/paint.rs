//! Paints: the colour sources a target reads along a span.

use embedded_graphics::pixelcolor::Rgb888;
#[cfg(test)]
use embedded_graphics::pixelcolor::RgbColor;

use crate::math::{magnitude_bits, DivideBy};
use crate::raster::{AreaWalks, Plane, ScreenPoint, Span, WordPlane};

/// A source of colours along a span, started at its first pixel.
pub trait Paint: core::fmt::Debug {
    /// The running colour along one span (which may read the paint).
    type Cursor<'p>: Iterator<Item = Rgb888> + core::fmt::Debug
    where
        Self: 'p;
    /// True when the colours come in the target's channel depths
    /// ([`RasterTarget::CHANNELS`](crate::buffer::RasterTarget::CHANNELS)) rather than in 8
    /// bits.
    const SCALED: bool = false;
    /// True when [`solid`](Self::solid) always gives `Some` (a paint that has one colour).
    const SOLID: bool = false;
    /// `Some` when the colour is the same at every pixel (spans can then be filled at once).
    fn solid(&self) -> Option<Rgb888>;
    /// The colours of `span`'s pixels, left to right.
    fn cursor(&self, span: Span) -> Self::Cursor<'_>;
    /// Hands `user` the paint in the form whose cursor suits this triangle: itself, or for a
    /// paint with a faster form for some triangles (a texture's), that form. Chosen once per
    /// triangle, so that each form's span loop is compiled on its own.
    #[inline(always)]
    fn visit<U: PaintUser>(&self, user: U) -> U::Output
    where
        Self: Sized,
    {
        user.with(self)
    }
}

/// What a triangle's filler does with its paint, whichever form [`Paint::visit`] hands it.
pub trait PaintUser {
    /// What the use returns.
    type Output;
    /// Uses `paint`.
    fn with<P: Paint>(self, paint: &P) -> Self::Output;
}

/// One colour for the whole triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SolidPaint(pub Rgb888);

impl Paint for SolidPaint {
    type Cursor<'p> = core::iter::Repeat<Rgb888>;
    const SOLID: bool = true;
    #[inline]
    fn solid(&self) -> Option<Rgb888> {
        Some(self.0)
    }
    #[inline]
    fn cursor(&self, _: Span) -> Self::Cursor<'_> {
        core::iter::repeat(self.0)
    }
}

/// Vertex colours carry this many fraction bits in [`PerspectivePaint`]'s planes.
const RGB_FRAC: u32 = 8;

/// Per channel, the smallest and largest of the three vertex values `channel(k)`.
fn channel_ranges(channel: impl Fn(usize) -> [i64; 3]) -> ([i64; 3], [i64; 3]) {
    let lo = [0, 1, 2].map(|k| channel(k).into_iter().min().unwrap_or(0));
    let hi = [0, 1, 2].map(|k| channel(k).into_iter().max().unwrap_or(0));
    (lo, hi)
}

/// A channel value as a [`WordPlane`] takes it: in the channel's depth with 6 fraction bits
/// (below 2¹⁴), shifted by 16, which the walk doubles, so that a channel is its bits 23 to 30.
const CHANNEL_SHIFT: u32 = 16;
/// Half a channel step in the walk's unit: added once, truncation then rounds to nearest.
const HALF_CHANNEL: i32 = 1 << 22;

/// The 8-bit channel `c` (0..=255) in a channel whose largest value is `max`, with 6 fraction
/// bits: for `max` 255, `c` itself; otherwise `c · max / 255` truncated (by a product and a
/// shift: a division would be a library call on Cortex-M0) with its last bit set, within
/// 2⁻⁵ of a step of it, and odd, so never halfway between two steps (see [`SmoothPaint`]).
#[inline(always)]
fn in_depth(c: i32, max: u8) -> i32 {
    if max == 255 {
        return c << 6;
    }
    // max · 2²² / 255 rounded up: at most 2²², and times c below 2³¹.
    let scale = (max as i32 * (1 << 22) + 254) / 255;
    ((c * scale) >> 16) | 1
}

/// Vertex colours interpolated across the triangle in 32-bit words (each channel a plane walked
/// by steps rounded once, as depth is), each channel rounded to nearest in the target's own
/// channel depth (one rounding: an RGB565 target's channels are not rounded to 8 bits first).
///
/// The vertex channels lie on a grid of 2⁻⁶ of a step with no value halfway between two steps
/// (whole 8-bit channels, clipped vertices' rounded so, scaled to the depth), and a walk errs
/// from the exact plane by less than 2⁻¹¹ of a step, so a pixel's rounded channel lies between
/// the rounded smallest and largest vertex values: every pixel is a convex combination of the
/// vertex colours (rule R8) with no clamp in the pixel loop.
#[derive(Clone, Copy, Debug)]
pub struct SmoothPaint {
    channels: [WordPlane; 3],
}

impl SmoothPaint {
    /// From vertex colours (whole 8-bit channels, 0..=255) at snapped screen positions, in
    /// channels whose largest values are `depths` (red, green, blue).
    pub(crate) fn new(
        p: &[ScreenPoint; 3],
        rgb: [[i32; 3]; 3],
        area2: i64,
        depths: [u8; 3],
    ) -> Self {
        let by_area = AreaWalks::new(area2);
        let [a, b, c] = rgb;
        let [dr, dg, db] = depths;
        SmoothPaint {
            channels: [
                channel_walk(&by_area, p, [a[0], b[0], c[0]], dr),
                channel_walk(&by_area, p, [a[1], b[1], c[1]], dg),
                channel_walk(&by_area, p, [a[2], b[2], c[2]], db),
            ],
        }
    }
}

/// One channel's walk, its vertex values `c` in a channel whose largest value is `max`.
#[inline(always)]
fn channel_walk(by_area: &AreaWalks, p: &[ScreenPoint; 3], c: [i32; 3], max: u8) -> WordPlane {
    let v = [
        in_depth(c[0], max),
        in_depth(c[1], max),
        in_depth(c[2], max),
    ];
    by_area.walk_any(p, v, CHANNEL_SHIFT, HALF_CHANNEL)
}

/// The running colour of a [`SmoothPaint`] along a span.
#[derive(Clone, Copy, Debug)]
pub struct SmoothCursor {
    acc: [u32; 3],
    step: [u32; 3],
}

impl Iterator for SmoothCursor {
    type Item = Rgb888;
    /// Each channel is bits 23 to 30 of its walk's value, which lies in [0, 2³¹) (see
    /// [`SmoothPaint`]): at most the channel's largest value.
    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        let ch = |k: usize| (self.acc[k] >> 23) as u8;
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
    type Cursor<'p> = SmoothCursor;
    const SCALED: bool = true;
    fn solid(&self) -> Option<Rgb888> {
        None
    }
    #[inline(always)]
    fn cursor(&self, span: Span) -> SmoothCursor {
        let (x, y) = (span.x0, span.y);
        let [r, g, b] = self.channels;
        SmoothCursor {
            acc: [r.at(x, y) as u32, g.at(x, y) as u32, b.at(x, y) as u32],
            step: [r.sx as u32, g.sx as u32, b.sx as u32],
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
    /// From vertex colours (whole channels, 0..=255) and weights `q` proportional to `1/w`
    /// (positive; any common scale).
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
        let channel = |k: usize| rgb.map(|c| (c.get(k).copied().unwrap_or(0) as i64) << RGB_FRAC);
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
    type Cursor<'p> = PerspectiveCursor;
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

    /// The exact value at pixel `(x, y)` of the plane through `(p[i], v[i])`, as `num / den`
    /// with `den > 0`.
    fn exact(p: &[ScreenPoint; 3], v: [i32; 3], area: i64, (x, y): (i32, i32)) -> (i128, i128) {
        let (nx, ny) = Plane::numerators(p, v);
        let (nx, ny, den) = Plane::over_positive_area(nx, ny, area);
        let (dx, dy) = (16 * x + 8 - p[0].x, 16 * y + 8 - p[0].y);
        let den = den as i128;
        let num = v[0] as i128 * den + nx as i128 * dx as i128 + ny as i128 * dy as i128;
        (num, den)
    }

    /// Checks every pixel of `p`'s spans (at most `per_span` of each) against the exact planes
    /// of the vertex channels `rgb` (whole 8-bit values) in channels of `depths`: each channel
    /// is the exact value rounded to nearest (unless that lies within 2⁻¹⁰ of a rounding
    /// boundary) and always between the smallest and the largest vertex value rounded (R8).
    /// Returns the pixels checked.
    fn check_spans(p: [ScreenPoint; 3], rgb: [[i32; 3]; 3], depths: [u8; 3], per_span: i32) -> u64 {
        let area = crate::raster::doubled_area(p[0], p[1], p[2]);
        if area == 0 {
            return 0;
        }
        let paint = SmoothPaint::new(&p, rgb, area, depths);
        let clip = crate::raster::PixelRect::new(0, 0, 4096, 4096);
        let mut pixels = 0;
        for span in crate::raster::triangle_spans(p, clip) {
            let mut cursor = paint.cursor(span);
            for x in span.x0..span.x1.min(span.x0 + per_span) {
                let c = cursor.next().unwrap_or_default();
                for (k, got) in [c.r(), c.g(), c.b()].into_iter().enumerate() {
                    // The vertex values in the channel's depth, 6 fraction bits.
                    let v = rgb.map(|v| in_depth(v[k], depths[k]));
                    let (num, den) = exact(&p, v, area, (x, span.y));
                    let round = |v: i32| (v + 32) >> 6;
                    let lo = round(*v.iter().min().unwrap_or(&0));
                    let hi = round(*v.iter().max().unwrap_or(&0));
                    let at = (x, span.y);
                    assert!((lo..=hi).contains(&(got as i32)), "{p:?} {rgb:?} {at:?}");
                    assert!(got <= depths[k], "{p:?} {rgb:?} {at:?}");
                    // The value plus a half, over 64 den: its floor is the rounding.
                    let (top, bottom) = (num + 32 * den, 64 * den);
                    let fraction = top.rem_euclid(bottom);
                    let near_boundary =
                        fraction * 1024 < bottom || (bottom - fraction) * 1024 < bottom;
                    if !near_boundary {
                        let rounded = top.div_euclid(bottom);
                        assert_eq!(got as i128, rounded, "{p:?} {rgb:?} {at:?}");
                    }
                }
                pixels += 1;
            }
        }
        pixels
    }

    /// Scaled vertex values: `c · max / 255` within 2⁻⁵ of a step (6 fraction bits), none
    /// halfway between two steps, within the channel's range, 8-bit channels unchanged.
    #[test]
    fn channels_scale_to_their_depths() {
        for max in [1u8, 3, 31, 63, 255] {
            for c in 0..=255 {
                let v = in_depth(c, max);
                let exact = c as f64 * max as f64 / 255.0 * 64.0;
                assert!((v as f64 - exact).abs() < 2.0, "{c} {max}");
                assert!((v + 32) >> 6 <= max as i32, "{c} {max}");
                assert_ne!(v & 63, 32, "{c} {max}");
                if max == 255 {
                    assert_eq!(v, c * 64);
                }
            }
        }
    }

    /// T36 and R8: colour ramps along spans up to 2048 pixels long are the exact planes
    /// rounded, with no drift, and never leave the range of the vertex colours.
    #[test]
    fn t36_long_span_ramp_has_no_drift() {
        let rgb = [[0, 128, 255], [255, 7, 0], [31, 255, 99]];
        for width in [64i32, 320, 1024, 2048] {
            let p = [
                ScreenPoint::new(0, 0),
                ScreenPoint::new(width * 16, 3),
                ScreenPoint::new(5, 40 * 16),
            ];
            for depths in [[255; 3], [31, 63, 31]] {
                assert!(check_spans(p, rgb, depths, width) > width as u64);
            }
        }
    }

    /// R8: random triangles of every size within the pipeline's range (slivers included,
    /// whose steps do not fit 32 bits), random whole vertex colours: every pixel is the exact
    /// colour rounded, within the vertex colours' range.
    #[test]
    fn r8_smooth_paint_is_the_exact_plane_rounded() {
        let mut rng = crate::testing::XorShift(0x5851_F42D_4C95_7F2Du64);
        let (mut pixels, mut steep_drawn) = (0, 0);
        for k in 0..4_000 {
            let scale = rng.pick(&[8, 40, 400, 4000, crate::raster::PIPELINE_LIMIT / 2]);
            let centre = ScreenPoint::new(16 * 1000, 16 * 1000);
            let mut p = rng.triangle(centre, scale);
            if k % 4 == 0 {
                // A sliver: the third vertex a sub-pixel off the first two's line.
                let [a, b, _] = p;
                p[2] = ScreenPoint::new((a.x + b.x) / 2 + rng.within(2), (a.y + b.y) / 2);
            }
            let rgb = [(); 3].map(|_| [(); 3].map(|_| (rng.next_u64() % 256) as i32));
            let area = crate::raster::doubled_area(p[0], p[1], p[2]) as i128;
            let depths = rng.pick(&[[255; 3], [31, 63, 31], [63, 63, 63], [1, 3, 15]]);
            let covered = check_spans(p, rgb, depths, 48);
            // Steps of 2⁵·n / area in the walk's unit (2²² per channel step).
            let steep = (0..3).any(|k| {
                let (nx, ny) = Plane::numerators(&p, rgb.map(|c| c[k] << 22));
                let big = |n: i64| area != 0 && (32 * n as i128 / area).abs() > i32::MAX as i128;
                big(nx) || big(ny)
            });
            steep_drawn += u32::from(steep && covered > 0);
            pixels += covered;
        }
        assert!(
            pixels > 200_000 && steep_drawn > 20,
            "{pixels} {steep_drawn}"
        );
    }
}

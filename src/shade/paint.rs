//! Paints: the colour sources a target reads along a span.

use embedded_graphics::pixelcolor::Rgb888;
#[cfg(test)]
use embedded_graphics::pixelcolor::RgbColor;

use crate::math::{
    leading_zeros64, magnitude_bits, mul_short_u32, mul_wide_u32, reciprocal16, shr_low_word,
    NARROW_CORE,
};
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
/// screen-space weights `λᵢ` and `qᵢ ∝ 1/wᵢ`, rounded to nearest with 8 fraction bits,
/// clamped to the range of the vertex values like [`SmoothPaint`], and rounded to 8 bits: the
/// exact quotient at every pixel, by word products rather than 64-bit divisions.
#[derive(Clone, Copy, Debug)]
pub struct PerspectivePaint {
    /// `cₖ·q` per channel, then `q`.
    planes: [Plane; 4],
    lo: [u8; 3],
    hi: [u8; 3],
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
        // The vertex values are whole channels: their ends are whole too.
        let (lo, hi) = channel_ranges(channel);
        let whole = |v: [i64; 3]| v.map(|c| (c >> RGB_FRAC).clamp(0, 255) as u8);
        PerspectivePaint {
            planes,
            lo: whole(lo),
            hi: whole(hi),
        }
    }
}

/// The running colour of a [`PerspectivePaint`] along a span.
#[derive(Clone, Copy, Debug)]
pub struct PerspectiveCursor {
    acc: [i64; 4],
    step: [i64; 4],
    lo: [u8; 3],
    hi: [u8; 3],
}

/// The most bits of [`Estimate`]'s shortened divisor on cores with a divide instruction.
const SHORT_DIVISOR_BITS: u32 = 22;

/// The largest denominator [`perspective_channel`] takes (a triangle's lie below 2⁴⁵): its
/// products then stay inside 64 bits.
const MOST_DENOMINATOR: i64 = 1 << 47;

/// How [`perspective_channel`] estimates its quotient from words: the dividend shifted right
/// by `shift`, times `reciprocal`, shifted right by 32 (cores with a long multiply and a
/// divide instruction) or 23 (cores without: see [`Estimate::of`]).
#[derive(Clone, Copy, Debug)]
struct Estimate {
    shift: u32,
    reciprocal: u32,
    /// The form of cores without a long multiply and a divide instruction.
    narrow: bool,
}

impl Estimate {
    /// The estimate for the divisor `whole` (`2⁸ ≤ whole < 2⁵⁶`, `bits` long), in the form of
    /// cores without a long multiply and a divide instruction (`narrow`) or the other; both are
    /// tested on every host.
    ///
    /// With a long multiply and a divide instruction: `whole` shifted right by `shift`, which
    /// leaves it at most [`SHORT_DIVISOR_BITS`] bits (at least 2²¹ where it shifts at all),
    /// and `reciprocal = ⌊(2³² − 1) / (that + 1)⌋`; the dividend is shifted the same way. The
    /// divisor's relative error is below 2⁻²⁰ (or at most one unit where it is whole) and the
    /// dividend's floor costs below half a unit: the estimate is short by at most two.
    ///
    /// Without them, where a division is a library routine: the divisor's top 16 bits
    /// `D = ⌊whole / 2^s⌋ + 1` in (2¹⁵, 2¹⁶] (`s = bits − 16`, negative for a short `whole`,
    /// which is then shifted left) and `reciprocal = ⌊2³¹ / D⌋` below 2¹⁶, from a table and
    /// a Newton step; the dividend is shifted by `s + 8` (at least 1), and a dividend whose
    /// shifted value reaches 2¹⁶ has a quotient above 2⁸. The product of two values below
    /// 2¹⁶ fits a word, and shifted by 23 it is at most `b / whole`, short of it by less than
    /// two: `D` errs by at most 2⁻¹⁵ of itself, the reciprocal's floor by less than 2⁻¹⁵, each
    /// less than 2⁻⁷ of a quotient below 2⁸; the dividend's floor costs less than 2¹⁶ / 2²³,
    /// and the last floor less than one.
    #[inline(always)]
    fn of(whole: i64, bits: u32, narrow: bool) -> Estimate {
        if narrow {
            // The top 16 bits, in words where 64-bit shifts are routines.
            let top = if bits >= 16 {
                shr_low_word(whole, bits - 16) as u32
            } else {
                (whole as u32) << (16 - bits)
            };
            Estimate {
                shift: bits.wrapping_sub(8),
                reciprocal: reciprocal16(top.wrapping_add(1)),
                narrow,
            }
        } else {
            let shift = bits.saturating_sub(SHORT_DIVISOR_BITS);
            let short = ((whole >> shift) as u32).wrapping_add(1);
            Estimate {
                shift,
                reciprocal: u32::MAX / short,
                narrow,
            }
        }
    }

    /// The estimate of `⌊b / whole⌋` for `b ≥ 0`, at most it and short of it by at most two
    /// where it is below 2⁸; `None` where the quotient is at least 2⁸.
    #[inline(always)]
    fn quotient(&self, b: i64) -> Option<u32> {
        let q = if self.narrow {
            // `b >> shift` (shift at least 1) in words, where 64-bit shifts are routines.
            let (high, low) = ((b >> 32) as u32, b as u32);
            let t = if self.shift >= 32 {
                high >> (self.shift - 32)
            } else if high >> self.shift == 0 {
                (high << (32 - self.shift)) | (low >> self.shift)
            } else {
                return None;
            };
            if t >= 1 << 16 {
                return None;
            }
            t.wrapping_mul(self.reciprocal) >> 23
        } else {
            let t = u32::try_from(b >> self.shift).ok()?;
            (mul_wide_u32(t, self.reciprocal) >> 32) as u32
        };
        (q < 256).then_some(q)
    }
}

/// What [`perspective_channel`] takes of the denominator plane's value `d` at a pixel, for
/// every channel: `whole = 2⁸d` and `⌊d/2⌋ + 2⁷d` (`d` held to `1..=`[`MOST_DENOMINATOR`]),
/// and the estimate of quotients by `whole` in the `narrow` form or the other.
#[inline(always)]
fn divisor(d: i64, narrow: bool) -> ((i64, i64), Estimate) {
    let d = d.clamp(1, MOST_DENOMINATOR);
    let whole = d << RGB_FRAC;
    let half_and_bias = (d >> 1).wrapping_add(d << (RGB_FRAC - 1));
    let bits = 64 - leading_zeros64(whole as u64);
    ((whole, half_and_bias), Estimate::of(whole, bits, narrow))
}

/// One channel of a [`PerspectivePaint`] at a pixel where its planes are `n = c·q` and
/// `d = q·2¹⁶` (`1 ≤ d ≤ 2⁴⁷`): `c = round(n·2¹⁶ / d)` (ties away from zero, [`RGB_FRAC`]
/// fraction bits; 0 for a negative `n`) clamped to `lo..=hi` and then rounded to 8 bits.
///
/// That is `⌊b / 2⁸d⌋` for `b = n·2¹⁶ + ⌊d/2⌋ + 2⁷d`, clamped to the 8-bit `lo..=hi` (nested
/// floors of whole steps make one; rounding commutes with the clamp), a quotient that matters
/// only below 2⁸. It is estimated from words: at most the quotient, and where it is below 2⁸
/// short of it by at most two (each form's bound is argued at [`Estimate::of`]). The exact
/// remainder (below 2⁶³: `whole` is at most 2⁵⁵) then steps it up: at most two turns of the
/// loop.
#[inline(always)]
fn perspective_channel(
    n: i64,
    (whole, half_and_bias): (i64, i64),
    estimate: &Estimate,
    (lo, hi): (u8, u8),
) -> u8 {
    // Wraps only for numerators no triangle has (inside one, |n| < 2⁴⁵).
    let b = (n << 16).wrapping_add(half_and_bias);
    if b < 0 {
        return lo;
    }
    let Some(mut q) = estimate.quotient(b) else {
        return hi;
    };
    // q below 2⁸: its product with the low word is a short one.
    let (w_high, w_low) = ((whole >> 32) as u32, whole as u32);
    let times_q = (((q * w_high) as u64) << 32) + mul_short_u32(q as i32, w_low) as u64;
    let mut rest = b as u64 - times_q;
    while rest >= whole as u64 {
        rest -= whole as u64;
        q += 1;
    }
    // At most `hi`: below 2⁸.
    q.clamp(u32::from(lo), u32::from(hi)) as u8
}

impl Iterator for PerspectiveCursor {
    type Item = Rgb888;
    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        // Shared by the channels: the divisor, exact and shortened to a word.
        let (divisor, estimate) = divisor(self.acc[3], NARROW_CORE);
        let [a0, a1, a2, a3] = self.acc;
        let ([l0, l1, l2], [h0, h1, h2]) = (self.lo, self.hi);
        // Written out: a closure over the channels stays a call at opt-level "s".
        let c = Rgb888::new(
            perspective_channel(a0, divisor, &estimate, (l0, h0)),
            perspective_channel(a1, divisor, &estimate, (l1, h1)),
            perspective_channel(a2, divisor, &estimate, (l2, h2)),
        );
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

    /// [`perspective_channel`] by its definition: the rounded quotient by a 64-bit division,
    /// clamped, then rounded to 8 bits.
    fn channel_by_division(n: i64, d: i64, (lo, hi): (u8, u8)) -> u8 {
        let c = crate::math::div_round(n.max(0) << 16, d.max(1));
        let c = c.clamp(i64::from(lo) << RGB_FRAC, i64::from(hi) << RGB_FRAC);
        ((c + (1 << (RGB_FRAC - 1))) >> RGB_FRAC).clamp(0, 255) as u8
    }

    /// The cursor's channel is the definition's for every divisor magnitude, at quotients
    /// around every 8-bit rounding boundary, below zero and far above 255, and at random.
    #[test]
    fn perspective_channels_are_the_rounded_quotients() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15);
        let cursor_channel = |n: i64, d: i64, range: (u8, u8)| {
            let mut cursor = PerspectiveCursor {
                acc: [n, n, n, d],
                step: [0; 4],
                lo: [range.0; 3],
                hi: [range.1; 3],
            };
            let c = cursor.next().map(|c| [c.r(), c.g(), c.b()]);
            assert_eq!(
                c,
                Some([channel_by_division(n, d, range); 3]),
                "{n} {d} {range:?}"
            );
        };
        let mut checked = 0;
        for bits in 0..46u32 {
            for _ in 0..2_000 {
                let x = rng.next_u64();
                // A divisor of `bits` bits, a quotient near a boundary v·2⁸ ± 2⁷ (or anywhere
                // from below 0 to past 2¹⁷), and a numerator giving it (±1 unit around).
                let d = ((x >> 20) & ((1 << bits) - 1) | 1 << bits) as i64;
                let v = match x % 4 {
                    0 => ((x >> 8) % 300) as i64 * 256 + 128,
                    1 => ((x >> 8) % 300) as i64 * 256 - 128,
                    _ => ((x >> 8) % (1 << 18)) as i64 - (1 << 16),
                };
                let n = ((i128::from(v) * i128::from(d)) >> 16) as i64;
                let (a, b) = ((x >> 40) as u8, (x >> 48) as u8);
                let range = (a.min(b), a.max(b));
                for n in [n - 1, n, n + 1] {
                    cursor_channel(n, d, range);
                    cursor_channel(n, d, (0, 255));
                    checked += 2;
                }
            }
        }
        assert_eq!(checked, 46 * 2_000 * 6);
        // Planes no triangle has: any value, no panic, an answer within the range.
        for _ in 0..100_000 {
            let [n, d] = [
                rng.next_u64() as i64,
                rng.next_u64() as i64 >> (rng.next_u64() % 64),
            ];
            let mut cursor = PerspectiveCursor {
                acc: [n, n >> 20, -n, d],
                step: [d, n, 1, n],
                lo: [10; 3],
                hi: [20; 3],
            };
            for _ in 0..2 {
                let c = cursor.next().map(|c| [c.r(), c.g(), c.b()]);
                assert!(c.is_some_and(|c| c.iter().all(|v| (10..=20).contains(v))));
            }
        }
        for d in [1, 2, 3, 255, 256, 257, (1 << 46) - 1, MOST_DENOMINATOR] {
            for n in [-1, 0, 1, 127, 128, 129, 1 << 20, 1 << 40, (1 << 46) - 1] {
                cursor_channel(n, d, (0, 255));
                cursor_channel(n, d, (3, 200));
            }
        }
    }

    /// Both forms of the estimate, whichever the core running the test takes, at every
    /// divisor size and around every quotient below 2⁸ and past it: never above the quotient,
    /// short of it by at most two below 2⁸ (what the correction loop's bound rests on), `None`
    /// only at 2⁸ and above; and the channel is the definition's.
    #[test]
    fn both_estimates_stay_within_two_below_the_quotient() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1D);
        let mut checked = 0;
        for narrow in [false, true] {
            // Divisors below 2⁴⁷ (`divisor` holds larger ones to it).
            for bits in 0..47u32 {
                for _ in 0..3_000 {
                    let x = rng.next_u64();
                    let d = ((x >> 16) & ((1 << bits) - 1) | 1 << bits) as i64;
                    let ((whole, half_and_bias), estimate) = divisor(d, narrow);
                    // A dividend around every quotient up to past 2⁸, and anywhere beyond.
                    let q = if x.is_multiple_of(3) {
                        (x >> 8) % (1 << 20)
                    } else {
                        (x >> 8) % 260
                    };
                    let b0 = i128::from(whole) * i128::from(q as i64);
                    for b in [b0 - 1, b0, b0 + 1, b0 + i128::from(whole) / 2] {
                        let Ok(b) = i64::try_from(b) else { continue };
                        if b < 0 {
                            continue;
                        }
                        let exact = b / whole;
                        match estimate.quotient(b) {
                            Some(e) => assert!(
                                i64::from(e) <= exact && exact <= i64::from(e) + 2,
                                "{narrow} {d} {b}: {e} for {exact}"
                            ),
                            None => assert!(exact >= 256, "{narrow} {d} {b}: None for {exact}"),
                        }
                        let n = (b - half_and_bias) >> 16;
                        let range = ((x >> 40) as u8 % 128, 128 + (x >> 48) as u8 % 128);
                        assert_eq!(
                            perspective_channel(n, (whole, half_and_bias), &estimate, range),
                            channel_by_division(n, d, range),
                            "{narrow} {n} {d}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert!(checked > 2 * 47 * 3_000 * 3, "{checked}");
    }

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

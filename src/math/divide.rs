//! Divisions. [`div_round`] rounds to nearest on every core; where 64-bit division is a long
//! library routine (32-bit cores) it runs as 32-bit divisions of digits (14 bits for short
//! divisors, 16 otherwise). On Armv6-M every division is a library routine of a hundred and more
//! instructions, and the pipeline often divides several numerators by the same number: a vertex's
//! x, y and depth by its `w`, a triangle's two depth gradients by its doubled area. [`DivideBy`]
//! then pays for one reciprocal of the divisor and divides with a widening multiply and a few
//! corrections (Möller and Granlund, "Improved division by invariant integers", IEEE Trans.
//! Computers 60(2), 2011: the reciprocal `v = ⌊(2⁶⁴ − 1)/d⌋ − 2³²` of the normalised divisor `d`,
//! and their two-by-one division, algorithm 4). A vertex's short quotients take
//! [`ShortQuotients`] there instead: a 16-bit reciprocal and 15-bit digits in 32-bit words.
//! Every path returns the same quotients, which the tests check against 128-bit arithmetic.

use core::num::NonZeroU32;

use super::scalar::{leading_zeros32, mul_wide, mul_wide_u32, shl_words, NARROW_CORE};

/// `n / d` rounded to nearest with ties away from zero; `d` must be positive (a non-positive
/// `d` returns 0). Never overflows.
pub(crate) const fn div_round(n: i64, d: i64) -> i64 {
    if d <= 0 {
        return 0;
    }
    let half = d / 2;
    // Where 64-bit division is a long library routine (32-bit cores), the same quotient by a
    // 32-bit division when the operands fit (most divisions of the pipeline), else by a few
    // when the divisor fits 32 bits (the depth divisions: see `div_round_u64_u32`).
    if cfg!(target_pointer_width = "32") {
        if let Some(q) = div_round_u32(n, d) {
            return q;
        }
        if let Some(q) = div_round_u64_u32(n, d) {
            return q;
        }
    }
    if n >= 0 {
        n.saturating_add(half) / d
    } else {
        -(n.saturating_neg().saturating_add(half) / d)
    }
}

/// `floor(n / d)` for `d > 0` and a quotient below 2³² (`n < d · 2³²`), by two 32-bit
/// divisions of 16-bit digits (Knuth's algorithm D, as in Hacker's Delight's `divlu`): on
/// 32-bit cores a 64-bit division is a library routine of a few hundred instructions; this
/// takes a few dozen with a hardware 32-bit divide (Cortex-M3/M4), and on Cortex-M0 two
/// library 32-bit divisions still cost less than the 64-bit one.
pub(crate) const fn div_u64_u32(n: u64, d: u32) -> u32 {
    // Normalise: the divisor's top bit set. n · 2^s < d · 2^s · 2³² ≤ 2⁶⁴: nothing is lost.
    let s = leading_zeros32(d);
    let (hi, lo) = shl_words(n, s);
    div_normalized(hi, lo, d << s)
}

/// `⌊(hi · 2³² + lo) / v⌋` for a normalised `v` (top bit set) and `hi < v`: two 16-bit digits.
/// Where a division is a library routine, each digit's first estimate comes from one
/// reciprocal of the divisor's top half instead (see [`by_reciprocal`]).
#[inline(always)]
const fn div_normalized(hi: u32, lo: u32, v: u32) -> u32 {
    const B: u32 = 1 << 16;
    let (vn1, vn0) = (v >> 16, v & 0xFFFF);
    let (un1, un0) = (lo >> 16, lo & 0xFFFF);
    // vn1 is in [2¹⁵, 2¹⁶): vn1 + 1 in reciprocal16's range.
    let r = if NARROW_CORE {
        reciprocal16(vn1 + 1)
    } else {
        0
    };
    let q1 = quotient_digit(hi, un1, (vn1, vn0), r);
    let un21 = hi
        .wrapping_mul(B)
        .wrapping_add(un1)
        .wrapping_sub(q1.wrapping_mul(v));
    let q0 = quotient_digit(un21, un0, (vn1, vn0), r);
    q1 * B + q0
}

/// `(⌊top / vn1⌋, top mod vn1)` for `2¹⁵ ≤ vn1 < 2¹⁶`, from `r = ⌊2³¹ / (vn1 + 1)⌋` (tested on
/// every host): `top · r / 2³¹` in two word products of `top`'s halves is at most the
/// quotient and short of it by less than eight (`r` lies below `2³¹ / vn1` by less than
/// `2³¹ / vn1²` plus one, which costs less than six units for a `top` below 2³², and the
/// floors less than two), which steps of the remainder make up. Every product fits a word.
// Out of line: both digits call it, and in line it measured little faster for more flash.
#[inline(never)]
const fn by_reciprocal(top: u32, vn1: u32, r: u32) -> (u32, u32) {
    let mut q = reciprocal_estimate(top, r);
    let mut rest = top - q * vn1;
    while rest >= vn1 {
        q += 1;
        rest -= vn1;
    }
    (q, rest)
}

/// `⌊top · r / 2³¹⌋` less at most one, in two word products of `top`'s halves: `th · r` is at
/// most `(2¹⁶ − 1)²` and the low product's top half below 2¹⁶, so their sum fits.
#[inline(always)]
const fn reciprocal_estimate(top: u32, r: u32) -> u32 {
    let (th, tl) = (top >> 16, top & 0xFFFF);
    (th * r + ((tl * r) >> 16)) >> 15
}

/// One 16-bit digit of `(top · 2¹⁶ + next) / v`, `v = vn1 · 2¹⁶ + vn0` normalised (top bit
/// set), `top < v`: estimated from the top 32 bits by the divisor's top 16 (by a division, or
/// from `r` where a division is a library routine: see [`by_reciprocal`]), then corrected (at
/// most twice). Every product and sum stays within 32 bits.
#[inline(always)]
const fn quotient_digit(top: u32, next: u32, (vn1, vn0): (u32, u32), r: u32) -> u32 {
    const B: u32 = 1 << 16;
    let (mut q, mut rhat) = if NARROW_CORE {
        by_reciprocal(top, vn1, r)
    } else {
        (top / vn1, top % vn1)
    };
    while q >= B || q * vn0 > B * rhat + next {
        q -= 1;
        rhat += vn1;
        if rhat >= B {
            break;
        }
    }
    q
}

/// `|n| + ⌊d/2⌋`, the magnitude [`div_round`] divides, saturated at `i64::MAX` as its 64-bit
/// path saturates it (so every path returns the same quotient).
#[inline(always)]
const fn rounded_magnitude(n: i64, d: u32) -> u64 {
    // At most 2⁶³ + 2³¹: no overflow.
    let a = n.unsigned_abs() + (d / 2) as u64;
    if a > i64::MAX as u64 {
        i64::MAX as u64
    } else {
        a
    }
}

/// `q` with the sign of `n` (`q ≤ i64::MAX`).
#[inline(always)]
const fn with_sign_of(n: i64, q: u64) -> i64 {
    if n >= 0 {
        q as i64
    } else {
        -(q as i64)
    }
}

/// [`div_round`] for `d` that fits 32 bits, by [`div_by_word`].
const fn div_round_u64_u32(n: i64, d: i64) -> Option<i64> {
    if d <= 0 || d > u32::MAX as i64 {
        return None;
    }
    let d = d as u32;
    let q = div_by_word(rounded_magnitude(n, d), d);
    Some(with_sign_of(n, q))
}

/// `⌊a / d⌋` for `d > 0` by [`div_u64_u32`]: once for a quotient below 2³², once more for its
/// high word.
const fn div_by_word(a: u64, d: u32) -> u64 {
    let hi = (a >> 32) as u32;
    if hi < d {
        div_u64_u32(a, d) as u64
    } else {
        let (qh, rh) = (hi / d, hi % d);
        ((qh as u64) << 32) | div_u64_u32(((rh as u64) << 32) | (a & 0xFFFF_FFFF), d) as u64
    }
}

/// `⌊n / d⌋` (0 for `d = 0`): by 32-bit digits ([`div_by_word`]) where `d` fits 32 bits (on
/// 32-bit cores a 64-bit division is a long library routine).
pub(crate) const fn div_floor(n: u64, d: u64) -> u64 {
    if d == 0 {
        return 0;
    }
    if d <= u32::MAX as u64 {
        return div_by_word(n, d as u32);
    }
    n / d
}

/// Divisors below `2^SHIFTED_DIVISOR_BITS` take [`shifted_by_short`]: a remainder shifted by
/// up to [`MAX_SHIFT`] bits, plus half the divisor, still fits a 32-bit word.
const SHIFTED_DIVISOR_BITS: u32 = 17;
/// The largest shift [`shifted_by_short`] takes in one step of its remainder.
const MAX_SHIFT: u32 = 14;

/// `⌊(m · 2^s + ⌊d/2⌋) / d⌋` for `0 < d < 2¹⁷` and `s ≤ 28`, by 32-bit divisions: with `m =
/// q·d + r`, it is `q · 2^s + ⌊(r · 2^s + ⌊d/2⌋) / d⌋`, and for `s ≤ 14`, `r · 2^s + ⌊d/2⌋` lies
/// below `2¹⁷ · 2¹⁴ + 2¹⁶`, a 32-bit word; a longer shift takes the remainder on in two steps
/// (`r · 2¹⁴ = q₂·d + r₂`, then `r₂` shifted by the rest). This is the magnitude [`div_round`]
/// rounds for a numerator `±m · 2^s`: the steps of a small triangle's word walks (see
/// [`DivideBy::round_shifted_i32`]), its depth and texture coordinates (numerators shifted by
/// 5 and 8) in two divides, its colour channels (shifted by 21) in three.
#[inline(always)]
const fn shifted_by_short(m: u32, s: u32, d: u32) -> u64 {
    let (q, r) = (m / d, m % d);
    if s <= MAX_SHIFT {
        return ((q as u64) << s) + ((r << s) + d / 2) as u64 / d as u64;
    }
    let rest = s - MAX_SHIFT;
    let t = r << MAX_SHIFT;
    let (q2, r2) = (t / d, t % d);
    ((q as u64) << s) + ((q2 as u64) << rest) + ((r2 << rest) + d / 2) as u64 / d as u64
}

/// [`div_round`]`(n · 2^s, d)` as a word, for `0 < d < 2¹⁷` and `s ≤ 28`: [`shifted_by_short`]
/// of `|n|` where it is below 2³² and its first quotient below 2^(30 − s), so that the
/// magnitude, at most `(q + 1)·2^s ≤ 2³⁰` (the rest is at most 2^s), takes its sign in a word;
/// `None` otherwise.
#[inline(always)]
fn shifted_i32_in_words(n: i64, s: u32, d: u32) -> Option<i32> {
    let m = u32::try_from(n.unsigned_abs()).ok()?;
    if m / d >= 1 << (30 - s) {
        return None;
    }
    let magnitude = shifted_by_short(m, s, d) as i32;
    Some(if n < 0 { -magnitude } else { magnitude })
}

/// `round(n · 2³⁰ / d)` for `d < 2¹⁹` and `0 ≤ n ≤ d`, which the caller knows (a vertex's
/// depth `z / w` in Q1.30; any other operands give a meaningless quotient, without overflow),
/// by three 32-bit divisions.
#[inline(always)]
pub(crate) const fn fraction_in_words(n: u32, d: NonZeroU32) -> i64 {
    let d = d.get();
    // `div_round(n << 30, d)` without its sign and saturation, which n ≥ 0 and the bound need
    // not, in three 32-bit divides: the numerator's low 30 bits are zero. With
    // n·2¹³ = q₁·d + r₁ and r₁·2¹³ = q₂·d + r₂, n·2³⁰ + ⌊d/2⌋ = d·(q₁·2¹⁷ + q₂·2⁴) + r₂·2⁴ + ⌊d/2⌋,
    // whose last part divides to at most 16. n ≤ d < 2¹⁹: every shifted value below fits a
    // word, and the sum is at most 2³⁰ (the sums wrap, without meaning, only for an n beyond d).
    let t = n << 13;
    let (q1, r1) = (t / d, t % d);
    let t = r1 << 13;
    let (q2, r2) = (t / d, t % d);
    let q3 = ((r2 << 4) + d / 2) / d;
    (q1 << 17).wrapping_add(q2 << 4).wrapping_add(q3) as i64
}

/// [`div_round`] by a 32-bit division, when `|n| + d/2` and `d > 0` fit 32 bits.
const fn div_round_u32(n: i64, d: i64) -> Option<i64> {
    if d <= 0 || d > u32::MAX as i64 {
        return None;
    }
    let a = rounded_magnitude(n, d as u32);
    if a > u32::MAX as u64 {
        return None;
    }
    Some(with_sign_of(n, (a as u32 / d as u32) as u64))
}

/// [`div_round`] of 32-bit operands in 32-bit words, exactly, for a divisor below 2³¹ known not
/// to be zero (no test of it): the one quotient beyond i32, 2³¹ (of `i32::MIN / 1`), is
/// negated after wrapping to the true `−2³¹`.
#[inline(always)]
pub(crate) const fn div_round_word(n: i32, d: NonZeroU32) -> i32 {
    let d = d.get();
    // |n| ≤ 2³¹ and d/2 < 2³⁰: the sum fits u32.
    let q = ((n.unsigned_abs() + d / 2) / d) as i32;
    if n < 0 {
        q.wrapping_neg()
    } else {
        q
    }
}

/// Rounded divisions by one divisor `d`: [`div_round`]`(n, d)` for every `n`, through a
/// [`Divisor`] where division is a library routine, by the divide instruction elsewhere.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DivideBy {
    d: i64,
    /// `d` where it is a positive i32 and the core divides words in one instruction, else 0:
    /// checked once for [`round_shifted_i32`](Self::round_shifted_i32)'s divisions.
    d32: i32,
    by: Option<Divisor>,
}

impl DivideBy {
    /// Divisions by `d` (any value: [`div_round`] returns 0 for `d ≤ 0`).
    #[inline(always)]
    pub(crate) fn new(d: i64) -> DivideBy {
        let by = if NARROW_CORE { Divisor::new(d) } else { None };
        let d32 = match i32::try_from(d) {
            Ok(d32) if d32 > 0 && !NARROW_CORE && cfg!(target_pointer_width = "32") => d32,
            _ => 0,
        };
        DivideBy { d, d32, by }
    }

    /// [`new`](Self::new) of a `d` the caller knows to be positive (a vertex's `w` inside the
    /// near plane, within 31 bits), without `new`'s tests of it, and with neither a
    /// [`Divisor`] nor a word copy: its divisions take [`div_round`] on every core (the vertex
    /// stage of cores without a divide instruction divides by `ShortQuotients` instead).
    #[inline(always)]
    pub(crate) fn new_positive32(d: i32) -> DivideBy {
        DivideBy {
            d: d as i64,
            d32: 0,
            by: None,
        }
    }

    /// [`round`](Self::round)`(n · 2³⁰)` for `0 ≤ n ≤ d`, which the caller knows (a vertex's
    /// depth `z / w` in Q1.30, inside the near and far planes).
    #[inline(always)]
    pub(crate) fn round_fraction(&self, n: i64) -> i64 {
        self.round(n << 30)
    }

    /// [`round`](Self::round)`(n << shift)` (for `shift ≤ 28`, and `n << shift` within i64)
    /// where it fits an i32, else `None`; by [`shifted_i32_in_words`] where it applies (the
    /// depth and colour gradients of a divisor with a word copy, which 32-bit cores with a
    /// divide instruction keep).
    #[inline(always)]
    pub(crate) fn round_shifted_i32(&self, n: i64, shift: u32) -> Option<i32> {
        if self.d32 > 0 && self.d32 < 1 << SHIFTED_DIVISOR_BITS && shift <= 2 * MAX_SHIFT {
            if let Some(q) = shifted_i32_in_words(n, shift, self.d32 as u32) {
                return Some(q);
            }
        }
        i32::try_from(self.round(n << shift)).ok()
    }

    /// [`div_round`]`(n, d)`.
    #[inline(always)]
    pub(crate) fn round(&self, n: i64) -> i64 {
        match self.by {
            Some(by) => by.div_round(n),
            None => div_round(n, self.d),
        }
    }
}

/// A positive divisor below 2³², prepared for [`Divisor::div_round`].
#[derive(Clone, Copy, Debug)]
struct Divisor {
    /// The divisor.
    d: u32,
    /// `d` shifted left until its top bit is set, and by how much.
    norm: u32,
    shift: u32,
    /// `⌊(2⁶⁴ − 1) / norm⌋ − 2³²`.
    v: u32,
}

impl Divisor {
    /// Prepares `d`; `None` unless `0 < d < 2³²`.
    fn new(d: i64) -> Option<Divisor> {
        let d = u32::try_from(d).ok().filter(|d| *d > 0)?;
        let shift = leading_zeros32(d);
        let norm = d << shift;
        let v = reciprocal(norm);
        Some(Divisor { d, norm, shift, v })
    }

    /// `(⌊n / d⌋, n mod d)` for `n < d · 2³²` (the quotient fits 32 bits).
    #[inline]
    fn div_rem(&self, n: u64) -> (u32, u32) {
        // n · 2^shift < norm · 2³² ≤ 2⁶⁴: the high word stays below norm.
        let (u1, u0) = shl_words(n, self.shift);
        // Algorithm 4: the quotient estimate from the reciprocal, off by at most one or two.
        let p = mul_wide_u32(self.v, u1).wrapping_add((u1 as u64) << 32 | u0 as u64);
        let (mut q, q0) = (((p >> 32) as u32).wrapping_add(1), p as u32);
        let mut r = u0.wrapping_sub(q.wrapping_mul(self.norm));
        if r > q0 {
            q = q.wrapping_sub(1);
            r = r.wrapping_add(self.norm);
        }
        if r >= self.norm {
            q = q.wrapping_add(1);
            r = r.wrapping_sub(self.norm);
        }
        (q, r >> self.shift)
    }

    /// [`div_round`]`(n, d)`: `n / d` rounded to nearest, ties away from zero.
    fn div_round(&self, n: i64) -> i64 {
        let a = rounded_magnitude(n, self.d);
        let hi = (a >> 32) as u32;
        let q = if hi < self.d {
            self.div_rem(a).0 as u64
        } else {
            // A quotient of more than 32 bits: its high word first, then the rest.
            let (qh, rh) = self.div_rem(hi as u64);
            ((qh as u64) << 32) | self.div_rem(((rh as u64) << 32) | (a & 0xFFFF_FFFF)).0 as u64
        };
        with_sign_of(n, q)
    }
}

/// Rounded divisions by a divisor `0 < d < 2²⁹` whose quotients are short, in 32-bit words
/// and without a division, for cores that lack a divide instruction (Cortex-M0): a vertex's
/// screen offsets and depth by its `w`, and a triangle's depth gradients by its doubled area.
/// [`DivideBy`] there pays for a reciprocal to 32 bits and 64-bit products; these quotients
/// need less.
///
/// With `b` the position of d's top bit and `t` d's top 16 bits (`d = t·2^(b−15) + less`),
/// `r = ⌊2³¹ / (t + 1)⌋` is below `2^(b+16) / d` and within `2⁻¹⁴` of it. A numerator `N`
/// whose bits from `b` up form `m < 2¹⁶` has the estimate `⌊m·r / 2¹⁶⌋` (one 32-bit product),
/// which is at most `N / d` and at most 5 below its floor: with `N = m·2^b + f` (`f < 2^b`),
/// `N / d < (m + 1)·2¹⁵ / t` and `m·r / 2¹⁶ > m·2¹⁵ / (t + 1) − m / 2¹⁶`, so the floor lies
/// above the estimate by less than `m·2¹⁵ / (t·(t + 1)) + 2¹⁵ / t + m / 2¹⁶ + 1`. For a
/// quotient `q ≤ 2¹⁵`, as every caller's is (`m < (q + 1)·(t + 1) / 2¹⁵`), that is below
/// `(2¹⁶ + 1) / t + (2¹⁵ + 1)·(t + 1) / 2³¹ + 1`, which over `t` in `[2¹⁵, 2¹⁶)` is largest
/// at `t = 2¹⁵`, a little over 3.5: the estimate is at most 3 below. The remainder `N − q·d`
/// is then below `4d < 2³²`: the difference of the low words, exact in one word, and up to
/// three subtractions finish the quotient (a numerator with a quotient beyond 2¹⁵, whose
/// estimate may lie further below, gets a meaningless digit). Each method states the bound
/// its numerators must meet: the vertex's are known to meet theirs and are not tested
/// (another numerator gives a meaningless quotient, but nothing overflows);
/// [`round_below_2_30`](Self::round_below_2_30) tests its own and declines a longer quotient.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShortQuotients {
    d: u32,
    /// `b`: a numerator's estimate takes its bits from here up.
    below: u32,
    /// `v · 2¹⁵ / 2^b` is `(v << up) >> down` (one of them 0).
    up: u32,
    down: u32,
    /// `⌊2³¹ / (t + 1)⌋`, in `[2¹⁵, 2¹⁶)`.
    r: u32,
}

impl ShortQuotients {
    /// Prepares `d`; `None` unless `0 < d < 2²⁹`. In line: the vertex stage prepares one a
    /// vertex and the depth walk one a triangle.
    #[inline(always)]
    pub(crate) fn new(d: i64) -> Option<ShortQuotients> {
        Self::new32(u32::try_from(d).ok()?)
    }

    /// [`new`](Self::new) of a word, one unsigned test of its range.
    #[inline(always)]
    pub(crate) fn new32(d: u32) -> Option<ShortQuotients> {
        if d.wrapping_sub(1) >= (1 << 29) - 1 {
            return None;
        }
        let below = 31 - leading_zeros32(d);
        let (up, down) = if below >= 15 {
            (0, below - 15)
        } else {
            (15 - below, 0)
        };
        let mut q = ShortQuotients {
            d,
            below,
            up,
            down,
            r: 0,
        };
        // d's top 16 bits, in [2¹⁵, 2¹⁶).
        q.r = reciprocal16(q.top(d) + 1);
        Some(q)
    }

    /// `⌊v · 2¹⁵ / 2^b⌋`: the estimate's bits of `v · 2¹⁵` (below 2¹⁶ for `v < 2d`).
    #[inline(always)]
    fn top(&self, v: u32) -> u32 {
        (v << self.up) >> self.down
    }

    /// `(⌊N / d⌋, N mod d)` from N's bits from `b` up (`m`) and its low word, for `m < 2¹⁶`
    /// and a quotient of at most 2¹⁵, which every caller's numerator meets (the bound is
    /// written where it calls): then the estimate is at most three below (see the type's
    /// documentation), and three steps correct it. The steps are written out (a loop
    /// measured slower), `m` is not tested, and there is no fallback to the exact division
    /// (for an estimate the steps would leave short, which no caller's is): another numerator
    /// gives a meaningless digit, but nothing overflows.
    #[inline(always)]
    fn digit(&self, m: u32, low: u32) -> (u32, u32) {
        let d = self.d;
        let mut q = m.wrapping_mul(self.r) >> 16;
        let mut rem = low.wrapping_sub(q.wrapping_mul(d));
        let mut step = || {
            if rem < d {
                return Some((q, rem));
            }
            q = q.wrapping_add(1);
            rem = rem.wrapping_sub(d);
            None
        };
        let found = step().or_else(&mut step).or_else(&mut step);
        found.unwrap_or((q, rem))
    }

    /// [`div_round`]`(n, d)` for `|n| < 2¹⁴·d`, which the caller knows (a vertex's screen
    /// offset inside the guard band), in words: `a = |n| + d/2` lies below `2¹⁵·d`, so its high
    /// word is below `2^b` and needs no test, its bits from `b` up, a digit's `m`, are below
    /// 2¹⁵, and the quotient, below 2¹⁵, takes its sign in a word. In line (out of line measured
    /// slower). Outside that range the quotient means nothing, but
    /// nothing overflows.
    #[inline(always)]
    pub(crate) fn round(&self, n: i64) -> i32 {
        let a = n.unsigned_abs() + (self.d / 2) as u64;
        let (hi, lo) = ((a >> 32) as u32, a as u32);
        let m = (hi << 1 << (31 - self.below)) | (lo >> self.below);
        let (q, _) = self.digit(m, lo);
        if n < 0 {
            (q as i32).wrapping_neg()
        } else {
            q as i32
        }
    }

    /// [`div_round`]`(n, d)` for a quotient below 2³⁰ (a triangle's usual depth gradient),
    /// `None` for a larger one: a long division in words of the rounded magnitude by two 15-bit
    /// digits, from its bits above them (below `d` exactly when the quotient is below 2³⁰).
    #[inline(always)]
    pub(crate) fn round_below_2_30(&self, n: i64) -> Option<i32> {
        // At most 2⁶³ + 2²⁸: no overflow, and no saturation as in `rounded_magnitude`, which
        // changes only magnitudes of 2⁶³ and more, far beyond those this answers.
        let a = n.unsigned_abs() + (self.d / 2) as u64;
        if a >> 30 >= self.d as u64 {
            return None;
        }
        // Each step divides `r·2¹⁵ + c` (r < d, c the next 15 bits): its bits from b up are
        // `top(r)` and c's from b up (none when b ≥ 15: the fraction `r` leaves below 2^(b−15)
        // and c's sum to less than one), below 2¹⁶; its low word wraps, and `digit` leaves the
        // remainder below d.
        let step = |r: u32, c: u32| self.digit(self.top(r) + (c >> self.below), (r << 15) | c);
        let (q1, r) = step((a >> 30) as u32, (a >> 15) as u32 & 0x7FFF);
        let (q0, _) = step(r, a as u32 & 0x7FFF);
        // Below 2³⁰: the signed quotient fits.
        Some(with_sign_of(n, ((q1 << 15) | q0) as u64) as i32)
    }

    /// [`div_round`]`(z · 2³⁰, d)` for `0 ≤ z ≤ d`, which the caller knows (a vertex's depth `z
    /// / w` in Q1.30, inside the near and far planes; any other `z` gives a meaningless
    /// quotient), as a long division of two 15-bit digits. In line (called, it measured
    /// slower). `z` is not checked against
    /// `d`: the caller knows it.
    #[inline(always)]
    pub(crate) fn round_fraction(&self, z: i64) -> i64 {
        let (d, z) = (self.d, z as u32);
        // z·2¹⁵ = q1·d + r1 and r1·2¹⁵ = q2·d + r2 (z and r1 at most d: estimates below 2¹⁶,
        // quotients at most 2¹⁵; the low words wrap, the remainders below 2³² are exact). The
        // sums wrap, without meaning, only for a z beyond d.
        let (q1, r1) = self.digit(self.top(z), z << 15);
        let (q2, r2) = self.digit(self.top(r1), r1 << 15);
        // r2 + d/2 < 2d: the rounding adds one when it reaches d.
        let up = (r2 + d / 2 >= d) as u32;
        (q1 << 15).wrapping_add(q2).wrapping_add(up) as i64
    }
}

/// `⌊2³¹ / den⌋` for `2¹⁵ < den ≤ 2¹⁶`, from a table seed of 8 bits and one Newton step in
/// 32-bit words. The step leaves the root exact or one below, for every such `den`
/// (`reciprocal16_is_exact` tries each): one test of the remainder `2³¹ − x·den` against `den`
/// makes it exact, where a loop of up to four steps either way measured slower. Outside that
/// range the result means nothing, but nothing overflows.
pub(crate) const fn reciprocal16(den: u32) -> u32 {
    // x0 ≈ 2³¹ / den (the table's 2⁴⁷ / (den · 2¹⁶)), below 2¹⁶.
    // The index, masked to 7 bits, lies in the table's 128 entries.
    let x0 = RECIPROCALS[(den.wrapping_sub(1) >> 8) as usize & 127] as i32;
    // den · x0 is within 2⁻⁸ of 2³¹: e below 2²³, and x0 · e / 2⁸ below 2³¹.
    let e = (1u32 << 31).wrapping_sub(den.wrapping_mul(x0 as u32)) as i32;
    let x = x0.wrapping_add(x0.wrapping_mul(e >> 8) >> 23) as u32;
    // x ≤ ⌊2³¹ / den⌋: the remainder lies in [0, 2·den).
    let rem = (1u32 << 31).wrapping_sub(x.wrapping_mul(den));
    x.wrapping_add((rem >= den) as u32)
}

/// `RECIPROCALS[i] = ⌊2⁴⁷ / ((128.5 + i) · 2²⁴)⌋`: `2⁴⁷ / d` to 8 bits for a normalised `d` by
/// its top byte, the seed of both [`newton_reciprocal`] and [`reciprocal16`].
pub(crate) static RECIPROCALS: [u16; 128] = {
    let mut t = [0u16; 128];
    let mut i = 0;
    while i < 128 {
        t[i] = ((1u64 << 24) / (257 + 2 * i as u64)) as u16;
        i += 1;
    }
    t
};

/// `d · x` modulo 2⁶⁴, from one 32x32→64 product and one 32-bit product.
#[inline(always)]
fn times(d: u32, x: u64) -> u64 {
    let high = d.wrapping_mul((x >> 32) as u32) as u64;
    mul_wide_u32(d, x as u32).wrapping_add(high << 32)
}

/// `⌊(2⁶⁴ − 1) / d⌋ − 2³²` for a normalised `d` (top bit set): see [`newton_reciprocal`].
/// In the case that never happens, a division of `2⁶⁴ − 1 − 2³²·d`, whose high word
/// `2³² − 1 − d` is below `d` (d ≥ 2³¹), so that the quotient fits 32 bits.
fn reciprocal(d: u32) -> u32 {
    newton_reciprocal(d).unwrap_or_else(|| div_normalized(!d, u32::MAX, d))
}

/// [`reciprocal`] from a table seed and two Newton steps (relative error 2⁻⁸, 2⁻¹⁶, then a
/// few units), made exact by stepping the remainder `2⁶⁴ − 1 − x·d` into `[0, d)`: products
/// only, no library division. `None` if eight steps do not suffice (the tests show they do).
fn newton_reciprocal(d: u32) -> Option<u32> {
    // x0 ≈ 2⁴⁷ / d, below 2¹⁶.
    let x0 = RECIPROCALS
        .get((d >> 24) as usize & 127)
        .copied()
        .unwrap_or(0) as u32;
    // The first step in 32-bit products of 16-bit halves: p = d·x0 / 2¹⁶ ≈ 2³¹ (within
    // 2⁻⁸ of it, so 0 < p < 2³²), then x1 = x0·(2³² − p) / 2¹⁶ ≈ 2⁶² / d, below 2³¹.
    // (Wrapping operations: no panic even if the bounds were wrong; the remainder check
    // below is what makes the result exact.)
    let p = (d >> 16)
        .wrapping_mul(x0)
        .wrapping_add((d & 0xFFFF).wrapping_mul(x0) >> 16);
    let t = p.wrapping_neg();
    let x1 = x0
        .wrapping_mul(t >> 16)
        .wrapping_add(x0.wrapping_mul(t & 0xFFFF) >> 16);
    // The second in 64 bits: x + x·(2⁶⁴ − d·x)/2⁶⁴ for x ≈ 2⁶⁴ / d; the error term is small,
    // so its wrapped value is its value. Its factors x / 2⁹ and e / 2²⁴ are below 2²⁵.
    let mut x = (x1 as u64) << 2;
    let e = 0u64.wrapping_sub(times(d, x)) as i64;
    x = x.wrapping_add_signed(mul_wide((x >> 9) as i32, (e >> 24) as i32) >> 31);
    // r = 2⁶⁴ − 1 − x·d (wrapped: its true value is small), stepped into [0, d).
    let mut r = u64::MAX.wrapping_sub(times(d, x)) as i64;
    for _ in 0..8 {
        if r < 0 {
            x = x.wrapping_sub(1);
            r = r.wrapping_add(d as i64);
        } else if r >= d as i64 {
            x = x.wrapping_add(1);
            r = r.wrapping_sub(d as i64);
        } else {
            return Some(x as u32);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shifted numerator's 32-bit divisions give `div_round`'s quotient, for every shift up
    /// to 28, divisors up to the bound and numerators of every 32-bit size, both signs.
    #[test]
    fn shifted_by_short_equals_div_round() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let top = (1u32 << SHIFTED_DIVISOR_BITS) - 1;
        for i in 0..300_000u32 {
            let x = rng.next_u64();
            let m = match i % 4 {
                0 => u32::MAX - (x as u32 & 0xFF),
                _ => (x as u32) >> ((x >> 32) % 32),
            };
            let d = match i % 5 {
                0 => top - ((x >> 40) as u32 & 0xF),
                1 => 1 + ((x >> 40) as u32 & 0x7),
                _ => 1 + ((x >> 40) as u32 % top),
            };
            let s = (x >> 58) as u32 % (2 * MAX_SHIFT + 1);
            let expected = div_round((m as i64) << s, d as i64);
            assert_eq!(shifted_by_short(m, s, d) as i64, expected, "{m} {s} {d}");
            assert_eq!(
                with_sign_of(-(m as i64), shifted_by_short(m, s, d)),
                div_round(-((m as i64) << s), d as i64)
            );
        }
    }

    /// The quotient in words is `div_round`'s wherever it answers, and it answers for every
    /// numerator below 2³² whose quotient is below 2^(30 − s).
    #[test]
    fn shifted_i32_in_words_equals_div_round() {
        let mut rng = crate::testing::XorShift(0xD1B5_4A32_D192_ED03u64);
        let top = (1u32 << SHIFTED_DIVISOR_BITS) - 1;
        let (mut answered, mut declined) = (0, 0);
        for i in 0..300_000u32 {
            let x = rng.next_u64();
            let n = match i % 3 {
                0 => (x as i64) >> (x % 64),
                _ => (x as i32 >> ((x >> 32) % 32)) as i64,
            };
            let d = match i % 5 {
                0 => top - ((x >> 40) as u32 & 0xF),
                1 => 1 + ((x >> 40) as u32 & 0x7),
                _ => 1 + ((x >> 40) as u32 % top),
            };
            let s = (x >> 58) as u32 % (2 * MAX_SHIFT + 1);
            match shifted_i32_in_words(n, s, d) {
                Some(q) => {
                    assert_eq!(q as i64, div_round(n << s, d as i64), "{n} {s} {d}");
                    answered += 1;
                }
                None => {
                    let short = n.unsigned_abs() < 1 << 32;
                    assert!(
                        !short || n.unsigned_abs() / d as u64 >= 1 << (30 - s),
                        "{n} {s} {d}"
                    );
                    declined += 1;
                }
            }
        }
        assert!(
            answered > 100_000 && declined > 50_000,
            "{answered} {declined}"
        );
    }

    /// `DivideBy::round_shifted_i32` is `round` of the shifted numerator where that fits an
    /// i32, at the ends of i32 too.
    #[test]
    fn round_shifted_i32_is_round_of_the_shifted_in_a_word() {
        let mut rng = crate::testing::XorShift(0x94D0_49BB_1331_11EBu64);
        let mut fits = 0;
        for i in 0..200_000u32 {
            let x = rng.next_u64();
            let s = (x >> 59) as u32 % (MAX_SHIFT + 1);
            // |n| below 2^(62 − s): n << s within i64.
            let n = ((x as i64) >> (x % 64)) >> (s + 1);
            let d = match i % 3 {
                0 => 1 + ((x >> 20) as i64 & 0xFF),
                _ => 1 + ((x >> 8) as i64 & 0x3FFF_FFFF),
            };
            let by = DivideBy::new(d);
            let expected = i32::try_from(by.round(n << s)).ok();
            assert_eq!(by.round_shifted_i32(n, s), expected, "{n} {s} {d}");
            fits += expected.is_some() as u32;
        }
        assert!(fits > 50_000, "{fits}");
        let ends = [
            (i32::MIN as i64, 0, 1),
            (i32::MAX as i64, 0, 1),
            (-(1 << 27), 4, 1),
        ];
        for (n, s, d) in ends
            .into_iter()
            .chain([(1 << 27, 4, 1), (-(1 << 30), 1, 1)])
        {
            let by = DivideBy::new(d);
            let expected = i32::try_from(by.round(n << s)).ok();
            assert_eq!(by.round_shifted_i32(n, s), expected, "{n} {s} {d}");
        }
        assert_eq!(
            DivideBy::new(1).round_shifted_i32(-(1 << 27), 4),
            Some(i32::MIN)
        );
        assert_eq!(DivideBy::new(0).round_shifted_i32(5, 3), Some(0));
    }

    /// The 32-bit division path gives the 64-bit path's quotient wherever it applies.
    #[test]
    fn div_round_32_bit_path_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let mut checked = 0;
        for _ in 0..200_000 {
            let x = rng.next_u64();
            let n = (x as i64) >> (31 + x % 33);
            let d = ((x >> 20) as i64 & 0xFFFF_FFFF) >> ((x >> 8) % 32);
            if let Some(q) = div_round_u32(n, d) {
                let (half, wide) = (d / 2, if n >= 0 { 1 } else { -1 });
                assert_eq!(q, wide * ((n.abs() + half) / d), "{n} / {d}");
                checked += 1;
            }
        }
        assert!(checked > 50_000);
    }

    /// The 32-bit-divisor paths give the 64-bit path's quotient for every numerator (quotients
    /// of any size, the ends of the range) and every divisor that fits 32 bits.
    #[test]
    fn div_round_32_bit_divisor_paths_are_exact() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let ends = [i64::MIN, i64::MIN + 1, i64::MAX, i64::MAX - 1, 0, 1, -1];
        for i in 0..300_000 {
            let x = rng.next_u64();
            let d = ((x >> 32) as i64 >> (x % 32)).max(1);
            let n = match ends.get(i % 50) {
                Some(&e) => e,
                None => rng.next_u64() as i64 >> ((x >> 8) % 64),
            };
            let expected = div_round(n, d);
            assert_eq!(div_round_u64_u32(n, d), Some(expected), "{n} / {d}");
            if let Some(q) = div_round_u32(n, d) {
                assert_eq!(q, expected, "{n} / {d}");
            }
        }
        assert_eq!(div_round_u64_u32(5, 1 << 32), None);
        assert_eq!(div_round_u64_u32(5, 0), None);
    }

    /// The 32-bit rounded division gives the 64-bit one's quotient for every numerator and
    /// positive divisor of 32 bits.
    #[test]
    fn div_round_in_32_bit_words_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let ends = [i32::MIN, i32::MIN + 1, i32::MAX, -1, 0, 1];
        for i in 0..300_000usize {
            let x = rng.next_u64();
            let d = ((x >> 33) as i32 >> (x % 31)).max(1);
            let n = match ends.get(i % 40) {
                Some(&e) => e,
                None => (rng.next_u64() as i32) >> (i % 32),
            };
            let expected = div_round(n as i64, d as i64);
            let d = NonZeroU32::new(d as u32).unwrap_or(NonZeroU32::MIN);
            assert_eq!(div_round_word(n, d) as i64, expected, "{n} / {d}");
        }
    }

    /// A depth's division by `w` through three 32-bit divisions equals `div_round(n · 2³⁰, d)`
    /// for `0 < d < 2¹⁹` and `0 ≤ n ≤ d` (the ends included), and overflows nowhere for an `n`
    /// outside its range (which its caller never passes).
    #[test]
    fn fraction_in_words_equals_div_round() {
        let mut rng = crate::testing::XorShift(0x5DEE_CE66_D1CE_4E5Bu64);
        let top = (1i64 << 19) - 1;
        for i in 0..200_000u32 {
            let d = ((rng.next_u64() >> 45) as i64 >> (i % 19)).max(1);
            let n = match i % 100 {
                0 => 0,
                1 => d,
                _ => (rng.next_u64() % (d as u64 + 1)) as i64,
            };
            let nz = NonZeroU32::new(d as u32).unwrap_or(NonZeroU32::MIN);
            assert_eq!(
                fraction_in_words(n as u32, nz),
                div_round(n << 30, d),
                "{n} / {d}"
            );
        }
        let nz = NonZeroU32::new(top as u32).unwrap_or(NonZeroU32::MIN);
        assert_eq!(fraction_in_words(top as u32, nz), 1 << 30);
        for (n, d) in [(-1i64, 5i32), (6, 5), (i64::MAX, top as i32), (i64::MIN, 1)] {
            fraction_in_words(
                n as u32,
                NonZeroU32::new(d as u32).unwrap_or(NonZeroU32::MIN),
            );
        }
    }

    /// The two-digit 64/32 division gives the 64-bit quotient wherever it applies: divisors
    /// of every size (normalisation shifts 0 to 31), quotients up to 2³² − 1, and the digit
    /// estimates that need their corrections.
    #[test]
    fn div_round_64_by_32_bit_path_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let mut checked = 0;
        for i in 0..400_000u32 {
            let x = rng.next_u64();
            let d = ((x >> 32) as u32 >> (i % 32)).max(1) as i64;
            let n = ((x as i64) >> (x % 40))
                .wrapping_mul(d >> (i % 7))
                .wrapping_add(x as i64 >> 40);
            if let Some(q) = div_round_u64_u32(n, d) {
                let (half, sign) = (d / 2, if n >= 0 { 1 } else { -1 });
                // The magnitude saturates at i64::MAX, as the 64-bit path's does.
                let a = (n.unsigned_abs() as i128 + half as i128).min(i64::MAX as i128);
                let expected = sign * (a / d as i128) as i64;
                assert_eq!(q, expected, "{n} / {d}");
                checked += 1;
            }
        }
        for (n, d) in [
            (u64::MAX >> 1, u32::MAX),
            ((1 << 32) - 1, 1),
            (0, 7),
            ((1 << 63) - 1, 1 << 31),
        ] {
            if let Some(q) = div_round_u64_u32(n as i64, d as i64) {
                let a = (n as i128 + (d / 2) as i128).min(i64::MAX as i128);
                assert_eq!(q, (a / d as i128) as i64);
            }
        }
        // Quotients of every size below 2³², remainders of every size below d.
        for _ in 0..200_000 {
            let x = rng.next_u64();
            let d = ((x >> 32) as u32 >> (x % 32)).max(1);
            let q = (x as u32) >> ((x >> 5) % 32);
            let r = ((x >> 16) as u32) % d;
            let n = q as u64 * d as u64 + r as u64;
            assert_eq!(div_u64_u32(n, d), q, "{n} / {d}");
        }
        assert!(checked > 100_000, "{checked}");
        // Floor division by 32-bit digits equals the 64-bit one for every size of divisor and
        // numerator, and the ends of both ranges.
        for k in 0..200_000u64 {
            let x = rng.next_u64();
            let n = rng.next_u64() >> (k % 64);
            let d = (x >> (x % 64)).max(1);
            assert_eq!(
                div_by_word(n, (d as u32).max(1)),
                n / u64::from((d as u32).max(1))
            );
            assert_eq!(div_floor(n, d), n / d, "{n} / {d}");
        }
        for (n, d) in [
            (u64::MAX, 1),
            (u64::MAX, u64::from(u32::MAX)),
            (0, 7),
            (5, 0),
        ] {
            assert_eq!(div_floor(n, d), n.checked_div(d).unwrap_or(0));
        }
    }

    /// The two-by-one division equals 128-bit division: random divisors of every size,
    /// numerators up to the largest the quotient allows, and the boundaries.
    #[test]
    fn div_rem_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let check = |d: u32, n: u64| {
            let Some(div) = Divisor::new(d as i64) else {
                panic!("{d}")
            };
            if (n >> 32) >= d as u64 {
                return;
            }
            let (q, r) = div.div_rem(n);
            assert_eq!(
                (q as u64, r as u64),
                (n / d as u64, n % d as u64),
                "{n} / {d}"
            );
        };
        for d in [
            1,
            2,
            3,
            7,
            1 << 31,
            (1 << 31) - 1,
            (1 << 31) + 1,
            u32::MAX,
            u32::MAX - 1,
        ] {
            for n in [
                0,
                1,
                d as u64 - 1,
                d as u64,
                (d as u64) << 31,
                ((d as u64) << 32) - 1,
            ] {
                check(d, n);
            }
        }
        for _ in 0..1_000_000 {
            let x = rng.next_u64();
            let d = ((x >> 32) as u32 >> (x % 32)).max(1);
            let n = rng.next_u64() >> ((x >> 8) % 64);
            check(d, n);
            check(d, ((d as u64) << 32).wrapping_sub(1 + (n >> 40)));
        }
    }

    /// The reciprocal equals 128-bit division for every seed interval's ends and middle and
    /// for random divisors, and never needs the fallback (which is exact too).
    #[test]
    fn reciprocal_is_exact() {
        let exact = |d: u32| ((u128::from(u64::MAX) / d as u128) - (1u128 << 32)) as u32;
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let top = (128u32..256).flat_map(|b| {
            let lo = b << 24;
            [lo, lo + 1, lo + (1 << 23), lo + 0xFF_FFFF, lo + 0xFF_FFFE]
        });
        let random = (0..1_000_000).map(|_| (rng.next_u64() as u32) | 1 << 31);
        for d in top.chain(random) {
            assert_eq!(newton_reciprocal(d), Some(exact(d)), "{d}");
            assert_eq!(div_normalized(!d, u32::MAX, d), exact(d), "fallback, {d}");
        }
    }

    /// `DivideBy::new_positive32` is `DivideBy::new` for every positive divisor of a word (its
    /// ends and at random), but for the `Divisor` that `new` prepares where division is a
    /// library routine, and divides as it does for numerators of every size. (The Cortex-M4's
    /// firmware hashes check it under emulation.)
    #[test]
    fn divide_by_a_known_positive_word_matches() {
        let mut rng = crate::testing::XorShift(0x0123_4567_89AB_CDEFu64);
        let ends = [1, 2, 3, (1 << 18) - 1, 1 << 18, i32::MAX];
        let random = (0..20_000).map(|_| (rng.next_u64() as i32 & i32::MAX).max(1));
        let divisors: std::vec::Vec<i32> = ends.into_iter().chain(random).collect();
        for d in divisors {
            let (known, tested) = (DivideBy::new_positive32(d), DivideBy::new(d as i64));
            assert_eq!((known.d, known.d32), (tested.d, tested.d32), "{d}");
            assert!(
                known.by.is_none() && (tested.by.is_none() || NARROW_CORE),
                "{d}"
            );
            let x = rng.next_u64();
            for n in [
                0,
                1,
                -1,
                d as i64,
                -(d as i64),
                (x as i64) >> (x % 64),
                i64::MIN,
            ] {
                assert_eq!(known.round(n), tested.round(n), "{n} / {d}");
            }
            let z = (x % (d as u64 + 1)) as i64;
            assert_eq!(
                known.round_fraction(z),
                tested.round_fraction(z),
                "{z} / {d}"
            );
        }
    }

    /// `Divisor::div_round` is `div_round` wherever the divisor is prepared.
    #[test]
    fn div_round_matches() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        assert!(Divisor::new(0).is_none() && Divisor::new(-3).is_none());
        assert!(Divisor::new(1 << 32).is_none());
        for _ in 0..500_000 {
            let x = rng.next_u64();
            let d = (x as i64 & 0xFFFF_FFFF) >> ((x >> 32) % 32);
            let n = (rng.next_u64() as i64) >> ((x >> 40) % 64);
            let Some(div) = Divisor::new(d) else {
                assert_eq!(d, 0);
                continue;
            };
            assert_eq!(div.div_round(n), div_round(n, d), "{n} / {d}");
        }
        let div = Divisor::new(3).unwrap_or_else(|| unreachable!());
        for n in [i64::MIN, i64::MIN + 1, i64::MAX, -5, -4, -1, 0, 1, 4, 5] {
            assert_eq!(div.div_round(n), div_round(n, 3), "{n}");
        }
    }

    /// The digit of cores without a divide instruction, on every host: for every top half
    /// `vn1` of a normalised divisor, at the ends of the dividends a digit takes (below
    /// `(vn1 + 1) · 2¹⁶`) and at random, the estimate is at most the quotient and short of
    /// it by less than eight, and the steps make it exact.
    #[test]
    fn digits_by_reciprocal_are_exact() {
        let mut rng = crate::testing::XorShift(0x0DDB_1A5E_5BAD_5EED);
        let mut worst = 0;
        for vn1 in 1u32 << 15..1 << 16 {
            let r = reciprocal16(vn1 + 1);
            let most = ((vn1 + 1) << 16).wrapping_sub(1).max(vn1 << 16);
            for top in [
                0,
                1,
                vn1 - 1,
                vn1,
                vn1 << 15,
                most - 1,
                most,
                rng.next_u64() as u32 % most,
            ] {
                let (q, rest) = (top / vn1, top % vn1);
                let estimate = reciprocal_estimate(top, r);
                assert!(
                    estimate <= q && q - estimate < 8,
                    "{top} / {vn1}: {estimate}"
                );
                worst = worst.max(q - estimate);
                assert_eq!(by_reciprocal(top, vn1, r), (q, rest), "{top} / {vn1}");
            }
        }
        assert!(worst >= 2, "the estimate is exercised short: {worst}");
    }

    /// The 16-bit reciprocal is exact for every divisor of its range.
    #[test]
    fn reciprocal16_is_exact() {
        for den in (1u32 << 15) + 1..=1 << 16 {
            assert_eq!(reciprocal16(den), (1u32 << 31) / den, "{den}");
        }
    }

    /// Random divisors below 2²⁹ at every bit length, with the ends of each length.
    fn short_divisors(rng: &mut crate::testing::XorShift) -> impl Iterator<Item = u32> + '_ {
        let ends = (0..29).flat_map(|b| [1u32 << b, (2u32 << b) - 1]);
        let random = (0..200_000).map(|_| {
            let x = rng.next_u64();
            ((x as u32 >> 3) >> ((x >> 32) % 29)).max(1)
        });
        ends.chain(random)
    }

    /// One digit is exact for every numerator whose estimate bits are below 2¹⁶ and whose
    /// quotient is at most 2¹⁵ (the callers'), the worst of them included; beyond that
    /// quotient it is at most two below, and nothing overflows.
    #[test]
    fn short_quotient_digit_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let mut divisors: std::vec::Vec<u32> = short_divisors(&mut rng).collect();
        divisors.truncate(100_000);
        for d in divisors {
            let Some(by) = ShortQuotients::new(d as i64) else {
                panic!("{d}")
            };
            let b = by.below;
            let top = (1u64 << (b + 16)) - 1;
            // The callers' numerators: quotients up to 2¹⁵.
            let callers = (((1u64 << 15) + 1) * d as u64 - 1).min(top);
            let x = rng.next_u64();
            for n in [
                0,
                1,
                d as u64,
                callers,
                callers - d as u64,
                x % (callers + 1),
                x >> (x % 64),
                top,
                top - d as u64,
                x % (top + 1),
            ] {
                let n = n.min(top);
                let m = (n >> b) as u32;
                let exact = ((n / d as u64) as u32, (n % d as u64) as u32);
                let (q, rem) = by.digit(m, n as u32);
                if n <= callers {
                    assert_eq!((q, rem), exact, "{n} / {d}");
                } else {
                    // Beyond: three steps from an estimate at most five below.
                    assert!(q <= exact.0 && exact.0 - q <= 2, "{n} / {d}: {q}");
                }
            }
        }
    }

    /// `round` and `round_fraction` are `div_round`'s, in words wherever a vertex needs them
    /// (numerators within ±2¹⁴·d, the ends included, and fractions of 0 ≤ z ≤ d); outside
    /// those ranges (never passed) they overflow nothing.
    #[test]
    fn short_quotients_equal_div_round() {
        assert!(ShortQuotients::new(0).is_none() && ShortQuotients::new(-1).is_none());
        assert!(
            ShortQuotients::new(1 << 29).is_none() && ShortQuotients::new((1 << 29) - 1).is_some()
        );
        // A word's range by one test: the same answers as through a 64-bit value.
        for d in [0, 1, 2, (1 << 29) - 1, 1 << 29, 1 << 31, u32::MAX] {
            let (word, wide) = (ShortQuotients::new32(d), ShortQuotients::new(d as i64));
            assert_eq!(word.is_some(), (1..1 << 29).contains(&d), "{d}");
            assert_eq!(word.map(|q| (q.d, q.r)), wide.map(|q| (q.d, q.r)), "{d}");
        }
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for d in short_divisors(&mut crate::testing::XorShift(0x1234_5678_9ABC_DEF1)) {
            let Some(by) = ShortQuotients::new(d as i64) else {
                panic!("{d}")
            };
            let x = rng.next_u64();
            let d64 = d as i64;
            let within = (x as i64).rem_euclid(2 * (d64 << 14) + 1) - (d64 << 14);
            let end = (d64 << 14) - 1;
            for n in [within, -within, d64 / 2, -(d64 / 2), end, -end] {
                let exact = div_round(n, d64) as i32;
                assert_eq!(by.round(n), exact, "{n} / {d}");
            }
            for n in [(x as i64) >> (x % 64), i64::MIN, i64::MAX] {
                let _ = by.round(n);
            }
            let z = (x >> 32) as i64 % (d64 + 1);
            for z in [z, 0, d64, d64 - 1, d64 / 2] {
                assert_eq!(by.round_fraction(z), div_round(z << 30, d64), "{z} / {d}");
            }
            // Outside [0, d] (never passed) some quotient, and no overflow.
            for z in [-z - 1, d64 + 1 + z, i64::MIN, i64::MAX] {
                let _ = by.round_fraction(z);
            }
        }
    }

    /// A digit whose estimate lies up to three below its quotient is corrected; one further
    /// below (a numerator outside the callers' bounds makes one) takes three steps and no more.
    #[test]
    fn digit_corrects_three_steps_and_no_more() {
        for d in short_divisors(&mut crate::testing::XorShift(0x5DEE_CE66_D1CE_4E5B)) {
            let Some(by) = ShortQuotients::new(d as i64) else {
                panic!("{d}")
            };
            let m = 1000;
            let estimate = (m * by.r) >> 16;
            for (below, rem) in [(0, 0), (1, d - 1), (3, d / 2), (3, d - 1), (4, 0), (5, 7)] {
                let low = (estimate + below).wrapping_mul(d).wrapping_add(rem % d);
                let expected = if below <= 3 {
                    (estimate + below, rem % d)
                } else {
                    (estimate + 3, (below - 3) * d + rem % d)
                };
                assert_eq!(by.digit(m, low), expected, "{d}: {below} below");
            }
        }
    }

    /// `round_below_2_30` is `div_round` wherever that lies within ±(2³⁰ − 1) and declines
    /// elsewhere: quotients of every size up to and past 2³⁰ (each rounded from the middle of
    /// its range, its ends and its ties), both signs, and the extremes of i64.
    #[test]
    fn short_quotients_below_2_30_equal_div_round() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let (mut answered, mut declined) = (0, 0);
        for d in short_divisors(&mut crate::testing::XorShift(0x0F1E_2D3C_4B5A_6978)) {
            let Some(by) = ShortQuotients::new(d as i64) else {
                panic!("{d}")
            };
            let d64 = d as i64;
            let x = rng.next_u64();
            let bits = (x % 32) as u32;
            let q = ((x >> 8) as i64 & ((1 << bits) - 1)).min((1 << 30) + 2);
            let around = [q, 0, 1, (1 << 15) - 1, 1 << 15, (1 << 30) - 1, 1 << 30];
            let mut numerators = std::vec![i64::MIN, i64::MAX, (x >> 1) as i64];
            for q in around {
                for k in [
                    -(d64 / 2) - 1,
                    -(d64 / 2),
                    0,
                    (d64 - 1) / 2,
                    d64 / 2,
                    d64 - 1,
                ] {
                    let n = q * d64 + k;
                    numerators.extend([n, -n]);
                }
            }
            for n in numerators {
                let exact = div_round(n, d64);
                match by.round_below_2_30(n) {
                    Some(q) => {
                        assert_eq!(q as i64, exact, "{n} / {d}");
                        assert!(exact.unsigned_abs() < 1 << 30, "{n} / {d}: {exact}");
                        answered += 1;
                    }
                    None => {
                        assert!(exact.unsigned_abs() >= 1 << 30, "{n} / {d}: {exact}");
                        declined += 1;
                    }
                }
            }
        }
        assert!(
            answered > 1_000_000 && declined > 100_000,
            "{answered} {declined}"
        );
    }
}

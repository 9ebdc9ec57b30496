//! The fixed-point formats, each named by what it holds.

use fixed::types::{I16F16, I2F30};

/// Model, world and view coordinates, and the entries of [`Mat4`](super::Mat4): Q16.16
/// (range ±32768, resolution 2⁻¹⁶ ≈ 1.5·10⁻⁵).
pub type Scalar = I16F16;

/// Values in [−2, 2): sines, cosines and the components of unit vectors: Q2.30.
pub type Unit = I2F30;

/// Fraction bits of screen coordinates: vertices are snapped to 1/16 of a pixel.
pub const SUBPIXEL_BITS: u32 = 4;

/// Sub-pixel units per pixel (`1 << SUBPIXEL_BITS`).
pub const SUBPIXEL_SCALE: i32 = 1 << SUBPIXEL_BITS;

/// Raw value of 1.0 in [`Unit`] (Q2.30).
pub(crate) const UNIT_ONE: i32 = 1 << 30;

/// Depth after projection, 0 at the near plane and this value at the far plane (Q1.30).
pub(crate) const DEPTH_ONE: i32 = 1 << 30;

/// `v / 2^s`, rounded to nearest with ties away from zero, so `shr_round(-v) == -shr_round(v)`.
/// Exact for every `v` and `s` (no sum can overflow). Out of line: called from many places,
/// mostly set-up, where its 64-bit steps in line would take several times the flash.
#[inline(never)]
pub(crate) const fn shr_round(v: i64, s: u32) -> i64 {
    if s == 0 {
        return v;
    }
    if s > 64 {
        return 0;
    }
    // The magnitude rounded half up, ⌊(m + 2^(s−1)) / 2^s⌋, is ⌊(⌊m / 2^(s−1)⌋ + 1) / 2⌋: at
    // most 2⁶², so it takes its sign in an i64.
    let m = (((v.unsigned_abs() >> (s - 1)) + 1) >> 1) as i64;
    if v < 0 {
        -m
    } else {
        m
    }
}

/// Significant bits of the largest magnitude among `values` (0 when all are zero): the shift
/// that renormalises a vector or matrix of any scale is taken from it.
pub(crate) fn magnitude_bits(values: &[i64]) -> u32 {
    let max = values.iter().map(|v| v.unsigned_abs()).max().unwrap_or(0);
    64 - leading_zeros64(max)
}

/// `v.leading_zeros()`; on cores without a count-leading-zeros instruction by
/// [`leading_zeros_by_halves`] instead of the library routine.
#[inline]
pub(crate) const fn leading_zeros32(v: u32) -> u32 {
    if NARROW_CORE {
        leading_zeros_by_halves(v)
    } else {
        v.leading_zeros()
    }
}

/// `BYTE_ZEROS[i]` is `(i as u8).leading_zeros()`: the top byte's count for
/// [`leading_zeros_by_halves`].
pub(crate) static BYTE_ZEROS: [u8; 256] = {
    let mut t = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = (i as u8).leading_zeros() as u8;
        i += 1;
    }
    t
};

/// `v.leading_zeros()` by two comparisons and shifts (binary search, written out), then the top
/// byte's own count from a table of 256 bytes.
#[inline(always)]
const fn leading_zeros_by_halves(v: u32) -> u32 {
    if v == 0 {
        return 32;
    }
    let (mut v, mut n) = (v, 0);
    if v >> 16 == 0 {
        v <<= 16;
        n += 16;
    }
    if v >> 24 == 0 {
        v <<= 8;
        n += 8;
    }
    // The top byte (below 256) indexes the table's 256 entries: no bounds test is left.
    n + BYTE_ZEROS[(v >> 24) as usize] as u32
}

/// `v.leading_zeros()`, from its words' counts.
#[inline]
pub(crate) const fn leading_zeros64(v: u64) -> u32 {
    let hi = (v >> 32) as u32;
    if hi != 0 {
        leading_zeros32(hi)
    } else {
        32 + leading_zeros32(v as u32)
    }
}

/// True on the smallest cores (Armv6-M; RISC-V without atomics), where every division and
/// every 64-bit product is a library routine: there a few comparisons that spare one pay for
/// themselves, elsewhere they cost more than the instruction. (`cfg` on stable Rust cannot
/// see the divide or the long multiply; these cores are told apart from Armv7-M and up by
/// their lack of 32-bit compare-and-swap.)
pub(crate) const NARROW_CORE: bool = cfg!(all(
    target_pointer_width = "32",
    not(target_has_atomic = "32")
));

/// True for `−2^bits < v < 2^bits` (`bits` < 63), by one unsigned comparison: on 32-bit cores a
/// 64-bit comparison is several instructions, and range checks of whole vectors are hot.
#[inline(always)]
pub(crate) const fn below_bits(v: i64, bits: u32) -> bool {
    let limit = 1u64 << bits;
    (v as u64).wrapping_add(limit - 1) < 2 * limit - 1
}

/// `ux·vy − vx·uy` in 32-bit words, of factors known to be short (within ±2¹⁵), untested: each
/// product within ±2³⁰, their difference within ±(2³¹ − 2¹⁵). Other factors give a meaningless
/// value, but nothing overflows.
#[inline(always)]
pub(crate) const fn short_sides_cross(ux: i32, uy: i32, vx: i32, vy: i32) -> i64 {
    ux.wrapping_mul(vy).wrapping_sub(vx.wrapping_mul(uy)) as i64
}

/// The words of `n << s` (`s < 32`, nothing shifted out), by 32-bit shifts: a 64-bit shift by
/// a variable amount is a library call on Cortex-M0.
#[inline(always)]
pub(super) const fn shl_words(n: u64, s: u32) -> (u32, u32) {
    let (hi, lo) = ((n >> 32) as u32, n as u32);
    // `lo >> (32 − s)` without a shift by 32 when s = 0.
    ((hi << s) | ((lo >> 1) >> (31 - s)), lo << s)
}

/// The low 32 bits of `v >> s` (arithmetic shift, `s < 64`), from 32-bit shifts of its words:
/// the whole result when it fits i32. A 64-bit shift by a variable amount is a library call on
/// Cortex-M0.
#[inline(always)]
pub(crate) const fn shr_low_word(v: i64, s: u32) -> i32 {
    let (hi, lo) = ((v >> 32) as i32, v as u32);
    if s >= 32 {
        hi >> (s - 32)
    } else {
        // `hi << (32 − s)` without a shift by 32 when s = 0.
        ((lo >> s) | (((hi as u32) << 1) << (31 - s))) as i32
    }
}

/// `[f(a), f(b), f(c)]`: `array::map` written out, which optimisers keep as three plain
/// expressions at every optimisation level (at `opt-level = "s"` the library's `map` becomes a
/// loop through a temporary, in the per-triangle hot path).
#[inline(always)]
pub(crate) fn map3<T, U>(v: [T; 3], mut f: impl FnMut(T) -> U) -> [U; 3] {
    let [a, b, c] = v;
    [f(a), f(b), f(c)]
}

/// `a · b` exactly, from 32-bit factors: the form compilers turn into one widening multiply
/// (SMULL) on Cortex-M3/M4 instead of a full 64-bit product; on cores without a long multiply
/// four 32-bit products of halves (one short routine) instead of the library's 64-bit product.
#[inline(always)]
pub(crate) const fn mul_wide(a: i32, b: i32) -> i64 {
    if NARROW_CORE {
        mul_halves(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// [`mul_wide`] for `|b| < 2¹⁵` (any `a`), or for `|a| ≤ 2³⁰` and `|b| < 2¹⁶` (a value
/// difference and a screen coordinate difference): on cores without a long multiply two
/// 32-bit products in line (of `b` by `a`'s bits from 15 up and below, each within ±2³¹
/// under either bound), instead of the four of [`mul_halves`].
#[inline(always)]
pub(crate) const fn mul_short(a: i32, b: i32) -> i64 {
    if NARROW_CORE {
        short_by_halves(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// [`mul_short`] on cores without a long multiply (tested on every host).
#[inline(always)]
const fn short_by_halves(a: i32, b: i32) -> i64 {
    let (high, low) = ((a >> 15).wrapping_mul(b), (a & 0x7FFF).wrapping_mul(b));
    ((high as i64) << 15).wrapping_add(low as i64)
}

/// `a · b` exactly for `|a| ≤ 2¹⁵` and `b` of any 32 bits unsigned: on cores without a long
/// multiply two 32-bit products, of `a` by `b`'s halves (each within ±2³¹), in line, instead
/// of the library's 64-bit product.
#[inline(always)]
pub(crate) const fn mul_short_u32(a: i32, b: u32) -> i64 {
    if NARROW_CORE {
        halves_times((b >> 16) as i32, (b & 0xFFFF) as i32, a)
    } else {
        a as i64 * b as i64
    }
}

/// `(high·2¹⁶ + low) · b` for halves `high`, `low` (`0 ≤ low < 2¹⁶`) of a long factor and a
/// short `b`, whose products with each half lie within ±2³¹: the low product's words, the high
/// product added into them (written so, the compiler does not turn it back into a 64-bit
/// product call).
#[inline(always)]
const fn halves_times(high: i32, low: i32, b: i32) -> i64 {
    let low = low.wrapping_mul(b);
    let (lo, hi) = add_shifted16(low as u32, low >> 31, high.wrapping_mul(b));
    ((hi as i64) << 32) | lo as i64
}

/// `hi·2³² + lo + m·2¹⁶` as words (`lo`, `hi`), for a signed 32-bit `m`: the low half of `m`
/// with a carry into the high word, its high half by an arithmetic shift (32-bit operations
/// only, where a 64-bit sum of a shifted product takes twice as many on Cortex-M0).
#[inline(always)]
const fn add_shifted16(lo: u32, hi: i32, m: i32) -> (u32, i32) {
    let (lo, carry) = lo.overflowing_add((m as u32) << 16);
    (lo, hi.wrapping_add(m >> 16).wrapping_add(carry as i32))
}

/// `⌊c · d / 2³⁰⌋` for `c ≤ 2¹⁶` and `d < 2³¹` (a light's channel and a cosine), below 2¹⁷:
/// on cores without a long multiply [`shr30_by_halves`], elsewhere the widening product.
#[inline(always)]
pub(crate) const fn mul_shr30_short(c: u32, d: u32) -> u32 {
    if NARROW_CORE {
        shr30_by_halves(c, d)
    } else {
        (mul_wide_u32(c, d) >> 30) as u32
    }
}

/// [`mul_shr30_short`] by two 32-bit products, of `c` by `d`'s bits from 15 up (`c·dₕ ≤ 2³² −
/// 2¹⁶`) and below (`c·dₗ < 2³¹`): `⌊(c·dₕ·2¹⁵ + c·dₗ) / 2³⁰⌋ = ⌊(c·dₕ + ⌊c·dₗ / 2¹⁵⌋) / 2¹⁵⌋`,
/// whose inner sum stays below 2³² (tested on every host).
#[inline(always)]
const fn shr30_by_halves(c: u32, d: u32) -> u32 {
    let (high, low) = (d >> 15, d & 0x7FFF);
    c.wrapping_mul(high).wrapping_add(c.wrapping_mul(low) >> 15) >> 15
}

/// `a · b` exactly for unsigned factors: [`mul_wide`]'s unsigned twin (UMULL on Cortex-M3/M4).
#[inline(always)]
pub(crate) const fn mul_wide_u32(a: u32, b: u32) -> u64 {
    if NARROW_CORE {
        mul_halves_u32(a, b)
    } else {
        a as u64 * b as u64
    }
}

/// [`mul_wide`] from 16-bit halves: every partial product fits 32 bits. Out of line: in line
/// at every product it measured slower and larger (the vertex transform takes
/// `SplitTransform` instead, two 32-bit products a term).
#[inline(never)]
const fn mul_halves(a: i32, b: i32) -> i64 {
    let (ah, al) = (a >> 16, (a & 0xFFFF) as u32);
    let (bh, bl) = (b >> 16, (b & 0xFFFF) as u32);
    // Low halves below 2¹⁶, high halves within ±2¹⁵: each product fits 32 bits. The outer
    // products are the words of a start; the two middle ones are added into them.
    let (m1, m2) = (ah.wrapping_mul(bl as i32), bh.wrapping_mul(al as i32));
    let (lo, hi) = add_shifted16(al * bl, ah.wrapping_mul(bh), m1);
    let (lo, hi) = add_shifted16(lo, hi, m2);
    ((hi as i64) << 32) | lo as i64
}

/// [`mul_wide_u32`] from 16-bit halves (out of line, as [`mul_halves`]).
#[inline(never)]
const fn mul_halves_u32(a: u32, b: u32) -> u64 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    // Every product of halves fits 32 bits; their sum in the middle may not.
    let middle = (ah * bl) as u64 + (al * bh) as u64;
    (((ah * bh) as u64) << 32) + (middle << 16) + (al * bl) as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Light terms by halves equal the widening product's, at the corners of their range and
    /// at random.
    #[test]
    fn shr30_by_halves_equals_the_wide_product() {
        let mut rng = crate::testing::XorShift(0xBB67_AE85_84CA_A73Bu64);
        let corners = [
            (0, 0),
            (1 << 16, (1 << 31) - 1),
            (1 << 16, 1 << 15),
            (1, 0x7FFF),
        ];
        let random = (0..200_000).map(|_| {
            let x = rng.next_u64();
            ((x as u32) % ((1 << 16) + 1), (x >> 33) as u32)
        });
        for (c, d) in corners.into_iter().chain(random) {
            let wide = ((c as u64 * d as u64) >> 30) as u32;
            assert_eq!(shr30_by_halves(c, d), wide, "{c} {d}");
            assert_eq!(mul_shr30_short(c, d), wide, "{c} {d}");
        }
    }
    use crate::math::div_round;

    /// The binary-search count of leading zeros is the instruction's, at every bit position.
    #[test]
    fn leading_zeros_by_halves_is_exact() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let values = (0..64).flat_map(|b| [1u64 << b, (1u64 << b) - 1, (1u64 << b) | 1]);
        for v in values.chain((0..10_000).map(|_| rng.next_u64() >> (rng.next_u64() % 64))) {
            let w = v as u32;
            assert_eq!(leading_zeros_by_halves(w), w.leading_zeros(), "{v}");
        }
    }

    /// `shr_round` is the quotient by 2^s rounded to nearest, ties away from zero, for every
    /// shift (past 64 too), at the ends of i64 (where a sum of half would overflow) and at
    /// random.
    #[test]
    fn shr_round_is_exact_at_every_shift() {
        let reference = |v: i64, s: u32| {
            let (m, half) = (i128::from(v).abs(), (1i128 << s) >> 1);
            let q = (m + half) >> s;
            (if v < 0 { -q } else { q }) as i64
        };
        let mut rng = crate::testing::XorShift(0x5851_F42D_4C95_7F2Du64);
        let ends = [
            i64::MIN,
            i64::MIN + 1,
            -3,
            -2,
            -1,
            0,
            1,
            2,
            3,
            i64::MAX - 1,
            i64::MAX,
        ];
        let random = (0..20_000).map(|_| rng.next_u64() as i64 >> (rng.next_u64() % 64));
        for v in ends.into_iter().chain(random) {
            for s in 0..70 {
                assert_eq!(shr_round(v, s), reference(v, s), "{v} >> {s}");
            }
        }
    }

    /// `shr_low_word` is the low word of the 64-bit shift, for every shift and sign.
    #[test]
    fn shr_low_word_is_the_shift() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..100_000 {
            let v = rng.next_u64() as i64 >> (rng.next_u64() % 64);
            for s in 0..64 {
                assert_eq!(shr_low_word(v, s), (v >> s) as i32, "{v} >> {s}");
            }
        }
    }

    /// The product of a short factor by the halves of a long unsigned one (what Cortex-M0's
    /// normalisation takes, so not run on the host otherwise) is the product, for factors
    /// within the bounds it is used at.
    #[test]
    fn short_times_halves_of_u32_is_the_product() {
        let narrow = |x: i32, y: u32| halves_times((y >> 16) as i32, (y & 0xFFFF) as i32, x);
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let xs = [-(1 << 15), -(1 << 15) + 1, -1, 0, 1, (1 << 15) - 1, 1 << 15];
        let ys = [0, 1, 0xFFFF, 0x1_0000, u32::MAX - 1, u32::MAX];
        for x in xs {
            for y in ys {
                assert_eq!(narrow(x, y), x as i64 * y as i64, "{x} {y}");
                assert_eq!(mul_short_u32(x, y), x as i64 * y as i64, "{x} {y}");
            }
        }
        for _ in 0..100_000 {
            let r = rng.next_u64();
            let x = ((r as i32) >> 16).clamp(-(1 << 15), 1 << 15);
            let y = (r >> 32) as u32;
            assert_eq!(narrow(x, y), x as i64 * y as i64, "{x} {y}");
        }
    }

    /// The short product is the product for any `a` and `|b| < 2¹⁵`, and for `|a| ≤ 2³⁰` and
    /// `|b| < 2¹⁶` (in its narrow form, which the host does not otherwise run): at the ends of
    /// both ranges and at random.
    #[test]
    fn short_products_are_the_products() {
        let check = |a: i32, b: i32| {
            assert_eq!(short_by_halves(a, b), a as i64 * b as i64, "{a} {b}");
            assert_eq!(mul_short(a, b), a as i64 * b as i64, "{a} {b}");
        };
        let bs = [-32_767, -1, 0, 1, 2560, 16_384, 32_767];
        for a in [i32::MIN, i32::MIN + 1, -65_536, -1, 0, 1, 65_535, i32::MAX] {
            for b in bs {
                check(a, b);
            }
        }
        let (most, edge) = (1 << 30, (1 << 16) - 1);
        let long_bs = [-edge, -edge + 1, -32_768, 32_768, edge - 1, edge];
        for a in [
            -most,
            -most + 1,
            -most + 32_767,
            -32_769,
            32_768,
            most - 1,
            most,
        ] {
            for b in long_bs.into_iter().chain(bs) {
                check(a, b);
            }
        }
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..200_000 {
            let x = rng.next_u64();
            check(x as i32, ((x >> 32) as i32) >> 17);
            check(
                (x as i32) >> 1,
                (((x >> 32) as i32) >> 15).max(1 - (1 << 16)),
            );
        }
    }

    /// The products of halves, signed and unsigned, are the 64-bit products: at the ends of
    /// the range and at random.
    #[test]
    fn products_of_halves_are_the_products() {
        let check = |a: i32, b: i32| {
            assert_eq!(mul_halves(a, b), a as i64 * b as i64, "{a} {b}");
            let (ua, ub) = (a as u32, b as u32);
            assert_eq!(mul_halves_u32(ua, ub), ua as u64 * ub as u64, "{ua} {ub}");
        };
        let ends = [
            i32::MIN,
            i32::MIN + 1,
            -65_536,
            -65_535,
            -1,
            0,
            1,
            65_535,
            65_536,
            i32::MAX,
        ];
        for a in ends {
            for b in ends {
                check(a, b);
            }
        }
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        for _ in 0..200_000 {
            let x = rng.next_u64();
            check(
                (x as i32) >> (x % 32),
                ((x >> 32) as i32) >> ((x >> 8) % 32),
            );
        }
    }

    /// `below_bits` is the open interval's test, at its ends and the ends of the range.
    #[test]
    fn below_bits_is_the_open_interval() {
        for bits in [0u32, 1, 15, 30, 31, 62] {
            let l = 1i64 << bits;
            for v in [
                i64::MIN,
                -l - 1,
                -l,
                -l + 1,
                -1,
                0,
                1,
                l - 1,
                l,
                l + 1,
                i64::MAX,
            ] {
                assert_eq!(
                    below_bits(v, bits),
                    -l < v && v < l,
                    "{v} within {bits} bits"
                );
            }
        }
    }

    #[test]
    fn rounding_is_symmetric() {
        for v in [-5i64, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, i64::MIN, i64::MAX] {
            assert_eq!(shr_round(v.saturating_neg(), 1), -shr_round(v, 1));
            assert_eq!(
                div_round(-v.max(-i64::MAX), 3),
                -div_round(v.max(-i64::MAX), 3)
            );
        }
        assert_eq!(shr_round(3, 1), 2);
        assert_eq!(shr_round(-3, 1), -2);
        assert_eq!(div_round(7, 2), 4);
        assert_eq!(div_round(-7, 2), -4);
        assert_eq!(div_round(1, 0), 0);
    }
}

//! Integer square root: the only root the pipeline takes (normals, light directions, camera
//! axes), exact and free of floats.

use super::divide::div_u64_u32;
use super::scalar::{leading_zeros64, mul_wide_u32};

/// `floor(sqrt(n))` of a word, bit by bit: a pair of bits a step, shifts, adds and compares,
/// no division.
const fn word_root(n: u32) -> u32 {
    let mut rem = n;
    let mut root = 0u32;
    let mut bit = 1u32 << 30;
    while bit > n {
        bit >>= 2;
    }
    while bit != 0 {
        if rem >= root + bit {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    root
}

/// `floor(sqrt(n))`: [`sqrt_above`]'s bound (within `1 + 2⁻¹⁴` of the root, or 1 above it,
/// found in words) improved by one integer Newton step, one division of 64 by 32 bits, which
/// stays at or above the root's floor and leaves it at most a few units above (the step's
/// error is the bound's squared over twice the root: below 2⁻²⁸ of the root, plus one), then
/// stepped down by squares. On 32-bit cores a 64-bit step takes several instructions: this
/// is a fraction of the work of finding the root's 32 bits one at a time. Out of line: its
/// callers share one copy.
#[inline(never)]
pub(crate) const fn isqrt_u64(n: u64) -> u64 {
    // From (2³² − 1)² on, the root's floor is 2³² − 1 (and a word quotient below could
    // overflow).
    if n >= (u32::MAX as u64) * (u32::MAX as u64) {
        return u32::MAX as u64;
    }
    // At or above √n, and below 2³² (√n < 2³² − 1 here): n / r ≤ √n is below 2³² too.
    let above = sqrt_above(n);
    let r = if above > u32::MAX as u64 {
        u32::MAX
    } else {
        above as u32
    };
    let mut r = ((r as u64 + div_u64_u32(n, r) as u64) / 2) as u32;
    while mul_wide_u32(r, r) > n {
        r -= 1;
    }
    r as u64
}

/// `⌈√n⌉` for `n < 2⁶⁴ − 2³³` (three squared i32 magnitudes are below 3·2⁶²), which fits 32
/// bits.
pub(crate) const fn isqrt_ceil(n: u64) -> u32 {
    let r = isqrt_u64(n);
    (if r * r < n { r + 1 } else { r }) as u32
}

/// An upper bound on `√n`, within a factor `1 + 2⁻¹⁴` of it (or 1 above it), found in 32-bit
/// words: `n`'s top bits below 2³¹ (an even shift `2k`), rounded up, their root rounded up, times
/// 2^k. Where a bound serves, it spares the Newton step and the squares [`isqrt_u64`] takes
/// from it.
pub(crate) const fn sqrt_above(n: u64) -> u64 {
    let bits = 64 - leading_zeros64(n);
    let k = bits.saturating_sub(31).div_ceil(2);
    // At least n / 2^2k, at most 2³¹.
    let top = (n >> (2 * k)) as u32 + 1;
    let root = word_root(top);
    // ⌈√top⌉ · 2^k ≥ √n.
    let root = if root * root < top { root + 1 } else { root };
    (root as u64) << k
}

/// `RSQRT[i] = 2³³ / sqrt(i)`: `1/sqrt(m)` at `m = i·2²⁴`, the knots of [`rsqrt_q45`]'s linear
/// seed for `m` in `[2²⁸, 2³⁰)`, from 16 to 64.
const RSQRT: [u32; 65] = {
    let mut t = [0u32; 65];
    let mut i = 0;
    while i < 65 {
        // 2³³ / sqrt(k) = sqrt(2⁶⁶ / k)
        let k = if i < 16 { 16 } else { i as u64 };
        t[i] = isqrt_u64(((1u128 << 66) / k as u128) as u64) as u32;
        i += 1;
    }
    t
};

/// `2⁴⁵ / sqrt(m)` for `m` in `[2²⁸, 2³⁰)`, rounded up: at or above the root, by less than
/// six units (checked for every `m` of the range once; the tests check a sample and the worst
/// ones). A seed interpolated between two knots of a table and one Newton step with its
/// second-order term, multiplications only (no division, no loop). Never below, a face facing
/// a light exactly gets its whole colour where the light's direction is exact.
pub(crate) fn rsqrt_q45(m: u32) -> u32 {
    // In [16, 64) for m in the range; masked, a table index for any m, and so is the next
    // (no bounds check).
    let idx = (m >> 24) as usize & 63;
    let (above, below) = (RSQRT[idx], RSQRT[idx + 1]);
    // The chord between the knots, at m's next 12 bits: within 3.6·10⁻⁴ above 2⁴⁵ / sqrt(m)
    // (the chord of a convex function lies above it, here by at most h²·3/(32·m²) of it, with
    // h = 2²⁴ and m ≥ 2²⁸). The knots' difference is below 2²⁶ and the table falls: a seventh
    // of its bits times the fraction's twelve fits a word.
    let fraction = (m >> 12) & 0xFFF;
    let y = above.wrapping_sub((above.wrapping_sub(below) >> 7).wrapping_mul(fraction) >> 5);
    // With e = m·y² − 1 (`d` in Q2.30, below 2²⁰), 1 / sqrt(m) = y·(1 − e/2 + 3e²/8 − …): the
    // factor in Q1.31 is 3·2³⁰ − m·y² (Newton's step) plus 3d²/2³² (`ds` is d / 2⁵, its square
    // below 2³⁰), and leaves an error of about e³/3 (below 10⁻¹⁰), where Newton's step alone
    // leaves 3e²/2. Every factor fits 32 bits (y ≤ 2³¹, m·y² / 2⁶⁰ near 1): 32x32→64 products,
    // one widening multiply each on Cortex-M3/M4. The floors lose less than two units; 4 more
    // in the factor (y·4 / 2³¹, two to four units, in the constant: no instruction) leave the
    // result at or above the root.
    let t = (mul_wide_u32(m, square_shr31(y)) >> 29) as u32;
    let ds = (t.wrapping_sub(1 << 30) as i32) >> 5;
    let second = (ds.wrapping_mul(ds) as u32).wrapping_mul(3) >> 22;
    let factor = ((3u32 << 30) + 4).wrapping_sub(t).wrapping_add(second);
    (mul_wide_u32(y, factor) >> 31) as u32
}

/// `⌊y² / 2³¹⌋` modulo 2³²: on cores without a long multiply from three 32-bit products of
/// y's halves in words (the square's two middle products are one), where the 64-bit square
/// is a routine of four; elsewhere the widening multiply.
#[inline(always)]
fn square_shr31(y: u32) -> u32 {
    (mul_wide_u32(y, y) >> 31) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The root rounded up: at or above `2⁴⁵ / sqrt(m)` by less than six units, over a
    /// sample of the range, every knot and the ends of its buckets, and the two `m` where a
    /// check of the whole range found the result nearest the root and farthest above it.
    #[test]
    fn rsqrt_is_the_root_rounded_up_within_six_units() {
        let knots = (16u32..64).flat_map(|i| [i << 24, (i << 24) + (1 << 23), (i << 24) - 1]);
        let sample = ((1u32 << 28)..(1 << 30)).step_by(4_099);
        let worst = [615_050_597, 268_444_031, 1 << 28, (1 << 30) - 1];
        for m in knots.filter(|&m| m >= 1 << 28).chain(sample).chain(worst) {
            let y = rsqrt_q45(m) as u128;
            // y ≥ 2⁴⁵ / sqrt(m) ⇔ y²·m ≥ 2⁹⁰, and y − 6 below it.
            assert!(y * y * m as u128 >= 1 << 90, "{m}: below");
            assert!((y - 6) * (y - 6) * (m as u128) < 1 << 90, "{m}: six above");
        }
    }

    /// The 32-bit factors lose nothing: the same steps in 64-bit arithmetic give the same
    /// values over the whole input range.
    #[test]
    fn rsqrt_32_bit_factors_are_exact() {
        let wide = |m: u64| {
            let i = (m >> 24) as usize;
            let (above, below) = (RSQRT[i] as u64, RSQRT[i + 1] as u64);
            let y = above - ((((above - below) >> 7) * ((m >> 12) & 0xFFF)) >> 5);
            let t = (m * ((y * y) >> 31)) >> 29;
            let d = t as i64 - (1 << 30);
            let factor = (3i64 << 30) + 4 - t as i64 + ((3 * (d >> 5) * (d >> 5)) >> 22);
            (y * factor as u64) >> 31
        };
        for m in ((1u32 << 28)..(1 << 30))
            .step_by(997)
            .chain([(1 << 30) - 1])
        {
            assert_eq!(rsqrt_q45(m) as u64, wide(m as u64), "{m}");
        }
    }

    #[test]
    fn sqrt_above_bounds_the_root_closely() {
        let mut rng = crate::testing::XorShift(0x94D0_49BB_1331_11EBu64);
        let ends = [
            0u64,
            1,
            2,
            3,
            4,
            (1 << 31) - 1,
            1 << 31,
            (1 << 32) - 1,
            u64::MAX,
        ];
        let random = (0..100_000).map(|_| {
            let x = rng.next_u64();
            x >> (x % 64)
        });
        for n in ends.into_iter().chain(random) {
            let r = sqrt_above(n) as u128;
            assert!(r * r >= n as u128, "{n}");
            let exact = isqrt_u64(n) as u128;
            assert!(r <= exact + 1 + exact / (1 << 14), "{n} {r} {exact}");
        }
    }

    #[test]
    fn isqrt_is_exact_floor() {
        for n in (0u64..20_000).chain([u64::MAX, u64::MAX - 1, 1 << 62, (1 << 62) - 1]) {
            let r = isqrt_u64(n) as u128;
            assert!(
                r * r <= n as u128 && (r + 1) * (r + 1) > n as u128,
                "n = {n}"
            );
        }
        let floor_root = |n: u64| {
            let r = isqrt_u64(n) as u128;
            assert!(
                r * r <= n as u128 && (r + 1) * (r + 1) > n as u128,
                "n = {n}"
            );
        };
        // Both sides of every square (where a root from above must stop), at every magnitude,
        // up to the largest.
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        for _ in 0..200_000 {
            let x = rng.next_u64();
            floor_root(x);
            floor_root(x >> (x % 64));
            let k = (x >> 32) >> (x % 32);
            for n in [k * k, (k * k).wrapping_sub(1), k * k + 1, k * k + 2 * k] {
                floor_root(n);
            }
        }
        let most = u32::MAX as u64;
        for n in [
            most * most - 1,
            most * most,
            most * most + 1,
            (most - 1) * (most - 1),
        ] {
            floor_root(n);
        }
    }
}

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
/// Saturates instead of overflowing (only `i64::MIN` is affected).
pub(crate) const fn shr_round(v: i64, s: u32) -> i64 {
    if s == 0 {
        return v;
    }
    let half = 1i64 << (s - 1);
    if v >= 0 {
        v.saturating_add(half) >> s
    } else {
        -(v.saturating_neg().saturating_add(half) >> s)
    }
}

/// `n / d` rounded to nearest with ties away from zero; `d` must be positive (a non-positive
/// `d` returns 0). Never overflows.
pub(crate) const fn div_round(n: i64, d: i64) -> i64 {
    if d <= 0 {
        return 0;
    }
    let half = d / 2;
    // Where 64-bit division is a long library routine (32-bit cores), the same quotient by a
    // 32-bit division when the operands fit: most divisions of the pipeline.
    if cfg!(target_pointer_width = "32") {
        if let Some(q) = div_round_u32(n, d) {
            return q;
        }
    }
    if n >= 0 {
        n.saturating_add(half) / d
    } else {
        -(n.saturating_neg().saturating_add(half) / d)
    }
}

/// Significant bits of the largest magnitude among `values` (0 when all are zero): the shift
/// that renormalises a vector or matrix of any scale is taken from it.
pub(crate) fn magnitude_bits(values: &[i64]) -> u32 {
    let max = values.iter().map(|v| v.unsigned_abs()).max().unwrap_or(0);
    64 - max.leading_zeros()
}

/// [`div_round`] by a 32-bit division, when `|n| + d/2` and `d > 0` fit 32 bits.
const fn div_round_u32(n: i64, d: i64) -> Option<i64> {
    let a = n.unsigned_abs().saturating_add((d / 2) as u64);
    if d <= 0 || a > u32::MAX as u64 || d > u32::MAX as i64 {
        return None;
    }
    let q = (a as u32 / d as u32) as i64;
    Some(if n >= 0 { q } else { -q })
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
/// (SMULL) on Cortex-M3/M4 instead of a full 64-bit product.
#[inline(always)]
pub(crate) const fn mul_wide(a: i32, b: i32) -> i64 {
    a as i64 * b as i64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 32-bit division path gives the 64-bit path's quotient wherever it applies.
    #[test]
    fn div_round_32_bit_path_is_exact() {
        let mut x = 0x9E37_79B9_7F4A_7C15u64;
        let mut checked = 0;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
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

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
    if n >= 0 {
        n.saturating_add(half) / d
    } else {
        -(n.saturating_neg().saturating_add(half) / d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

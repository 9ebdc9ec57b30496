//! Binary angles: a full turn is 2³², so adding angles wraps exactly and a spinning object or a
//! camera turned a million times keeps its precision (case T32).

use core::ops::{Add, AddAssign, Neg, Sub, SubAssign};

use super::scalar::{shr_round, Unit, UNIT_ONE};

/// An angle as a fraction of a full turn: `2³²` units per turn (about 8.4·10⁻⁸ degrees each).
///
/// Arithmetic wraps modulo one turn, exactly. Sine and cosine come from an integer polynomial,
/// with an error below 6·10⁻⁹ (six units in the last place of Q2.30) over the whole circle, identical on every platform.
///
/// ```
/// use fixed3d::math::Angle;
/// let a = Angle::from_degrees(90);
/// assert_eq!(a.sin().to_bits(), 1 << 30);
/// assert_eq!((a + a + a + a), Angle::ZERO);
/// assert!(a.cos().to_num::<f64>().abs() < 1e-8);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Angle(u32);

const QUARTER: u32 = 1 << 30;
/// `sin(πx/2) ≈ x·(c1 + x²(c3 + x²(c5 + x²(c7 + x²·c9))))` on [0, 1], coefficients Q2.30,
/// a minimax fit (maximum error 3.4·10⁻⁹).
const SIN_COEFFS: [i64; 5] = [1_686_629_674, -693_597_877, 85_564_855, -5_016_768, 161_943];

impl Angle {
    /// Zero.
    pub const ZERO: Angle = Angle(0);
    /// A quarter turn, 90 degrees.
    pub const QUARTER_TURN: Angle = Angle(QUARTER);
    /// A half turn, 180 degrees.
    pub const HALF_TURN: Angle = Angle(1 << 31);

    /// From raw units (`2³²` per turn).
    #[must_use]
    pub const fn from_bits(bits: u32) -> Self {
        Angle(bits)
    }

    /// Raw units (`2³²` per turn).
    #[must_use]
    pub const fn to_bits(self) -> u32 {
        self.0
    }

    /// Whole degrees, any value (wrapped into one turn).
    ///
    /// ```
    /// use fixed3d::math::Angle;
    /// assert_eq!(Angle::from_degrees(-90), Angle::from_degrees(270));
    /// ```
    #[must_use]
    pub const fn from_degrees(degrees: i32) -> Self {
        let d = degrees.rem_euclid(360) as u64;
        Angle(((d << 32) / 360) as u32)
    }

    /// Degrees given as a float (built once per frame, never in the pipeline). A non-finite
    /// value gives [`Angle::ZERO`]; any finite value is wrapped into one turn.
    ///
    /// ```
    /// use fixed3d::math::Angle;
    /// assert_eq!(Angle::from_degrees_f32(45.0), Angle::from_degrees(45));
    /// assert_eq!(Angle::from_degrees_f32(f32::NAN), Angle::ZERO);
    /// ```
    #[must_use]
    pub fn from_degrees_f32(degrees: f32) -> Self {
        Self::from_turns_f32(degrees / 360.0)
    }

    /// Radians given as a float; a non-finite value gives [`Angle::ZERO`].
    #[must_use]
    pub fn from_radians_f32(radians: f32) -> Self {
        Self::from_turns_f32(radians / core::f32::consts::TAU)
    }

    fn from_turns_f32(turns: f32) -> Self {
        if !turns.is_finite() {
            return Angle::ZERO;
        }
        // Keep the fractional turn only; exact for every finite f32 (from 2²⁴ up an f32 has
        // no fraction bits).
        let frac = if turns.abs() >= 16_777_216.0 {
            0.0
        } else {
            turns - (turns as i32) as f32
        };
        let bits = (frac as f64 * 4_294_967_296.0) as i64;
        Angle(bits as u32)
    }

    /// Degrees as a float, in [0, 360) (for display and tests).
    #[must_use]
    pub fn to_degrees_f32(self) -> f32 {
        (self.0 as f64 * (360.0 / 4_294_967_296.0)) as f32
    }

    /// The sine as a [`Unit`] (Q2.30).
    #[must_use]
    pub const fn sin(self) -> Unit {
        Unit::from_bits(self.sin_bits())
    }

    /// The cosine as a [`Unit`] (Q2.30).
    #[must_use]
    pub const fn cos(self) -> Unit {
        Unit::from_bits(self.cos_bits())
    }

    /// Sine, raw Q2.30.
    pub(crate) const fn sin_bits(self) -> i32 {
        let quadrant = self.0 >> 30;
        let x = (self.0 & (QUARTER - 1)) as i64;
        let v = match quadrant {
            0 => quarter_sine(x),
            1 => quarter_sine(QUARTER as i64 - x),
            2 => -quarter_sine(x),
            _ => -quarter_sine(QUARTER as i64 - x),
        };
        v as i32
    }

    /// Cosine, raw Q2.30.
    pub(crate) const fn cos_bits(self) -> i32 {
        Angle(self.0.wrapping_add(QUARTER)).sin_bits()
    }

    /// Wrapping addition (the same as `+`), usable in constants.
    #[must_use]
    pub const fn wrapping_add(self, other: Angle) -> Angle {
        Angle(self.0.wrapping_add(other.0))
    }

    /// This angle times `n`, wrapped into one turn (exact).
    #[must_use]
    pub const fn wrapping_mul(self, n: u32) -> Angle {
        Angle(self.0.wrapping_mul(n))
    }

    /// `self * num / den`, for dividing a turn into `den` steps; `den == 0` gives zero.
    #[must_use]
    pub const fn turn_fraction(num: u32, den: u32) -> Angle {
        if den == 0 {
            return Angle::ZERO;
        }
        Angle((((num % den) as u64) << 32).wrapping_div(den as u64) as u32)
    }
}

/// `sin(π/2 · x)` for `x` in [0, 2³⁰] (Q2.30), result Q2.30 clamped to [0, 1].
const fn quarter_sine(x: i64) -> i64 {
    let x2 = shr_round(x * x, 30);
    let mut acc = SIN_COEFFS[4];
    acc = SIN_COEFFS[3] + shr_round(acc * x2, 30);
    acc = SIN_COEFFS[2] + shr_round(acc * x2, 30);
    acc = SIN_COEFFS[1] + shr_round(acc * x2, 30);
    acc = SIN_COEFFS[0] + shr_round(acc * x2, 30);
    let s = shr_round(acc * x, 30);
    if s < 0 {
        0
    } else if s > UNIT_ONE as i64 {
        UNIT_ONE as i64
    } else {
        s
    }
}

impl Add for Angle {
    type Output = Angle;
    fn add(self, rhs: Angle) -> Angle {
        self.wrapping_add(rhs)
    }
}

impl Sub for Angle {
    type Output = Angle;
    fn sub(self, rhs: Angle) -> Angle {
        Angle(self.0.wrapping_sub(rhs.0))
    }
}

impl Neg for Angle {
    type Output = Angle;
    fn neg(self) -> Angle {
        Angle(self.0.wrapping_neg())
    }
}

impl AddAssign for Angle {
    fn add_assign(&mut self, rhs: Angle) {
        *self = *self + rhs;
    }
}

impl SubAssign for Angle {
    fn sub_assign(&mut self, rhs: Angle) {
        *self = *self - rhs;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate std;

    /// M9: sine and cosine over the whole circle, including the quadrant seams.
    #[test]
    fn m9_sin_cos_error_over_whole_circle() {
        let mut worst = 0f64;
        let mut bits = 0u32;
        loop {
            for probe in [bits, bits.wrapping_add(1), bits.wrapping_sub(1)] {
                let a = Angle::from_bits(probe);
                let t = probe as f64 / 4_294_967_296.0 * core::f64::consts::TAU;
                let es = (a.sin_bits() as f64 / (1u64 << 30) as f64 - t.sin()).abs();
                let ec = (a.cos_bits() as f64 / (1u64 << 30) as f64 - t.cos()).abs();
                worst = worst.max(es).max(ec);
            }
            match bits.checked_add(0x0001_0001) {
                Some(b) => bits = b,
                None => break,
            }
        }
        assert!(worst < 6e-9, "worst sin/cos error {worst}");
    }

    #[test]
    fn exact_quadrants() {
        assert_eq!(Angle::ZERO.sin_bits(), 0);
        assert_eq!(Angle::ZERO.cos_bits(), 1 << 30);
        assert_eq!(Angle::HALF_TURN.sin_bits(), 0);
        assert_eq!(Angle::HALF_TURN.cos_bits(), -(1 << 30));
        assert_eq!(Angle::from_degrees(270).sin_bits(), -(1 << 30));
    }

    #[test]
    fn float_constructors_wrap_and_reject_non_finite() {
        assert_eq!(Angle::from_degrees_f32(f32::INFINITY), Angle::ZERO);
        assert_eq!(Angle::from_radians_f32(f32::NEG_INFINITY), Angle::ZERO);
        assert_eq!(
            Angle::from_degrees_f32(720.0 + 90.0),
            Angle::from_degrees(90)
        );
        assert_eq!(Angle::from_degrees_f32(-90.0), Angle::from_degrees(270));
        let big = Angle::from_degrees_f32(3.0e38);
        let _ = big.sin();
    }
}

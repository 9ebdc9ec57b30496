//! Numbers as a user hands them in: whole numbers, floats or [`Scalar`]s, turned into the
//! crate's fixed point once, where a value enters (a camera, a light, a model's placement),
//! never in the pipeline.

use super::{Angle, Scalar, Vec3};

/// A number the high-level API accepts: `i32`, `f32`, `f64` or [`Scalar`]. The conversion
/// saturates to the [`Scalar`] range (±32768) and turns a non-finite float into 0; it never
/// panics. Firmware that wants no float code at all passes whole numbers or [`Scalar`]s.
///
/// ```
/// use fixed3d::math::{Number, Scalar};
/// assert_eq!(2.to_scalar(), Scalar::from_num(2));
/// assert_eq!(0.5.to_scalar(), Scalar::from_num(0.5));
/// assert_eq!(1e9_f32.to_scalar(), Scalar::MAX);
/// assert_eq!(f64::NAN.to_scalar(), Scalar::ZERO);
/// ```
pub trait Number: Copy {
    /// This number in Q16.16, saturated.
    fn to_scalar(self) -> Scalar;
}

impl Number for Scalar {
    fn to_scalar(self) -> Scalar {
        self
    }
}

impl Number for i32 {
    fn to_scalar(self) -> Scalar {
        Scalar::saturating_from_num(self)
    }
}

impl Number for f32 {
    fn to_scalar(self) -> Scalar {
        if self.is_nan() {
            Scalar::ZERO
        } else {
            Scalar::saturating_from_num(self)
        }
    }
}

impl Number for f64 {
    fn to_scalar(self) -> Scalar {
        if self.is_nan() {
            Scalar::ZERO
        } else {
            Scalar::saturating_from_num(self)
        }
    }
}

impl<T: Number> From<[T; 3]> for Vec3 {
    /// `[x, y, z]`, each saturated (see [`Number`]).
    ///
    /// ```
    /// use fixed3d::math::Vec3;
    /// assert_eq!(Vec3::from([0, 1, 0]), Vec3::Y);
    /// assert_eq!(Vec3::from([0.0, 0.5, 0.0]), Vec3::from_bits(0, 1 << 15, 0));
    /// ```
    fn from([x, y, z]: [T; 3]) -> Self {
        Vec3::new(x.to_scalar(), y.to_scalar(), z.to_scalar())
    }
}

impl Angle {
    /// Degrees given as any [`Number`], wrapped into one turn, rounded down to the angle's
    /// unit (as [`from_degrees`](Self::from_degrees) rounds whole degrees).
    ///
    /// ```
    /// use fixed3d::math::Angle;
    /// assert_eq!(Angle::degrees(90), Angle::QUARTER_TURN);
    /// assert_eq!(Angle::degrees(-90.0), Angle::from_degrees(270));
    /// assert_eq!(Angle::degrees(60), Angle::from_degrees(60));
    /// ```
    #[must_use]
    pub fn degrees(degrees: impl Number) -> Self {
        // Raw Q16.16 degrees times 2³² / (360 · 2¹⁶) units per degree: the remainder below
        // 360 · 2¹⁶ < 2²⁵, so the product stays below 2⁵⁷.
        let raw = i64::from(degrees.to_scalar().to_bits());
        let turn = 360i64 << 16;
        let bits = (raw.rem_euclid(turn) << 32) / turn;
        Angle::from_bits(bits as u32)
    }
}

//! Numbers the pipeline computes with: fixed-point formats named by their use, binary angles
//! with an integer sine, vectors and 4x4 matrices, and the divisions (rounded, and several by
//! one divisor) that every stage shares.
//!
//! This module is the only place that names the `fixed` crate's types; the rest of the crate uses
//! the aliases below. Every operation saturates instead of wrapping and never panics; where a
//! function rounds, its documentation says how.

mod angle;
mod divide;
mod face;
mod matrix;
mod methods;
mod number;
mod scalar;
mod sqrt;
mod vector;

pub use angle::Angle;
pub use matrix::Mat4;
pub(crate) use matrix::{is_scaled_rotation, product3};
pub(crate) use methods::NewtonDirection;
pub use methods::{Normalize, Trig};
pub use number::Number;
pub use scalar::{Scalar, Unit, SUBPIXEL_BITS, SUBPIXEL_SCALE};
pub use vector::Vec3;

pub(crate) use scalar::{
    below_bits, leading_zeros64, magnitude_bits, map3, mul_short, mul_short_u32, mul_shr30_short,
    mul_wide, mul_wide_u32, short_sides_cross, shr_low_word, shr_round, DEPTH_ONE, NARROW_CORE,
    UNIT_ONE,
};

pub(crate) use divide::{
    div_floor, div_round, div_round_word, fraction_in_words, reciprocal16, DivideBy, ShortQuotients,
};
#[cfg(test)]
pub(crate) use face::shrink_below;
pub(crate) use face::{apply, face_direction, face_newton_direction, shrink};
pub(crate) use sqrt::{isqrt_ceil, isqrt_u64, sqrt_above};
#[cfg(test)]
pub(crate) use vector::dot_wide;
pub(crate) use vector::{
    cosine_unit, cross_in_words, cross_wide, dot_is_positive, normalize, unit_and_length,
};

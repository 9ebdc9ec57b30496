//! Three-component vectors in model, world or view space.

use core::ops::{Add, Neg, Sub};

use super::scalar::{magnitude_bits, mul_wide, mul_wide_u32, shr_round, Scalar, UNIT_ONE};
use super::sqrt::isqrt_u64;

/// A point or direction with [`Scalar`] (Q16.16) components.
///
/// `+`, `-` and negation saturate at the ends of the Q16.16 range instead of wrapping.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// let v = Vec3::from_int(1, 2, 3) + Vec3::Y;
/// assert_eq!(v, Vec3::from_int(1, 3, 3));
/// assert_eq!(Vec3::X.cross(Vec3::Y), Vec3::Z);
/// assert_eq!(v.dot(Vec3::X), Scalar::from_num(1));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(C)]
pub struct Vec3 {
    /// X component.
    pub x: Scalar,
    /// Y component.
    pub y: Scalar,
    /// Z component.
    pub z: Scalar,
}

impl Vec3 {
    /// (0, 0, 0).
    pub const ZERO: Vec3 = Vec3::from_bits(0, 0, 0);
    /// (1, 0, 0).
    pub const X: Vec3 = Vec3::from_int(1, 0, 0);
    /// (0, 1, 0), "up" in world space.
    pub const Y: Vec3 = Vec3::from_int(0, 1, 0);
    /// (0, 0, 1).
    pub const Z: Vec3 = Vec3::from_int(0, 0, 1);

    /// From three [`Scalar`]s.
    #[must_use]
    pub const fn new(x: Scalar, y: Scalar, z: Scalar) -> Self {
        Vec3 { x, y, z }
    }

    /// From raw Q16.16 values.
    #[must_use]
    pub const fn from_bits(x: i32, y: i32, z: i32) -> Self {
        Vec3::new(
            Scalar::from_bits(x),
            Scalar::from_bits(y),
            Scalar::from_bits(z),
        )
    }

    /// From whole numbers in [−32768, 32767].
    #[must_use]
    pub const fn from_int(x: i16, y: i16, z: i16) -> Self {
        Vec3::from_bits((x as i32) << 16, (y as i32) << 16, (z as i32) << 16)
    }

    /// From floats, rounded to nearest; `None` if a component is not finite or is outside the
    /// Q16.16 range.
    ///
    /// ```
    /// use fixed3d::math::Vec3;
    /// assert!(Vec3::from_f32(0.5, -2.25, 1e-3).is_some());
    /// assert!(Vec3::from_f32(f32::NAN, 0.0, 0.0).is_none());
    /// assert!(Vec3::from_f32(40_000.0, 0.0, 0.0).is_none());
    /// ```
    #[must_use]
    pub fn from_f32(x: f32, y: f32, z: f32) -> Option<Self> {
        Some(Vec3::new(
            scalar_from_f32(x)?,
            scalar_from_f32(y)?,
            scalar_from_f32(z)?,
        ))
    }

    /// Raw Q16.16 components.
    #[must_use]
    pub const fn to_bits(self) -> [i32; 3] {
        [self.x.to_bits(), self.y.to_bits(), self.z.to_bits()]
    }

    /// Dot product, saturated to the [`Scalar`] range and rounded to nearest.
    #[must_use]
    pub fn dot(self, o: Vec3) -> Scalar {
        let [a, b, c] = self.to_bits().map(i64::from);
        let [d, e, f] = o.to_bits().map(i64::from);
        saturate(shr_round(a * d + b * e + c * f, 16))
    }

    /// Cross product, saturated to the [`Scalar`] range and rounded to nearest.
    #[must_use]
    pub fn cross(self, o: Vec3) -> Vec3 {
        let w = cross_wide(self.to_bits(), o.to_bits());
        Vec3::new(
            saturate(shr_round(w[0], 16)),
            saturate(shr_round(w[1], 16)),
            saturate(shr_round(w[2], 16)),
        )
    }

    /// Euclidean length (integer square root, rounded down, saturated).
    #[must_use]
    pub fn length(self) -> Scalar {
        let [a, b, c] = self.to_bits().map(|v| i64::from(v).unsigned_abs());
        let sum = (a * a) as u128 + (b * b) as u128 + (c * c) as u128;
        // sum < 3·2⁶² fits u64.
        saturate(isqrt_u64(sum as u64) as i64)
    }

    /// The unit vector in the same direction, `None` for the zero vector.
    ///
    /// ```
    /// use fixed3d::math::{Scalar, Vec3};
    /// let n = Vec3::from_int(0, 3, 4).normalized().unwrap();
    /// assert_eq!(n, Vec3::new(Scalar::ZERO, Scalar::from_num(0.6), Scalar::from_num(0.8)));
    /// assert!(Vec3::ZERO.normalized().is_none());
    /// ```
    #[must_use]
    pub fn normalized(self) -> Option<Vec3> {
        let u = normalize(self.to_bits().map(i64::from))?;
        Some(Vec3::from_bits(
            shr_round(u[0] as i64, 14) as i32,
            shr_round(u[1] as i64, 14) as i32,
            shr_round(u[2] as i64, 14) as i32,
        ))
    }
}

fn scalar_from_f32(v: f32) -> Option<Scalar> {
    // `checked_from_num` is the only total conversion: NaN and infinities give None.
    Scalar::checked_from_num(v)
}

/// Saturates a raw i64 Q16.16 value into a [`Scalar`].
pub(crate) fn saturate(v: i64) -> Scalar {
    Scalar::from_bits(v.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
}

/// Exact cross product of raw vectors whose components fit in i32 (each term < 2⁶³).
#[inline(never)]
pub(crate) fn cross_wide(a: [i32; 3], b: [i32; 3]) -> [i64; 3] {
    let ([a0, a1, a2], [b0, b1, b2]) = (a, b);
    // Products of i32 factors lie in [−2⁶² + 2³¹, 2⁶²], so a difference of two lies within
    // ±(2⁶³ − 2³¹): no overflow, and no clamp.
    [
        mul_wide(a1, b2).wrapping_sub(mul_wide(a2, b1)),
        mul_wide(a2, b0).wrapping_sub(mul_wide(a0, b2)),
        mul_wide(a0, b1).wrapping_sub(mul_wide(a1, b0)),
    ]
}

/// [`cross_wide`] in 32-bit words, for vectors the caller knows to have their six components
/// in [−2¹⁵, 2¹⁵): every product lies within ±2³⁰ and every difference of two within ±2³¹, so
/// each component is exact in an i32 (for other vectors a wrapped value, never an overflow).
#[inline(always)]
pub(crate) fn cross_in_words(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    let ([a0, a1, a2], [b0, b1, b2]) = (a, b);
    let c = |p: i32, q: i32, r: i32, s: i32| p.wrapping_mul(q).wrapping_sub(r.wrapping_mul(s));
    [c(a1, b2, a2, b1), c(a2, b0, a0, b2), c(a0, b1, a1, b0)]
}

/// Unit vector (Q2.30) of any non-zero integer vector, whatever its scale: the components are
/// first shifted so that the largest has its top bit at 2³⁰ (the leading-zero renormalisation
/// of case T33), then divided by the integer square root of the sum of squares. `None` for zero.
pub(crate) fn normalize(v: [i64; 3]) -> Option<[i32; 3]> {
    unit_and_length(v).map(|(unit, _)| unit)
}

/// [`normalize`]'s unit vector and the vector's length in its own units (found from the
/// shifted components: within about 2^(shift) of the exact length; saturated at `u64::MAX`).
/// In line, so that [`normalize`] carries no code for the length.
#[inline(always)]
pub(crate) fn unit_and_length(v: [i64; 3]) -> Option<([i32; 3], u64)> {
    let bits = magnitude_bits(&v) as i32;
    if bits == 0 {
        return None;
    }
    let shift = bits - 31; // bring the largest to [2^30, 2^31)
    let scaled = v.map(|c| {
        if shift > 0 {
            // Rounding shift, away from zero.
            shr_round(c, shift as u32)
        } else {
            // Below 2³¹ in magnitude before and after: a word shift.
            i64::from((c as i32) << (-shift) as u32)
        }
    });
    let sum: u64 = scaled
        .iter()
        .map(|c| {
            // At most 2³¹: a word.
            let a = c.unsigned_abs() as u32;
            mul_wide_u32(a, a)
        })
        .sum(); // each < 2^62 (after rounding at most 2^31 → 2^62), three sum below 2^64
    let len = isqrt_u64(sum); // in [2^30, 2^31·√3)
    if len == 0 {
        return None;
    }
    // One divisor for the three components (below 2³²: prepared once where that is faster).
    let by = super::DivideBy::new(len as i64);
    let unit = scaled.map(|c| {
        let q = by.round(c << 30);
        q.clamp(-(UNIT_ONE as i64), UNIT_ONE as i64) as i32
    });
    let length = if shift > 0 {
        len.saturating_mul(1 << shift)
    } else {
        len >> (-shift) as u32
    };
    Some((unit, length))
}

/// `a·b` exactly, for components whose products sum within ±2⁶³ (written out: at
/// `opt-level = "s"` an iterator's sum stays a loop).
#[inline(always)]
pub(crate) fn dot_wide(a: [i32; 3], b: [i32; 3]) -> i64 {
    let ([a0, a1, a2], [b0, b1, b2]) = (a, b);
    mul_wide(a0, b0)
        .wrapping_add(mul_wide(a1, b1))
        .wrapping_add(mul_wide(a2, b2))
}

/// `a·b > 0` for a face direction `a` (any i32 components but `i32::MIN`) and a light's unit
/// direction `b` (Q2.30, components within ±2³⁰). Products below 2⁶¹, three sum
/// below 2⁶³: the exact sum fits i64.
#[inline(always)]
pub(crate) fn dot_is_positive(a: [i32; 3], b: [i32; 3]) -> bool {
    dot_wide(a, b) > 0
}

/// `max(0, a·b)` of two Q2.30 unit vectors, Q2.30, the dot product rounded to nearest: Lambert's
/// cosine. Only positive sums need rounding (a sum at or below zero gives zero either way), so
/// one addition and a shift do it, without a sign test.
#[inline]
pub(crate) fn cosine_unit(a: [i32; 3], b: [i32; 3]) -> i32 {
    // Components within ±2³⁰: products within ±2⁶⁰, three sum within ±2⁶².
    let s = dot_wide(a, b);
    ((s + (1 << 29)) >> 30).clamp(0, 2 * UNIT_ONE as i64 - 1) as i32
}

impl Add for Vec3 {
    type Output = Vec3;
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_add(o.x),
            self.y.saturating_add(o.y),
            self.z.saturating_add(o.z),
        )
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    fn sub(self, o: Vec3) -> Vec3 {
        Vec3::new(
            self.x.saturating_sub(o.x),
            self.y.saturating_sub(o.y),
            self.z.saturating_sub(o.z),
        )
    }
}

impl Neg for Vec3 {
    type Output = Vec3;
    fn neg(self) -> Vec3 {
        Vec3::new(
            self.x.saturating_neg(),
            self.y.saturating_neg(),
            self.z.saturating_neg(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cross product is exact for every i32 component, the ends of the range included
    /// (where each difference comes within 2³¹ of overflowing).
    #[test]
    fn cross_wide_is_exact_at_the_ends() {
        let ends = [i32::MIN, i32::MAX, 0, 1, -1];
        let end = |k: usize| ends[k % ends.len()];
        for k in 0..5usize.pow(6) {
            let a = [end(k), end(k / 5), end(k / 25)];
            let b = [end(k / 125), end(k / 625), end(k / 3125)];
            let w = |x: i32, y: i32| x as i128 * y as i128;
            let exact = [
                w(a[1], b[2]) - w(a[2], b[1]),
                w(a[2], b[0]) - w(a[0], b[2]),
                w(a[0], b[1]) - w(a[1], b[0]),
            ];
            assert_eq!(cross_wide(a, b).map(i128::from), exact, "{a:?} {b:?}");
        }
    }

    /// The cosine of two unit vectors is the rounded dot product's positive part, at every
    /// sign and at the rounding boundaries.
    #[test]
    fn cosine_unit_is_the_positive_part_of_the_rounded_dot() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let one = UNIT_ONE;
        let edges = [0, 1, -1, 1 << 29, -(1 << 29), (1 << 29) - 1, one, -one];
        for i in 0..100_000usize {
            let mut pick = |k: usize| match edges.get((i + k) % 64) {
                Some(&e) => e,
                None => rng.within(one),
            };
            let (a, b) = ([pick(0), pick(1), pick(2)], [one, pick(3), pick(5)]);
            let s: i64 = (0..3).map(|k| a[k] as i64 * b[k] as i64).sum();
            let rounded = shr_round(s, 30).clamp(-(2 * one as i64), 2 * one as i64 - 1);
            assert_eq!(cosine_unit(a, b) as i64, rounded.max(0), "{a:?} {b:?}");
        }
    }

    #[test]
    fn fast_normalize_agrees() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..20_000 {
            let x = rng.next_u64();
            let scale = (x >> 58) as u32;
            let v = [
                (x as i16) as i64,
                ((x >> 16) as i16) as i64,
                ((x >> 32) as i16) as i64,
            ]
            .map(|c| c << scale);
            match (normalize(v), crate::math::Normalize::Newton.unit(v)) {
                (Some(a), Some(b)) => {
                    for (p, q) in a.iter().zip(b) {
                        assert!((p - q).abs() <= 4 << 10, "{v:?}: {a:?} {b:?}");
                    }
                }
                (a, b) => assert_eq!(a.is_none(), b.is_none()),
            }
        }
    }

    #[test]
    fn normalize_any_scale() {
        for scale in [1i64, 7, 1 << 20, 1 << 40, (1 << 62) - 1] {
            let u = normalize([scale, 0, 0]).unwrap();
            assert_eq!(u, [UNIT_ONE, 0, 0]);
            let u = normalize([0, -scale, scale]).unwrap();
            let expect = (0.5f64.sqrt() * (1u64 << 30) as f64).round() as i32;
            assert!((u[2] - expect).abs() <= 1 && u[1] == -u[2]);
        }
        assert!(normalize([0, 0, 0]).is_none());
        let u = normalize([i64::MIN, i64::MAX, i64::MIN]).unwrap();
        assert!(u.iter().all(|c| c.abs() <= UNIT_ONE));
    }
}

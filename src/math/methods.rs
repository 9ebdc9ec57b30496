//! The approximation methods behind two precision knobs: how sines and cosines are computed when
//! a matrix is built from an angle ([`Trig`]), and how lighting normalises normals
//! ([`Normalize`]). Each is a plain value: the default is what the crate uses everywhere, the
//! others exist so that their error and cost can be measured (`docs/accuracy.md`) and chosen.

use super::angle::Angle;
use super::scalar::{
    leading_zeros32, magnitude_bits, map3, mul_short, mul_short_u32, mul_wide_u32, shr_low_word,
    shr_round, UNIT_ONE,
};
use super::sqrt::rsqrt_q45;
use super::vector::normalize;
use super::Unit;

/// How [`Angle`]s become sines and cosines (for [`Transform::matrix_by`](crate::mesh::Transform::matrix_by)).
///
/// | method | max error | cost |
/// |---|---|---|
/// | [`Polynomial`](Trig::Polynomial) | 6·10⁻⁹ | 5 multiply-adds in i64 |
/// | [`Table`](Trig::Table) | 3.1·10⁻³ | one load (514 bytes of flash) |
/// | `Micromath` (feature `micromath`) | about 10⁻³ | f32 polynomial; float code on the target |
///
/// ```
/// use fixed3d::math::{Angle, Trig};
/// let (s, c) = Trig::Table.sin_cos(Angle::from_degrees(30));
/// assert!((s.to_num::<f64>() - 0.5).abs() < 4e-3);
/// assert!((c.to_num::<f64>() - 0.75f64.sqrt()).abs() < 4e-3);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Trig {
    /// The crate's integer polynomial (the default): bit-identical on every target.
    #[default]
    Polynomial,
    /// A 257-entry quarter-wave table of Q1.15 values, nearest entry, no interpolation: the
    /// kind of table small fixed-point renderers use.
    Table,
    /// micromath's f32 approximations (feature `micromath`).
    #[cfg(feature = "micromath")]
    Micromath,
}

/// Entries of the quarter-wave table: `sin(π/2 · i/256)` in Q1.15, from the polynomial.
const TABLE_STEPS: u32 = 256;
const SINE_TABLE: [u16; TABLE_STEPS as usize + 1] = {
    let mut t = [0u16; TABLE_STEPS as usize + 1];
    let mut i = 0;
    while i <= TABLE_STEPS {
        // An angle of i/256 of a quarter turn is i · 2²² in binary-angle units.
        let s = Angle::from_bits(i << 22).sin_bits() as i64;
        t[i as usize] = shr_round(s, 15) as u16;
        i += 1;
    }
    t
};

fn table_sine(a: Angle) -> i32 {
    let bits = a.to_bits();
    let quadrant = bits >> 30;
    // Nearest entry: 2²² binary-angle units per step.
    let step = (((bits & ((1 << 30) - 1)) + (1 << 21)) >> 22) as usize;
    let at = |i: usize| SINE_TABLE.get(i).copied().unwrap_or(0) as i32;
    let n = TABLE_STEPS as usize;
    let v = match quadrant {
        0 => at(step),
        1 => at(n.saturating_sub(step)),
        2 => -at(step),
        _ => -at(n.saturating_sub(step)),
    };
    v << 15
}

impl Trig {
    /// Sine and cosine of `a` as [`Unit`]s (Q2.30), each within [−1, 1].
    #[must_use]
    pub fn sin_cos(self, a: Angle) -> (Unit, Unit) {
        let quarter = Angle::from_bits(1 << 30);
        let (s, c) = match self {
            Trig::Polynomial => (a.sin_bits(), a.cos_bits()),
            Trig::Table => (table_sine(a), table_sine(a + quarter)),
            #[cfg(feature = "micromath")]
            Trig::Micromath => {
                // The binary angle as a signed fraction of half a turn, in radians.
                let r = a.to_bits() as i32 as f32 * (core::f32::consts::PI / 2_147_483_648.0);
                let (s, c) = micromath::F32(r).sin_cos();
                let q =
                    |v: micromath::F32| ((v.0 * UNIT_ONE as f32) as i32).clamp(-UNIT_ONE, UNIT_ONE);
                (q(s), q(c))
            }
        };
        (Unit::from_bits(s), Unit::from_bits(c))
    }

    /// Sine and cosine rounded to Q16.16, for matrices.
    pub(crate) fn sin_cos_q16(self, a: Angle) -> (i32, i32) {
        let (s, c) = self.sin_cos(a);
        let q = |v: Unit| shr_round(v.to_bits() as i64, 14) as i32;
        (q(s), q(c))
    }
}

/// How lighting turns a normal into a unit vector (per face for flat shading, per vertex for
/// Gouraud); set with [`Precision::with_normalize`](crate::pipeline::Precision::with_normalize).
///
/// | method | max relative error | cost |
/// |---|---|---|
/// | [`Newton`](Normalize::Newton) | 5·10⁻⁹ | a seed between two table entries, one Newton step with its second-order term, no division |
/// | [`Exact`](Normalize::Exact) | 2⁻³⁰ (correctly rounded) | a 32-step integer square root, 3 divisions |
/// | `Micromath` (feature `micromath`) | 3.4·10⁻² (measured) | micromath's f32 `invsqrt`: a bit trick, no Newton step |
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Normalize {
    /// Reciprocal square root from a seed between two entries of a 65-entry table and one
    /// Newton step with its second-order term, never below the root (the default). Flat
    /// shading forms no unit normal with it: each light's product with the face's direction
    /// is divided by the direction's length, one multiply by the reciprocal.
    #[default]
    Newton,
    /// Integer square root and a rounded division per component.
    Exact,
    /// micromath's f32 `invsqrt` (feature `micromath`).
    #[cfg(feature = "micromath")]
    Micromath,
}

impl Normalize {
    /// [`unit`](Self::unit) of a vector whose components fit 32 bits (a face normal): the same
    /// result, in 32-bit words where the method allows.
    pub(crate) fn unit32(self, v: [i32; 3]) -> Option<[i32; 3]> {
        match self {
            Normalize::Newton => newton_unit(shrink_to_15_bits32(v)?),
            _ => self.unit(map3(v, i64::from)),
        }
    }

    /// Unit vector (Q2.30) of a non-zero integer vector of any scale; `None` for zero.
    pub(crate) fn unit(self, v: [i64; 3]) -> Option<[i32; 3]> {
        match self {
            Normalize::Newton => normalize_newton(v),
            Normalize::Exact => normalize(v),
            #[cfg(feature = "micromath")]
            Normalize::Micromath => {
                let c = shrink_to_15_bits(v)?;
                let s = c.iter().map(|x| (x * x) as f32).sum::<f32>();
                let k = micromath::F32(s).invsqrt().0 * UNIT_ONE as f32;
                Some(c.map(|x| ((x as f32 * k) as i32).clamp(-UNIT_ONE, UNIT_ONE)))
            }
        }
    }
}

/// A direction prepared for [`Normalize::Newton`] cosines with unit vectors (the lights'
/// directions), in place of its unit vector: the direction shifted so that its largest
/// component lies in [2¹⁴, 2¹⁵), and the reciprocal of its length. A cosine is the product
/// with the unit vector over the length: one multiply, where the unit vector takes one per
/// component (each rounded and clamped) before the product, and on cores without a long
/// multiply the products of 15-bit components take two 32-bit multiplies each where the unit
/// vector's take four. Within 3 units of 2⁻³⁰ of the unit vector's cosine.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub(crate) struct NewtonDirection {
    c: [i16; 3],
    /// `2⁴⁵ / sqrt(m)`, where `m` is the sum of the squares, quartered from 2³⁰ on.
    y: u32,
    quartered: bool,
}

impl NewtonDirection {
    /// The zero vector's (no direction: every product with it is zero).
    pub(crate) const ZERO: NewtonDirection = NewtonDirection {
        c: [0; 3],
        y: 0,
        quartered: false,
    };

    /// The direction of a vector whose components fit 32 bits; `None` for zero.
    #[inline(always)]
    pub(crate) fn new(v: [i32; 3]) -> Option<NewtonDirection> {
        let c = map3(shrink_to_15_bits32(v)?, |x| x as i32);
        let [s0, s1, s2] = map3(c, |x| x.wrapping_mul(x) as u32);
        // Squares at most 2³⁰ (a component may be −2¹⁵), their sum in [2²⁸, 3·2³⁰]: a word.
        let s = s0.wrapping_add(s1).wrapping_add(s2);
        let quartered = s >= 1 << 30;
        let y = rsqrt_q45(if quartered { s >> 2 } else { s });
        let c = map3(c, |x| x as i16);
        Some(NewtonDirection { c, y, quartered })
    }

    /// The product of the shifted direction with a unit vector `l` (Q2.30): within ±2⁴⁶, of
    /// the sign of the direction's own product with `l` wherever it lies beyond ±2³¹.
    #[inline(always)]
    pub(crate) fn dot(&self, l: [i32; 3]) -> i64 {
        let ([c0, c1, c2], [l0, l1, l2]) = (self.c, l);
        mul_short(l0, c0 as i32)
            .wrapping_add(mul_short(l1, c1 as i32))
            .wrapping_add(mul_short(l2, c2 as i32))
    }

    /// `max(0, u·l)` (Q2.30, below 2³¹) for the unit vector `u` of this direction and a unit
    /// vector `l` (Q2.30), rounded to nearest.
    #[inline(always)]
    pub(crate) fn cosine(&self, l: [i32; 3]) -> i32 {
        // Components below 2¹⁵ times a unit's: the sum t lies within ±|c|·2³⁰ (below 2⁴⁶).
        let t = self.dot(l);
        if t <= 0 {
            return 0;
        }
        // t / 2¹⁵ is below |c|·2¹⁵ < 2³¹, and y ≈ 2⁴⁵ / sqrt(m): the product is below 2⁶²,
        // and over 2³⁰ (2³¹ when quartered) it is t / |c|, the cosine in Q2.30.
        let t = ((t as u64).wrapping_add(1 << 14) >> 15) as u32;
        let p = mul_wide_u32(t, self.y);
        let cos = if self.quartered {
            p.wrapping_add(1 << 30) >> 31
        } else {
            p.wrapping_add(1 << 29) >> 30
        };
        // A cosine of unit vectors in Q2.30 (the light's within an ulp of unit length, y less
        // than 10⁻⁸ above its value): at most 2³⁰·(1 + 10⁻⁸), so the low word holds it.
        cos as u32 as i32
    }
}

/// The vector shifted so that its largest component lies in [2¹⁴, 2¹⁵); `None` for zero.
#[inline]
fn shrink_to_15_bits(v: [i64; 3]) -> Option<[i64; 3]> {
    let bits = magnitude_bits(&v);
    if bits == 0 {
        return None;
    }
    let shift = bits as i32 - 15;
    Some(map3(v, |x| {
        if shift > 0 {
            // The result is below 2¹⁵: the low word of the shift is all of it.
            shr_low_word(x, shift as u32) as i64
        } else {
            x << (-shift) as u32
        }
    }))
}

/// The vector shifted so that its largest component lies in [2¹⁴, 2¹⁵), for components
/// that fit 32 bits: [`shrink_to_15_bits`] in 32-bit words (the same values); `None` for zero.
#[inline]
fn shrink_to_15_bits32(v: [i32; 3]) -> Option<[i64; 3]> {
    let [a, b, c] = map3(v, i32::unsigned_abs);
    let max = a.max(b).max(c);
    let bits = 32 - leading_zeros32(max);
    if bits == 0 {
        return None;
    }
    let shift = bits as i32 - 15;
    Some(map3(v, |x| {
        // Right: the result is below 2¹⁵; left: below 2¹⁵ before, so below 2²⁹ after.
        if shift > 0 {
            (x >> shift) as i64
        } else {
            (x << (-shift) as u32) as i64
        }
    }))
}

/// [`Normalize::Newton`]: error below 5·10⁻⁹ (M9), no division and no loop.
#[inline]
fn normalize_newton(v: [i64; 3]) -> Option<[i32; 3]> {
    newton_unit(shrink_to_15_bits(v)?)
}

/// The unit vector of `c`, whose largest component lies in [2¹⁴, 2¹⁵).
#[inline(always)]
fn newton_unit(c: [i64; 3]) -> Option<[i32; 3]> {
    // The sum of squares lies in [2²⁸, 3·2³⁰): 32-bit squares and sum (components below 2¹⁵).
    let [s0, s1, s2] = map3(c, |x| (x as i32 * x as i32) as u32);
    let s = s0 + s1 + s2;
    let (m, quartered) = if s >= 1 << 30 {
        (s >> 2, true)
    } else {
        (s, false)
    };
    // y = 2⁴⁵ / sqrt(m); c / sqrt(s) in Q2.30 = c · y / 2¹⁵ (halved again when s was quartered;
    // shifts by constants: a 64-bit shift by a variable amount is a library call on Cortex-M0).
    let y = rsqrt_q45(m);
    Some(map3(c, |x| {
        // |x| ≤ sqrt(s) and y ≤ 2⁴⁵ / sqrt(m)·(1 + 10⁻⁶): the unit component (halved again
        // when s was quartered) lies within ±2³⁰·(1 + 10⁻⁶), so it fits a 32-bit word before
        // its clamp (one shift of the product's words, where a 64-bit clamp takes twice the
        // instructions on 32-bit cores).
        let p = mul_short_u32(x as i32, y);
        let u = if quartered { p >> 16 } else { p >> 15 } as i32;
        u.clamp(-UNIT_ONE, UNIT_ONE)
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate std;

    fn worst_trig(method: Trig) -> f64 {
        let mut worst = 0f64;
        for i in 0..(1u32 << 16) {
            let a = Angle::from_bits(i.wrapping_mul(65_537));
            let t = a.to_bits() as f64 / 4_294_967_296.0 * core::f64::consts::TAU;
            let (s, c) = method.sin_cos(a);
            worst = worst
                .max((s.to_num::<f64>() - t.sin()).abs())
                .max((c.to_num::<f64>() - t.cos()).abs());
        }
        worst
    }

    /// M9 for every trig method over the whole circle.
    #[test]
    fn m9_trig_methods() {
        assert!(worst_trig(Trig::Polynomial) < 6e-9);
        let table = worst_trig(Trig::Table);
        assert!(table < 3.2e-3 && table > 1e-3, "table {table}");
        #[cfg(feature = "micromath")]
        assert!(worst_trig(Trig::Micromath) < 2e-3);
    }

    /// The 32-bit normalisation returns what the 64-bit one returns, for every method and
    /// vectors of every scale that fits 32 bits.
    #[test]
    fn unit32_equals_unit() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let methods = [
            Normalize::Newton,
            Normalize::Exact,
            #[cfg(feature = "micromath")]
            Normalize::Micromath,
        ];
        for _ in 0..200_000 {
            let r = rng.next_u64();
            let v = [0, 21, 42].map(|k| ((r >> k) as i32) >> ((r >> (k + 16)) % 32));
            for method in methods {
                assert_eq!(method.unit32(v), method.unit(v.map(i64::from)), "{v:?}");
            }
        }
        for v in [
            [0; 3],
            [i32::MIN, i32::MAX, 0],
            [i32::MIN; 3],
            [1, 0, 0],
            [-1, -1, -1],
        ] {
            assert_eq!(
                Normalize::Newton.unit32(v),
                Normalize::Newton.unit(v.map(i64::from))
            );
        }
    }

    /// `newton_unit` shifts and clamps each component in a 32-bit word: the same values as in
    /// 64 bits, for every shrunk vector the method hands it (largest component in [2¹⁴, 2¹⁵)),
    /// sums of squares quartered (s ≥ 2³⁰) or not, and units along an axis (within 2⁻¹⁸ of
    /// 1, where the clamp to 2³⁰ would act).
    #[test]
    fn newton_unit_in_words_equals_64_bits() {
        let wide = |c: [i64; 3]| {
            let s: u32 = c.iter().map(|x| (x * x) as u32).sum();
            let (m, quartered) = if s >= 1 << 30 {
                (s >> 2, true)
            } else {
                (s, false)
            };
            let y = crate::math::sqrt::rsqrt_q45(m);
            c.map(|x| {
                let u = (x * y as i64) >> 15;
                let u = if quartered { u >> 1 } else { u };
                u.clamp(-(UNIT_ONE as i64), UNIT_ONE as i64) as i32
            })
        };
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let (mut quartered, mut clamped) = (0, 0);
        let edge = [1 << 14, (1 << 15) - 1, -(1 << 14), 1 - (1 << 15)];
        let fixed = edge.iter().flat_map(|&a| {
            [
                [a, 0, 0],
                [0, a, 0],
                [0, 0, a],
                [a, a, a],
                [a, -a, 1],
                [a, (1 << 15) - 1, 0],
            ]
        });
        let random = (0..300_000).map(|_| {
            let big = rng.within(1 << 14);
            let big = big.signum().max(1) * ((1 << 14) + big.abs());
            let mut v = [big, rng.within(big.abs() + 1), rng.within(big.abs() + 1)];
            v.rotate_left(rng.pick(&[0, 1, 2]));
            v
        });
        for v in fixed.chain(random) {
            let c = v.map(i64::from);
            let expected = wide(c);
            assert_eq!(newton_unit(c), Some(expected), "{v:?}");
            quartered += (c.iter().map(|x| x * x).sum::<i64>() >= 1 << 30) as u32;
            // Components at the top of the range, where the clamp would act.
            clamped += expected.iter().any(|u| u.abs() > UNIT_ONE - (1 << 12)) as u32;
        }
        assert!(quartered > 50_000 && clamped >= 12, "{quartered} {clamped}");
    }

    /// A cosine never reaches the clamp to i32::MAX (so 32-bit cores take its low word without
    /// one): directions along a light at every scale, and near it, give cosines within 2¹²
    /// of 2³⁰ at most, sums of squares quartered or not.
    #[test]
    fn newton_cosine_fits_a_word() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let lights = [[-1, 1, 1], [0, 0, 1], [3, -2, 7], [1, 1, 0], [-5, 1, 2]];
        let mut worst = 0;
        for l in lights {
            let Some(unit) = normalize(l.map(|c: i64| c << 40)) else {
                unreachable!()
            };
            for shift in 0..=28 {
                for k in 0..200 {
                    let mut nudge = |c: i32| c.wrapping_add(rng.within(k) << 4);
                    let v = unit.map(|c| nudge(c >> shift));
                    let Some(d) = NewtonDirection::new(v) else {
                        continue;
                    };
                    let cos = d.cosine(unit);
                    assert!(cos <= (1 << 30) + (1 << 12), "{v:?} {cos}");
                    worst = worst.max(cos);
                }
            }
        }
        assert!(worst > (1 << 30) - (1 << 12), "{worst}");
    }

    /// M9 for every normalisation method, over many scales.
    #[test]
    fn m9_normalize_methods() {
        let methods = [
            (Normalize::Newton, 5e-9),
            (Normalize::Exact, 3e-9),
            #[cfg(feature = "micromath")]
            (Normalize::Micromath, 3.5e-2),
        ];
        for (method, bound) in methods {
            let mut worst = 0f64;
            for i in 1..2000i64 {
                let v = [i * 7919 % 1013 - 506, i * 104_729 % 2017 - 1008, i - 1000];
                for shift in [0u32, 9, 20, 40] {
                    let v = v.map(|c| c << shift);
                    let Some(u) = method.unit(v) else { continue };
                    let len = v.iter().map(|c| (*c as f64).powi(2)).sum::<f64>().sqrt();
                    for (got, c) in u.iter().zip(v) {
                        let e = (*got as f64 / UNIT_ONE as f64 - c as f64 / len).abs();
                        worst = worst.max(e);
                    }
                }
            }
            assert!(worst < bound, "{method:?}: {worst}");
        }
        assert_eq!(Normalize::Exact.unit([0; 3]), None);
        assert_eq!(Normalize::Newton.unit([0; 3]), None);
    }
}

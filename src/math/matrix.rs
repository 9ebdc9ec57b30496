//! 4x4 matrices: row-major `m[row][col]`, column vectors, translation in the last column, so a
//! chain reads right to left (`clip_from_model = projection * view * model`).

use core::ops::Mul;

use super::angle::Angle;
use super::scalar::{magnitude_bits, mul_wide, shr_round, Scalar};
use super::vector::{cross_wide, saturate, Vec3};

/// A 4x4 matrix of [`Scalar`] (Q16.16) entries.
///
/// Products are computed exactly in 64 bits, rounded to nearest and saturated to the Q16.16
/// range: a chain of matrices never wraps.
///
/// ```
/// use fixed3d::math::{Angle, Mat4, Vec3};
/// let m = Mat4::translation(Vec3::from_int(1, 2, 3)) * Mat4::rotation_y(Angle::from_degrees(90));
/// // (1, 0, 0) turns to (0, 0, -1), then moves by (1, 2, 3).
/// assert_eq!(m.transform_point(Vec3::X), Vec3::from_int(1, 2, 2));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Mat4 {
    m: [[i32; 4]; 4],
}

const ONE: i32 = 1 << 16;

/// `v = h·2^k + l` with `l` in [−2^(k−1), 2^(k−1)) (its low `k` bits, signed) and `h` exact,
/// for `1 ≤ k ≤ 16`.
#[inline(always)]
const fn split(v: i32, k: u32) -> (i32, i32) {
    let l = ((v as u32) << (32 - k)) as i32 >> (32 - k);
    ((v.wrapping_sub(l)) >> k, l)
}

/// A matrix prepared for 32-bit vertex transforms (from [`Mat4::split_transform`]), for cores
/// without a long multiply, where each of [`Mat4::transform_short`]'s twelve 64-bit products is
/// four multiplies put back together. Each coordinate is split as `x = xh·2^k + xl` (`xl` its
/// low `k` bits, signed), so that a row's `Σ m·x + t·2¹⁶ + 2¹⁵` is `2^k·A + L + t·2¹⁶ + 2¹⁵`
/// with `A = Σ m·xh` and `L = Σ m·xl`, two 32-bit products a term: `k` is as large as keeps
/// `L + 2¹⁵` a word for the matrix's entries, and `Mat4::split_transform` bounds
/// `A + t·2^(16−k)` and the rounded `L` below 2³¹ for the mesh's extent. The row's floor over
/// 2¹⁶ is `(A + t·2^(16−k) + ⌊(L + 2¹⁵) / 2^k⌋) >> (16 − k)` (`2^k·A` and `t·2¹⁶` are
/// multiples of 2^k, so the fraction dropped inside cannot carry), the rounded row, exactly.
/// The two bounds pull `k` apart (the entries' sums down, the extent up): a unit-scale scene
/// meets both (the reference view at `k` = 13 or 14, by the model's rotation), a mesh more
/// than about a thousand units across at unit scale does not, and takes the general 64-bit
/// transform.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SplitTransform {
    rows: [[i32; 3]; 4],
    /// Each row's translation times 2^(16−k).
    t: [i32; 4],
    /// Where a coordinate is split, from 1 to 16.
    k: u32,
}

impl SplitTransform {
    /// [`Mat4::transform_within`] of a point within the extent it was made for.
    #[inline(always)]
    pub(crate) fn transform(&self, p: [i32; 3]) -> [i64; 4] {
        self.transform_words(p).map(i64::from)
    }

    /// [`transform`](Self::transform)'s coordinates, each a word (their sums are bounded
    /// below 2³¹, see the type).
    #[inline(always)]
    pub(crate) fn transform_words(&self, p: [i32; 3]) -> [i32; 4] {
        let k = self.k;
        let [x0, x1, x2] = [split(p[0], k), split(p[1], k), split(p[2], k)];
        // One term of a row's sums (written out: at opt-level "s" a loop over three stays a
        // loop).
        let term = |(a, l): (i32, i32), m: i32, (xh, xl): (i32, i32)| {
            (
                a.wrapping_add(m.wrapping_mul(xh)),
                l.wrapping_add(m.wrapping_mul(xl)),
            )
        };
        let row = |r: &[i32; 3], t: i32| {
            let [m0, m1, m2] = *r;
            let (a, l) = term(term(term((t, 0), m0, x0), m1, x1), m2, x2);
            a.wrapping_add(l.wrapping_add(1 << 15) >> k) >> (16 - k)
        };
        let [r0, r1, r2, r3] = &self.rows;
        let [t0, t1, t2, t3] = self.t;
        [row(r0, t0), row(r1, t1), row(r2, t2), row(r3, t3)]
    }
}

impl Default for Mat4 {
    fn default() -> Self {
        Mat4::IDENTITY
    }
}

impl Mat4 {
    /// The identity.
    pub const IDENTITY: Mat4 = Mat4::from_bits([
        [ONE, 0, 0, 0],
        [0, ONE, 0, 0],
        [0, 0, ONE, 0],
        [0, 0, 0, ONE],
    ]);

    /// From raw Q16.16 entries, `m[row][col]`.
    #[must_use]
    pub const fn from_bits(m: [[i32; 4]; 4]) -> Self {
        Mat4 { m }
    }

    /// From rows of [`Scalar`]s.
    #[must_use]
    pub fn from_rows(rows: [[Scalar; 4]; 4]) -> Self {
        Mat4 {
            m: rows.map(|r| r.map(Scalar::to_bits)),
        }
    }

    /// Raw Q16.16 entries, `m[row][col]`.
    #[must_use]
    pub const fn to_bits(&self) -> [[i32; 4]; 4] {
        self.m
    }

    /// The entries as [`Scalar`]s, `rows()[row][col]`.
    #[must_use]
    pub fn rows(&self) -> [[Scalar; 4]; 4] {
        self.m.map(|r| r.map(Scalar::from_bits))
    }

    /// Translation by `t`.
    #[must_use]
    pub const fn translation(t: Vec3) -> Self {
        let [x, y, z] = t.to_bits();
        Mat4::from_bits([
            [ONE, 0, 0, x],
            [0, ONE, 0, y],
            [0, 0, ONE, z],
            [0, 0, 0, ONE],
        ])
    }

    /// Scaling along the axes by `s`.
    #[must_use]
    pub const fn scaling(s: Vec3) -> Self {
        let [x, y, z] = s.to_bits();
        Mat4::from_bits([[x, 0, 0, 0], [0, y, 0, 0], [0, 0, z, 0], [0, 0, 0, ONE]])
    }

    /// Rotation about +X by `a` (right-handed: +Y turns towards +Z).
    #[must_use]
    pub const fn rotation_x(a: Angle) -> Self {
        Mat4::rotation_x_sc(sin_cos_q16(a))
    }

    /// Rotation about +Y by `a` (right-handed: +Z turns towards +X).
    #[must_use]
    pub const fn rotation_y(a: Angle) -> Self {
        Mat4::rotation_y_sc(sin_cos_q16(a))
    }

    /// Rotation about +Z by `a` (right-handed: +X turns towards +Y).
    #[must_use]
    pub const fn rotation_z(a: Angle) -> Self {
        Mat4::rotation_z_sc(sin_cos_q16(a))
    }

    /// Rotation about +X from its Q16.16 sine and cosine.
    pub(crate) const fn rotation_x_sc((s, c): (i32, i32)) -> Self {
        Mat4::from_bits([[ONE, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, ONE]])
    }

    /// Rotation about +Y from its Q16.16 sine and cosine.
    pub(crate) const fn rotation_y_sc((s, c): (i32, i32)) -> Self {
        Mat4::from_bits([[c, 0, s, 0], [0, ONE, 0, 0], [-s, 0, c, 0], [0, 0, 0, ONE]])
    }

    /// Rotation about +Z from its Q16.16 sine and cosine.
    pub(crate) const fn rotation_z_sc((s, c): (i32, i32)) -> Self {
        Mat4::from_bits([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, ONE, 0], [0, 0, 0, ONE]])
    }

    /// Transforms a point (w = 1), rounding to nearest and saturating; the result is divided
    /// by nothing (for affine matrices w stays 1).
    #[must_use]
    pub fn transform_point(&self, p: Vec3) -> Vec3 {
        let v = self.transform_wide(p.to_bits());
        Vec3::new(saturate(v[0]), saturate(v[1]), saturate(v[2]))
    }

    /// Transforms a direction (w = 0): rotation and scale only.
    #[must_use]
    pub fn transform_vector(&self, d: Vec3) -> Vec3 {
        let p = d.to_bits().map(i64::from);
        let row = |r: &[i32; 4]| {
            let s = (r[0] as i64 * p[0])
                .saturating_add(r[1] as i64 * p[1])
                .saturating_add(r[2] as i64 * p[2]);
            saturate(shr_round(s, 16))
        };
        Vec3::new(row(&self.m[0]), row(&self.m[1]), row(&self.m[2]))
    }

    /// `self * (p, 1)` as raw Q16.16 in 64 bits, for the vertex stage. Each product (below 2⁶²)
    /// is halved before the sum so that no input can overflow it, and the sum is rounded once
    /// (half up): within 2⁻¹⁶ of a unit of the exact value. Every component is below 2⁴⁸.
    /// Out of line: only meshes beyond ±2²⁹ take it (and `transform_point`), so it need not
    /// be copied into every caller.
    #[inline(never)]
    pub(crate) fn transform_wide(&self, p: [i32; 3]) -> [i64; 4] {
        let [x, y, z] = p;
        let row = |r: &[i32; 4]| {
            let s = (mul_wide(r[0], x) >> 1)
                + (mul_wide(r[1], y) >> 1)
                + (mul_wide(r[2], z) >> 1)
                + ((r[3] as i64) << 15);
            (s + (1 << 14)) >> 15
        };
        let [r0, r1, r2, r3] = &self.m;
        [row(r0), row(r1), row(r2), row(r3)]
    }

    /// The vertex stage's transform of a point of a mesh whose coordinates lie within
    /// ±`extent`: [`transform_short`](Self::transform_short) below 2²⁹ (every unit-scale
    /// model), else [`transform_wide`](Self::transform_wide). Clipping transforms a triangle's
    /// vertices again through this, so that shared vertices land on the same pixels.
    #[inline(always)]
    pub(crate) fn transform_within(&self, p: [i32; 3], extent: u32) -> [i64; 4] {
        if extent < 1 << 29 {
            self.transform_short(p)
        } else {
            self.transform_wide(p)
        }
    }

    /// True when [`transform_within`](Self::transform_within) of every point within ±`extent`
    /// has all four coordinates strictly within ±2³¹ (so the vertex stage need not check
    /// them): from a bound on each row's sum, `Σ|m_j|·extent + |m_3|·2¹⁶ + 2¹⁵ < 2⁴⁷`, for
    /// meshes that take [`transform_short`](Self::transform_short).
    pub(crate) fn fits_32_bits(&self, extent: u32) -> bool {
        if extent >= 1 << 29 {
            return false;
        }
        let e = extent as u64;
        let a = |v: i32| v.unsigned_abs() as u64;
        // Below 3·2³¹·2²⁹ + 2⁴⁷ + 2¹⁵: no overflow.
        self.m
            .iter()
            .all(|r| (a(r[0]) + a(r[1]) + a(r[2])) * e + (a(r[3]) << 16) + (1 << 15) < 1 << 47)
    }

    /// [`transform_wide`](Self::transform_wide) of a point whose coordinates lie within ±2²⁹:
    /// each product is then below 2⁶⁰ and the sum needs no halving, so it is rounded once
    /// (half up), exactly. On cores without a long multiply the vertex stage takes a
    /// [`SplitTransform`] instead: there this serves clipping, and matrices and meshes too
    /// large for the split.
    #[inline]
    pub(crate) fn transform_short(&self, p: [i32; 3]) -> [i64; 4] {
        let [x, y, z] = p;
        // Each sum starts from its row's translation with the rounding's half added, one
        // constant of the loop over a mesh's vertices that every product accumulates onto.
        let row = |r: &[i32; 4]| {
            let s = (((r[3] as i64) << 16) + (1 << 15))
                .wrapping_add(mul_wide(r[0], x))
                .wrapping_add(mul_wide(r[1], y))
                .wrapping_add(mul_wide(r[2], z));
            s >> 16
        };
        let [r0, r1, r2, r3] = &self.m;
        [row(r0), row(r1), row(r2), row(r3)]
    }

    /// The [`SplitTransform`] of this matrix for points within ±`extent`, or `None` where no
    /// split keeps every sum a word (see the type).
    pub(crate) fn split_transform(&self, extent: u32) -> Option<SplitTransform> {
        // Each row's Σ|m|, below 2³¹ (else no split serves), and the largest.
        let mut sums = [0u32; 4];
        for (sum, r) in sums.iter_mut().zip(&self.m) {
            let [a, b, c, _] = r.map(i32::unsigned_abs);
            *sum = a.checked_add(b)?.checked_add(c).filter(|&s| s < 1 << 31)?;
        }
        let largest = sums.iter().copied().max().unwrap_or(0);
        // The split whose low parts' sum, |L| ≤ Σ|m|·2^(k−1), lies below 2³⁰ (L + 2¹⁵ a
        // word): at most 16, at least 1.
        let k = (31 - (32 - largest.leading_zeros())).clamp(1, 16);
        if extent >= 1 << 29 || (largest as u64) << (k - 1) >= 1 << 30 {
            return None;
        }
        // A coordinate's high part is at most (extent + 2^(k−1)) / 2^k in magnitude.
        let high = ((extent + (1 << (k - 1))) >> k) + 1;
        let s = 16 - k;
        let mut t = [0; 4];
        for ((t, r), sum) in t.iter_mut().zip(&self.m).zip(sums) {
            // |A| + |t|·2^s + |⌊(L + 2¹⁵) / 2^k⌋| (at most 2^(30−k) + 1), below 2³¹: the
            // row's word.
            let bound = sum as u64 * high as u64
                + ((r[3].unsigned_abs() as u64) << s)
                + (1 << (30 - k))
                + 1;
            if bound >= 1 << 31 {
                return None;
            }
            *t = r[3] << s;
        }
        Some(SplitTransform {
            rows: self.m.map(|r| [r[0], r[1], r[2]]),
            t,
            k,
        })
    }

    /// The upper-left 3x3 block's cofactor matrix (`det · M⁻ᵀ`) times a power of two: it
    /// carries normals from model to world space, for any scale, with no division. Only
    /// directions matter (normals are normalised after), so the exact cofactors are shifted
    /// together until the largest lies in [2²⁹, 2³⁰): a model scaled by 8000 neither saturates
    /// (cofactors grow with the scale squared) nor does one scaled by 1/1024 lose its normals
    /// to rounding (case T33).
    pub(crate) fn normal_matrix(&self) -> [[i32; 3]; 3] {
        let r = |i: usize| [self.m[i][0], self.m[i][1], self.m[i][2]];
        let c = [
            cross_wide(r(1), r(2)),
            cross_wide(r(2), r(0)),
            cross_wide(r(0), r(1)),
        ];
        let bits = magnitude_bits(c.as_flattened());
        c.map(|row| {
            row.map(|v| {
                let v = if bits > 30 {
                    shr_round(v, bits - 30)
                } else {
                    v << (30 - bits)
                };
                v.clamp(-(1 << 30), 1 << 30) as i32
            })
        })
    }

    /// The transpose.
    #[must_use]
    pub fn transpose(&self) -> Mat4 {
        let mut t = [[0; 4]; 4];
        for (i, row) in self.m.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                if let Some(cell) = t.get_mut(j).and_then(|r| r.get_mut(i)) {
                    *cell = *v;
                }
            }
        }
        Mat4 { m: t }
    }
}

const fn sin_cos_q16(a: Angle) -> (i32, i32) {
    (
        shr_round(a.sin_bits() as i64, 14) as i32,
        shr_round(a.cos_bits() as i64, 14) as i32,
    )
}

/// The product `a · b · c` of three matrices in 64-bit integers, with a binary exponent:
/// returns `(m, f)` with `a · b · c ≈ m / 2^f`. `b · c` is exact (Q32.32, saturating only
/// beyond ±2³¹), then shifted so that its largest entry has at most 30 bits before the product
/// with `a`, which is then exact: every entry of `m` carries at least 29 significant bits
/// relative to the largest. No 128-bit arithmetic (it would cost a long library call per
/// product on Cortex-M0).
pub(crate) fn product3(a: &Mat4, b: &Mat4, c: &Mat4) -> ([[i64; 4]; 4], i32) {
    let mut bc = [[0i64; 4]; 4];
    for (row, brow) in bc.iter_mut().zip(b.m.iter()) {
        for (j, cell) in row.iter_mut().enumerate() {
            *cell = brow.iter().zip(c.m.iter()).fold(0i64, |acc, (x, crow)| {
                acc.saturating_add(*x as i64 * crow.get(j).copied().unwrap_or(0) as i64)
            });
        }
    }
    let shift = magnitude_bits(bc.as_flattened()).saturating_sub(30);
    let bc = bc.map(|row| row.map(|v| shr_round(v, shift)));
    let mut abc = [[0i64; 4]; 4];
    for (row, arow) in abc.iter_mut().zip(a.m.iter()) {
        for (j, cell) in row.iter_mut().enumerate() {
            // |a| < 2³¹ and |bc| ≤ 2³⁰: each product below 2⁶¹, four below 2⁶³.
            *cell = arow.iter().zip(bc.iter()).fold(0i64, |acc, (x, bcrow)| {
                acc.wrapping_add(*x as i64 * bcrow.get(j).copied().unwrap_or(0))
            });
        }
    }
    (abc, 48 - shift as i32)
}

impl Mul for Mat4 {
    type Output = Mat4;
    fn mul(self, o: Mat4) -> Mat4 {
        let mut out = [[0i32; 4]; 4];
        for (orow, arow) in out.iter_mut().zip(self.m.iter()) {
            for (j, cell) in orow.iter_mut().enumerate() {
                let s = arow.iter().zip(o.m.iter()).fold(0i64, |acc, (a, brow)| {
                    let b = brow.get(j).copied().unwrap_or(0);
                    acc.saturating_add(*a as i64 * b as i64)
                });
                *cell = shr_round(s, 16).clamp(i32::MIN as i64, i32::MAX as i64) as i32;
            }
        }
        Mat4 { m: out }
    }
}

impl Mul<&Mat4> for &Mat4 {
    type Output = Mat4;
    fn mul(self, o: &Mat4) -> Mat4 {
        *self * *o
    }
}

/// True when `m` is a rotation times a scale, within 2⁻¹²: its columns orthogonal and of one
/// length, `mᵀm = s²·I`. (A Q16.16 rotation is one within about 2⁻¹⁶; treating a matrix 2⁻¹²
/// away as one moves a lit colour by at most a sixteenth of an 8-bit level.) Entries within
/// ±2³⁰ (a normal matrix): every product below 2⁶⁰, every sum of three below 2⁶².
pub(crate) fn is_scaled_rotation(m: &[[i32; 3]; 3]) -> bool {
    let dot = |a: usize, b: usize| -> i64 { (0..3).map(|i| m[i][a] as i64 * m[i][b] as i64).sum() };
    let s2 = dot(0, 0);
    let tolerance = s2 >> 12;
    s2 > 0
        && (dot(1, 1) - s2).abs() <= tolerance
        && (dot(2, 2) - s2).abs() <= tolerance
        && dot(0, 1).abs() <= tolerance
        && dot(0, 2).abs() <= tolerance
        && dot(1, 2).abs() <= tolerance
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The short transform is the exact product rounded once (half up), checked in i128, for
    /// any matrix and points within ±2²⁹; the wide one within one unit of it.
    #[test]
    fn short_transform_rounds_once() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..100_000 {
            let mut next = |bits: u64| {
                let x = rng.next_u64();
                (x as i64 >> (x % bits + 64 - bits)) as i32
            };
            let m = Mat4::from_bits([[0; 4]; 4].map(|r| r.map(|_: i32| next(32))));
            let limit = (1 << 29) - 1;
            let p = [0; 3].map(|_: i32| next(31).clamp(-limit, limit));
            let short = m.transform_within(p, limit as u32);
            let wide = m.transform_wide(p);
            for (i, row) in m.m.iter().enumerate() {
                let exact = (0..3).map(|j| row[j] as i128 * p[j] as i128).sum::<i128>()
                    + ((row[3] as i128) << 16);
                let rounded = (exact + (1 << 15)) >> 16;
                assert_eq!(short[i] as i128, rounded, "{m:?} {p:?}");
                assert!((wide[i] as i128 - rounded).abs() <= 1, "{m:?} {p:?}");
            }
        }
    }

    /// A number of about `bits` bits (at most 32), of either sign.
    fn sized(rng: &mut crate::testing::XorShift, bits: u64) -> i32 {
        let x = rng.next_u64();
        (x as i64 >> (x % bits + 64 - bits)) as i32
    }

    /// A matrix of entries of every size and an extent below 2²⁹ for its points.
    fn random_matrix(rng: &mut crate::testing::XorShift) -> (Mat4, u32) {
        let m = Mat4::from_bits([[0; 4]; 4].map(|r| r.map(|_: i32| sized(rng, 32))));
        (m, sized(rng, 30).unsigned_abs().min((1 << 29) - 1))
    }

    /// The corners of the cube of points within ±`extent` (where a transform's sums are
    /// largest) and eight random points inside it.
    fn points_within(rng: &mut crate::testing::XorShift, extent: u32) -> std::vec::Vec<[i32; 3]> {
        let e = extent as i32;
        let corners = (0..8).map(|k| [k & 1, k & 2, k & 4].map(|b| if b == 0 { e } else { -e }));
        let inside: std::vec::Vec<[i32; 3]> = (0..8)
            .map(|_| [0; 3].map(|_: i32| sized(rng, 31).clamp(-e, e)))
            .collect();
        corners.chain(inside).collect()
    }

    /// Where `fits_32_bits` holds, every point within the extent (its corners, where the
    /// sums are largest, and random ones) transforms to coordinates strictly within ±2³¹; it
    /// holds for a unit-scale scene and fails where they could be larger.
    #[test]
    fn fits_32_bits_bounds_the_transform() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let below_31 = |c: [i64; 4]| c.iter().all(|v| -(1 << 31) < *v && *v < 1 << 31);
        let (mut held, mut failed) = (0, 0);
        for _ in 0..20_000 {
            let (m, extent) = random_matrix(&mut rng);
            if !m.fits_32_bits(extent) {
                failed += 1;
                continue;
            }
            held += 1;
            for p in points_within(&mut rng, extent) {
                assert!(below_31(m.transform_within(p, extent)), "{m:?} {p:?}");
            }
        }
        assert!(held > 1000 && failed > 1000, "{held} {failed}");
        let unit =
            Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::scaling(Vec3::from_int(3, 3, 3));
        assert!(unit.fits_32_bits(2 << 16));
        assert!(!unit.fits_32_bits(1 << 29));
        assert!(!Mat4::scaling(Vec3::from_int(30000, 1, 1)).fits_32_bits(30000 << 16));
    }

    /// How many random matrices `transform` (one made for a matrix and an extent, where it
    /// is) takes and turns away; where it takes one, it equals `transform_within` bit for bit
    /// at every point within the extent (its corners included).
    fn held_and_refused<T>(
        make: impl Fn(&Mat4, u32) -> Option<T>,
        transform: impl Fn(&T, [i32; 3]) -> [i64; 4],
    ) -> (u32, u32) {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let (mut held, mut refused) = (0, 0);
        for _ in 0..40_000 {
            let (m, extent) = random_matrix(&mut rng);
            let Some(h) = make(&m, extent) else {
                refused += 1;
                continue;
            };
            held += 1;
            for p in points_within(&mut rng, extent) {
                assert_eq!(
                    transform(&h, p),
                    m.transform_within(p, extent),
                    "{m:?} {p:?}"
                );
            }
        }
        (held, refused)
    }

    /// The reference scene's clip-from-model matrix (docs/reference-scene.md: its camera, the torus's
    /// extent of 1.4), its extent and three points within it.
    fn reference_clip_from_model() -> (Mat4, u32, [[i32; 3]; 3]) {
        let viewport = crate::projection::Viewport::new(320, 240).unwrap();
        let eye = Vec3::from_f32(0.0, 0.0, 2.6).unwrap();
        let view = crate::camera::LookAt::new(eye, Vec3::ZERO, Vec3::Y)
            .view()
            .unwrap();
        let s = Scalar::from_num;
        let projection = crate::projection::Projection::perspective(
            Angle::from_degrees(60),
            viewport.aspect(),
            s(1),
            s(10),
        )
        .unwrap();
        let extent = 92_000;
        let frame = crate::pipeline::Frame::new(&view, &projection, viewport);
        let m = frame.clip_from_model_within(&Mat4::IDENTITY, extent);
        let e = extent as i32;
        (
            m,
            extent,
            [[e, -e, 5], [-1, 0, 1], [60_000, 30_000, -91_999]],
        )
    }

    /// `SplitTransform` (Cortex-M0's, so not run on the host otherwise) is `transform_within`,
    /// bit for bit, for every matrix `split_transform` accepts and every point within the
    /// extent; it accepts the matrices of ordinary scenes and turns away those whose 32-bit
    /// sums could overflow. The reference scene splits at bit 14.
    #[test]
    fn split_transform_equals_transform_within() {
        let words = |h: &SplitTransform, p| h.transform(p);
        let (held, refused) = held_and_refused(|m, e| m.split_transform(e), words);
        assert!(held > 2000 && refused > 5000, "{held} {refused}");
        let (m, extent, points) = reference_clip_from_model();
        let h = m
            .split_transform(extent)
            .expect("the reference scene takes the split");
        assert_eq!(h.k, 14);
        for p in points {
            assert_eq!(words(&h, p), m.transform_within(p, extent), "{p:?}");
        }
        let big = Mat4::scaling(Vec3::from_int(30000, 1, 1));
        assert!(big.split_transform(30000 << 16).is_none());
        assert!(Mat4::IDENTITY.split_transform(1 << 29).is_none());
        let unit =
            Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::scaling(Vec3::from_int(3, 3, 3));
        assert!(unit.split_transform(2 << 16).is_some());
        // At twice the scale, 4,096 units across: beyond the split's bounds.
        let far = Mat4::scaling(Vec3::from_int(2, 2, 2));
        assert!(far.split_transform(4096 << 16).is_none());
        assert!(far.split_transform(1024 << 16).is_some());
    }

    #[test]
    fn rotations_follow_right_hand_rule() {
        let q = Angle::from_degrees(90);
        assert_eq!(Mat4::rotation_x(q).transform_point(Vec3::Y), Vec3::Z);
        assert_eq!(Mat4::rotation_y(q).transform_point(Vec3::Z), Vec3::X);
        assert_eq!(Mat4::rotation_z(q).transform_point(Vec3::X), Vec3::Y);
    }

    #[test]
    fn products_saturate_instead_of_wrapping() {
        let big = Mat4::scaling(Vec3::from_int(30000, 30000, 30000));
        let m = big * big;
        assert_eq!(m.to_bits()[0][0], i32::MAX);
        let p = m.transform_point(Vec3::from_int(-30000, 1, 1));
        assert_eq!(p.x.to_bits(), i32::MIN);
    }

    #[test]
    fn normal_matrix_of_scaled_rotation() {
        let m = Mat4::rotation_z(Angle::from_degrees(90)) * Mat4::scaling(Vec3::from_int(2, 1, 1));
        let n = m.normal_matrix();
        // det * M^-T for diag(2,1,1) rotated: rows scaled by (1, 2, 2), then by 2^28.
        assert_eq!(n[0], [0, -2 << 28, 0]);
        assert_eq!(n[1], [1 << 28, 0, 0]);
        assert_eq!(n[2], [0, 0, 2 << 28]);
        // Any uniform scale gives the same directions.
        for s in [Scalar::from_bits(64), Scalar::from_num(8000)] {
            let big = Mat4::rotation_z(Angle::from_degrees(90)) * Mat4::scaling(Vec3::new(s, s, s));
            let n = big.normal_matrix();
            let k = n[2][2];
            assert!((1 << 29..1 << 30).contains(&k), "{k}");
            assert_eq!(n, [[0, -k, 0], [k, 0, 0], [0, 0, k]]);
        }
    }
}

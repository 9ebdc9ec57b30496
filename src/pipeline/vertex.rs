//! The vertex stage: model space → clip space → screen (once per vertex per frame), with the
//! outcodes that decide which triangles need clipping.
//!
//! Clip-space coordinates are raw Q16.16 in 64 bits (below 2⁴⁸ in magnitude). Before any product
//! they are *reduced*: shifted right together until all four fit in 31 bits, which changes no
//! ratio that matters and keeps every product below 2⁶². In practice (coordinates below 32768)
//! nothing is shifted.

use core::num::NonZeroU32;

use super::Precision;
use crate::math::{
    below_bits, div_round, div_round_word, fraction_in_words, magnitude_bits, mul_short, mul_wide,
    mul_wide_u32, shr_round, sqrt_above, DivideBy, Mat4, ShortQuotients, DEPTH_ONE,
};
use crate::projection::Viewport;
use crate::raster::{ScreenPoint, PIPELINE_LIMIT};

/// One transformed vertex in the per-frame cache: snapped screen position, depth, lit colour
/// (Gouraud) and the clip planes it is outside of. 16 bytes; a frame needs one per vertex of
/// the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ScreenVertex {
    pub(crate) x: i32,
    pub(crate) y: i32,
    pub(crate) z: i32,
    pub(crate) rgb: [u8; 3],
    pub(crate) outcode: u8,
}

impl ScreenVertex {
    /// An unused cache slot (for initialising arrays).
    pub const DEFAULT: ScreenVertex = ScreenVertex {
        x: 0,
        y: 0,
        z: 0,
        rgb: [0; 3],
        outcode: 0,
    };

    /// The snapped screen position in sub-pixels (meaningful when [`is_inside`](Self::is_inside)).
    #[must_use]
    pub const fn point(&self) -> ScreenPoint {
        ScreenPoint::new(self.x, self.y)
    }

    /// True when the vertex lies between the near and far planes and inside the guard band, so
    /// that its screen position is valid.
    #[must_use]
    pub const fn is_inside(&self) -> bool {
        self.outcode == 0
    }

    /// Depth after projection as a fraction of 2³⁰ (0 near, 2³⁰ far).
    #[must_use]
    pub const fn depth(&self) -> i32 {
        self.z
    }
}

/// Clip planes, one bit each, in the order clipping applies them: near, far, then the guard
/// band's left, right, top and bottom.
pub(crate) const PLANES: u32 = 6;

/// Half the guard band in sub-pixels around the screen centre: projected coordinates within it
/// stay below 2¹⁵ in magnitude (the attribute set-up's bound) for viewports up to 2048 pixels.
pub(super) const GUARD: i64 = (1 << 14) - 16;
// The band around the farthest screen centre (a 2048-pixel viewport's) ends at the bound the
// rasteriser relies on.
const _: () = assert!((1 << 14) + GUARD == PIPELINE_LIMIT as i64);
// Vertices inside every plane lie within GUARD of the screen centre at every snapping (each
// snapping step, up to 2⁴ sub-pixels, divides GUARD), so two of them lie less than 2¹⁵ apart
// on each axis: the triangle walk takes their sides as short (see `inside_area2`).
const _: () = assert!(2 * GUARD < 1 << 15 && GUARD % 16 == 0);

/// Viewport constants in sub-pixels.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScreenMap {
    half_w: i64,
    half_h: i64,
    /// Vertices snap to multiples of `1 << snap` sub-pixels from the centre.
    snap: u32,
}

impl ScreenMap {
    pub(crate) fn new(v: &Viewport, precision: &Precision) -> Self {
        // width/2 · 16 = width · 8
        ScreenMap {
            half_w: v.width() as i64 * 8,
            half_h: v.height() as i64 * 8,
            snap: precision.snap_shift(),
        }
    }

    /// What holds for every point within `radius` of the origin (raw Q16.16) through `m`, its
    /// coordinates rounded as [`Mat4::transform_short`] rounds them (for a matrix that
    /// [`fits_32_bits`](Mat4::fits_32_bits)): inside every clip plane, and then whether its
    /// projection's operands fit words (see [`Known`]). A plane's distance is an affine
    /// function of the point, `a·t + g·p` (`a` its coefficients over the clip coordinates, `t`
    /// the matrix' translation, `g = a·M` through its other columns), least on the sphere at
    /// `a·t − |g|·radius`, and the rounding of the four coordinates moves it by at most half of
    /// `Σ|a_i|`; so are the bounds on `x·half_w`, `y·half_h` and `w` (see [`keeps_sphere`]).
    pub(crate) fn known(&self, m: &Mat4, radius: u32) -> Known {
        // At most 2¹⁴ each (viewports of at most 2048 pixels).
        let (hw, hh, g) = (self.half_w as i32, self.half_h as i32, GUARD as i32);
        let rows = m.to_bits();
        let keeps = |&(a, offset): &([i32; 4], i64)| keeps_sphere(&a, offset, &rows, radius);
        // Each plane's coefficients of (x, y, z, w), in `distance`'s order.
        let planes = [
            ([0, 0, 1, 0], 0),
            ([0, 0, -1, 1], 0),
            ([hw, 0, 0, g], 0),
            ([-hw, 0, 0, g], 0),
            ([0, -hh, 0, g], 0),
            ([0, hh, 0, g], 0),
        ];
        if !planes.iter().all(keeps) {
            return Known::Nothing;
        }
        // |x·half_w| and |y·half_h| below 2³¹ − 1, w below 2¹⁹ (w > 0 inside the planes).
        let words = i64::from(i32::MAX);
        let bounds = [
            ([-hw, 0, 0, 0], words),
            ([hw, 0, 0, 0], words),
            ([0, -hh, 0, 0], words),
            ([0, hh, 0, 0], words),
            ([0, 0, 0, -1], 1 << 19),
        ];
        if self.snap == 0 && bounds.iter().all(keeps) {
            Known::InWords
        } else {
            Known::Inside
        }
    }

    /// `x·half_w` and `y·half_h` of reduced coordinates (below 2³¹; half sizes at most 2¹⁴,
    /// viewports being at most 2048 pixels): 32-bit factors, the second short.
    #[inline(always)]
    fn viewport_products(&self, x: i64, y: i64) -> (i64, i64) {
        (
            mul_short(x as i32, self.half_w as i32),
            mul_short(y as i32, self.half_h as i32),
        )
    }

    /// [`viewport_products`](Self::viewport_products) where they are known to fit i32 (see
    /// [`Known::InWords`]): one 32-bit multiply each, whose low word is the product (on
    /// Cortex-M0 for two of `mul_short`'s).
    #[inline(always)]
    fn viewport_products_in_words(&self, x: i32, y: i32) -> (i64, i64) {
        (
            x.wrapping_mul(self.half_w as i32) as i64,
            y.wrapping_mul(self.half_h as i32) as i64,
        )
    }
}

/// True when `a·c + offset > 0` for the clip coordinates `c` (x, y, z, w; coefficients `a`
/// within ±2¹⁵, `offset` within ±2⁴⁰) that the matrix of raw entries `rows` gives every point
/// within `radius` of the origin, rounded half up (see [`ScreenMap::known`]): times 2¹⁶,
/// `(a·t + offset)·2¹⁶ − |g|·radius − 2¹⁵·Σ|a_i| > 0`. False where `a·t + offset` reaches 2⁴⁷
/// or a component of `g` 2⁴⁰ (matrices far beyond unit scale).
#[inline(never)]
fn keeps_sphere(a: &[i32; 4], offset: i64, rows: &[[i32; 4]; 4], radius: u32) -> bool {
    // The plane's coefficients of the matrix' columns, each within ±2⁴⁸ (the products of its
    // zero coefficients left out: most are).
    let mut columns = [0i64; 4];
    for (&ai, r) in a.iter().zip(rows) {
        if ai != 0 {
            for (c, &m) in columns.iter_mut().zip(r) {
                *c += mul_wide(ai, m);
            }
        }
    }
    let [g0, g1, g2, at_origin] = columns;
    let at_origin = at_origin + offset;
    // The origin itself inside (below 2⁴⁷, so that the products below fit).
    if at_origin <= 0 || !below_bits(at_origin, 47) {
        return false;
    }
    // Within ±2⁶³, and positive where the plane keeps the sphere.
    let least =
        (at_origin << 16) - (i64::from(a.iter().map(|v| v.unsigned_abs()).sum::<u32>()) << 15);
    // `least` must exceed |g|·radius: `g'`, g's components over 2⁹ rounded up (below 2³¹ for
    // every g below 2⁴⁰, squares summing below 2⁶⁴), bounds |g| / 2⁹, `sqrt_above` bounds |g'|.
    const SHIFT: u32 = 9;
    let g = [g0, g1, g2];
    if !g.iter().all(|&c| below_bits(c, 31 + SHIFT)) {
        return false;
    }
    let squares = g.iter().fold(0u64, |s, &c| {
        let c = ((c.unsigned_abs() + (1 << SHIFT) - 1) >> SHIFT) as u32;
        s + mul_wide_u32(c, c)
    });
    // At most 2³³: where it fits a word (every g but those near 2⁴⁰), a product of words.
    let Ok(root) = u32::try_from(sqrt_above(squares)) else {
        return false;
    };
    least > 0 && (least as u64) >> SHIFT > mul_wide_u32(root, radius)
}

/// What the vertex stage knows of every vertex of an object before it transforms any (from
/// [`ScreenMap::known`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Known {
    /// Nothing: each vertex is tested against the clip planes.
    Nothing,
    /// Inside every clip plane: no vertex is tested.
    Inside,
    /// Inside every clip plane, with `x·half_w` and `y·half_h` within i32 and `w` below 2¹⁹,
    /// at the default sub-pixel precision (no snapping): the projection multiplies words, and
    /// on cores with a divide instruction divides them, without testing its operands.
    InWords,
}

/// Shift that brings the largest magnitude below 2³¹.
fn reduce_shift(c: &[i64; 4]) -> u32 {
    magnitude_bits(c).saturating_sub(31)
}

#[inline]
pub(crate) fn reduce(c: [i64; 4]) -> [i64; 4] {
    // The common case, coordinates below 2³¹, needs nothing (four comparisons without a
    // branch between them).
    let fits = |v: i64| below_bits(v, 31);
    if fits(c[0]) & fits(c[1]) & fits(c[2]) & fits(c[3]) {
        return c;
    }
    let s = reduce_shift(&c);
    c.map(|v| shr_round(v, s))
}

/// Two vertices reduced by a common shift (for intersections); returns the shift too.
pub(crate) fn reduce_pair(a: [i64; 4], b: [i64; 4]) -> ([i64; 4], [i64; 4], u32) {
    let s = reduce_shift(&a).max(reduce_shift(&b));
    (a.map(|v| shr_round(v, s)), b.map(|v| shr_round(v, s)), s)
}

/// Signed distance to clip plane `k` of reduced coordinates (positive inside).
pub(crate) fn distance(k: u32, c: &[i64; 4], m: &ScreenMap) -> i64 {
    let [x, y, z, w] = *c;
    match k {
        0 => z,                        // near: z > 0
        1 => w - z,                    // far: z <= w
        2 => GUARD * w + x * m.half_w, // left guard
        3 => GUARD * w - x * m.half_w, // right guard
        4 => GUARD * w - y * m.half_h, // top guard (clip +y is up)
        _ => GUARD * w + y * m.half_h, // bottom guard
    }
}

/// On the near plane counts as outside (so nothing is drawn at depth exactly 0 from a triangle
/// lying in the plane, case T18); on any other plane counts as inside.
pub(crate) fn inside(k: u32, d: i64) -> bool {
    if k == 0 {
        d > 0
    } else {
        d >= 0
    }
}

/// The planes a vertex is outside of, from reduced `z`, `w`, `x·half_w` and `y·half_h`:
/// [`distance`] and [`inside`] for each plane, written out.
#[inline(always)]
fn outcode_reduced(z: i64, w: i64, xh: i64, yh: i64) -> u8 {
    // w is reduced (within 31 bits) and the guard below 2¹⁵: the short product (on Cortex-M0
    // two multiplies, where the compiler would call the library's 64-bit product).
    let g = mul_short(w as i32, GUARD as i32);
    (z <= 0) as u8
        | ((w - z < 0) as u8) << 1
        | ((g + xh < 0) as u8) << 2
        | ((g - xh < 0) as u8) << 3
        | ((g - yh < 0) as u8) << 4
        | ((g + yh < 0) as u8) << 5
}

/// Perspective divide and viewport: snapped sub-pixel x, y (round to nearest, ties away from
/// the screen centre, so `snap(−x) = −snap(x)` about it) and Q1.30 depth clamped to [0, 1].
/// `None` when w ≤ 0: the pipeline never divides by it.
pub(crate) fn project(c: [i64; 4], m: &ScreenMap) -> Option<(ScreenPoint, i32)> {
    let [x, y, z, w] = reduce(c);
    let (xh, yh) = m.viewport_products(x, y);
    project_reduced(xh, yh, z, w, m)
}

/// The vertex stage's hot path: the planes a clip-space vertex is outside of (one bit each,
/// in [`distance`]'s order) and, when there are none, its [`project`]ion; the reduction and
/// the viewport products are done once for both. `fits` says that every coordinate is known
/// to lie strictly within ±2³¹ (see `Mat4::fits_32_bits`): nothing to reduce. `known` is what
/// holds for the vertex before it is tested (see [`Known`]).
#[inline(always)]
pub(crate) fn outcode_and_project(
    c: [i64; 4],
    m: &ScreenMap,
    fits: bool,
    known: Known,
) -> (u8, ScreenPoint, i32) {
    let [x, y, z, w] = if fits { c } else { reduce(c) };
    let (xh, yh) = if known == Known::InWords {
        m.viewport_products_in_words(x as i32, y as i32)
    } else {
        m.viewport_products(x, y)
    };
    let code = if known == Known::Nothing {
        outcode_reduced(z, w, xh, yh)
    } else {
        0
    };
    if code != 0 {
        return (code, ScreenPoint::default(), 0);
    }
    // Snapped to the sub-pixel grid (never for `Known::InWords`, found only without snapping).
    if known != Known::InWords && m.snap != 0 {
        let (p, depth) = project_reduced(xh, yh, z, w, m).unwrap_or_default();
        return (code, p, depth);
    }
    // Inside every plane: 0 < z ≤ w, and |x·half_w|, |y·half_h| ≤ GUARD·w, so both offsets
    // from the centre are at most GUARD (the rounded quotient of at most GUARD·w by w) and the
    // depth lies in [0, 2³⁰]. With half sizes at most 2¹⁴ (viewports up to 2048 pixels) the
    // screen position lies within ±(2¹⁴ + GUARD), which is ±PIPELINE_LIMIT: `project`'s clamps
    // would change nothing, and every result fits a 32-bit word.
    let (qx, qy, sz) = if known == Known::InWords {
        // x·half_w and y·half_h within i32 and 0 < z ≤ w < 2¹⁹ (see `Known::InWords`): words,
        // untested (w is never 0 here; as 1 it would divide without meaning, but not by zero).
        let w = NonZeroU32::new(w as u32).unwrap_or(NonZeroU32::MIN);
        (
            div_round_word(xh as i32, w) as i64,
            div_round_word(yh as i32, w) as i64,
            fraction_in_words(z as u32, w),
        )
    } else {
        let by_w = DivideBy::new_positive32(w as i32);
        (by_w.round(xh), by_w.round(yh), by_w.round_fraction(z))
    };
    (code, screen_point(qx, qy, m), sz as i32)
}

/// [`outcode_and_project`]'s quotients on cores without a divide instruction: short quotients
/// by w in words instead of a reciprocal to 32 bits, their numerators within the band and the
/// planes as they require (untested there).
#[inline(always)]
fn short_quotients(xh: i64, yh: i64, z: i64, w: i64) -> (i64, i64, i64) {
    match ShortQuotients::new32(w as u32) {
        Some(by_w) => (
            by_w.round(xh) as i64,
            by_w.round(yh) as i64,
            by_w.round_fraction(z),
        ),
        None => (div_round(xh, w), div_round(yh, w), div_round(z << 30, w)),
    }
}

/// The screen position of offsets `qx`, `qy` from the centre (y down).
#[inline(always)]
fn screen_point(qx: i64, qy: i64, m: &ScreenMap) -> ScreenPoint {
    let sx = (m.half_w as i32).wrapping_add(qx as i32);
    let sy = (m.half_h as i32).wrapping_sub(qy as i32);
    ScreenPoint::new(sx, sy)
}

/// [`outcode_and_project`] of a vertex of a [`Known::InWords`] object on cores without a
/// divide instruction, from the coordinates of a `SplitTransform`, which are words: in line
/// in the vertex loop, where the general path is a call taking 64-bit coordinates.
#[inline(always)]
pub(crate) fn project_words(c: [i32; 4], m: &ScreenMap) -> (ScreenPoint, i32) {
    let [x, y, z, w] = c;
    let (xh, yh) = m.viewport_products_in_words(x, y);
    let (qx, qy, sz) = short_quotients(xh, yh, z as i64, w as i64);
    (screen_point(qx, qy, m), sz as i32)
}

/// [`outcode_and_project`] from its definitions: [`distance`] and [`inside`] for each plane of
/// the reduced coordinates, then [`project`] (the clipper's code).
#[cfg(test)]
pub(crate) fn outcode_and_project_by_planes(c: [i64; 4], m: &ScreenMap) -> (u8, ScreenPoint, i32) {
    let r = reduce(c);
    let code = (0..PLANES).fold(0u8, |code, k| {
        if inside(k, distance(k, &r, m)) {
            code
        } else {
            code | 1 << k
        }
    });
    if code != 0 {
        return (code, ScreenPoint::default(), 0);
    }
    let (p, depth) = project(c, m).unwrap_or_default();
    (code, p, depth)
}

/// [`project`] of reduced coordinates, from `x·half_w`, `y·half_h`, `z` and `w`. Out of line:
/// only clipped vertices and coarser snapping reach it, and in line the vertex loop's
/// registers move around it.
#[inline(never)]
fn project_reduced(xh: i64, yh: i64, z: i64, w: i64, m: &ScreenMap) -> Option<(ScreenPoint, i32)> {
    if w <= 0 {
        return None;
    }
    // Vertices inside the guard band lie within it already (see `outcode_and_project`); the
    // clamp keeps clipped ones, whose intersections are rounded, within the bound that the
    // rasteriser relies on too.
    let lim = PIPELINE_LIMIT as i64;
    let by_w = DivideBy::new(w);
    let (sx, sy) = if m.snap == 0 {
        (by_w.round(xh), by_w.round(yh))
    } else {
        // One rounding to the coarser grid (no double rounding through sixteenths).
        let (g, wg) = (m.snap, w << m.snap);
        (div_round(xh, wg) << g, div_round(yh, wg) << g)
    };
    let sz = by_w.round(z << 30);
    let sx = (m.half_w + sx).clamp(-lim, lim);
    let sy = (m.half_h - sy).clamp(-lim, lim);
    let sz = sz.clamp(0, DEPTH_ONE as i64);
    Some((ScreenPoint::new(sx as i32, sy as i32), sz as i32))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec;
    use std::vec::Vec;

    /// The screen map of a 320x240 viewport at the default precision.
    fn map_320x240() -> ScreenMap {
        let viewport = Viewport::new(320, 240).unwrap_or_else(|_| unreachable!());
        ScreenMap::new(&viewport, &Precision::DEFAULT)
    }

    /// A frame of a random camera, lens and viewport, and a random model matrix (rotation and
    /// scale), with a random mesh radius: the clip-from-model matrix, the screen map and the
    /// radius (raw Q16.16).
    fn random_view(rng: &mut crate::testing::XorShift) -> (Mat4, ScreenMap, u32) {
        use crate::camera::LookAt;
        use crate::math::{Angle, Scalar, Vec3};
        use crate::pipeline::Frame;
        use crate::projection::Projection;
        let mut unit = |lo: f64, hi: f64| lo + (hi - lo) * (rng.next_u64() % 10_000) as f64 / 1e4;
        let (w, h) = (unit(16.0, 1024.0) as u32, unit(16.0, 1024.0) as u32);
        let viewport = Viewport::new(w, h).unwrap_or_else(|_| unreachable!());
        let (distance, turn, tilt) = (
            unit(1.5, 8.0),
            unit(0.0, std::f64::consts::TAU),
            unit(-1.4, 1.4),
        );
        let eye = Vec3::from_f32(
            (distance * turn.cos() * tilt.cos()) as f32,
            (distance * tilt.sin()) as f32,
            (distance * turn.sin() * tilt.cos()) as f32,
        )
        .unwrap_or_else(|| unreachable!());
        let aim = Vec3::from_f32(unit(-0.5, 0.5) as f32, unit(-0.5, 0.5) as f32, 0.0)
            .unwrap_or_else(|| unreachable!());
        let view = LookAt::new(eye, aim, Vec3::Y)
            .view()
            .unwrap_or_else(|_| unreachable!());
        let near = unit(0.1, 2.0);
        let projection = Projection::perspective(
            Angle::from_degrees(unit(20.0, 120.0) as i32),
            viewport.aspect(),
            Scalar::from_num(near),
            Scalar::from_num(near + unit(0.5, 40.0)),
        )
        .unwrap_or_else(|_| unreachable!());
        let frame = Frame::new(&view, &projection, viewport);
        let scale = Scalar::from_num(unit(0.2, 3.0));
        let model = Mat4::rotation_y(Angle::from_degrees(unit(0.0, 360.0) as i32))
            * Mat4::rotation_x(Angle::from_degrees(unit(0.0, 360.0) as i32))
            * Mat4::scaling(Vec3::new(scale, scale, scale));
        let radius = (unit(0.05, 4.0) * 65536.0) as u32;
        let m = frame.clip_from_model_within(&model, radius);
        (m, ScreenMap::new(&viewport, &Precision::DEFAULT), radius)
    }

    /// Points within `radius` of the origin: on the sphere (where a plane's distance is least)
    /// in random directions, and inside it.
    fn points_in_sphere(rng: &mut crate::testing::XorShift, radius: u32) -> Vec<[i32; 3]> {
        (0..64)
            .map(|k| {
                let mut c = || (rng.next_u64() % 20_001) as f64 / 1e4 - 1.0;
                let d = [c(), c(), c()];
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt().max(1e-9);
                let r = radius as f64 * if k % 4 == 0 { c().abs() } else { 1.0 };
                // Rounded toward the origin: within the radius.
                d.map(|v| (v / len * r).trunc() as i32)
            })
            .collect()
    }

    /// Case T18's rule on the near plane and the guard band's, for whole objects: where
    /// `known` finds a mesh's sphere inside every plane, every point within it projects inside
    /// every plane, to the point and depth the per-vertex path gives (which the vertex stage
    /// then skips); where it finds the projection in words, its operands fit them. Both hold
    /// for the reference scene (the torus, radius 1.4, seen from 2.6 units with the near plane
    /// at 1.0; in words only without snapping) and for many random views, and fail for many
    /// others.
    #[test]
    fn t18_sphere_inside_every_plane_means_every_vertex_inside() {
        let mut rng = crate::testing::XorShift(0xD1B5_4A32_D192_ED03u64);
        let (mut held, mut in_words, mut failed, mut split) = (0, 0, 0, 0);
        for _ in 0..4000 {
            let (m, map, radius) = random_view(&mut rng);
            let known = map.known(&m, radius);
            if !m.fits_32_bits(radius) || known == Known::Nothing {
                failed += 1;
                continue;
            }
            held += 1;
            in_words += (known == Known::InWords) as u32;
            // The Cortex-M0's transform in words, where the matrix allows it.
            let h = m.split_transform(radius);
            split += (h.is_some() && known == Known::InWords) as u32;
            for p in points_in_sphere(&mut rng, radius) {
                let c = m.transform_short(p);
                let tested = outcode_and_project(c, &map, true, Known::Nothing);
                assert_eq!(tested.0, 0, "{m:?} {radius} {p:?}");
                assert_eq!(outcode_and_project(c, &map, true, known), tested);
                if known == Known::InWords {
                    let (xh, yh) = map.viewport_products(c[0], c[1]);
                    let word = |v: i64| i32::try_from(v).is_ok();
                    assert!(word(xh) && word(yh) && 0 < c[3] && c[3] < 1 << 19, "{c:?}");
                    // Its path for such vertices: the same point and depth.
                    if let Some(h) = &h {
                        let (pt, z) = project_words(h.transform_words(p), &map);
                        assert_eq!((0, pt, z), tested, "{m:?} {radius} {p:?}");
                    }
                }
            }
        }
        assert!(in_words > 50 && held > in_words + 500 && failed > 500);
        assert!(split > 50, "{split}");
        assert!(held > 500 && failed > 500, "{held} {failed}");
        // The reference scene's torus and view (docs/reference-scene.md).
        use crate::camera::LookAt;
        use crate::math::{Angle, Scalar, Vec3};
        use crate::mesh::{torus, torus_counts, Mesh};
        use crate::projection::Projection;
        let (nv, nt) = torus_counts(48, 24);
        let (mut p, mut n, mut t) = (vec![Vec3::ZERO; nv], vec![Vec3::ZERO; nv], vec![[0; 3]; nt]);
        let s = Scalar::from_num;
        let mesh = torus(s(1.0), s(0.4), 48, 24, &mut p, &mut n, &mut t).unwrap_or(Mesh::EMPTY);
        let viewport = Viewport::new(320, 240).unwrap_or_else(|_| unreachable!());
        let view = LookAt::new(Vec3::new(s(0.0), s(0.0), s(2.6)), Vec3::ZERO, Vec3::Y).view();
        let projection =
            Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(1.0), s(10.0));
        let (Ok(view), Ok(projection)) = (view, projection) else {
            unreachable!()
        };
        let model =
            Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::rotation_x(Angle::from_degrees(20));
        let m = super::super::Frame::new(&view, &projection, viewport)
            .clip_from_model_within(&model, mesh.extent());
        let map = ScreenMap::new(&viewport, &Precision::DEFAULT);
        assert_eq!(mesh.radius(), 91751);
        assert!(m.fits_32_bits(mesh.extent()));
        assert_eq!(map.known(&m, mesh.radius()), Known::InWords);
        // Snapped to coarser sub-pixels, its vertices are inside, but not projected in words.
        let coarse = ScreenMap::new(&viewport, &Precision::DEFAULT.with_subpixel_bits(2));
        assert_eq!(coarse.known(&m, mesh.radius()), Known::Inside);
    }

    /// The written-out outcode is the one `distance` and `inside` define, plane by plane.
    #[test]
    fn outcode_matches_the_plane_definitions() {
        let map = map_320x240();
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..100_000 {
            let mut c = [0i64; 4];
            for v in &mut c {
                let x = rng.next_u64();
                *v = (x as i64) >> (x % 60);
            }
            let r = reduce(c);
            let expected = (0..PLANES).fold(0u8, |code, k| {
                if inside(k, distance(k, &r, &map)) {
                    code
                } else {
                    code | (1 << k)
                }
            });
            let general = outcode_and_project(c, &map, false, Known::Nothing);
            assert_eq!(general.0, expected, "{c:?}");
            assert_eq!(outcode_and_project_by_planes(c, &map), general, "{c:?}");
            if c.iter().all(|v| below_bits(*v, 31)) {
                assert_eq!(
                    outcode_and_project(c, &map, true, Known::Nothing).0,
                    expected,
                    "{c:?}"
                );
            }
        }
    }

    /// A vertex inside every plane projects in 32-bit words where `project` takes 64: the
    /// same point and depth, for vertices all over the guard band and the depth range, at
    /// every scale of w.
    #[test]
    fn inside_vertices_project_as_project_does() {
        let map = map_320x240();
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let (mut inside, mut widest) = (0, 0);
        for i in 0..200_000u32 {
            let w = (rng.next_u64() >> (34 + i % 30)) as i64 + 1;
            let mut coordinate = |range: i64| {
                let x = rng.next_u64() as i64;
                x.rem_euclid(2 * range + 1) - range
            };
            // Out to the guard band and past it (GUARD over half the viewport: 12.8w, 17.05w).
            let (x, y) = (coordinate(w * 13), coordinate(w * 18));
            let z = coordinate(w).abs();
            let c = [x, y, z, w];
            let (code, p, depth) = outcode_and_project(c, &map, false, Known::Nothing);
            assert_eq!(
                outcode_and_project_by_planes(c, &map),
                (code, p, depth),
                "{c:?}"
            );
            if code == 0 {
                assert_eq!(project(c, &map), Some((p, depth)), "{c:?}");
                inside += 1;
                widest = widest.max((p.x - 2560).abs()).max((p.y - 1920).abs());
            }
        }
        // Offsets reach the guard band's edge (GUARD: 16368 sub-pixels).
        assert!(inside > 40_000 && widest > 16_300, "{inside} {widest}");
    }

    /// A vertex inside every plane lies within `GUARD` sub-pixels of the screen centre at every
    /// snapping (the triangle walk's area in words relies on it), out to that edge.
    #[test]
    fn inside_vertices_lie_within_the_guard_band_at_every_snapping() {
        let viewport = Viewport::new(320, 240).unwrap_or_else(|_| unreachable!());
        let mut rng = crate::testing::XorShift(0xD1B5_4A32_D192_ED03u64);
        for bits in 0..=4 {
            let map = ScreenMap::new(&viewport, &Precision::DEFAULT.with_subpixel_bits(bits));
            let mut widest = 0;
            for i in 0..50_000u32 {
                let w = (rng.next_u64() >> (34 + i % 30)) as i64 + 1;
                let mut coordinate = |range: i64| {
                    let x = rng.next_u64() as i64;
                    x.rem_euclid(2 * range + 1) - range
                };
                // Out to the guard band and past it (GUARD over half the viewport: 12.8w, 17.05w).
                let c = [
                    coordinate(w * 13),
                    coordinate(w * 18),
                    coordinate(w).abs(),
                    w,
                ];
                let (code, p, _) = outcode_and_project(c, &map, false, Known::Nothing);
                if code == 0 {
                    let offset = (p.x - 2560).abs().max((p.y - 1920).abs()) as i64;
                    assert!(offset <= GUARD, "{bits} {c:?} {p:?}");
                    widest = widest.max(offset);
                }
            }
            assert!(widest > GUARD - 64, "{bits} {widest}");
        }
    }
}

//! The vertex stage: model space → clip space → screen (once per vertex per frame), with the
//! outcodes that decide which triangles need clipping.
//!
//! Clip-space coordinates are raw Q16.16 in 64 bits (below 2⁴⁸ in magnitude). Before any product
//! they are *reduced*: shifted right together until all four fit in 31 bits, which changes no
//! ratio that matters and keeps every product below 2⁶². In practice (coordinates below 32768)
//! nothing is shifted.

use super::Precision;
use crate::math::{
    below_bits, div_round, magnitude_bits, mul_short, shr_round, DivideBy, ShortQuotients,
    DEPTH_ONE, NARROW_CORE,
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

    /// `x·half_w` and `y·half_h` of reduced coordinates (below 2³¹; half sizes at most 2¹⁴,
    /// viewports being at most 2048 pixels): 32-bit factors, the second short.
    #[inline(always)]
    fn viewport_products(&self, x: i64, y: i64) -> (i64, i64) {
        (
            mul_short(x as i32, self.half_w as i32),
            mul_short(y as i32, self.half_h as i32),
        )
    }
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
/// to lie strictly within ±2³¹ (see `Mat4::fits_32_bits`): nothing to reduce.
// In line on cores with a long multiply, where the vertex loop calls it on its path from a
// transform known to fit 32 bits (the coordinates stay in registers: the Cortex-M4's frame 1.6%
// fewer instructions); on the others at the compiler's choice (forced: Cortex-M0 0.6% more).
#[cfg_attr(
    not(all(target_pointer_width = "32", not(target_has_atomic = "32"))),
    inline(always)
)]
#[cfg_attr(
    all(target_pointer_width = "32", not(target_has_atomic = "32")),
    inline
)]
pub(crate) fn outcode_and_project(
    c: [i64; 4],
    m: &ScreenMap,
    fits: bool,
) -> (u8, ScreenPoint, i32) {
    let [x, y, z, w] = if fits { c } else { reduce(c) };
    let (xh, yh) = m.viewport_products(x, y);
    let code = outcode_reduced(z, w, xh, yh);
    if code != 0 {
        return (code, ScreenPoint::default(), 0);
    }
    if m.snap != 0 {
        let (p, depth) = project_reduced(xh, yh, z, w, m).unwrap_or_default();
        return (code, p, depth);
    }
    // Inside every plane: 0 < z ≤ w, and |x·half_w|, |y·half_h| ≤ GUARD·w, so both offsets
    // from the centre are at most GUARD (the rounded quotient of at most GUARD·w by w) and the
    // depth lies in [0, 2³⁰]. With half sizes at most 2¹⁴ (viewports up to 2048 pixels) the
    // screen position lies within ±(2¹⁴ + GUARD), which is ±PIPELINE_LIMIT: `project`'s clamps
    // would change nothing, and every result fits a 32-bit word.
    let (qx, qy, sz) = if NARROW_CORE {
        // Without a divide instruction: short quotients by w in words (w below 2²⁹, every
        // ordinary scene; 6% of the Cortex-M0's frame) instead of a reciprocal to 32 bits,
        // their numerators within the band and the planes as they require (untested there).
        match ShortQuotients::new32(w as u32) {
            Some(by_w) => (
                by_w.round(xh) as i64,
                by_w.round(yh) as i64,
                by_w.round_fraction(z),
            ),
            None => (div_round(xh, w), div_round(yh, w), div_round(z << 30, w)),
        }
    } else {
        let by_w = DivideBy::new_positive32(w as i32);
        let (qx, qy) = (by_w.round_i32(xh), by_w.round_i32(yh));
        (qx, qy, by_w.round_fraction(z))
    };
    let sx = (m.half_w as i32).wrapping_add(qx as i32);
    let sy = (m.half_h as i32).wrapping_sub(qy as i32);
    (code, ScreenPoint::new(sx, sy), sz as i32)
}

/// [`outcode_and_project`] where the vertex loop does not take its in-line path for coordinates
/// known to fit: on 32-bit cores with a long multiply by [`outcode_and_project_by_planes`], no
/// second copy of the hot path (the M4's flash: 480 bytes less; on x86-64 the same call
/// measured 0.7% more instructions in the default build, so it keeps the general one).
#[inline(always)]
pub(crate) fn outcode_and_project_unfit(
    c: [i64; 4],
    m: &ScreenMap,
    fits: bool,
) -> (u8, ScreenPoint, i32) {
    #[cfg(all(target_pointer_width = "32", target_has_atomic = "32"))]
    {
        let _ = fits;
        outcode_and_project_by_planes(c, m)
    }
    #[cfg(not(all(target_pointer_width = "32", target_has_atomic = "32")))]
    outcode_and_project(c, m, fits)
}

/// [`outcode_and_project`] from its definitions: [`distance`] and [`inside`] for each plane of
/// the reduced coordinates, then [`project`] (the clipper's code).
#[cfg(any(test, doc, all(target_pointer_width = "32", target_has_atomic = "32")))]
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

/// [`project`] of reduced coordinates, from `x·half_w`, `y·half_h`, `z` and `w`. Out of line on
/// Cortex-M0, where only clipped vertices and coarser snapping reach it: in line, the vertex
/// loop's registers moved around it (0.2% more instructions per frame).
#[cfg_attr(
    not(all(target_pointer_width = "32", not(target_has_atomic = "32"))),
    inline(always)
)]
#[cfg_attr(
    all(target_pointer_width = "32", not(target_has_atomic = "32")),
    inline(never)
)]
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
        (by_w.round_i32(xh), by_w.round_i32(yh))
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

    /// The screen map of a 320x240 viewport at the default precision.
    fn map_320x240() -> ScreenMap {
        let viewport = Viewport::new(320, 240).unwrap_or_else(|_| unreachable!());
        ScreenMap::new(&viewport, &Precision::DEFAULT)
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
            let general = outcode_and_project(c, &map, false);
            assert_eq!(general.0, expected, "{c:?}");
            assert_eq!(outcode_and_project_by_planes(c, &map), general, "{c:?}");
            if c.iter().all(|v| below_bits(*v, 31)) {
                assert_eq!(outcode_and_project(c, &map, true).0, expected, "{c:?}");
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
            let (code, p, depth) = outcode_and_project(c, &map, false);
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
                let (code, p, _) = outcode_and_project(c, &map, false);
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

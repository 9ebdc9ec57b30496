//! Attribute planes: depth and colour as linear functions of screen position through the three
//! snapped vertices (affine in screen space, which is exact for depth after projection).

use core::cell::Cell;

use super::{first_centre_from32, ScreenPoint};
use crate::math::{
    mul_short, DivideBy, ShortQuotients, NARROW_CORE, SUBPIXEL_BITS, SUBPIXEL_SCALE,
};

/// `v(x, y) = v0 + gx·(x − x0) + gy·(y − y0)` with x, y in sub-pixels, through the first
/// vertex `(x0, y0, v0)`, kept as its value at the centre of pixel (0, 0): the value at pixel
/// `(px, py)` is then that plus `px` and `py` pixel steps, with no vertex offsets to form.
///
/// Vertex values are scaled so that they stay below 2⁴⁵ in magnitude and vertex coordinates
/// within ±2¹⁵ (the guard band): the gradient numerators then stay below 2⁶², and the gradients
/// are rounded to the values' own unit. Evaluating at any pixel centre inside the triangle
/// errs by at most 2¹⁷ units (distance below 2¹⁷ sub-pixels times half a unit each way); the
/// products may wrap in between (the value at pixel (0, 0) may lie far outside the triangle),
/// but the sum is exact modulo 2⁶⁴ and the true result fits, so wrapping arithmetic returns it
/// exactly.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Plane {
    /// The value at the centre of pixel (0, 0), modulo 2⁶⁴.
    origin: i64,
    gx: i64,
    gy: i64,
}

impl Plane {
    /// The plane through `(p[i], v[i])` (see [`new_each`](Self::new_each)).
    #[inline]
    #[cfg(test)]
    pub(crate) fn new(p: &[ScreenPoint; 3], v: [i64; 3], area2: i64) -> Plane {
        let [plane] = Plane::new_each(p, [v], area2);
        plane
    }

    /// For each value set `v[k]`, the plane through `(p[i], v[k][i])`: the planes of one
    /// triangle, which share the division by its area. `area2` is the triangle's doubled signed
    /// area `(x1−x0)(y2−y0) − (x2−x0)(y1−y0)`, non-zero.
    pub(crate) fn new_each<const K: usize>(
        p: &[ScreenPoint; 3],
        v: [[i64; 3]; K],
        area2: i64,
    ) -> [Plane; K] {
        let [a, b, c] = *p;
        let (dx1, dy1) = (b.x as i64 - a.x as i64, b.y as i64 - a.y as i64);
        let (dx2, dy2) = (c.x as i64 - a.x as i64, c.y as i64 - a.y as i64);
        let by_area = AreaDivisor::new(area2);
        v.map(|v| {
            let (dv1, dv2) = (v[1].wrapping_sub(v[0]), v[2].wrapping_sub(v[0]));
            let nx = dv1.wrapping_mul(dy2).wrapping_sub(dv2.wrapping_mul(dy1));
            let ny = dx1.wrapping_mul(dv2).wrapping_sub(dx2.wrapping_mul(dv1));
            by_area.plane(a, v[0], nx, ny, 0)
        })
    }

    /// The plane through `(p[i], v[i] << shift)` with every `v[i]` in [0, 2³⁰] (depth in
    /// Q1.30, colour channels): the numerators from 32-bit differences and products, shifted
    /// once, the same values (exact, as their true values fit).
    #[inline]
    pub(crate) fn scaled(p: &[ScreenPoint; 3], v: [i32; 3], shift: u32, area2: i64) -> Plane {
        let [plane] = Plane::scaled_each(p, [v], shift, area2);
        plane
    }

    /// [`scaled`](Self::scaled) for each value set of `v`: the planes of one triangle, which
    /// share the division by its area.
    #[inline]
    pub(crate) fn scaled_each<const K: usize>(
        p: &[ScreenPoint; 3],
        v: [[i32; 3]; K],
        shift: u32,
        area2: i64,
    ) -> [Plane; K] {
        let by_area = AreaDivisor::new(area2);
        v.map(|v| {
            let (nx, ny) = Plane::numerators(p, v);
            by_area.plane(p[0], (v[0] as i64) << shift, nx, ny, shift)
        })
    }

    /// The numerators of the gradients along x and y of the plane through `(p[i], v[i])` (`v[1]`
    /// and `v[2]` within 2³⁰ of `v[0]`, coordinates within the pipeline's ±(2¹⁵ − 16)), over
    /// the doubled signed area: exact, within ±2⁴⁷, from 32-bit differences and short products.
    #[inline(always)]
    pub(crate) fn numerators(p: &[ScreenPoint; 3], v: [i32; 3]) -> (i64, i64) {
        let [a, b, c] = *p;
        // Value differences within ±2³⁰, coordinate differences below 2¹⁶ in magnitude:
        // `mul_short`'s second bound.
        let (dx1, dy1) = (b.x.wrapping_sub(a.x), b.y.wrapping_sub(a.y));
        let (dx2, dy2) = (c.x.wrapping_sub(a.x), c.y.wrapping_sub(a.y));
        let (dv1, dv2) = (v[1].wrapping_sub(v[0]), v[2].wrapping_sub(v[0]));
        let nx = mul_short(dv1, dy2).wrapping_sub(mul_short(dv2, dy1));
        let ny = mul_short(dv2, dx1).wrapping_sub(mul_short(dv1, dx2));
        (nx, ny)
    }

    /// [`numerators`](Self::numerators) of values in [0, 2¹⁴) (and coordinates within ±2¹⁵),
    /// in 32-bit words: each product lies within ±2³⁰, their difference within ±2³¹.
    #[inline(always)]
    pub(crate) fn short_numerators(p: &[ScreenPoint; 3], v: [i32; 3]) -> (i64, i64) {
        let [a, b, c] = *p;
        let (dx1, dy1) = (b.x.wrapping_sub(a.x), b.y.wrapping_sub(a.y));
        let (dx2, dy2) = (c.x.wrapping_sub(a.x), c.y.wrapping_sub(a.y));
        let (dv1, dv2) = (v[1].wrapping_sub(v[0]), v[2].wrapping_sub(v[0]));
        let nx = dv1.wrapping_mul(dy2).wrapping_sub(dv2.wrapping_mul(dy1));
        let ny = dv2.wrapping_mul(dx1).wrapping_sub(dv1.wrapping_mul(dx2));
        (nx as i64, ny as i64)
    }

    /// Gradient numerators `nx`, `ny` over the doubled signed area `area2`, as the same
    /// fractions over its magnitude (what a division rounding to nearest takes).
    #[inline(always)]
    pub(crate) fn over_positive_area(nx: i64, ny: i64, area2: i64) -> (i64, i64, i64) {
        if area2 < 0 {
            (nx.wrapping_neg(), ny.wrapping_neg(), area2.wrapping_neg())
        } else {
            (nx, ny, area2)
        }
    }

    /// The value at the centre of pixel `(px, py)`: the value at pixel (0, 0) and `px`, `py`
    /// pixel steps, modulo 2⁶⁴.
    #[inline]
    pub(crate) fn at(&self, px: i32, py: i32) -> i64 {
        let (along, down) = self.pixel_steps();
        self.origin
            .wrapping_add(along.wrapping_mul(px as i64))
            .wrapping_add(down.wrapping_mul(py as i64))
    }

    /// The exact changes of [`at`](Self::at) from one pixel to the next along a row and down a
    /// column (modulo 2⁶⁴, like `at` itself): walking by them reproduces `at` bit for bit.
    #[inline]
    pub(crate) fn pixel_steps(&self) -> (i64, i64) {
        let s = SUBPIXEL_SCALE as i64;
        (self.gx.wrapping_mul(s), self.gy.wrapping_mul(s))
    }

    /// The plane at the first pixel of each row's span, row after row from row `y`, for spans
    /// starting at or right of column `x_base`: see [`PlaneRows`].
    #[inline]
    pub(crate) fn rows(&self, x_base: i32, y: i32) -> PlaneRows {
        let (gx, gy) = self.pixel_steps();
        PlaneRows {
            at_row: self.at(x_base, y),
            gx,
            gy,
            x_base,
        }
    }

    /// The change from one pixel to the next along a row. Saturated: a gradient too steep to
    /// represent belongs to a triangle no row of which is two pixels wide.
    #[inline]
    pub(crate) fn step_x(&self) -> i64 {
        self.gx.saturating_mul(SUBPIXEL_SCALE as i64)
    }
}

/// Division by a triangle's doubled signed area, set up once for all its planes: gradient
/// numerators over the area become the same fractions over its magnitude, rounded to nearest.
struct AreaDivisor {
    by_area: DivideBy,
    negative: bool,
}

impl AreaDivisor {
    #[inline(always)]
    fn new(area2: i64) -> AreaDivisor {
        AreaDivisor {
            by_area: DivideBy::new(area2.wrapping_abs()),
            negative: area2 < 0,
        }
    }

    /// The plane through `a` (value `v0`) with gradient numerators `nx << shift`,
    /// `ny << shift` over the area.
    #[inline(always)]
    fn plane(&self, a: ScreenPoint, v0: i64, nx: i64, ny: i64, shift: u32) -> Plane {
        let (nx, ny) = if self.negative {
            (nx.wrapping_neg(), ny.wrapping_neg())
        } else {
            (nx, ny)
        };
        let (gx, gy) = (
            self.by_area.round(nx << shift),
            self.by_area.round(ny << shift),
        );
        // The centre of pixel (0, 0) in sub-pixels from the vertex.
        let half = SUBPIXEL_SCALE as i64 / 2;
        let (dx, dy) = (half - a.x as i64, half - a.y as i64);
        Plane {
            origin: v0
                .wrapping_add(gx.wrapping_mul(dx))
                .wrapping_add(gy.wrapping_mul(dy)),
            gx,
            gy,
        }
    }
}

/// A plane walked in 32-bit words, the form the span loops take: its steps from one pixel to
/// the next along a row (`sx`) and down a column (`sy`), each rounded once to the walk's unit,
/// and its value at a reference pixel beside the first vertex (the pixel whose column holds
/// the vertex, on the first row at or below it) from the vertex's own value and those steps,
/// kept as its value at pixel (0, 0) modulo 2³². The values walked are twice the plane's (for
/// vertex values `v` within 2³⁰ of each other) plus a `bias`.
///
/// Each rounded step errs by at most half a unit, so the value at pixel `(x, y)` errs from the
/// exact one by at most `(|x − x_r| + |y − y_r|) / 2 + 5/4` units: below 2¹² + 2 for the
/// pipeline's triangles (its pixels lie within 2¹² of a triangle's vertices). The walk depends
/// on nothing but the triangle, so a band draws what the whole frame draws.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct WordPlane {
    /// The walk's value at pixel (0, 0), modulo 2³².
    origin: i32,
    /// The step along a row.
    pub(crate) sx: i32,
    /// The step down a column.
    pub(crate) sy: i32,
}

/// The division by a triangle's doubled signed area (non-zero) that its [`WordPlane`]s share,
/// prepared once: short quotients on cores without a divide instruction, and a [`DivideBy`]
/// for the other cores (and for the steps short quotients decline).
pub(crate) struct AreaWalks {
    area: i64,
    short: Option<ShortQuotients>,
    /// The [`DivideBy`] of the area's magnitude, made by the first walk that needs it and kept
    /// for the triangle's other walks.
    by: Cell<Option<DivideBy>>,
}

impl AreaWalks {
    #[inline(always)]
    pub(crate) fn new(area: i64) -> AreaWalks {
        let short = if NARROW_CORE {
            ShortQuotients::new(area.wrapping_abs())
        } else {
            None
        };
        AreaWalks {
            area,
            short,
            by: Cell::new(None),
        }
    }

    /// The division by the area's magnitude `den`, prepared once.
    #[inline(always)]
    fn divide_by(&self, den: i64) -> DivideBy {
        match self.by.get() {
            Some(by) => by,
            None => {
                let by = DivideBy::new(den);
                self.by.set(Some(by));
                by
            }
        }
    }

    /// The walk of the plane through `(p[i], v[i] · 2^shift)` with `bias` added, for `v[1]` and
    /// `v[2]` within 2³⁰ of `v[0]` (depths and colour channels in [0, 2³⁰], or a texture
    /// coordinate's differences from vertex 0's with `v[0]` 0), in [0, 2¹⁴) where `shift` is 16
    /// or more; `None` where its steps do not fit 32 bits (a triangle nearly edge-on). Shifting
    /// the values rather than the numerators keeps those short (colour channels, with 6
    /// fraction bits, are shifted by 16).
    #[inline(always)]
    pub(crate) fn walk(
        &self,
        p: &[ScreenPoint; 3],
        v: [i32; 3],
        shift: u32,
        bias: i32,
    ) -> Option<WordPlane> {
        // Values below 2¹⁴ (shifted by 16 or more) give numerators within ±2³¹: their
        // products and difference fit words, where wide products take a routine on cores
        // without a long multiply.
        let (nx, ny) = if shift >= 16 {
            Plane::short_numerators(p, v)
        } else {
            Plane::numerators(p, v)
        };
        let (sx, sy) = word_steps(nx, ny, shift, self)?;
        let reference = Reference::of(p[0]);
        let offset = reference.offset(sx, sy);
        let at_ref = (v[0] << shift)
            .wrapping_mul(2)
            .wrapping_add(bias)
            .wrapping_add(offset);
        Some(reference.plane(at_ref, sx, sy))
    }

    /// [`walk`](Self::walk) whatever its steps: see [`WordPlane::wrapping`].
    #[inline(always)]
    pub(crate) fn walk_any(
        &self,
        p: &[ScreenPoint; 3],
        v: [i32; 3],
        shift: u32,
        bias: i32,
    ) -> WordPlane {
        match self.walk(p, v, shift, bias) {
            Some(walk) => walk,
            None => WordPlane::wrapping(p, v, shift, bias, self.area),
        }
    }
}

impl WordPlane {
    /// The walk of one value set whatever its steps: those that do not fit 32 bits are kept
    /// modulo 2³², which the walk's sums are taken in (a value inside the triangle, within its
    /// bound of the exact one, still comes out exact). Through 64-bit divisions: for the few
    /// triangles [`AreaWalks::walk`] declines.
    #[cold]
    #[inline(never)]
    pub(crate) fn wrapping(
        p: &[ScreenPoint; 3],
        v: [i32; 3],
        shift: u32,
        bias: i32,
        area: i64,
    ) -> WordPlane {
        let (nx, ny) = Plane::numerators(p, v);
        let (nx, ny, den) = Plane::over_positive_area(nx, ny, area);
        // |n · 2^shift| < 2⁴⁸: the shifted numerators, the quotients and their products with
        // the offsets (within ±2⁴) stay far inside i64.
        let by = DivideBy::new(den);
        let (sx, sy) = (by.round(nx << shift << 5), by.round(ny << shift << 5));
        let reference = Reference::of(p[0]);
        let offset = sx
            .wrapping_mul(reference.dx as i64)
            .wrapping_add(sy.wrapping_mul(reference.dy as i64));
        let offset = offset.wrapping_add(SUBPIXEL_SCALE as i64 / 2) >> SUBPIXEL_BITS;
        let at_ref = ((v[0] as i64) << (shift + 1))
            .wrapping_add(bias as i64)
            .wrapping_add(offset);
        reference.plane(at_ref as i32, sx as i32, sy as i32)
    }

    /// The walk times 2^`bits`, modulo 2³² (its low `32 − bits` bits moved to the top).
    #[inline(always)]
    pub(crate) fn shifted_up(&self, bits: u32) -> WordPlane {
        WordPlane {
            origin: self.origin << bits,
            sx: self.sx << bits,
            sy: self.sy << bits,
        }
    }

    /// The walk's value at pixel `(x, y)`, modulo 2³².
    #[inline(always)]
    pub(crate) fn at(&self, x: i32, y: i32) -> i32 {
        self.origin
            .wrapping_add(self.sx.wrapping_mul(x))
            .wrapping_add(self.sy.wrapping_mul(y))
    }
}

/// A [`WordPlane`]'s reference pixel `(x, y)` for a first vertex, and its centre's offset
/// from the vertex in sub-pixels: `dx` in (−8, 8], `dy` in [0, 16).
struct Reference {
    x: i32,
    y: i32,
    dx: i32,
    dy: i32,
}

impl Reference {
    #[inline(always)]
    fn of(a: ScreenPoint) -> Reference {
        let (x, y) = (a.x >> SUBPIXEL_BITS, first_centre_from32(a.y));
        Reference {
            x,
            y,
            dx: x.wrapping_mul(SUBPIXEL_SCALE) + SUBPIXEL_SCALE / 2 - a.x,
            dy: y.wrapping_mul(SUBPIXEL_SCALE) + SUBPIXEL_SCALE / 2 - a.y,
        }
    }

    /// `⌊(sx·dx + sy·dy + 8) / 16⌋` modulo 2³²: the change of a walk with steps `sx`, `sy` from
    /// the vertex to this pixel's centre, rounded to the walk's unit. In words: with `s = 16q +
    /// r` (`0 ≤ r < 16`) for each step, the sum is `16·(qx·dx + qy·dy) + (rx·dx + ry·dy)`, whose
    /// first part divides exactly (and is wanted modulo 2³² only) and whose second lies within
    /// ±2⁹.
    #[inline(always)]
    fn offset(&self, sx: i32, sy: i32) -> i32 {
        let half = SUBPIXEL_SCALE / 2;
        let (qx, rx) = (sx >> SUBPIXEL_BITS, sx & (SUBPIXEL_SCALE - 1));
        let (qy, ry) = (sy >> SUBPIXEL_BITS, sy & (SUBPIXEL_SCALE - 1));
        let whole = qx
            .wrapping_mul(self.dx)
            .wrapping_add(qy.wrapping_mul(self.dy));
        let part = (rx * self.dx + ry * self.dy + half) >> SUBPIXEL_BITS;
        whole.wrapping_add(part)
    }

    /// The walk with value `at_ref` here and steps `sx`, `sy`, as its value at pixel (0, 0).
    #[inline(always)]
    fn plane(&self, at_ref: i32, sx: i32, sy: i32) -> WordPlane {
        WordPlane {
            origin: at_ref
                .wrapping_sub(sx.wrapping_mul(self.x))
                .wrapping_sub(sy.wrapping_mul(self.y)),
            sx,
            sy,
        }
    }
}

/// The steps `round(32·n·2^shift / area)` of gradient numerators over the doubled signed area
/// (per pixel, 16 sub-pixels, in units of half the shifted values'), where both fit an i32.
/// On cores without a divide instruction, for the usual triangle (a doubled area below 2²⁹,
/// steps below 2³⁰), by two 15-bit digits each through the walks' short quotients, the area's
/// magnitude prepared (fewer instructions than through a reciprocal to 32 bits); elsewhere by
/// the triangle's [`DivideBy`], made by the first walk that needs it.
#[inline(always)]
fn word_steps(nx: i64, ny: i64, shift: u32, walks: &AreaWalks) -> Option<(i32, i32)> {
    let (nx, ny, den) = Plane::over_positive_area(nx, ny, walks.area);
    let shift = shift + 5;
    if let Some(by) = &walks.short {
        if let (Some(sx), Some(sy)) = (
            by.round_below_2_30(nx << shift),
            by.round_below_2_30(ny << shift),
        ) {
            return Some((sx, sy));
        }
    }
    let by = walks.divide_by(den);
    Some((
        by.round_shifted_i32(nx, shift)?,
        by.round_shifted_i32(ny, shift)?,
    ))
}

/// Walks a [`Plane`] down the rows, for a span loop that starts each row's span from the
/// plane's value at its first pixel: [`at`](RowStarts::at) is that value on the current row
/// (in the form the loop takes: [`PlaneRows`] gives [`Plane::at`] itself, bit for bit modulo
/// 2⁶⁴), [`next_row`](RowStarts::next_row) moves down one row.
pub(crate) trait RowStarts {
    /// What the span loop starts from.
    type Start: Copy;
    /// The value at column `x` (at or right of the base column) of the current row.
    fn at(&self, x: i32) -> Self::Start;
    /// Moves to the next row.
    fn next_row(&mut self);
}

/// [`RowStarts`] in 64 bits: the plane's own value.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PlaneRows {
    /// The plane at the base column of the current row.
    at_row: i64,
    gx: i64,
    gy: i64,
    x_base: i32,
}

impl RowStarts for PlaneRows {
    type Start = i64;

    #[inline(always)]
    fn at(&self, x: i32) -> i64 {
        let dx = x.wrapping_sub(self.x_base) as i64;
        self.at_row.wrapping_add(self.gx.wrapping_mul(dx))
    }

    #[inline(always)]
    fn next_row(&mut self) {
        self.at_row = self.at_row.wrapping_add(self.gy);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The offset in words is the wide one modulo 2³², for steps across i32 and every offset
    /// within a pixel.
    #[test]
    fn reference_offset_in_words_is_the_wide_one() {
        let mut rng = crate::testing::XorShift(0xA54F_F53A_5F1D_36F1u64);
        let steps = [
            0,
            1,
            -1,
            15,
            -16,
            i32::MAX,
            i32::MIN,
            i32::MAX - 7,
            i32::MIN + 9,
        ];
        for k in 0..200_000usize {
            let pick = |j: usize, r: u64| match steps.get((k + j) % 40) {
                Some(&s) => s,
                None => r as i32,
            };
            let (sx, sy) = (pick(0, rng.next_u64()), pick(3, rng.next_u64()));
            let vertex = ScreenPoint::new(rng.within(1 << 14), rng.within(1 << 14));
            let reference = Reference::of(vertex);
            let wide = (sx as i64 * reference.dx as i64 + sy as i64 * reference.dy as i64 + 8) >> 4;
            assert_eq!(
                reference.offset(sx, sy),
                wide as i32,
                "{sx} {sy} {vertex:?}"
            );
        }
    }

    /// Triangles and vertex values for the numerator tests: every combination of the
    /// coordinate range's corners with the four `corners` values, then random ones (values from
    /// `random`).
    fn numerator_cases(
        corners: [i32; 4],
        seed: u64,
        mut random: impl FnMut(&mut crate::testing::XorShift) -> i32,
    ) -> impl Iterator<Item = ([ScreenPoint; 3], [i32; 3])> {
        let coordinates = [-(1 << 15), 1 << 15, 0, 1];
        let mut rng = crate::testing::XorShift(seed);
        (0..100_000usize).map(move |k| {
            if k < 4usize.pow(6) {
                let c = |j: u32| coordinates[k / 4usize.pow(j) % 4];
                let p = [0, 2, 4].map(|j| ScreenPoint::new(c(j), c(j + 1)));
                (p, [0, 1, 2].map(|j| corners[(k + j) % 4]))
            } else {
                let p = [(); 3].map(|_| ScreenPoint::new(rng.within(1 << 15), rng.within(1 << 15)));
                (p, [(); 3].map(|_| random(&mut rng)))
            }
        })
    }

    /// Values below 2¹⁴ give the same numerators in words, at the corners of the range and at
    /// random.
    #[test]
    fn short_numerators_equal_the_wide_ones() {
        let cases = numerator_cases([0, (1 << 14) - 1, 1, 255], 0x6A09_E667_F3BC_C909, |rng| {
            rng.within(1 << 13) + (1 << 13) - 1
        });
        for (p, v) in cases {
            assert_eq!(
                Plane::short_numerators(&p, v),
                Plane::numerators(&p, v),
                "{p:?} {v:?}"
            );
        }
    }

    /// The numerators are the exact ones: at the corners of the range (coordinates ±2¹⁵,
    /// values 0 and 2³⁰, or differences of ±2³⁰ from 0) and at random.
    #[test]
    fn numerators_are_exact() {
        let cases = numerator_cases(
            [0, 1 << 30, 1, (1 << 30) - 1],
            0x9E37_79B9_7F4A_7C15,
            |rng| rng.within(1 << 29) + (1 << 29),
        );
        // And differences from a vertex 0 of 0 (a texture coordinate's), of either sign.
        let differences = numerator_cases(
            [-(1 << 30), 1 << 30, -1, (1 << 30) - 1],
            0xBB67_AE85_84CA_A73B,
            |rng| rng.within(1 << 30),
        )
        .map(|(p, v)| (p, [0, v[1], v[2]]));
        for (p, v) in cases.chain(differences) {
            let exact = (
                (v[1] - v[0]) as i64 * (p[2].y - p[0].y) as i64
                    - (v[2] - v[0]) as i64 * (p[1].y - p[0].y) as i64,
                (v[2] - v[0]) as i64 * (p[1].x - p[0].x) as i64
                    - (v[1] - v[0]) as i64 * (p[2].x - p[0].x) as i64,
            );
            assert_eq!(Plane::numerators(&p, v), exact, "{p:?} {v:?}");
        }
    }

    /// `scaled` is `new` of the shifted values, bit for bit: coordinates across ±2¹⁵, values
    /// across [0, 2³⁰], both signs of area, the shifts the pipeline uses.
    #[test]
    fn scaled_equals_new() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let mut planes = 0;
        for _ in 0..200_000 {
            let scale = rng.pick(&[1 << 5, 1 << 10, 1 << 15]);
            let p = rng.triangle(ScreenPoint::default(), scale);
            let area = crate::raster::doubled_area(p[0], p[1], p[2]);
            if area == 0 {
                continue;
            }
            let v = [(); 3].map(|_| rng.within(1 << 29) + (1 << 29));
            for shift in [14, 28] {
                let wide = Plane::new(&p, v.map(|v| (v as i64) << shift), area);
                let short = Plane::scaled(&p, v, shift, area);
                assert_eq!(
                    (short.origin, short.gx, short.gy),
                    (wide.origin, wide.gx, wide.gy),
                    "{p:?} {v:?} {shift}"
                );
            }
            planes += 1;
        }
        assert!(planes > 190_000);
    }
}

//! Textured paint: texture coordinates walked across a triangle to texels, each texel's
//! channels scaled by a light paint's colour into the target's channel depths.

use core::cell::Cell;

use embedded_graphics::pixelcolor::{IntoStorage, Rgb565, Rgb888, RgbColor};

use crate::math::{magnitude_bits, mul_short_u32, mul_wide_u32, DivideBy};
use crate::raster::{AreaWalks, Plane, ScreenPoint, Span, WordPlane};
use crate::texture::{
    rgb565_channels, texture_coords, Mapping, Sampler, Texture, COORD_BITS, SCALE_BITS,
};

use super::{Paint, PaintUser};

/// A triangle's texture coordinates, less vertex 0's, are held within ±2²⁹ (512 images
/// across): the perspective planes' values then stay below 2⁴⁶, and the walks' values, with
/// vertex 0's added, within ±2³¹ where a clamped texture needs them to be.
const SPREAD: i64 = 1 << 29;
/// [`SPREAD`] as a UV difference (Q16.16).
const SPREAD_UV: i32 = (SPREAD >> (COORD_BITS - 16)) as i32;
/// Vertex weights `q ∝ 1/w` are scaled so that the largest lies in [2¹⁶, 2¹⁷).
const Q_BITS: u32 = 16;
/// The denominator plane carries `q` shifted by this (its values below 2⁴¹).
const Q_PLANE_SHIFT: u32 = 24;
/// A coordinate walk's values are twice a [`WordPlane`]'s values, shifted by this: UV
/// differences in Q16.16 become texture coordinates.
const WALK_SHIFT: u32 = COORD_BITS - 17;

/// A texture across one triangle, lit by `light` (a [`SolidPaint`](super::SolidPaint) or a
/// [`SmoothPaint`](super::SmoothPaint) of 8-bit light colours: white shows the texel as it
/// is), in the target's channel depths.
#[derive(Clone, Debug)]
pub struct TexturePaint<'t, L> {
    sampler: &'t Sampler<'t>,
    light: L,
    /// A solid light's scales (see [`Sampler::lit`]); for another light, per channel, the gain
    /// from the texels' depth to the target's (see [`Sampler::gains`]), which each pixel's light
    /// scales.
    scale: [u32; 3],
    /// Vertex 0's texture coordinates.
    base: [i32; 2],
    coords: Coords,
}

/// How a [`TexturePaint`]'s coordinates run across its triangle.
#[derive(Clone, Debug)]
enum Coords {
    /// Affine: each coordinate walked in 32-bit words, as depth is.
    Walks([WordPlane; 2]),
    /// Perspective: `(c − c₀)·q` for each coordinate, and `q << Q_PLANE_SHIFT`; and the span
    /// being drawn (one at a time: its cursor borrows the paint).
    Perspective([Plane; 3], Cell<Runs>),
}

impl<'t, L: Paint> TexturePaint<'t, L> {
    /// `texture` across the triangle `p` (doubled signed area `area2`) with raw Q16.16 UVs
    /// `uv`, in channels whose largest values are `depths`. For a perspective projection,
    /// `depths_for_q` gives the vertex depths (Q1.30) and the offset `1/w` is proportional to
    /// after subtracting them (see `FaceInputs::inverse_w_offset`); `None` for an orthographic
    /// one.
    pub(crate) fn new(
        texture: &'t Texture<'t>,
        p: &[ScreenPoint; 3],
        uv: &[[i32; 2]; 3],
        depths_for_q: Option<(i64, [i32; 3])>,
        area2: i64,
        (light, depths): (L, [u8; 3]),
    ) -> Self {
        let sampler = Sampler::of(texture);
        let [u0, v0] = uv[0];
        let base = texture_coords(u0, v0, sampler.repeats());
        // Differences from vertex 0 (t runs down: 1 − v), Q16.16, held within the spread: in
        // [−2²⁵, 2²⁵), a signed 26-bit range, which one saturating instruction clamps to.
        // Written out: at the firmware's opt-level "s" an array's `map` stays a loop.
        let [_, [ua, va], [ub, vb]] = *uv;
        let d = |from: i32, to: i32| to.saturating_sub(from).clamp(-SPREAD_UV, SPREAD_UV - 1);
        let (s1, s2, t1, t2) = (d(u0, ua), d(u0, ub), d(va, v0), d(vb, v0));
        let gains = sampler.gains(depths);
        let perspective = match (texture.mapping(), depths_for_q) {
            (Mapping::Perspective, Some((offset, z)))
                if !nearly_affine(offset, z, texel_range([s1, s2], [t1, t2], sampler)) =>
            {
                Some((offset, z))
            }
            _ => None,
        };
        // Built in place: the affine walks (most triangles') written where they go, and the
        // perspective variant, far larger, only where needed.
        let mut paint = TexturePaint {
            sampler,
            scale: match light.solid().filter(|_| L::SOLID) {
                Some(solid) => scales(solid, gains),
                None => gains,
            },
            light,
            base,
            coords: Coords::Walks(if perspective.is_none() {
                let by_area = AreaWalks::new(area2);
                [
                    coordinate_walk(&by_area, p, (s1, s2), base[0]),
                    coordinate_walk(&by_area, p, (t1, t2), base[1]),
                ]
            } else {
                [WordPlane::default(); 2]
            }),
        };
        if let Some((offset, z)) = perspective {
            let q = weights(offset, z);
            let [q0, q1, q2] = q;
            // In texture coordinates, times the weights (vertex 0's difference is 0).
            let shift = COORD_BITS - 16;
            let times_q =
                |d1: i32, d2: i32| [0, i64::from(d1 << shift) * q1, i64::from(d2 << shift) * q2];
            let den = [q0, q1, q2].map(|q| q << Q_PLANE_SHIFT);
            paint.coords = Coords::Perspective(
                Plane::new_each(p, [times_q(s1, s2), times_q(t1, t2), den], area2),
                Cell::new(Runs::default()),
            );
        }
        paint
    }
}

/// The walk of one texture coordinate whose vertex values are `base` plus `0`, `d1` and `d2`
/// (differences from vertex 0's, Q16.16, in [−2²⁵, 2²⁵)): the differences walked doubled and
/// shifted into texture coordinates, from vertex 0's own coordinate.
#[inline(always)]
fn coordinate_walk(
    by_area: &AreaWalks,
    p: &[ScreenPoint; 3],
    (d1, d2): (i32, i32),
    base: i32,
) -> WordPlane {
    by_area.walk_any(p, [0, d1, d2], WALK_SHIFT, base)
}

/// The weights `q ∝ 1/w` of vertices at depths `z` (`offset − z`, positive), scaled so that
/// the largest lies in [2^[`Q_BITS`], 2^([`Q_BITS`] + 1)) (each at least 1).
fn weights(offset: i64, z: [i32; 3]) -> [i64; 3] {
    let q = z.map(|z| offset.saturating_sub(i64::from(z)).max(1));
    let shift = magnitude_bits(&q) as i32 - Q_BITS as i32 - 1;
    q.map(|v| {
        let v = if shift > 0 {
            v >> shift
        } else {
            v << (-shift) as u32
        };
        v.max(1)
    })
}

/// The larger of a triangle's texture coordinate ranges along the two axes (vertex 0's
/// coordinate among them), in texels (Q16.16), saturated to 32 bits, from the differences
/// from vertex 0's UV (Q16.16): `[s1, s2]` across the image, `[t1, t2]` down it.
fn texel_range([s1, s2]: [i32; 2], [t1, t2]: [i32; 2], sampler: &Sampler<'_>) -> u32 {
    // Vertex 0's difference is 0: the range runs from at most 0 to at least 0.
    let range = |a: i32, b: i32| a.max(b).max(0).abs_diff(a.min(b).min(0));
    let (width, height) = sampler.sides();
    // A side is at most 2¹²: two short products.
    let texels =
        mul_short_u32(width as i32, range(s1, s2)).max(mul_short_u32(height as i32, range(t1, t2)));
    u32::try_from(texels).unwrap_or(u32::MAX)
}

/// True when mapping the triangle linearly errs by less than 1/8 texel anywhere in it, for
/// vertices at depths `z` (weights `q = offset − z ∝ 1/w`) and texture coordinates that span
/// at most `range` texels (Q16.16) along either axis. The perspective map's value is
/// `Σλᵢqᵢsᵢ / Q` with `Q = Σλᵢqᵢ`, the linear map's `Σλᵢsᵢ`. They differ by
/// `Σλᵢsᵢ(qᵢ − Q) / Q`, which is `Σλᵢ(sᵢ − c)(qᵢ − Q) / Q` for any `c` (as `Σλᵢ(qᵢ − Q) = 0`):
/// with `c` the middle of the coordinates' range, at most `range / 2 · Σλᵢ|qᵢ − Q| / Q`. The
/// mean deviation `Σλᵢ|qᵢ − Q|` of weights between `a = q_min` and `b = q_max` whose mean is
/// `Q` is at most `2(Q − a)(b − Q) / (b − a)`, and that over `Q` at most
/// `2(√b − √a)² / (b − a) ≤ (b − a) / (2a)`: the error is below `range · (b − a) / (4a)`.
/// Equal weights (a triangle facing the camera) are affine.
fn nearly_affine(offset: i64, z: [i32; 3], range: u32) -> bool {
    let (near, far) = (z[0].min(z[1]).min(z[2]), z[0].max(z[1]).max(z[2]));
    // b − a is the depth range (below 2³²), a = offset − far.
    let depths = far.wrapping_sub(near) as u32;
    // A projection's offset and a depth are far inside i64: no wrap.
    let least = offset.wrapping_sub(i64::from(far)).max(1) as u64;
    // range · (b − a) · 2 < a · 2¹⁶: both sides divided by 2, then by 2¹⁵ (the left below
    // 2⁶⁴, floored: for a whole a, the same test).
    mul_wide_u32(range, depths) >> 15 < least
}

/// A perspective span's state: the planes at the next exact point, their steps, the pixels
/// after it, and the coordinates there.
#[derive(Clone, Copy, Debug, Default)]
struct Runs {
    acc: [i64; 3],
    step: [i64; 3],
    rest: u32,
    exact: [i32; 2],
}

/// The running texture coordinates of a [`TexturePaint`] along a span, and its light.
#[derive(Debug)]
pub struct TextureCursor<'p, 't, L: Paint> {
    paint: &'p TexturePaint<'t, L>,
    light: L::Cursor<'p>,
    /// Texture coordinates and their steps (wrapping: a repeating texture reads the
    /// fraction bits).
    c: [i32; 2],
    step: [i32; 2],
    /// Pixels the current run has left (perspective: at none, the next pixel starts the next
    /// run), or more than any span has.
    left: u32,
    /// The paint's scales (see [`TexturePaint`]), copied once a span (read at every pixel).
    scale: [u32; 3],
}

impl<L: Paint> TextureCursor<'_, '_, L> {
    /// Starts a perspective span (out of line: the usual span is affine, and its start is
    /// then a few instructions the span loop takes in line). Takes no reference to the cursor,
    /// which the span loop then keeps in registers.
    #[inline(never)]
    fn start_runs(
        paint: &TexturePaint<'_, L>,
        [ps, pt, pq]: &[Plane; 3],
        runs: &Cell<Runs>,
        span: Span,
    ) {
        let Span { y, x0, x1 } = span;
        let acc = [ps.at(x0, y), pt.at(x0, y), pq.at(x0, y)];
        runs.set(Runs {
            acc,
            step: [ps.step_x(), pt.step_x(), pq.step_x()],
            rest: x1.wrapping_sub(x0).max(0) as u32,
            exact: exact_at(paint, acc),
        });
    }

    /// The next run of at most the texture's run of pixels (see [`Texture::with_run`]):
    /// exact at both its ends, linear between. Returns the coordinates at its start, their
    /// steps and its length; takes no reference to the cursor, which the span loop then keeps
    /// in registers.
    #[inline(never)]
    fn next_run(paint: &TexturePaint<'_, L>) -> ([i32; 2], [i32; 2], u32) {
        let Coords::Perspective(_, cell) = &paint.coords else {
            return ([0; 2], [0; 2], u32::MAX);
        };
        let mut runs = cell.get();
        let n = runs.rest.clamp(1, u32::from(paint.sampler.run).max(1));
        runs.rest = runs.rest.saturating_sub(n);
        let k = i64::from(n);
        let [a0, a1, a2] = runs.acc;
        let [s0, s1, s2] = runs.step;
        runs.acc = [
            a0.wrapping_add(s0.wrapping_mul(k)),
            a1.wrapping_add(s1.wrapping_mul(k)),
            a2.wrapping_add(s2.wrapping_mul(k)),
        ];
        let start = runs.exact;
        let end = exact_at(paint, runs.acc);
        runs.exact = end;
        cell.set(runs);
        // The change along a run lies within ±2³⁰ (twice the spread at most).
        let step = |end: i32, start: i32| end.wrapping_sub(start) / n as i32;
        (start, [step(end[0], start[0]), step(end[1], start[1])], n)
    }
}

/// The affine coordinate walks at the first pixel of `span`, and their steps along it.
#[inline(always)]
fn walks_at([s, t]: &[WordPlane; 2], span: Span) -> ([i32; 2], [i32; 2]) {
    let Span { y, x0, .. } = span;
    ([s.at(x0, y), t.at(x0, y)], [s.sx, t.sx])
}

/// The texture coordinates at the perspective planes' values `acc`.
#[inline]
fn exact_at<L>(paint: &TexturePaint<'_, L>, acc: [i64; 3]) -> [i32; 2] {
    let [u, v, q] = acc;
    // (c − c₀) = U / q = U·2¹² / (Q >> 12), Q = q·2²⁴: every value below 2⁵⁹.
    let by = DivideBy::new((q >> 12).max(1));
    let limit = 1i64 << 46;
    let repeat = paint.sampler.repeats();
    let at = |n: i64, base: i32| {
        let d = by
            .round(n.clamp(-limit, limit) << 12)
            .clamp(-SPREAD, SPREAD);
        if repeat {
            (d as i32).wrapping_add(base)
        } else {
            // Within ±(2³⁰ + 2²⁹): beyond the same edge as the exact value.
            (d + i64::from(base)) as i32
        }
    };
    [at(u, paint.base[0]), at(v, paint.base[1])]
}

/// An 8-bit light's scales: its channels times the gains.
#[inline(always)]
fn scales(light: Rgb888, [r, g, b]: [u32; 3]) -> [u32; 3] {
    // A gain is at most 2²³ · 255 / 31 / 255 + 2 (see `gain`): times 255, below 2²⁷.
    [
        u32::from(light.r()) * r,
        u32::from(light.g()) * g,
        u32::from(light.b()) * b,
    ]
}

impl<L: Paint> Iterator for TextureCursor<'_, '_, L> {
    type Item = Rgb888;

    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        // One subtraction, whose borrow starts the next run (perspective only).
        let (left, ended) = self.left.overflowing_sub(1);
        self.left = left;
        if ended {
            let (c, step, n) = Self::next_run(self.paint);
            (self.c, self.step, self.left) = (c, step, n.wrapping_sub(1));
        }
        let paint = self.paint;
        let scale = if L::SOLID {
            self.scale
        } else {
            scales(self.light.next().unwrap_or(Rgb888::WHITE), paint.scale)
        };
        let [r, g, b] = paint.sampler.lit(self.c, scale);
        let [s, t] = self.c;
        let [ds, dt] = self.step;
        self.c = [s.wrapping_add(ds), t.wrapping_add(dt)];
        Some(Rgb888::new(r, g, b))
    }
}

impl<'t, L: Paint> Paint for TexturePaint<'t, L> {
    type Cursor<'p>
        = TextureCursor<'p, 't, L>
    where
        Self: 'p;
    const SCALED: bool = true;

    fn solid(&self) -> Option<Rgb888> {
        None
    }

    /// The tiled form where the texture and the mapping allow it (see [`TiledPaint`]).
    #[inline(always)]
    fn visit<U: PaintUser>(&self, user: U) -> U::Output {
        // The texels cut to the image's own (a texture holds at least those), here rather than
        // once in the sampler: the span loop then sees their number as the power of two it
        // masks an index by, and needs no bounds test (kept in the sampler, it measured slower).
        let tiled = self.sampler.tiled565().and_then(|(texels, [w, h])| {
            let texels = texels.get(..1usize << ((w + h) & 31))?;
            Some((texels, [w, h]))
        });
        match (&self.coords, tiled) {
            (Coords::Walks(walks), Some((texels, [width_bits, height_bits]))) => {
                user.with(&TiledPaint {
                    paint: self,
                    texels,
                    walks: [
                        walks[0].shifted_up(32 - COORD_BITS),
                        walks[1].shifted_up(32 - COORD_BITS),
                    ],
                    shifts: (32 - width_bits, 32 - height_bits, width_bits),
                    half: core::hint::black_box(1 << (SCALE_BITS - 1)),
                })
            }
            _ => user.with(self),
        }
    }

    #[inline(always)]
    fn cursor(&self, span: Span) -> Self::Cursor<'_> {
        let mut cursor = TextureCursor {
            paint: self,
            light: self.light.cursor(span),
            c: [0; 2],
            step: [0; 2],
            left: u32::MAX,
            scale: self.scale,
        };
        match &self.coords {
            Coords::Walks(walks) => (cursor.c, cursor.step) = walks_at(walks, span),
            Coords::Perspective(planes, runs) => {
                TextureCursor::start_runs(self, planes, runs, span);
                cursor.left = 0;
            }
        }
        cursor
    }
}

/// A [`TexturePaint`] in its tiled form, the usual one of firmware: a repeating Rgb565 texture
/// with sides of powers of two, read nearest and mapped affinely. Its coordinate walks carry
/// the fraction bits of the image at the top of a word, where they wrap round by themselves,
/// so that a texel's column and row are the top bits of each: its pixel is three shifts, one
/// read and the light's scales, with no texel format to match, no clamp and no perspective
/// run to end. It gives exactly the general form's colours.
#[derive(Debug)]
pub struct TiledPaint<'p, 't, L> {
    paint: &'p TexturePaint<'t, L>,
    /// The image's texels, exactly a power of two of them (see [`TiledCursor`]).
    texels: &'t [Rgb565],
    /// The coordinate walks shifted up to the top of a word.
    walks: [WordPlane; 2],
    /// See [`TiledCursor`].
    shifts: (u32, u32, u32),
    /// Half a unit of the scaled channels, a value the compiler does not see: held in a
    /// register, each channel's rounding then joins its multiply (one multiply-accumulate on
    /// cores that have it, where a constant took a multiply and an addition).
    half: u32,
}

/// The running texture coordinates and light of a [`TiledPaint`] along a span.
#[derive(Debug)]
pub struct TiledCursor<'p, L: Paint + 'p> {
    /// The image's texels, exactly a power of two of them: a texel's index, already below
    /// their number, is masked by it less one, which the compiler knows needs no bounds test.
    texels: &'p [Rgb565],
    /// Shifts from a coordinate (the image's fraction bits at the top of a word) down to its
    /// texel column and row (32 less the sides' bits, at most 31), and the row's up into an
    /// index (the width's bits).
    shifts: (u32, u32, u32),
    light: L::Cursor<'p>,
    /// The paint's scales or gains (see [`TexturePaint`]).
    scale: [u32; 3],
    /// Half a unit of the scaled channels, which rounds them (see [`TiledPaint`]).
    half: u32,
    c: [i32; 2],
    step: [i32; 2],
}

impl<'t, L: Paint> Paint for TiledPaint<'_, 't, L> {
    type Cursor<'q>
        = TiledCursor<'q, L>
    where
        Self: 'q;
    const SCALED: bool = true;

    fn solid(&self) -> Option<Rgb888> {
        None
    }

    #[inline(always)]
    fn cursor(&self, span: Span) -> Self::Cursor<'_> {
        let paint = self.paint;
        let (c, step) = walks_at(&self.walks, span);
        TiledCursor {
            texels: self.texels,
            shifts: self.shifts,
            light: paint.light.cursor(span),
            scale: paint.scale,
            half: self.half,
            c,
            step,
        }
    }
}

impl<L: Paint> Iterator for TiledCursor<'_, L> {
    type Item = Rgb888;

    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        let scale = if L::SOLID {
            self.scale
        } else {
            scales(self.light.next().unwrap_or(Rgb888::WHITE), self.scale)
        };
        let [s, t] = self.c;
        let (across, down, row) = self.shifts;
        // The shifts are below 32 (sides of 2 or more): they lose no bit they should keep.
        let i = ((t as u32).wrapping_shr(down) << row) | (s as u32).wrapping_shr(across);
        let raw = self
            .texels
            .get(i as usize & self.texels.len().wrapping_sub(1))
            .map_or([0; 3], |&c| rgb565_channels(c.into_storage()));
        // The scaling of `Sampler::lit`, written out in both: shared through a function, even
        // inlined, both loops compiled longer.
        let half = self.half;
        let ch = |k: usize| (raw[k].wrapping_mul(scale[k]).wrapping_add(half) >> SCALE_BITS) as u8;
        let [r, g, b] = [ch(0), ch(1), ch(2)];
        let [ds, dt] = self.step;
        self.c = [s.wrapping_add(ds), t.wrapping_add(dt)];
        Some(Rgb888::new(r, g, b))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::XorShift;
    use crate::texture::Texels;

    /// The largest gap between the linear and the perspective map (in texels) over a fine grid
    /// of points of the triangle, for weights `q` and coordinates `c` (texels, vertex 0's 0).
    fn largest_gap(q: [f64; 3], c: [f64; 3]) -> f64 {
        let n = 48;
        let mut largest = 0.0f64;
        for i in 0..=n {
            for j in 0..=n - i {
                let l = [i, j, n - i - j].map(|k| f64::from(k) / f64::from(n));
                let big_q: f64 = (0..3).map(|k| l[k] * q[k]).sum();
                let perspective: f64 = (0..3).map(|k| l[k] * q[k] * c[k]).sum::<f64>() / big_q;
                let linear: f64 = (0..3).map(|k| l[k] * c[k]).sum();
                largest = largest.max((perspective - linear).abs());
            }
        }
        largest
    }

    /// Wherever `nearly_affine` takes a triangle for affine, the linear map lies within 1/8
    /// texel of the perspective one at every point of a fine grid of it: random coordinates
    /// over up to four images each way and random weights, from equal to 33 times apart. A
    /// triangle whose coordinates all lie on one side of vertex 0's (a half of a grid's quad)
    /// passes at twice the depth range that the coordinates' largest distance from vertex 0's
    /// alone would allow.
    #[test]
    fn nearly_affine_triangles_err_below_an_eighth_of_a_texel() {
        let texels = [Rgb565::BLACK; 64 * 32];
        let texture = Texture::new(Texels::Rgb565(&texels), 64, 32).unwrap();
        let sampler = Sampler::of(&texture);
        let mut rng = XorShift(0x2545_F491_4F6C_DD1D);
        let (mut affine, mut tried) = (0, 0);
        for _ in 0..4_000 {
            let bits = rng.pick(&[8, 11, 14, 16, 18]);
            let mut uv = || rng.within(1 << bits);
            let ([s1, s2], [t1, t2]) = ([uv(), uv()], [uv(), uv()]);
            let far = 1 << rng.pick(&[20, 26, 29]);
            let spread = far >> rng.pick(&[1, 4, 7, 10, 13, 16]);
            let z = [0; 3].map(|_: i32| far - rng.within(spread).abs());
            let offset = i64::from(far) + i64::from(far >> rng.pick(&[0, 3, 6]));
            tried += 1;
            if !nearly_affine(offset, z, texel_range([s1, s2], [t1, t2], sampler)) {
                continue;
            }
            affine += 1;
            let q = z.map(|z| (offset - i64::from(z)) as f64);
            let texels = |d: [i32; 2], side: f64| {
                [
                    0.0,
                    f64::from(d[0]) * side / 65536.0,
                    f64::from(d[1]) * side / 65536.0,
                ]
            };
            let gap =
                largest_gap(q, texels([s1, s2], 64.0)).max(largest_gap(q, texels([t1, t2], 32.0)));
            assert!(
                gap < 0.125,
                "{gap} texels: {s1} {s2} {t1} {t2} {z:?} {offset}"
            );
        }
        assert!(
            affine > tried / 10 && affine < tried * 9 / 10,
            "{affine} of {tried}"
        );

        // Ten texels on one side of vertex 0's, weights 4% apart: the gap is under 1/8 texel,
        // and a bound from the largest distance alone (ten texels, half the relative range)
        // would be 0.2.
        let d = (1 << 30) / 25;
        let (offset, z) = (1i64 << 30, [0, 0, d]);
        let q = z.map(|z| (offset - i64::from(z)) as f64);
        let (a, b) = (q[2], q[0]);
        assert!(10.0 * (b - a) / (2.0 * a) > 0.2);
        assert!(largest_gap(q, [0.0, 10.0, 10.0]) < 0.125);
        let ten = 10 * 65536 / 64;
        assert!(nearly_affine(
            offset,
            z,
            texel_range([ten, ten], [0, 0], sampler)
        ));
        // Ten texels on either side: twenty across, and the bound no longer holds.
        assert!(!nearly_affine(
            offset,
            z,
            texel_range([ten, -ten], [0, 0], sampler)
        ));
    }
}

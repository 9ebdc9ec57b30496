//! Textured paint: UVs mapped across a triangle to texels, modulated by a light paint.

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use crate::math::{magnitude_bits, DivideBy};
use crate::raster::{Plane, ScreenPoint, Span};
use crate::texture::{Mapping, Sampler, Texture};

use super::Paint;

/// A triangle's texel coordinates, less vertex 0's, are held within ±2¹² texels (this many
/// bits in Q16.16): with the weights below, the planes' values stay below 2⁴⁵.
const SPREAD_BITS: u32 = 28;
/// Vertex weights `q ∝ 1/w` are scaled so that the largest lies in [2¹⁶, 2¹⁷).
const Q_BITS: u32 = 16;
/// The denominator plane carries `q` shifted by this (its values below 2⁴¹).
const Q_PLANE_SHIFT: u32 = 24;

/// A texture across one triangle, lit by `light` (a [`SolidPaint`](super::SolidPaint) or a
/// [`SmoothPaint`](super::SmoothPaint) of light colours: white shows the texel as it is).
#[derive(Clone, Copy, Debug)]
pub struct TexturePaint<'t, L> {
    sampler: Sampler<'t>,
    light: L,
    /// Vertex 0's texel coordinates (Q16.16), reduced into the image when it repeats.
    base: [i32; 2],
    /// Affine: `s − s₀`, `t − t₀` in Q16.32 (the third plane unused). Perspective:
    /// `(s − s₀)·q`, `(t − t₀)·q` and `q << Q_PLANE_SHIFT`.
    planes: [Plane; 3],
    perspective: bool,
    /// Affine: the steps along a row in Q16.16, reduced into the period when repeating
    /// (perspective: found for each run).
    step: [i32; 2],
}

/// `v` into [0, period) when repeating, else clamped to ±2²⁹ (so that a span's steps cannot
/// wrap it).
#[inline(always)]
fn reduce(v: i64, period: i32, repeat: bool) -> i32 {
    if repeat {
        // The pipeline's values fit 32 bits (see `TextureCursor::exact_at`).
        let v = v.clamp(i32::MIN as i64, i32::MAX as i64) as i32;
        v.rem_euclid(period.max(1))
    } else {
        v.clamp(-(1 << 29), 1 << 29) as i32
    }
}

/// A step along a row: into [0, period) when repeating (a whole period is no change), else
/// clamped to ±2¹⁹ (2048 of them stay within ±2³⁰).
#[inline(always)]
fn reduce_step(v: i64, period: i32, repeat: bool) -> i32 {
    if repeat {
        reduce(v, period, true)
    } else {
        v.clamp(-(1 << 19), 1 << 19) as i32
    }
}

impl<'t, L> TexturePaint<'t, L> {
    /// `texture` across the triangle `p` (doubled signed area `area2`) with raw Q16.16 UVs
    /// `uv` and weights `q ∝ 1/w` (positive; `None` for an orthographic projection).
    pub(crate) fn new(
        texture: &Texture<'t>,
        p: &[ScreenPoint; 3],
        uv: &[[i32; 2]; 3],
        q: Option<[i64; 3]>,
        area2: i64,
        light: L,
    ) -> Self {
        let sampler = Sampler::new(texture);
        let (width, height) = (i64::from(texture.width()), i64::from(texture.height()));
        // s = u·width, t = (1 − v)·height, Q16.16 texel units.
        let st = uv.map(|[u, v]| [i64::from(u) * width, ((1i64 << 16) - i64::from(v)) * height]);
        let [s0, t0] = st[0];
        let limit = 1i64 << SPREAD_BITS;
        let spread =
            st.map(|[s, t]| [(s - s0).clamp(-limit, limit), (t - t0).clamp(-limit, limit)]);
        let (periods, repeat) = (sampler.periods(), sampler.repeats());
        let base = [reduce(s0, periods.0, repeat), reduce(t0, periods.1, repeat)];
        let q = match (texture.mapping(), q) {
            (Mapping::Perspective, Some(q)) => scaled_weights(q),
            _ => None,
        };
        let extent = spread
            .iter()
            .flat_map(|v| v.iter())
            .fold(0i64, |m, v| m.max(v.abs()));
        let q = q.filter(|q| !nearly_affine(q, extent));
        let ds = |k: usize| spread.map(|v| v.get(k).copied().unwrap_or(0));
        let (planes, perspective) = match q {
            Some(q) => {
                let times_q = |v: [i64; 3]| [v[0] * q[0], v[1] * q[1], v[2] * q[2]];
                let den = q.map(|q| q << Q_PLANE_SHIFT);
                let planes = Plane::new_each(p, [times_q(ds(0)), times_q(ds(1)), den], area2);
                (planes, true)
            }
            None => {
                let [a, b] =
                    Plane::new_each(p, [ds(0).map(|v| v << 16), ds(1).map(|v| v << 16)], area2);
                ([a, b, Plane::default()], false)
            }
        };
        let step = |k: usize, period: i32| match planes.get(k) {
            Some(p) if !perspective => {
                reduce_step(p.step_x().saturating_add(1 << 15) >> 16, period, repeat)
            }
            _ => 0,
        };
        TexturePaint {
            sampler,
            light,
            base,
            step: [step(0, periods.0), step(1, periods.1)],
            planes,
            perspective,
        }
    }
}

/// The weights scaled so that the largest lies in [2^[`Q_BITS`], 2^([`Q_BITS`] + 1)) (each at
/// least 1); `None` when
/// they are all equal (nothing to correct).
fn scaled_weights(q: [i64; 3]) -> Option<[i64; 3]> {
    let q = q.map(|v| v.max(1));
    if q[0] == q[1] && q[1] == q[2] {
        return None;
    }
    let shift = magnitude_bits(&q) as i32 - Q_BITS as i32 - 1;
    Some(q.map(|v| {
        let v = if shift > 0 {
            v >> shift
        } else {
            v << (-shift) as u32
        };
        v.max(1)
    }))
}

/// True when mapping the triangle linearly errs by less than 1/8 texel anywhere in it. The
/// perspective map's value is `Σλᵢqᵢsᵢ / Q` with `Q = Σλᵢqᵢ`, the linear map's `Σλᵢsᵢ`; with
/// vertex 0's coordinates taken as 0 (each `|sᵢ| ≤ extent`) they differ by
/// `|Σλᵢsᵢ(qᵢ − Q)| / Q ≤ extent · Σλᵢ|qᵢ − Q| / Q`, and the mean deviation `Σλᵢ|qᵢ − Q|` of
/// values between `q_min` and `q_max` is at most `(q_max − q_min) / 2`.
fn nearly_affine(q: &[i64; 3], extent: i64) -> bool {
    let lo = q.iter().copied().min().unwrap_or(1).max(1);
    let hi = q.iter().copied().max().unwrap_or(1);
    // extent ≤ 2²⁸ (Q16.16), hi − lo < 2¹⁷: the product stays below 2⁴⁸.
    extent.saturating_mul(hi - lo).saturating_mul(4) < lo << 16
}

/// The running texel coordinates of a [`TexturePaint`] along a span, and its light.
#[derive(Clone, Copy, Debug)]
pub struct TextureCursor<'t, C> {
    sampler: Sampler<'t>,
    light: C,
    /// Texel coordinates (Q16.16) and their steps: `s` in [0, period) when repeating.
    s: [i32; 2],
    step: [i32; 2],
    /// What a coordinate is brought back below: the period when repeating, else a bound
    /// that a clamped coordinate (below 2³¹ in magnitude, see `reduce`) never reaches.
    wrap: [i32; 2],
    /// Pixels left before the next exact point (perspective), or of the whole span.
    left: u32,
    /// Perspective: the planes at the next exact point, their steps, and the pixels after it.
    acc: [i64; 3],
    acc_step: [i64; 3],
    rest: u32,
    base: [i32; 2],
    /// The exact coordinates at the current point, before reduction.
    exact: [i64; 2],
}

impl<C> TextureCursor<'_, C> {
    /// The exact texel coordinates at the planes' values `acc` (Q16.16).
    #[inline]
    fn exact_at(&self, acc: [i64; 3]) -> [i64; 2] {
        let [u, v, q] = acc;
        // (s − s₀) = U / q = U·2¹² / (Q >> 12), Q = q·2²⁴: every value below 2⁵⁹.
        let by = DivideBy::new((q >> 12).max(1));
        let limit = 1i64 << 46;
        let at = |n: i64, base: i32| {
            by.round(n.clamp(-limit, limit) << 12)
                .clamp(-(1 << 30), 1 << 30)
                .wrapping_add(i64::from(base))
        };
        [at(u, self.base[0]), at(v, self.base[1])]
    }

    /// Starts the next run of at most the texture's run of pixels (see
    /// [`Texture::with_run`]): exact at both its ends, linear between.
    #[inline(never)]
    fn next_run(&mut self) {
        let n = self.rest.clamp(1, u32::from(self.sampler.run).max(1));
        self.rest = self.rest.saturating_sub(n);
        let [a0, a1, a2] = self.acc;
        let [s0, s1, s2] = self.acc_step;
        let k = i64::from(n);
        self.acc = [
            a0.wrapping_add(s0.wrapping_mul(k)),
            a1.wrapping_add(s1.wrapping_mul(k)),
            a2.wrapping_add(s2.wrapping_mul(k)),
        ];
        let start = self.exact;
        let end = self.exact_at(self.acc);
        self.exact = end;
        let (periods, repeat) = (self.sampler.periods(), self.sampler.repeats());
        let step = |k: usize, period: i32| {
            let d = end[k]
                .wrapping_sub(start[k])
                .clamp(-i32::MAX as i64, i32::MAX as i64);
            reduce_step(i64::from(d as i32 / n.max(1) as i32), period, repeat)
        };
        self.step = [step(0, periods.0), step(1, periods.1)];
        self.s = [
            reduce(start[0], periods.0, repeat),
            reduce(start[1], periods.1, repeat),
        ];
        self.left = n;
    }

    /// Moves to the next pixel: a repeating coordinate and its step both lie in
    /// [0, period), so one subtraction brings their sum back into it.
    #[inline(always)]
    fn advance(&mut self) {
        let [s, t] = self.s;
        let [ds, dt] = self.step;
        let [ws, wt] = self.wrap;
        let (mut s, mut t) = (s.wrapping_add(ds), t.wrapping_add(dt));
        if s >= ws {
            s = s.wrapping_sub(ws);
        }
        if t >= wt {
            t = t.wrapping_sub(wt);
        }
        self.s = [s, t];
    }
}

/// `texel · light`, each channel scaled by `light / 255` (so white leaves it as it is).
#[inline(always)]
fn modulate(texel: Rgb888, light: Rgb888) -> Rgb888 {
    let ch = |t: u8, l: u8| {
        let l = u32::from(l) + (u32::from(l) >> 7);
        ((u32::from(t) * l) >> 8) as u8
    };
    Rgb888::new(
        ch(texel.r(), light.r()),
        ch(texel.g(), light.g()),
        ch(texel.b(), light.b()),
    )
}

impl<C: Iterator<Item = Rgb888>> Iterator for TextureCursor<'_, C> {
    type Item = Rgb888;

    #[inline(always)]
    fn next(&mut self) -> Option<Rgb888> {
        if self.left == 0 {
            self.next_run();
        }
        self.left = self.left.wrapping_sub(1);
        let [s, t] = self.s;
        let texel = self.sampler.texel(s, t);
        self.advance();
        let light = self.light.next().unwrap_or(Rgb888::WHITE);
        Some(modulate(texel, light))
    }
}

impl<'t, L: Paint> Paint for TexturePaint<'t, L> {
    type Cursor = TextureCursor<'t, L::Cursor>;

    fn solid(&self) -> Option<Rgb888> {
        None
    }

    #[inline(always)]
    fn cursor(&self, span: Span) -> Self::Cursor {
        let Span { y, x0, x1 } = span;
        let (periods, repeat) = (self.sampler.periods(), self.sampler.repeats());
        let mut cursor = TextureCursor {
            sampler: self.sampler,
            light: self.light.cursor(span),
            s: [0; 2],
            step: self.step,
            wrap: if repeat {
                [periods.0, periods.1]
            } else {
                [i32::MAX; 2]
            },
            left: u32::MAX,
            acc: [0; 3],
            acc_step: [0; 3],
            rest: 0,
            base: self.base,
            exact: [0; 2],
        };
        let [ps, pt, pq] = self.planes;
        if self.perspective {
            cursor.acc = [ps.at(x0, y), pt.at(x0, y), pq.at(x0, y)];
            cursor.acc_step = [ps.step_x(), pt.step_x(), pq.step_x()];
            cursor.rest = x1.wrapping_sub(x0).max(0) as u32;
            cursor.exact = cursor.exact_at(cursor.acc);
            cursor.left = 0;
        } else {
            let at = |p: Plane, base: i32| {
                i64::from(base).wrapping_add(p.at(x0, y).saturating_add(1 << 15) >> 16)
            };
            cursor.s = [
                reduce(at(ps, self.base[0]), periods.0, repeat),
                reduce(at(pt, self.base[1]), periods.1, repeat),
            ];
        }
        cursor
    }
}

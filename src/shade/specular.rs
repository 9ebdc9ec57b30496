//! Blinn-Phong highlights in fixed point, per vertex (see [`Specular`] for the formula).

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use super::lambert::{attenuate, term};
use crate::math::{cosine_unit, map3, mul_wide_u32, normalize, UNIT_ONE};
use crate::mesh::Specular;
use crate::scene::Lighting;

/// Whether glossy models show highlights (the `specular` feature): without it no code that
/// finds them is linked, and a model that needs it is an error.
pub(crate) const SPECULAR: bool = cfg!(feature = "specular");

/// What one glossy object's highlights need for a frame: its highlight colour and shininess,
/// the unit direction towards the viewer and, per directional light, the unit half vector
/// (found once here, not per vertex).
#[derive(Debug)]
pub(crate) struct Highlights<const N: usize> {
    color: Rgb888,
    shininess: u16,
    /// Q2.30.
    towards_viewer: [i32; 3],
    /// Q2.30, one per directional light in order (zero where the light faces the viewer
    /// head-on: it has no half vector).
    halves: [[i32; 3]; N],
}

impl<const N: usize> Highlights<N> {
    /// The highlights of `specular` under `lighting`, for a viewer far along `towards_viewer`
    /// (any non-zero direction, world space); `None` for a zero direction.
    pub(crate) fn new(
        specular: &Specular,
        towards_viewer: [i64; 3],
        lighting: &Lighting<N>,
    ) -> Option<Self> {
        let towards_viewer = normalize(towards_viewer)?;
        let mut halves = [[0; 3]; N];
        for (light, h) in lighting.lights().zip(&mut halves) {
            *h = half(&light.direction, &towards_viewer);
        }
        Some(Highlights {
            color: specular.color,
            shininess: specular.shininess,
            towards_viewer,
            halves,
        })
    }

    /// The highlight at a vertex of unit normal `n` (Q2.30) at world point `at` (raw Q16.16),
    /// per channel, to add to its diffuse colour.
    pub(crate) fn at(&self, n: &[i32; 3], at: &[i64; 3], lighting: &Lighting<N>) -> [u8; 3] {
        let mut sum = [0i64; 3];
        let mut add = |color: &[i32; 3], p: i32| {
            for (s, &c) in sum.iter_mut().zip(color) {
                *s = s.wrapping_add(term(c.into(), p));
            }
        };
        for (light, h) in lighting.lights().zip(&self.halves) {
            if cosine_unit(*n, light.direction) > 0 {
                add(&light.color, power(cosine_unit(*n, *h), self.shininess));
            }
        }
        for point in lighting.points() {
            let Some((l, factor)) = point.towards(at) else {
                continue;
            };
            if cosine_unit(*n, l) > 0 {
                let h = half(&l, &self.towards_viewer);
                let p = power(cosine_unit(*n, h), self.shininess);
                add(&point.color, attenuate(p, factor));
            }
        }
        let [r, g, b] = sum.map(|s| s.clamp(0, 1 << 16) as i32);
        let scaled = |c: u8, s: i32| ((c as i32 * s) >> 16) as u8;
        let c = self.color;
        [scaled(c.r(), r), scaled(c.g(), g), scaled(c.b(), b)]
    }
}

/// The unit half vector (Q2.30) of two unit vectors; zero where they are opposite.
fn half(a: &[i32; 3], b: &[i32; 3]) -> [i32; 3] {
    let sum = map3([0, 1, 2], |k| a[k] as i64 + b[k] as i64);
    normalize(sum).unwrap_or([0; 3])
}

/// `c^k` for a cosine `c` (Q2.30, taken within [0, 1]) and `k ≥ 1` (0 counts as 1), by
/// squaring, each of at most 32 products rounded down: within `2k·2⁻³⁰` below the exact power.
fn power(c: i32, k: u16) -> i32 {
    let mut base = c.clamp(0, UNIT_ONE) as u32;
    let mut k = k.max(1);
    let mut result = 1u32 << 30;
    // Factors at most 2³⁰: products below 2⁶⁰, and back to at most 2³⁰.
    let times = |a: u32, b: u32| (mul_wide_u32(a, b) >> 30) as u32;
    while k != 0 {
        if k & 1 != 0 {
            result = times(result, base);
        }
        base = times(base, base);
        k >>= 1;
    }
    result as i32
}

/// The highlight added to a diffuse colour, each channel saturating.
pub(crate) fn add_highlight(diffuse: Rgb888, highlight: [u8; 3]) -> Rgb888 {
    let [r, g, b] = highlight;
    Rgb888::new(
        diffuse.r().saturating_add(r),
        diffuse.g().saturating_add(g),
        diffuse.b().saturating_add(b),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `power` is the exact power of the rounded cosine within its stated bound, for every
    /// shininess up to 2¹⁶ − 1; 0 counts as 1, and 1 stays 1.
    #[test]
    fn power_within_its_bound() {
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        for _ in 0..20_000 {
            let c = rng.within(1 << 30).abs();
            let k = rng.pick(&[1u16, 2, 3, 7, 32, 128, 1000, 65_535]);
            let exact = (c as f64 / (1u64 << 30) as f64).powi(k as i32) * (1u64 << 30) as f64;
            let got = power(c, k) as f64;
            assert!(
                got <= exact + 1e-6 && exact - got <= 2.0 * k as f64 + 1.0,
                "{c} {k}"
            );
        }
        assert_eq!(power(1 << 30, 65_535), 1 << 30);
        assert_eq!(power(12_345, 0), 12_345);
        assert_eq!(power(-5, 3), 0);
    }

    /// Highlights at random unit normals, views and lights (directional and point, every
    /// attenuation, coloured and overbright), shininess 1 to 1000: each channel within one
    /// step of the f64 value of the same quantised inputs; nothing from a light the surface
    /// turns from.
    #[test]
    #[cfg(all(feature = "specular", feature = "point-light"))]
    fn highlights_within_one_step_of_f64() {
        use crate::math::{Scalar, Vec3};
        use crate::scene::{Attenuation, DirectionalLight, LightColor, PointLight};
        let mut rng = crate::testing::XorShift(0xD1B5_4A32_D192_ED03u64);
        let mut uniform = |lo: f64, hi: f64| {
            lo + (hi - lo) * ((rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
        };
        let q = |v: f64| Scalar::from_num(v);
        let f = |s: Scalar| s.to_bits() as f64 / 65536.0;
        let unit = |v: [i32; 3]| v.map(|c| c as f64 / (1u64 << 30) as f64);
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let norm = |a: [f64; 3]| {
            let l = dot(a, a).sqrt();
            a.map(|c| c / l)
        };
        let (mut shone, mut compared) = (0, 0);
        for k in 0..20_000 {
            let mut random_unit = |scale: f64| [(); 3].map(|_| (uniform(-1.0, 1.0) * scale) as i64);
            let (Some(n), Some(d)) = (normalize(random_unit(1e6)), normalize(random_unit(1e6)))
            else {
                continue;
            };
            // Normals near the light's and the viewer's directions, where highlights are.
            let towards = map3([0, 1, 2], |j| n[j] as i64 * 3 + d[j] as i64);
            let view = map3([0, 1, 2], |j| n[j] as i64 * 2 - d[j] as i64 / 2);
            let shininess = [1u16, 4, 16, 64, 128, 1000][k % 6];
            let color = LightColor::new(q(uniform(0.0, 2.0)), q(uniform(0.0, 1.0)), q(0.6));
            let mut lighting = Lighting::<2>::new(LightColor::gray(q(0.1)));
            let directional = k % 2 == 0;
            let at = [(); 3].map(|_| q(uniform(-4.0, 4.0)));
            let position = [(); 3].map(|_| q(uniform(-4.0, 4.0)));
            let attenuation = [Attenuation::None, Attenuation::InverseSquare][k / 2 % 2];
            if directional {
                let [x, y, z] = towards.map(|c| c as i32 >> 2);
                let light = DirectionalLight::new(Vec3::from_bits(x, y, z), color);
                if lighting.push(light).is_err() {
                    continue;
                }
            } else {
                let p = Vec3::new(position[0], position[1], position[2]);
                let _ = lighting.push_point(PointLight::new(p, color).attenuated(attenuation));
            }
            let gloss = Specular::new(Rgb888::new(255, 200, 100), shininess);
            let Some(h) = Highlights::new(&gloss, view, &lighting) else {
                continue;
            };
            let at_bits = at.map(|c| i64::from(c.to_bits()));
            let got = h.at(&n, &at_bits, &lighting);
            // The f64 value.
            let nf = unit(n);
            let v = norm(view.map(|c| c as f64));
            let (l, fall) = if directional {
                let light = lighting
                    .lights()
                    .next()
                    .map(|l| l.direction)
                    .unwrap_or_default();
                (unit(light), 1.0)
            } else {
                let w: [f64; 3] = core::array::from_fn(|j| f(position[j]) - f(at[j]));
                let d = dot(w, w).sqrt();
                let fall = match attenuation {
                    Attenuation::InverseSquare => 1.0 / (1.0 + d * d),
                    _ => 1.0,
                };
                (norm(w), fall)
            };
            let facing = dot(nf, l);
            if facing.abs() < 1e-6 || dot(l, v) < -0.999 {
                continue;
            }
            let hv = norm([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
            let s = if facing > 0.0 {
                dot(nf, hv).max(0.0).powi(shininess as i32) * fall
            } else {
                0.0
            };
            let want = [(color.r, 255u8), (color.g, 200), (color.b, 100)]
                .map(|(c, g)| (g as f64 * (f(c) * s).clamp(0.0, 1.0)).floor() as i32);
            let got = got.map(i32::from);
            for (g, w) in got.iter().zip(want) {
                assert!((g - w).abs() <= 1, "{k}: {n:?} {got:?} vs {want:?}");
            }
            shone += (want[2] > 20) as u32;
            compared += 1;
        }
        assert!(compared > 15_000 && shone > 3_000, "{compared} {shone}");
    }
}

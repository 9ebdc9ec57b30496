//! Lambert's law in fixed point, and the normals it needs.

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};

use crate::math::{
    apply, cosine_unit, dot_is_positive, face_direction, map3, mul_shr30_short, mul_wide, shrink,
    NewtonDirection, Normalize, UNIT_ONE,
};
#[cfg(test)]
use crate::math::{dot_wide, normalize};
use crate::scene::Lighting;

/// Lit colour of `base` for unit normal `n` (Q2.30), or ambient only when there is no normal,
/// at the point `at` (raw Q16.16 in the lighting's space: read for point lights alone).
/// Per channel: `floor(base · clamp(ambient + Σ light · attenuation · max(0, n·l), 0, 1))`.
pub(crate) fn lambert<const N: usize>(
    base: Rgb888,
    n: Option<[i32; 3]>,
    at: &[i64; 3],
    lighting: &Lighting<N>,
) -> Rgb888 {
    lambert_by(base, lighting, at, |l| cosine(n, l))
}

/// [`lambert`] with `max(0, n·l)` (Q2.30) for each light's unit direction `l` from `cosine`.
#[inline(always)]
fn lambert_by<const N: usize>(
    base: Rgb888,
    lighting: &Lighting<N>,
    at: &[i64; 3],
    cosine: impl Fn(&[i32; 3]) -> i32,
) -> Rgb888 {
    // A sum per channel, from the cosines gathered here: the directional lights', then the
    // point lights' (together at most N).
    let mut cosines = [0; N];
    let mut slots = cosines.iter_mut();
    for (light, d) in lighting.lights().zip(slots.by_ref()) {
        *d = cosine(&light.direction);
    }
    for (point, d) in lighting.points().zip(slots) {
        *d = point
            .towards(at)
            .map_or(0, |(l, factor)| attenuate(cosine(&l), factor));
    }
    lambert_sums(base, lighting, &cosines)
}

/// The lit colour from each directional light's `max(0, n·l)`, then each point light's
/// attenuated one, in `cosines`: a sum per channel, in words where every channel lies in
/// [0, 1] (the usual lights).
#[inline(never)]
fn lambert_sums<const N: usize>(
    base: Rgb888,
    lighting: &Lighting<N>,
    cosines: &[i32; N],
) -> Rgb888 {
    // The channels' sums held apart (not as an array), so that they stay in registers.
    let [r, g, b] = if lighting.channels_in_words() {
        // Each term below 2¹⁷, the ambient at most 2¹⁶: the sums fit words.
        let sums = sum_lights(lighting, cosines, lighting.ambient().bits(), |s, c, d| {
            s.wrapping_add(term_in_words(c as u32, d as u32) as i32)
        });
        let [r, g, b] = sums;
        let unit = |s: i32| s.clamp(0, 1 << 16);
        [unit(r), unit(g), unit(b)]
    } else {
        let sums = sum_lights(
            lighting,
            cosines,
            lighting.ambient().channels(),
            |s, c, d| s.wrapping_add(term(c.into(), d)),
        );
        let [r, g, b] = sums;
        [intensity(r), intensity(g), intensity(b)]
    };
    Rgb888::new(lit(base.r(), r), lit(base.g(), g), lit(base.b(), b))
}

/// `ambient` with each light's terms added by `add(sum, channel, cosine)`, per channel: the
/// directional lights' (their cosines first in `cosines`), then the point lights'. Two loops of
/// their own, with the three sums apart, keep the sums in registers.
#[inline(always)]
fn sum_lights<const N: usize, T: Copy>(
    lighting: &Lighting<N>,
    cosines: &[i32; N],
    ambient: [T; 3],
    add: impl Fn(T, i32, i32) -> T,
) -> [T; 3] {
    let (first, rest) = cosines
        .split_at_checked(lighting.directional_count())
        .unwrap_or((cosines, &[]));
    let add3 = |[r, g, b]: [T; 3], &[cr, cg, cb]: &[i32; 3], d: i32| {
        [add(r, cr, d), add(g, cg, d), add(b, cb, d)]
    };
    let mut sums = ambient;
    for (light, &d) in lighting.lights().zip(first) {
        sums = add3(sums, &light.color, d);
    }
    for (point, &d) in lighting.points().zip(rest) {
        sums = add3(sums, &point.color, d);
    }
    sums
}

/// `max(0, n·l)` (Q2.30) for unit normal `n` and a light's unit direction `l` (no normal: 0).
#[inline(always)]
fn cosine(n: Option<[i32; 3]>, l: &[i32; 3]) -> i32 {
    n.map_or(0, |n| cosine_unit(n, *l))
}

/// A cosine (Q2.30, below 2³¹) scaled by an attenuation factor (Q2.30, in [0, 1]).
#[inline(always)]
pub(super) fn attenuate(d: i32, factor: i32) -> i32 {
    (mul_wide(d, factor) >> 30) as i32
}

/// One channel's term of a light whose `cosine` is `d`: Q16.16 · Q2.30 → Q16.16 (the channel
/// is a Scalar's bits: it fits i32), within ±2³¹: no count of lights a memory can hold
/// overflows a sum of them.
#[inline(always)]
pub(super) fn term(channel: i64, d: i32) -> i64 {
    mul_wide(channel as i32, d) >> 30
}

/// [`term`] of a channel `c ≤ 2¹⁶` and a cosine `d < 2³¹` (both non-negative), below 2¹⁷.
#[inline(always)]
fn term_in_words(c: u32, d: u32) -> u32 {
    mul_shr30_short(c, d)
}

/// A channel's sum clamped to [0, 1] (Q16.16).
#[inline(always)]
fn intensity(s: i64) -> i32 {
    s.clamp(0, 1 << 16) as i32
}

/// `⌊base · intensity⌋` (255 · 2¹⁶ fits 32 bits).
#[inline(always)]
fn lit(base: u8, intensity: i32) -> u8 {
    ((base as i32 * intensity) >> 16) as u8
}

/// Unit face normal (Q2.30) of a model-space triangle, counter-clockwise front, in world space
/// through `normal_matrix` (in model space without one); `None` for a zero-area triangle.
#[cfg(test)]
pub(crate) fn face_normal(
    p: [[i32; 3]; 3],
    normal_matrix: Option<&[[i32; 3]; 3]>,
    method: Normalize,
    extent: u32,
) -> Option<[i32; 3]> {
    method.unit32(face_direction(p, normal_matrix, extent, u32::MAX))
}

/// Lit colour of a model-space triangle, counter-clockwise front, flat shaded: Lambert of its
/// face normal, in world space through `normal_matrix` (in the lighting's space without one),
/// by [`face_lambert`], at the point `at` (its centre in the lighting's space, raw Q16.16: read
/// for point lights alone). `extent` and `edge_extent` bound the mesh's coordinates and its
/// triangles' edges (see [`face_direction`]).
pub(crate) fn flat_color<const N: usize>(
    base: Rgb888,
    p: [[i32; 3]; 3],
    at: &[i64; 3],
    normal_matrix: Option<&[[i32; 3]; 3]>,
    method: Normalize,
    (extent, edge_extent): (u32, u32),
    lighting: &Lighting<N>,
) -> Rgb888 {
    face_lambert(
        base,
        face_direction(p, normal_matrix, extent, edge_extent),
        at,
        method,
        lighting,
    )
}

/// [`flat_color`] in model space with [`Normalize::Newton`], from the face's kept
/// direction `d`: the same colour, or `None` where `d` cannot tell whether the face turns to a
/// light (each product within ±2³¹, where the direction's rounding to 15 bits could move the
/// sign of its product: the remainders of the shift, each below one unit of the shifted
/// direction, move it by less than the light's components' sum of magnitudes, √3·2³⁰), or
/// where there are point lights (a kept normal is lit without the face's position).
#[inline(always)]
pub(crate) fn kept_face_color<const N: usize>(
    base: Rgb888,
    d: &NewtonDirection,
    lighting: &Lighting<N>,
) -> Option<Rgb888> {
    const SURE: i64 = 1 << 31;
    if lighting.points().next().is_some() {
        return None;
    }
    let mut undecided = false;
    for light in lighting.lights() {
        let t = d.dot(light.direction);
        if t >= SURE {
            return Some(lambert_by(base, lighting, &[0; 3], |l| d.cosine(*l)));
        }
        undecided |= t > -SURE;
    }
    if undecided {
        None
    } else {
        Some(lambert(base, None, &[0; 3], lighting))
    }
}

/// Lambert of a face whose direction is `n` (any i32 components but `i32::MIN`, as
/// [`face_direction`] gives) at the point `at`. Without point lights, a face that turns from
/// every light gets the ambient colour without being normalised: its direction's products with
/// the lights are all ≤ 0, so Lambert adds nothing. With [`Normalize::Newton`] (the default)
/// no unit normal is formed: each light's cosine is the direction's product with the light
/// over its length.
#[inline(always)]
fn face_lambert<const N: usize>(
    base: Rgb888,
    n: [i32; 3],
    at: &[i64; 3],
    method: Normalize,
    lighting: &Lighting<N>,
) -> Rgb888 {
    // Components below 2³¹ and unit directions: products below 2⁶¹, sums below 2⁶³.
    let faces = |l: &[i32; 3]| dot_is_positive(n, *l);
    let lit = lighting.points().next().is_some() || lighting.lights().any(|l| faces(&l.direction));
    // Every case but Newton's leaves through the one `lambert` below: with a second call
    // (an early return for faces turned away) it and the reciprocal square root left the
    // line and took more flash.
    let unit = if !lit {
        None
    } else if method == Normalize::Newton {
        if let Some(d) = NewtonDirection::new(n) {
            return lambert_by(base, lighting, at, |l| d.cosine(*l));
        }
        None
    } else {
        method.unit32(n)
    };
    lambert(base, unit, at, lighting)
}

/// Unit world-space vertex normal (Q2.30) from a model-space normal (raw Q16.16); `None` for a
/// zero normal (lit by ambient only, case T34).
pub(crate) fn vertex_normal(
    n: [i32; 3],
    normal_matrix: &[[i32; 3]; 3],
    method: Normalize,
) -> Option<[i32; 3]> {
    let v = shrink(map3(n, i64::from));
    let w = method.unit(apply(normal_matrix, v))?;
    debug_assert!(w.iter().all(|c| c.abs() <= UNIT_ONE));
    Some(w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{
        below_bits, cross_in_words, cross_wide, face_newton_direction, shrink_below, Angle, Mat4,
        Scalar, Vec3,
    };
    use crate::scene::{DirectionalLight, LightColor, LightError};

    const IDENTITY: [[i32; 3]; 3] = [[1 << 16, 0, 0], [0, 1 << 16, 0], [0, 0, 1 << 16]];

    fn to_f(v: [i32; 3]) -> [f64; 3] {
        v.map(|c| c as f64 / (1u64 << 30) as f64)
    }

    /// The face direction in words for edges within ±2¹⁵, `cross_in_words`, is the 64-bit
    /// path's `shrink_below(cross_wide(u, v), 31)` for every such edge: the corners of the
    /// range (products of ±2³⁰, components up to 2³¹ − 2¹⁵) and random edges of every scale.
    /// So a mesh whose edges all lie within ±2¹⁵ gets the face directions of any other.
    #[test]
    fn short_cross_equals_shrunk_wide_cross() {
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let wide = |u, v| map3(shrink_below(cross_wide(u, v), 31), |c| c as i32);
        let (mut large, mut in_range) = (0, 0);
        let corners = [-(1 << 15), (1 << 15) - 1, 0, 1, -1];
        let corner = |k: usize| corners[k % corners.len()];
        for k in 0..5usize.pow(6) {
            let u = [corner(k), corner(k / 5), corner(k / 25)];
            let v = [corner(k / 125), corner(k / 625), corner(k / 3125)];
            assert_eq!(cross_in_words(u, v), wide(u, v), "{u:?} {v:?}");
            large += (cross_wide(u, v).iter().any(|c| !below_bits(*c, 30))) as u32;
        }
        for _ in 0..200_000 {
            let scale = rng.pick(&[1 << 8, 1 << 14, 1 << 15, 1 << 16]);
            let u = [(); 3].map(|_| rng.within(scale));
            let v = [(); 3].map(|_| rng.within(scale));
            let short = u
                .iter()
                .chain(&v)
                .all(|&c| (-(1 << 15)..1 << 15).contains(&c));
            // For edges a mesh's `edge_extent` bounds, the same; beyond them a wrapped value,
            // never an overflow.
            let words = cross_in_words(u, v);
            assert!(!short || words == wide(u, v), "{u:?} {v:?}");
            in_range += u32::from(short);
        }
        assert!(large > 100 && in_range > 100_000, "{large} {in_range}");
    }

    /// `shrink` leaves vectors below 2³⁰ alone and brings larger ones below it, at the
    /// boundaries and the ends of the range.
    #[test]
    fn shrink_boundaries() {
        let edges = [
            i64::MIN,
            -(1 << 30) - 1,
            -(1 << 30),
            -(1 << 30) + 1,
            -1,
            0,
            1,
        ];
        let values = edges.iter().flat_map(|&e| [e, e.saturating_neg()]);
        for a in values.clone() {
            for b in values.clone() {
                let v = [a, b, 7];
                let s = shrink(v);
                assert!(
                    s.iter().all(|c| c.unsigned_abs() <= 1 << 30),
                    "{v:?} -> {s:?}"
                );
                if v.iter().all(|c| c.unsigned_abs() < 1 << 30) {
                    assert_eq!(s, v);
                }
            }
        }
    }

    /// T33: face normals of triangles with edges from 1e-4 to 1e3 world units: no panic, the
    /// direction within 1 degree of the exact normal of the quantised vertices.
    #[test]
    fn t33_face_normals_at_every_scale() {
        for scale in [1e-4f64, 1e-3, 0.01, 0.1, 1.0, 10.0, 100.0, 1000.0] {
            let raw = [[0.0, 0.0, 0.0], [1.0, 0.2, -0.3], [0.3, 1.1, 0.4]]
                .map(|p| p.map(|c: f64| (c * scale * 65536.0).round() as i32));
            let extent = raw
                .iter()
                .flatten()
                .map(|c| c.unsigned_abs())
                .max()
                .unwrap_or(0);
            let n = face_normal(raw, Some(&IDENTITY), Normalize::Newton, extent)
                .expect("non-degenerate");
            // The unchecked short edges give what the checked ones give.
            assert_eq!(
                Some(n),
                face_normal(raw, Some(&IDENTITY), Normalize::Newton, u32::MAX)
            );
            let p = raw.map(|v| v.map(|c| c as f64));
            let e1 = [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]];
            let e2 = [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]];
            let x = [
                e1[1] * e2[2] - e1[2] * e2[1],
                e1[2] * e2[0] - e1[0] * e2[2],
                e1[0] * e2[1] - e1[1] * e2[0],
            ];
            let len = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
            let f = to_f(n);
            let cos = (f[0] * x[0] + f[1] * x[1] + f[2] * x[2]) / len;
            assert!(cos > 1f64.to_radians().cos(), "scale {scale}: cos {cos}");
        }
        // A zero-area triangle has no normal (ambient only), never a division.
        assert!(face_normal([[5, 5, 5]; 3], None, Normalize::Newton, 5).is_none());
        assert!(face_normal(
            [[0, 0, 0], [1 << 16, 0, 0], [2 << 16, 0, 0]],
            Some(&IDENTITY),
            Normalize::Newton,
            2 << 16
        )
        .is_none());
        // Extreme coordinates do not overflow.
        let big = [
            [i32::MIN, i32::MIN, 0],
            [i32::MAX, i32::MIN, 0],
            [i32::MIN, i32::MAX, 7],
        ];
        assert!(face_normal(big, Some(&IDENTITY), Normalize::Newton, u32::MAX).is_some());
        assert!(face_normal(big, None, Normalize::Newton, u32::MAX).is_some());
    }

    /// T34: Lambert with random unit vectors, zero normals and back-facing normals: intensity in
    /// [0, 1] and within 1 LSB of the exact value per 8-bit channel.
    #[test]
    fn t34_lambert_bounds_and_error() {
        let mut lighting = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.2)));
        assert_eq!(
            lighting.push(DirectionalLight::new(Vec3::ZERO, LightColor::WHITE)),
            Err(LightError::ZeroDirection)
        );
        let l = [-1.0f64, 1.0, 1.0];
        lighting
            .push(DirectionalLight::new(
                Vec3::from_int(-1, 1, 1),
                LightColor::gray(Scalar::from_num(0.8)),
            ))
            .unwrap();
        let base = Rgb888::new(255, 160, 64);
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let mut next = || {
            let state = rng.next_u64();
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let ll = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
        for _ in 0..20_000 {
            let v = [next(), next(), next()];
            let raw = v.map(|c| (c * (1 << 20) as f64) as i64);
            let Some(n) = normalize(raw) else { continue };
            let got = lambert(base, Some(n), &[0; 3], &lighting);
            let nf = to_f(n);
            let d = ((nf[0] * l[0] + nf[1] * l[1] + nf[2] * l[2]) / ll).max(0.0);
            let s = 0.2 + 0.8 * d;
            let expect = [255.0 * s, 160.0 * s, 64.0 * s];
            let got = [got.r(), got.g(), got.b()];
            for (g, e) in got.iter().zip(expect) {
                assert!(
                    (*g as f64 - e.floor()).abs() <= 1.0,
                    "{got:?} vs {expect:?}"
                );
            }
        }
        // No normal: ambient only.
        assert_eq!(
            lambert(base, None, &[0; 3], &lighting),
            Rgb888::new(50, 31, 12)
        );
        // Overbright lights clamp at full intensity.
        let mut hot = Lighting::<1>::new(LightColor::gray(Scalar::from_num(3)));
        hot.push(DirectionalLight::new(
            Vec3::Y,
            LightColor::gray(Scalar::from_num(100)),
        ))
        .unwrap();
        assert_eq!(lambert(base, Some([0, 1 << 30, 0]), &[0; 3], &hot), base);
    }

    /// The sums in words (every channel in [0, 1]) equal the sums in 64 bits, for one to three
    /// lights, grey and coloured; an overbright light takes the 64-bit sums.
    #[test]
    fn sums_in_words_equal_the_wide_sums() {
        let color = |r: f64, g: f64, b: f64| {
            LightColor::new(
                Scalar::from_num(r),
                Scalar::from_num(g),
                Scalar::from_num(b),
            )
        };
        let wide = |base: Rgb888, lighting: &Lighting<3>, cosines: &[i32; 3]| {
            let mut sum = lighting.ambient().channels();
            for (light, &d) in lighting.lights().zip(cosines) {
                for (s, &c) in sum.iter_mut().zip(&light.color) {
                    *s += (c as i64 * d as i64) >> 30;
                }
            }
            let [r, g, b] = sum.map(|s| s.clamp(0, 1 << 16) as i32);
            Rgb888::new(lit(base.r(), r), lit(base.g(), g), lit(base.b(), b))
        };
        let mut rng = crate::testing::XorShift(0x2545_F491_4F6C_DD1Du64);
        let base = Rgb888::new(255, 160, 64);
        let lights = [
            ((-1, 1, 1), color(0.8, 0.8, 0.8)),
            ((2, -1, 3), color(1.0, 0.25, 0.5)),
            ((0, 0, -1), color(0.1, 1.0, 0.0)),
        ];
        for (k, ambient) in [
            color(0.0, 0.0, 0.0),
            color(0.2, 0.3, 0.1),
            color(1.0, 1.0, 1.0),
        ]
        .into_iter()
        .enumerate()
        {
            for overbright in [false, true] {
                let mut lighting = Lighting::<3>::new(ambient);
                for (d, c) in lights.into_iter().take(k + 1) {
                    let c = if overbright { color(2.5, 0.5, 1.0) } else { c };
                    let light = DirectionalLight::new(Vec3::from_int(d.0, d.1, d.2), c);
                    lighting.push(light).unwrap();
                }
                assert_eq!(lighting.channels_in_words(), !overbright);
                for _ in 0..5_000 {
                    let v = [(); 3].map(|_| rng.within(1 << 20) as i64);
                    let n = normalize(v);
                    let mut cosines = [0; 3];
                    for (c, light) in cosines.iter_mut().zip(lighting.lights()) {
                        *c = cosine(n, &light.direction);
                    }
                    assert_eq!(
                        lambert(base, n, &[0; 3], &lighting),
                        wide(base, &lighting, &cosines),
                        "{v:?}"
                    );
                }
            }
        }
        let mut tinted = Lighting::<1>::new(color(0.2, 0.2, 0.2));
        tinted
            .push(DirectionalLight::new(Vec3::Y, color(1.0, 1.0, 0.5)))
            .unwrap();
        assert_eq!(
            lambert(base, Some([0, 1 << 30, 0]), &[0; 3], &tinted),
            Rgb888::new(255, 160, 44)
        );
    }

    /// Flat Lambert through [`NewtonDirection`] (no unit normal) gives the colours of the unit
    /// normal: exactly for every face of the reference torus turned three ways, with the
    /// scene's light, three grey lights and coloured ones, and within one 8-bit step for random
    /// faces of every scale; each cosine within 3 units of 2⁻³⁰ of the unit normal's, and
    /// within 5·10⁻⁹ of the exact cosine of the direction kept (M9).
    #[test]
    fn newton_direction_lights_as_the_unit_normal() {
        extern crate std;
        use crate::mesh::{torus, torus_counts};
        use std::vec;
        let unit_lambert = |base, n, lighting: &Lighting<4>| {
            let faces = lighting.lights().any(|l| dot_wide(n, l.direction) > 0);
            let unit = faces.then(|| Normalize::Newton.unit32(n)).flatten();
            lambert(base, unit, &[0; 3], lighting)
        };
        let scene = lighting_of(&[((-1, 1, 1), 0.8)]);
        let mut three = lighting_of(&[((-1, 1, 1), 0.6), ((2, -1, 3), 0.5), ((0, 0, -1), 2.5)]);
        let mut coloured = three.clone();
        let tint = LightColor::new(Scalar::ONE, Scalar::from_num(0.5), Scalar::from_num(0.25));
        let _ = coloured.push(DirectionalLight::new(Vec3::from_int(1, 2, -1), tint));
        let _ = three.push(DirectionalLight::new(
            Vec3::X,
            LightColor::gray(Scalar::from_num(0.1)),
        ));
        assert!(!three.channels_in_words() && !coloured.channels_in_words());
        let (nv, nt) = torus_counts(48, 24);
        let (mut p, mut nrm, mut t) =
            (vec![Vec3::ZERO; nv], vec![Vec3::ZERO; nv], vec![[0; 3]; nt]);
        let mesh = torus(
            Scalar::ONE,
            Scalar::from_num(0.4),
            48,
            24,
            &mut p,
            &mut nrm,
            &mut t,
        )
        .unwrap();
        let base = Rgb888::new(255, 160, 64);
        let (mut faces, mut lit) = (0, 0);
        for (a, b) in [(0, 0), (20, 30), (-75, 140)] {
            let m =
                Mat4::rotation_y(Angle::from_degrees(b)) * Mat4::rotation_x(Angle::from_degrees(a));
            let nm = m.normal_matrix();
            for lighting in [&scene, &three, &coloured] {
                for tri in mesh.triangles() {
                    let q = tri.map(|i| mesh.positions()[i as usize].to_bits());
                    let n = face_direction(q, Some(&nm), mesh.extent(), mesh.edge_extent());
                    let got = face_lambert(base, n, &[0; 3], Normalize::Newton, lighting);
                    assert_eq!(got, unit_lambert(base, n, lighting), "{q:?}");
                    faces += 1;
                    lit += (got != lambert(base, None, &[0; 3], lighting)) as usize;
                }
            }
        }
        assert!(faces == 9 * nt && lit > 4 * nt, "{faces} {lit}");
        // Random directions of every scale, and crafted ones (the largest sums of squares,
        // which are quartered, and the smallest).
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let (mut worst, mut worst_exact) = (0, 0f64);
        let top = (1 << 30) - 1;
        let crafted = [
            [top, top, top],
            [top, 0, 0],
            [1 << 14, 0, 0],
            [-top, 1, -1],
            [1, 1, 1],
            [i32::MIN, i32::MAX, 0],
            [i32::MIN; 3],
        ];
        for k in 0..100_000 {
            let r = rng.next_u64();
            let n = crafted.get(k % 1000).copied().unwrap_or_else(|| {
                [0, 21, 42].map(|s| ((r >> s) as i32 >> 2) >> ((r >> (s + 16)) % 30))
            });
            let mut d = || rng.within(100) as i16;
            let light = lighting_of(&[((d(), d(), d()), 0.8)]);
            let (Some(l), Some(dir)) = (light.lights().next(), NewtonDirection::new(n)) else {
                continue;
            };
            let got = dir.cosine(l.direction);
            let unit = Normalize::Newton
                .unit32(n)
                .map_or(0, |u| cosine_unit(u, l.direction));
            worst = worst.max(got.abs_diff(unit));
            // The exact cosine of the direction the method keeps: n shifted to 15 bits.
            let bits = 32
                - n.iter()
                    .map(|c| c.unsigned_abs())
                    .max()
                    .unwrap_or(0)
                    .leading_zeros();
            let c = n.map(|x| (x as f64 * 2f64.powi(15 - bits as i32)).floor());
            let c = if bits > 15 { c } else { n.map(|x| x as f64) };
            let len = c.iter().map(|c| c * c).sum::<f64>().sqrt();
            let exact = c
                .iter()
                .zip(l.direction)
                .map(|(c, l)| c * l as f64)
                .sum::<f64>()
                / len;
            worst_exact = worst_exact.max((got as f64 - exact.max(0.0)).abs() / UNIT_ONE as f64);
            let (a, b) = (
                face_lambert(base, n, &[0; 3], Normalize::Newton, &light),
                unit_lambert(base, n, &light),
            );
            for (a, b) in [(a.r(), b.r()), (a.g(), b.g()), (a.b(), b.b())] {
                assert!(a.abs_diff(b) <= 1, "{n:?} {l:?}");
            }
        }
        assert!(worst <= 3 && worst_exact < 5e-9, "{worst} {worst_exact}");
        assert!(NewtonDirection::new([0; 3]).is_none());
    }

    /// A kept face normal decides which lights a face turns to only where its 15-bit
    /// direction's product with a light lies beyond ±2³¹, and there as the exact product
    /// does; where it decides, the colour is [`flat_color`]'s. Random triangles of every scale
    /// (the long edges' path too), lit by a random light or by one in the face's plane tilted
    /// by its rounding, with and without a second light: the second kind needs the margin
    /// (some of its 15-bit products take the other sign than the exact one).
    #[test]
    fn kept_face_normals_light_as_the_positions() {
        let mut rng = crate::testing::XorShift(0xD1B5_4A32_D192_ED03u64);
        let base = Rgb888::new(255, 160, 64);
        let (mut decided, mut undecided, mut flipped) = (0, 0, 0);
        for k in 0..60_000 {
            let scale = rng.pick(&[1 << 10, 1 << 16, 1 << 22, 1 << 28, 1 << 30]);
            let p = [(); 3].map(|_| [(); 3].map(|_| rng.within(scale)));
            let extent = p
                .iter()
                .flatten()
                .map(|c| c.unsigned_abs())
                .max()
                .unwrap_or(0);
            let edge = |q: [i32; 3]| map3([0, 1, 2], |j| (q[j] as i64 - p[0][j] as i64).abs());
            let edges = [edge(p[1]), edge(p[2])];
            let edge_extent = edges.iter().flatten().copied().max().unwrap_or(0) as u32;
            let extents = (extent, edge_extent);
            let n = face_direction(p, None, extent, edge_extent);
            let d = face_newton_direction(p, extents).unwrap_or(NewtonDirection::ZERO);
            let r = [(); 3].map(|_| rng.within(1000) as f64);
            let nf = n.map(|c| c as f64);
            let light = if k % 2 == 0 {
                r
            } else {
                // r × n: in the face's plane.
                [
                    r[1] * nf[2] - r[2] * nf[1],
                    r[2] * nf[0] - r[0] * nf[2],
                    r[0] * nf[1] - r[1] * nf[0],
                ]
            };
            let big = light.iter().map(|c| c.abs()).fold(0.0, f64::max);
            if big == 0.0 {
                continue;
            }
            let l = light.map(|c| (c / big * (1 << 20) as f64) as i32);
            let mut lighting = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.2)));
            let gray = LightColor::gray(Scalar::from_num(0.8));
            let _ = lighting.push(DirectionalLight::new(
                Vec3::from_bits(l[0], l[1], l[2]),
                gray,
            ));
            if k % 3 == 0 {
                let r = [(); 3].map(|_| rng.within(1 << 16));
                let tint = LightColor::new(Scalar::ONE, Scalar::from_num(0.5), Scalar::ZERO);
                let _ = lighting.push(DirectionalLight::new(
                    Vec3::from_bits(r[0], r[1], r[2]),
                    tint,
                ));
            }
            for light in lighting.lights() {
                let (t, exact) = (d.dot(light.direction), dot_wide(n, light.direction));
                if t.abs() >= 1 << 31 {
                    assert_eq!(t > 0, exact > 0, "{p:?} {light:?}");
                }
                flipped += ((t > 0) != (exact > 0)) as u32;
            }
            match kept_face_color(base, &d, &lighting) {
                Some(color) => {
                    let from_positions = flat_color(
                        base,
                        p,
                        &[0; 3],
                        None,
                        Normalize::Newton,
                        extents,
                        &lighting,
                    );
                    assert_eq!(color, from_positions, "{p:?} {lighting:?}");
                    decided += 1;
                }
                None => undecided += 1,
            }
        }
        assert!(
            decided > 30_000 && undecided > 10_000 && flipped > 1_000,
            "{decided} {undecided} {flipped}"
        );
    }

    /// Point lights at random surface points, normals and positions, under every attenuation,
    /// with and without a range, coloured and overbright, beside a directional light: every
    /// channel within one 8-bit step of the f64 value of the same (quantised) inputs. A surface
    /// at the light or from its range on gets nothing from it.
    #[test]
    #[cfg(feature = "point-light")]
    fn point_lights_within_one_step_of_f64() {
        use crate::scene::{Attenuation, PointLight};
        let mut rng = crate::testing::XorShift(0x6A09_E667_F3BC_C909u64);
        let mut uniform = |lo: f64, hi: f64| {
            lo + (hi - lo) * ((rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
        };
        let q = |v: f64| Scalar::from_num(v);
        let f = |s: Scalar| s.to_bits() as f64 / 65536.0;
        let base = Rgb888::new(255, 160, 64);
        let (mut lit, mut cut) = (0, 0);
        for k in 0..30_000 {
            let raw = [(); 3].map(|_| (uniform(-1.0, 1.0) * (1 << 20) as f64) as i64);
            let Some(n) = normalize(raw) else { continue };
            let at = [(); 3].map(|_| q(uniform(-8.0, 8.0)));
            let position = [(); 3].map(|_| q(uniform(-8.0, 8.0)));
            let attenuation = [
                Attenuation::None,
                Attenuation::Linear,
                Attenuation::InverseSquare,
            ][k % 3];
            let color = LightColor::new(q(uniform(0.0, 2.0)), q(uniform(0.0, 1.0)), q(0.5));
            let mut light =
                PointLight::new(Vec3::new(position[0], position[1], position[2]), color)
                    .attenuated(attenuation);
            if k % 4 == 0 {
                light = light.within(q(uniform(0.5, 12.0)));
            }
            let mut lighting = Lighting::<2>::new(LightColor::gray(q(0.1)));
            let sun = LightColor::gray(q(0.3));
            if k % 2 == 0 {
                lighting
                    .push(DirectionalLight::new(Vec3::from_int(-1, 1, 1), sun))
                    .unwrap();
            }
            lighting.push_point(light).unwrap();
            let at_bits = at.map(|c| i64::from(c.to_bits()));
            let got = lambert(base, Some(n), &at_bits, &lighting);
            // The f64 value.
            let nf = n.map(|c| c as f64 / (1u64 << 30) as f64);
            let v: [f64; 3] = core::array::from_fn(|j| f(position[j]) - f(at[j]));
            let d = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let in_range = light.range.is_none_or(|r| d < f(r));
            let near_edge = light.range.is_some_and(|r| (d - f(r)).abs() < 1e-3);
            if near_edge || d < 1e-3 {
                continue;
            }
            let cos = (nf[0] * v[0] + nf[1] * v[1] + nf[2] * v[2]) / d;
            let factor = match attenuation {
                Attenuation::Linear => 1.0 / (1.0 + d),
                Attenuation::InverseSquare => 1.0 / (1.0 + d * d),
                _ => 1.0,
            };
            let point = if in_range { cos.max(0.0) * factor } else { 0.0 };
            let s3 = 1.0 / 3f64.sqrt();
            let sun_cos = (-nf[0] + nf[1] + nf[2]) * s3;
            let sun = if k % 2 == 0 {
                f(q(0.3)) * sun_cos.max(0.0)
            } else {
                0.0
            };
            let channel = |c: Scalar, b: u8| {
                let s = (f(q(0.1)) + sun + f(c) * point).clamp(0.0, 1.0);
                (b as f64 * s).floor() as i32
            };
            let want = [
                channel(color.r, base.r()),
                channel(color.g, base.g()),
                channel(color.b, base.b()),
            ];
            let got = [got.r(), got.g(), got.b()].map(i32::from);
            for (g, w) in got.iter().zip(want) {
                assert!(
                    (g - w).abs() <= 1,
                    "{n:?} {at:?} {light:?}: {got:?} vs {want:?}"
                );
            }
            lit += (in_range && cos > 0.0) as u32;
            cut += !in_range as u32;
        }
        assert!(lit > 10_000 && cut > 1_000, "{lit} {cut}");
        // Without a range, a light lights surfaces however far (here 104,000 units away,
        // beyond what a range's 32 bits hold).
        let mut far = Lighting::<1>::new(LightColor::BLACK);
        far.push_point(PointLight::new([-30_000; 3], 1)).unwrap();
        let at = [30_000i64 << 16; 3];
        assert_eq!(lambert(base, normalize([-1; 3]), &at, &far), base);
        // At the light itself: ambient alone.
        let mut lighting = Lighting::<1>::new(LightColor::gray(q(0.2)));
        lighting.push_point(PointLight::new([1, 2, 3], 1)).unwrap();
        let at = [1i64 << 16, 2 << 16, 3 << 16];
        assert_eq!(
            lambert(base, Some([0, 1 << 30, 0]), &at, &lighting),
            lambert(base, None, &at, &lighting)
        );
    }

    /// Grey lights over an ambient of 0.2 (a zero direction is left out).
    fn lighting_of(lights: &[((i16, i16, i16), f64)]) -> Lighting<4> {
        let mut l = Lighting::<4>::new(LightColor::gray(Scalar::from_num(0.2)));
        for &(d, c) in lights {
            let light = DirectionalLight::new(
                Vec3::from_int(d.0, d.1, d.2),
                LightColor::gray(Scalar::from_num(c)),
            );
            let _ = l.push(light);
        }
        l
    }

    fn lighting() -> Lighting<2> {
        let mut l = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.2)));
        for (d, c) in [((-1, 1, 1), 0.6), ((2, -1, 3), 0.5)] {
            let light = DirectionalLight::new(
                Vec3::from_int(d.0, d.1, d.2),
                LightColor::gray(Scalar::from_num(c)),
            );
            l.push(light).unwrap();
        }
        l
    }

    /// Flat shading in model space (lights turned by a rotation's transpose once) gives the
    /// colour of shading in world space (normals through the normal matrix) within one 8-bit
    /// step, for rotations about every axis and uniform scales; a non-uniform scale or a shear
    /// keeps the world-space path, and so does a rotation scaled so small that its Q16.16
    /// entries are no longer a rotation within 2⁻¹².
    #[test]
    fn model_space_lighting_equals_world_space() {
        let lighting = lighting();
        let base = Rgb888::new(255, 160, 64);
        let mut rng = crate::testing::XorShift(0x9E37_79B9_7F4A_7C15u64);
        let mut next = |range: i32| rng.within(range);
        let mut compared = 0;
        for k in 0..200 {
            let turn = |d: i32| Angle::from_degrees(d);
            let scale = Scalar::from_num([1.0, 0.01, 37.5][k % 3]);
            let small = k % 3 == 1;
            let m = Mat4::rotation_z(turn(next(180)))
                * Mat4::rotation_y(turn(next(180)))
                * Mat4::rotation_x(turn(next(180)))
                * Mat4::scaling(Vec3::new(scale, scale, scale));
            let nm = m.normal_matrix();
            let Some(model) = lighting.in_model_space(&nm) else {
                assert!(small, "{m:?}");
                continue;
            };
            for _ in 0..50 {
                let p = [(); 3].map(|_| [(); 3].map(|_| next(1 << 17)));
                let world = flat_color(
                    base,
                    p,
                    &[0; 3],
                    Some(&nm),
                    Normalize::Newton,
                    (1 << 17, 1 << 18),
                    &lighting,
                );
                let local = flat_color(
                    base,
                    p,
                    &[0; 3],
                    None,
                    Normalize::Newton,
                    (1 << 17, 1 << 18),
                    &model,
                );
                let (w, l) = (
                    [world.r(), world.g(), world.b()],
                    [local.r(), local.g(), local.b()],
                );
                for (a, b) in w.iter().zip(l) {
                    assert!(a.abs_diff(b) <= 1, "{p:?}: {world:?} vs {local:?}");
                }
                compared += 1;
            }
        }
        assert!(compared >= 6_600, "{compared}");
        let stretched = Mat4::scaling(Vec3::new(Scalar::ONE, Scalar::from_num(1.01), Scalar::ONE));
        assert!(lighting
            .in_model_space(&stretched.normal_matrix())
            .is_none());
        let one = 1 << 16;
        let sheared = Mat4::from_bits([
            [one, 1 << 12, 0, 0],
            [0, one, 0, 0],
            [0, 0, one, 0],
            [0, 0, 0, one],
        ]);
        assert!(lighting.in_model_space(&sheared.normal_matrix()).is_none());
    }
}

//! Textures through the renderer: a receding floor, cut by the near plane, matches an exact
//! f64 ray cast texel for texel away from texel boundaries (perspective-correct), and does
//! not when mapped affinely; bands give the image of one pass; golden images for nearest,
//! bilinear, repeat, clamp and a lit textured torus; UVs survive OBJ seams.

mod common;

use common::golden;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use embedded_graphics::Pixel;
use fixed3d::camera::Camera;
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::{textured_torus, textured_torus_counts, Mesh, Uv};
use fixed3d::render::{Model, Renderer, Shade, Storage};
use fixed3d::scene::Light;
use fixed3d::texture::{Filter, Mapping, Texels, Texture, Wrap};

/// A display that keeps what it is sent.
struct Screen {
    w: u32,
    h: u32,
    pixels: Vec<Rgb888>,
}

impl Screen {
    fn new(w: u32, h: u32) -> Self {
        Screen {
            w,
            h,
            pixels: vec![Rgb888::new(1, 2, 3); (w * h) as usize],
        }
    }
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(self.w, self.h)
    }
}

impl DrawTarget for Screen {
    type Color = Rgb888;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        it: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in it {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.w && (p.y as u32) < self.h {
                self.pixels[(p.y as u32 * self.w + p.x as u32) as usize] = c;
            }
        }
        Ok(())
    }
}

/// A 64x64 texture whose every texel differs from its neighbours in every channel step.
fn texels() -> Vec<Rgb888> {
    (0..64 * 64)
        .map(|i| {
            let (x, y) = ((i % 64) as u8, (i / 64) as u8);
            Rgb888::new(x * 4, y * 4, (x ^ y) * 4 + 1)
        })
        .collect()
}

const W: u32 = 320;
const H: u32 = 240;
const EYE: [f64; 3] = [0.3, 1.0, 2.0];
const TARGET: [f64; 3] = [0.0, 0.0, -6.0];
const FOV: f64 = 60.0;

/// The floor y = 0 from x = −20 to 20, z = 4 (behind the eye: the near plane cuts it) to
/// z = −60, with u = (x + 20)/4 and v = (4 − z)/4: ten repeats across, sixteen away.
fn floor_positions() -> [Vec3; 4] {
    let p = |x: i32, z: i32| Vec3::from_int(x as i16, 0, z as i16);
    [p(-20, 4), p(20, 4), p(20, -60), p(-20, -60)]
}

fn floor_uvs() -> [Uv; 4] {
    let s = |v: i32| Scalar::from_num(v);
    [[s(0), s(0)], [s(10), s(0)], [s(10), s(16)], [s(0), s(16)]]
}

const FLOOR_TRIANGLES: [[u16; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

/// The floor drawn with `texture` under a white ambient light of 1, through buffers of
/// `rows` rows.
fn draw_floor(texture: &Texture<'_>, rows: u32) -> Vec<Rgb888> {
    let positions = floor_positions();
    let uvs = floor_uvs();
    let mesh = Mesh::new(&positions, &FLOOR_TRIANGLES)
        .and_then(|m| m.with_uvs(&uvs))
        .unwrap();
    let camera = Camera::perspective(FOV, 0.5, 100)
        .looking_at(EYE.map(Scalar::from_num), TARGET.map(Scalar::from_num));
    let models = [Model::new(&mesh, Rgb888::WHITE).textured(texture)];
    let mut storage = Storage::<4, 2>::new();
    let n = (W * rows) as usize;
    let (mut color, mut depth) = (vec![Rgb888::BLACK; n], vec![0u16; n]);
    let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
    let mut screen = Screen::new(W, H);
    renderer
        .render(&models, &[Light::ambient(1)], &camera, &mut screen)
        .unwrap();
    screen.pixels
}

/// The texel coordinates (s, t) = (u·64, (1 − v)·64) where the ray through screen point
/// (x, y) meets the floor, in f64; `None` above the horizon.
fn cast(x: f64, y: f64) -> Option<(f64, f64)> {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let norm = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|c| c / l)
    };
    let forward = norm(sub(TARGET, EYE));
    let right = norm(cross(forward, [0.0, 1.0, 0.0]));
    let up = cross(right, forward);
    let f = (FOV.to_radians() / 2.0).tan();
    let nx = (2.0 * x / W as f64 - 1.0) * f * W as f64 / H as f64;
    let ny = (1.0 - 2.0 * y / H as f64) * f;
    let d: [f64; 3] = [0, 1, 2].map(|k| forward[k] + nx * right[k] + ny * up[k]);
    if d[1] >= 0.0 {
        return None;
    }
    let t = -EYE[1] / d[1];
    let (px, pz) = (EYE[0] + t * d[0], EYE[2] + t * d[2]);
    if !(-19.0..19.0).contains(&px) || !(-58.0..3.0).contains(&pz) {
        return None;
    }
    let (u, v) = ((px + 20.0) / 4.0, (4.0 - pz) / 4.0);
    Some((u * 64.0, (1.0 - v) * 64.0))
}

/// The texel the exact map gives pixel (px, py) where it is unambiguous: the same for the
/// pixel's centre moved by an eighth of a pixel each way, and for the texel coordinates moved
/// by a sixteenth of a texel (the snapping of vertices, the error allowed the map).
fn reference_texel(px: u32, py: u32) -> Option<(i64, i64)> {
    let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
    let mut texel = None;
    for (dx, dy) in [
        (0.0, 0.0),
        (-0.125, 0.0),
        (0.125, 0.0),
        (0.0, -0.125),
        (0.0, 0.125),
    ] {
        let (s, t) = cast(cx + dx, cy + dy)?;
        for (ds, dt) in [(0.0, 0.0), (-0.0625, -0.0625), (0.0625, 0.0625)] {
            let here = (
                ((s + ds).floor() as i64).rem_euclid(64),
                ((t + dt).floor() as i64).rem_euclid(64),
            );
            if texel.is_some_and(|t| t != here) {
                return None;
            }
            texel = Some(here);
        }
    }
    texel
}

/// (pixels compared, pixels that differ from the exact map's texel).
fn compare_with_reference(pixels: &[Rgb888], texels: &[Rgb888]) -> (usize, usize) {
    let (mut compared, mut differ) = (0, 0);
    for py in 0..H {
        for px in 0..W {
            let Some((s, t)) = reference_texel(px, py) else {
                continue;
            };
            compared += 1;
            if pixels[(py * W + px) as usize] != texels[(t * 64 + s) as usize] {
                differ += 1;
            }
        }
    }
    (compared, differ)
}

/// The receding floor, cut by the near plane, perspective-correct: every pixel the exact map
/// puts clearly inside a texel shows that texel. Mapped affinely, thousands do not.
#[test]
fn textured_floor_matches_the_exact_map_texel_for_texel() {
    let texels = texels();
    let texture = Texture::new(Texels::from(&texels[..]), 64, 64).unwrap();
    let pixels = draw_floor(&texture, H);
    let (compared, differ) = compare_with_reference(&pixels, &texels);
    assert!(compared > 15_000, "{compared} pixels compared");
    assert_eq!(
        differ, 0,
        "{differ} of {compared} pixels show another texel"
    );
    let affine = draw_floor(&texture.with_mapping(Mapping::Affine), H);
    let (_, wrong) = compare_with_reference(&affine, &texels);
    assert!(wrong > 5_000, "affine mapping: only {wrong} pixels differ");
}

/// Bands of any height draw the textured floor's pixels as one pass does.
#[test]
fn textured_bands_equal_one_pass() {
    let texels = texels();
    let texture = Texture::new(Texels::from(&texels[..]), 64, 64)
        .unwrap()
        .with_filter(Filter::Bilinear);
    let whole = draw_floor(&texture, H);
    for rows in [1, 7, 16, 100] {
        assert!(draw_floor(&texture, rows) == whole, "bands of {rows} rows");
    }
}

/// Golden images of the floor: nearest and bilinear, repeated and clamped.
#[test]
fn textured_floor_golden_images() {
    let texels = texels();
    let texture = Texture::new(Texels::from(&texels[..]), 64, 64).unwrap();
    for (name, t) in [
        ("texture_nearest_repeat", texture),
        (
            "texture_bilinear_repeat",
            texture.with_filter(Filter::Bilinear),
        ),
        ("texture_nearest_clamp", texture.with_wrap(Wrap::Clamp)),
        (
            "texture_bilinear_clamp",
            texture.with_wrap(Wrap::Clamp).with_filter(Filter::Bilinear),
        ),
    ] {
        golden::check(name, W, H, &draw_floor(&t, H));
    }
}

/// A textured torus lit flat and Gouraud by a directional light: golden images, and under a
/// white ambient light of 1 every pixel is a texel as it is.
#[test]
fn textured_torus_lit_golden_images() {
    let texels = texels();
    let texture = Texture::new(Texels::from(&texels[..]), 64, 64).unwrap();
    const COUNTS: (usize, usize) = textured_torus_counts(48, 24);
    let (mut p, mut n, mut uv, mut t) = (
        vec![Vec3::ZERO; COUNTS.0],
        vec![Vec3::ZERO; COUNTS.0],
        vec![[Scalar::ZERO; 2]; COUNTS.0],
        vec![[0u16; 3]; COUNTS.1],
    );
    let (one, minor) = (Scalar::ONE, Scalar::from_num(0.4));
    let torus = textured_torus(one, minor, 48, 24, &mut p, &mut n, &mut uv, &mut t).unwrap();
    let camera = Camera::perspective(45, 1, 10).looking_at([0, 2, 4], [0, 0, 0]);
    let lights = [Light::ambient(0.2), Light::directional([-1, 2, 1], 0.8)];
    let draw = |shade: Shade, lights: &[Light]| {
        let model = Model::new(&torus, Rgb888::WHITE)
            .rotated_x(20)
            .textured(&texture)
            .shaded(shade);
        let mut storage = Storage::<{ COUNTS.0 }, { COUNTS.1 }>::new();
        let (mut color, mut depth) = (vec![Rgb888::BLACK; 320 * 16], vec![0u16; 320 * 16]);
        let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
        let mut screen = Screen::new(320, 240);
        renderer
            .render(&[model], lights, &camera, &mut screen)
            .unwrap();
        screen.pixels
    };
    golden::check("texture_torus_flat", 320, 240, &draw(Shade::Flat, &lights));
    golden::check(
        "texture_torus_gouraud",
        320,
        240,
        &draw(Shade::Gouraud, &lights),
    );
    let plain = draw(Shade::Flat, &[Light::ambient(1)]);
    let drawn: Vec<_> = plain
        .iter()
        .filter(|&&c| c != Rgb888::new(1, 2, 3))
        .collect();
    assert!(drawn.len() > 20_000);
    assert!(drawn
        .iter()
        .all(|c| **c == Rgb888::BLACK || texels.contains(c)));
}

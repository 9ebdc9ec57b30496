//! Textures through the renderer: a receding floor, cut by the near plane, matches an exact
//! f64 ray cast texel for texel away from texel boundaries (perspective-correct), and does
//! not when mapped affinely; bands give the image of one pass; golden images for nearest,
//! bilinear, repeat, clamp and a lit textured torus; UVs survive OBJ seams.

mod common;

use common::floor::*;
use common::golden;
use common::screen::Screen;
use embedded_graphics::pixelcolor::{IntoStorage, Rgb565, Rgb888, RgbColor};
use fixed3d::camera::Camera;
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::{textured_torus, textured_torus_counts, Mesh};
use fixed3d::render::{Model, Renderer, Shade, Storage};
use fixed3d::scene::Light;
use fixed3d::texture::{Filter, Mapping, Texels, Texture, Wrap};

/// `models` under `lights` seen by `camera` on a W x H display (blank where nothing was
/// written), through buffers of `rows` rows.
fn render<const V: usize, const T: usize>(
    storage: &mut Storage<V, T>,
    models: &[Model<'_>],
    lights: &[Light],
    camera: &Camera,
    rows: u32,
) -> Vec<Rgb888> {
    let n = (W * rows) as usize;
    let (mut color, mut depth) = (vec![Rgb888::BLACK; n], vec![0u16; n]);
    let mut renderer = Renderer::new(storage, &mut color, &mut depth);
    let mut screen = Screen::new(W, H, Rgb888::new(1, 2, 3));
    renderer
        .render(models, lights, camera, &mut screen)
        .unwrap();
    screen.pixels
}

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
    render(&mut storage, &models, &[Light::ambient(1)], &camera, rows)
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

/// The 48 x 24 textured torus, turned 20° about x, under `lights`, shaded `shade`, through
/// buffers of 16 rows.
fn draw_torus(texture: &Texture<'_>, shade: Shade, lights: &[Light]) -> Vec<Rgb888> {
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
    let model = Model::new(&torus, Rgb888::WHITE)
        .rotated_x(20)
        .textured(texture)
        .shaded(shade);
    let mut storage = Storage::<{ COUNTS.0 }, { COUNTS.1 }>::new();
    render(&mut storage, &[model], lights, &camera, 16)
}

/// A textured torus lit flat and Gouraud by a directional light: golden images, and under a
/// white ambient light of 1 every pixel is a texel as it is.
#[test]
fn textured_torus_lit_golden_images() {
    let texels = texels();
    let texture = Texture::new(Texels::from(&texels[..]), 64, 64).unwrap();
    let lights = [Light::ambient(0.2), Light::directional([-1, 2, 1], 0.8)];
    golden::check(
        "texture_torus_flat",
        320,
        240,
        &draw_torus(&texture, Shade::Flat, &lights),
    );
    golden::check(
        "texture_torus_gouraud",
        320,
        240,
        &draw_torus(&texture, Shade::Gouraud, &lights),
    );
    let plain = draw_torus(&texture, Shade::Flat, &[Light::ambient(1)]);
    let drawn: Vec<_> = plain
        .iter()
        .filter(|&&c| c != Rgb888::new(1, 2, 3))
        .collect();
    assert!(drawn.len() > 20_000);
    assert!(drawn
        .iter()
        .all(|c| **c == Rgb888::BLACK || texels.contains(c)));
}

/// A repeating Rgb565 texture read nearest with sides of powers of two takes a faster form
/// wherever a triangle is mapped affinely; it draws exactly what the general form does. The
/// same texels as big-endian bytes, which the general form reads, give the same images: the
/// floor affine and perspective-correct (its coordinates run over many repeats, and the near
/// plane cuts it) at sides from 1 to 4096, powers of two and not, and the torus flat and
/// Gouraud under a coloured light.
#[test]
fn tiled_rgb565_textures_draw_as_the_general_form() {
    let texels: Vec<Rgb565> = texels().into_iter().map(Rgb565::from).collect();
    let bytes: Vec<u8> = texels
        .iter()
        .flat_map(|c| c.into_storage().to_be_bytes())
        .collect();
    let sides = [
        (64, 64),
        (2, 2048),
        (4096, 1),
        (1, 4096),
        (128, 32),
        (48, 64),
        (3, 5),
    ];
    for (width, height) in sides {
        let n = usize::from(width * height);
        let tiled = Texture::new(Texels::from(&texels[..n]), width, height).unwrap();
        let general = Texture::new(Texels::Rgb565Be(&bytes[..2 * n]), width, height).unwrap();
        for mapping in [Mapping::Affine, Mapping::Perspective] {
            let (a, b) = (tiled.with_mapping(mapping), general.with_mapping(mapping));
            let floor = draw_floor(&a, H);
            assert!(floor.iter().filter(|&&c| c != Rgb888::new(1, 2, 3)).count() > 30_000);
            let what = format!("{width}x{height} {mapping:?} floor");
            assert!(floor == draw_floor(&b, H), "{what}");
        }
    }
    let tiled = Texture::new(Texels::from(&texels[..]), 64, 64).unwrap();
    let general = Texture::new(Texels::Rgb565Be(&bytes), 64, 64).unwrap();
    let lights = [
        Light::ambient(0.2),
        Light::directional([-1, 2, 1], Rgb888::new(255, 160, 64)),
    ];
    for shade in [Shade::Flat, Shade::Gouraud] {
        let torus = draw_torus(&tiled, shade, &lights);
        assert!(
            torus == draw_torus(&general, shade, &lights),
            "{shade:?} torus"
        );
    }
}

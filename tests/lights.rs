//! Point lights and highlights through the renderer: a flat face lit at its centre and Gouraud
//! vertices lit at their world positions, and highlights seen along the camera's axis, against
//! f64, wherever the model and camera are placed; golden images of the torus under a point
//! light, flat and Gouraud, and glossy.

mod common;

use common::golden;
use common::screen::Screen;
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use fixed3d::mesh::{torus, torus_counts, Mesh, Specular};
use fixed3d::prelude::*;
use fixed3d::scene::LightColor;

const BLANK: Rgb888 = Rgb888::new(1, 2, 3);
const BASE: Rgb888 = Rgb888::new(255, 160, 64);

/// The reference torus (48 x 24) in storage of its own.
struct Torus {
    p: Vec<Vec3>,
    n: Vec<Vec3>,
    t: Vec<[u16; 3]>,
}

impl Torus {
    fn new() -> Self {
        let (nv, nt) = torus_counts(48, 24);
        Torus {
            p: vec![Vec3::ZERO; nv],
            n: vec![Vec3::ZERO; nv],
            t: vec![[0; 3]; nt],
        }
    }

    fn mesh(&mut self) -> Mesh<'_> {
        let (one, minor) = (Scalar::ONE, Scalar::from_num(0.4));
        torus(one, minor, 48, 24, &mut self.p, &mut self.n, &mut self.t).unwrap()
    }
}

/// One `w` x `h` frame of `models` through the renderer, in bands of `rows` rows.
fn frame(
    models: &[Model<'_>],
    lights: &[Light],
    camera: &Camera,
    (w, h): (u32, u32),
    rows: usize,
) -> Vec<Rgb888> {
    let vertices = models.iter().map(|m| m.mesh().positions().len()).sum();
    let triangles = models.iter().map(|m| m.mesh().triangles().len()).sum();
    let mut screen = Screen::new(w, h, BLANK);
    let (mut v, mut b) = (
        vec![fixed3d::pipeline::ScreenVertex::DEFAULT; vertices],
        vec![fixed3d::pipeline::Bin::EMPTY; triangles],
    );
    let cells = w as usize * rows;
    let (mut c, mut d) = (vec![Rgb888::BLACK; cells], vec![0u16; cells]);
    let mut renderer = Renderer::from_slices(&mut v, &mut b, &mut c, &mut d);
    renderer
        .render(models, lights, camera, &mut screen)
        .unwrap();
    screen.pixels
}

/// The pixels `model` covers in a 64x64 frame (its background black).
fn covered(model: Model<'_>, lights: &[Light], camera: &Camera) -> Vec<Rgb888> {
    let pixels = frame(&[model], lights, camera, (64, 64), 64);
    pixels.into_iter().filter(|&p| p != Rgb888::BLACK).collect()
}

/// Every pixel within one 8-bit step of `want` per channel.
fn all_within_one(pixels: &[Rgb888], want: [i32; 3]) -> bool {
    pixels.iter().all(|p| {
        let got = [p.r(), p.g(), p.b()].map(i32::from);
        got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 1)
    })
}

/// An equilateral triangle about the origin in the plane y = 0, facing +y, its corners one
/// unit from the centre, every vertex normal +y. A light on the y axis is as far from each
/// corner as from the others and at the same angle: Gouraud then gives one colour.
fn triangle_positions() -> [Vec3; 3] {
    let s = 3f64.sqrt() / 2.0;
    [[0.0, 0.0, -1.0], [-s, 0.0, 0.5], [s, 0.0, 0.5]].map(Vec3::from)
}

/// The triangle of `positions`, every vertex normal +y.
fn facing_up(positions: &[Vec3; 3]) -> Mesh<'_> {
    static NORMALS: [Vec3; 3] = [Vec3::Y; 3];
    static TRIANGLE: [[u16; 3]; 1] = [[0, 1, 2]];
    Mesh::new(positions, &TRIANGLE)
        .and_then(|m| m.with_normals(&NORMALS))
        .unwrap()
}

fn attenuate(a: Attenuation, d: f64) -> f64 {
    match a {
        Attenuation::Linear => 1.0 / (1.0 + d),
        Attenuation::InverseSquare => 1.0 / (1.0 + d * d),
        _ => 1.0,
    }
}

/// The f64 colour of a surface lit by ambient 0.1 and a white point light of `intensity` at
/// distance `d` and cosine `cos`.
fn expected(intensity: f64, a: Attenuation, d: f64, cos: f64) -> [i32; 3] {
    let s = (0.1 + intensity * cos * attenuate(a, d)).clamp(0.0, 1.0);
    [BASE.r(), BASE.g(), BASE.b()].map(|b| (b as f64 * s).floor() as i32)
}

/// Flat: the face's colour is that of its centre, straight below the light (cosine 1,
/// distance h·scale). Gouraud: each corner's, at distance scale·√(1 + h²). Random turns,
/// scales and places, every attenuation, one light above the triangle.
#[test]
fn point_lights_light_faces_at_their_centre_and_vertices_where_they_are() {
    let positions = triangle_positions();
    let mesh = facing_up(&positions);
    let mut rng = common::Rng(0x9E37_79B9_7F4A_7C15);
    let mut checked = 0;
    for k in 0..60 {
        let (turn, scale) = (rng.range(0.0, 360.0), rng.range(0.5, 3.0));
        let place = [
            rng.range(-5.0, 5.0),
            rng.range(-2.0, 2.0),
            rng.range(-5.0, 5.0),
        ];
        let h = rng.range(0.3, 4.0);
        let attenuation = [
            Attenuation::None,
            Attenuation::Linear,
            Attenuation::InverseSquare,
        ][k % 3];
        let intensity = rng.range(0.2, 3.0);
        // Quantise what the f64 value reads as the library does.
        let (scale, h, intensity) = (
            Scalar::from_num(scale).to_num::<f64>(),
            Scalar::from_num(h).to_num::<f64>(),
            Scalar::from_num(intensity).to_num::<f64>(),
        );
        let place = place.map(|c| Scalar::from_num(c).to_num::<f64>());
        let lamp = [place[0], place[1] + h * scale, place[2]];
        let lights = [
            Light::ambient(0.1),
            PointLight::new(lamp, intensity)
                .attenuated(attenuation)
                .into(),
        ];
        let centre = Vec3::from(place);
        let eye = [
            place[0] + 0.5,
            place[1] + 6.0 * scale,
            place[2] + 3.0 * scale,
        ];
        let camera = Camera::perspective(60, 0.5, 100).looking_at(eye, centre);
        let corner = scale * (1.0 + h * h).sqrt();
        for (shade, want) in [
            (
                Shade::Flat,
                expected(intensity, attenuation, h * scale, 1.0),
            ),
            (
                Shade::Gouraud,
                expected(intensity, attenuation, corner, h * scale / corner),
            ),
        ] {
            let model = Model::new(&mesh, BASE)
                .scaled(scale)
                .rotated_y(turn)
                .translated(place)
                .shaded(shade);
            let drawn = covered(model, &lights, &camera);
            assert!(drawn.len() > 50, "{k}: {} pixels", drawn.len());
            assert!(
                all_within_one(&drawn, want),
                "{k} {shade:?} {attenuation:?}: {drawn:?} vs {want:?}"
            );
            checked += 1;
        }
    }
    assert_eq!(checked, 120);
}

/// A light's range cuts it off: a face beyond it gets the ambient light alone, a face within
/// it more.
#[test]
fn a_point_light_lights_nothing_from_its_range_on() {
    let positions = triangle_positions();
    let triangles = [[0u16, 1, 2]];
    let mesh = Mesh::new(&positions, &triangles).unwrap();
    let camera = Camera::perspective(60, 0.5, 100).looking_at([0.5, 6.0, 3.0], [0, 0, 0]);
    let colour = |range: f64| {
        let lamp = PointLight::new([0, 2, 0], 1).within(range);
        let lights = [Light::ambient(0.1), lamp.into()];
        let pixels = frame(&[Model::new(&mesh, BASE)], &lights, &camera, (64, 64), 64);
        pixels[32 * 64 + 32]
    };
    let ambient = Rgb888::new(25, 16, 6);
    assert_eq!(colour(1.99), ambient);
    assert_eq!(colour(2.0), ambient);
    assert_eq!(colour(2.01), BASE);
}

/// The torus of the reference scene beside a warm point light that falls off with the square
/// of the distance, a cool directional light and a little ambient: flat and Gouraud.
#[test]
fn golden_point_light_torus() {
    let mut torus = Torus::new();
    let mesh = torus.mesh();
    let warm = Rgb888::new(255, 200, 140);
    let lights = [
        Light::ambient(0.08),
        Light::directional([1, 1, 1], Rgb888::new(40, 60, 90)),
        PointLight::new(
            [-0.9, 0.4, 0.8],
            LightColor::from_rgb888(warm, Scalar::from_num(3)),
        )
        .attenuated(Attenuation::InverseSquare)
        .within(4)
        .into(),
    ];
    let camera = Camera::perspective(60, 1, 10).looking_at([0.0, 1.2, 3.0], [0, 0, 0]);
    let draw = |shade: Shade| {
        let model = Model::new(&mesh, Rgb888::new(230, 230, 230))
            .rotated_x(60)
            .shaded(shade);
        frame(&[model], &lights, &camera, (320, 240), 40)
    };
    let flat = draw(Shade::Flat);
    let gouraud = draw(Shade::Gouraud);
    golden::check("point_light_torus_flat", 320, 240, &flat);
    golden::check("point_light_torus_gouraud", 320, 240, &gouraud);
    // The light falls off: the brightest pixels are far brighter than the dimmest lit ones.
    let luma = |c: &Rgb888| c.r() as u32 + c.g() as u32 + c.b() as u32;
    let lit: Vec<u32> = gouraud
        .iter()
        .filter(|c| **c != Rgb888::BLACK)
        .map(luma)
        .collect();
    assert!(lit.len() > 20_000);
    assert!(lit.iter().max() > Some(&600) && lit.iter().min() < Some(&150));
}

/// Highlights are seen along the camera's view axis: the triangle facing +y, glossy, every
/// vertex normal +y, under one directional light, seen from random eyes: every vertex gets the
/// same colour, which is the f64 Blinn-Phong value for the half vector between the light and
/// the direction from the target to the eye.
#[test]
fn highlights_follow_the_camera() {
    let positions = triangle_positions();
    let mesh = facing_up(&positions);
    let mut rng = common::Rng(0x6A09_E667_F3BC_C909);
    let norm = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|c| c / l)
    };
    let (mut checked, mut bright) = (0, 0);
    for k in 0..80 {
        let q = |v: f64| Scalar::from_num(v).to_num::<f64>();
        let eye = [
            q(rng.range(-3.0, 3.0)),
            q(rng.range(2.0, 6.0)),
            q(rng.range(-3.0, 3.0)),
        ];
        let towards = [q(rng.range(-1.0, 1.0)), 1.0, q(rng.range(-1.0, 1.0))];
        let shininess = [1u16, 8, 32, 128][k % 4];
        let lights = [Light::ambient(0.1), Light::directional(towards, 0.5)];
        let camera = Camera::perspective(60, 0.5, 100).looking_at(eye, [0, 0, 0]);
        let gloss = Specular::new(Rgb888::new(200, 220, 255), shininess);
        let model = Model::new(&mesh, BASE)
            .shaded(Shade::Gouraud)
            .glossy(&gloss);
        let drawn = covered(model, &lights, &camera);
        let l = norm(towards);
        let v = norm(eye);
        let h = norm([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
        let spec = (h[1].max(0.0).powi(shininess as i32) * 0.5).min(1.0);
        let diffuse = (0.1 + 0.5 * l[1]).min(1.0);
        let want = [(BASE.r(), 200u8), (BASE.g(), 220), (BASE.b(), 255)].map(|(b, s)| {
            let d = (b as f64 * diffuse).floor() as i32;
            (d + (s as f64 * spec).floor() as i32).min(255)
        });
        assert!(drawn.len() > 20, "{k}: {} pixels", drawn.len());
        assert!(
            all_within_one(&drawn, want),
            "{k} eye {eye:?}: {drawn:?} vs {want:?}"
        );
        bright += (want[2] > 100) as u32;
        checked += 1;
    }
    assert!(checked == 80 && bright > 10, "{checked} {bright}");
}

/// The torus of the reference scene, glossy under a white directional light and a warm point
/// light: Gouraud and perspective-correct Gouraud; flat leaves the highlights out.
#[test]
fn golden_specular_torus() {
    let mut torus = Torus::new();
    let mesh = torus.mesh();
    let lights = [
        Light::ambient(0.1),
        Light::directional([-1, 1, 1], 0.6),
        PointLight::new([1.2, -0.4, 1.0], Rgb888::new(255, 190, 120))
            .attenuated(Attenuation::Linear)
            .into(),
    ];
    let camera = Camera::perspective(60, 1, 10).looking_at([0.0, 0.0, 2.6], [0, 0, 0]);
    let gloss = Specular::new(Rgb888::new(255, 255, 255), 24);
    let draw = |shade: Shade| {
        let model = Model::new(&mesh, Rgb888::new(40, 90, 200))
            .rotated_x(20)
            .rotated_y(30)
            .shaded(shade)
            .glossy(&gloss);
        frame(&[model], &lights, &camera, (320, 240), 240)
    };
    let gouraud = draw(Shade::Gouraud);
    golden::check("specular_torus_gouraud", 320, 240, &gouraud);
    golden::check(
        "specular_torus_perspective",
        320,
        240,
        &draw(Shade::PerspectiveGouraud),
    );
    // Highlights: pixels far redder than a blue surface can be lit (its red is 40 at most),
    // which flat shading does not have.
    let white = |p: &[Rgb888]| p.iter().filter(|c| c.r() > 150 && c.g() > 150).count();
    assert!(white(&gouraud) > 100, "{}", white(&gouraud));
    assert_eq!(white(&draw(Shade::Flat)), 0);
}

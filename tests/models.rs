//! Golden images (exact) of the reference torus and two of the shared models in each mode, drawn
//! through the same desktop code as the render tool and the viewer.

mod common;
#[path = "../examples/common/desktop.rs"]
mod desktop;

use desktop::{framed, render, Mode, Model, Placed, View};
use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Scalar, Vec3};
use fixed3d::projection::{Projection, Viewport};

fn view(mode: Mode, look: LookAt, projection: Projection, w: u32, h: u32) -> View {
    View {
        width: w,
        height: h,
        mode,
        view: look.view().unwrap(),
        projection,
        ambient: Scalar::from_num(0.2),
        lights: desktop::default_lights(),
        background: Rgb888::new(0, 0, 0),
        cull: true,
        depth: true,
        bands: 0,
        specular: None,
    }
}

#[test]
fn reference_torus_in_each_mode() {
    let (torus, matrix) = Model::reference_torus();
    let objects = [Placed {
        model: &torus,
        matrix,
        color: Rgb888::new(255, 160, 64),
        texture: None,
    }];
    let viewport = Viewport::new(320, 240).unwrap();
    let look = LookAt::new(Vec3::from_f32(0.0, 0.0, 2.6).unwrap(), Vec3::ZERO, Vec3::Y);
    let p = Projection::perspective(
        Angle::from_degrees(60),
        viewport.aspect(),
        Scalar::from_num(1),
        Scalar::from_num(10),
    )
    .unwrap();
    for mode in [Mode::Wire, Mode::Flat, Mode::Gouraud] {
        let r = render(&objects, &view(mode, look, p, 320, 240)).unwrap();
        if mode != Mode::Wire {
            // The integer-generated torus covers the reference scene's pixels within 0.1%.
            let covered = r.covered(Rgb888::new(0, 0, 0)) as i64;
            assert!((covered - 28_515).abs() <= 28, "{mode:?}: {covered}");
        }
        common::golden::check(
            &format!("torus_{}_rgb888", mode.name()),
            320,
            240,
            &r.pixels,
        );
    }
}

#[test]
fn shared_models_in_each_mode() {
    for name in ["teapot", "suzanne"] {
        let model =
            Model::load_obj(&format!("{}/models/{name}.obj", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let objects = [Placed {
            model: &model,
            matrix: fixed3d::math::Mat4::IDENTITY,
            color: Rgb888::new(220, 200, 140),
            texture: None,
        }];
        let viewport = Viewport::new(200, 150).unwrap();
        let (look, p) = framed(
            &model.bounds,
            Vec3::from_int(1, 1, 3),
            Angle::from_degrees(50),
            viewport.aspect(),
        )
        .unwrap();
        for mode in [Mode::Wire, Mode::Flat, Mode::Gouraud] {
            let r = render(&objects, &view(mode, look, p, 200, 150)).unwrap();
            assert!(r.covered(Rgb888::new(0, 0, 0)) > 2000, "{name} {mode:?}");
            common::golden::check(&format!("{name}_{}", mode.name()), 200, 150, &r.pixels);
        }
    }
}

#[test]
fn bands_and_direct_filling_match_the_full_frame() {
    let model =
        Model::load_obj(&format!("{}/models/spot.obj", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let objects = [Placed {
        model: &model,
        matrix: fixed3d::math::Mat4::IDENTITY,
        color: Rgb888::new(220, 200, 140),
        texture: None,
    }];
    let viewport = Viewport::new(160, 120).unwrap();
    let (look, p) = framed(
        &model.bounds,
        Vec3::from_int(2, 1, 2),
        Angle::from_degrees(50),
        viewport.aspect(),
    )
    .unwrap();
    let full = render(&objects, &view(Mode::Gouraud, look, p, 160, 120)).unwrap();
    let mut banded = view(Mode::Gouraud, look, p, 160, 120);
    banded.bands = 9;
    let b = render(&objects, &banded).unwrap();
    assert!(full.pixels == b.pixels);
    assert_eq!(
        (full.stats.drawn, full.stats.culled),
        (b.stats.drawn, b.stats.culled)
    );
}

/// Per-object textures: under a white ambient light of 1 alone, a textured sphere in front of
/// an untextured cube shows its texels and the cube its colour, wherever each is in front,
/// in every solid mode, in one pass and in bands (one pass per texture, sharing the depth
/// buffer), and the sphere alone draws the same pixels as in the scene where it is in front.
#[test]
fn each_object_has_its_own_texture() {
    use fixed3d::math::Mat4;
    use fixed3d::texture::{Texels, Texture};
    let sphere = Model::shape_with_uvs("sphere").unwrap();
    let cube = Model::shape("cube").unwrap();
    let texels: Vec<Rgb888> = (0..32 * 16)
        .map(|i| Rgb888::new((i % 32 * 8) as u8, (i / 32 * 16) as u8, 200))
        .collect();
    let texture = Texture::new(Texels::Rgb888(&texels), 32, 16).unwrap();
    let grey = Rgb888::new(90, 90, 90);
    let near = Mat4::translation(Vec3::from_f32(0.0, 0.0, 2.5).unwrap());
    let objects = [
        Placed {
            model: &cube,
            matrix: Mat4::scaling(Vec3::from_int(2, 2, 2)),
            color: grey,
            texture: None,
        },
        Placed {
            model: &sphere,
            matrix: near,
            color: Rgb888::new(255, 0, 0),
            texture: Some(&texture),
        },
    ];
    let viewport = Viewport::new(160, 120).unwrap();
    let look = LookAt::new(Vec3::from_int(0, 0, 6), Vec3::ZERO, Vec3::Y);
    let p = Projection::perspective(
        Angle::from_degrees(60),
        viewport.aspect(),
        Scalar::from_num(1),
        Scalar::from_num(20),
    )
    .unwrap();
    for mode in [Mode::Flat, Mode::Gouraud, Mode::Perspective] {
        let mut v = view(mode, look, p, 160, 120);
        v.ambient = Scalar::ONE;
        v.lights.clear();
        let r = render(&objects, &v).unwrap();
        let (shown, greys) = (
            r.pixels.iter().filter(|c| texels.contains(c)).count(),
            r.pixels.iter().filter(|&&c| c == grey).count(),
        );
        let background = r
            .pixels
            .iter()
            .filter(|&&c| c == Rgb888::new(0, 0, 0))
            .count();
        assert_eq!(shown + greys + background, 160 * 120, "{mode:?}");
        assert!(shown > 1500 && greys > 1500, "{mode:?}: {shown} {greys}");
        v.bands = 9;
        assert!(render(&objects, &v).unwrap().pixels == r.pixels, "{mode:?}");
        let alone = render(&objects[1..], &v).unwrap();
        for (a, b) in alone.pixels.iter().zip(&r.pixels) {
            assert!(*a == Rgb888::new(0, 0, 0) || a == b, "{mode:?}");
        }
    }
}

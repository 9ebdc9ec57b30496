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

fn view(mode: Mode, look: LookAt, projection: Projection, w: u32, h: u32) -> View<'static> {
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
        texture: None,
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

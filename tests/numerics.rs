//! Cases T31, T32, T35 and T37: long-lived camera state, angle wrap-around, coordinates at the
//! edge of the fixed-point range, and float entry points.

mod common;

use common::world::Setup;
use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::buffer::Direct;
use fixed3d::camera::FlyCamera;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{Object, Transform, CUBE};
use fixed3d::pipeline::{Cull, ScreenVertex};
use fixed3d::scene::{LightColor, Lighting, Scene};
use fixed3d::shade::Unlit;

fn orthonormality(m: &Mat4) -> (f64, f64) {
    let r: Vec<Vec<f64>> = (0..3)
        .map(|i| (0..3).map(|j| m.to_bits()[i][j] as f64 / 65536.0).collect())
        .collect();
    let mut worst = 0f64;
    for i in 0..3 {
        for j in 0..3 {
            let d: f64 = (0..3).map(|k| r[k][i] * r[k][j]).sum();
            worst = worst.max((d - if i == j { 1.0 } else { 0.0 }).abs());
        }
    }
    let det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1])
        - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0])
        + r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    (worst, (det - 1.0).abs())
}

/// T31: a camera turned 0.7 degrees per frame (yaw, with the pitch swinging) for 100,000 frames
/// stays orthonormal at every frame: its matrix is rebuilt from integer angles, never
/// accumulated.
#[test]
fn t31_camera_stays_orthonormal() {
    let mut cam = FlyCamera::new(Vec3::from_int(1, 2, 3));
    let step = Angle::from_degrees_f32(0.7);
    let mut worst = (0f64, 0f64);
    for frame in 0..100_000u32 {
        let pitch = if (frame / 300) % 2 == 0 {
            Angle::from_degrees_f32(0.45)
        } else {
            -Angle::from_degrees_f32(0.45)
        };
        cam.turn(step, pitch);
        cam.move_forward(Scalar::from_num(0.001));
        let (o, d) = orthonormality(&cam.view());
        worst = (worst.0.max(o), worst.1.max(d));
        assert!(o <= 1e-4 && d <= 1e-4, "frame {frame}: {o} {d}");
    }
    assert!(worst.0 < 1e-4);
}

/// T32: an angle accumulated a million times is exactly the product modulo a turn, so its
/// sine is as accurate as on the first frame.
#[test]
fn t32_angle_accumulators_wrap_exactly() {
    let step = Angle::from_degrees_f32(0.7);
    let mut a = Angle::ZERO;
    for _ in 0..1_000_000 {
        a += step;
    }
    assert_eq!(a, step.wrapping_mul(1_000_000));
    let t = a.to_bits() as f64 / 4_294_967_296.0 * std::f64::consts::TAU;
    assert!((a.sin().to_num::<f64>() - t.sin()).abs() < 6e-9);
    assert!((a.cos().to_num::<f64>() - t.cos()).abs() < 6e-9);
}

fn draw_cube(s: &Setup, model: Mat4) -> (Vec<u32>, u32) {
    let objects = [Object::new(&CUBE, model, Rgb888::new(255, 255, 255))];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let prepared = s
        .frame()
        .with_cull(Cull::Back)
        .prepare(&scene, &mut cache, Unlit)
        .unwrap();
    let mut canvas = common::HitCanvas::new(s.w as i32, s.h as i32);
    let stats = prepared.draw(&mut Direct::new(&mut canvas)).unwrap();
    assert_eq!(canvas.outside, 0);
    (canvas.hits, stats.written)
}

/// T35: scale 0 draws nothing; translations at the edge of the Q16.16 range saturate and
/// never wrap into view; a scene far from the origin draws like the same scene at the origin.
#[test]
fn t35_extreme_model_matrices() {
    let s = Setup::new([0.0, 0.0, 5.0], [0.0, 0.0, 0.0]);
    let zero = Transform::new().scaled(Vec3::ZERO).matrix();
    assert_eq!(draw_cube(&s, zero).1, 0);
    for x in [32767, -32768] {
        let far = Transform::new()
            .translated(Vec3::from_int(x, 0, 0))
            .scaled(Vec3::from_int(3, 3, 3))
            .matrix();
        assert_eq!(draw_cube(&s, far).1, 0, "x = {x}");
    }
    let here = draw_cube(&s, Mat4::IDENTITY).0;
    let mut s2 = s;
    s2.eye = [32000.0, 0.0, 5.0];
    s2.target = [32000.0, 0.0, 0.0];
    let there = draw_cube(
        &s2,
        Transform::new()
            .translated(Vec3::from_int(32000, 0, 0))
            .matrix(),
    )
    .0;
    let differ = here.iter().zip(&there).filter(|(a, b)| a != b).count();
    assert!(differ <= 8, "{differ} pixels differ far from the origin");
}

/// T37: float entry points discard non-finite values instead of panicking.
#[test]
fn t37_non_finite_floats() {
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30] {
        assert!(Vec3::from_f32(bad, 0.0, 0.0).is_none());
        assert!(Vec3::from_f32(0.0, 0.0, bad).is_none());
    }
    assert_eq!(
        Vec3::from_f32(f32::MIN_POSITIVE / 2.0, -0.0, 0.0),
        Some(Vec3::ZERO)
    );
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(Angle::from_degrees_f32(bad), Angle::ZERO);
        assert_eq!(Angle::from_radians_f32(bad), Angle::ZERO);
    }
    let _ = Angle::from_degrees_f32(f32::MAX).sin();
}

/// Constructors given nonsense return an error, never a broken matrix.
#[test]
fn constructors_refuse_nonsense() {
    use fixed3d::camera::{CameraError, LookAt};
    use fixed3d::projection::{Projection, ProjectionError, Viewport};
    let s = |v: f64| Scalar::from_num(v);
    let fov = Angle::from_degrees(60);
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(0.0), s(10.0)),
        Err(ProjectionError::NearTooSmall)
    );
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(-1.0), s(10.0)),
        Err(ProjectionError::NearTooSmall)
    );
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(0.0001), s(10.0)),
        Err(ProjectionError::NearTooSmall)
    );
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(2.0), s(2.0)),
        Err(ProjectionError::FarNotBeyondNear)
    );
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(2.0), s(1.0)),
        Err(ProjectionError::FarNotBeyondNear)
    );
    assert_eq!(
        Projection::perspective(fov, s(1.0), s(30000.0), Scalar::from_bits(30000 << 16 | 1)),
        Err(ProjectionError::FarNotBeyondNear)
    );
    for bad in [
        Angle::ZERO,
        Angle::HALF_TURN,
        Angle::from_degrees(200),
        Angle::from_bits(1),
    ] {
        assert_eq!(
            Projection::perspective(bad, s(1.0), s(1.0), s(10.0)),
            Err(ProjectionError::FieldOfView),
            "{bad:?}"
        );
    }
    assert_eq!(
        Projection::perspective(fov, s(0.0), s(1.0), s(10.0)),
        Err(ProjectionError::Aspect)
    );
    assert_eq!(
        Projection::perspective(fov, Scalar::from_bits(1), s(1.0), s(10.0)),
        Err(ProjectionError::Aspect)
    );
    assert!(
        Projection::perspective(Angle::from_degrees(179), s(1.0), s(0.001), s(10000.0)).is_ok()
    );
    assert_eq!(
        Projection::orthographic(s(0.0), s(1.0), s(0.0), s(1.0)),
        Err(ProjectionError::Aspect)
    );
    assert_eq!(
        Projection::orthographic(s(2.0), s(1.0), s(1.0), s(1.0)),
        Err(ProjectionError::FarNotBeyondNear)
    );
    assert!(Projection::orthographic(s(2.0), s(1.0), s(-5.0), s(5.0)).is_ok());
    assert_eq!(Viewport::new(2049, 10), Err(ProjectionError::ViewportSize));
    let up = Vec3::Y;
    assert_eq!(
        LookAt::new(Vec3::from_int(1, 2, 3), Vec3::from_int(1, 2, 3), up).view(),
        Err(CameraError::EyeAtTarget)
    );
    assert_eq!(
        LookAt::new(Vec3::from_int(0, 5, 0), Vec3::ZERO, up).view(),
        Err(CameraError::UpParallelToView)
    );
    assert_eq!(
        LookAt::new(Vec3::from_int(0, 0, 5), Vec3::ZERO, Vec3::ZERO).view(),
        Err(CameraError::UpParallelToView)
    );
    // Extreme but valid: eye and target at opposite corners of the range.
    let v = LookAt::new(
        Vec3::from_int(32767, 32767, 32767),
        Vec3::from_int(-32768, -32768, -32768),
        up,
    )
    .view()
    .unwrap();
    let (o, d) = orthonormality(&v);
    assert!(o < 1e-4 && d < 1e-4);
}

/// Orthographic projection: a cube seen face-on shows exactly its front face at its true size
/// (the back face, as large, hides behind it), where a perspective view would magnify it.
#[test]
fn orthographic_projection_draws_true_size() {
    use fixed3d::camera::LookAt;
    use fixed3d::pipeline::Frame;
    use fixed3d::projection::{Projection, Viewport};
    let viewport = Viewport::new(64, 64).unwrap();
    let view = LookAt::new(Vec3::from_int(0, 0, 5), Vec3::ZERO, Vec3::Y)
        .view()
        .unwrap();
    let s = |v: f64| Scalar::from_num(v);
    let draw = |projection: Projection| {
        let objects = [Object::new(
            &CUBE,
            Mat4::IDENTITY,
            Rgb888::new(255, 255, 255),
        )];
        let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
        let mut cache = vec![ScreenVertex::DEFAULT; 8];
        let prepared = Frame::new(&view, &projection, viewport)
            .prepare(&scene, &mut cache, Unlit)
            .unwrap();
        let mut canvas = common::HitCanvas::new(64, 64);
        prepared.draw(&mut Direct::new(&mut canvas)).unwrap();
        canvas
    };
    // A 4-unit tall view of 64 pixels: the 2-unit face is 32 x 32 pixels, centred.
    let ortho = draw(Projection::orthographic(s(4.0), s(1.0), s(1.0), s(10.0)).unwrap());
    for y in 0..64 {
        for x in 0..64 {
            let inside = (16..48).contains(&x) && (16..48).contains(&y);
            assert_eq!(ortho.at(x, y), u32::from(inside), "pixel ({x}, {y})");
        }
    }
    let persp =
        draw(Projection::perspective(Angle::from_degrees(44), s(1.0), s(1.0), s(10.0)).unwrap());
    assert!(persp.hits.iter().sum::<u32>() > 1024);
}

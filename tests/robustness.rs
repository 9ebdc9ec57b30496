//! Rules R6, R10, R11 and cases T38–T40: nothing written outside the buffers, errors instead
//! of panics, repeatable output, and random scenes with extreme values through the whole
//! pipeline (run with overflow checks: `cargo test` builds the test profile with them on).

mod common;

use common::scene::*;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics::Pixel;
use fixed3d::buffer::{BufferError, ColorDepth, DepthBuffer, Direct, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Normalize, Scalar, Vec3};
use fixed3d::mesh::{FaceNormal, Mesh, MeshError, Object, CUBE};
use fixed3d::pipeline::{Cull, Frame, MatrixFormat, Precision, PrepareError, ScreenVertex};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{LightColor, Lighting, Scene};
use fixed3d::shade::{Flat, Gouraud, PerspectiveGouraud, Unlit};
use proptest::prelude::*;

/// T38: a depth-tested scene drawn in reverse triangle order gives the same image.
#[test]
fn t38_triangle_order_does_not_matter_without_ties() {
    let data = torus_f64();
    let reversed: Vec<[u16; 3]> = data.triangles.iter().rev().copied().collect();
    let image = |tris: &[[u16; 3]]| {
        let mesh = Mesh::new(&data.positions, tris).unwrap();
        let objects = [Object::new(&mesh, identity(), BASE)];
        let scene = Scene::new(&objects, lighting());
        let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
        let prepared = frame().prepare(&scene, &mut cache, Flat).unwrap();
        let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 240], vec![u16::MAX; 320 * 240]);
        let mut color = FrameBuffer::new(&mut c, 320, 240).unwrap();
        let mut depth = DepthBuffer::new(&mut d, 320, 240).unwrap();
        prepared
            .draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
            .unwrap();
        c
    };
    assert_eq!(image(&data.triangles), image(&reversed));
}

/// A display that fails after `budget` calls.
struct Failing {
    budget: u32,
    drawn: u32,
}

impl OriginDimensions for Failing {
    fn size(&self) -> Size {
        Size::new(64, 48)
    }
}

impl DrawTarget for Failing {
    type Color = Rgb565;
    type Error = &'static str;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        if self.budget == 0 {
            return Err("bus error");
        }
        self.budget -= 1;
        self.drawn += pixels.into_iter().count() as u32;
        Ok(())
    }
}

fn cube_frame(w: u32, h: u32) -> Frame {
    let viewport = Viewport::new(w, h).unwrap();
    let view = LookAt::new(Vec3::from_int(3, 2, 4), Vec3::ZERO, Vec3::Y)
        .view()
        .unwrap();
    let s = Scalar::from_num;
    let p = Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(0.5), s(50.0))
        .unwrap();
    Frame::new(&view, &p, viewport)
}

/// T39: buffers of the wrong size are refused, empty buffers draw nothing, a failing display's
/// error comes back at once, and the next frame is correct.
#[test]
fn t39_buffers_and_failing_targets() {
    let mut px = [Rgb565::BLACK; 10];
    assert_eq!(
        FrameBuffer::new(&mut px, 4, 3).unwrap_err(),
        BufferError::TooShort {
            needed: 12,
            len: 10
        }
    );
    assert!(FrameBuffer::new(&mut px, u32::MAX, u32::MAX).is_err());
    let mut one = [Rgb565::BLACK; 1];
    assert!(FrameBuffer::new(&mut one, 1, 1).is_ok());
    let mut d = [0u16; 12];
    let mut c = [Rgb565::BLACK; 12];
    let mut color = FrameBuffer::new(&mut c, 4, 3).unwrap();
    let mut depth = DepthBuffer::new(&mut d, 3, 4).unwrap();
    assert_eq!(
        ColorDepth::new(&mut color, &mut depth).unwrap_err(),
        BufferError::SizeMismatch
    );
    assert!(Viewport::new(0, 10).is_err());

    let objects = [Object::new(&CUBE, Mat4::IDENTITY, Rgb888::WHITE)];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
    let mut small = [ScreenVertex::DEFAULT; 3];
    assert_eq!(
        cube_frame(64, 48)
            .prepare(&scene, &mut small, Unlit)
            .unwrap_err(),
        PrepareError::CacheTooSmall {
            needed: 8,
            capacity: 3
        }
    );
    let mut cache = [ScreenVertex::DEFAULT; 8];
    let prepared = cube_frame(64, 48)
        .prepare(&scene, &mut cache, Unlit)
        .unwrap();

    // A 0-row framebuffer draws nothing.
    let mut none: [Rgb565; 0] = [];
    let mut empty = FrameBuffer::new(&mut none, 64, 0).unwrap();
    let stats = prepared.draw(&mut Direct::new(&mut empty)).unwrap();
    assert_eq!(stats.written, 0);

    // Errors propagate; the next frame is complete.
    let mut failing = Failing {
        budget: 3,
        drawn: 0,
    };
    assert_eq!(
        prepared.draw_wireframe(&mut failing).unwrap_err(),
        "bus error"
    );
    let mut ok = Failing {
        budget: u32::MAX,
        drawn: 0,
    };
    let stats = prepared.draw_wireframe(&mut ok).unwrap();
    assert_eq!(ok.drawn, stats.written);
    assert!(stats.written > 50);
}

/// T40: indices out of range are refused by the mesh (and skipped by the pipeline), meshes of
/// more than 65,535 triangles draw.
#[test]
fn t40_indices_and_large_meshes() {
    let p = [Vec3::ZERO, Vec3::X, Vec3::Y];
    assert_eq!(
        Mesh::new(&p, &[[0, 1, u16::MAX]]).unwrap_err(),
        MeshError::TriangleIndexOutOfRange { triangle: 0 }
    );
    assert_eq!(
        Mesh::new(&p, &[[0, 1, 2], [3, 1, 2]]).unwrap_err(),
        MeshError::TriangleIndexOutOfRange { triangle: 1 }
    );
    // 70,000 triangles over a 3-vertex mesh.
    let tris = vec![[0u16, 1, 2]; 70_000];
    let mesh = Mesh::new(&p, &tris).unwrap();
    let objects = [Object::new(
        &mesh,
        Mat4::translation(Vec3::from_int(0, 0, -1)),
        Rgb888::WHITE,
    )];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
    let mut cache = [ScreenVertex::DEFAULT; 3];
    let viewport = Viewport::new(64, 48).unwrap();
    let s = Scalar::from_num;
    let proj = Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(0.5), s(50.0))
        .unwrap();
    let frame = Frame::new(&Mat4::IDENTITY, &proj, viewport).with_cull(Cull::None);
    let prepared = frame.prepare(&scene, &mut cache, Unlit).unwrap();
    let mut c = vec![Rgb565::BLACK; 64 * 48];
    let mut fb = FrameBuffer::new(&mut c, 64, 48).unwrap();
    let stats = prepared.draw(&mut Direct::new(&mut fb)).unwrap();
    assert_eq!(stats.primitives, 70_000);
    assert_eq!(stats.drawn, 70_000);
}

const CANARY: Rgb565 = Rgb565::new(31, 0, 31);

fn coord() -> impl Strategy<Value = f32> {
    prop_oneof![
        6 => -4.0f32..4.0,
        2 => -40.0f32..40.0,
        1 => prop::sample::select(vec![-32767.0f32, 32767.0, 0.0, 1e-5, -1e-5, 30000.0, -30000.0]),
    ]
}

fn vec3() -> impl Strategy<Value = Vec3> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| Vec3::from_f32(x, y, z).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// R6/R11/M12: random meshes with extreme coordinates, random cameras (some inside the
    /// geometry), every shading and culling mode, full frames and bands: no panic, nothing
    /// written outside the buffers (canaries on both sides), the same image twice, and from
    /// the mesh's kept face normals the image `Flat` draws from its positions.
    #[test]
    fn random_scenes_never_panic_or_write_outside(
        positions in prop::collection::vec(vec3(), 3..24),
        raw_tris in prop::collection::vec((0u16..24, 0u16..24, 0u16..24), 1..40),
        eye in vec3(), target in vec3(),
        near in prop::sample::select(vec![0.001f32, 0.01, 0.5, 2.0]),
        far_factor in prop::sample::select(vec![1.01f32, 10.0, 1e4]),
        cull in prop::sample::select(vec![Cull::Back, Cull::Front, Cull::None]),
        w in 1u32..48, h in 1u32..40, band in 1u32..9,
        subpixel in 0u32..5, matrix_bits in prop::sample::select(vec![0u32, 8, 16]),
        exact in any::<bool>(), scale_bits in prop::sample::select(vec![64i32, 1 << 16, 100 << 16]),
    ) {
        let n = positions.len() as u16;
        let tris: Vec<[u16; 3]> = raw_tris.iter().map(|&(a, b, c)| [a % n, b % n, c % n]).collect();
        let normals: Vec<Vec3> = positions.iter().map(|p| *p - Vec3::from_int(0, 1, 0)).collect();
        let mut faces = vec![FaceNormal::ZERO; tris.len()];
        let mesh = Mesh::new(&positions, &tris).unwrap().with_normals(&normals).unwrap();
        let plain_mesh = mesh;
        let mesh = mesh.with_face_normals(&mut faces).unwrap();
        let scale = Scalar::from_bits(scale_bits);
        let model = Mat4::scaling(Vec3::new(scale, scale, scale));
        let objects = [Object::new(&mesh, model, Rgb888::new(200, 120, 40))];
        let mut lighting = Lighting::<2>::new(LightColor::gray(Scalar::from_num(0.2)));
        lighting.push(fixed3d::scene::DirectionalLight::new(Vec3::from_int(-1, 1, 1), LightColor::WHITE)).unwrap();
        let plain_objects = [Object::new(&plain_mesh, model, Rgb888::new(200, 120, 40))];
        let plain = Scene::new(&plain_objects, lighting.clone());
        let scene = Scene::new(&objects, lighting);
        let Ok(view) = LookAt::new(eye, target, Vec3::Y).view() else { return Ok(()) };
        let viewport = Viewport::new(w, h).unwrap();
        let far = Scalar::from_num((near * far_factor).min(30000.0));
        let Ok(proj) = Projection::perspective(Angle::from_degrees(70), viewport.aspect(), Scalar::from_num(near), far) else { return Ok(()) };
        // Every precision knob (docs/accuracy.md) goes through the same checks.
        let precision = Precision::DEFAULT
            .with_subpixel_bits(subpixel)
            .with_normalize(if exact { Normalize::Exact } else { Normalize::Newton });
        let precision = match matrix_bits {
            0 => precision,
            b => precision.with_matrix(MatrixFormat::Fixed(b)),
        };
        let frame = Frame::new(&view, &proj, viewport).with_cull(cull).with_precision(precision);
        let mut cache = vec![ScreenVertex::DEFAULT; positions.len()];

        let render_full = |cache: &mut [ScreenVertex], gouraud: u8| {
            let len = (w * h) as usize;
            let mut c = vec![CANARY; len + 32];
            let mut d = vec![0u16; len + 32];
            {
                let mut color = FrameBuffer::new(&mut c[16..16 + len], w, h).unwrap();
                let mut depth = DepthBuffer::new(&mut d[16..16 + len], w, h).unwrap();
                color.fill(Rgb565::BLACK);
                depth.clear();
                let mut t = ColorDepth::new(&mut color, &mut depth).unwrap();
                match gouraud {
                    0 => frame.prepare(&scene, cache, Flat).unwrap().draw(&mut t).unwrap(),
                    1 => frame.prepare(&scene, cache, Gouraud).unwrap().draw(&mut t).unwrap(),
                    3 => frame.prepare(&plain, cache, Flat).unwrap().draw(&mut t).unwrap(),
                    _ => frame.prepare(&scene, cache, PerspectiveGouraud).unwrap().draw(&mut t).unwrap(),
                };
            }
            assert!(c[..16].iter().chain(&c[16 + len..]).all(|&p| p == CANARY));
            assert!(d[..16].iter().chain(&d[16 + len..]).all(|&p| p == 0));
            c[16..16 + len].to_vec()
        };
        // The kept face normals light the faces as their positions do.
        prop_assert_eq!(render_full(&mut cache, 3), render_full(&mut cache, 0));
        for gouraud in [0u8, 1, 2] {
            let full = render_full(&mut cache, gouraud);
            prop_assert_eq!(&full, &render_full(&mut cache, gouraud));
            // The same frame in bands of `band` rows.
            let prepared = frame.prepare(&scene, &mut cache, Flat).unwrap();
            let mut banded = Vec::new();
            let mut y0 = 0;
            while y0 < h {
                let rows = band.min(h - y0);
                let len = (w * rows) as usize;
                let mut c = vec![Rgb565::BLACK; len];
                let mut d = vec![0u16; len];
                let mut color = FrameBuffer::new(&mut c, w, rows).unwrap();
                let mut depth = DepthBuffer::new(&mut d, w, rows).unwrap();
                depth.clear();
                prepared.draw(&mut ColorDepth::band(&mut color, &mut depth, y0).unwrap()).unwrap();
                banded.extend_from_slice(&c);
                y0 += rows;
            }
            if gouraud == 0 {
                prop_assert_eq!(&full, &banded);
            }
            // Wireframe straight into a framebuffer with canaries.
            let len = (w * h) as usize;
            let mut c = vec![CANARY; len + 32];
            {
                let mut color = FrameBuffer::new(&mut c[16..16 + len], w, h).unwrap();
                prepared.draw_wireframe(&mut color).unwrap();
            }
            prop_assert!(c[..16].iter().chain(&c[16 + len..]).all(|&p| p == CANARY));
        }
    }
}

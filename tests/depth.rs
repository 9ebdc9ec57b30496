//! Rule R7 and cases T21–T25: depth interpolated from the snapped vertices, within 1 LSB of the
//! plane, saturated never wrapped, and the visible surface of the f64 reference.

mod common;

use common::reference::{classify, depth_at, Cover, V3};
use common::world::{back, q, Setup};
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, DepthTest, FrameBuffer, Less, LessOrEqual};
use fixed3d::math::Mat4;
use fixed3d::mesh::{Mesh, Object};
use fixed3d::pipeline::{Cull, ScreenVertex, Stats};
use fixed3d::scene::{LightColor, Lighting, Scene};
use fixed3d::shade::Unlit;
use proptest::prelude::*;

const RED: Rgb888 = Rgb888::new(255, 0, 0);
const BLUE: Rgb888 = Rgb888::new(0, 0, 255);

struct Rendered {
    color: Vec<Rgb565>,
    depth: Vec<u16>,
    vertices: Vec<ScreenVertex>,
    stats: Stats,
}

/// Renders triangle lists as objects (one colour each) with a u16 depth buffer.
fn render<T: DepthTest>(s: &Setup, objects: &[(Vec<[V3; 3]>, Rgb888)], test: T) -> Rendered {
    let data: Vec<(Vec<fixed3d::math::Vec3>, Vec<[u16; 3]>)> = objects
        .iter()
        .map(|(tris, _)| {
            let p = tris.iter().flat_map(|t| t.map(q)).collect();
            let t = (0..tris.len() as u16)
                .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
                .collect();
            (p, t)
        })
        .collect();
    let meshes: Vec<Mesh> = data.iter().map(|(p, t)| Mesh::new(p, t).unwrap()).collect();
    let objs: Vec<Object> = meshes
        .iter()
        .zip(objects)
        .map(|(m, (_, c))| Object::new(m, Mat4::IDENTITY, *c))
        .collect();
    let scene = Scene::new(&objs, Lighting::<0>::new(LightColor::WHITE));
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let prepared = s
        .frame()
        .with_cull(Cull::None)
        .prepare(&scene, &mut cache, Unlit)
        .unwrap();
    let n = (s.w * s.h) as usize;
    let (mut c, mut d) = (vec![Rgb565::BLACK; n], vec![u16::MAX; n]);
    let mut color = FrameBuffer::new(&mut c, s.w, s.h).unwrap();
    let mut depth = DepthBuffer::new(&mut d, s.w, s.h).unwrap();
    let stats = prepared
        .draw(
            &mut ColorDepth::new(&mut color, &mut depth)
                .unwrap()
                .with_test(test),
        )
        .unwrap();
    let vertices = prepared.vertices().to_vec();
    Rendered {
        color: c,
        depth: d,
        vertices,
        stats,
    }
}

fn setup() -> Setup {
    let mut s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    s.w = 96;
    s.h = 72;
    s
}

/// T21: the same triangle twice: with LESS the second writes nothing, with LEQUAL everything.
#[test]
fn t21_same_triangle_twice() {
    let s = setup();
    let t = vec![[[-1.0, -1.0, -3.0], [1.5, -0.7, -4.0], [0.2, 1.3, -5.0]]];
    let once = render(&s, &[(t.clone(), RED)], Less).stats.written;
    assert!(once > 500);
    let less = render(&s, &[(t.clone(), RED), (t.clone(), BLUE)], Less);
    assert_eq!(less.stats.written, once);
    assert!(less.color.iter().all(|&c| c != Rgb565::from(BLUE)));
    let le = render(&s, &[(t.clone(), RED), (t, BLUE)], LessOrEqual);
    assert_eq!(le.stats.written, 2 * once);
    assert!(le.color.iter().all(|&c| c != Rgb565::from(RED)));
}

/// T22: two triangles interpenetrating at 30 degrees: the visible surface matches the f64
/// reference everywhere outside the tie band (|z1 - z2| <= 2 LSB) and the partial band.
#[test]
fn t22_interpenetrating_triangles() {
    let s = setup();
    let a30 = 30f64.to_radians();
    let flat = vec![[[-2.0, -1.5, -4.0], [2.0, -1.5, -4.0], [0.0, 1.8, -4.0]]];
    // Tilted 30 degrees about the x axis through z = -4.
    let tilt = |x: f64, y: f64| [x, y * a30.cos(), -4.0 - y * a30.sin()];
    let tilted = vec![[tilt(-1.8, -2.0), tilt(1.8, -2.0), tilt(0.3, 2.0)]];
    let r = render(&s, &[(flat.clone(), RED), (tilted.clone(), BLUE)], Less);
    let cam = s.camera();
    let pa = cam.project_triangle(flat[0].map(|p| back(q(p))));
    let pb = cam.project_triangle(tilted[0].map(|p| back(q(p))));
    let (mut checked, mut wrong) = (0, 0);
    for y in 0..s.h as i32 {
        for x in 0..s.w as i32 {
            if classify(&pa, x, y, 0.15) != Cover::Full || classify(&pb, x, y, 0.15) != Cover::Full
            {
                continue;
            }
            let (za, zb) = (depth_at(&pa, x, y), depth_at(&pb, x, y));
            if (za - zb).abs() * 65536.0 <= 2.0 {
                continue;
            }
            checked += 1;
            let expect = if za < zb { RED } else { BLUE };
            if r.color[(y as u32 * s.w + x as u32) as usize] != Rgb565::from(expect) {
                wrong += 1;
            }
        }
    }
    assert!(checked > 300, "checked {checked}");
    assert_eq!(wrong, 0);
}

/// T23: parallel planes at view depth 50 and 51 (near 0.1, far 100): a 16-bit depth quantum at
/// 50 is 0.38 units, so a gap of 1 (over two quanta) is resolved at every pixel, in either draw
/// order. Below two quanta the planes may fight: the documented limit.
#[test]
fn t23_parallel_planes_far_away() {
    let mut s = setup();
    s.near = 0.1;
    let plane = |z: f64| vec![[[-40.0, -40.0, z], [40.0, -40.0, z], [0.0, 40.0, z]]];
    for order in [
        [(plane(-50.0), RED), (plane(-51.0), BLUE)],
        [(plane(-51.0), BLUE), (plane(-50.0), RED)],
    ] {
        let r = render(&s, &order, Less);
        let red = r.color.iter().filter(|&&c| c == Rgb565::from(RED)).count();
        let blue = r.color.iter().filter(|&&c| c == Rgb565::from(BLUE)).count();
        assert!(red > 1000);
        assert_eq!(blue, 0);
    }
}

/// T24: geometry beyond the far plane is clipped away, and stored depth never wraps: it only
/// grows with distance and stays within [0, 65535].
#[test]
fn t24_beyond_far_and_at_near() {
    let mut s = setup();
    s.far = 20.0;
    // A floor strip from depth 1 to depth 40, seen from above: the far half is cut.
    let strip = vec![
        [[-3.0, -1.0, -1.0], [3.0, -1.0, -1.0], [3.0, -1.0, -40.0]],
        [[-3.0, -1.0, -1.0], [3.0, -1.0, -40.0], [-3.0, -1.0, -40.0]],
    ];
    let r = render(&s, &[(strip, RED)], Less);
    assert!(r.stats.clipped >= 2);
    // Depth down each column (towards the horizon) never decreases.
    for x in 0..s.w as usize {
        let col: Vec<u16> = (0..s.h as usize)
            .rev()
            .map(|y| r.depth[y * s.w as usize + x])
            .filter(|&d| d != u16::MAX)
            .collect();
        assert!(col.windows(2).all(|w| w[0] <= w[1]), "column {x}: {col:?}");
    }
    // The horizon of the cut: nothing drawn where the floor would be beyond depth 20.
    let cam = s.camera();
    let z20 = cam.screen(cam.clip([0.0, -1.0, -20.0]))[1];
    let rows_above = (z20 - 1.0).floor() as usize;
    for y in 0..rows_above.min(s.h as usize) {
        for x in 30..66 {
            assert_eq!(
                r.depth[y * s.w as usize + x],
                u16::MAX,
                "pixel ({x}, {y}) beyond the far plane"
            );
        }
    }
}

/// The f64 plane through the snapped vertices, in 16-bit depth units, at a pixel centre.
fn snapped_plane(v: [ScreenVertex; 3], x: i32, y: i32) -> f64 {
    let p: Vec<[f64; 3]> = v
        .iter()
        .map(|v| {
            [
                v.point().x as f64 / 16.0,
                v.point().y as f64 / 16.0,
                v.depth() as f64 / (1u64 << 30) as f64,
            ]
        })
        .collect();
    depth_at(&p, x, y) * 65536.0
}

/// Asserts R7 for a one-triangle render: every written depth within 1 LSB of the plane.
fn assert_depth_on_plane(s: &Setup, r: &Rendered) -> usize {
    let v = [r.vertices[0], r.vertices[1], r.vertices[2]];
    let mut n = 0;
    for y in 0..s.h as i32 {
        for x in 0..s.w as i32 {
            let d = r.depth[(y as u32 * s.w + x as u32) as usize];
            if d == u16::MAX {
                continue;
            }
            let expect = snapped_plane(v, x, y).clamp(0.0, 65535.0);
            assert!(
                (d as f64 - expect).abs() <= 1.0,
                "pixel ({x}, {y}): {d} vs {expect}"
            );
            n += 1;
        }
    }
    n
}

/// T25: a steep triangle 320 pixels wide from the near plane to the far plane: every pixel's
/// depth within 1 LSB of the plane through the snapped vertices (no drift along spans).
#[test]
fn t25_steep_wide_triangle_depth_on_plane() {
    let mut s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    s.w = 320;
    s.h = 240;
    s.near = 1.0;
    s.far = 10.0;
    let t = vec![[[-1.1, -0.8, -1.05], [9.0, 0.2, -9.9], [-0.5, 0.7, -1.1]]];
    let r = render(&s, &[(t, RED)], Less);
    assert_eq!(r.stats.clipped, 0);
    let n = assert_depth_on_plane(&s, &r);
    assert!(n > 5000, "{n} pixels");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// M4: random triangles in view: depth within 1 LSB of the plane of the snapped vertices.
    #[test]
    fn m4_depth_within_one_lsb(c in prop::array::uniform9(-3.0f64..3.0), zs in prop::array::uniform3(-9.0f64..-1.2)) {
        let s = setup();
        let t = vec![[[c[0], c[1], zs[0]], [c[3], c[4], zs[1]], [c[6], c[7], zs[2]]]];
        let r = render(&s, &[(t, RED)], Less);
        if r.stats.clipped == 0 {
            assert_depth_on_plane(&s, &r);
        }
    }
}

/// T36 for depth: a triangle spanning a 2048-pixel viewport, every pixel within 1 LSB of the
/// plane (no drift along the longest spans the pipeline accepts).
#[test]
fn t36_depth_along_2048_pixel_spans() {
    let mut s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    s.w = 2048;
    s.h = 24;
    s.fov_deg = 10;
    s.near = 1.0;
    s.far = 10.0;
    // Nearly edge-on from left (near) to right (far), wider than the screen.
    let t = vec![[[-9.0, -0.1, -1.3], [70.0, -0.8, -9.5], [-8.5, 0.1, -1.2]]];
    let r = render(&s, &[(t, RED)], Less);
    assert_eq!(r.stats.clipped, 0);
    let n = assert_depth_on_plane(&s, &r);
    assert!(n > 10_000, "{n} pixels");
}

/// The u32 depth format: the same visibility, 2¹⁶ times finer steps.
#[test]
fn u32_depth_resolves_what_u16_cannot() {
    let mut s = setup();
    s.near = 0.1;
    s.far = 100.0;
    // Planes 0.05 apart at depth 50: a tenth of a 16-bit quantum, thousands of 32-bit ones.
    let plane = |z: f64| vec![[[-40.0, -40.0, z], [40.0, -40.0, z], [0.0, 40.0, z]]];
    let objs = [(plane(-50.0), RED), (plane(-50.05), BLUE)];
    let data: Vec<(Vec<fixed3d::math::Vec3>, Vec<[u16; 3]>)> = objs
        .iter()
        .map(|(t, _)| (t.iter().flat_map(|t| t.map(q)).collect(), vec![[0, 1, 2]]))
        .collect();
    let meshes: Vec<Mesh> = data.iter().map(|(p, t)| Mesh::new(p, t).unwrap()).collect();
    // Far plane first, so only a finer depth buffer can let the near one win everywhere.
    let objects = [
        Object::new(&meshes[1], Mat4::IDENTITY, BLUE),
        Object::new(&meshes[0], Mat4::IDENTITY, RED),
    ];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
    let mut cache = vec![ScreenVertex::DEFAULT; 6];
    let prepared = s.frame().prepare(&scene, &mut cache, Unlit).unwrap();
    let n = (s.w * s.h) as usize;
    let mut c = vec![Rgb565::BLACK; n];
    let mut d32 = vec![0u32; n];
    let mut color = FrameBuffer::new(&mut c, s.w, s.h).unwrap();
    let mut depth = DepthBuffer::new(&mut d32, s.w, s.h).unwrap();
    depth.clear();
    prepared
        .draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
        .unwrap();
    let blue = c.iter().filter(|&&p| p == Rgb565::from(BLUE)).count();
    let red = c.iter().filter(|&&p| p == Rgb565::from(RED)).count();
    assert!(red > 1000);
    assert_eq!(blue, 0);
    // With 16 bits the same planes share depth values at many pixels: the first drawn stays.
    let mut c16 = vec![Rgb565::BLACK; n];
    let mut d16 = vec![0u16; n];
    let mut color = FrameBuffer::new(&mut c16, s.w, s.h).unwrap();
    let mut depth = DepthBuffer::new(&mut d16, s.w, s.h).unwrap();
    depth.clear();
    prepared
        .draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
        .unwrap();
    assert!(c16.iter().filter(|&&p| p == Rgb565::from(BLUE)).count() > 0);
}

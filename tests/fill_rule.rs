//! Rules R1–R4 and cases T01–T12 of docs/cases.md: coverage, the top-left rule, watertightness,
//! degenerate triangles and snapping, each checked exactly against the integer model.

mod common;

use common::*;
use fixed3d::raster::{PixelRect, ScreenPoint};
use proptest::prelude::*;

fn px(x: i32, y: i32) -> ScreenPoint {
    ScreenPoint::new(x * 16, y * 16)
}

fn permutations(v: [ScreenPoint; 3]) -> Vec<[ScreenPoint; 3]> {
    let [a, b, c] = v;
    vec![
        [a, b, c],
        [a, c, b],
        [b, a, c],
        [b, c, a],
        [c, a, b],
        [c, b, a],
    ]
}

const SCREEN: PixelRect = PixelRect::new(0, 0, 64, 64);

#[test]
fn t01_square_split_on_its_diagonal() {
    let a = [px(0, 0), px(4, 0), px(4, 4)];
    let b = [px(0, 0), px(4, 4), px(0, 4)];
    for (tri, expect) in [(a, 10), (b, 6)] {
        for p in permutations(tri) {
            let got = crate_triangle(p, SCREEN);
            assert_eq!(got.len(), expect);
            assert_eq!(got, model_triangle(p, SCREEN));
        }
    }
    let ca = crate_triangle(a, SCREEN);
    let cb = crate_triangle(b, SCREEN);
    assert!(ca.is_disjoint(&cb));
    assert_eq!(ca.union(&cb).count(), 16);
    // The diagonal's centres go to A, whose diagonal is a left edge.
    assert!(ca.contains(&(0, 0)) && ca.contains(&(3, 3)));
}

#[test]
fn t02_rectangle_on_half_pixels() {
    let (p00, p10, p11, p01) = (sp(0.5, 0.5), sp(2.5, 0.5), sp(2.5, 4.5), sp(0.5, 4.5));
    let mut hits = Hits::new(8, 8);
    hits.add_triangle([p00, p10, p11]);
    hits.add_triangle([p00, p11, p01]);
    for y in 0..8 {
        for x in 0..8 {
            let expect = u32::from(x < 2 && y < 4);
            assert_eq!(hits.n[(y * 8 + x) as usize], expect, "pixel ({x}, {y})");
        }
    }
}

#[test]
fn t03_overdraw_fan_enclosing_the_screen() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for _ in 0..30 {
        let centre = sp(rng.range(1.0, 63.0), rng.range(1.0, 63.0));
        let mut rim = Vec::new();
        let mut a = 0.0f64;
        while a < std::f64::consts::TAU {
            // A circle of radius 60 around the screen centre encloses the 64x64 screen.
            rim.push(sp(32.0 + 60.0 * a.cos(), 32.0 + 60.0 * a.sin()));
            a += rng.range(0.0005, 0.3);
        }
        let mut hits = Hits::new(64, 64);
        for i in 0..rim.len() {
            hits.add_triangle([centre, rim[i], rim[(i + 1) % rim.len()]]);
        }
        assert_eq!(hits.count(1), 64 * 64, "every pixel exactly once");
    }
}

#[test]
fn t03_rect_variant_rim_on_inner_rectangle() {
    let mut rng = Rng(77);
    for _ in 0..30 {
        let centre = sp(rng.range(20.0, 40.0), rng.range(20.0, 40.0));
        // Rim on the perimeter of [10, 54] x [12, 50] at non-integer steps.
        let (x0, y0, x1, y1) = (10.0f64, 12.0f64, 54.0f64, 50.0f64);
        // Walk each side at random non-integer steps; the corners are always rim vertices.
        let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)];
        let mut rim = Vec::new();
        for k in 0..4 {
            let (p, q) = (corners[k], corners[(k + 1) % 4]);
            let len: f64 = (q.0 - p.0).abs() + (q.1 - p.1).abs();
            let mut t = 0.0;
            while t < len {
                let f = t / len;
                rim.push(sp(p.0 + (q.0 - p.0) * f, p.1 + (q.1 - p.1) * f));
                t += rng.range(0.05, 3.7);
            }
        }
        let mut hits = Hits::new(64, 64);
        for i in 0..rim.len() {
            hits.add_triangle([centre, rim[i], rim[(i + 1) % rim.len()]]);
        }
        // Every pixel whose centre is strictly inside the probe rectangle: exactly once.
        for y in 12..50 {
            for x in 10..54 {
                assert_eq!(hits.n[(y * 64 + x) as usize], 1, "pixel ({x}, {y})");
            }
        }
        assert_eq!(hits.n.iter().filter(|&&n| n > 1).count(), 0);
    }
}

#[test]
fn t04_rotated_quads_never_overlap() {
    // 4x4 quads of side 0.15 NDC (= 4.8 px on 64 px) with the rotation swept.
    for step in 0..24 {
        let rot = step as f64 * std::f64::consts::PI / 48.0;
        let mut hits = Hits::new(64, 64);
        for qy in 0..4 {
            for qx in 0..4 {
                let c = (8.0 + 14.0 * qx as f64, 8.0 + 14.0 * qy as f64);
                let h = 4.8 / 2.0;
                let corner = |k: f64| {
                    let a = rot + k * std::f64::consts::FRAC_PI_2 + std::f64::consts::FRAC_PI_4;
                    sp(
                        c.0 + h * 2f64.sqrt() * a.cos(),
                        c.1 + h * 2f64.sqrt() * a.sin(),
                    )
                };
                let (a, b, cc, d) = (corner(0.0), corner(1.0), corner(2.0), corner(3.0));
                hits.add_triangle([a, b, cc]);
                hits.add_triangle([a, cc, d]);
            }
        }
        assert_eq!(
            hits.n.iter().filter(|&&n| n > 1).count(),
            0,
            "rotation step {step}"
        );
    }
}

#[test]
fn t05_fan_around_a_sample_centre() {
    let c = sp(10.5, 10.5);
    let mut hits = Hits::new(32, 32);
    for k in 0..6 {
        let a0 = k as f64 * std::f64::consts::TAU / 6.0;
        let a1 = (k + 1) as f64 * std::f64::consts::TAU / 6.0;
        hits.add_triangle([
            c,
            sp(10.5 + 7.0 * a0.cos(), 10.5 + 7.0 * a0.sin()),
            sp(10.5 + 7.0 * a1.cos(), 10.5 + 7.0 * a1.sin()),
        ]);
    }
    assert_eq!(hits.n[10 * 32 + 10], 1);
    assert_eq!(hits.n.iter().filter(|&&n| n > 1).count(), 0);
}

#[test]
fn t06_small_triangle_without_a_sample() {
    let t = [sp(0.6, 0.6), sp(1.4, 0.6), sp(1.0, 1.4)];
    assert!(crate_triangle(t, SCREEN).is_empty());
}

#[test]
fn t07_degenerate_triangles_cover_nothing() {
    for t in [
        [px(0, 0), px(5, 5), px(10, 10)],
        [px(3, 3), px(3, 3), px(3, 3)],
        [px(0, 0), px(0, 0), px(10, 3)],
        [sp(0.0, 0.0), sp(10.0, 10.0), sp(20.0, 20.03)],
    ] {
        for p in permutations(t) {
            assert!(crate_triangle(p, SCREEN).is_empty());
        }
    }
}

#[test]
fn t08_needle_is_exact() {
    let t = [sp(0.5, 0.5), sp(60.5, 1.5), sp(60.5, 1.5625)];
    let got = crate_triangle(t, SCREEN);
    assert_eq!(got, [(57, 1), (58, 1), (59, 1)].into_iter().collect());
    assert_eq!(got, model_triangle(t, SCREEN));
}

#[test]
fn t09_integer_translation_moves_coverage_exactly() {
    let t = [sp(3.3, 2.1), sp(17.9, 9.4), sp(6.2, 15.7)];
    let base = crate_triangle(t, PixelRect::new(-100, -100, 100, 100));
    for (k, m) in [(1, 0), (0, 1), (-3, 5), (7, -2), (-11, -13)] {
        let moved = t.map(|p| ScreenPoint::new(p.x + 16 * k, p.y + 16 * m));
        let got = crate_triangle(moved, PixelRect::new(-100, -100, 100, 100));
        let expect: std::collections::BTreeSet<_> =
            base.iter().map(|&(x, y)| (x + k, y + m)).collect();
        assert_eq!(got, expect);
    }
}

#[test]
fn t11_t_junction_matches_model() {
    let big = [px(0, 0), px(32, 0), px(0, 32)];
    for v in [sp(16.0, 16.0), sp(16.1, 16.0)] {
        let others = [[px(32, 0), px(32, 32), v], [v, px(32, 32), px(0, 32)]];
        let mut hits = Hits::new(40, 40);
        hits.add_triangle(big);
        for o in others {
            hits.add_triangle(o);
            assert_eq!(
                crate_triangle(o, hits.clip()),
                model_triangle(o, hits.clip())
            );
        }
        let doubles = hits.n.iter().filter(|&&n| n > 1).count();
        let holes = (0..32)
            .flat_map(|y| (0..32).map(move |x| (x, y)))
            .filter(|&(x, y)| hits.n[(y * 40 + x) as usize] == 0)
            .count();
        if v == sp(16.0, 16.0) {
            assert_eq!((holes, doubles), (0, 0), "vertex on the edge: watertight");
        } else {
            assert_eq!(holes, 32, "0.1 px off the edge: the documented holes");
        }
    }
}

#[test]
fn t12_snapping_ties_and_piglit_shifts() {
    // Ties in snapping are the pipeline's; here: tiny triangles around (0.5, 0.5) shifted by
    // -1/16..+1/16 must equal the model exactly.
    for sx in -1..=1 {
        for sy in -1..=1 {
            let c = ScreenPoint::new(8 + sx, 8 + sy);
            let d = 3; // 3/16 px
            for t in [
                [
                    c,
                    ScreenPoint::new(c.x + d, c.y),
                    ScreenPoint::new(c.x, c.y + d),
                ],
                [
                    c,
                    ScreenPoint::new(c.x - d, c.y),
                    ScreenPoint::new(c.x, c.y + d),
                ],
                [
                    c,
                    ScreenPoint::new(c.x + d, c.y),
                    ScreenPoint::new(c.x, c.y - d),
                ],
                [
                    c,
                    ScreenPoint::new(c.x - d, c.y),
                    ScreenPoint::new(c.x, c.y - d),
                ],
            ] {
                assert_eq!(crate_triangle(t, SCREEN), model_triangle(t, SCREEN));
            }
        }
    }
}

fn coord() -> impl Strategy<Value = i32> {
    prop_oneof![
        8 => -64i32..(64 * 16 + 64),
        2 => -(1i32 << 14)..(1 << 14),
        1 => prop::sample::select(vec![
            -(1 << 24), (1 << 24), -(1 << 14), 1 << 14, (1 << 14) - 1, 0, 1, -1, 8, 7, 9, 1023, 1024,
        ]),
    ]
}

fn point() -> impl Strategy<Value = ScreenPoint> {
    (coord(), coord()).prop_map(|(x, y)| ScreenPoint::new(x, y))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// M1 = 0: random triangles on the sub-pixel grid (extremes mixed in) equal the model.
    #[test]
    fn m1_random_triangles_equal_the_model(a in point(), b in point(), c in point()) {
        let clip = PixelRect::new(0, 0, 64, 64);
        prop_assert_eq!(crate_triangle([a, b, c], clip), model_triangle([a, b, c], clip));
    }

    /// Permutation and winding invariance.
    #[test]
    fn permutation_invariance(a in point(), b in point(), c in point()) {
        let clip = PixelRect::new(0, 0, 64, 64);
        let base = crate_triangle([a, b, c], clip);
        for p in permutations([a, b, c]) {
            prop_assert_eq!(&crate_triangle(p, clip), &base);
        }
    }

    /// Watertightness: a random quad split either way, and a random fan, hit each pixel once.
    #[test]
    fn shared_edges_are_watertight(a in point(), b in point(), c in point(), d in point()) {
        let clip = PixelRect::new(0, 0, 64, 64);
        let t1 = crate_triangle([a, b, c], clip);
        let t2 = crate_triangle([a, c, d], clip);
        // Triangles on opposite sides of edge a-c never share a pixel.
        let s1 = (b.x as i128 - a.x as i128) * (c.y as i128 - a.y as i128) - (b.y as i128 - a.y as i128) * (c.x as i128 - a.x as i128);
        let s2 = (d.x as i128 - a.x as i128) * (c.y as i128 - a.y as i128) - (d.y as i128 - a.y as i128) * (c.x as i128 - a.x as i128);
        if (s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0) {
            prop_assert!(t1.is_disjoint(&t2));
        }
    }

    /// Coverage never leaves the clip rectangle and is bounded by it.
    #[test]
    fn spans_stay_in_the_clip(a in point(), b in point(), c in point(),
                              x0 in -10i32..40, y0 in -10i32..40, w in 0i32..40, h in 0i32..40) {
        let clip = PixelRect::new(x0, y0, x0 + w, y0 + h);
        let got = crate_triangle([a, b, c], clip);
        prop_assert!(got.len() <= (w * h) as usize);
        prop_assert_eq!(got, model_triangle([a, b, c], clip));
    }
}

/// T10: with culling on, exactly one winding is drawn, decided on the snapped area; zero-area
/// triangles are never drawn.
#[test]
fn t10_culling_by_snapped_winding() {
    use common::world::Setup;
    use fixed3d::pipeline::Cull;
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let ccw = [[-1.0, -1.0, -3.0], [1.0, -1.0, -3.0], [0.0, 1.0, -3.0]];
    let cw = [ccw[0], ccw[2], ccw[1]];
    let (front, stats) = s.hits(&[ccw], Cull::Back);
    assert_eq!((stats.drawn, stats.culled), (1, 0));
    assert!(front.hits.contains(&1));
    let (back, stats) = s.hits(&[cw], Cull::Back);
    assert_eq!((stats.drawn, stats.culled), (0, 1));
    assert!(back.hits.iter().all(|&h| h == 0));
    let (only_back, _) = s.hits(&[cw], Cull::Front);
    assert_eq!(only_back.hits, front.hits);
    // Both windings with culling off: the same pixels.
    let (none, _) = s.hits(&[cw], Cull::None);
    assert_eq!(none.hits, front.hits);
    // Collinear after snapping: zero area, never drawn, whatever the culling.
    let sliver = [[-1.0, 0.0, -3.0], [1.0, 0.0, -3.0], [0.0, 0.000001, -3.0]];
    for cull in [Cull::Back, Cull::Front, Cull::None] {
        let (c, stats) = s.hits(&[sliver], cull);
        assert!(c.hits.iter().all(|&h| h == 0));
        assert_eq!(stats.degenerate, 1);
    }
}

/// T12 through the pipeline: snapping is symmetric about the screen centre, so a scene and its
/// mirror image (x → −x) snap to mirrored sub-pixel positions.
#[test]
fn t12_snapping_is_symmetric_about_the_centre() {
    use embedded_graphics::pixelcolor::Rgb888;
    use fixed3d::math::{Mat4, Vec3};
    use fixed3d::mesh::{Mesh, Object};
    use fixed3d::pipeline::ScreenVertex;
    use fixed3d::scene::{LightColor, Lighting, Scene};
    use fixed3d::shade::Unlit;
    let s = common::world::Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let mut rng = Rng(5);
    let pts: Vec<Vec3> = (0..200)
        .map(|_| {
            Vec3::from_f32(
                rng.range(-3.0, 3.0) as f32,
                rng.range(-3.0, 3.0) as f32,
                rng.range(-9.0, -1.0) as f32,
            )
            .unwrap()
        })
        .collect();
    let mirrored: Vec<Vec3> = pts.iter().map(|p| Vec3::new(-p.x, -p.y, p.z)).collect();
    let snap = |p: &[Vec3]| {
        let mesh = Mesh::new(p, &[]).unwrap();
        let objects = [Object::new(&mesh, Mat4::IDENTITY, Rgb888::new(1, 2, 3))];
        let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
        let mut cache = vec![ScreenVertex::DEFAULT; p.len()];
        let prepared = s.frame().prepare(&scene, &mut cache, Unlit).unwrap();
        prepared
            .vertices()
            .iter()
            .map(|v| v.point())
            .collect::<Vec<_>>()
    };
    let (a, b) = (snap(&pts), snap(&mirrored));
    let (cx, cy) = (s.w as i32 * 8, s.h as i32 * 8);
    for (p, q) in a.iter().zip(&b) {
        assert_eq!((p.x - cx, p.y - cy), (cx - q.x, cy - q.y));
    }
}

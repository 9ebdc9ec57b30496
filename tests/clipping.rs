//! Rule R5 and cases T13–T20: geometry far off screen, crossing or on the near plane, and the
//! guard band, through the whole pipeline, against the f64 reference.

mod common;

use common::reference::V3;
use common::world::Setup;
use common::*;
use fixed3d::pipeline::Cull;
use fixed3d::raster::{triangle_spans, PixelRect, ScreenPoint, COORD_LIMIT};

const TOL: f64 = 0.15;

fn quad(a: V3, b: V3, c: V3, d: V3) -> Vec<[V3; 3]> {
    vec![[a, b, c], [a, c, d]]
}

/// T13: a quad filling the screen whose vertices project to millions of pixels: every pixel
/// exactly once, through guard-band clipping.
#[test]
fn t13_screen_filling_quad_with_huge_projected_vertices() {
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    // At view depth 1 with fov 60, x = 30000 projects to about 1.6e6 pixels.
    let z = -1.0;
    let h = 20000.0;
    let tris = quad([-h, -h, z], [h, -h, z], [h, h, z], [-h, h, z]);
    let (canvas, stats) = s.hits(&tris, Cull::None);
    assert!(stats.clipped == 2, "{stats:?}");
    assert!(
        canvas.hits.iter().all(|&h| h == 1),
        "every pixel exactly once"
    );
    // Rotated about the view axis too.
    for k in 1..8 {
        let a = k as f64 * 0.37;
        let r = |x: f64, y: f64| [x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos(), z];
        let tris = quad(r(-h, -h), r(h, -h), r(h, h), r(-h, h));
        let (canvas, _) = s.hits(&tris, Cull::None);
        assert!(canvas.hits.iter().all(|&h| h == 1), "rotation {k}");
    }
}

/// T14: vertices at the rasteriser's limits are exact; beyond them nothing is drawn (the
/// pipeline's guard band keeps every projected vertex far inside).
#[test]
fn t14_coordinate_limits() {
    let clip = PixelRect::new(0, 0, 64, 64);
    let lim = COORD_LIMIT;
    for t in [
        [
            ScreenPoint::new(16383, -16384),
            ScreenPoint::new(-16384, 500),
            ScreenPoint::new(700, 16383),
        ],
        [
            ScreenPoint::new(16384, -16385),
            ScreenPoint::new(-16385, 500),
            ScreenPoint::new(700, 16384),
        ],
        [
            ScreenPoint::new(lim, -lim),
            ScreenPoint::new(-lim, 500),
            ScreenPoint::new(700, lim),
        ],
    ] {
        assert_eq!(crate_triangle(t, clip), model_triangle(t, clip));
    }
    let beyond = [
        ScreenPoint::new(lim + 1, 0),
        ScreenPoint::new(0, 5000),
        ScreenPoint::new(-5000, -5000),
    ];
    assert_eq!(triangle_spans(beyond, clip).count(), 0);
}

/// T14: triangles millions of pixels tall over a clip thousands of rows tall, exact on every
/// row, across the middle vertex's row too. They are built so that a walk by a rounded
/// fraction of the step would drift as early as it can (a step's fraction above its exact
/// value by nearly a unit each row, 2³² − 1 being a multiple of the edge's height, and a
/// crossing a sub-pixel from the bottom vertex): such a walk's last rows over 300 would be
/// off by a pixel; the span iterator's quotient-and-remainder walk is exact on all of them.
#[test]
fn t14_tall_triangles_over_tall_clips_are_exact_on_every_row() {
    let (dy, bottom) = (257 * 65537, 16 * 526_343 + 9);
    for side in [-1, 1] {
        let a = ScreenPoint::new(39, bottom - dy);
        let c = ScreenPoint::new(40, bottom);
        let b = ScreenPoint::new(side * COORD_LIMIT, 0);
        let clip = PixelRect::new(0, 526_344 - 300, 6, 526_346);
        let expected = model_triangle([a, b, c], clip);
        assert!(expected.len() > 300);
        assert_eq!(crate_triangle([a, b, c], clip), expected, "{side}");
    }
    let clip = PixelRect::new(0, -1500, 6, 1500);
    let lim = COORD_LIMIT as f64;
    let mut rng = Rng(7);
    let mut covered = 0;
    for k in 0..24 {
        // The long edge from far above to far below crosses the clip, leaning by up to about
        // 12 columns over its 3000 rows; the middle vertex lies in the clip's rows for half.
        let lean = rng.range(-2.0, 2.0) * 65536.0;
        let x = rng.range(0.0, 96.0);
        let a = ScreenPoint::new((x - lean) as i32, -(lim as i32));
        let c = ScreenPoint::new((x + lean) as i32, lim as i32);
        let by = if k % 2 == 0 {
            rng.range(-20000.0, 20000.0)
        } else {
            rng.range(-lim, lim)
        };
        let b = ScreenPoint::new(rng.range(-lim, lim) as i32, by as i32);
        let expected = model_triangle([a, b, c], clip);
        assert_eq!(
            crate_triangle([a, b, c], clip),
            expected,
            "{a:?} {b:?} {c:?}"
        );
        covered += expected.len();
    }
    assert!(covered > 50_000, "{covered}");
}

/// T15: a triangle far above the screen costs nothing: no row is visited.
#[test]
fn t15_far_off_screen_triangle_visits_no_row() {
    let t = [sp(10.0, -30000.0), sp(50.0, -29000.0), sp(-20.0, -29500.0)];
    let spans = triangle_spans(t, PixelRect::new(0, 0, 64, 64));
    assert_eq!(spans.rows_left(), 0);
    // A huge triangle covering the screen visits only the screen's rows.
    let big = [sp(-1e6, -1e6), sp(1e6, -1e6), sp(0.0, 1e6)];
    assert_eq!(
        triangle_spans(big, PixelRect::new(0, 0, 64, 64)).rows_left(),
        64
    );
}

/// T16: one, two and three vertices behind the camera.
#[test]
fn t16_vertices_behind_the_camera() {
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    // View z = +1 is behind (the camera looks down -z), -2 and -3 in front.
    let one_behind = [[[-1.0, -0.8, 1.0], [1.5, -0.5, -2.0], [-0.3, 1.2, -3.0]]];
    let two_behind = [[[-1.0, -0.8, 1.0], [1.5, -0.5, 2.0], [-0.3, 1.2, -3.0]]];
    let three_behind = [[[-1.0, -0.8, 1.0], [1.5, -0.5, 2.0], [-0.3, 1.2, 3.0]]];
    for tris in [&one_behind[..], &two_behind[..]] {
        let (missing, unexpected, _) = s.compare(tris, Cull::None, TOL);
        assert_eq!((missing, unexpected), (0, 0));
        let (canvas, stats) = s.hits(tris, Cull::None);
        assert_eq!(stats.clipped, 1);
        assert!(canvas.hits.iter().any(|&h| h > 0));
    }
    let (canvas, stats) = s.hits(&three_behind, Cull::None);
    assert!(canvas.hits.iter().all(|&h| h == 0));
    assert_eq!(stats.outside, 1);
}

/// T17: vertices at (or one unit of Q16.16 either side of) the camera plane, with a huge x.
#[test]
fn t17_vertices_on_the_camera_plane() {
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let ulp = 1.0 / 65536.0;
    for z in [ulp, 0.0, -ulp] {
        let tris = [[[30000.0, 0.0, z], [-1.0, -1.0, -2.0], [1.0, 1.0, -3.0]]];
        let (missing, unexpected, _) = s.compare(&tris, Cull::None, TOL);
        assert_eq!((missing, unexpected), (0, 0), "z = {z}");
    }
}

/// T18: vertices exactly on the near plane count as outside; all three on it draws nothing.
#[test]
fn t18_vertices_on_the_near_plane() {
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let n = -s.near;
    let all_on = [[[-1.0, -1.0, n], [1.0, -1.0, n], [0.0, 1.0, n]]];
    let (canvas, _) = s.hits(&all_on, Cull::None);
    assert!(canvas.hits.iter().all(|&h| h == 0));
    let one_on = [[[-0.2, -0.2, n], [1.0, -1.0, -3.0], [0.0, 1.0, -2.0]]];
    let (missing, unexpected, _) = s.compare(&one_on, Cull::None, TOL);
    assert_eq!((missing, unexpected), (0, 0));
}

/// T19: two triangles sharing an edge that crosses the near plane stay watertight.
#[test]
fn t19_shared_edge_across_the_near_plane() {
    let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let mut rng = Rng(99);
    for _ in 0..200 {
        let a = [
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
            rng.range(0.5, 3.0),
        ]; // behind
        let b = [
            rng.range(-2.0, 2.0),
            rng.range(-2.0, 2.0),
            rng.range(-6.0, -1.0),
        ]; // in front
           // c and d on opposite sides of a-b in one plane: a convex quad split along a-b.
        let mid = [0, 1, 2].map(|k| (a[k] + b[k]) / 2.0);
        let u = [
            rng.range(-3.0, 3.0),
            rng.range(-3.0, 3.0),
            rng.range(-1.0, 1.0),
        ];
        let c = [0, 1, 2].map(|k| mid[k] + u[k]);
        let d = [0, 1, 2].map(|k| mid[k] - u[k]);
        let tris = [[a, b, c], [b, a, d]];
        let (canvas, _) = s.hits(&tris, Cull::None);
        assert!(canvas.hits.iter().all(|&h| h <= 1), "a pixel drawn twice");
        let (missing, unexpected, _) = s.compare(&tris, Cull::None, TOL);
        assert_eq!((missing, unexpected), (0, 0));
    }
}

/// T20: the camera inside a closed cube, close to a corner, the near plane slicing the faces:
/// no pixel is drawn twice and the picture equals the reference.
#[test]
fn t20_camera_inside_a_cube() {
    let c = |x: f64, y: f64, z: f64| [x, y, z];
    let v = [
        c(-1., -1., -1.),
        c(1., -1., -1.),
        c(1., 1., -1.),
        c(-1., 1., -1.),
        c(-1., -1., 1.),
        c(1., -1., 1.),
        c(1., 1., 1.),
        c(-1., 1., 1.),
    ];
    let faces = [
        [4, 5, 6, 7],
        [0, 3, 2, 1],
        [1, 2, 6, 5],
        [0, 4, 7, 3],
        [3, 7, 6, 2],
        [0, 1, 5, 4],
    ];
    let tris: Vec<[V3; 3]> = faces
        .iter()
        .flat_map(|f| [[v[f[0]], v[f[1]], v[f[2]]], [v[f[0]], v[f[2]], v[f[3]]]])
        .collect();
    for (eye, target) in [
        ([0.8, 0.7, 0.75], [1.0, 1.0, 1.0]),
        ([0.0, 0.0, 0.0], [1.0, 0.2, 0.3]),
        ([-0.85, 0.1, 0.8], [-1.0, -0.5, 2.0]),
    ] {
        let mut s = Setup::new(eye, target);
        s.fov_deg = 100;
        s.near = 0.3;
        let (canvas, stats) = s.hits(&tris, Cull::None);
        assert!(canvas.hits.iter().all(|&h| h <= 1), "{stats:?}");
        let (missing, unexpected, partial) = s.compare(&tris, Cull::None, TOL);
        assert_eq!((missing, unexpected), (0, 0), "partial {partial}");
        // Seen from inside, the cube's faces are back faces: culling front faces keeps them.
        let (front_culled, _) = s.hits(&tris, Cull::Front);
        assert_eq!(front_culled.hits, canvas.hits);
    }
}

use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// M3 through the whole pipeline: fans whose rim lies thousands of units away (far outside
    /// the guard band), in planes tilted so that part of the rim is behind the camera, cover
    /// every pixel at most once and equal the f64 reference outside the partial band.
    #[test]
    fn fans_enclosing_the_screen_are_watertight(seed in any::<u64>(), tilt_x in -0.7f64..0.7, tilt_y in -0.7f64..0.7) {
        let s = Setup::new([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
        let mut rng = Rng(seed | 1);
        let plane = |x: f64, y: f64| [x, y, -3.0 + tilt_x * x + tilt_y * y];
        let centre = plane(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
        let radius = 9000.0;
        let mut rim = Vec::new();
        let mut a = 0.0f64;
        while a < std::f64::consts::TAU {
            rim.push(plane(radius * a.cos(), radius * a.sin()));
            a += rng.range(0.0005, 0.3);
        }
        let tris: Vec<[V3; 3]> = (0..rim.len()).map(|i| [centre, rim[i], rim[(i + 1) % rim.len()]]).collect();
        let (canvas, _) = s.hits(&tris, Cull::None);
        prop_assert!(canvas.hits.iter().all(|&h| h <= 1), "a pixel drawn twice");
        let (missing, unexpected, _) = s.compare(&tris, Cull::None, TOL);
        prop_assert_eq!((missing, unexpected), (0, 0));
        if tilt_x.abs() < 1e-3 && tilt_y.abs() < 1e-3 {
            prop_assert!(canvas.hits.iter().all(|&h| h == 1));
        }
    }
}

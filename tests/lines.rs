//! Rule R9 and cases T26–T30: lines by the column-centre rule, exact against the model,
//! clipping that changes nothing, bounded work for far endpoints.

mod common;

use common::*;
use fixed3d::raster::{line_pixels, PixelRect, ScreenPoint, COORD_LIMIT};
use proptest::prelude::*;

fn c(x: i32, y: i32) -> ScreenPoint {
    ScreenPoint::pixel_center(x, y)
}

fn set(v: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let mut v = v.to_vec();
    v.sort();
    v
}

const SCREEN: PixelRect = PixelRect::new(0, 0, 16, 16);

#[test]
fn t26_centre_aligned_lines() {
    type Case = ((i32, i32), (i32, i32), &'static [(i32, i32)]);
    let cases: [Case; 6] = [
        ((0, 0), (5, 2), &[(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)]),
        ((0, 0), (4, 2), &[(0, 0), (1, 1), (2, 1), (3, 2)]),
        ((4, 2), (0, 0), &[(1, 1), (2, 1), (3, 2), (4, 2)]),
        ((0, 0), (5, 5), &[(0, 0), (1, 1), (2, 2), (3, 3), (4, 4)]),
        ((0, 0), (0, 3), &[(0, 0), (0, 1), (0, 2)]),
        ((2, 2), (2, 2), &[]),
    ];
    for (a, b, expect) in cases {
        let got = crate_line(c(a.0, a.1), c(b.0, b.1), SCREEN);
        assert_eq!(got, set(expect), "{a:?} -> {b:?}");
        assert_eq!(got, model_line(c(a.0, a.1), c(b.0, b.1), SCREEN));
    }
}

#[test]
fn t27_sub_pixel_endpoints() {
    let got = crate_line(sp(0.3, 0.2), sp(5.8, 2.9), SCREEN);
    assert_eq!(got, set(&[(0, 0), (1, 0), (2, 1), (3, 1), (4, 2), (5, 2)]));
}

#[test]
fn t28_strips_and_loops() {
    // A strip in one octant: no duplicate and no gap at the shared endpoints.
    let pts = [sp(0.3, 0.4), sp(4.7, 1.9), sp(9.2, 3.1), sp(15.6, 5.5)];
    let mut all = Vec::new();
    for w in pts.windows(2) {
        all.extend(crate_line(w[0], w[1], SCREEN));
    }
    let mut dedup = all.clone();
    dedup.sort();
    dedup.dedup();
    assert_eq!(dedup.len(), all.len(), "no duplicates");
    let cols: Vec<i32> = dedup.iter().map(|p| p.0).collect();
    assert_eq!(
        cols,
        (0..16).collect::<Vec<_>>(),
        "one pixel per column, no gap"
    );
    // A closed loop: each vertex pixel exactly once.
    let loop_pts = [c(2, 2), c(12, 4), c(7, 13)];
    let mut hits = std::collections::HashMap::new();
    for i in 0..3 {
        for p in crate_line(loop_pts[i], loop_pts[(i + 1) % 3], SCREEN) {
            *hits.entry(p).or_insert(0) += 1;
        }
    }
    for v in [(2, 2), (12, 4), (7, 13)] {
        assert_eq!(hits.get(&v), Some(&1), "vertex {v:?}");
    }
    // Mixed octants equal the model.
    for (a, b) in [
        (c(1, 1), c(14, 3)),
        (c(14, 3), c(9, 15)),
        (c(9, 15), c(1, 1)),
    ] {
        assert_eq!(crate_line(a, b, SCREEN), model_line(a, b, SCREEN));
    }
}

#[test]
fn t29_clipping_changes_nothing() {
    let (a, b) = (sp(-1000.5, -333.7), sp(20.25, 7.1));
    let got = crate_line(a, b, SCREEN);
    let unclipped = model_line(a, b, PixelRect::new(-2000, -2000, 2000, 2000));
    let on_screen: Vec<_> = unclipped
        .into_iter()
        .filter(|&(x, y)| SCREEN.contains(x, y))
        .collect();
    assert_eq!(got, on_screen);
    assert_eq!(got.len(), 16);
}

#[test]
fn t30_far_endpoints_and_edges_of_the_screen() {
    let far = COORD_LIMIT;
    // Bounded work: the iterator's length is the number of pixels on screen.
    let it = line_pixels(
        ScreenPoint::new(-far, -far),
        ScreenPoint::new(far, far),
        SCREEN,
    );
    assert_eq!(it.len(), 16);
    let got = crate_line(
        ScreenPoint::new(-far, -far),
        ScreenPoint::new(far, far),
        SCREEN,
    );
    assert_eq!(
        got,
        model_line(
            ScreenPoint::new(-far, -far),
            ScreenPoint::new(far, far),
            SCREEN
        )
    );
    // Between the screen and the coordinate limit, both ways round: a line whose first column
    // is on screen has it set up in words at the largest differences there are.
    let on_screen = ScreenPoint::new(21, 30);
    for (fx, fy) in [
        (far, far),
        (-far, far),
        (far, -far),
        (-far, -far),
        (far, 37),
        (-far, -5),
        (3, far),
        (-9, -far),
    ] {
        let off = ScreenPoint::new(fx, fy);
        for (a, b) in [(on_screen, off), (off, on_screen)] {
            assert_eq!(
                crate_line(a, b, SCREEN),
                model_line(a, b, SCREEN),
                "{a:?} {b:?}"
            );
        }
    }
    // Beyond the coordinate limit: rejected as a whole.
    assert_eq!(
        line_pixels(ScreenPoint::new(-far - 1, 0), c(3, 3), SCREEN).count(),
        0
    );
    assert_eq!(
        line_pixels(ScreenPoint::new(i32::MIN, i32::MAX), c(3, 3), SCREEN).count(),
        0
    );
    // Along y = 0, y = H-1 and y = H.
    let row = |y: i32| {
        crate_line(
            ScreenPoint::new(-far, y * 16 + 8),
            ScreenPoint::new(far, y * 16 + 8),
            SCREEN,
        )
    };
    assert_eq!(row(0), (0..16).map(|x| (x, 0)).collect::<Vec<_>>());
    assert_eq!(row(15), (0..16).map(|x| (x, 15)).collect::<Vec<_>>());
    assert!(row(16).is_empty());
}

fn coord() -> impl Strategy<Value = i32> {
    prop_oneof![
        8 => -64i32..(20 * 16 + 64),
        2 => -(1i32 << 16)..(1 << 16),
        1 => prop::sample::select(vec![-(1 << 24), 1 << 24, 0, 8, 7, 9, -8]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// M10: set difference to the model is empty, clipped or not (R9).
    #[test]
    fn m10_random_lines_equal_the_model(ax in coord(), ay in coord(), bx in coord(), by in coord(),
                                        x0 in -4i32..12, y0 in -4i32..12, w in 0i32..20, h in 0i32..20) {
        let (a, b) = (ScreenPoint::new(ax, ay), ScreenPoint::new(bx, by));
        let clip = PixelRect::new(x0, y0, x0 + w, y0 + h);
        prop_assert_eq!(crate_line(a, b, clip), model_line(a, b, clip));
    }

    /// M10: lines that start inside the clip rectangle (their first column set up in words,
    /// from the endpoint the walk starts by, forwards and backwards) equal the model too.
    #[test]
    fn m10_lines_started_inside_the_clip_equal_the_model(
        ax in -64i32..(40 * 16), ay in -64i32..(40 * 16),
        bx in -64i32..(40 * 16), by in -64i32..(40 * 16),
    ) {
        let (a, b) = (ScreenPoint::new(ax, ay), ScreenPoint::new(bx, by));
        let clip = PixelRect::new(-8, -8, 48, 48);
        prop_assert_eq!(crate_line(a, b, clip), model_line(a, b, clip));
    }

    /// dEQP-style checks: an x-major line has one pixel per column.
    #[test]
    fn one_pixel_per_major_column(ax in coord(), ay in coord(), bx in coord(), by in coord()) {
        let (a, b) = (ScreenPoint::new(ax, ay), ScreenPoint::new(bx, by));
        let got = crate_line(a, b, PixelRect::new(-50, -50, 400, 400));
        let xmajor = (bx - ax).abs() >= (by - ay).abs();
        let mut keys: Vec<i32> = got.iter().map(|p| if xmajor { p.0 } else { p.1 }).collect();
        let n = keys.len();
        keys.dedup();
        prop_assert_eq!(keys.len(), n);
    }
}

//! A reduced run of the error-against-run-time report (`examples/accuracy.rs`,
//! `docs/accuracy.md`): the report's scenes at 160x120 (the OBJ models but Suzanne left out),
//! every configuration, and the limits the default configuration must hold.

#[path = "../examples/common/accuracy.rs"]
mod accuracy;
#[path = "../examples/common/desktop.rs"]
mod desktop;
#[path = "../examples/common/exact.rs"]
mod exact;
#[path = "../examples/common/reference.rs"]
mod reference;

use accuracy::{configs, ideal, measure, render, scenes, Config, Metrics, SceneDef, Shade};

fn reduced_scenes() -> Vec<SceneDef> {
    let models = concat!(env!("CARGO_MANIFEST_DIR"), "/models");
    let dir = std::path::Path::new(models).is_dir().then_some(models);
    scenes(dir, true)
        .into_iter()
        .filter(|s| !["teapot", "spot", "beetle"].contains(&s.name))
        .collect()
}

fn run(scene: &SceneDef, config: &Config) -> Metrics {
    let shade = if config.shade == Shade::Flat {
        Shade::Flat
    } else {
        Shade::Perspective
    };
    let reference = ideal(scene, shade, config.precision.subpixel_bits());
    let (image, _) = render(scene, config, 1).expect("the scene renders");
    measure(scene, config, &reference, &image)
}

/// Issue #5's limits for the default configuration, on every report scene: M1 = 0; no missing
/// and no unexpected pixel outside the partial band (M2); no occlusion error (M5); depth within
/// 1 LSB of the plane through the snapped vertices (M4); flat Lambert within 1 LSB per channel
/// (M6), and in the textured scenes every pixel whose texel is plain showing it; every vertex
/// within half a sub-pixel per axis plus its transform bound (M7).
#[test]
fn m1_m2_m4_m5_m6_m7_default_configuration_on_every_scene() {
    let scenes = reduced_scenes();
    assert!(scenes.len() >= 9, "{} scenes", scenes.len());
    for scene in &scenes {
        let m = run(scene, &Config::DEFAULT);
        let name = scene.name;
        assert!(m.covered > 500, "{name}: only {} pixels drawn", m.covered);
        assert_eq!(m.m1, 0, "{name}: M1");
        assert_eq!((m.missing, m.unexpected), (0, 0), "{name}: M2 {m:?}");
        assert_eq!(m.occlusion, 0, "{name}: M5");
        assert!(m.depth_plane_max <= 1.0, "{name}: M4 {}", m.depth_plane_max);
        if scene.textured {
            // Every pixel whose texel is plain shows it.
            assert!(m.texel_compared > 1000, "{name}: {m:?}");
            assert_eq!(m.texel_over, 0, "{name}: {m:?}");
        } else {
            assert!(m.color_max <= 1.0, "{name}: M6 {}", m.color_max);
        }
        assert_eq!(
            m.vertex_over_bound, 0,
            "{name}: M7, vertex max {}",
            m.vertex_max
        );
        // tiny-matrix documents a limit of the input: a Q16.16 model matrix scaled by 1/1024
        // holds its rotation with 6 significant bits (its bound accounts for it).
        if name != "tiny-matrix" {
            assert!(m.vertex_max <= 0.6, "{name}: vertex error {}", m.vertex_max);
        }
    }
}

/// Every knob, on the scene where it matters: the rasteriser rule holds whatever the knobs
/// (M1 = 0), and each knob changes what the report says it changes, so the report's columns
/// measure something.
#[test]
fn every_knob_is_real_and_measured() {
    let scenes = reduced_scenes();
    let scene = |name: &str| {
        scenes
            .iter()
            .find(|s| s.name == name)
            .unwrap_or_else(|| panic!("no scene {name}"))
    };
    let by_name = |name: &str| {
        configs()
            .into_iter()
            .find(|c| c.name == name)
            .unwrap_or_else(|| panic!("no configuration {name}"))
    };
    for config in configs() {
        for s in ["torus", "near-crossing", "slivers"] {
            assert_eq!(run(scene(s), &config).m1, 0, "{} on {s}", config.name);
        }
    }
    let torus = scene("torus");
    let default = run(torus, &Config::DEFAULT);
    // Coarser snapping moves vertices further.
    let coarse = run(torus, &by_name("subpixel-0"));
    assert!(coarse.vertex_max > 4.0 && default.vertex_max < 0.6);
    assert!(coarse.image_rmse > default.image_rmse);
    // Q24.8 loses the tiny model; the default keeps it.
    let tiny = scene("tiny");
    let q8 = run(tiny, &by_name("matrix-q24.8"));
    assert!(q8.missing + q8.unexpected > 100, "{q8:?}");
    // Q16.16 loses precision on it too; the default's exponent keeps it.
    let q16 = run(tiny, &by_name("matrix-q16.16"));
    let normalized = run(tiny, &Config::DEFAULT);
    assert!(q16.vertex_max > 4.0 * normalized.vertex_max, "{q16:?}");
    // The table's sines move vertices; the polynomial's do not.
    let table = run(torus, &by_name("trig-table"));
    assert!(table.vertex_max > 2.0, "{table:?}");
    // Depth width: u32 resolves what u16 does, in 65536 times finer units.
    let u32_depth = run(scene("far-near-1e4"), &by_name("depth-u32"));
    let u16_depth = run(scene("far-near-1e4"), &Config::DEFAULT);
    assert_eq!(u32_depth.occlusion, 0);
    assert!(u32_depth.depth_max > 1000.0 * u16_depth.depth_max.max(0.01));
    // Perspective correction matters on the receding floor, and is within 2 levels there (the
    // vertex colours are floored to 8 bits, the ideal ones are not).
    let floor = scene("floor");
    let affine = run(floor, &by_name("gouraud-affine"));
    let perspective = run(floor, &by_name("gouraud-perspective"));
    assert!(affine.color_max > 50.0, "{affine:?}");
    assert!(perspective.color_max <= 2.0, "{perspective:?}");
    // Exact normalisation and the default agree within a level; micromath's invsqrt does not.
    let exact = run(torus, &by_name("normalize-exact"));
    assert!(exact.color_max <= 1.0);
    // Highlights and point lights, per vertex, follow the f64 values as the plain torus does
    // (within 3 levels, perspective-correct); a crate frame without them is far off.
    let perspective = by_name("gouraud-perspective");
    for name in ["glossy", "lamp-near", "lamp-far"] {
        let m = run(scene(name), &perspective);
        assert!(m.color_max <= 3.0, "{name}: {m:?}");
    }
    // Affine texture mapping shows other texels on the receding floor; exact divisions at
    // every pixel show the same as the default's runs.
    let floor = scene("floor-textured");
    let affine = run(floor, &by_name("texture-affine"));
    let exact = run(floor, &by_name("texture-run-1"));
    assert!(
        affine.texel_over > 1000 && affine.texel_max > 4.0,
        "{affine:?}"
    );
    assert_eq!(exact.texel_over, 0, "{exact:?}");
    let glossy = scene("glossy");
    let matte = SceneDef {
        gloss: None,
        lamp: None,
        ..glossy.clone()
    };
    let reference = ideal(glossy, Shade::Perspective, 4);
    let (image, _) = render(&matte, &perspective, 1).expect("the scene renders");
    let m = measure(glossy, &perspective, &reference, &image);
    assert!(m.color_max > 100.0, "{m:?}");
}

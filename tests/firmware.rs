//! Host and target agree bit for bit: the firmware presets' frames rendered here, with the
//! firmware's own scene code (`bench/mcu/src/scenes.rs`), hash to the values in
//! `bench/mcu/hashes.txt`, which `bench/mcu/run.sh` (with CHECK=1) requires of the firmware
//! running on the emulated Cortex-M0 and M4. `BLESS=1 cargo test --test firmware` rewrites the
//! file.

#[path = "../bench/mcu/src/scenes.rs"]
#[allow(dead_code)]
mod scenes;

/// The `variants` preset's `wire-depth` configuration, as its firmware compiles it.
#[path = "../bench/mcu/src/wire_depth.rs"]
mod wire_depth;

/// The board firmwares' drawing code (`boards/showcase`), as the `boards` preset runs it.
#[path = "../boards/showcase/src/scene.rs"]
#[allow(dead_code)]
mod showcase;

use embedded_graphics::geometry::Size;
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, RgbColor};
use fixed3d::buffer::Carried;
use fixed3d::math::Vec3;
use fixed3d::mesh::FaceNormal;
use fixed3d::pipeline::{Bin, ScreenVertex};
use scenes::*;

/// Positions, normals and triangles for a generated torus of this size.
fn torus_storage(vertices: usize, triangles: usize) -> (Vec<Vec3>, Vec<Vec3>, Vec<[u16; 3]>) {
    (
        vec![Vec3::ZERO; vertices],
        vec![Vec3::ZERO; vertices],
        vec![[0u16; 3]; triangles],
    )
}

fn frame_hash(fb: &[Rgb565]) -> u32 {
    let mut h = Fnv::new();
    h.pixels(fb);
    h.0
}

/// Draws one frame into the cache, colour and depth buffers.
type DrawFrame<'a> = dyn FnMut(u32, &mut [ScreenVertex], &mut [Rgb565], &mut [u16]) + 'a;

fn host_hashes() -> Vec<(&'static str, u32)> {
    let n = (W * H) as usize;
    let (mut p, mut nrm, mut t) = (
        vec![Vec3::ZERO; TORUS_VERTICES],
        vec![Vec3::ZERO; TORUS_VERTICES],
        vec![[0u16; 3]; TORUS_TRIANGLES],
    );
    let mesh = torus_mesh(&mut p, &mut nrm, &mut t);
    let mut cache = vec![ScreenVertex::DEFAULT; TORUS_VERTICES];
    let (mut fb, mut depth) = (vec![Rgb565::BLACK; n], vec![0u16; n]);
    let mut framed = |draw: &mut DrawFrame<'_>| {
        chain(|f| {
            fb.fill(Rgb565::BLACK);
            depth.fill(u16::MAX);
            draw(f, &mut cache, &mut fb, &mut depth);
            frame_hash(&fb)
        })
    };
    let full_hash = framed(&mut |f, c, fb, d| {
        full(&mesh, f, c, fb, d);
    });
    // The firmware's `full` keeps the face normals: the same frames (and without them).
    let mut faces = vec![FaceNormal::ZERO; TORUS_TRIANGLES];
    let kept = mesh.with_face_normals(&mut faces).unwrap();
    let kept_hash = framed(&mut |f, c, fb, d| {
        full(&kept, f, c, fb, d);
    });
    let plain_hash = framed(&mut |f, c, fb, d| {
        full(&mesh, f, c, fb, d);
    });
    assert_eq!((kept_hash, plain_hash), (full_hash, full_hash));
    let gouraud_hash = framed(&mut |f, c, fb, d| {
        gouraud(&mesh, f, c, fb, d);
    });
    let phong_hash = framed(&mut |f, c, fb, d| {
        phong(&mesh, f, c, fb, d);
    });
    let (mut tp, mut tn, mut tuv, mut tt) = (
        vec![Vec3::ZERO; TEXTURED_VERTICES],
        vec![Vec3::ZERO; TEXTURED_VERTICES],
        vec![[fixed3d::math::Scalar::ZERO; 2]; TEXTURED_VERTICES],
        vec![[0u16; 3]; TORUS_TRIANGLES],
    );
    let textured_torus = textured_torus_mesh(&mut tp, &mut tn, &mut tuv, &mut tt);
    // Its own vertex cache: the textured torus has more vertices than `framed` holds.
    let mut texture_cache = vec![ScreenVertex::DEFAULT; TEXTURED_VERTICES];
    let textured_hash = framed(&mut |f, _, fb, d| {
        textured(&textured_torus, f, &mut texture_cache, fb, d);
    });
    let flat_hash = framed(&mut |f, c, fb, _| {
        flat(f, c, fb);
    });
    let (mut op, mut ot) = ([Vec3::ZERO; 16], [[0u16; 3]; 16]);
    let gem = obj_mesh(&mut op, &mut ot);
    assert_eq!(gem.triangles().len(), 8);
    let obj_hash = framed(&mut |f, c, fb, d| {
        obj(&gem, f, c, fb, d);
    });
    let mut cache2 = vec![ScreenVertex::DEFAULT; 2 * TORUS_VERTICES];
    let (mut rp, mut rt) = (
        vec![Vec3::ZERO; 3 * RANDOM_TRIANGLES],
        vec![[0u16; 3]; RANDOM_TRIANGLES],
    );
    let random = random_mesh(&mut rp, &mut rt);
    assert_eq!(random.triangles().len(), RANDOM_TRIANGLES);
    let variant_hashes: Vec<(&'static str, u32)> = VARIANTS
        .iter()
        .map(|&name| {
            let key: &'static str = Box::leak(format!("variants:{name}").into_boxed_str());
            let h = chain(|f| {
                fb.fill(Rgb565::BLACK);
                depth.fill(u16::MAX);
                let word = if name == "wire-depth" {
                    wire_depth::wire_depth(&mesh, f, true, &mut cache2, &mut fb, &mut depth)
                } else {
                    variant(name, &mesh, &random, f, &mut cache2, &mut fb, &mut depth)
                };
                frame_hash(&fb) ^ word.unwrap_or(0)
            });
            (key, h)
        })
        .collect();
    // The clipped variant does what it is there for: the near plane cuts triangles, and
    // spans reach every side of the screen (clamped to the target's columns).
    {
        use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
        use fixed3d::mesh::Object;
        use fixed3d::scene::Scene;
        use fixed3d::shade::Flat;
        let objects = [Object::new(&mesh, torus_model(0), ORANGE)];
        let scene = Scene::new(&objects, sun());
        let frame = clipped_frame(W, H).expect("frame");
        let p = frame.prepare(&scene, &mut cache2, Flat).expect("prepare");
        fb.fill(Rgb565::BLACK);
        depth.fill(u16::MAX);
        let mut c = FrameBuffer::new(&mut fb, W, H).expect("colour buffer");
        let mut d = DepthBuffer::new(&mut depth, W, H).expect("depth buffer");
        let stats = p.draw(&mut ColorDepth::new(&mut c, &mut d).expect("target"));
        let stats = stats.expect("drawn");
        assert!(stats.clipped > 50, "{stats:?}");
        let lit = |x: u32, y: u32| fb[(y * W + x) as usize] != Rgb565::BLACK;
        assert!((0..H).any(|y| lit(0, y)) && (0..H).any(|y| lit(W - 1, y)));
        assert!((0..W).any(|x| lit(x, 0)) && (0..W).any(|x| lit(x, H - 1)));
    }
    let rows = (W * BAND_ROWS) as usize;
    let (mut band, mut band_depth) = (vec![Rgb565::BLACK; rows], vec![0u16; rows]);
    let mut bins = vec![Bin::EMPTY; BAND_BINS];
    let mut carried = vec![Carried::EMPTY; BAND_CARRIED];
    let mut banded = |f, cache: &mut [ScreenVertex]| {
        let (b, d) = ((&mut bins[..], &mut carried[..]), &mut band_depth);
        bands(&mesh, f, cache, b, &mut band, d, &mut NoDisplay, &mut |w| {
            w()
        })
        .unwrap_or(0)
    };
    let bands_hash = chain(|f| banded(f, &mut cache));
    let mono_n = (MONO_W * MONO_H) as usize;
    let (mut mono_px, mut mono_depth) = (vec![BinaryColor::Off; mono_n], vec![0u16; mono_n]);
    let display_chain = chain(|f| {
        let colour = banded(f, &mut cache);
        mono(&mesh, f, &mut cache, &mut mono_px, &mut mono_depth);
        display_hash(colour, mono_hash(&mono_px))
    });
    let wire_hash = chain(|f| {
        let mut display = HashDisplay {
            hash: Fnv::new(),
            size: Size::new(W, H),
        };
        wire(&mesh, f, &mut cache, &mut display);
        display.hash.0
    });
    let (mut sp, mut sn, mut st) = (
        vec![Vec3::ZERO; SMALL_VERTICES],
        vec![Vec3::ZERO; SMALL_VERTICES],
        vec![[0u16; 3]; SMALL_TRIANGLES],
    );
    let small = small_torus_mesh(&mut sp, &mut sn, &mut st);
    let mut small_cache = vec![ScreenVertex::DEFAULT; SMALL_VERTICES];
    let microbit_hash = chain(|f| {
        let mut display = HashDisplay {
            hash: Fnv::new(),
            size: Size::new(SMALL_W, SMALL_H),
        };
        wire(&small, f, &mut small_cache, &mut display);
        display.hash.0
    });
    let boards_hash = {
        use showcase::*;
        let (mut p, mut n, mut t) = torus_storage(TORUS_VERTICES, TORUS_TRIANGLES);
        let lcd = showcase::torus_mesh(TORUS_RING, TORUS_TUBE, &mut p, &mut n, &mut t);
        let (mut sp, mut sn, mut st) = torus_storage(SMALL_VERTICES, SMALL_TRIANGLES);
        let small = showcase::torus_mesh(SMALL_RING, SMALL_TUBE, &mut sp, &mut sn, &mut st);
        let (mut cache, mut bins) = (
            vec![ScreenVertex::DEFAULT; TORUS_VERTICES],
            vec![Bin::EMPTY; LCD_BINS],
        );
        let (mut color, mut depth, mut bytes) = (
            vec![Rgb565::BLACK; LCD_BAND_CELLS],
            vec![0u16; LCD_BAND_CELLS],
            vec![0u8; 2 * LCD_BAND_CELLS],
        );
        let mut small_cache = vec![ScreenVertex::DEFAULT; SMALL_VERTICES];
        let (mut pixels, mut small_depth) =
            (vec![BinaryColor::Off; OLED_CELLS], vec![0u16; OLED_CELLS]);
        // As bench/mcu/src/bin/boards.rs draws and hashes a frame.
        chain(|f| {
            let mut h = Fnv::new();
            let models = lcd_models(&lcd, f);
            let frame = prepare_lcd(&models, &mut cache, &mut bins).expect("prepared");
            send_lcd_frame(&frame, &mut color, &mut depth, &mut bytes, |b| h.bytes(b))
                .expect("bands");
            draw_oled(&small, f, &mut small_cache, &mut pixels, &mut small_depth).expect("oled");
            display_hash(h.0, mono_hash(&pixels))
        })
    };
    let mut hashes = vec![
        ("boards", boards_hash),
        ("wire", wire_hash),
        ("wire@microbit", microbit_hash),
        ("flat", flat_hash),
        ("full", full_hash),
        ("gouraud", gouraud_hash),
        ("phong", phong_hash),
        ("textured", textured_hash),
        ("bands", bands_hash),
        ("obj", obj_hash),
        ("display", display_chain),
    ];
    hashes.extend(variant_hashes);
    hashes
}

/// The `wire-depth` variant draws what it is there to check: the wireframe (drawn first) and
/// the solid torus, whose surface hides part of the lines behind it though they were drawn
/// before it, and which they in turn cross in front of.
#[test]
fn wire_depth_variant_hides_the_lines_behind_the_solid() {
    let (mut p, mut n, mut t) = torus_storage(TORUS_VERTICES, TORUS_TRIANGLES);
    let mesh = torus_mesh(&mut p, &mut n, &mut t);
    let mut cache = vec![ScreenVertex::DEFAULT; 2 * TORUS_VERTICES];
    let (mut fb, mut depth) = (
        vec![Rgb565::BLACK; (W * H) as usize],
        vec![0u16; (W * H) as usize],
    );
    let blue = Rgb565::from(wire_depth::WIRE_BLUE);
    let mut count = |solid| {
        wire_depth::wire_depth(&mesh, 0, solid, &mut cache, &mut fb, &mut depth).expect("drawn");
        let lines = fb.iter().filter(|&&c| c == blue).count();
        (
            lines,
            fb.iter()
                .filter(|&&c| c != blue && c != Rgb565::BLACK)
                .count(),
        )
    };
    let (alone, none) = count(false);
    let (hidden, surface) = count(true);
    assert_eq!(none, 0);
    assert!(alone > 2000 && surface > 10_000, "{alone} {surface}");
    assert!(
        hidden > alone / 10 && hidden < alone * 9 / 10,
        "{hidden} of {alone}"
    );
}

#[test]
fn host_hashes_match_the_firmware_file() {
    let hashes = host_hashes();
    let full = hashes.iter().find(|(p, _)| *p == "full").map(|h| h.1);
    let bands = hashes.iter().find(|(p, _)| *p == "bands").map(|h| h.1);
    assert_eq!(
        full, bands,
        "a frame drawn in bands is the frame drawn at once"
    );
    let variant = |name: &str| hashes.iter().find(|(p, _)| *p == name).map(|h| h.1);
    assert_eq!(
        variant("variants:less"),
        full,
        "the torus drawn again at the same depths wins no pixel under the strict test"
    );
    assert_ne!(
        variant("variants:less-or-equal"),
        full,
        "it wins them all under <="
    );
    let text: String = hashes
        .iter()
        .map(|(p, h)| format!("{p} 0x{h:08x}\n"))
        .collect();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/bench/mcu/hashes.txt");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(path, &text).unwrap();
    }
    assert_eq!(std::fs::read_to_string(path).unwrap(), text);
}

/// The `triangles` variant reaches every case of a triangle's row set-up (each core compiles
/// its own, checked by this variant's hash under emulation): corners
/// tied in y, the middle corner's row the first, the last or between, both windings, spans
/// beyond the screen's sides, the near plane cutting triangles, rows above the band; and it
/// draws.
/// The floor variants take the perspective-correct spans they are there to check on every
/// core: each frame covers much of the screen, and differs from the same floor mapped or
/// interpolated affinely in many pixels.
#[test]
fn floor_variants_draw_perspective_spans() {
    let n = (W * H) as usize;
    let mut cache = vec![ScreenVertex::DEFAULT; 4];
    let mut draw = |kind: &str, f: u32| {
        let (mut fb, mut depth) = (vec![Rgb565::BLACK; n], vec![u16::MAX; n]);
        floor(kind, f, &mut cache, &mut fb, &mut depth).expect(kind);
        fb
    };
    for f in 0..FRAMES {
        for (perspective, affine) in [
            ("textured", "textured-affine"),
            ("gouraud", "gouraud-affine"),
        ] {
            let (p, a) = (draw(perspective, f), draw(affine, f));
            let covered = p.iter().filter(|&&c| c != Rgb565::BLACK).count();
            assert!(covered > n / 5, "{perspective} {f}: {covered} pixels");
            let differ = p.iter().zip(&a).filter(|(p, a)| p != a).count();
            assert!(
                differ > covered / 2,
                "{perspective} {f}: {differ} of {covered}"
            );
        }
    }
}

#[test]
fn triangles_variant_reaches_every_setup_case() {
    let (mut rp, mut rt) = (
        vec![Vec3::ZERO; 3 * RANDOM_TRIANGLES],
        vec![[0u16; 3]; RANDOM_TRIANGLES],
    );
    let random = random_mesh(&mut rp, &mut rt);
    let (mut p, mut n, mut t) = (
        vec![Vec3::ZERO; TORUS_VERTICES],
        vec![Vec3::ZERO; TORUS_VERTICES],
        vec![[0u16; 3]; TORUS_TRIANGLES],
    );
    let torus = torus_mesh(&mut p, &mut n, &mut t);
    let mut cache = vec![ScreenVertex::DEFAULT; 2 * TORUS_VERTICES];
    let (mut fb, mut depth) = (
        vec![Rgb565::BLACK; (W * H) as usize],
        vec![u16::MAX; (W * H) as usize],
    );
    let word = variant(
        "triangles",
        &torus,
        &random,
        0,
        &mut cache,
        &mut fb,
        &mut depth,
    );
    let lit = fb.iter().filter(|&&c| c != Rgb565::BLACK).count();
    assert!(word.is_some() && lit > 10_000, "{word:?} {lit}");
    // The screen triangles of frame 0, from the cache `variant` left (sub-pixels, 16 a pixel).
    let first_row = |y: i32| (y + 7) >> 4;
    let (mut tied, mut at_first, mut at_last, mut between) = (0, 0, 0, 0);
    let (mut windings, mut beyond_sides, mut cut, mut above_band) = ([0; 2], 0, 0, 0);
    for tri in random.triangles() {
        let v = tri.map(|i| cache[i as usize]);
        if !v.iter().all(|v| v.is_inside()) {
            cut += 1;
            continue;
        }
        let q = v.map(|v| v.point());
        let mut ys = q.map(|q| q.y);
        ys.sort();
        tied += (ys[0] == ys[1] || ys[1] == ys[2]) as u32;
        let (a, b, c) = (first_row(ys[0]), first_row(ys[1]), first_row(ys[2]));
        if a < c {
            at_first += (b == a) as u32;
            at_last += (b == c) as u32;
            between += (a < b && b < c) as u32;
        }
        let area = (q[1].x - q[0].x) as i64 * (q[2].y - q[0].y) as i64
            - (q[2].x - q[0].x) as i64 * (q[1].y - q[0].y) as i64;
        windings[(area > 0) as usize] += 1;
        beyond_sides += q.iter().any(|q| q.x < 0 || q.x > 16 * W as i32) as u32;
        above_band += q.iter().any(|q| q.y < 16 * 37) as u32;
    }
    let counts = [tied, at_first, at_last, between, windings[0], windings[1]];
    assert!(counts.iter().all(|&k| k >= 30), "{counts:?}");
    assert!(
        beyond_sides >= 30 && cut >= 30 && above_band >= 30,
        "{beyond_sides} {cut} {above_band}"
    );
}

/// The `front` variant walks an object inside every clip plane culled to its front faces
/// (checked by this variant's hash, which folds in every count and the depths, under
/// emulation) over back faces, front faces
/// and faces of zero area, with runs of back and of front faces; and it draws.
#[test]
fn front_variant_walks_every_kind_of_face_inside_every_plane() {
    use fixed3d::pipeline::Stats;
    let (mut rp, mut rt) = (
        vec![Vec3::ZERO; 3 * RANDOM_TRIANGLES],
        vec![[0u16; 3]; RANDOM_TRIANGLES],
    );
    let random = random_mesh(&mut rp, &mut rt);
    let mut cache = vec![ScreenVertex::DEFAULT; RANDOM_TRIANGLES * 3];
    let (mut fb, mut depth) = (
        vec![Rgb565::BLACK; (W * H) as usize],
        vec![u16::MAX; (W * H) as usize],
    );
    let stats = random_front_stats(&random, 0, &mut cache, &mut fb, &mut depth);
    let stats = stats.expect("drawn");
    let Stats {
        culled,
        degenerate,
        drawn,
        outside,
        clipped,
        invalid,
        ..
    } = stats;
    assert_eq!((outside, clipped, invalid), (0, 0, 0), "{stats:?}");
    assert!(cache.iter().all(|v| v.is_inside()));
    assert!(
        culled >= 100 && drawn >= 100 && degenerate >= 5,
        "{stats:?}"
    );
    // The kind of each triangle in turn: back (2), front (0) or of zero area (1).
    let kinds: Vec<i64> = random
        .triangles()
        .iter()
        .map(|tri| {
            let q = tri.map(|i| cache[i as usize].point());
            let area = (q[1].x - q[0].x) as i64 * (q[2].y - q[0].y) as i64
                - (q[2].x - q[0].x) as i64 * (q[1].y - q[0].y) as i64;
            area.signum() + 1
        })
        .collect();
    let runs = |k: i64| kinds.windows(2).filter(|w| w == &[k, k]).count();
    assert!(runs(0) >= 10 && runs(2) >= 10, "{} {}", runs(0), runs(2));
    assert_eq!(kinds.iter().filter(|&&k| k == 1).count() as u32, degenerate);
    assert_eq!(kinds.iter().filter(|&&k| k == 2).count() as u32, culled);
    let lit = fb.iter().filter(|&&c| c != Rgb565::BLACK).count();
    assert!(lit > 1_000, "{lit}");
}

/// The RP2040 firmware's scheme (boards/pico-st7789): one prepared frame, the even bands drawn
/// by one core and the odd ones by the other, gives the frame's image band for band; and the
/// frame shows the torus.
#[test]
fn board_bands_from_two_threads_equal_one_pass() {
    use showcase::*;
    let (mut p, mut n, mut t) = torus_storage(TORUS_VERTICES, TORUS_TRIANGLES);
    let lcd = showcase::torus_mesh(TORUS_RING, TORUS_TUBE, &mut p, &mut n, &mut t);
    let (mut cache, mut bins) = (
        vec![ScreenVertex::DEFAULT; TORUS_VERTICES],
        vec![Bin::EMPTY; LCD_BINS],
    );
    let models = lcd_models(&lcd, 7);
    let frame = prepare_lcd(&models, &mut cache, &mut bins).expect("prepared");
    let bands_of = |parity: u32| {
        let mut bytes = Vec::new();
        let (mut color, mut depth) = (
            vec![Rgb565::BLACK; LCD_BAND_CELLS],
            vec![0u16; LCD_BAND_CELLS],
        );
        let mut clean = false;
        for band in (parity..LCD_BANDS).step_by(2) {
            clean = draw_lcd_band(&frame, band, &mut color, &mut depth, clean).expect("band");
            let mut b = vec![0u8; 2 * LCD_BAND_CELLS];
            lcd_bytes(&color, &mut b);
            bytes.push((band, b));
        }
        bytes
    };
    let (even, odd) = std::thread::scope(|s| {
        let even = s.spawn(|| bands_of(0));
        let odd = s.spawn(|| bands_of(1));
        (even.join().unwrap(), odd.join().unwrap())
    });
    let mut two: Vec<(u32, Vec<u8>)> = even.into_iter().chain(odd).collect();
    two.sort_by_key(|(band, _)| *band);
    let two: Vec<u8> = two.into_iter().flat_map(|(_, b)| b).collect();
    // One pass: the whole frame through buffers of all its rows.
    let all = (LCD_SIZE * LCD_SIZE) as usize;
    let (mut color, mut depth) = (vec![Rgb565::BLACK; all], vec![u16::MAX; all]);
    frame.draw_band(0, &mut color, &mut depth).expect("frame");
    let mut one = vec![0u8; 2 * all];
    lcd_bytes(&color, &mut one);
    assert_eq!(two, one);
    let lit = color.iter().filter(|&&c| c != Rgb565::BLACK).count();
    assert!(lit > all / 10, "the torus covers {lit} of {all} pixels");
}

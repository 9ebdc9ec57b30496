//! The OBJ parser: hostile inputs O1–O27 of docs/cases.md, the four real models, and
//! property tests that arbitrary bytes never panic or write past the caller's storage.

use fixed3d::math::{Scalar, Vec3};
use fixed3d::obj::{
    bounds, parse, split_corners, Aabb, ObjBuffers, ObjCounts, ObjError, ObjErrorKind, ObjStream,
    Placement, SplitBuffers, StaticObj, Storage, NO_INDEX,
};
use proptest::prelude::*;

#[derive(Debug)]
struct Parsed {
    counts: ObjCounts,
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    texcoords: Vec<[Scalar; 2]>,
    triangles: Vec<[u16; 3]>,
    tri_normals: Vec<[u16; 3]>,
    tri_texcoords: Vec<[u16; 3]>,
}

/// Owned storage for a parse, of one capacity for everything.
struct Store {
    positions: Vec<Vec3>,
    normals: Vec<Vec3>,
    texcoords: Vec<[Scalar; 2]>,
    triangles: Vec<[u16; 3]>,
    tri_normals: Vec<[u16; 3]>,
    tri_texcoords: Vec<[u16; 3]>,
}

impl Store {
    fn new(cap: usize) -> Self {
        Store {
            positions: vec![Vec3::ZERO; cap],
            normals: vec![Vec3::ZERO; cap],
            texcoords: vec![[Scalar::ZERO; 2]; cap],
            triangles: vec![[0u16; 3]; cap],
            tri_normals: vec![[0u16; 3]; cap],
            tri_texcoords: vec![[0u16; 3]; cap],
        }
    }

    fn buffers(&mut self) -> ObjBuffers<'_> {
        ObjBuffers {
            positions: &mut self.positions,
            texcoords: &mut self.texcoords,
            normals: &mut self.normals,
            triangles: &mut self.triangles,
            triangle_texcoords: &mut self.tri_texcoords,
            triangle_normals: &mut self.tri_normals,
        }
    }

    /// What the parse wrote, cut to its counts.
    fn parsed(mut self, counts: ObjCounts) -> Parsed {
        self.positions.truncate(counts.positions);
        self.normals.truncate(counts.normals);
        self.texcoords.truncate(counts.texcoords);
        self.triangles.truncate(counts.triangles);
        self.tri_normals.truncate(counts.triangles);
        self.tri_texcoords.truncate(counts.triangles);
        Parsed {
            counts,
            positions: self.positions,
            normals: self.normals,
            texcoords: self.texcoords,
            triangles: self.triangles,
            tri_normals: self.tri_normals,
            tri_texcoords: self.tri_texcoords,
        }
    }
}

fn parse_with(text: &[u8], cap: usize) -> Result<Parsed, ObjError> {
    let mut store = Store::new(cap);
    let counts = parse(text, &mut store.buffers(), Placement::AsIs)?;
    Ok(store.parsed(counts))
}

fn p(text: &str) -> Result<Parsed, ObjError> {
    parse_with(text.as_bytes(), 64)
}

fn kind(text: &str) -> (u32, ObjErrorKind) {
    match p(text) {
        Ok(_) => panic!("{text:?} parsed"),
        Err(e) => (e.line, e.kind),
    }
}

fn s(v: f64) -> Scalar {
    Scalar::from_num(v)
}

const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

#[test]
fn o01_missing_coordinate() {
    assert_eq!(kind("v 1.0 2.0"), (1, ObjErrorKind::MissingField));
}

#[test]
fn o02_homogeneous_weight() {
    assert_eq!(kind("v 1 2 3 0"), (1, ObjErrorKind::ScaleByZero));
    let r = p("v 1 2 3 0.5").unwrap();
    assert_eq!(r.positions[0], Vec3::from_int(2, 4, 6));
    assert_eq!(
        p("v 1 2 3 1").unwrap().positions[0],
        Vec3::from_int(1, 2, 3)
    );
    assert_eq!(kind("v 30000 0 0 0.5"), (1, ObjErrorKind::NumberOutOfRange));
}

#[test]
fn o03_vertex_colours_and_bad_arity() {
    assert_eq!(
        p("v 1 2 3 0.5 0.5 0.5").unwrap().positions[0],
        Vec3::from_int(1, 2, 3)
    );
    assert_eq!(kind("v 1 2 3 4 5"), (1, ObjErrorKind::ExtraField));
    assert_eq!(kind("v 1 2 3 4 5 6 7"), (1, ObjErrorKind::ExtraField));
}

#[test]
fn o04_not_finite() {
    for t in ["v inf 0 0", "v -inf 0 0", "v nan 0 0"] {
        assert_eq!(kind(t), (1, ObjErrorKind::NumberNotFinite), "{t}");
    }
    assert_eq!(kind("v 1e40 0 0"), (1, ObjErrorKind::NumberOutOfRange));
}

#[test]
fn o05_out_of_fixed_point_range() {
    assert_eq!(kind("v 40000 0 0"), (1, ObjErrorKind::NumberOutOfRange));
    let e = p("v 0 0 40000").unwrap_err();
    assert_eq!(e.column, 7);
    // Within half a step of the largest value: rounds to it (no float double rounding).
    assert_eq!(p("v 32767.99999 0 0").unwrap().positions[0].x, Scalar::MAX);
}

#[test]
fn o06_tiny_values_and_negative_zero() {
    let r = p("v 0.0000076 0 0\nv -0 -0.0 0").unwrap();
    assert_eq!(r.positions, vec![Vec3::ZERO, Vec3::ZERO]);
}

#[test]
fn o07_invalid_numbers_with_line_and_column() {
    for t in [
        "v 1,5 2 3",
        "v 1.0.0 2 3",
        "v 0x10 0 0",
        "v 1e 0 0",
        "v --1 0 0",
        "v 1_0 0 0",
        "v ١ 0 0",
    ] {
        let e = p(&format!("# header\n{t}")).unwrap_err();
        assert_eq!(
            (e.line, e.column, e.kind),
            (2, 3, ObjErrorKind::NumberInvalid),
            "{t}"
        );
    }
}

#[test]
fn o08_valid_grammar_variants() {
    assert_eq!(
        p("v +1.0 -.5 1.").unwrap().positions[0],
        Vec3::new(s(1.0), s(-0.5), s(1.0))
    );
}

#[test]
fn o09_long_mantissa() {
    let r = p("v 0.123456789012345678901234567890123456789012345678901234567890 0 0").unwrap();
    assert_eq!(
        r.positions[0].x.to_bits(),
        (0.123_456_789_012_345_68f64 * 65536.0).round() as i32
    );
}

#[test]
fn o10_forward_and_early_references() {
    assert_eq!(kind("f 1 2 3\nv 0 0 0"), (1, ObjErrorKind::IndexOutOfRange));
    assert_eq!(
        kind(&format!("{TRI}f 1 2 9")),
        (4, ObjErrorKind::IndexOutOfRange)
    );
    // A forward reference to a vertex defined later is still out of range.
    assert_eq!(
        kind(&format!("{TRI}f 1 2 4\nv 1 1 1")),
        (4, ObjErrorKind::IndexOutOfRange)
    );
}

#[test]
fn o11_index_zero() {
    assert_eq!(kind(&format!("{TRI}f 0 1 2")), (4, ObjErrorKind::IndexZero));
}

#[test]
fn o12_relative_indices() {
    let r = p(&format!("{TRI}v 5 5 5\nf -1 -2 -3")).unwrap();
    assert_eq!(r.triangles, vec![[3, 2, 1]]);
    assert_eq!(
        kind("v 0 0 0\nv 1 0 0\nf -1 -2 -3"),
        (3, ObjErrorKind::IndexOutOfRange)
    );
}

#[test]
fn o13_index_overflow() {
    assert_eq!(
        kind(&format!("{TRI}f 1 2 99999999999999999999")),
        (4, ObjErrorKind::NumberOutOfRange)
    );
    assert_eq!(
        kind(&format!("{TRI}f 1 2 -2147483648")),
        (4, ObjErrorKind::IndexOutOfRange)
    );
    assert_eq!(
        kind(&format!("{TRI}f 1 2 -9223372036854775808")),
        (4, ObjErrorKind::NumberOutOfRange)
    );
    assert_eq!(
        p(&format!("{TRI}f 1 2 +3")).unwrap().triangles,
        vec![[0, 1, 2]]
    );
}

#[test]
fn o14_too_few_corners() {
    assert_eq!(
        kind(&format!("{TRI}f 1 2")),
        (4, ObjErrorKind::FaceTooFewVertices)
    );
    assert_eq!(
        kind(&format!("{TRI}f")),
        (4, ObjErrorKind::FaceTooFewVertices)
    );
}

#[test]
fn o15_degenerate_faces_are_kept() {
    let r = p(&format!("{TRI}f 1 1 1\nf 1 2 1")).unwrap();
    assert_eq!(r.triangles, vec![[0, 0, 0], [0, 1, 0]]);
}

#[test]
fn o16_large_polygons_fan_without_a_fixed_array() {
    let mut text = String::new();
    for k in 0..40 {
        let a = k as f64 / 40.0 * std::f64::consts::TAU;
        text += &format!("v {:.4} {:.4} 0\n", a.cos(), a.sin());
    }
    text += "f";
    for k in 1..=40 {
        text += &format!(" {k}");
    }
    let r = p(&text).unwrap();
    assert_eq!(r.triangles.len(), 38);
    for (i, t) in r.triangles.iter().enumerate() {
        assert_eq!(*t, [0, i as u16 + 1, i as u16 + 2]);
    }
}

#[test]
fn o17_corner_forms() {
    let base = format!("{TRI}vt 0 0\nvt 1 0\nvn 0 0 1\n");
    let r = p(&format!(
        "{base}f 1/1/1 2/2/1 3/1/1\nf 1//1 2//1 3//1\nf 1/ 2/ 3/\nf 1 2/2 3//1"
    ))
    .unwrap();
    assert_eq!(r.triangles, vec![[0, 1, 2]; 4]);
    assert_eq!(
        r.tri_texcoords,
        vec![
            [0, 1, 0],
            [NO_INDEX; 3],
            [NO_INDEX; 3],
            [NO_INDEX, 1, NO_INDEX]
        ]
    );
    assert_eq!(
        r.tri_normals,
        vec![[0, 0, 0], [0, 0, 0], [NO_INDEX; 3], [NO_INDEX, NO_INDEX, 0]]
    );
    assert_eq!(
        kind(&format!("{base}f 1/1/1/1 2 3")),
        (7, ObjErrorKind::ExtraField)
    );
    assert_eq!(
        kind(&format!("{base}f 1/3 2 3")),
        (7, ObjErrorKind::IndexOutOfRange)
    );
    assert_eq!(
        kind(&format!("{base}f 1//2 2 3")),
        (7, ObjErrorKind::IndexOutOfRange)
    );
    assert_eq!(
        kind(&format!("{base}f /1 2 3")),
        (7, ObjErrorKind::NumberInvalid)
    );
}

#[test]
fn o18_texcoord_and_normal_indices_without_elements() {
    assert_eq!(
        kind(&format!("{TRI}f 1/1 2/1 3/1")),
        (4, ObjErrorKind::IndexOutOfRange)
    );
    assert_eq!(
        kind(&format!("{TRI}f 1//1 2//1 3//1")),
        (4, ObjErrorKind::IndexOutOfRange)
    );
}

#[test]
fn o19_line_endings_and_whitespace() {
    let lf = p("v 1 2 3\nv 4 5 6\nv 7 8 9\nf 1 2 3\n").unwrap();
    for text in [
        "v 1 2 3\r\nv 4 5 6\r\nv 7 8 9\r\nf 1 2 3\r\n",
        "v 1 2 3\rv 4 5 6\rv 7 8 9\rf 1 2 3",
        "v 1 2 3\nv 4 5 6\nv 7 8 9\nf 1 2 3",
        "  v\t1   2\t\t3\n\tv 4 5 6 \nv 7 8 9\t\nf 1 2 3   ",
    ] {
        let r = p(text).unwrap();
        assert_eq!(
            (&r.positions, &r.triangles),
            (&lf.positions, &lf.triangles),
            "{text:?}"
        );
    }
    // Line numbers count CRLF once.
    assert_eq!(
        kind("v 1 2 3\r\nv 1 2\r\n"),
        (2, ObjErrorKind::MissingField)
    );
}

#[test]
fn o20_comments() {
    let r = p(
        "# a comment\n\nv 1 2 3 # trailing\n   # indented\nv 4 5 6\nv 7 8 9#glued\nf 1 2 3 # done",
    )
    .unwrap();
    assert_eq!(
        (r.counts.positions, r.counts.triangles, r.counts.skipped),
        (3, 1, 0)
    );
}

#[test]
fn o21_unknown_statements_are_skipped_and_counted() {
    let text = format!("o obj\ng grp\ns off\nusemtl m\nmtllib a.mtl\nl 1 2\np 1\nvp 0.5\ncurv 0 1 1 2\nv1 2 3\n{TRI}f 1 2 3");
    let r = p(&text).unwrap();
    assert_eq!(
        (r.counts.skipped, r.counts.positions, r.counts.triangles),
        (10, 3, 1)
    );
}

#[test]
fn o22_empty_files() {
    for text in ["", "# only a comment\n", "\n\n\n"] {
        let r = p(text).unwrap();
        assert_eq!((r.counts.positions, r.counts.triangles), (0, 0));
    }
}

#[test]
fn o23_capacity() {
    let text = format!("{TRI}v 1 1 1\nf 1 2 3\nf 2 3 4\n");
    let e = parse_with(text.as_bytes(), 3).unwrap_err();
    assert_eq!(
        (e.line, e.kind),
        (4, ObjErrorKind::CapacityExceeded(Storage::Positions))
    );
    let mut pos = [Vec3::ZERO; 8];
    let mut tris = [[7u16; 3]; 3];
    let e = parse(
        text.as_bytes(),
        &mut ObjBuffers::new(&mut pos, &mut tris[..1]),
        Placement::AsIs,
    )
    .unwrap_err();
    assert_eq!(
        (e.line, e.kind),
        (6, ObjErrorKind::CapacityExceeded(Storage::Triangles))
    );
    // Nothing written past the slice given.
    assert_eq!(tris[1..], [[7, 7, 7], [7, 7, 7]]);
    // Zero-capacity optional storage means "count, do not keep".
    let mut pos = [Vec3::ZERO; 8];
    let mut tris = [[0u16; 3]; 8];
    let c = parse(
        b"vn 0 0 1\nvt 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1 2/1/1 3/1/1",
        &mut ObjBuffers::new(&mut pos, &mut tris),
        Placement::AsIs,
    )
    .unwrap();
    assert_eq!((c.normals, c.texcoords, c.triangles), (1, 1, 1));
}

#[test]
fn o24_huge_whitespace_and_long_lines() {
    let mut text = " ".repeat(5_000_000);
    text += "\n";
    text += &"\t".repeat(1_000_000);
    text += TRI;
    text += "v 1";
    text += &" ".repeat(1_000_000);
    text += "2 3\nf 1 2 3";
    let r = p(&text).unwrap();
    assert_eq!((r.counts.positions, r.counts.triangles), (4, 1));
}

#[test]
fn o25_encoding() {
    assert_eq!(kind("v 1 2 3\nv 1 \u{0} 3"), (2, ObjErrorKind::Encoding));
    let bad = b"v 1 2 3\n# \xff\xfe\n";
    assert_eq!(parse_with(bad, 8).unwrap_err().kind, ObjErrorKind::Encoding);
    let r = p("\u{feff}v 1 2 3\nv 0 0 0\nv 1 1 1\nf 1 2 3").unwrap();
    assert_eq!(r.counts.positions, 3);
}

#[test]
fn o26_zero_and_tiny_normals_are_kept_as_written() {
    let r = p("vn 0 0 0\nvn 0.000000001 0 0\nvn 3 4 0").unwrap();
    assert_eq!(
        r.normals,
        vec![Vec3::ZERO, Vec3::ZERO, Vec3::from_int(3, 4, 0)]
    );
}

#[test]
fn o27_truncated_final_line() {
    assert_eq!(kind(&format!("{TRI}f 1 2")), kind(&format!("{TRI}f 1 2\n")));
    assert_eq!(
        p("v 1. 2 3").unwrap().positions,
        p("v 1. 2 3\n").unwrap().positions
    );
}

#[test]
fn texcoords_are_stored() {
    let r = p("vt 0.25\nvt 0.5 0.75 1").unwrap();
    assert_eq!(r.texcoords, vec![[s(0.25), s(0.0)], [s(0.5), s(0.75)]]);
    assert_eq!(kind("vt 1 2 3 4"), (1, ObjErrorKind::ExtraField));
    assert_eq!(kind("vt"), (1, ObjErrorKind::MissingField));
    assert_eq!(kind("vn 1 2"), (1, ObjErrorKind::MissingField));
}

#[test]
fn more_than_65536_vertices_is_an_error() {
    let text = "v 0 0 0\n".repeat(65_537);
    let e = parse_with(text.as_bytes(), 70_000).unwrap_err();
    assert_eq!((e.line, e.kind), (65_537, ObjErrorKind::TooManyVertices));
}

fn model(name: &str) -> Vec<u8> {
    std::fs::read(format!("{}/models/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

#[test]
fn the_four_models_parse_with_the_right_counts() {
    for (name, v, t, n, vt) in [
        ("teapot.obj", 3644, 6320, 0, 0),
        ("suzanne.obj", 507, 968, 507, 0),
        ("spot.obj", 2930, 5856, 0, 3225),
        ("beetle.obj", 1148, 2053, 1212, 0),
    ] {
        let r = parse_with(&model(name), 8000).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            (
                r.counts.positions,
                r.counts.triangles,
                r.counts.normals,
                r.counts.texcoords
            ),
            (v, t, n, vt),
            "{name}"
        );
        assert!(r.triangles.iter().flatten().all(|&i| (i as usize) < v));
    }
    let r = parse_with(&model("beetle.obj"), 8000).unwrap();
    assert!(r.counts.skipped >= 3, "mtllib, o, s, usemtl");
}

/// A model can be parsed at compile time into flash.
static SUZANNE: StaticObj<507, 968> =
    match StaticObj::parse(include_bytes!("../models/suzanne.obj")) {
        Ok(m) => m,
        Err(_) => panic!("suzanne.obj does not parse"),
    };

#[test]
fn static_parse_equals_run_time_parse() {
    let r = parse_with(&model("suzanne.obj"), 1000).unwrap();
    let m = SUZANNE.mesh();
    assert_eq!(m.positions(), &r.positions[..]);
    assert_eq!(m.triangles(), &r.triangles[..]);
    assert_eq!(SUZANNE.counts().triangles, 968);
}

#[test]
fn bounds_and_fit() {
    let text = b"v -100000 5 0.5\nv 300000 -7 1e3\nv 0 0 0\nf 1 2 3";
    assert_eq!(
        parse_with(text, 8).unwrap_err().kind,
        ObjErrorKind::NumberOutOfRange
    );
    let b = bounds(text).unwrap();
    assert_eq!(b.min[0], -100000 << 16);
    assert_eq!(b.max[0], 300000 << 16);
    let fit = Placement::fit(&b, Scalar::from_num(10));
    let mut pos = [Vec3::ZERO; 3];
    let mut tris = [[0u16; 3]; 1];
    let c = parse(text, &mut ObjBuffers::new(&mut pos, &mut tris), fit).unwrap();
    assert_eq!(c.bounds.min.x, Scalar::from_num(-10));
    assert_eq!(c.bounds.max.x, Scalar::from_num(10));
    // 400000 units across become 20: one Q16.16 step is 20000/65536 of a file unit.
    assert!((fit.resolution() - 20_000.0 / 65536.0).abs() < 1e-9);
    assert_eq!(Placement::AsIs.resolution(), 1.0 / 65536.0);
    let spot = parse_with(&model("spot.obj"), 8000).unwrap();
    let Aabb { min, max } = spot.counts.bounds;
    assert!(min.x < max.x && min.y < max.y && min.z < max.z);
}

fn valid_model() -> impl Strategy<Value = Vec<u8>> {
    Just(model("suzanne.obj")[..6000].to_vec())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Arbitrary bytes: never a panic, never a write past the (small) storage.
    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400), cap in 0usize..6) {
        check_bounded(&bytes, cap);
    }

    /// Bytes that look like OBJ (keywords, numbers, slashes, signs, line breaks).
    #[test]
    fn obj_like_text_never_panics(tokens in prop::collection::vec(prop::sample::select(vec![
        "v", "vt", "vn", "f", "o", " ", "\t", "\n", "\r", "\r\n", "#", "/", "//", "-", "+", ".", "e", "E",
        "0", "1", "2", "3", "9", "-1", "-3", "65536", "99999999999999999999", "inf", "nan", "1e40", "\u{0}",
    ]), 0..120), cap in 0usize..8) {
        let text: String = tokens.concat();
        check_bounded(text.as_bytes(), cap);
    }

    /// A valid file with bytes mutated.
    #[test]
    fn mutated_models_never_panic(base in valid_model(), edits in prop::collection::vec((0usize..6000, any::<u8>()), 1..20), cap in 0usize..700) {
        let mut bytes = base;
        for (at, b) in edits {
            if let Some(x) = bytes.get_mut(at) {
                *x = b;
            }
        }
        check_bounded(&bytes, cap);
    }

    /// Round trip: a random valid mesh written as OBJ parses back identically.
    #[test]
    fn round_trip(points in prop::collection::vec((-30000i32..30000, -30000i32..30000, -30000i32..30000), 3..40),
                  faces in prop::collection::vec((0usize..40, 0usize..40, 0usize..40), 0..40)) {
        let n = points.len();
        let mut text = String::new();
        let pos: Vec<Vec3> = points.iter().map(|&(x, y, z)| Vec3::from_bits(x * 7, y * 3, z)).collect();
        for v in &pos {
            let e = |c: Scalar| format!("{:.16}", c.to_num::<f64>()); // exact decimal
            text += &format!("v {} {} {}\n", e(v.x), e(v.y), e(v.z));
        }
        let tris: Vec<[u16; 3]> = faces.iter().map(|&(a, b, c)| [(a % n) as u16, (b % n) as u16, (c % n) as u16]).collect();
        for t in &tris {
            text += &format!("f {} {} -{}\n", t[0] + 1, t[1] + 1, n - t[2] as usize);
        }
        let r = parse_with(text.as_bytes(), 64).unwrap();
        prop_assert_eq!(r.positions, pos);
        prop_assert_eq!(r.triangles, tris);
    }
}

fn check_bounded(bytes: &[u8], cap: usize) {
    const CANARY: Vec3 = Vec3::from_int(-7, -7, -7);
    let mut pos = vec![CANARY; cap + 4];
    let mut nor = vec![CANARY; cap + 4];
    let mut tex = vec![[Scalar::MIN; 2]; cap + 4];
    let mut tris = vec![[0xAAAA; 3]; cap + 4];
    let mut tt = vec![[0xAAAA; 3]; cap + 4];
    let mut tn = vec![[0xAAAA; 3]; cap + 4];
    let result = {
        let mut b = ObjBuffers {
            positions: &mut pos[..cap],
            texcoords: &mut tex[..cap],
            normals: &mut nor[..cap],
            triangles: &mut tris[..cap],
            triangle_texcoords: &mut tt[..cap],
            triangle_normals: &mut tn[..cap],
        };
        parse(bytes, &mut b, Placement::AsIs)
    };
    assert!(pos[cap..].iter().chain(&nor[cap..]).all(|v| *v == CANARY));
    assert!(tex[cap..].iter().all(|v| *v == [Scalar::MIN; 2]));
    assert!(tris[cap..]
        .iter()
        .chain(&tt[cap..])
        .chain(&tn[cap..])
        .all(|t| *t == [0xAAAA; 3]));
    if let Ok(c) = result {
        assert!(c.positions <= cap && c.triangles <= cap);
        for t in &tris[..c.triangles] {
            assert!(t.iter().all(|&i| (i as usize) < c.positions));
        }
    }
}

/// Framing: every vertex of each model, placed by its bounding box, projects inside the
/// viewport and between the near and far planes.
#[test]
fn framing_shows_the_whole_model() {
    use embedded_graphics::pixelcolor::Rgb888;
    use fixed3d::camera::Framing;
    use fixed3d::math::{Angle, Mat4};
    use fixed3d::mesh::{Mesh, Object};
    use fixed3d::pipeline::{Frame, ScreenVertex};
    use fixed3d::projection::{Projection, Viewport};
    use fixed3d::scene::{LightColor, Lighting, Scene};
    use fixed3d::shade::Unlit;
    for name in ["teapot.obj", "suzanne.obj", "spot.obj", "beetle.obj"] {
        let r = parse_with(&model(name), 8000).unwrap();
        for (w, h) in [(320, 240), (128, 128), (100, 300)] {
            let viewport = Viewport::new(w, h).unwrap();
            let b = r.counts.bounds;
            let f = Framing::of_box(
                b.min,
                b.max,
                Vec3::from_int(1, 1, 2),
                Angle::from_degrees(60),
                viewport.aspect(),
            )
            .unwrap();
            let proj =
                Projection::perspective(Angle::from_degrees(60), viewport.aspect(), f.near, f.far)
                    .unwrap();
            let mesh = Mesh::new(&r.positions, &r.triangles).unwrap();
            let objects = [Object::new(&mesh, Mat4::IDENTITY, Rgb888::new(1, 1, 1))];
            let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
            let mut cache = vec![ScreenVertex::DEFAULT; r.positions.len()];
            let prepared = Frame::new(&f.look_at.view().unwrap(), &proj, viewport)
                .prepare(&scene, &mut cache, Unlit)
                .unwrap();
            for v in prepared.vertices() {
                assert!(v.is_inside(), "{name}");
                let p = v.point();
                assert!(
                    p.x >= 0 && p.y >= 0 && p.x < w as i32 * 16 && p.y < h as i32 * 16,
                    "{name} {w}x{h}: {p:?}"
                );
            }
        }
    }
}

/// Parses through an ObjStream in chunks of the given sizes (cycled).
fn parse_stream<const N: usize>(
    text: &[u8],
    chunks: &[usize],
    cap: usize,
) -> Result<Parsed, ObjError> {
    use fixed3d::obj::ObjStream;
    let mut store = Store::new(cap);
    let counts = {
        let mut b = store.buffers();
        let mut stream = ObjStream::<N>::new(Placement::AsIs);
        let mut rest = text;
        let mut k = 0;
        while !rest.is_empty() {
            let n = chunks[k % chunks.len()].clamp(1, rest.len());
            let (head, tail) = rest.split_at(n);
            stream.push(head, &mut b)?;
            rest = tail;
            k += 1;
        }
        stream.finish(&mut b)?
    };
    Ok(store.parsed(counts))
}

fn same_result(a: &Result<Parsed, ObjError>, b: &Result<Parsed, ObjError>) -> bool {
    match (a, b) {
        (Ok(x), Ok(y)) => {
            x.counts == y.counts
                && x.positions == y.positions
                && x.normals == y.normals
                && x.texcoords == y.texcoords
                && x.triangles == y.triangles
                && x.tri_normals == y.tri_normals
                && x.tri_texcoords == y.tri_texcoords
        }
        (Err(x), Err(y)) => x == y,
        _ => false,
    }
}

#[test]
fn stream_in_blocks_equals_whole_file() {
    for name in ["teapot.obj", "suzanne.obj", "spot.obj", "beetle.obj"] {
        let bytes = model(name);
        let whole = parse_with(&bytes, 8000);
        for chunks in [&[512usize][..], &[1], &[7, 1, 300, 2]] {
            assert!(
                same_result(&whole, &parse_stream::<128>(&bytes, chunks, 8000)),
                "{name} {chunks:?}"
            );
        }
    }
    // Line ends split across chunks, a BOM split too, errors with the same line numbers.
    for text in [
        "\u{feff}v 1 2 3\r\nv 4 5 6\rv 7 8 9\r\n\r\nf 1 2 3",
        "v 1 2 3\r\nv 4 5\r\nv 7 8 9\n",
        "v 1 2 3\n\n\nf 1 1 1\nf 1 2 3\n",
    ] {
        let whole = p(text);
        for chunks in [&[1usize][..], &[2], &[3, 1]] {
            assert!(
                same_result(&whole, &parse_stream::<64>(text.as_bytes(), chunks, 64)),
                "{text:?}"
            );
        }
    }
}

/// O24 for the streaming parser: a line longer than its buffer is an error naming the line.
#[test]
fn o24_stream_line_too_long() {
    let text = format!("v 1 2 3\nv 1 2 3{}\nv 0 0 0\n", " ".repeat(200));
    let e = parse_stream::<32>(text.as_bytes(), &[16], 8).unwrap_err();
    assert_eq!(
        (e.line, e.column, e.kind),
        (2, 33, ObjErrorKind::LineTooLong)
    );
    let e = parse_stream::<32>(&text.as_bytes()[..100], &[1000], 8).unwrap_err();
    assert_eq!((e.line, e.kind), (2, ObjErrorKind::LineTooLong));
    assert!(parse_stream::<256>(text.as_bytes(), &[16], 8).is_ok());
}

/// O24: the error comes with the byte that overflows the buffer, not at the line's end: a
/// file without line breaks (a sparse or corrupt one, say) is not read to its end.
#[test]
fn o24_stream_fails_on_the_overflowing_byte() {
    let (mut p, mut t) = ([Vec3::ZERO; 4], [[0u16; 3]; 4]);
    let mut out = ObjBuffers::new(&mut p, &mut t);
    let mut stream = ObjStream::<32>::new(Placement::AsIs);
    assert!(stream.push(b"v 1 2 3\n", &mut out).is_ok());
    assert!(stream.push(&[0; 32], &mut out).is_ok());
    let e = stream.push(&[0], &mut out).unwrap_err();
    assert_eq!(
        (e.line, e.column, e.kind),
        (2, 33, ObjErrorKind::LineTooLong)
    );
    assert_eq!(stream.counts().positions, 1);
    assert_eq!(stream.push(b"\n", &mut out), Err(e));
    assert_eq!(stream.finish(&mut out), Err(e));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Any text, any chunking: the stream gives exactly what the whole-file parser gives (as
    /// long as every line fits its buffer).
    #[test]
    fn stream_equals_parse_for_any_chunking(tokens in prop::collection::vec(prop::sample::select(vec![
        "v", "vt", "vn", "f", "o", " ", "\n", "\r", "\r\n", "#", "/", "//", "-", ".", "0", "1", "2", "3", "-1", "\u{feff}",
    ]), 0..150), chunks in prop::collection::vec(1usize..20, 1..6), cap in 0usize..10) {
        let text: String = tokens.concat();
        let whole = parse_with(text.as_bytes(), cap);
        let streamed = parse_stream::<1024>(text.as_bytes(), &chunks, cap);
        prop_assert!(same_result(&whole, &streamed), "{:?}\n{:?}\n{:?}", text, whole, streamed);
    }
}

/// `split_corners` gives each distinct (position, UV) its own vertex: corners that agree share
/// one (two UV indices of equal values count as one UV), a corner without `vt` takes (0, 0),
/// and short storage or a bad index is an error, never a write past a slice.
#[test]
fn split_corners_shares_what_agrees_and_splits_seams() {
    let s = Scalar::from_num;
    let p = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    let uv = [
        [s(0), s(0)],
        [s(1), s(0)],
        [s(0), s(1)],
        [s(0), s(0)],
        [s(1), s(1)],
    ];
    // Triangle 0 and 1 share positions 0 and 2; position 0's UVs agree (indices 0 and 3 hold
    // equal values), position 2's differ (a seam). Triangle 2 has no texture coordinates.
    let tris = [[0, 1, 2], [0, 2, 3], [1, 3, 0]];
    let tri_uv = [[0, 1, 2], [3, 4, 2], [NO_INDEX; 3]];
    let split_these = |tris: &[[u16; 3]], cap: usize, first: usize, t: usize| {
        let (mut sp, mut su, mut st) = (
            vec![Vec3::ZERO; cap],
            vec![[Scalar::ZERO; 2]; cap],
            vec![[9u16; 3]; t],
        );
        let (mut f, mut n) = (vec![0u16; first], vec![0u16; cap]);
        let mut out = SplitBuffers {
            positions: &mut sp,
            uvs: &mut su,
            triangles: &mut st,
            first: &mut f,
            next: &mut n,
        };
        split_corners(&p, tris, &uv, &tri_uv, &mut out).map(|k| (k, sp, su, st))
    };
    let split = |cap: usize, first: usize, t: usize| split_these(&tris, cap, first, t);
    let (k, sp, su, st) = split(9, 4, 3).unwrap();
    assert_eq!(k, 7);
    assert_eq!(st, vec![[0, 1, 2], [0, 3, 4], [5, 6, 0]]);
    assert_eq!(&sp[..k], &[p[0], p[1], p[2], p[2], p[3], p[1], p[3]]);
    let zero = [Scalar::ZERO; 2];
    assert_eq!(&su[..k], &[uv[0], uv[1], uv[2], uv[4], uv[2], zero, zero]);
    let kind = |r: Result<_, ObjError>| r.map(|_| ()).unwrap_err().kind;
    let positions = ObjErrorKind::CapacityExceeded(Storage::Positions);
    assert_eq!(kind(split(5, 4, 3)), positions);
    assert_eq!(kind(split(9, 3, 3)), positions);
    assert_eq!(
        kind(split(9, 4, 2)),
        ObjErrorKind::CapacityExceeded(Storage::Triangles)
    );
    let bad = split_these(&[[0, 1, 9]], 3, 4, 1);
    assert_eq!(kind(bad), ObjErrorKind::IndexOutOfRange);
}

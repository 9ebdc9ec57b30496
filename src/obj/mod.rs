//! Wavefront OBJ without an allocator: a streaming parser over a byte slice (in flash, in RAM,
//! read from an SD card) that writes into caller-supplied storage and names the line and column
//! of anything wrong with the file.
//!
//! Grammar: `v x y z [w]` (and the `v x y z r g b` colour extension, colours ignored), `vt u [v
//! [w]]`, `vn i j k`, `f` with corners `v`, `v/vt`, `v/vt/vn` or `v//vn`, 1-based or negative
//! (relative) indices that may refer only to elements already read, polygons of any size
//! fan-triangulated `(0, 1, 2), (0, 2, 3), …`, `#` comments anywhere, LF, CRLF or lone CR line
//! ends, tabs, a missing final newline and a leading byte-order mark. Other statements (`o`,
//! `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, …) are skipped and counted.
//!
//! Numbers go straight from decimal to fixed point, correctly rounded (ties to even): no float
//! is involved, so `inf`, `nan` and out-of-range values are errors, never wrapped coordinates.
//! Memory is the caller's storage and nothing else; time is linear in the file's size.
//!
//! Three ways in, one grammar:
//! - [`parse`] reads a whole file from a byte slice;
//! - [`ObjStream`] takes the file in pieces of any size (blocks from an SD card, packets from a
//!   UART) and holds only one line of a size you choose;
//! - [`StaticObj`] parses a model from `include_bytes!` at compile time (the parser is a
//!   `const fn`) into arrays that live in flash, so a firmware pays nothing at run time.

mod number;
mod split;
mod statement;
mod static_obj;
mod stream;

use core::fmt;

use crate::math::{Scalar, Vec3};
use crate::mesh::Triangle;

pub use split::{split_corners, SplitBuffers};
pub use static_obj::StaticObj;
pub use stream::ObjStream;

/// What was wrong with a file, where.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ObjError {
    /// 1-based line number.
    pub line: u32,
    /// 1-based byte column of the offending token (the line's end for a missing one).
    pub column: u32,
    /// What is wrong.
    pub kind: ObjErrorKind,
}

/// Which storage ran out.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Storage {
    /// Vertex positions.
    Positions,
    /// Texture coordinates.
    TexCoords,
    /// Normals.
    Normals,
    /// Triangles (or their texture-coordinate or normal indices).
    Triangles,
}

/// The kinds of [`ObjError`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ObjErrorKind {
    /// A statement has too few numbers (`v 1 2`, `vn 0 1`, `vt`).
    MissingField,
    /// A statement has more fields than its forms allow (`v 1 2 3 4 5`, `f 1/2/3/4`).
    ExtraField,
    /// `v x y z 0`: a homogeneous weight of zero.
    ScaleByZero,
    /// Not a decimal number or index.
    NumberInvalid,
    /// `inf` or `nan`.
    NumberNotFinite,
    /// A number outside the fixed-point range (±32768 as parsed, or after rescaling), or an
    /// index too large to mean anything.
    NumberOutOfRange,
    /// Index 0 (OBJ indices start at 1).
    IndexZero,
    /// An index to an element not (yet) read.
    IndexOutOfRange,
    /// A face with fewer than three corners.
    FaceTooFewVertices,
    /// The caller's storage is full.
    CapacityExceeded(Storage),
    /// More than 65,536 positions (meshes use 16-bit indices).
    TooManyVertices,
    /// A NUL byte or invalid UTF-8.
    Encoding,
    /// A line longer than an [`ObjStream`]'s line buffer.
    LineTooLong,
}

impl ObjCounts {
    /// Nothing read yet.
    pub const EMPTY: ObjCounts = ObjCounts {
        positions: 0,
        texcoords: 0,
        normals: 0,
        triangles: 0,
        faces: 0,
        skipped: 0,
        lines: 0,
        bounds: Aabb {
            min: Vec3::ZERO,
            max: Vec3::ZERO,
        },
    };
}

impl fmt::Display for ObjError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}: ", self.line, self.column)?;
        match self.kind {
            ObjErrorKind::MissingField => f.write_str("too few fields"),
            ObjErrorKind::ExtraField => f.write_str("too many fields"),
            ObjErrorKind::ScaleByZero => f.write_str("vertex weight w is zero"),
            ObjErrorKind::NumberInvalid => f.write_str("not a number"),
            ObjErrorKind::NumberNotFinite => f.write_str("inf and nan are not coordinates"),
            ObjErrorKind::NumberOutOfRange => f.write_str("number out of range"),
            ObjErrorKind::IndexZero => f.write_str("index 0 (OBJ indices start at 1)"),
            ObjErrorKind::IndexOutOfRange => {
                f.write_str("index refers to an element not defined before it")
            }
            ObjErrorKind::FaceTooFewVertices => f.write_str("a face needs at least 3 vertices"),
            ObjErrorKind::CapacityExceeded(s) => write!(f, "no room for more {s:?}"),
            ObjErrorKind::TooManyVertices => f.write_str("more than 65536 vertices"),
            ObjErrorKind::Encoding => f.write_str("NUL byte or invalid UTF-8"),
            ObjErrorKind::LineTooLong => f.write_str("line longer than the line buffer"),
        }
    }
}

impl core::error::Error for ObjError {}

/// The index stored for a corner that has no texture coordinate or normal.
pub const NO_INDEX: u16 = u16::MAX;

/// Caller-supplied storage for a parse. `positions` and `triangles` are required; any other
/// slice may be empty, which means "count but do not keep" (its elements are still checked).
#[derive(Debug)]
pub struct ObjBuffers<'a> {
    /// Vertex positions (`v`).
    pub positions: &'a mut [Vec3],
    /// Texture coordinates (`vt`), `[u, v]`.
    pub texcoords: &'a mut [[Scalar; 2]],
    /// Normals (`vn`), as written (not normalised).
    pub normals: &'a mut [Vec3],
    /// Triangles: position indices.
    pub triangles: &'a mut [Triangle],
    /// Per triangle, the texture-coordinate index of each corner ([`NO_INDEX`] if none).
    pub triangle_texcoords: &'a mut [Triangle],
    /// Per triangle, the normal index of each corner ([`NO_INDEX`] if none).
    pub triangle_normals: &'a mut [Triangle],
}

impl<'a> ObjBuffers<'a> {
    /// Storage for positions and triangles only.
    pub fn new(positions: &'a mut [Vec3], triangles: &'a mut [Triangle]) -> Self {
        ObjBuffers {
            positions,
            texcoords: &mut [],
            normals: &mut [],
            triangles,
            triangle_texcoords: &mut [],
            triangle_normals: &mut [],
        }
    }
}

/// A box aligned with the axes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Aabb {
    /// The smallest coordinate on each axis.
    pub min: Vec3,
    /// The largest coordinate on each axis.
    pub max: Vec3,
}

/// What a parse read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ObjCounts {
    /// Positions read (`v`).
    pub positions: usize,
    /// Texture coordinates read (`vt`).
    pub texcoords: usize,
    /// Normals read (`vn`).
    pub normals: usize,
    /// Triangles after fan triangulation.
    pub triangles: usize,
    /// Faces (`f`) read.
    pub faces: usize,
    /// Statements skipped (unknown or unsupported keywords).
    pub skipped: usize,
    /// Lines in the file.
    pub lines: u32,
    /// The bounding box of the positions as stored (after any [`Placement`]).
    pub bounds: Aabb,
}

/// Where the file's coordinates go.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Placement {
    /// As written; each coordinate must lie within the Q16.16 range (±32768).
    #[default]
    AsIs,
    /// `(p − centre) · scale`, computed before narrowing to Q16.16, so a model in micrometres
    /// or a survey in metres loads all the same. Build it with [`Placement::fit`].
    Transformed {
        /// Subtracted first (Q32.16, raw).
        centre: [i64; 3],
        /// Then multiplied by `scale / 2^shift`.
        scale: u64,
        /// See `scale`.
        shift: u32,
    },
}

/// The bounding box of a file's positions as written, in Q32.16 (±2³¹), from [`bounds`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct WideBounds {
    /// The smallest coordinate on each axis (raw Q32.16).
    pub min: [i64; 3],
    /// The largest coordinate on each axis (raw Q32.16).
    pub max: [i64; 3],
}

impl Placement {
    /// Centres the box on the origin and scales it uniformly so that its largest half-extent
    /// becomes `half_size`. The resolution in the file's own units is then
    /// `2⁻¹⁶ / scale`: see [`Placement::resolution`].
    ///
    /// ```
    /// use fixed3d::math::Scalar;
    /// use fixed3d::obj::{bounds, parse, ObjBuffers, Placement};
    /// use fixed3d::math::Vec3;
    /// // Millimetres far beyond the Q16.16 range.
    /// let file = b"v 100000 0 0\nv 300000 0 0\nv 200000 50000 0\nf 1 2 3\n";
    /// let b = bounds(file).unwrap();
    /// let fit = Placement::fit(&b, Scalar::ONE);
    /// let (mut p, mut t) = ([Vec3::ZERO; 3], [[0u16; 3]; 1]);
    /// let counts = parse(file, &mut ObjBuffers::new(&mut p, &mut t), fit).unwrap();
    /// // Centred on the box (x 100000..300000, y 0..50000), the longest half-extent becomes 1.
    /// assert_eq!(p[0], Vec3::new(-Scalar::ONE, Scalar::from_num(-0.25), Scalar::ZERO));
    /// assert_eq!(counts.bounds.max.x, Scalar::ONE);
    /// ```
    #[must_use]
    pub fn fit(b: &WideBounds, half_size: Scalar) -> Placement {
        let mut centre = [0i64; 3];
        let mut half = 0i64;
        for (k, c) in centre.iter_mut().enumerate() {
            let (lo, hi) = (
                b.min.get(k).copied().unwrap_or(0),
                b.max.get(k).copied().unwrap_or(0),
            );
            *c = lo + (hi - lo) / 2;
            half = half.max((hi - lo) / 2);
        }
        let target = half_size.to_bits().max(0) as u128;
        if half <= 0 {
            return Placement::Transformed {
                centre,
                scale: 1,
                shift: 0,
            };
        }
        // The largest shift that keeps the factor below 2⁶³: about 62 significant bits.
        let half = half as u128;
        let mut shift = 96u32;
        while shift > 0 && ((target << shift) + half / 2) / half >= 1u128 << 63 {
            shift -= 1;
        }
        let scale = ((target << shift) + half / 2) / half;
        Placement::Transformed {
            centre,
            scale: scale as u64,
            shift,
        }
    }

    /// The size of one Q16.16 step in the file's own units (what the placement can resolve).
    #[must_use]
    pub fn resolution(&self) -> f64 {
        match self {
            Placement::AsIs => 1.0 / 65536.0,
            Placement::Transformed { scale, shift, .. } => {
                let mut factor = *scale as f64;
                for _ in 0..*shift {
                    factor /= 2.0;
                }
                1.0 / (factor * 65536.0)
            }
        }
    }
}

/// Parses `bytes` into `out`: see the [module documentation](self). On error nothing is
/// written past any slice's end; what was written before the error is left in place.
///
/// ```
/// use fixed3d::math::Vec3;
/// use fixed3d::obj::{parse, ObjBuffers, ObjErrorKind, Placement};
/// let file = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
/// let (mut p, mut t) = ([Vec3::ZERO; 4], [[0u16; 3]; 2]);
/// let counts = parse(file, &mut ObjBuffers::new(&mut p, &mut t), Placement::AsIs).unwrap();
/// assert_eq!((counts.positions, counts.triangles), (4, 2));
/// assert_eq!(t, [[0, 1, 2], [0, 2, 3]]);
///
/// let bad = b"v 0 0 0\nv 1 0 0\nf 1 2 3\n";
/// let e = parse(bad, &mut ObjBuffers::new(&mut p, &mut t), Placement::AsIs).unwrap_err();
/// assert_eq!((e.line, e.column, e.kind), (3, 7, ObjErrorKind::IndexOutOfRange));
/// ```
pub const fn parse(
    bytes: &[u8],
    out: &mut ObjBuffers<'_>,
    placement: Placement,
) -> Result<ObjCounts, ObjError> {
    let mut c = ObjCounts::EMPTY;
    let mut i = statement::skip_bom(bytes);
    while i < bytes.len() {
        let (end, next) = statement::next_line(bytes, i);
        if let Err(e) =
            statement::parse_line(statement::sub(bytes, i, end), &mut c, out, &placement)
        {
            return Err(e);
        }
        i = next;
    }
    Ok(c)
}

/// The bounding box of a file's positions as written (Q32.16, so coordinates up to ±2³¹ are
/// accepted), for [`Placement::fit`]. Reads only `v` statements; the file is fully checked by
/// [`parse`] afterwards.
pub const fn bounds(bytes: &[u8]) -> Result<WideBounds, ObjError> {
    let mut b = WideBounds {
        min: [0; 3],
        max: [0; 3],
    };
    let mut first = true;
    let mut i = statement::skip_bom(bytes);
    let mut line_no = 0u32;
    while i < bytes.len() {
        let (end, next) = statement::next_line(bytes, i);
        let raw_line = statement::sub(bytes, i, end);
        i = next;
        line_no = line_no.saturating_add(1);
        let mut end = 0;
        while end < raw_line.len() && raw_line[end] != b'#' {
            end += 1;
        }
        let line = statement::sub(raw_line, 0, end);
        let Some((ka, kb)) = statement::next_token(line, 0) else {
            continue;
        };
        if !statement::same(statement::sub(line, ka, kb), b"v") {
            continue;
        }
        let (xyz, _) = match statement::vertex(line, kb, true, line_no) {
            Ok(v) => v,
            Err(e) => return Err(e),
        };
        let mut k = 0;
        while k < 3 {
            if first || xyz[k] < b.min[k] {
                b.min[k] = xyz[k];
            }
            if first || xyz[k] > b.max[k] {
                b.max[k] = xyz[k];
            }
            k += 1;
        }
        first = false;
    }
    Ok(b)
}

/// Per-vertex normals from an OBJ file's corner normals (`f v//vn`): each position gets the
/// average direction of the normals its corners name (each normalised first; zero normals and
/// corners without one are ignored), unit length. Positions no corner gives a normal get zero
/// (ambient light only); fill those with [`vertex_normals`](crate::mesh::vertex_normals) if
/// needed. `out` needs one entry per position.
///
/// ```
/// use fixed3d::math::Vec3;
/// use fixed3d::obj::{corner_normals_to_vertices, parse, ObjBuffers, Placement};
/// let file = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n";
/// let (mut p, mut n, mut t, mut tn) = ([Vec3::ZERO; 3], [Vec3::ZERO; 1], [[0u16; 3]; 1], [[0u16; 3]; 1]);
/// let mut b = ObjBuffers::new(&mut p, &mut t);
/// b.normals = &mut n;
/// b.triangle_normals = &mut tn;
/// parse(file, &mut b, Placement::AsIs).unwrap();
/// let mut per_vertex = [Vec3::ZERO; 3];
/// corner_normals_to_vertices(&t, &tn, &n, &mut per_vertex);
/// assert_eq!(per_vertex, [Vec3::Z; 3]);
/// ```
pub fn corner_normals_to_vertices(
    triangles: &[Triangle],
    triangle_normals: &[Triangle],
    normals: &[Vec3],
    out: &mut [Vec3],
) {
    out.fill(Vec3::ZERO);
    for (t, tn) in triangles.iter().zip(triangle_normals) {
        for (&v, &n) in t.iter().zip(tn) {
            let (Some(o), Some(dir)) = (out.get_mut(v as usize), normals.get(n as usize)) else {
                continue;
            };
            let Some(u) = dir.normalized() else { continue };
            let (a, b) = (o.to_bits(), u.to_bits());
            let s = |k: usize| {
                let x =
                    a.get(k).copied().unwrap_or(0) as i64 + b.get(k).copied().unwrap_or(0) as i64;
                x.clamp(i32::MIN as i64, i32::MAX as i64) as i32
            };
            *o = Vec3::from_bits(s(0), s(1), s(2));
        }
    }
    for o in out.iter_mut() {
        *o = o.normalized().unwrap_or(Vec3::ZERO);
    }
}

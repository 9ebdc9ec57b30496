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
//! The parser is a `const fn`: [`StaticObj`] parses a model from `include_bytes!` at compile
//! time into arrays that live in flash, so a firmware pays nothing at run time.

mod number;

use core::fmt;

use number::{parse_index, parse_q16, parse_wide, NumberError};

use crate::math::{Scalar, Vec3};
use crate::mesh::{Mesh, Triangle};

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

/// Byte range `[a, b)` of `s` (const-friendly slicing; `a ≤ b ≤ s.len()`).
const fn sub(s: &[u8], a: usize, b: usize) -> &[u8] {
    let (head, _) = s.split_at(b);
    let (_, tail) = head.split_at(a);
    tail
}

const fn same(a: &[u8], b: &[u8]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

const fn is_space(b: u8) -> bool {
    b == b' ' || b == b'\t' || b == 0x0b || b == 0x0c
}

/// The next token of `line` from `pos`: `(start, end)`, or `None` at the end.
const fn next_token(line: &[u8], pos: usize) -> Option<(usize, usize)> {
    let mut i = pos;
    while i < line.len() && is_space(line[i]) {
        i += 1;
    }
    if i >= line.len() {
        return None;
    }
    let start = i;
    while i < line.len() && !is_space(line[i]) {
        i += 1;
    }
    Some((start, i))
}

/// Where parsing starts: after a UTF-8 byte-order mark, if there is one.
const fn skip_bom(bytes: &[u8]) -> usize {
    if bytes.len() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF {
        3
    } else {
        0
    }
}

/// The line starting at `i`: its end (exclusive, without the line break) and where the next
/// line starts. LF, CRLF and a lone CR each end a line.
const fn next_line(bytes: &[u8], i: usize) -> (usize, usize) {
    let len = bytes.len();
    let mut end = i;
    while end < len && bytes[end] != b'\n' && bytes[end] != b'\r' {
        end += 1;
    }
    let next = if end + 1 < len && bytes[end] == b'\r' && bytes[end + 1] == b'\n' {
        end + 2
    } else if end < len {
        end + 1
    } else {
        end
    };
    (end, next)
}

const fn err(line: u32, column: usize, kind: ObjErrorKind) -> ObjError {
    ObjError {
        line,
        column: if column >= u32::MAX as usize {
            u32::MAX
        } else {
            column as u32 + 1
        },
        kind,
    }
}

const fn number_error(e: NumberError) -> ObjErrorKind {
    match e {
        NumberError::Invalid => ObjErrorKind::NumberInvalid,
        NumberError::NotFinite => ObjErrorKind::NumberNotFinite,
        NumberError::OutOfRange => ObjErrorKind::NumberOutOfRange,
    }
}

/// Up to `N` tokens after the keyword: their byte ranges and how many there were (more than
/// `N` is reported as `N + 1`).
const fn tokens<const N: usize>(line: &[u8], from: usize) -> ([(usize, usize); N], usize) {
    let mut out = [(0usize, 0usize); N];
    let mut n = 0;
    let mut pos = from;
    while let Some((a, b)) = next_token(line, pos) {
        if n == N {
            return (out, N + 1);
        }
        out[n] = (a, b);
        n += 1;
        pos = b;
    }
    (out, n)
}

/// Parses the coordinate tokens `t[0..n]` as wide (Q32.16) or Q16.16 values.
const fn coords<const N: usize>(
    line: &[u8],
    t: &[(usize, usize); N],
    n: usize,
    wide: bool,
    line_no: u32,
) -> Result<[i64; N], ObjError> {
    let mut out = [0i64; N];
    let mut k = 0;
    while k < n && k < N {
        let (a, b) = t[k];
        let tok = sub(line, a, b);
        let v = if wide {
            parse_wide(tok)
        } else {
            match parse_q16(tok) {
                Ok(v) => Ok(v as i64),
                Err(e) => Err(e),
            }
        };
        match v {
            Ok(v) => out[k] = v,
            Err(e) => return Err(err(line_no, a, number_error(e))),
        }
        k += 1;
    }
    Ok(out)
}

/// One corner of a face: resolved 0-based indices (`NO_INDEX` when absent).
#[derive(Clone, Copy)]
struct Corner {
    v: u16,
    t: u16,
    n: u16,
}

/// Resolves a 1-based or negative OBJ index against the `count` elements read so far.
const fn resolve(tok: &[u8], count: usize, line_no: u32, column: usize) -> Result<u16, ObjError> {
    let idx = match parse_index(tok) {
        Ok(i) => i,
        Err(e) => return Err(err(line_no, column, number_error(e))),
    };
    if idx == 0 {
        return Err(err(line_no, column, ObjErrorKind::IndexZero));
    }
    let resolved = if idx > 0 { idx - 1 } else { count as i64 + idx };
    if resolved < 0 || resolved >= count as i64 {
        return Err(err(line_no, column, ObjErrorKind::IndexOutOfRange));
    }
    Ok(resolved as u16)
}

/// Parses `v`, `v/t`, `v/t/n` or `v//n` (a trailing `/` leaves its field empty, i.e. absent).
const fn corner(
    line: &[u8],
    a: usize,
    b: usize,
    c: &ObjCounts,
    line_no: u32,
) -> Result<Corner, ObjError> {
    let tok = sub(line, a, b);
    let mut fields = [(0usize, 0usize); 3];
    let mut nf = 0;
    let mut start = 0;
    let mut i = 0;
    while i <= tok.len() {
        if i == tok.len() || tok[i] == b'/' {
            if nf == 3 {
                return Err(err(line_no, a + i, ObjErrorKind::ExtraField));
            }
            fields[nf] = (start, i);
            nf += 1;
            start = i + 1;
        }
        i += 1;
    }
    let (v0, v1) = fields[0];
    if v0 == v1 {
        return Err(err(line_no, a, ObjErrorKind::NumberInvalid));
    }
    let v = match resolve(sub(tok, v0, v1), c.positions, line_no, a + v0) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let mut t = NO_INDEX;
    if nf > 1 && fields[1].0 != fields[1].1 {
        t = match resolve(
            sub(tok, fields[1].0, fields[1].1),
            c.texcoords,
            line_no,
            a + fields[1].0,
        ) {
            Ok(t) => t,
            Err(e) => return Err(e),
        };
    }
    let mut n = NO_INDEX;
    if nf > 2 && fields[2].0 != fields[2].1 {
        n = match resolve(
            sub(tok, fields[2].0, fields[2].1),
            c.normals,
            line_no,
            a + fields[2].0,
        ) {
            Ok(n) => n,
            Err(e) => return Err(e),
        };
    }
    Ok(Corner { v, t, n })
}

const fn place(
    v: [i64; 3],
    placement: &Placement,
    line_no: u32,
    column: usize,
) -> Result<Vec3, ObjError> {
    let mut out = [0i32; 3];
    let mut k = 0;
    while k < 3 {
        let raw = match placement {
            Placement::AsIs => v[k],
            Placement::Transformed {
                centre,
                scale,
                shift,
            } => {
                // (p − centre) · scale / 2^shift, rounded to nearest: below 2⁴⁸ · 2⁶³.
                let d = (v[k] - centre[k]) as i128 * *scale as i128;
                let half = if *shift == 0 {
                    0
                } else {
                    1i128 << (*shift - 1)
                };
                let r = if d >= 0 {
                    (d + half) >> *shift
                } else {
                    -((-d + half) >> *shift)
                };
                if r > i64::MAX as i128 || r < i64::MIN as i128 {
                    return Err(err(line_no, column, ObjErrorKind::NumberOutOfRange));
                }
                r as i64
            }
        };
        if raw > i32::MAX as i64 || raw < i32::MIN as i64 {
            return Err(err(line_no, column, ObjErrorKind::NumberOutOfRange));
        }
        out[k] = raw as i32;
        k += 1;
    }
    Ok(Vec3::from_bits(out[0], out[1], out[2]))
}

const fn grow(b: &mut Aabb, p: Vec3, first: bool) {
    if first {
        b.min = p;
        b.max = p;
        return;
    }
    let (pb, mut lo, mut hi) = (p.to_bits(), b.min.to_bits(), b.max.to_bits());
    let mut k = 0;
    while k < 3 {
        if pb[k] < lo[k] {
            lo[k] = pb[k];
        }
        if pb[k] > hi[k] {
            hi[k] = pb[k];
        }
        k += 1;
    }
    b.min = Vec3::from_bits(lo[0], lo[1], lo[2]);
    b.max = Vec3::from_bits(hi[0], hi[1], hi[2]);
}

/// `v x y z [w | r g b]` → the (wide or narrow) coordinates divided by w.
const fn vertex(
    line: &[u8],
    from: usize,
    wide: bool,
    line_no: u32,
) -> Result<([i64; 3], usize), ObjError> {
    let (t, n) = tokens::<7>(line, from);
    if n < 3 {
        return Err(err(line_no, line.len(), ObjErrorKind::MissingField));
    }
    if n == 5 || n > 6 {
        let at = if n > 6 { line.len() } else { t[4].0 };
        return Err(err(line_no, at, ObjErrorKind::ExtraField));
    }
    let v = match coords::<7>(line, &t, n, wide, line_no) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let mut xyz = [v[0], v[1], v[2]];
    if n == 4 {
        let w = v[3];
        if w == 0 {
            return Err(err(line_no, t[3].0, ObjErrorKind::ScaleByZero));
        }
        let mut k = 0;
        while k < 3 {
            // (x / w) in the same fixed format, checked.
            let q = ((xyz[k] as i128) << 16) / w as i128;
            if q > i64::MAX as i128 / 2 || q < i64::MIN as i128 / 2 {
                return Err(err(line_no, t[3].0, ObjErrorKind::NumberOutOfRange));
            }
            xyz[k] = q as i64;
            k += 1;
        }
    }
    Ok((xyz, t[0].0))
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
    let wide = !matches!(placement, Placement::AsIs);
    let mut c = ObjCounts {
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
    let mut i = skip_bom(bytes);
    while i < bytes.len() {
        let (end, next) = next_line(bytes, i);
        let raw_line = sub(bytes, i, end);
        i = next;
        c.lines = c.lines.saturating_add(1);
        let line_no = c.lines;
        if core::str::from_utf8(raw_line).is_err() {
            return Err(err(line_no, 0, ObjErrorKind::Encoding));
        }
        // Strip a comment; reject NUL.
        let mut end = 0;
        while end < raw_line.len() && raw_line[end] != b'#' {
            if raw_line[end] == 0 {
                return Err(err(line_no, end, ObjErrorKind::Encoding));
            }
            end += 1;
        }
        let mut k = end;
        while k < raw_line.len() {
            if raw_line[k] == 0 {
                return Err(err(line_no, k, ObjErrorKind::Encoding));
            }
            k += 1;
        }
        let line = sub(raw_line, 0, end);
        let Some((ka, kb)) = next_token(line, 0) else {
            continue;
        };
        let key = sub(line, ka, kb);
        if same(key, b"v") {
            if c.positions >= 65_536 {
                return Err(err(line_no, ka, ObjErrorKind::TooManyVertices));
            }
            let (xyz, col) = match vertex(line, kb, wide, line_no) {
                Ok(v) => v,
                Err(e) => return Err(e),
            };
            let p = match place(xyz, &placement, line_no, col) {
                Ok(p) => p,
                Err(e) => return Err(e),
            };
            if c.positions >= out.positions.len() {
                return Err(err(
                    line_no,
                    ka,
                    ObjErrorKind::CapacityExceeded(Storage::Positions),
                ));
            }
            out.positions[c.positions] = p;
            grow(&mut c.bounds, p, c.positions == 0);
            c.positions += 1;
        } else if same(key, b"vt") {
            let (t, n) = tokens::<3>(line, kb);
            if n == 0 {
                return Err(err(line_no, line.len(), ObjErrorKind::MissingField));
            }
            if n > 3 {
                return Err(err(line_no, line.len(), ObjErrorKind::ExtraField));
            }
            let v = match coords::<3>(line, &t, n, false, line_no) {
                Ok(v) => v,
                Err(e) => return Err(e),
            };
            if !out.texcoords.is_empty() {
                if c.texcoords >= out.texcoords.len() {
                    return Err(err(
                        line_no,
                        ka,
                        ObjErrorKind::CapacityExceeded(Storage::TexCoords),
                    ));
                }
                out.texcoords[c.texcoords] = [
                    Scalar::from_bits(v[0] as i32),
                    Scalar::from_bits(v[1] as i32),
                ];
            }
            c.texcoords += 1;
        } else if same(key, b"vn") {
            let (t, n) = tokens::<3>(line, kb);
            if n < 3 {
                return Err(err(line_no, line.len(), ObjErrorKind::MissingField));
            }
            if n > 3 {
                return Err(err(line_no, line.len(), ObjErrorKind::ExtraField));
            }
            let v = match coords::<3>(line, &t, n, false, line_no) {
                Ok(v) => v,
                Err(e) => return Err(e),
            };
            if !out.normals.is_empty() {
                if c.normals >= out.normals.len() {
                    return Err(err(
                        line_no,
                        ka,
                        ObjErrorKind::CapacityExceeded(Storage::Normals),
                    ));
                }
                out.normals[c.normals] = Vec3::from_bits(v[0] as i32, v[1] as i32, v[2] as i32);
            }
            c.normals += 1;
        } else if same(key, b"f") {
            let mut pos = kb;
            let mut corners = 0usize;
            let mut first = Corner { v: 0, t: 0, n: 0 };
            let mut prev = first;
            while let Some((a, b)) = next_token(line, pos) {
                pos = b;
                let cur = match corner(line, a, b, &c, line_no) {
                    Ok(k) => k,
                    Err(e) => return Err(e),
                };
                if corners == 0 {
                    first = cur;
                } else if corners >= 2 {
                    if c.triangles >= out.triangles.len() {
                        return Err(err(
                            line_no,
                            a,
                            ObjErrorKind::CapacityExceeded(Storage::Triangles),
                        ));
                    }
                    out.triangles[c.triangles] = [first.v, prev.v, cur.v];
                    if !out.triangle_texcoords.is_empty() {
                        if c.triangles >= out.triangle_texcoords.len() {
                            return Err(err(
                                line_no,
                                a,
                                ObjErrorKind::CapacityExceeded(Storage::Triangles),
                            ));
                        }
                        out.triangle_texcoords[c.triangles] = [first.t, prev.t, cur.t];
                    }
                    if !out.triangle_normals.is_empty() {
                        if c.triangles >= out.triangle_normals.len() {
                            return Err(err(
                                line_no,
                                a,
                                ObjErrorKind::CapacityExceeded(Storage::Triangles),
                            ));
                        }
                        out.triangle_normals[c.triangles] = [first.n, prev.n, cur.n];
                    }
                    c.triangles += 1;
                }
                prev = cur;
                corners += 1;
            }
            if corners < 3 {
                return Err(err(line_no, line.len(), ObjErrorKind::FaceTooFewVertices));
            }
            c.faces += 1;
        } else {
            c.skipped += 1;
        }
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
    let mut i = skip_bom(bytes);
    let mut line_no = 0u32;
    while i < bytes.len() {
        let (end, next) = next_line(bytes, i);
        let raw_line = sub(bytes, i, end);
        i = next;
        line_no = line_no.saturating_add(1);
        let mut end = 0;
        while end < raw_line.len() && raw_line[end] != b'#' {
            end += 1;
        }
        let line = sub(raw_line, 0, end);
        let Some((ka, kb)) = next_token(line, 0) else {
            continue;
        };
        if !same(sub(line, ka, kb), b"v") {
            continue;
        }
        let (xyz, _) = match vertex(line, kb, true, line_no) {
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

/// A model parsed at compile time into arrays: `V` positions and `T` triangles at most.
///
/// ```
/// use fixed3d::obj::StaticObj;
/// static QUAD: StaticObj<4, 2> = match StaticObj::parse(b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4") {
///     Ok(m) => m,
///     Err(_) => panic!("bad model"), // a compile error, not a run-time panic
/// };
/// assert_eq!(QUAD.mesh().triangles().len(), 2);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct StaticObj<const V: usize, const T: usize> {
    positions: [Vec3; V],
    triangles: [Triangle; T],
    counts: ObjCounts,
}

impl<const V: usize, const T: usize> StaticObj<V, T> {
    /// Parses `bytes` (with [`Placement::AsIs`]); usable in a `static` initialiser.
    pub const fn parse(bytes: &[u8]) -> Result<Self, ObjError> {
        let mut positions = [Vec3::ZERO; V];
        let mut triangles = [[0u16; 3]; T];
        let counts = {
            let mut buffers = ObjBuffers {
                positions: &mut positions,
                texcoords: &mut [],
                normals: &mut [],
                triangles: &mut triangles,
                triangle_texcoords: &mut [],
                triangle_normals: &mut [],
            };
            match parse(bytes, &mut buffers, Placement::AsIs) {
                Ok(c) => c,
                Err(e) => return Err(e),
            }
        };
        Ok(StaticObj {
            positions,
            triangles,
            counts,
        })
    }

    /// What the parse read.
    #[must_use]
    pub const fn counts(&self) -> &ObjCounts {
        &self.counts
    }

    /// The mesh over the parsed arrays (its indices were checked by the parser).
    #[must_use]
    pub const fn mesh(&self) -> Mesh<'_> {
        let (p, _) = self.positions.split_at(self.counts.positions);
        let (t, _) = self.triangles.split_at(self.counts.triangles);
        match Mesh::new(p, t) {
            Ok(m) => m,
            // Unreachable: the parser resolved every index against the positions read.
            Err(_) => match Mesh::new(p, &[]) {
                Ok(m) => m,
                Err(_) => Mesh::EMPTY,
            },
        }
    }
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

//! One line of an OBJ file: tokens, numbers, corners and the statement they make. Everything
//! here is a `const fn`, so files can be parsed at compile time.

use super::number::{parse_index, parse_q16, parse_wide, NumberError};
use super::{Aabb, ObjBuffers, ObjCounts, ObjError, ObjErrorKind, Placement, Storage, NO_INDEX};
use crate::math::{Scalar, Vec3};
use crate::mesh::Triangle;

/// Byte range `[a, b)` of `s` (const-friendly slicing; `a ≤ b ≤ s.len()`).
pub(crate) const fn sub(s: &[u8], a: usize, b: usize) -> &[u8] {
    let (head, _) = s.split_at(b);
    let (_, tail) = head.split_at(a);
    tail
}

pub(crate) const fn same(a: &[u8], b: &[u8]) -> bool {
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
pub(crate) const fn next_token(line: &[u8], pos: usize) -> Option<(usize, usize)> {
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
pub(crate) const fn skip_bom(bytes: &[u8]) -> usize {
    if bytes.len() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF {
        3
    } else {
        0
    }
}

/// The line starting at `i`: its end (exclusive, without the line break) and where the next
/// line starts. LF, CRLF and a lone CR each end a line.
pub(crate) const fn next_line(bytes: &[u8], i: usize) -> (usize, usize) {
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

/// Stores triangle `i` of an index stream; false when the stream is full. An empty optional
/// stream keeps nothing (and is never full).
const fn put(stream: &mut [Triangle], i: usize, t: Triangle, optional: bool) -> bool {
    if optional && stream.is_empty() {
        return true;
    }
    if i >= stream.len() {
        return false;
    }
    stream[i] = t;
    true
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
pub(crate) const fn vertex(
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

/// Parses one line (without its line break) into `out`, updating the counts; the line number is
/// `c.lines + 1`. Shared by [`parse`](super::parse) and [`ObjStream`](super::ObjStream).
pub(crate) const fn parse_line(
    raw_line: &[u8],
    c: &mut ObjCounts,
    out: &mut ObjBuffers<'_>,
    placement: &Placement,
) -> Result<(), ObjError> {
    let wide = !matches!(placement, Placement::AsIs);
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
        return Ok(());
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
        let p = match place(xyz, placement, line_no, col) {
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
            let cur = match corner(line, a, b, c, line_no) {
                Ok(k) => k,
                Err(e) => return Err(e),
            };
            if corners == 0 {
                first = cur;
            } else if corners >= 2 {
                let i = c.triangles;
                let full = err(
                    line_no,
                    a,
                    ObjErrorKind::CapacityExceeded(Storage::Triangles),
                );
                if !put(out.triangles, i, [first.v, prev.v, cur.v], false)
                    || !put(out.triangle_texcoords, i, [first.t, prev.t, cur.t], true)
                    || !put(out.triangle_normals, i, [first.n, prev.n, cur.n], true)
                {
                    return Err(full);
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
    Ok(())
}

//! Splitting a file's vertices where their corners' texture coordinates differ.

use super::{ObjError, ObjErrorKind, Storage, NO_INDEX};
use crate::math::{Scalar, Vec3};
use crate::mesh::{Triangle, Uv};

/// Storage for [`split_corners`]: the split mesh's arrays, and two index arrays it works in.
#[derive(Debug)]
pub struct SplitBuffers<'a> {
    /// The split mesh's positions (one per distinct corner, at most three per triangle).
    pub positions: &'a mut [Vec3],
    /// Its UVs, one per position.
    pub uvs: &'a mut [Uv],
    /// Its triangles (as many as the file's).
    pub triangles: &'a mut [Triangle],
    /// Work space: one per position of the file.
    pub first: &'a mut [u16],
    /// Work space: one per position of the split mesh.
    pub next: &'a mut [u16],
}

/// Gives every distinct (position, texture coordinate) pair of a file's corners its own
/// vertex, as [`Mesh::with_uvs`](crate::mesh::Mesh::with_uvs) needs: a position whose
/// corners carry different UVs (a seam) is split, corners that agree share one. Corners
/// without a texture coordinate take UV (0, 0). Returns the split mesh's vertex count; its
/// triangles are `out.triangles[..triangles.len()]`, and the file's `triangle_normals` go
/// with them ([`corner_normals_to_vertices`](super::corner_normals_to_vertices) gives the
/// new vertices normals). Errors have line and column 0:
/// [`ObjErrorKind::CapacityExceeded`] of [`Storage::Positions`] when `first` holds fewer than
/// the file's positions or the split vertices outgrow `positions`, `uvs` or `next`, of
/// [`Storage::Triangles`] when `out.triangles` is the shorter;
/// [`ObjErrorKind::IndexOutOfRange`] for a corner naming no position;
/// [`ObjErrorKind::TooManyVertices`] when more than 65,535 vertices result.
///
/// ```
/// use fixed3d::math::{Scalar, Vec3};
/// use fixed3d::obj::{parse, split_corners, ObjBuffers, Placement, SplitBuffers};
/// // Two triangles sharing an edge whose UVs differ on each side: 4 positions, 6 vertices.
/// let file = b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n\
///              f 1/1 2/2 3/3\nf 1/5 3/5 4/4\n";
/// let (mut p, mut t, mut vt, mut tt) =
///     ([Vec3::ZERO; 4], [[0u16; 3]; 2], [[Scalar::ZERO; 2]; 5], [[0u16; 3]; 2]);
/// let mut b = ObjBuffers::new(&mut p, &mut t);
/// b.texcoords = &mut vt;
/// b.triangle_texcoords = &mut tt;
/// parse(file, &mut b, Placement::AsIs).unwrap();
/// let (mut sp, mut uv, mut st, mut first, mut next) =
///     ([Vec3::ZERO; 6], [[Scalar::ZERO; 2]; 6], [[0u16; 3]; 2], [0u16; 4], [0u16; 6]);
/// let mut out = SplitBuffers {
///     positions: &mut sp, uvs: &mut uv, triangles: &mut st, first: &mut first, next: &mut next,
/// };
/// let n = split_corners(&p, &t, &vt, &tt, &mut out).unwrap();
/// assert_eq!(n, 6);
/// assert_eq!(st, [[0, 1, 2], [3, 4, 5]]);
/// ```
pub fn split_corners(
    positions: &[Vec3],
    triangles: &[Triangle],
    texcoords: &[Uv],
    triangle_texcoords: &[Triangle],
    out: &mut SplitBuffers<'_>,
) -> Result<usize, ObjError> {
    let fail = |kind| ObjError {
        line: 0,
        column: 0,
        kind,
    };
    let first = out
        .first
        .get_mut(..positions.len())
        .ok_or(fail(ObjErrorKind::CapacityExceeded(Storage::Positions)))?;
    first.fill(NO_INDEX);
    let mut count = 0usize;
    for (k, tri) in triangles.iter().enumerate() {
        let uv_of = triangle_texcoords.get(k).copied().unwrap_or([NO_INDEX; 3]);
        let mut split = [0u16; 3];
        for ((slot, &p), t) in split.iter_mut().zip(tri).zip(uv_of) {
            let uv = texcoords
                .get(t as usize)
                .copied()
                .unwrap_or([Scalar::ZERO; 2]);
            let Some(head) = first.get_mut(p as usize) else {
                return Err(fail(ObjErrorKind::IndexOutOfRange));
            };
            // The vertices of position p so far: is one of them at this UV?
            let mut o = *head;
            while o != NO_INDEX && out.uvs.get(o as usize) != Some(&uv) {
                o = out.next.get(o as usize).copied().unwrap_or(NO_INDEX);
            }
            if o == NO_INDEX {
                if count >= usize::from(NO_INDEX) {
                    return Err(fail(ObjErrorKind::TooManyVertices));
                }
                let (Some(pos), Some(slot_uv), Some(next)) = (
                    out.positions.get_mut(count),
                    out.uvs.get_mut(count),
                    out.next.get_mut(count),
                ) else {
                    return Err(fail(ObjErrorKind::CapacityExceeded(Storage::Positions)));
                };
                *pos = positions.get(p as usize).copied().unwrap_or_default();
                *slot_uv = uv;
                *next = *head;
                o = count as u16;
                *head = o;
                count += 1;
            }
            *slot = o;
        }
        let Some(t) = out.triangles.get_mut(k) else {
            return Err(fail(ObjErrorKind::CapacityExceeded(Storage::Triangles)));
        };
        *t = split;
    }
    Ok(count)
}

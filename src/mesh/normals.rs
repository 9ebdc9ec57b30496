//! Vertex normals for meshes that come without them, and the face normals flat shading keeps.

use super::{MeshError, Triangle};
use crate::math::face_newton_direction;
use crate::math::{normalize, shr_round, NewtonDirection, Vec3};

/// A triangle's face normal as flat shading uses it, kept in a mesh by
/// [`Mesh::with_face_normals`](super::Mesh::with_face_normals): the cross product of its edges
/// scaled so that the largest component has 15 bits, and the reciprocal of its length, 12
/// bytes. A mesh's positions do not change from frame to frame, and neither does this:
/// found once, it spares every frame each drawn face's cross product and square root.
///
/// [`Flat`](crate::shade::Flat) reads it, with the same colours as it finds from the
/// positions. A face turned almost edge-on to every
/// light, where the 15 bits cannot tell whether the face turns to it, is lit from its positions
/// instead (a product of the kept direction and a light within ±2³¹ of zero, where the
/// direction's rounding could move its sign). It is read where flat shading lights a face in
/// model space (the model matrix a rotation times a uniform scale) with
/// [`Normalize::Newton`](crate::math::Normalize) (the default); otherwise faces are lit from
/// their positions.
///
/// ```
/// use fixed3d::mesh::{FaceNormal, MeshError, CUBE};
/// let mut faces = [FaceNormal::ZERO; 12]; // one per triangle: in RAM, 12 bytes each
/// let cube = CUBE.with_face_normals(&mut faces).unwrap();
/// assert_eq!(cube.face_normals().map(<[_]>::len), Some(12));
/// assert_eq!(core::mem::size_of::<FaceNormal>(), 12);
/// // Drawn with `prepare(&scene, &mut cache, Flat)`: the colours the positions give.
/// let mut short = [FaceNormal::ZERO; 11];
/// let refused = CUBE.with_face_normals(&mut short);
/// assert_eq!(refused, Err(MeshError::FaceNormalCountMismatch));
/// assert_eq!(refused.unwrap_err().to_string(), "there must be one face normal per triangle");
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct FaceNormal(pub(crate) NewtonDirection);

impl FaceNormal {
    /// A zero-area triangle's, and a starting value for storage.
    pub const ZERO: FaceNormal = FaceNormal(NewtonDirection::ZERO);

    /// The face normal of triangle `t` of `positions` (raw Q16.16 bounds `extents`: the
    /// mesh's extent and edge extent), found by flat shading's own code
    /// ([`face_newton_direction`]), so that a kept normal and one found every frame cannot
    /// differ.
    pub(crate) fn of(positions: &[Vec3], t: &Triangle, extents: (u32, u32)) -> FaceNormal {
        let p = |i: u16| {
            positions
                .get(i as usize)
                .copied()
                .unwrap_or_default()
                .to_bits()
        };
        let direction = face_newton_direction([p(t[0]), p(t[1]), p(t[2])], extents);
        FaceNormal(direction.unwrap_or(NewtonDirection::ZERO))
    }
}

/// Headroom bits of an accumulated normal: the largest face's cross product is scaled to 2²⁴
/// (256 in Q16.16), so 128 of the largest faces can meet at a vertex before the sum saturates.
const FACE_BITS: u32 = 24;

fn bits(v: u64) -> u32 {
    64 - v.leading_zeros()
}

/// Area-weighted vertex normals (unit length) of `positions` and `triangles`, into `out`
/// (one per position; a vertex used by no triangle of non-zero area gets a zero normal, which
/// shading lights by the ambient term only).
///
/// Every face contributes its cross product (twice its area, in its normal's direction), all
/// at one common scale chosen from the largest edge, in exact integer arithmetic: triangles
/// from 10⁻⁴ to 10³ units across get the same direction accuracy (case T33). Faces more than
/// 2²⁴ times smaller than the largest one contribute nothing.
///
/// ```
/// use fixed3d::math::Vec3;
/// use fixed3d::mesh::{vertex_normals, CUBE};
/// let mut normals = [Vec3::ZERO; 8];
/// vertex_normals(CUBE.positions(), CUBE.triangles(), &mut normals).unwrap();
/// // A cube corner's normal points out along its diagonal.
/// let n = normals[6];
/// assert!(n.x > 0 && n.y > 0 && n.z > 0);
/// assert!((n.length().to_num::<f64>() - 1.0).abs() < 1e-4);
/// ```
pub fn vertex_normals(
    positions: &[Vec3],
    triangles: &[Triangle],
    out: &mut [Vec3],
) -> Result<(), MeshError> {
    let Some(out) = out.get_mut(..positions.len()) else {
        return Err(MeshError::NormalCountMismatch);
    };
    out.fill(Vec3::ZERO);
    let corners = |t: &Triangle| -> Option<[[i64; 3]; 3]> {
        let p = |i: u16| {
            positions
                .get(i as usize)
                .map(|v| v.to_bits().map(i64::from))
        };
        Some([p(t[0])?, p(t[1])?, p(t[2])?])
    };
    // Pass 1: the common scale. Edges shifted below 2³⁰ keep each cross product below 2⁶².
    let mut max_edge = 0u64;
    for t in triangles {
        if let Some([a, b, c]) = corners(t) {
            for k in 0..3 {
                let (e1, e2) = (b[k] - a[k], c[k] - a[k]);
                max_edge = max_edge.max(e1.unsigned_abs()).max(e2.unsigned_abs());
            }
        }
    }
    let edge_shift = bits(max_edge).saturating_sub(30);
    let cross = |t: &Triangle| -> Option<[i64; 3]> {
        let [a, b, c] = corners(t)?;
        let e1 = [0, 1, 2].map(|k| (b[k] - a[k]) >> edge_shift);
        let e2 = [0, 1, 2].map(|k| (c[k] - a[k]) >> edge_shift);
        Some([
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        ])
    };
    // Pass 2: the largest cross component sets the accumulation scale.
    let max_cross = triangles
        .iter()
        .filter_map(cross)
        .flat_map(|n| n.map(|c| c.unsigned_abs()))
        .max()
        .unwrap_or(0);
    if max_cross == 0 {
        return Ok(());
    }
    let b = bits(max_cross);
    // Pass 3: accumulate, saturating.
    for t in triangles {
        let Some(n) = cross(t) else { continue };
        let scaled = n.map(|c| {
            if b > FACE_BITS {
                shr_round(c, b - FACE_BITS)
            } else {
                c << (FACE_BITS - b)
            }
        });
        for &i in t {
            if let Some(o) = out.get_mut(i as usize) {
                let s = o.to_bits();
                let add = |k: usize| {
                    let cur = s.get(k).copied().unwrap_or(0) as i64;
                    let d = scaled.get(k).copied().unwrap_or(0);
                    (cur + d).clamp(i32::MIN as i64, i32::MAX as i64) as i32
                };
                *o = Vec3::from_bits(add(0), add(1), add(2));
            }
        }
    }
    // Pass 4: unit length.
    for o in out.iter_mut() {
        *o = match normalize(o.to_bits().map(i64::from)) {
            Some(u) => {
                let q = u.map(|c| shr_round(c as i64, 14) as i32);
                Vec3::from_bits(q[0], q[1], q[2])
            }
            None => Vec3::ZERO,
        };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate std;

    /// T33 for vertex normals: a fan of triangles at scales from 1e-4 to 1e3 units around a
    /// vertex on the plane z = x: the normal at the apex is the plane's normal within 1 degree.
    #[test]
    fn t33_vertex_normals_at_every_scale() {
        for scale in [1e-4f64, 1e-2, 1.0, 100.0, 1000.0] {
            let q = |x: f64, y: f64| {
                let v = |c: f64| (c * scale * 65536.0).round() as i32;
                Vec3::from_bits(v(x), v(y), v(x))
            };
            let positions = [
                q(0.0, 0.0),
                q(1.0, 0.0),
                q(0.3, 1.0),
                q(-1.0, 0.4),
                q(-0.2, -1.0),
            ];
            let triangles = [[0u16, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]];
            let mut out = [Vec3::ZERO; 5];
            vertex_normals(&positions, &triangles, &mut out).unwrap();
            let n = out[0].to_bits().map(|c| c as f64 / 65536.0);
            let expect = [-(0.5f64.sqrt()), 0.0, 0.5f64.sqrt()];
            let cos = n[0] * expect[0] + n[1] * expect[1] + n[2] * expect[2];
            assert!(cos > 1f64.to_radians().cos(), "scale {scale}: {n:?}");
        }
    }

    #[test]
    fn unused_and_degenerate_vertices_get_zero_normals() {
        let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::from_int(5, 5, 5)];
        let mut out = [Vec3::X; 4];
        vertex_normals(&positions, &[[0, 1, 2], [0, 0, 0]], &mut out).unwrap();
        assert_eq!(out[3], Vec3::ZERO);
        assert_eq!(out[0], Vec3::Z);
        let mut short = [Vec3::ZERO; 2];
        assert_eq!(
            vertex_normals(&positions, &[], &mut short),
            Err(MeshError::NormalCountMismatch)
        );
        let huge = [
            Vec3::from_int(-32768, -32768, 0),
            Vec3::from_int(32767, -32768, 0),
            Vec3::from_int(-32768, 32767, 0),
        ];
        let mut out = [Vec3::ZERO; 3];
        vertex_normals(&huge, &[[0, 1, 2]], &mut out).unwrap();
        assert_eq!(out[0], Vec3::Z);
    }
}

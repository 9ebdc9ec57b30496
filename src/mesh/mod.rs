//! Meshes and objects: what a scene is made of.
//!
//! A [`Mesh`] borrows its arrays, so it can live in flash as `static` data: positions, triangle
//! indices, optional per-vertex normals and UVs, and an optional edge list for wireframes. Face normals
//! for flat shading can be kept too, found once at start-up into RAM
//! ([`Mesh::with_face_normals`]). Its constructors check every index once (they are
//! `const fn`, so a mesh in a `static` is checked at compile time) and the pipeline reads
//! indices with checked access all the same.
//! An [`Object`] places a mesh in the world with a model matrix and gives it a colour.

mod normals;
mod shapes;

use core::fmt;

use embedded_graphics::pixelcolor::Rgb888;

use crate::math::{isqrt_ceil, Angle, Mat4, Scalar, Trig, Vec3};

pub use normals::{vertex_normals, FaceNormal};
pub use shapes::{
    textured_torus, textured_torus_counts, textured_uv_sphere, textured_uv_sphere_counts, torus,
    torus_counts, uv_sphere, uv_sphere_counts, ShapeError, CUBE, OCTAHEDRON, TETRAHEDRON,
    TEXTURED_CUBE,
};

/// A triangle: three indices into a mesh's positions, counter-clockwise seen from its front.
pub type Triangle = [u16; 3];

/// A texture coordinate `[u, v]`: (0, 0) is an image's bottom-left corner, (1, 1) its
/// top-right.
pub type Uv = [Scalar; 2];

/// An edge for wireframes: two indices into a mesh's positions.
pub type Edge = [u16; 2];

/// Why a mesh was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum MeshError {
    /// Triangle `triangle` refers to a vertex that does not exist.
    TriangleIndexOutOfRange {
        /// Position of the triangle in the list.
        triangle: usize,
    },
    /// Edge `edge` refers to a vertex that does not exist.
    EdgeIndexOutOfRange {
        /// Position of the edge in the list.
        edge: usize,
    },
    /// The normals array is not as long as the positions array.
    NormalCountMismatch,
    /// The face normals' storage is not as long as the triangles array.
    FaceNormalCountMismatch,
    /// The UVs array is not as long as the positions array.
    UvCountMismatch,
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::TriangleIndexOutOfRange { triangle } => {
                write!(
                    f,
                    "triangle {triangle} refers to a vertex that does not exist"
                )
            }
            MeshError::EdgeIndexOutOfRange { edge } => {
                write!(f, "edge {edge} refers to a vertex that does not exist")
            }
            MeshError::NormalCountMismatch => f.write_str("there must be one normal per vertex"),
            MeshError::FaceNormalCountMismatch => {
                f.write_str("there must be one face normal per triangle")
            }
            MeshError::UvCountMismatch => f.write_str("there must be one UV per vertex"),
        }
    }
}

impl core::error::Error for MeshError {}

/// A triangle mesh in model space, borrowed from slices (in flash or RAM).
///
/// ```
/// use fixed3d::math::Vec3;
/// use fixed3d::mesh::{Mesh, MeshError};
/// static POSITIONS: [Vec3; 3] = [Vec3::from_int(0, 0, 0), Vec3::from_int(1, 0, 0), Vec3::from_int(0, 1, 0)];
/// static TRIANGLES: [[u16; 3]; 1] = [[0, 1, 2]];
/// // Checked at compile time:
/// static MESH: Mesh = match Mesh::new(&POSITIONS, &TRIANGLES) {
///     Ok(m) => m,
///     Err(_) => panic!("bad mesh"),
/// };
/// assert_eq!(MESH.triangles().len(), 1);
/// assert_eq!(MESH.extent(), 1 << 16); // the largest coordinate, 1.0, in raw Q16.16
/// assert_eq!(
///     Mesh::new(&POSITIONS, &[[0, 1, 3]]).unwrap_err(),
///     MeshError::TriangleIndexOutOfRange { triangle: 0 }
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Mesh<'a> {
    positions: &'a [Vec3],
    /// Every index below `positions.len()`: checked by `new`, the only constructor that sets
    /// `positions` or `triangles` (the others copy both).
    triangles: &'a [Triangle],
    normals: Option<&'a [Vec3]>,
    uvs: Option<&'a [Uv]>,
    face_normals: Option<&'a [FaceNormal]>,
    edges: Option<&'a [Edge]>,
    /// The largest coordinate magnitude of any position (raw Q16.16).
    extent: u32,
    /// The largest component magnitude of any triangle's two edges from its first vertex (raw
    /// Q16.16).
    edge_extent: u32,
    /// The largest distance of any position from the origin, rounded up (raw Q16.16).
    radius: u32,
}

impl<'a> Mesh<'a> {
    /// A mesh with nothing in it.
    pub const EMPTY: Mesh<'static> = Mesh {
        positions: &[],
        triangles: &[],
        normals: None,
        uvs: None,
        face_normals: None,
        edges: None,
        extent: 0,
        edge_extent: 0,
        radius: 0,
    };

    /// A mesh of `positions` and `triangles`; every index must be below `positions.len()`.
    pub const fn new(positions: &'a [Vec3], triangles: &'a [Triangle]) -> Result<Self, MeshError> {
        let n = positions.len();
        let mut edge_extent = 0u32;
        let mut i = 0;
        while i < triangles.len() {
            let [a, b, c] = triangles[i];
            if a as usize >= n || b as usize >= n || c as usize >= n {
                return Err(MeshError::TriangleIndexOutOfRange { triangle: i });
            }
            let [a, b, c] = [
                positions[a as usize].to_bits(),
                positions[b as usize].to_bits(),
                positions[c as usize].to_bits(),
            ];
            let mut j = 0;
            while j < 3 {
                // A difference of two i32s has a magnitude of at most 2³² − 1: a u32.
                let u = (b[j] as i64 - a[j] as i64).unsigned_abs() as u32;
                let v = (c[j] as i64 - a[j] as i64).unsigned_abs() as u32;
                let m = if u > v { u } else { v };
                if m > edge_extent {
                    edge_extent = m;
                }
                j += 1;
            }
            i += 1;
        }
        let mut extent = 0u32;
        // The largest squared distance from the origin: three squares below 2⁶² each.
        let mut farthest = 0u64;
        let mut k = 0;
        while k < n {
            let c = positions[k].to_bits();
            let mut squared = 0u64;
            let mut j = 0;
            while j < 3 {
                let m = c[j].unsigned_abs();
                if m > extent {
                    extent = m;
                }
                squared += m as u64 * m as u64;
                j += 1;
            }
            if squared > farthest {
                farthest = squared;
            }
            k += 1;
        }
        Ok(Mesh {
            positions,
            triangles,
            normals: None,
            uvs: None,
            face_normals: None,
            edges: None,
            extent,
            edge_extent,
            radius: isqrt_ceil(farthest),
        })
    }

    /// Adds per-vertex normals (any length; zero normals light as ambient only), used by
    /// Gouraud shading. There must be exactly one per position.
    pub const fn with_normals(self, normals: &'a [Vec3]) -> Result<Self, MeshError> {
        if normals.len() != self.positions.len() {
            return Err(MeshError::NormalCountMismatch);
        }
        Ok(Mesh {
            normals: Some(normals),
            ..self
        })
    }

    /// Adds a texture coordinate per vertex, read by textured models (see
    /// [`texture`](crate::texture)). There must be exactly one per position: where a vertex's
    /// corners need different UVs (a seam), the vertex is split, as
    /// [`obj::split_corners`](crate::obj::split_corners) splits an OBJ file's.
    pub const fn with_uvs(self, uvs: &'a [Uv]) -> Result<Self, MeshError> {
        if uvs.len() != self.positions.len() {
            return Err(MeshError::UvCountMismatch);
        }
        Ok(Mesh {
            uvs: Some(uvs),
            ..self
        })
    }

    /// Keeps each triangle's face normal for flat shading, found here once into `out`, which
    /// must hold exactly one per triangle: frames then light each face from it instead of
    /// finding it from the positions every time, with the same colours (see [`FaceNormal`]).
    pub fn with_face_normals(self, out: &'a mut [FaceNormal]) -> Result<Self, MeshError> {
        if out.len() != self.triangles.len() {
            return Err(MeshError::FaceNormalCountMismatch);
        }
        for (n, t) in out.iter_mut().zip(self.triangles) {
            *n = FaceNormal::of(self.positions, t, (self.extent, self.edge_extent));
        }
        Ok(Mesh {
            face_normals: Some(out),
            ..self
        })
    }

    /// Adds an edge list: wireframes then draw each listed edge once instead of the three
    /// edges of every front-facing triangle.
    pub const fn with_edges(self, edges: &'a [Edge]) -> Result<Self, MeshError> {
        let n = self.positions.len();
        let mut i = 0;
        while i < edges.len() {
            let [a, b] = edges[i];
            if a as usize >= n || b as usize >= n {
                return Err(MeshError::EdgeIndexOutOfRange { edge: i });
            }
            i += 1;
        }
        Ok(Mesh {
            edges: Some(edges),
            ..self
        })
    }

    /// The largest magnitude of any coordinate of any position, raw Q16.16 (the vertex stage
    /// sizes its arithmetic by it).
    #[must_use]
    pub const fn extent(&self) -> u32 {
        self.extent
    }

    /// The largest distance of any position from the model's origin, rounded up, raw Q16.16:
    /// the radius of a sphere about the origin that holds the mesh (the vertex stage skips
    /// the clip planes' tests of each vertex of an object whose sphere lies inside them).
    ///
    /// ```
    /// use fixed3d::math::Vec3;
    /// use fixed3d::mesh::Mesh;
    /// let p = [Vec3::from_int(3, 0, 0), Vec3::from_int(0, 3, 4), Vec3::from_int(-1, 1, 1)];
    /// let mesh = Mesh::new(&p, &[[0, 1, 2]]).unwrap();
    /// assert_eq!(mesh.radius(), 5 << 16);
    /// ```
    #[must_use]
    pub const fn radius(&self) -> u32 {
        self.radius
    }

    /// The largest magnitude of any component of any triangle's two edges from its first
    /// vertex, raw Q16.16: flat shading takes its face normals in 32-bit words, untested,
    /// where it is below 2¹⁵.
    #[must_use]
    pub(crate) const fn edge_extent(&self) -> u32 {
        self.edge_extent
    }

    /// The vertex positions.
    #[must_use]
    pub const fn positions(&self) -> &'a [Vec3] {
        self.positions
    }

    /// The triangles.
    #[must_use]
    pub const fn triangles(&self) -> &'a [Triangle] {
        self.triangles
    }

    /// The per-vertex normals, if any.
    #[must_use]
    pub const fn normals(&self) -> Option<&'a [Vec3]> {
        self.normals
    }

    /// The per-vertex UVs, if any.
    #[must_use]
    pub const fn uvs(&self) -> Option<&'a [Uv]> {
        self.uvs
    }

    /// The face normals kept by [`with_face_normals`](Self::with_face_normals), if any.
    #[must_use]
    pub const fn face_normals(&self) -> Option<&'a [FaceNormal]> {
        self.face_normals
    }

    /// The edge list, if any.
    #[must_use]
    pub const fn edges(&self) -> Option<&'a [Edge]> {
        self.edges
    }
}

/// Position, rotation and scale, composed as `translate · Rz · Rx · Ry · scale` (the mesh is
/// scaled, turned about Y, then X, then Z, then moved).
///
/// ```
/// use fixed3d::math::{Angle, Vec3};
/// use fixed3d::mesh::Transform;
/// let m = Transform::new()
///     .translated(Vec3::from_int(0, 0, -5))
///     .rotated_y(Angle::from_degrees(90))
///     .matrix();
/// assert_eq!(m.transform_point(Vec3::X), Vec3::from_int(0, 0, -6));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Transform {
    /// Where the model's origin goes.
    pub translation: Vec3,
    /// Rotation about X (applied after Y).
    pub rotation_x: Angle,
    /// Rotation about Y (applied first).
    pub rotation_y: Angle,
    /// Rotation about Z (applied last).
    pub rotation_z: Angle,
    /// Scale along the model's axes.
    pub scale: Vec3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::new()
    }
}

impl Transform {
    /// The identity: no move, no turn, scale 1.
    #[must_use]
    pub const fn new() -> Self {
        Transform {
            translation: Vec3::ZERO,
            rotation_x: Angle::ZERO,
            rotation_y: Angle::ZERO,
            rotation_z: Angle::ZERO,
            scale: Vec3::from_int(1, 1, 1),
        }
    }

    /// With `translation`.
    #[must_use]
    pub const fn translated(self, translation: Vec3) -> Self {
        Transform {
            translation,
            ..self
        }
    }

    /// With a rotation about X.
    #[must_use]
    pub const fn rotated_x(self, a: Angle) -> Self {
        Transform {
            rotation_x: a,
            ..self
        }
    }

    /// With a rotation about Y.
    #[must_use]
    pub const fn rotated_y(self, a: Angle) -> Self {
        Transform {
            rotation_y: a,
            ..self
        }
    }

    /// With a rotation about Z.
    #[must_use]
    pub const fn rotated_z(self, a: Angle) -> Self {
        Transform {
            rotation_z: a,
            ..self
        }
    }

    /// With `scale`.
    #[must_use]
    pub const fn scaled(self, scale: Vec3) -> Self {
        Transform { scale, ..self }
    }

    /// The model matrix.
    #[must_use]
    pub fn matrix(&self) -> Mat4 {
        self.matrix_by(Trig::Polynomial)
    }

    /// The model matrix, its sines and cosines computed by `trig` (a precision knob: see
    /// [`Trig`] and `docs/accuracy.md`).
    ///
    /// ```
    /// use fixed3d::math::{Angle, Trig};
    /// use fixed3d::mesh::Transform;
    /// let t = Transform::new().rotated_y(Angle::from_degrees(90));
    /// assert_eq!(t.matrix_by(Trig::Polynomial), t.matrix());
    /// ```
    #[must_use]
    pub fn matrix_by(&self, trig: Trig) -> Mat4 {
        Mat4::translation(self.translation)
            * Mat4::rotation_z_sc(trig.sin_cos_q16(self.rotation_z))
            * Mat4::rotation_x_sc(trig.sin_cos_q16(self.rotation_x))
            * Mat4::rotation_y_sc(trig.sin_cos_q16(self.rotation_y))
            * Mat4::scaling(self.scale)
    }
}

/// A mesh placed in the world with a model matrix and a colour.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb888;
/// use fixed3d::mesh::{Object, Transform, CUBE};
/// let cube = Object::new(&CUBE, Transform::new().matrix(), Rgb888::new(255, 160, 64));
/// assert_eq!(cube.mesh.triangles().len(), 12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Object<'a> {
    /// The mesh.
    pub mesh: &'a Mesh<'a>,
    /// World from model.
    pub model: Mat4,
    /// Base colour (lit by the scene's lights, or drawn as is when unlit).
    pub color: Rgb888,
    /// Its highlights, if it is glossy (per-vertex shading only).
    pub specular: Option<&'a Specular>,
}

impl<'a> Object<'a> {
    /// An object, not glossy.
    #[must_use]
    pub const fn new(mesh: &'a Mesh<'a>, model: Mat4, color: Rgb888) -> Self {
        Object {
            mesh,
            model,
            color,
            specular: None,
        }
    }

    /// With highlights `specular` (or none).
    #[must_use]
    pub const fn with_specular(self, specular: Option<&'a Specular>) -> Self {
        Object { specular, ..self }
    }
}

/// A glossy surface's highlights (Blinn-Phong): their colour and how tight they are.
///
/// Each light adds `light · attenuation · max(0, N·H)^shininess` to the highlight's intensity,
/// where `H` is the unit half vector between the directions towards the light and towards the
/// viewer (taken along the camera's view axis, as if the viewer were far away), for a surface
/// that faces the light; the sum, clamped to [0, 1], scales `color`, which is added to the
/// surface's diffuse colour (each channel saturating at 255). Lit per vertex: models shaded
/// [`Gouraud`](crate::render::Shade::Gouraud) or perspective-correct Gouraud show it.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb888;
/// use fixed3d::mesh::Specular;
/// static GLOSS: Specular = Specular::new(Rgb888::new(255, 255, 255), 32);
/// assert_eq!(GLOSS.shininess, 32);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Specular {
    /// The highlight's colour at full intensity.
    pub color: Rgb888,
    /// The exponent of `N·H`: larger is smaller and sharper (1 to 65,535; 0 counts as 1).
    pub shininess: u16,
}

impl Specular {
    /// Highlights of `color` and `shininess` (a `const fn`: they can be a `static`).
    #[must_use]
    pub const fn new(color: Rgb888, shininess: u16) -> Self {
        Specular { color, shininess }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `edge_extent` is the largest component of any triangle's edges from its first vertex,
    /// exact at the ends of the coordinate range (a difference of 2³² − 1).
    #[test]
    fn edge_extent_bounds_every_edge_from_the_first_vertex() {
        let q = Vec3::from_bits;
        let positions = [
            q(0, 0, 0),
            q(5, -7, 2),
            q(-3, 4, 6),
            q(i32::MIN, 0, 0),
            q(i32::MAX, 0, 0),
        ];
        let mesh = |t: &'static [Triangle]| Mesh::new(&positions, t).map(|m| m.edge_extent());
        // Edges 1 − 0 and 2 − 0: components up to 7; 2 − 1 (11 in y) is not one of them.
        assert_eq!(mesh(&[[0, 1, 2]]), Ok(7));
        assert_eq!(mesh(&[[1, 0, 2]]), Ok(11));
        assert_eq!(mesh(&[[0, 1, 2], [3, 4, 0]]), Ok(u32::MAX));
        assert_eq!(mesh(&[]), Ok(0));
        assert_eq!(Mesh::EMPTY.edge_extent(), 0);
    }

    /// `radius` is the largest distance of any position from the origin, rounded up, at the
    /// ends of the coordinate range too (three squares of 2³¹ sum to 3·2⁶²), and for random
    /// positions; the vertex stage's sphere test relies on it bounding every position.
    #[test]
    fn radius_is_the_farthest_distance_rounded_up() {
        let q = Vec3::from_bits;
        let radius = |p: &[Vec3]| Mesh::new(p, &[]).map(|m| m.radius()).unwrap_or(0);
        assert_eq!(radius(&[q(3, 4, 0), q(-2, 2, 1)]), 5);
        assert_eq!(radius(&[q(1, 1, 1)]), 2);
        assert_eq!(radius(&[q(i32::MIN, i32::MIN, i32::MIN)]), 3_719_550_787);
        assert_eq!(radius(&[]), 0);
        assert_eq!(Mesh::EMPTY.radius(), 0);
        let mut rng = crate::testing::XorShift(0x5851_F42D_4C95_7F2Du64);
        for _ in 0..2000 {
            let p: std::vec::Vec<Vec3> = (0..4)
                .map(|_| {
                    let x = rng.next_u64() as i32 >> (rng.next_u64() % 32);
                    q(x, rng.next_u64() as i32 >> 8, rng.next_u64() as i32)
                })
                .collect();
            let r = u128::from(radius(&p));
            let farthest = p
                .iter()
                .map(|v| {
                    v.to_bits()
                        .iter()
                        .map(|&c| (c as i128 * c as i128) as u128)
                        .sum()
                })
                .max()
                .unwrap_or(0u128);
            assert!(
                r * r >= farthest && (r == 0 || (r - 1) * (r - 1) < farthest),
                "{p:?}"
            );
        }
    }
}

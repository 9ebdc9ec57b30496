//! Models parsed at compile time.

use super::{parse, ObjBuffers, ObjCounts, ObjError, Placement};
use crate::math::Vec3;
use crate::mesh::{Mesh, Triangle};

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

//! What the `asm` feature's triangle walks share (src/target/thumb1.rs on ARMv6-M,
//! src/target/thumb2.rs on ARMv7-M and ARMv8-M mainline, src/target/x86_64.rs on x86-64): the
//! walk's state, checked here, and what a stop of it means. Each core's module holds its
//! `next_stop` in assembly and the proof that it reads and writes only what this state allows.

use core::mem::{offset_of, size_of};

use crate::mesh::{Mesh, Triangle};
use crate::pipeline::{FaceStop, ScreenVertex};
use crate::raster::ScreenPoint;

/// The triangles of a mesh, walked with their back faces skipped in assembly: each call of
/// `next_stop` (in the core's module) gives the next triangle that is not a back face
/// ([`FaceStop`]); the back faces are those not given, the number of triangles less the stops.
/// For an object whose every vertex lies inside every clip plane, culled to its front faces:
/// a back face has a doubled signed area (`doubled_area`) above 0, a front face below, and
/// for a front face the walk copies its corners (position and depth) for `fill_face`.
///
/// Its indices are read unchecked: every index of a [`Mesh`] lies below its number of
/// positions (`Mesh::new` checks them once), and [`new`](Self::new) requires one vertex for
/// each position. Its fields are set by `new` and moved on only by the walks in assembly,
/// which keep `next` and `left` as documented below (the safety of each walk rests on it).
pub(crate) struct FrontFaces<'t, 'v> {
    pub(super) triangles: &'t [Triangle],
    pub(super) vertices: &'v [ScreenVertex],
    /// The next triangle to look at (within `triangles`, or one past its end).
    pub(super) next: *const Triangle,
    /// The triangles from `next` to the end (at most `triangles.len()`).
    pub(super) left: usize,
}

impl<'t, 'v> FrontFaces<'t, 'v> {
    /// A walk of `mesh`'s triangles from the first, their vertices in `vertices`: none
    /// unless it holds one for each of the mesh's positions.
    pub(crate) fn new(mesh: &Mesh<'t>, vertices: &'v [ScreenVertex]) -> Option<Self> {
        let triangles = mesh.triangles();
        (vertices.len() == mesh.positions().len()).then_some(Self {
            triangles,
            vertices,
            next: triangles.as_ptr(),
            left: triangles.len(),
        })
    }

    /// What the assembly's `code` ([`FaceStop::FRONT`] and the others) means, the front face
    /// being the triangle before `next`, with the doubled signed area `area`.
    #[inline(always)]
    pub(super) fn stopped(&self, code: u32, area: i64) -> FaceStop<'t> {
        if code == FaceStop::FRONT {
            let k = self.triangles.len().wrapping_sub(self.left).wrapping_sub(1);
            if let Some(tri) = self.triangles.get(k) {
                return FaceStop::Front(k, tri, area);
            }
        }
        if code == FaceStop::DEGENERATE {
            FaceStop::Degenerate
        } else {
            FaceStop::End
        }
    }
}

// The layouts the walks read and write: triangles of three u16 indices, vertices of 16 bytes
// with their x, y and z one after the other at the start, the corners they write as three
// words (x, y, z) after one another.
const _: () = {
    assert!(size_of::<Triangle>() == 6 && size_of::<ScreenVertex>() == 16);
    assert!(offset_of!(ScreenVertex, x) == 0 && offset_of!(ScreenVertex, y) == 4);
    assert!(offset_of!(ScreenVertex, z) == 8 && size_of::<(ScreenPoint, i32)>() == 12);
    assert!(offset_of!((ScreenPoint, i32), 0) == 0 && offset_of!((ScreenPoint, i32), 1) == 8);
};

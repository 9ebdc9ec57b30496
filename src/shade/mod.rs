//! Shading: what colour each pixel of a triangle gets.
//!
//! Three shading types, chosen as a type parameter so that a program links only what it uses:
//! [`Unlit`] (the object's colour as is), [`Flat`] (Lambert once per triangle, from its face
//! normal) and [`Gouraud`] (Lambert once per vertex, from the mesh's normals, then colours
//! interpolated across the triangle: affine in screen space, every pixel a convex combination
//! of the vertex colours).

mod lambert;
mod paint;

pub(crate) use lambert::{face_normal, lambert, vertex_normal};
pub use paint::{Paint, SmoothCursor, SmoothPaint, SolidPaint};

use embedded_graphics::pixelcolor::Rgb888;

use crate::raster::ScreenPoint;
use crate::scene::Lighting;

mod sealed {
    pub trait Sealed {}
}

/// What a shading type needs to colour one triangle.
#[derive(Debug)]
pub struct FaceInputs<'a> {
    /// The object's base colour.
    pub(crate) base: Rgb888,
    /// Model-space positions of the three vertices (raw Q16.16).
    pub(crate) model: [[i32; 3]; 3],
    /// World-from-model normal matrix (cofactor, raw Q16.16).
    pub(crate) normal_matrix: &'a [[i32; 3]; 3],
    /// Per-vertex lit colours (Gouraud).
    pub(crate) vertex_rgb: [[i32; 3]; 3],
    /// Snapped screen positions.
    pub(crate) screen: [ScreenPoint; 3],
    /// Doubled signed screen area.
    pub(crate) area2: i64,
}

/// A way of shading triangles: [`Unlit`], [`Flat`] or [`Gouraud`].
pub trait Shading: Copy + sealed::Sealed + core::fmt::Debug {
    /// The per-triangle colour source handed to targets.
    #[doc(hidden)]
    type Paint: Paint;
    /// True when the vertex stage must light every vertex.
    #[doc(hidden)]
    const PER_VERTEX: bool;
    #[doc(hidden)]
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, lighting: &Lighting<N>) -> Self::Paint;
}

/// The object's colour, no lighting: the smallest code (wireframes, flat-coloured scenes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Unlit;

/// Lambert per triangle, from the face normal of its model-space positions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Flat;

/// Lambert per vertex from the mesh's normals, colours interpolated across each triangle.
/// An object whose mesh has no normals is shaded [`Flat`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Gouraud;

impl sealed::Sealed for Unlit {}
impl sealed::Sealed for Flat {}
impl sealed::Sealed for Gouraud {}

impl Shading for Unlit {
    type Paint = SolidPaint;
    const PER_VERTEX: bool = false;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, _: &Lighting<N>) -> SolidPaint {
        SolidPaint(face.base)
    }
}

impl Shading for Flat {
    type Paint = SolidPaint;
    const PER_VERTEX: bool = false;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, lighting: &Lighting<N>) -> SolidPaint {
        let n = face_normal(face.model, face.normal_matrix);
        SolidPaint(lambert(face.base, n, lighting))
    }
}

impl Shading for Gouraud {
    type Paint = SmoothPaint;
    const PER_VERTEX: bool = true;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, _: &Lighting<N>) -> SmoothPaint {
        SmoothPaint::new(&face.screen, face.vertex_rgb, face.area2)
    }
}

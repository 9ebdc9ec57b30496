//! The per-frame pipeline, in the order data flows:
//!
//! 1. [`Frame::prepare`] runs the vertex stage once per vertex: `clip = projection · (view ·
//!    model) · position`, then the outcode against the near and far planes and the guard band,
//!    then (for vertices inside all of them) the divide by w, the viewport and the snap to
//!    sub-pixels. [`Gouraud`](crate::shade::Gouraud) also lights each vertex here. The results go
//!    into a caller-supplied cache of [`ScreenVertex`], one per vertex of the scene.
//! 2. [`Prepared::draw`] (filled) or [`Prepared::draw_wireframe`] walks the triangles, reading
//!    the cache: a triangle entirely outside one plane is dropped; one with every vertex
//!    inside goes straight on (filled, for an object whose every vertex is inside, which
//!    `prepare` notes, without reading the outcodes); any other is clipped in homogeneous
//!    space (at most 9 vertices, drawn as a fan), so nothing is ever divided by w ≤ 0 and no
//!    coordinate outgrows the rasteriser's arithmetic. Then back-face culling by the sign of
//!    the snapped screen area, shading, and the rasteriser into the target. Drawing can be
//!    repeated per band: the cache is read, never written.
//!
//! [`Stats`] counts what was drawn and what was dropped and why.

mod clip;
mod draw;
mod precision;
mod vertex;

pub use crate::stats::Stats;
pub use draw::Bin;
pub use precision::{MatrixFormat, Precision};
pub use vertex::ScreenVertex;

use core::fmt;

use embedded_graphics::pixelcolor::RgbColor;

use crate::math::{Mat4, NARROW_CORE};
use crate::projection::{Projection, Viewport};
use crate::scene::Scene;
use crate::shade::{add_highlight, lambert, vertex_normal, Highlights, Shading, SPECULAR};

use vertex::{outcode_and_project, project_words, Known, ScreenMap};

/// Which triangles back-face culling removes. Front faces are counter-clockwise when seen from
/// outside (in world space); on screen (y down) that is a negative signed area.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Cull {
    /// Remove triangles facing away from the camera (the default).
    #[default]
    Back,
    /// Remove triangles facing the camera.
    Front,
    /// Keep both.
    None,
}

fn bump(c: &mut u32) {
    *c = c.saturating_add(1);
}

/// Adds `n` to a statistic, saturating.
fn add_count(c: &mut u32, n: usize) {
    *c = c.saturating_add(u32::try_from(n).unwrap_or(u32::MAX));
}

/// Why a frame could not be prepared.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum PrepareError {
    /// The vertex cache holds fewer entries than the scene has vertices.
    CacheTooSmall {
        /// Vertices in the scene.
        needed: usize,
        /// Entries in the cache.
        capacity: usize,
    },
}

impl fmt::Display for PrepareError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PrepareError::CacheTooSmall { needed, capacity } => {
                write!(
                    f,
                    "vertex cache holds {capacity} entries, the scene has {needed} vertices"
                )
            }
        }
    }
}

impl core::error::Error for PrepareError {}

/// The per-frame constants: camera, projection, viewport and culling.
///
/// ```
/// use fixed3d::camera::LookAt;
/// use fixed3d::math::{Angle, Scalar, Vec3};
/// use fixed3d::pipeline::Frame;
/// use fixed3d::projection::{Projection, Viewport};
/// let viewport = Viewport::new(320, 240).unwrap();
/// let view = LookAt::new(Vec3::from_int(0, 0, 3), Vec3::ZERO, Vec3::Y).view().unwrap();
/// let s = Scalar::from_num;
/// let projection = Projection::perspective(Angle::from_degrees(60), viewport.aspect(), s(1), s(10)).unwrap();
/// let frame = Frame::new(&view, &projection, viewport);
/// assert_eq!(frame.viewport().width(), 320);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Frame {
    view: Mat4,
    projection: Mat4,
    viewport: Viewport,
    cull: Cull,
    precision: Precision,
    /// See [`PerspectiveGouraud`](crate::shade::PerspectiveGouraud): `1/w` is proportional to
    /// this minus the depth (perspective projections only).
    inverse_w_offset: Option<i64>,
}

impl Frame {
    /// A frame seen through `view` and `projection`, drawn into `viewport`.
    #[must_use]
    pub fn new(view: &Mat4, projection: &Projection, viewport: Viewport) -> Self {
        Frame {
            view: *view,
            projection: *projection.matrix(),
            viewport,
            cull: Cull::Back,
            precision: Precision::DEFAULT,
            inverse_w_offset: projection.inverse_w_offset(),
        }
    }

    /// With another culling mode.
    #[must_use]
    pub fn with_cull(self, cull: Cull) -> Self {
        Frame { cull, ..self }
    }

    /// With other precision knobs (the default is [`Precision::DEFAULT`]).
    #[must_use]
    pub fn with_precision(self, precision: Precision) -> Self {
        Frame { precision, ..self }
    }

    /// The precision knobs.
    #[must_use]
    pub fn precision(&self) -> Precision {
        self.precision
    }

    /// The viewport.
    #[must_use]
    pub fn viewport(&self) -> Viewport {
        self.viewport
    }

    /// The view matrix (view from world).
    #[must_use]
    pub fn view(&self) -> &Mat4 {
        &self.view
    }

    /// Clip from model: `projection · (view · model)`. The view and model matrices are
    /// composed first, so an object and a camera far from the origin (translations that cancel)
    /// keep their precision instead of saturating the projection's entries (case T35). The
    /// product is computed with 29 significant bits and rounded once, to the [`Precision`]'s
    /// [`MatrixFormat`]: by default Q16.16, or scaled up by a power of two where the clip
    /// coordinates would be small, which changes no projected position (clip coordinates are
    /// homogeneous) but keeps tiny models and near cameras precise.
    ///
    /// This is the matrix for points within ±2 (what the format's scaling assumes); the vertex
    /// stage sizes it by each mesh's [`extent`](crate::mesh::Mesh::extent).
    #[must_use]
    pub fn clip_from_model(&self, model: &Mat4) -> Mat4 {
        self.clip_from_model_within(model, 2 << 16)
    }

    /// [`clip_from_model`](Self::clip_from_model) for points whose coordinates are at most
    /// `extent` (raw Q16.16) in magnitude.
    #[must_use]
    pub fn clip_from_model_within(&self, model: &Mat4, extent: u32) -> Mat4 {
        self.precision
            .product(&self.projection, &self.view, model, extent)
    }

    /// Runs the vertex stage for every object of `scene` into `cache` (one entry per vertex,
    /// see [`Scene::vertex_count`]) and returns the frame ready to draw.
    pub fn prepare<'s, 'c, const N: usize, S: Shading>(
        &self,
        scene: &'s Scene<'s, N>,
        cache: &'c mut [ScreenVertex],
        shading: S,
    ) -> Result<Prepared<'s, 'c, N, S>, PrepareError> {
        let needed = scene.vertex_count();
        if cache.len() < needed {
            return Err(PrepareError::CacheTooSmall {
                needed,
                capacity: cache.len(),
            });
        }
        let map = ScreenMap::new(&self.viewport, &self.precision);
        let mut slots = &mut cache[..];
        let mut inside = 0u64;
        for (k, object) in scene.objects.iter().enumerate() {
            let mut planes = 0u8;
            let clip_from_model = self.clip_from_model_within(&object.model, object.mesh.extent());
            let normal_matrix = if S::PER_VERTEX {
                object.model.normal_matrix()
            } else {
                Default::default()
            };
            let normals = if S::PER_VERTEX {
                object.mesh.normals()
            } else {
                None
            };
            let extent = object.mesh.extent();
            let points = S::PER_VERTEX && scene.lighting.points().next().is_some();
            // Vertices lit in model space where the model matrix is a rotation times a scale
            // (see `Lighting::in_model_space`): no product by the normal matrix per vertex.
            // Glossy objects are lit in world space, where their viewer is.
            let model_lighting = match (normals, object.specular) {
                (Some(_), None) if S::PER_VERTEX => scene.lighting.in_model_space(&normal_matrix),
                _ => None,
            };
            let lighting = model_lighting.as_ref().unwrap_or(&scene.lighting);
            // A glossy object's highlights, for a viewer along the camera's view axis (the
            // view matrix's third row, world space).
            let highlights = match object.specular {
                Some(specular) if S::PER_VERTEX && SPECULAR => {
                    let [x, y, z, _] = self.view.to_bits()[2];
                    let towards_viewer = [x, y, z].map(i64::from);
                    Highlights::new(specular, towards_viewer, &scene.lighting)
                }
                _ => None,
            };
            // Clip coordinates known to need no reduction (every unit-scale scene).
            let fits = clip_from_model.fits_32_bits(extent);
            // Every vertex known inside every plane (an object on screen and beyond the near
            // plane): no vertex is tested against them. The sphere test costs about what testing
            // `SPHERE_TEST_VERTICES` vertices does: smaller meshes test each vertex.
            let known = if fits && object.mesh.positions().len() >= SPHERE_TEST_VERTICES {
                map.known(&clip_from_model, object.mesh.radius())
            } else {
                Known::Nothing
            };
            // Without a long multiply, the transform in 32-bit products where they suffice.
            let split = if NARROW_CORE {
                clip_from_model.split_transform(extent)
            } else {
                None
            };
            let positions = object.mesh.positions();
            // This object's slots (the cache holds one for every vertex of the scene).
            let rest = core::mem::take(&mut slots);
            let (these, after) = rest.split_at_mut(positions.len().min(rest.len()));
            slots = after;
            for (i, (p, slot)) in positions.iter().zip(these).enumerate() {
                let (code, pt, z) = if let (Some(h), Known::InWords) = (&split, known) {
                    // Known inside in words (the reference torus) on cores without a long
                    // multiply: the transform's words projected in line, without the general
                    // path's 64-bit coordinates.
                    let (pt, z) = project_words(h.transform_words(p.to_bits()), &map);
                    (0, pt, z)
                } else {
                    let c = match &split {
                        Some(h) => h.transform(p.to_bits()),
                        None => clip_from_model.transform_within(p.to_bits(), extent),
                    };
                    outcode_and_project(c, &map, fits, known)
                };
                let rgb = match normals.and_then(|n| n.get(i)) {
                    Some(n) => {
                        // World position, for point lights alone.
                        let at = if points {
                            let w = object.model.transform_within(p.to_bits(), extent);
                            [w[0], w[1], w[2]]
                        } else {
                            [0; 3]
                        };
                        let method = self.precision.normalize();
                        let unit = match &model_lighting {
                            Some(_) => method.unit32(n.to_bits()),
                            None => vertex_normal(n.to_bits(), &normal_matrix, method),
                        };
                        let mut lit = lambert(object.color, unit, &at, lighting);
                        if let (Some(h), Some(n)) = (&highlights, &unit) {
                            lit = add_highlight(lit, h.at(n, &at, &scene.lighting));
                        }
                        [lit.r(), lit.g(), lit.b()]
                    }
                    None => [0; 3],
                };
                planes |= code;
                *slot = ScreenVertex {
                    x: pt.x,
                    y: pt.y,
                    z,
                    rgb,
                    outcode: code,
                };
            }
            if planes == 0 && k < 64 {
                inside |= 1 << k;
            }
        }
        Ok(Prepared {
            frame: *self,
            scene,
            cache,
            shading,
            inside,
        })
    }
}

/// The fewest vertices of a mesh whose bounding sphere the vertex stage tests against the clip
/// planes instead of testing each vertex (see `ScreenMap::known`).
const SPHERE_TEST_VERTICES: usize = 128;

/// A frame whose vertices are transformed, ready to draw (in full or band by band).
#[derive(Debug)]
pub struct Prepared<'s, 'c, const N: usize, S> {
    frame: Frame,
    scene: &'s Scene<'s, N>,
    cache: &'c [ScreenVertex],
    shading: S,
    /// Bit k set: every vertex of object k (of the first 64) lies inside every clip plane.
    inside: u64,
}

impl<'s, 'c, const N: usize, S> Prepared<'s, 'c, N, S> {
    /// A frame `prepare` made before, drawn again from its cache: `inside` is what its
    /// [`inside_bits`](Self::inside_bits) were, `scene` and `shading` what it was given.
    pub(crate) fn resume(
        frame: Frame,
        scene: &'s Scene<'s, N>,
        cache: &'c [ScreenVertex],
        shading: S,
        inside: u64,
    ) -> Self {
        Prepared {
            frame,
            scene,
            cache,
            shading,
            inside,
        }
    }

    /// Bit k set: every vertex of object k (of the first 64) lies inside every clip plane.
    pub(crate) fn inside_bits(&self) -> u64 {
        self.inside
    }
}

impl<const N: usize, S> Prepared<'_, '_, N, S> {
    /// The cached vertices of all objects, in scene order.
    #[must_use]
    pub fn vertices(&self) -> &[ScreenVertex] {
        self.cache
    }
}

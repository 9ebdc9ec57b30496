//! Shading: what colour each pixel of a triangle gets.
//!
//! Four shading types, chosen as a type parameter so that a program links only what it uses:
//! [`Unlit`] (the object's colour as is), [`Flat`] (Lambert once per triangle, from its face
//! normal, kept in the mesh where it has them), [`Gouraud`] (Lambert, and a glossy object's
//! Blinn-Phong highlights, once per vertex from the mesh's normals, then colours interpolated
//! across the triangle: affine in screen space, each channel rounded once to the target's own
//! depth, every pixel a convex combination of the vertex colours) and [`PerspectiveGouraud`]
//! (the same, interpolated perspective-correctly: one word division and a few products a
//! pixel; `docs/accuracy.md` measures the difference). [`Textured`] maps a
//! [`Texture`] across each triangle and scales its texels by one of
//! the others' light.

mod lambert;
mod paint;
mod specular;
mod texture;

pub(crate) use lambert::{flat_color, kept_face_color, lambert, vertex_normal};
pub use paint::{
    Paint, PaintUser, PerspectiveCursor, PerspectivePaint, SmoothCursor, SmoothPaint, SolidPaint,
};
pub(crate) use specular::{add_highlight, Highlights, SPECULAR};
pub use texture::{TextureCursor, TexturePaint, TiledCursor, TiledPaint};

use embedded_graphics::pixelcolor::Rgb888;

use crate::math::{map3, Mat4, Normalize, Vec3};
use crate::mesh::{FaceNormal, Triangle};
use crate::raster::ScreenPoint;
use crate::scene::Lighting;
use crate::texture::Texture;

mod sealed {
    pub trait Sealed {}
}

/// What a shading type needs to colour one triangle (read where needed: flat shading reads the
/// model-space positions, Gouraud the screen vertices and their colours).
#[derive(Debug)]
pub struct FaceInputs<'a> {
    /// The object's base colour.
    pub(crate) base: Rgb888,
    /// The mesh's model-space positions, and the triangle's indices into them.
    pub(crate) positions: &'a [Vec3],
    pub(crate) indices: &'a Triangle,
    /// The triangle's kept face normal, where its mesh keeps them and the shading reads them
    /// ([`Flat`]), lit in model space (no normal matrix) by [`Normalize::Newton`].
    pub(crate) face_normal: Option<&'a FaceNormal>,
    /// The mesh's largest coordinate magnitude and largest edge component (raw Q16.16, see
    /// [`Mesh::edge_extent`](crate::mesh::Mesh)).
    pub(crate) extents: (u32, u32),
    /// World-from-model matrix (for the face's centre, which point lights read).
    pub(crate) model_matrix: &'a Mat4,
    /// World-from-model normal matrix (cofactor, raw Q16.16); `None` when the lighting is
    /// already in model space.
    pub(crate) normal_matrix: Option<&'a [[i32; 3]; 3]>,
    /// How normals are normalised.
    pub(crate) normalize: Normalize,
    /// Per vertex: snapped screen position and depth (Q1.30).
    pub(crate) vertices: &'a [(ScreenPoint, i32); 3],
    /// The snapped screen positions alone, as the triangle walk takes them.
    pub(crate) screen: &'a [ScreenPoint; 3],
    /// Per vertex: lit colour, whole channels 0..=255 (Gouraud; zeros for other shadings).
    pub(crate) colors: &'a [[i32; 3]; 3],
    /// Per vertex: UV, raw Q16.16 (textured shadings; zeros for the others).
    pub(crate) uvs: &'a [[i32; 2]; 3],
    /// For perspective projections, the value `1/w` is proportional to after subtracting the
    /// depth (Q1.30).
    pub(crate) inverse_w_offset: Option<i64>,
    /// Doubled signed screen area.
    pub(crate) area2: i64,
    /// The channel depths smooth shading hands the target
    /// ([`RasterTarget::CHANNELS`](crate::buffer::RasterTarget::CHANNELS)).
    pub(crate) channels: [u8; 3],
}

impl<'a> FaceInputs<'a> {
    /// Model-space positions of the three vertices (raw Q16.16). `Mesh::new` checked every
    /// index against the positions; here one test of the largest bounds the three reads (the
    /// compiler drops their own tests).
    #[inline]
    fn model(&self) -> [[i32; 3]; 3] {
        let [a, b, c] = *self.indices;
        let (a, b, c) = (a as usize, b as usize, c as usize);
        let Some(p) = self.positions.get(..=a.max(b).max(c)) else {
            return [[0; 3]; 3];
        };
        map3([a, b, c], |i| {
            p.get(i).copied().unwrap_or_default().to_bits()
        })
    }

    /// The face's centre in the lighting's space (raw Q16.16): world space where there are
    /// point lights (the lighting is then never in model space), else unread and zero.
    fn centre<const N: usize>(&self, lighting: &Lighting<N>) -> [i64; 3] {
        if lighting.points().next().is_none() {
            return [0; 3];
        }
        let [a, b, c] = self.model();
        let mean = map3([0, 1, 2], |j| {
            ((a[j] as i64 + b[j] as i64 + c[j] as i64) / 3) as i32
        });
        let w = self.model_matrix.transform_within(mean, self.extents.0);
        [w[0], w[1], w[2]]
    }

    fn vertex_rgb(&self) -> [[i32; 3]; 3] {
        *self.colors
    }

    /// The same face for a paint whose colours stay in 8 bits.
    fn in_8_bits(&self) -> FaceInputs<'a> {
        FaceInputs {
            channels: [255; 3],
            ..*self
        }
    }
}

/// A way of shading triangles: [`Unlit`], [`Flat`], [`Gouraud`], [`PerspectiveGouraud`] or
/// [`Textured`].
pub trait Shading: Copy + sealed::Sealed + core::fmt::Debug {
    /// The per-triangle colour source handed to targets.
    #[doc(hidden)]
    type Paint: Paint;
    /// True when the vertex stage must light every vertex.
    #[doc(hidden)]
    const PER_VERTEX: bool;
    /// True when every face is lit from its face normal (so the lights are worth turning into
    /// each object's model space once).
    #[doc(hidden)]
    const FACE_LIGHTING: bool = false;
    /// True when faces are lit from the face normals a mesh keeps, where it keeps them.
    #[doc(hidden)]
    const KEPT_FACE_NORMALS: bool = false;
    /// True when the triangles read their vertices' UVs.
    #[doc(hidden)]
    const TEXTURED: bool = false;
    #[doc(hidden)]
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, lighting: &Lighting<N>) -> Self::Paint;
    /// The paint of a mesh without vertex normals, lit flat (per-vertex shadings only).
    #[doc(hidden)]
    type Fallback: Paint;
    #[doc(hidden)]
    fn fallback<const N: usize>(
        &self,
        face: &FaceInputs<'_>,
        lighting: &Lighting<N>,
    ) -> Self::Fallback;
}

/// The object's colour, no lighting: the smallest code (wireframes, flat-coloured scenes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Unlit;

/// Lambert per triangle, from the triangle's face normal: the normal the mesh keeps
/// ([`Mesh::with_face_normals`], found once), else the one its model-space positions give,
/// found for each drawn face every frame. Both give the same colours. Faces lit in world space
/// (a model matrix that is not a rotation times a uniform scale), faces under another
/// [`Normalize`] method than the default and faces the kept normal cannot decide (see
/// [`FaceNormal`]) are lit from their positions.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
/// use fixed3d::camera::LookAt;
/// use fixed3d::math::{Angle, Scalar, Vec3};
/// use fixed3d::mesh::{FaceNormal, Object, Transform, CUBE};
/// use fixed3d::pipeline::{Frame, ScreenVertex};
/// use fixed3d::projection::{Projection, Viewport};
/// use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
/// use fixed3d::shade::Flat;
/// use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
///
/// // Once, at start-up: the cube's 12 face normals.
/// let mut faces = [FaceNormal::ZERO; 12];
/// let cube = CUBE.with_face_normals(&mut faces).unwrap();
///
/// let s = Scalar::from_num;
/// let model = Transform::new().rotated_y(Angle::from_degrees(30)).matrix();
/// let mut lighting = Lighting::<1>::new(LightColor::gray(s(0.2)));
/// let sun = DirectionalLight::new(Vec3::from_int(-1, 1, 1), LightColor::gray(s(0.8)));
/// lighting.push(sun).unwrap();
/// let viewport = Viewport::new(64, 48).unwrap();
/// let view = LookAt::new(Vec3::from_int(3, 2, 4), Vec3::ZERO, Vec3::Y).view().unwrap();
/// let fov = Angle::from_degrees(60);
/// let projection = Projection::perspective(fov, viewport.aspect(), s(1.0), s(20.0)).unwrap();
/// let frame = Frame::new(&view, &projection, viewport);
///
/// // Every frame: the same pixels from the kept normals as from the positions.
/// let pixels = |mesh: &fixed3d::mesh::Mesh<'_>| {
///     let objects = [Object::new(mesh, model, Rgb888::new(255, 160, 64))];
///     let scene = Scene::new(&objects, lighting.clone());
///     let (mut c, mut d) = ([Rgb565::BLACK; 64 * 48], [0u16; 64 * 48]);
///     let mut color = FrameBuffer::new(&mut c, 64, 48).unwrap();
///     let mut depth = DepthBuffer::new(&mut d, 64, 48).unwrap();
///     depth.clear();
///     let mut target = ColorDepth::new(&mut color, &mut depth).unwrap();
///     let mut cache = [ScreenVertex::DEFAULT; 8];
///     frame.prepare(&scene, &mut cache, Flat).unwrap().draw(&mut target).unwrap();
///     c
/// };
/// let kept = pixels(&cube);
/// assert_eq!(kept, pixels(&CUBE));
/// assert!(kept.iter().filter(|&&p| p != Rgb565::BLACK).count() > 300);
/// ```
///
/// [`Mesh::with_face_normals`]: crate::mesh::Mesh::with_face_normals
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Flat;

/// Lambert per vertex from the mesh's normals, colours interpolated across each triangle.
/// An object whose mesh has no normals is shaded [`Flat`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Gouraud;

/// [`Gouraud`] with perspective-correct interpolation: each colour is weighted by `1/w` as
/// the f64 reference does, at the price of a division per pixel, shared by the channels
/// (`docs/accuracy.md` measures both). Under an orthographic projection it draws what
/// [`Gouraud`] draws.
///
/// `1/w` is not stored: for a perspective projection the depth `d = z/w` is `−a + b/w` (`a`,
/// `b` from the projection's third row), so `1/w ∝ −a − d` is recovered from the depth every
/// vertex already has.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct PerspectiveGouraud;

/// A texture lit by the shading `L` ([`Unlit`], [`Flat`] or [`Gouraud`]), each texel's
/// channels scaled by the light's (`L` lights a white surface: under a white ambient light of
/// 1 the texel shows as it is). UVs come from the mesh ([`Mesh::with_uvs`]); a mesh without
/// them reads the texel at UV (0, 0) everywhere.
///
/// [`Mesh::with_uvs`]: crate::mesh::Mesh::with_uvs
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Textured<'t, L> {
    /// The texture.
    pub texture: &'t Texture<'t>,
    /// The lighting.
    pub light: L,
}

impl<'t, L: Shading> Textured<'t, L> {
    /// The texture across the face, lit by `light` (in 8 bits: the paint scales each texel by
    /// it into the target's depths).
    fn across<P: Paint>(&self, face: &FaceInputs<'_>, light: P) -> TexturePaint<'t, P> {
        TexturePaint::new(
            self.texture,
            face.screen,
            face.uvs,
            Self::depths_for_q(face),
            face.area2,
            (light, face.channels),
        )
    }

    /// For a perspective projection, what `1/w` at each vertex comes from: the offset and the
    /// vertex depths.
    fn depths_for_q(face: &FaceInputs<'_>) -> Option<(i64, [i32; 3])> {
        face.inverse_w_offset
            .map(|offset| (offset, map3(*face.vertices, |v| v.1)))
    }
}

impl<L> sealed::Sealed for Textured<'_, L> {}

impl<'t, L: Shading> Shading for Textured<'t, L> {
    type Paint = TexturePaint<'t, L::Paint>;
    type Fallback = TexturePaint<'t, L::Fallback>;
    const PER_VERTEX: bool = L::PER_VERTEX;
    const FACE_LIGHTING: bool = L::FACE_LIGHTING;
    const KEPT_FACE_NORMALS: bool = L::KEPT_FACE_NORMALS;
    const TEXTURED: bool = true;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, lighting: &Lighting<N>) -> Self::Paint {
        self.across(face, self.light.paint(&face.in_8_bits(), lighting))
    }
    fn fallback<const N: usize>(
        &self,
        face: &FaceInputs<'_>,
        lighting: &Lighting<N>,
    ) -> Self::Fallback {
        self.across(face, self.light.fallback(&face.in_8_bits(), lighting))
    }
}

impl sealed::Sealed for Unlit {}
impl sealed::Sealed for Flat {}
impl sealed::Sealed for Gouraud {}
impl sealed::Sealed for PerspectiveGouraud {}

impl Shading for Unlit {
    type Paint = SolidPaint;
    type Fallback = SolidPaint;
    fn fallback<const N: usize>(&self, face: &FaceInputs<'_>, l: &Lighting<N>) -> SolidPaint {
        self.paint(face, l)
    }
    const PER_VERTEX: bool = false;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, _: &Lighting<N>) -> SolidPaint {
        SolidPaint(face.base)
    }
}

impl Shading for Flat {
    type Paint = SolidPaint;
    type Fallback = SolidPaint;
    fn fallback<const N: usize>(&self, face: &FaceInputs<'_>, l: &Lighting<N>) -> SolidPaint {
        self.paint(face, l)
    }
    const PER_VERTEX: bool = false;
    const FACE_LIGHTING: bool = true;
    const KEPT_FACE_NORMALS: bool = true;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, lighting: &Lighting<N>) -> SolidPaint {
        if let Some(n) = face.face_normal {
            if let Some(color) = kept_face_color(face.base, &n.0, lighting) {
                return SolidPaint(color);
            }
        }
        SolidPaint(flat_color(
            face.base,
            face.model(),
            &face.centre(lighting),
            face.normal_matrix,
            face.normalize,
            face.extents,
            lighting,
        ))
    }
}

impl Shading for Gouraud {
    type Paint = SmoothPaint;
    type Fallback = SolidPaint;
    fn fallback<const N: usize>(&self, face: &FaceInputs<'_>, l: &Lighting<N>) -> SolidPaint {
        Flat.paint(face, l)
    }
    const PER_VERTEX: bool = true;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, _: &Lighting<N>) -> SmoothPaint {
        SmoothPaint::new(face.screen, face.vertex_rgb(), face.area2, face.channels)
    }
}

impl Shading for PerspectiveGouraud {
    type Paint = PerspectivePaint;
    type Fallback = SolidPaint;
    fn fallback<const N: usize>(&self, face: &FaceInputs<'_>, l: &Lighting<N>) -> SolidPaint {
        Flat.paint(face, l)
    }
    const PER_VERTEX: bool = true;
    fn paint<const N: usize>(&self, face: &FaceInputs<'_>, _: &Lighting<N>) -> PerspectivePaint {
        let q = match face.inverse_w_offset {
            Some(offset) => map3(*face.vertices, |v| offset.saturating_sub(v.1 as i64)),
            None => [1; 3],
        };
        PerspectivePaint::new(face.screen, face.vertex_rgb(), q, face.area2)
    }
}

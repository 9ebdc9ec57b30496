//! The common path: models, a slice of lights, a camera, and a [`Renderer`] over the buffers
//! the firmware owns; one call a frame clears, draws band by band and presents.
//!
//! ```
//! use embedded_graphics::mock_display::MockDisplay;
//! use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
//! use fixed3d::mesh::CUBE;
//! use fixed3d::render::{Model, Renderer, Storage};
//! use fixed3d::{camera::Camera, scene::Light};
//!
//! let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
//! let lights = [Light::ambient(0.2), Light::directional([-1, 1, 1], 0.8)];
//! let mut storage = Storage::<8, 12>::new(); // the cube's vertices and triangles
//! let (mut color, mut depth) = ([Rgb565::new(0, 0, 0); 64 * 16], [0u16; 64 * 16]);
//! let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
//! let mut display = MockDisplay::<Rgb565>::new(); // 64x64: drawn in four bands of 16 rows
//! display.set_allow_overdraw(true);
//! let cube = Model::new(&CUBE, Rgb888::new(255, 160, 64)).rotated_y(30);
//! let stats = renderer.render(&[cube], &lights, &camera, &mut display).unwrap();
//! assert!(stats.drawn > 0);
//! ```
//!
//! Beneath it, for firmware that drives bands itself (DMA double buffering, two cores drawing
//! alternate bands): [`PreparedFrame`] runs the vertex stage and bins the triangles once, and
//! [`PreparedFrame::draw_band`] draws any band into any buffers, from any thread;
//! [`PreparedFrame::draw_band_carrying`] draws bands in order, each going on with the solid
//! triangles the band above stopped. The layers below that ([`pipeline`](crate::pipeline),
//! [`buffer`](crate::buffer)) stay public too.

use core::cell::Cell;
use core::fmt;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{Point, Size};
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Drawable;

use crate::buffer::{
    fill, BufferError, Carried, Carrier, Carries, ColorDepth, DepthBuffer, DepthFormat,
    FrameBuffer, RasterTarget, TargetColor,
};
use crate::camera::{Camera, CameraError};
use crate::math::{Angle, Mat4, Number, Scalar, Vec3};
use crate::mesh::{Mesh, Object, Specular};
use crate::pipeline::{Bin, Cull, Frame, PrepareError, Prepared, ScreenVertex, Stats};
use crate::projection::{ProjectionError, Viewport};
use crate::scene::{Light, LightColor, LightError, Lighting, Scene};
use crate::shade::{Flat, Gouraud, PerspectiveGouraud, Shading, Textured, Unlit, SPECULAR};
use crate::texture::Texture;

/// The most directional and point lights a frame of the [`Renderer`] takes (ambient lights
/// are summed into one and do not count).
pub const MAX_LIGHTS: usize = 4;

/// How a model's surfaces are lit (Lambert's law, see [`scene`](crate::scene)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Shade {
    /// The model's colour as it is.
    Unlit,
    /// One colour per triangle, from its face normal (kept in the mesh, where it has them:
    /// see [`Mesh::with_face_normals`]).
    #[default]
    Flat,
    /// Colours lit at the vertices (from the mesh's vertex normals) and interpolated
    /// linearly across the screen; flat where the mesh has no vertex normals.
    Gouraud,
    /// Gouraud interpolated perspective-correctly (through 1/w).
    PerspectiveGouraud,
}

/// Whether a model is drawn as filled triangles or as edges.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Style {
    /// Filled, depth-tested triangles.
    #[default]
    Solid,
    /// The edges of the triangles that face the camera (or the mesh's edge list), one pixel
    /// wide, depth-tested against the solid models of the frame.
    Wireframe,
}

/// A mesh placed in the world, with a colour, a [`Shade`] and a [`Style`].
///
/// Each placement applies after the ones before it: `.rotated_x(20).rotated_y(30)` turns the
/// model about X first, then about Y; `.translated(..)` last moves it into place.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb888;
/// use fixed3d::math::Vec3;
/// use fixed3d::mesh::CUBE;
/// use fixed3d::render::{Model, Shade};
/// let cube = Model::new(&CUBE, Rgb888::new(255, 160, 64))
///     .rotated_y(90)
///     .translated([0, 0, -5])
///     .shaded(Shade::Unlit);
/// assert_eq!(cube.object().model.transform_point(Vec3::X), Vec3::from_int(0, 0, -6));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Model<'a> {
    mesh: &'a Mesh<'a>,
    model: Mat4,
    color: Rgb888,
    shade: Shade,
    style: Style,
    texture: Option<&'a Texture<'a>>,
    specular: Option<&'a Specular>,
}

impl<'a> Model<'a> {
    /// `mesh` in `color` (any embedded-graphics RGB colour), flat-shaded and solid, at the
    /// origin.
    #[must_use]
    pub fn new(mesh: &'a Mesh<'a>, color: impl Into<Rgb888>) -> Self {
        Model {
            mesh,
            model: Mat4::IDENTITY,
            color: color.into(),
            shade: Shade::Flat,
            style: Style::Solid,
            texture: None,
            specular: None,
        }
    }

    /// Then turned `degrees` about the X axis.
    #[must_use]
    pub fn rotated_x(self, degrees: impl Number) -> Self {
        self.then(Mat4::rotation_x(Angle::degrees(degrees)))
    }

    /// Then turned `degrees` about the Y axis.
    #[must_use]
    pub fn rotated_y(self, degrees: impl Number) -> Self {
        self.then(Mat4::rotation_y(Angle::degrees(degrees)))
    }

    /// Then turned `degrees` about the Z axis.
    #[must_use]
    pub fn rotated_z(self, degrees: impl Number) -> Self {
        self.then(Mat4::rotation_z(Angle::degrees(degrees)))
    }

    /// Then moved by `offset`.
    #[must_use]
    pub fn translated(self, offset: impl Into<Vec3>) -> Self {
        self.then(Mat4::translation(offset.into()))
    }

    /// Then scaled by `factor` along every axis.
    #[must_use]
    pub fn scaled(self, factor: impl Number) -> Self {
        let s = factor.to_scalar();
        self.then(Mat4::scaling(Vec3::new(s, s, s)))
    }

    /// Placed by `model` (world from model) alone, whatever was applied before: for a
    /// [`Transform`](crate::mesh::Transform)'s matrix or any other.
    #[must_use]
    pub fn with_matrix(self, model: Mat4) -> Self {
        Model { model, ..self }
    }

    /// `m` applied after the placement so far.
    fn then(self, m: Mat4) -> Self {
        Model {
            model: m * self.model,
            ..self
        }
    }

    /// Lit by `shade`.
    #[must_use]
    pub fn shaded(self, shade: Shade) -> Self {
        Model { shade, ..self }
    }

    /// Covered by `texture` through the mesh's UVs ([`Mesh::with_uvs`]), lit by its
    /// [`Shade`] (the model's colour is then its wireframe's alone): see
    /// [`texture`](crate::texture).
    ///
    /// ```
    /// # if cfg!(not(feature = "texture")) { return; }
    /// use embedded_graphics::mock_display::MockDisplay;
    /// use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
    /// use fixed3d::mesh::TEXTURED_CUBE;
    /// use fixed3d::prelude::*;
    /// use fixed3d::texture::{Texels, Texture};
    ///
    /// static TEXELS: [Rgb565; 4] = [Rgb565::new(31, 0, 0), Rgb565::new(0, 63, 0),
    ///                               Rgb565::new(0, 0, 31), Rgb565::new(31, 63, 31)];
    /// let texture = Texture::new(Texels::Rgb565(&TEXELS), 2, 2).unwrap();
    /// let cube = Model::new(&TEXTURED_CUBE, Rgb888::new(255, 255, 255)).textured(&texture);
    /// let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
    /// let mut storage = Storage::<24, 12>::new();
    /// let (mut color, mut depth) = ([Rgb565::new(0, 0, 0); 64 * 64], [0u16; 64 * 64]);
    /// let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
    /// let mut display = MockDisplay::<Rgb565>::new();
    /// let stats = renderer.render(&[cube], &[Light::ambient(1)], &camera, &mut display).unwrap();
    /// assert_eq!(stats.drawn, 6); // three faces in view, two triangles each
    /// // Under a white ambient light of 1, every pixel is one of the four texels.
    /// let pixels = (0..64).flat_map(|y| (0..64).map(move |x| (x, y)));
    /// let drawn: Vec<_> = pixels.filter_map(|(x, y)| display.get_pixel((x, y).into())).collect();
    /// assert!(drawn.iter().all(|c| TEXELS.contains(c) || *c == Rgb565::new(0, 0, 0)));
    /// assert!(TEXELS.iter().all(|t| drawn.contains(t)));
    /// ```
    #[must_use]
    pub fn textured(self, texture: &'a Texture<'a>) -> Self {
        Model {
            texture: Some(texture),
            ..self
        }
    }

    /// Glossy: with the highlights `specular` (Blinn-Phong: a colour and a shininess), found at
    /// the vertices of a model shaded [`Shade::Gouraud`] or [`Shade::PerspectiveGouraud`]
    /// (flat, unlit and textured models leave them out).
    ///
    /// ```
    /// # if cfg!(not(all(feature = "gouraud", feature = "specular"))) { return; }
    /// use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    /// use fixed3d::mesh::torus;
    /// use fixed3d::prelude::*;
    /// static GLOSS: Specular = Specular::new(Rgb888::new(255, 255, 255), 32);
    /// let (mut p, mut n, mut t) = ([Vec3::ZERO; 200], [Vec3::ZERO; 200], [[0; 3]; 400]);
    /// let ring = torus(Scalar::ONE, Scalar::from_num(0.4), 16, 8, &mut p, &mut n, &mut t).unwrap();
    /// let shiny = Model::new(&ring, Rgb888::new(200, 30, 30))
    ///     .shaded(Shade::Gouraud)
    ///     .glossy(&GLOSS);
    /// let lights = [Light::ambient(0.1), Light::directional([0, 0, 1], 0.9)];
    /// let camera = Camera::perspective(60, 1, 10).looking_at([0, 0, 3], [0, 0, 0]);
    /// let mut storage = Storage::<200, 400>::new();
    /// let (mut color, mut depth) = ([Rgb888::new(0, 0, 0); 64 * 64], [0u16; 64 * 64]);
    /// let mut renderer = Renderer::new(&mut storage, &mut color, &mut depth);
    /// let mut display = embedded_graphics::mock_display::MockDisplay::<Rgb888>::new();
    /// display.set_allow_overdraw(true);
    /// renderer.render(&[shiny], &lights, &camera, &mut display).unwrap();
    /// // Where the surface faces the light and the viewer, the highlight whitens it.
    /// let pixels = (0..64).flat_map(|y| (0..64).map(move |x| (x, y)));
    /// let drawn: Vec<_> = pixels.filter_map(|(x, y)| display.get_pixel((x, y).into())).collect();
    /// assert!(drawn.iter().any(|c| c.g() > 200 && c.b() > 200));
    /// ```
    #[must_use]
    pub fn glossy(self, specular: &'a Specular) -> Self {
        Model {
            specular: Some(specular),
            ..self
        }
    }

    /// Drawn as edges.
    #[must_use]
    pub fn wireframe(self) -> Self {
        Model {
            style: Style::Wireframe,
            ..self
        }
    }

    /// The mesh.
    #[must_use]
    pub fn mesh(&self) -> &'a Mesh<'a> {
        self.mesh
    }

    /// How it is lit.
    #[must_use]
    pub fn shade(&self) -> Shade {
        self.shade
    }

    /// How it is drawn.
    #[must_use]
    pub fn style(&self) -> Style {
        self.style
    }

    /// Its texture, if any.
    #[must_use]
    pub fn texture(&self) -> Option<&'a Texture<'a>> {
        self.texture
    }

    /// Its highlights, if it is glossy.
    #[must_use]
    pub fn specular(&self) -> Option<&'a Specular> {
        self.specular
    }

    /// The model as the pipeline's [`Object`]: its mesh, model matrix, colour (white for a
    /// textured solid: lighting then gives the light that scales its texels) and highlights
    /// (none for a textured solid).
    #[must_use]
    pub fn object(&self) -> Object<'a> {
        let textured = self.texture.is_some() && self.style == Style::Solid;
        let color = if textured {
            Rgb888::new(255, 255, 255)
        } else {
            self.color
        };
        let specular = self.specular.filter(|_| SPECULAR && !textured);
        Object::new(self.mesh, self.model, color).with_specular(specular)
    }
}

/// Why a frame could not be drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum RenderError<E> {
    /// The display refused a write.
    Display(E),
    /// The display is empty or larger than [`Viewport::MAX_SIZE`] on a side.
    Viewport(ProjectionError),
    /// The camera's lens does not make a projection (see [`Camera::projection`]).
    Projection(ProjectionError),
    /// The camera's placement does not make a view (see [`Camera::view`]).
    Camera(CameraError),
    /// More than [`MAX_LIGHTS`] directional and point lights, or a directional light with a
    /// zero direction.
    Lights(LightError),
    /// The storage holds fewer vertices than the models have.
    CacheTooSmall {
        /// Vertices of all models.
        needed: usize,
        /// Vertices the storage holds.
        capacity: usize,
    },
    /// The colour or depth buffer holds less than one row of the display.
    BuffersTooSmall {
        /// Cells in one row (the display's width).
        row: usize,
    },
    /// More models than 65,535.
    TooManyModels,
    /// A model or light needs a cargo feature this build lacks (`gouraud`, `point-light`,
    /// `specular`, `texture` or `wireframe`).
    Disabled {
        /// The feature.
        feature: &'static str,
    },
}

impl<E> RenderError<E> {
    /// The same error for another display error type (for errors that are not the display's).
    fn cast<F>(self) -> Option<RenderError<F>> {
        Some(match self {
            RenderError::Display(_) => return None,
            RenderError::Viewport(e) => RenderError::Viewport(e),
            RenderError::Projection(e) => RenderError::Projection(e),
            RenderError::Camera(e) => RenderError::Camera(e),
            RenderError::Lights(e) => RenderError::Lights(e),
            RenderError::CacheTooSmall { needed, capacity } => {
                RenderError::CacheTooSmall { needed, capacity }
            }
            RenderError::BuffersTooSmall { row } => RenderError::BuffersTooSmall { row },
            RenderError::TooManyModels => RenderError::TooManyModels,
            RenderError::Disabled { feature } => RenderError::Disabled { feature },
        })
    }
}

impl<E: fmt::Debug> fmt::Display for RenderError<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderError::Display(e) => write!(f, "the display refused a write: {e:?}"),
            RenderError::Viewport(e) => write!(f, "the display's size: {e}"),
            RenderError::Projection(e) => write!(f, "the camera's lens: {e}"),
            RenderError::Camera(e) => write!(f, "the camera's placement: {e}"),
            RenderError::Lights(e) => write!(f, "the lights: {e}"),
            RenderError::CacheTooSmall { needed, capacity } => write!(
                f,
                "the storage holds {capacity} vertices, the models have {needed}"
            ),
            RenderError::BuffersTooSmall { row } => {
                write!(f, "a buffer holds less than one row of {row} pixels")
            }
            RenderError::TooManyModels => f.write_str("more than 65,535 models"),
            RenderError::Disabled { feature } => {
                write!(f, "the scene needs the `{feature}` feature of fixed3d")
            }
        }
    }
}

impl<E: fmt::Debug> core::error::Error for RenderError<E> {}

/// Storage for one frame's work, sized for the scene: a transformed vertex per vertex of all
/// models, a bin per triangle that can face the camera, and room for the solid triangles
/// that cross from one band into the next. [`bytes`](Self::bytes) gives its size.
///
/// Bins are what make bands cheap: each band fetches, shades and sets up only the triangles
/// that touch its rows, in the mesh's order. Of the others it reads each one's rows, or one
/// summary for a whole block of them (a run of a mesh's triangles, which mostly lie close
/// together) where none of the block touches its rows. A frame whose visible triangles do not
/// fit is still drawn right, by walking every triangle for every band; one drawn in a single
/// pass needs none (`TRIANGLES` may then be 0).
///
/// A triangle of one colour that a band stops at its last row is carried into the next band
/// ([`Carried`]): that band goes on with its walk instead of fetching, shading and setting it
/// up again. `CARRIED` entries (by default 32) hold those crossing one band boundary; where
/// more cross one, the rest are set up again, and the pixels are the same: a dense model
/// drawn in short bands can use more room than the default ([`Stats::carried`] tells how many
/// a frame carried). A frame drawn in one pass carries nothing.
///
/// ```
/// use fixed3d::buffer::Carried;
/// use fixed3d::render::Storage;
/// // The torus of the reference scene: 1152 vertices, 2304 triangles.
/// let carried = 32 * core::mem::size_of::<Carried>();
/// assert_eq!(Storage::<1152, 2304>::bytes(), 1152 * 16 + 2304 * 12 + carried);
/// ```
#[derive(Clone, Debug)]
pub struct Storage<const VERTICES: usize, const TRIANGLES: usize, const CARRIED: usize = 32> {
    vertices: [ScreenVertex; VERTICES],
    bins: [Bin; TRIANGLES],
    carried: [Carried; CARRIED],
}

impl<const VERTICES: usize, const TRIANGLES: usize, const CARRIED: usize>
    Storage<VERTICES, TRIANGLES, CARRIED>
{
    /// Empty storage (a `const fn`: it can be a `static`).
    #[must_use]
    pub const fn new() -> Self {
        Storage {
            vertices: [ScreenVertex::DEFAULT; VERTICES],
            bins: [Bin::EMPTY; TRIANGLES],
            carried: [Carried::EMPTY; CARRIED],
        }
    }

    /// Its size in bytes.
    #[must_use]
    pub const fn bytes() -> usize {
        core::mem::size_of::<Self>()
    }
}

impl<const VERTICES: usize, const TRIANGLES: usize, const CARRIED: usize> Default
    for Storage<VERTICES, TRIANGLES, CARRIED>
{
    fn default() -> Self {
        Self::new()
    }
}

/// Draws frames of models into any embedded-graphics display through the buffers it is
/// given: a colour buffer and a depth buffer of the same number of cells, as many rows of the
/// display as they hold (the display's width each). Buffers as large as the display draw it
/// in one pass; smaller ones draw it in bands, top to bottom, each presented as soon as it is
/// drawn, each going on with the solid triangles the band above stopped at its last row (as
/// far as [`Storage`] has room for them).
///
/// Fragments are not counted ([`Stats::fragments`] and [`Stats::written`] stay 0); the depth
/// test is strictly nearer wins; back faces are culled unless [`with_cull`](Self::with_cull)
/// says otherwise.
#[derive(Debug)]
pub struct Renderer<'b, C, D = u16> {
    vertices: &'b mut [ScreenVertex],
    bins: &'b mut [Bin],
    carried: &'b mut [Carried],
    color: &'b mut [C],
    depth: &'b mut [D],
    background: Option<C>,
    cull: Cull,
}

impl<'b, C, D> Renderer<'b, C, D>
where
    C: TargetColor,
    D: DepthFormat,
{
    /// A renderer over `storage` and the colour and depth buffers (their common length, in
    /// whole rows of the display, is a band's height).
    pub fn new<const VERTICES: usize, const TRIANGLES: usize, const CARRIED: usize>(
        storage: &'b mut Storage<VERTICES, TRIANGLES, CARRIED>,
        color: &'b mut [C],
        depth: &'b mut [D],
    ) -> Self {
        Self::from_slices(&mut storage.vertices, &mut storage.bins, color, depth)
            .with_carried(&mut storage.carried)
    }

    /// A renderer over storage of any length (see [`Storage`] for what each slice holds),
    /// which carries no triangle from band to band until given room
    /// ([`with_carried`](Self::with_carried)).
    pub fn from_slices(
        vertices: &'b mut [ScreenVertex],
        bins: &'b mut [Bin],
        color: &'b mut [C],
        depth: &'b mut [D],
    ) -> Self {
        Renderer {
            vertices,
            bins,
            carried: &mut [],
            color,
            depth,
            background: None,
            cull: Cull::Back,
        }
    }

    /// With room for the triangles of one colour that cross from one band into the next (see
    /// [`Storage`]).
    #[must_use]
    pub fn with_carried(self, carried: &'b mut [Carried]) -> Self {
        Renderer { carried, ..self }
    }

    /// With the colour each frame is cleared to (by default black, the colour of `Rgb888`'s
    /// zero).
    #[must_use]
    pub fn with_background(self, color: C) -> Self {
        Renderer {
            background: Some(color),
            ..self
        }
    }

    /// With another culling mode (by default back faces are culled).
    #[must_use]
    pub fn with_cull(self, cull: Cull) -> Self {
        Renderer { cull, ..self }
    }

    /// Draws `models` lit by `lights` and seen by `camera` into `display`: the frame's
    /// vertex stage once, then each band cleared (unless the band before drew nothing into
    /// the buffers), drawn and sent with one `fill_contiguous`.
    /// The viewport is the display's bounding box. Returns what was drawn.
    pub fn render<T>(
        &mut self,
        models: &[Model<'_>],
        lights: &[Light],
        camera: &Camera,
        display: &mut T,
    ) -> Result<Stats, RenderError<T::Error>>
    where
        T: DrawTarget<Color = C>,
    {
        let area = display.bounding_box();
        let viewport =
            Viewport::new(area.size.width, area.size.height).map_err(RenderError::Viewport)?;
        let width = area.size.width as usize;
        let rows = (self.color.len().min(self.depth.len()) / width).min(area.size.height as usize);
        if rows == 0 {
            return Err(RenderError::BuffersTooSmall { row: width });
        }
        // One pass reads every triangle once: it needs no bins.
        let bins = if rows < viewport.height() as usize {
            &mut *self.bins
        } else {
            &mut []
        };
        let frame = PreparedFrame::new(
            models,
            lights,
            camera,
            viewport,
            self.cull,
            &mut *self.vertices,
            bins,
        )
        .map_err(|e| e.cast().unwrap_or(RenderError::TooManyModels))?;
        let background = self
            .background
            .unwrap_or_else(|| C::from(Rgb888::new(0, 0, 0)));
        let mut stats = frame.stats();
        let mut carries = Carries::new(&mut *self.carried);
        let mut first = 0usize;
        // True when the buffers hold only the background and the far depth: after a band that
        // drew nothing (every write into them is part of a triangle or line counted as drawn),
        // the next needs no clearing.
        let mut clean = false;
        while first < viewport.height() as usize {
            let n = rows.min(viewport.height() as usize - first) * width;
            let (Some(color), Some(depth)) = (self.color.get_mut(..n), self.depth.get_mut(..n))
            else {
                break;
            };
            if !clean {
                fill(color, background);
                fill(depth, D::FAR);
            }
            let band = frame
                .draw_band_carrying(first as u32, color, depth, &mut carries)
                .map_err(|_| RenderError::BuffersTooSmall { row: width })?;
            clean = band.drawn == 0;
            // The first band counts what was not binned (every band counts the same).
            if first == 0 {
                stats = stats + band;
            } else {
                stats.drawn = stats.drawn.saturating_add(band.drawn);
                stats.carried = stats.carried.saturating_add(band.carried);
            }
            let rect = Rectangle::new(
                Point::new(
                    area.top_left.x,
                    area.top_left.y.saturating_add(first as i32),
                ),
                Size::new(width as u32, (n / width) as u32),
            );
            display
                .fill_contiguous(&rect, color.iter().copied())
                .map_err(RenderError::Display)?;
            first += n / width;
        }
        Ok(stats)
    }
}

/// A frame whose vertex stage has run and whose triangles are binned by the rows they touch:
/// any band of it can then be drawn, in any order, from any thread (it is only read), into
/// buffers of the caller's. What [`Renderer::render`] does band by band.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
/// use fixed3d::mesh::CUBE;
/// use fixed3d::pipeline::{Bin, Cull, ScreenVertex};
/// use fixed3d::projection::Viewport;
/// use fixed3d::render::{Model, PreparedFrame};
/// use fixed3d::buffer::DepthFormat;
/// use fixed3d::{camera::Camera, scene::Light};
///
/// let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
/// let models = [Model::new(&CUBE, Rgb888::new(255, 160, 64))];
/// let (mut vertices, mut bins) = ([ScreenVertex::DEFAULT; 8], [Bin::EMPTY; 12]);
/// let viewport = Viewport::new(32, 32).unwrap();
/// let frame = PreparedFrame::new(
///     &models, &[Light::ambient(1)], &camera, viewport, Cull::Back, &mut vertices, &mut bins,
/// ).unwrap();
/// // Rows 8 to 15, into buffers of eight rows:
/// let (mut color, mut depth) = ([Rgb565::new(0, 0, 0); 32 * 8], [u16::FAR; 32 * 8]);
/// let stats = frame.draw_band(8, &mut color, &mut depth).unwrap();
/// assert!(stats.drawn > 0);
/// ```
#[derive(Debug)]
pub struct PreparedFrame<'f> {
    models: &'f [Model<'f>],
    lighting: Lighting<MAX_LIGHTS>,
    frame: Frame,
    vertices: &'f [ScreenVertex],
    /// The binned triangles of the solid models, in model order; `None` when they did not
    /// fit (every band then walks every triangle).
    bins: Option<&'f [Bin]>,
    /// Bit m set: every vertex of model m (of the first 64) is inside every clip plane.
    inside: u64,
    stats: Stats,
}

impl<'f> PreparedFrame<'f> {
    /// Runs the vertex stage of `models` into `vertices` and bins their triangles into `bins`
    /// (see [`Storage`]), for `viewport`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        models: &'f [Model<'f>],
        lights: &[Light],
        camera: &Camera,
        viewport: Viewport,
        cull: Cull,
        vertices: &'f mut [ScreenVertex],
        bins: &'f mut [Bin],
    ) -> Result<Self, RenderError<core::convert::Infallible>> {
        if models.len() > usize::from(u16::MAX) {
            return Err(RenderError::TooManyModels);
        }
        if let Some(feature) = models.iter().find_map(missing_feature) {
            return Err(RenderError::Disabled { feature });
        }
        let lighting = Lighting::from_lights(lights).map_err(|e| match e {
            LightError::Disabled => RenderError::Disabled {
                feature: "point-light",
            },
            e => RenderError::Lights(e),
        })?;
        let view = camera.view().map_err(RenderError::Camera)?;
        let projection = camera
            .projection(&viewport)
            .map_err(RenderError::Projection)?;
        let frame = Frame::new(&view, &projection, viewport).with_cull(cull);
        let needed = models
            .iter()
            .fold(0usize, |n, m| n.saturating_add(m.mesh.positions().len()));
        if needed > vertices.len() {
            return Err(RenderError::CacheTooSmall {
                needed,
                capacity: vertices.len(),
            });
        }
        let (mut stats, mut inside, mut binned, mut offset) = (Stats::default(), 0u64, 0, 0usize);
        let mut fits = true;
        for (m, model) in models.iter().enumerate() {
            let n = model.mesh.positions().len();
            let Some(cache) = vertices.get_mut(offset..offset.saturating_add(n)) else {
                break;
            };
            offset = offset.saturating_add(n);
            let object = model.object();
            let scene = Scene::new(
                core::slice::from_ref(&object),
                lighting_of(model, &lighting),
            );
            let tag = m as u16;
            let solid = model.style == Style::Solid;
            let mut bin = |p: &dyn Binning| {
                let ok = !(fits && solid) || p.bin(tag, bins, &mut binned, &mut stats);
                (fits && ok, p.inside_bits() & 1)
            };
            let (ok, bit) = dispatch(model, |shading| {
                Ok(match shading {
                    Shadings::Gouraud if GOURAUD => bin(&frame.prepare(&scene, cache, Gouraud)?),
                    Shadings::PerspectiveGouraud if GOURAUD => {
                        bin(&frame.prepare(&scene, cache, PerspectiveGouraud)?)
                    }
                    Shadings::Textured(texture) if TEXTURE => {
                        let light = Flat;
                        bin(&frame.prepare(&scene, cache, Textured { texture, light })?)
                    }
                    Shadings::TexturedGouraud(texture) if TEXTURE && GOURAUD => {
                        let light = Gouraud;
                        bin(&frame.prepare(&scene, cache, Textured { texture, light })?)
                    }
                    _ => bin(&frame.prepare(&scene, cache, Flat)?),
                })
            })
            .map_err(|e: PrepareError| match e {
                PrepareError::CacheTooSmall { needed, capacity } => {
                    RenderError::CacheTooSmall { needed, capacity }
                }
            })?;
            fits = ok;
            if m < 64 {
                inside |= bit << m;
            }
        }
        let vertices: &'f [ScreenVertex] = vertices;
        let bins: &'f [Bin] = bins;
        Ok(PreparedFrame {
            models,
            lighting,
            frame,
            vertices,
            bins: if fits { bins.get(..binned) } else { None },
            inside,
            // Counts of a binning cut short would be a part of the frame's.
            stats: if fits { stats } else { Stats::default() },
        })
    }

    /// The viewport the frame was prepared for.
    #[must_use]
    pub fn viewport(&self) -> Viewport {
        self.frame.viewport()
    }

    /// What binning counted: triangles looked at, and those invalid, outside, clipped,
    /// culled or degenerate (zero when the bins were too small: then each band counts them).
    #[must_use]
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// Draws the band of the frame that starts at row `first_row` into `color` and `depth`
    /// (as many whole rows of the viewport's width as both hold, cleared by the caller), and
    /// returns what it drew (and, where the bins did not hold the frame, what it culled and
    /// dropped, the same for every band). [`BufferError`] when they hold no whole row.
    /// On Cortex-M cores [`FrameBuffer::fill`] and [`DepthBuffer::clear`] clear the buffers
    /// in fewer instructions than `slice::fill`, which calls `memset` for black and the far
    /// depth. A band that drew nothing ([`Stats::drawn`] 0) wrote nothing: its buffers need
    /// no clearing for the next.
    pub fn draw_band<C, D>(
        &self,
        first_row: u32,
        color: &mut [C],
        depth: &mut [D],
    ) -> Result<Stats, BufferError>
    where
        C: TargetColor,
        D: DepthFormat,
    {
        self.draw_band_with(first_row, color, depth, &mut ())
    }

    /// [`draw_band`](Self::draw_band) for the band below the one drawn last with `carries`,
    /// which goes on with the solid triangles that band stopped at its last row instead of
    /// setting them up again (see [`Carries`]); any other band sets up every triangle it
    /// meets. One queue serves the bands of one frame, drawn top to bottom: start each frame
    /// with a new one. The pixels are those of [`draw_band`](Self::draw_band).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
    /// use fixed3d::buffer::{Carried, Carries, DepthFormat};
    /// use fixed3d::mesh::CUBE;
    /// use fixed3d::pipeline::{Bin, Cull, ScreenVertex};
    /// use fixed3d::projection::Viewport;
    /// use fixed3d::render::{Model, PreparedFrame};
    /// use fixed3d::{camera::Camera, scene::Light};
    ///
    /// let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
    /// let models = [Model::new(&CUBE, Rgb888::new(255, 160, 64))];
    /// let (mut vertices, mut bins) = ([ScreenVertex::DEFAULT; 8], [Bin::EMPTY; 12]);
    /// let viewport = Viewport::new(32, 32).unwrap();
    /// let frame = PreparedFrame::new(
    ///     &models, &[Light::ambient(1)], &camera, viewport, Cull::Back, &mut vertices, &mut bins,
    /// ).unwrap();
    /// let mut room = [Carried::EMPTY; 8];
    /// let mut carries = Carries::new(&mut room);
    /// let (mut color, mut depth) = ([Rgb565::new(0, 0, 0); 32 * 4], [u16::FAR; 32 * 4]);
    /// let mut carried = 0;
    /// for first_row in (0..32).step_by(4) {
    ///     color.fill(Rgb565::new(0, 0, 0));
    ///     depth.fill(u16::FAR);
    ///     let stats = frame.draw_band_carrying(first_row, &mut color, &mut depth, &mut carries);
    ///     carried += stats.unwrap().carried;
    ///     // … send `color` to the display's rows first_row..first_row + 4
    /// }
    /// assert!(carried > 0); // the cube's faces cross band boundaries
    /// ```
    pub fn draw_band_carrying<C, D>(
        &self,
        first_row: u32,
        color: &mut [C],
        depth: &mut [D],
        carries: &mut Carries<'_>,
    ) -> Result<Stats, BufferError>
    where
        C: TargetColor,
        D: DepthFormat,
    {
        self.draw_band_with(first_row, color, depth, carries)
    }

    /// A band, its solid triangles handed to `carries`.
    fn draw_band_with<C, D, B>(
        &self,
        first_row: u32,
        color: &mut [C],
        depth: &mut [D],
        carries: &mut B,
    ) -> Result<Stats, BufferError>
    where
        C: TargetColor,
        D: DepthFormat,
        B: Carrier,
    {
        let width = self.frame.viewport().width();
        let rows = (color.len().min(depth.len()) / width as usize) as u32;
        let n = rows as usize * width as usize;
        let (Some(color), Some(depth)) = (color.get_mut(..n), depth.get_mut(..n)) else {
            return Err(BufferError::SizeMismatch);
        };
        let mut color = FrameBuffer::new(color, width, rows)?;
        let mut depth = DepthBuffer::new(depth, width, rows)?;
        let mut target = ColorDepth::band(&mut color, &mut depth, first_row)?.uncounted();
        let clip = target.clip();
        carries.begin_band(clip.y0, clip.y1);
        let mut stats = Stats::default();
        let mut offset = 0usize;
        // This band's bins: the runs of each model, in model order.
        let mut bins = self.bins.unwrap_or(&[]);
        for (m, model) in self.models.iter().enumerate() {
            let n = model.mesh.positions().len();
            let cache = self
                .vertices
                .get(offset..offset.saturating_add(n))
                .unwrap_or(&[]);
            offset = offset.saturating_add(n);
            // Bins are in model order: the run of this model's ends where the next begins.
            let run = bins.partition_point(|b| b.object() <= m as u16);
            let (mine, rest) = bins.split_at(run);
            bins = rest;
            let object = model.object();
            let scene = Scene::new(
                core::slice::from_ref(&object),
                lighting_of(model, &self.lighting),
            );
            let inside = if m < 64 { self.inside >> m & 1 } else { 0 };
            let mut draw = |p: &dyn Drawing<_, B>| {
                let bins = (m as u16, mine, self.bins.is_some());
                p.band(&mut target, bins, model.style, carries)
            };
            let (frame, inside) = (self.frame, inside);
            let drawn = dispatch(model, |shading| {
                Ok::<_, core::convert::Infallible>(match shading {
                    Shadings::Gouraud if GOURAUD => {
                        draw(&Prepared::resume(frame, &scene, cache, Gouraud, inside))
                    }
                    Shadings::PerspectiveGouraud if GOURAUD => draw(&Prepared::resume(
                        frame,
                        &scene,
                        cache,
                        PerspectiveGouraud,
                        inside,
                    )),
                    Shadings::Textured(texture) if TEXTURE => {
                        let shading = Textured {
                            texture,
                            light: Flat,
                        };
                        draw(&Prepared::resume(frame, &scene, cache, shading, inside))
                    }
                    Shadings::TexturedGouraud(texture) if TEXTURE && GOURAUD => {
                        let shading = Textured {
                            texture,
                            light: Gouraud,
                        };
                        draw(&Prepared::resume(frame, &scene, cache, shading, inside))
                    }
                    _ => draw(&Prepared::resume(frame, &scene, cache, Flat, inside)),
                })
            });
            let Ok(drawn) = drawn;
            stats = stats + drawn;
        }
        Ok(stats)
    }
}

/// The pipeline's shading type for a model: five, so that a firmware links at most five
/// copies of the triangle walk (and one without the `gouraud` and `texture` features).
#[derive(Clone, Copy)]
enum Shadings<'t> {
    /// [`Flat`]: also unlit models, under a white ambient light alone, and
    /// wireframes, whose walk reads no shading.
    Flat,
    Gouraud,
    PerspectiveGouraud,
    /// [`Textured`] lit [`Flat`] (or unlit, as above).
    Textured(&'t Texture<'t>),
    /// [`Textured`] lit [`Gouraud`] (also for [`Shade::PerspectiveGouraud`]).
    TexturedGouraud(&'t Texture<'t>),
}

/// Calls `f` with the shading type `model` is drawn with.
fn dispatch<'t, R, E>(
    model: &Model<'t>,
    f: impl FnOnce(Shadings<'t>) -> Result<R, E>,
) -> Result<R, E> {
    let smooth = matches!(model.shade, Shade::Gouraud | Shade::PerspectiveGouraud);
    f(match (model.style, model.texture, model.shade) {
        (Style::Wireframe, _, _) => Shadings::Flat,
        (_, Some(texture), _) if smooth => Shadings::TexturedGouraud(texture),
        (_, Some(texture), _) => Shadings::Textured(texture),
        (_, None, Shade::Unlit | Shade::Flat) => Shadings::Flat,
        (_, None, Shade::Gouraud) => Shadings::Gouraud,
        (_, None, Shade::PerspectiveGouraud) => Shadings::PerspectiveGouraud,
    })
}

/// The lights a model is drawn under: the frame's, or for an unlit model a white ambient
/// light alone (flat shading then gives each face the model's colour as it is).
fn lighting_of(model: &Model<'_>, frame: &Lighting<MAX_LIGHTS>) -> Lighting<MAX_LIGHTS> {
    match model.shade {
        Shade::Unlit => Lighting::new(LightColor::WHITE),
        _ => frame.clone(),
    }
}

/// Whether the renderer draws [`Shade::Gouraud`] and [`Shade::PerspectiveGouraud`] models
/// (the `gouraud` feature), textured ones (the `texture` feature) and [`Style::Wireframe`]
/// ones (the `wireframe` feature): without a feature its code is not linked, and a model that
/// needs it is an error.
const GOURAUD: bool = cfg!(feature = "gouraud");
/// See [`GOURAUD`].
const TEXTURE: bool = cfg!(feature = "texture");
/// See [`GOURAUD`].
const WIREFRAME: bool = cfg!(feature = "wireframe");

/// The feature `model` needs that this build lacks, if any.
fn missing_feature(model: &Model<'_>) -> Option<&'static str> {
    let smooth = matches!(model.shade, Shade::Gouraud | Shade::PerspectiveGouraud);
    let solid = model.style == Style::Solid;
    if !solid && !WIREFRAME {
        Some("wireframe")
    } else if smooth && solid && !GOURAUD {
        Some("gouraud")
    } else if model.texture.is_some() && solid && !TEXTURE {
        Some("texture")
    } else if model.specular.is_some() && smooth && solid && !SPECULAR {
        Some("specular")
    } else {
        None
    }
}

/// A prepared model binning its triangles, whatever its shading type.
trait Binning {
    fn bin(&self, tag: u16, bins: &mut [Bin], len: &mut usize, stats: &mut Stats) -> bool;
    fn inside_bits(&self) -> u64;
}

impl<S: Shading> Binning for Prepared<'_, '_, MAX_LIGHTS, S> {
    fn bin(&self, tag: u16, bins: &mut [Bin], len: &mut usize, stats: &mut Stats) -> bool {
        Prepared::bin(self, tag, bins, len, stats)
    }

    fn inside_bits(&self) -> u64 {
        Prepared::inside_bits(self)
    }
}

/// A prepared model drawing one band, whatever its shading type.
trait Drawing<T, B> {
    fn band(
        &self,
        target: &mut T,
        bins: (u16, &[Bin], bool),
        style: Style,
        carries: &mut B,
    ) -> Stats;
}

impl<C, D, Q, K, S, B> Drawing<ColorDepth<'_, '_, C, D, Q, crate::buffer::Less, K>, B>
    for Prepared<'_, '_, MAX_LIGHTS, S>
where
    C: TargetColor,
    D: DepthFormat,
    Q: crate::buffer::Quantize<C>,
    K: crate::buffer::FragmentCount,
    S: Shading,
    B: Carrier,
{
    fn band(
        &self,
        target: &mut ColorDepth<'_, '_, C, D, Q, crate::buffer::Less, K>,
        (tag, bins, binned): (u16, &[Bin], bool),
        style: Style,
        carries: &mut B,
    ) -> Stats {
        let drawn = match (style, binned) {
            (Style::Wireframe, _) if WIREFRAME => self.draw_wireframe_tested(target),
            (Style::Wireframe, _) => Ok(Stats::default()),
            (Style::Solid, true) => self.draw_binned(target, tag, bins, carries),
            (Style::Solid, false) => self.draw_with(target, carries),
        };
        let Ok(stats) = drawn;
        stats
    }
}

/// Models drawn as wireframes straight into a display, with no colour or depth buffer: an
/// embedded-graphics [`Drawable`]. Every model is drawn as edges whatever its [`Style`], in
/// its own colour, with no depth test. The vertex stage still needs its storage, a
/// transformed vertex per vertex of the models.
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Rgb888, Drawable};
/// use fixed3d::mesh::CUBE;
/// use fixed3d::pipeline::ScreenVertex;
/// use fixed3d::render::{Model, Wireframe};
/// use fixed3d::camera::Camera;
///
/// let camera = Camera::perspective(60, 1, 10).looking_at([2, 2, 3], [0, 0, 0]);
/// let models = [Model::new(&CUBE, Rgb888::new(255, 255, 255))];
/// let mut vertices = [ScreenVertex::DEFAULT; 8];
/// let mut display = MockDisplay::<Rgb888>::new();
/// display.set_allow_overdraw(true);
/// let stats = Wireframe::new(&models, &camera, &mut vertices).draw(&mut display).unwrap();
/// assert_eq!(stats.drawn, 12); // the cube lists its 12 edges: each is drawn once
/// ```
pub struct Wireframe<'a> {
    models: &'a [Model<'a>],
    camera: &'a Camera,
    /// Taken while drawing and put back (`draw` takes `&self`).
    vertices: Cell<Option<&'a mut [ScreenVertex]>>,
}

impl fmt::Debug for Wireframe<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Wireframe")
            .field("models", &self.models)
            .field("camera", &self.camera)
            .finish_non_exhaustive()
    }
}

impl<'a> Wireframe<'a> {
    /// `models` seen by `camera`, with `vertices` for the vertex stage.
    #[must_use]
    pub fn new(
        models: &'a [Model<'a>],
        camera: &'a Camera,
        vertices: &'a mut [ScreenVertex],
    ) -> Self {
        Wireframe {
            models,
            camera,
            vertices: Cell::new(Some(vertices)),
        }
    }
}

impl Drawable for Wireframe<'_> {
    type Color = Rgb888;
    type Output = Stats;

    /// Draws the edges. A frame that cannot be set up (an empty display, a bad camera, too
    /// little storage) draws nothing and returns empty [`Stats`].
    fn draw<T>(&self, target: &mut T) -> Result<Stats, T::Error>
    where
        T: DrawTarget<Color = Rgb888>,
    {
        let Some(vertices) = self.vertices.take() else {
            return Ok(Stats::default());
        };
        let drawn = self.draw_with(target, &mut *vertices);
        self.vertices.set(Some(vertices));
        drawn
    }
}

impl Wireframe<'_> {
    fn draw_with<T>(&self, target: &mut T, vertices: &mut [ScreenVertex]) -> Result<Stats, T::Error>
    where
        T: DrawTarget<Color = Rgb888>,
    {
        let area = target.bounding_box().size;
        let (Ok(viewport), Ok(view)) = (Viewport::new(area.width, area.height), self.camera.view())
        else {
            return Ok(Stats::default());
        };
        let Ok(projection) = self.camera.projection(&viewport) else {
            return Ok(Stats::default());
        };
        let frame = Frame::new(&view, &projection, viewport);
        let mut stats = Stats::default();
        let mut rest = vertices;
        for model in self.models {
            let n = model.mesh.positions().len();
            let Some((cache, after)) = rest.split_at_mut_checked(n) else {
                break;
            };
            rest = after;
            let object = model.object();
            let scene = Scene::<0>::new(
                core::slice::from_ref(&object),
                Lighting::new(Scalar::ONE.into()),
            );
            let Ok(prepared) = frame.prepare(&scene, cache, Unlit) else {
                break;
            };
            stats = stats + prepared.draw_wireframe(target)?;
        }
        Ok(stats)
    }
}

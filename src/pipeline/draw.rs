//! Drawing a prepared frame: triangles into a [`RasterTarget`], edges into any `DrawTarget`.

use core::cell::Cell;

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::Pixel;

use super::clip::{clip_polygon, clip_segment, ClipVertex, Polygon};
use super::vertex::{project, ScreenMap};
use super::{add_count, bump, Cull, Frame, Prepared, ScreenVertex, Stats};
use crate::buffer::{
    Carrier, ColorDepth, DepthFormat, DepthTest, FragmentCount, Quantize, RasterTarget,
    ScreenTriangle, TargetColor,
};
use crate::math::{map3, Mat4, Normalize, NARROW_CORE};
use crate::mesh::{FaceNormal, Object, Triangle, Uv};
use crate::raster::{line_pixels, PixelRect, ScreenPoint};
use crate::scene::{LightColor, Lighting};
use crate::shade::{FaceInputs, Paint, PaintUser, Shading};

/// What a triangle's vertices carry to its shading: lit colours (per-vertex shading) and UVs
/// (textured shading), each borrowed, so that a shading that reads one builds only that one.
#[derive(Clone, Copy, Debug)]
struct Varyings<'v> {
    rgb: &'v [[i32; 3]; 3],
    uv: &'v [[i32; 2]; 3],
}

/// The varyings handed to shadings that read none: arrays of zeros, which no triangle stores.
const NO_VARYINGS: Varyings<'static> = Varyings {
    rgb: &[[0; 3]; 3],
    uv: &[[0; 2]; 3],
};

/// Doubled signed area, y down: negative for front faces.
#[inline]
fn area2(p: &[ScreenPoint; 3]) -> i64 {
    crate::raster::doubled_area(p[0], p[1], p[2])
}

/// [`area2`] of a triangle whose vertices all lie inside every clip plane (outcode 0): each
/// within `GUARD` sub-pixels of the screen centre (a rounded quotient of at most `GUARD`, whose
/// every snapping step divides it: see `outcode_and_project`), so each side within ±2·`GUARD`,
/// below 2¹⁵. On cores without a long multiply the cross product in words then needs no test of
/// the sides, which `area2` makes.
#[inline(always)]
fn inside_area2(p: &[ScreenPoint; 3]) -> i64 {
    if NARROW_CORE {
        crate::raster::short_sides_area(p[0], p[1], p[2])
    } else {
        area2(p)
    }
}

/// True when culling keeps a triangle of this signed area, never one of zero area: by the sign
/// alone where culling keeps one side, the zero test only for the others.
#[inline(always)]
fn facing_kept(cull: Cull, area: i64) -> bool {
    match cull {
        Cull::Back => area < 0,
        Cull::Front => area > 0,
        Cull::None => area != 0,
    }
}

/// True when a primitive of this signed area is drawn; otherwise counts it as degenerate (zero
/// area) or culled. The drawn case is decided first, by [`facing_kept`].
#[inline(always)]
fn kept(cull: Cull, area: i64, stats: &mut Stats) -> bool {
    if facing_kept(cull, area) {
        return true;
    }
    if area == 0 {
        bump(&mut stats.degenerate);
    } else {
        bump(&mut stats.culled);
    }
    false
}

/// A triangle of a prepared frame that may cover pixels, with the rows it may touch: a
/// frame drawn in bands is binned once, so that each band reads only the triangles that touch
/// its rows. Storage for them is the caller's (see [`Storage`](crate::render::Storage)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Bin {
    triangle: u32,
    object: u16,
    top: u16,
    bottom: u16,
    /// One end of the rows of the block of [`BIN_BLOCK`] bins it opens (see [`block_rows`]):
    /// in a block's first bin the first row any of its bins may touch, in its second the last
    /// (room the alignment of `triangle` leaves: a bin is no larger for it).
    block_row: u16,
}

/// An object's bins are read in blocks of this many, from its first on: a band skips each
/// block none of whose bins touches its rows after one test, so that it reads the bins of
/// its own rows and one test per block of the others.
const BIN_BLOCK: usize = 32;

/// The first and last rows that any bin of `block` (a block of [`BIN_BLOCK`] bins, an
/// object's last one possibly shorter) may touch.
#[inline(always)]
fn block_rows(block: &[Bin]) -> (u16, u16) {
    match block {
        [first, second, ..] => (first.block_row, second.block_row),
        [only] => (only.top, only.bottom),
        [] => (u16::MAX, 0),
    }
}

impl Bin {
    /// An unused entry (storage is overwritten before it is read).
    pub const EMPTY: Bin = Bin {
        triangle: 0,
        object: 0,
        top: 0,
        bottom: 0,
        block_row: 0,
    };

    /// The tag of the objects whose triangle this is (see `Prepared::bin`).
    pub(crate) fn object(&self) -> u16 {
        self.object
    }

    /// The rows of a triangle that crosses a clip plane: all of them (its screen rows are
    /// known only once it is clipped). No other bin's bottom row is `u16::MAX`.
    const EVERY_ROW: (u16, u16) = (0, u16::MAX);
}

/// Per-object constants for drawing.
struct ObjectSetup<'o, const N: usize> {
    object: &'o Object<'o>,
    vertices: &'o [ScreenVertex],
    frame: &'o Frame,
    /// Computed when the first triangle of the object needs clipping (most objects need none).
    clip_from_model: Cell<Option<Mat4>>,
    normal_matrix: [[i32; 3]; 3],
    /// For flat shading, the lights seen from model space when the model matrix is a rotation
    /// times a scale (`in_model_space`: face normals then need no normal matrix); otherwise
    /// faces read the scene's (see [`lighting`](Self::lighting)).
    model_lighting: Lighting<N>,
    in_model_space: bool,
    scene_lighting: &'o Lighting<N>,
    /// The mesh's kept face normals, where the shading reads them ([`Flat`]): lit in model
    /// space, by [`Normalize::Newton`] (what they keep); none otherwise. An empty slice rather
    /// than `None`: a front face's normal is one bounds test.
    ///
    /// [`Flat`]: crate::shade::Flat
    face_normals: &'o [FaceNormal],
    /// Every vertex lies inside every clip plane: no triangle needs its outcodes read.
    inside: bool,
    /// The target holds a band of the frame's rows, not all of them (see `fill_face`).
    band: bool,
}

impl<const N: usize> ObjectSetup<'_, N> {
    /// The lights its faces are lit by: one place for every face to read them.
    #[inline(always)]
    fn lighting(&self) -> &Lighting<N> {
        if self.in_model_space {
            &self.model_lighting
        } else {
            self.scene_lighting
        }
    }

    /// The cached vertices of triangle `tri`; `None` if an index refers to no vertex.
    #[inline(always)]
    fn corners(&self, tri: &Triangle) -> Option<[&ScreenVertex; 3]> {
        let v = self.vertices;
        match (
            v.get(tri[0] as usize),
            v.get(tri[1] as usize),
            v.get(tri[2] as usize),
        ) {
            (Some(a), Some(b), Some(c)) => Some([a, b, c]),
            _ => None,
        }
    }

    /// The UV of vertex `index`, raw Q16.16 (zero where the mesh has none).
    #[inline(always)]
    fn uv(&self, index: u16) -> [i32; 2] {
        uv_of(self.object.mesh.uvs().unwrap_or(&[]), index)
    }

    /// The UVs of a triangle's vertices (zeros where the mesh has none), the mesh's read once
    /// and one test of the largest index bounding the three reads (the compiler drops their
    /// own): a mesh has a UV for each position, and its indices are below their number.
    #[inline(always)]
    fn uvs(&self, tri: &Triangle) -> [[i32; 2]; 3] {
        let uvs = self.object.mesh.uvs().unwrap_or(&[]);
        let [a, b, c] = *tri;
        match uvs.get(..=usize::from(a.max(b).max(c))) {
            Some(uvs) => map3(*tri, |i| uv_of(uvs, i)),
            None => [[0; 2]; 3],
        }
    }

    fn clip_from_model(&self) -> Mat4 {
        if let Some(m) = self.clip_from_model.get() {
            return m;
        }
        let m = self
            .frame
            .clip_from_model_within(&self.object.model, self.object.mesh.extent());
        self.clip_from_model.set(Some(m));
        m
    }

    fn clip_vertex(&self, index: u16) -> ClipVertex {
        let p = self
            .object
            .mesh
            .positions()
            .get(index as usize)
            .copied()
            .unwrap_or_default();
        let rgb = self
            .vertices
            .get(index as usize)
            .map(|v| v.rgb)
            .unwrap_or_default();
        ClipVertex {
            c: self
                .clip_from_model()
                .transform_within(p.to_bits(), self.object.mesh.extent()),
            varying: {
                let [r, g, b] = rgb.map(|c| (c as i32) << 8);
                let [u, v] = self.uv(index);
                [r, g, b, u, v]
            },
        }
    }
}

/// UV `index` of `uvs`, raw Q16.16 (zero past their end).
#[inline(always)]
fn uv_of(uvs: &[Uv], index: u16) -> [i32; 2] {
    uvs.get(index as usize)
        .map_or([0; 2], |[u, v]| [u.to_bits(), v.to_bits()])
}

/// Rows `[ceil((min−8)/16), ceil((max−8)/16))` of a triangle overlap the clip's rows.
fn rows_overlap(p: &[ScreenPoint; 3], clip: &PixelRect) -> bool {
    let ymin = p.iter().map(|q| q.y).min().unwrap_or(0);
    let ymax = p.iter().map(|q| q.y).max().unwrap_or(0);
    // Row py is sampled at 16·py + 8; it can be covered only if ymin ≤ 16·py + 8 < ymax.
    let first = crate::raster::first_centre_from(ymin as i64);
    let end = crate::raster::first_centre_from(ymax as i64);
    first < clip.y1 as i64 && end > clip.y0 as i64
}

fn fill<T: RasterTarget, P: Paint, B: Carrier>(
    target: &mut T,
    triangle: &ScreenTriangle,
    paint: &P,
    carries: &mut B,
    stats: &mut Stats,
) -> Result<(), T::Error> {
    bump(&mut stats.drawn);
    paint.visit(Fill {
        target,
        triangle,
        carries,
        stats,
    })
}

/// A triangle's fill, handed its paint's form by [`Paint::visit`].
struct Fill<'a, T, B> {
    target: &'a mut T,
    triangle: &'a ScreenTriangle,
    carries: &'a mut B,
    stats: &'a mut Stats,
}

impl<T: RasterTarget, B: Carrier> PaintUser for Fill<'_, T, B> {
    type Output = Result<(), T::Error>;
    #[inline(always)]
    fn with<P: Paint>(self, paint: &P) -> Self::Output {
        let Fill {
            target,
            triangle,
            carries,
            stats,
        } = self;
        // A band that carries triangles into the next fills solid ones its own way (a solid
        // paint's colour is a constant).
        if let Some(rgb) = paint.solid().filter(|_| P::SOLID) {
            let carried = carries.with_carries(|c| target.fill_carrying(triangle, rgb, c, stats));
            if let Some(done) = carried {
                return done;
            }
        }
        target.fill_triangle(triangle, paint, stats)
    }
}

impl<const N: usize, S: Shading> Prepared<'_, '_, N, S> {
    fn objects(&self, band: bool) -> impl Iterator<Item = ObjectSetup<'_, N>> {
        let mut offset = 0usize;
        let objects = self.scene.objects.iter().enumerate();
        objects.map(move |(k, object)| {
            let n = object.mesh.positions().len();
            let vertices = self
                .cache
                .get(offset..offset.saturating_add(n))
                .unwrap_or(&[]);
            offset = offset.saturating_add(n);
            let normal_matrix = object.model.normal_matrix();
            // Only flat shading lights faces (per-vertex shading lights the vertices in world
            // space, in `prepare`; unlit shading and wireframes need no lights).
            let model_lighting = if S::FACE_LIGHTING {
                self.scene.lighting.in_model_space(&normal_matrix)
            } else {
                None
            };
            let newton = self.frame.precision.normalize() == Normalize::Newton;
            let in_model_space = model_lighting.is_some();
            let face_normals = if in_model_space && newton && S::KEPT_FACE_NORMALS {
                object.mesh.face_normals()
            } else {
                None
            }
            .unwrap_or(&[]);
            ObjectSetup {
                object,
                vertices,
                frame: &self.frame,
                clip_from_model: Cell::new(None),
                normal_matrix,
                model_lighting: model_lighting.unwrap_or(Lighting::new(LightColor::BLACK)),
                in_model_space,
                scene_lighting: &self.scene.lighting,
                face_normals,
                // Bit k of `inside` (none from the 65th object on).
                inside: k < 64 && self.inside & 1 << k != 0,
                band,
            }
        })
    }

    /// Fills every triangle of the scene into `target` (a [`ColorDepth`] frame or band, or a
    /// [`Direct`](crate::buffer::Direct) draw target). Returns what was drawn, or the target's
    /// first error.
    pub fn draw<T: RasterTarget>(&self, target: &mut T) -> Result<Stats, T::Error> {
        // A frame drawn by walking every triangle carries nothing from band to band.
        self.draw_with(target, &mut ())
    }

    /// [`draw`](Self::draw), carrying solid triangles into the next band by `carries` (see
    /// [`Carries`](crate::buffer::Carries)) where it is one.
    pub(crate) fn draw_with<T: RasterTarget, B: Carrier>(
        &self,
        target: &mut T,
        carries: &mut B,
    ) -> Result<Stats, T::Error> {
        let cull = self.frame.cull;
        let mut stats = Stats::default();
        let map = ScreenMap::new(&self.frame.viewport, &self.frame.precision);
        // Found once per drawing, not per triangle.
        let clip = target.clip();
        let band = clip.y0 > 0 || clip.y1 < self.frame.viewport.height() as i32;
        for setup in self.objects(band) {
            let triangles = setup.object.mesh.triangles();
            // Counted once per object (an error returns no statistics at all).
            add_count(&mut stats.primitives, triangles.len());
            let inside = setup.inside;
            for (k, tri) in triangles.iter().enumerate() {
                self.triangle(
                    target,
                    &setup,
                    (k, tri),
                    inside,
                    cull,
                    &map,
                    carries,
                    &mut stats,
                )?;
            }
        }
        Ok(stats)
    }

    /// One triangle of the walk: fetched, tested against the clip planes (unless its object is
    /// `inside` them all), culled, clipped where it crosses a plane, shaded and filled.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn triangle<T: RasterTarget, B: Carrier>(
        &self,
        target: &mut T,
        setup: &ObjectSetup<'_, N>,
        (k, tri): (usize, &Triangle),
        inside: bool,
        cull: Cull,
        map: &ScreenMap,
        carries: &mut B,
        stats: &mut Stats,
    ) -> Result<(), T::Error> {
        let Some([a, b, c]) = setup.corners(tri) else {
            bump(&mut stats.invalid);
            return Ok(());
        };
        // Inside every plane first (the usual case), then outside one of them. An object that
        // `prepare` found inside every plane reads no outcode.
        if inside || a.outcode | b.outcode | c.outcode == 0 {
            // Culled before anything else is gathered: half the triangles of a closed
            // mesh end here.
            let area = inside_area2(&[a.point(), b.point(), c.point()]);
            if !kept(cull, area, stats) {
                return Ok(());
            }
            // Written out: at the firmware's opt-level "s" `array::map` stays a loop.
            let v = [(a.point(), a.z), (b.point(), b.z), (c.point(), c.z)];
            // Vertex colours matter only to per-vertex shading, UVs to textures.
            let (rgb, uv);
            let varyings = Varyings {
                rgb: if S::PER_VERTEX {
                    let lit = |v: &ScreenVertex| map3(v.rgb, |c| c as i32);
                    rgb = [lit(a), lit(b), lit(c)];
                    &rgb
                } else {
                    NO_VARYINGS.rgb
                },
                uv: if S::TEXTURED {
                    uv = setup.uvs(tri);
                    &uv
                } else {
                    NO_VARYINGS.uv
                },
            };
            self.fill_face(
                target,
                setup,
                (Self::face_normal(setup, k), tri),
                &v,
                varyings,
                area,
                carries,
                stats,
            )?;
            return Ok(());
        }
        if a.outcode & b.outcode & c.outcode != 0 {
            bump(&mut stats.outside);
            return Ok(());
        }
        let planes = a.outcode | b.outcode | c.outcode;
        self.fill_clipped(target, setup, (k, tri), planes, map, carries, stats)
    }

    /// Bins the frame: every triangle that may cover a pixel goes into `bins` (from `*len` on)
    /// with the rows it may touch, tagged `tag` plus its object's index in the scene; invalid,
    /// outside, culled and degenerate ones and those that cover no pixel row are counted in
    /// `stats` instead. A triangle that crosses a clip plane is binned for every row (its
    /// clipping and culling wait for the draw). An object's bins are in blocks of
    /// [`BIN_BLOCK`] from its first, each with its rows (see [`block_rows`]). False when
    /// `bins` is full: the frame must then be drawn by [`draw`](Self::draw) for every band.
    pub(crate) fn bin(
        &self,
        tag: u16,
        bins: &mut [Bin],
        len: &mut usize,
        stats: &mut Stats,
    ) -> bool {
        let cull = self.frame.cull;
        for (j, setup) in self.objects(false).enumerate() {
            let object = tag.saturating_add(u16::try_from(j).unwrap_or(u16::MAX));
            let start = *len;
            let triangles = setup.object.mesh.triangles();
            add_count(&mut stats.primitives, triangles.len());
            for (k, tri) in triangles.iter().enumerate() {
                let Some([a, b, c]) = setup.corners(tri) else {
                    bump(&mut stats.invalid);
                    continue;
                };
                let rows = if setup.inside || a.outcode | b.outcode | c.outcode == 0 {
                    let p = [a.point(), b.point(), c.point()];
                    if !kept(cull, inside_area2(&p), stats) {
                        continue;
                    }
                    // Rows whose centres (16·row + 8) lie in [min y, max y): see `rows_overlap`.
                    // Written out: at the firmware's opt-level "s" an iterator's `min` over
                    // three stays a loop.
                    let ymin = p[0].y.min(p[1].y).min(p[2].y);
                    let ymax = p[0].y.max(p[1].y).max(p[2].y);
                    // Inside every clip plane: coordinates within the guard band, words.
                    let first = crate::raster::first_centre_from32(ymin);
                    let end = crate::raster::first_centre_from32(ymax);
                    // Below `u16::MAX`, the bottom row of clipped triangles alone.
                    let row = |r: i32| r.clamp(0, i32::from(u16::MAX) - 1) as u16;
                    if end <= first.max(0) || first >= i32::from(u16::MAX) {
                        continue;
                    }
                    (row(first), row(end - 1))
                } else if a.outcode & b.outcode & c.outcode != 0 {
                    bump(&mut stats.outside);
                    continue;
                } else {
                    bump(&mut stats.clipped);
                    Bin::EVERY_ROW
                };
                let Some(slot) = bins.get_mut(*len) else {
                    return false;
                };
                *slot = Bin {
                    triangle: u32::try_from(k).unwrap_or(u32::MAX),
                    object,
                    top: rows.0,
                    bottom: rows.1,
                    block_row: 0,
                };
                *len += 1;
            }
            // Each block's rows in its first two bins (a block of one has its bin's own).
            for block in bins
                .get_mut(start..*len)
                .unwrap_or(&mut [])
                .chunks_mut(BIN_BLOCK)
            {
                let rows = block.iter().fold((u16::MAX, 0), |(first, last), bin| {
                    (first.min(bin.top), last.max(bin.bottom))
                });
                if let [first, second, ..] = block {
                    (first.block_row, second.block_row) = rows;
                }
            }
        }
        true
    }

    /// Fills the triangles of `bins` tagged for this frame (`tag` plus an object's index, as
    /// [`bin`](Self::bin) wrote them) whose rows meet the target's, in the order `bin` wrote
    /// them (the mesh's: triangles at equal depths then cover each other as in one pass).
    /// A solid triangle the band before stopped at its last row and `carries` holds goes on
    /// from there. Counts only what it draws (`drawn`, `carried`, `fragments`, `written`): the
    /// rest was counted when binning.
    pub(crate) fn draw_binned<T: RasterTarget, B: Carrier>(
        &self,
        target: &mut T,
        tag: u16,
        bins: &[Bin],
        carries: &mut B,
    ) -> Result<Stats, T::Error> {
        let clip = target.clip();
        let (y0, y1) = (clip.y0, clip.y1);
        let map = ScreenMap::new(&self.frame.viewport, &self.frame.precision);
        let band = y0 > 0 || y1 < self.frame.viewport.height() as i32;
        let mut stats = Stats::default();
        // Counts of a triangle's second look (clipped again, culled after clipping) go here.
        let mut again = Stats::default();
        let meets = |bin: &Bin| i32::from(bin.top) < y1 && i32::from(bin.bottom) >= y0;
        let mut rest = bins;
        while let Some(object) = rest.first().map(Bin::object) {
            // An object's bins are a run; only an object that meets the band's rows is set up.
            let (run, after) = rest.split_at(rest.partition_point(|b| b.object == object));
            rest = after;
            // Set up at the first bin that meets the band's rows.
            let mut set_up = None;
            'run: for block in run.chunks(BIN_BLOCK) {
                // Written apart from `meets`: through it, the compiled scan took more.
                let (first, last) = block_rows(block);
                if i32::from(first) >= y1 || i32::from(last) < y0 {
                    continue;
                }
                for bin in block {
                    if !meets(bin) {
                        continue;
                    }
                    let setup = match &mut set_up {
                        Some(setup) => setup,
                        None => {
                            let found = object
                                .checked_sub(tag)
                                .and_then(|j| self.objects(band).nth(j.into()));
                            let Some(setup) = found else {
                                break 'run;
                            };
                            set_up.insert(setup)
                        }
                    };
                    let triangles = setup.object.mesh.triangles();
                    // A bin's rows are its triangle's own: only the pieces of a clipped one
                    // (binned for every row) are tested against the band's rows again.
                    let clipped = bin.bottom == Bin::EVERY_ROW.1;
                    setup.band = band && clipped;
                    // A solid triangle the band before carried goes on where it stopped, with
                    // nothing set up again (the pieces of a clipped one are not carried).
                    let key = (bin.object, bin.triangle);
                    if carries.meet((!clipped).then_some(key)) {
                        bump(&mut again.drawn);
                        bump(&mut again.carried);
                        if let Some(done) =
                            carries.with_carries(|c| target.resume_carried(c, &mut again))
                        {
                            done?;
                        }
                        continue;
                    }
                    let k = bin.triangle as usize;
                    let Some(tri) = triangles.get(k) else {
                        continue;
                    };
                    self.triangle(
                        target,
                        setup,
                        (k, tri),
                        setup.inside,
                        self.frame.cull,
                        &map,
                        carries,
                        &mut again,
                    )?;
                }
            }
        }
        stats.drawn = again.drawn;
        stats.carried = again.carried;
        stats.fragments = again.fragments;
        stats.written = again.written;
        Ok(stats)
    }

    /// Triangle `k`'s kept face normal where the shading reads it (none otherwise: a constant
    /// for the others, whose code then holds nothing of it).
    fn face_normal<'o>(setup: &ObjectSetup<'o, N>, k: usize) -> Option<&'o FaceNormal> {
        if S::KEPT_FACE_NORMALS {
            setup.face_normals.get(k)
        } else {
            None
        }
    }

    /// Clips a triangle that crosses a clip plane (`planes`: those its vertices are outside of)
    /// and fills the fan of what is left. Few triangles need it: out of line, its code does
    /// not move the registers of the triangle walk's loop.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn fill_clipped<T: RasterTarget, B: Carrier>(
        &self,
        target: &mut T,
        setup: &ObjectSetup<'_, N>,
        (k, tri): (usize, &Triangle),
        planes: u8,
        map: &ScreenMap,
        carries: &mut B,
        stats: &mut Stats,
    ) -> Result<(), T::Error> {
        bump(&mut stats.clipped);
        let poly = clip_polygon(tri.map(|i| setup.clip_vertex(i)), planes, map);
        let Some(projected) = project_polygon(&poly, map) else {
            bump(&mut stats.degenerate);
            return Ok(());
        };
        // The polygon faces one way as a whole: a sliver of its fan that snapping turned
        // over is culled with the rest (it would cover pixels outside the polygon).
        let area = fan_area(&projected);
        if !kept(self.frame.cull, area, stats) {
            return Ok(());
        }
        let facing = if area < 0 { Cull::Back } else { Cull::Front };
        // A convex polygon: a fan from its first vertex.
        let Some((first, rest)) = projected.split_first() else {
            return Ok(());
        };
        for pair in rest.windows(2) {
            if let (Some(v1), Some(v2)) = (pair.first(), pair.get(1)) {
                let v = [(first.0, first.1), (v1.0, v1.1), (v2.0, v2.1)];
                let area = area2(&[v[0].0, v[1].0, v[2].0]);
                if kept(facing, area, stats) {
                    let varyings = Varyings {
                        rgb: &[first.2, v1.2, v2.2],
                        uv: &[first.3, v1.3, v2.3],
                    };
                    let face = (Self::face_normal(setup, k), tri);
                    self.fill_face(target, setup, face, &v, varyings, area, carries, stats)?;
                }
            }
        }
        Ok(())
    }

    /// Shades and fills one screen triangle of `tri` (the whole triangle, or a piece of it after
    /// clipping), which culling kept: vertices are (snapped position, depth), `varyings`
    /// their lit colours and UVs, `area` its doubled signed area.
    // Not inlined: one call per triangle costs little and keeps the stage measurable.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn fill_face<T: RasterTarget, B: Carrier>(
        &self,
        target: &mut T,
        setup: &ObjectSetup<'_, N>,
        (kept, tri): (Option<&FaceNormal>, &Triangle),
        v: &[(ScreenPoint, i32); 3],
        varyings: Varyings<'_>,
        area: i64,
        carries: &mut B,
        stats: &mut Stats,
    ) -> Result<(), T::Error> {
        let p = map3(*v, |v| v.0);
        // Culling came first so that every band of a frame counts the same culled triangles.
        // A band skips shading the triangles of other bands; a whole frame has none to skip.
        if setup.band && !rows_overlap(&p, &target.clip()) {
            return Ok(());
        }
        // Made before the paint, which reads its points.
        let triangle = ScreenTriangle::new(p, map3(*v, |v| v.1), area);
        // Flat shading in model space where the model matrix allows it (see `in_model_space`).
        let lighting = setup.lighting();
        let normal_matrix = (!setup.in_model_space).then_some(&setup.normal_matrix);
        let face = FaceInputs {
            base: setup.object.color,
            positions: setup.object.mesh.positions(),
            indices: tri,
            face_normal: if S::KEPT_FACE_NORMALS { kept } else { None },
            extents: (setup.object.mesh.extent(), setup.object.mesh.edge_extent()),
            model_matrix: &setup.object.model,
            normal_matrix,
            normalize: self.frame.precision.normalize(),
            vertices: v,
            screen: triangle.points(),
            // Read by per-vertex shading only: for the others the argument is dead, and the
            // compiler drops it from the call.
            colors: if S::PER_VERTEX {
                varyings.rgb
            } else {
                NO_VARYINGS.rgb
            },
            uvs: if S::TEXTURED {
                varyings.uv
            } else {
                NO_VARYINGS.uv
            },
            inverse_w_offset: self.frame.inverse_w_offset,
            area2: area,
            channels: T::CHANNELS,
        };
        // Gouraud needs per-vertex normals; without them the object is shaded flat.
        if !S::PER_VERTEX || setup.object.mesh.normals().is_some() {
            let paint = self.shading.paint(&face, lighting);
            fill(target, &triangle, &paint, carries, stats)
        } else {
            let paint = self.shading.fallback(&face, lighting);
            fill(target, &triangle, &paint, carries, stats)
        }
    }

    /// Draws edges into any `DrawTarget`, in each object's colour, with no depth test: for a
    /// mesh with an edge list, every listed edge once; otherwise the three edges of every
    /// triangle that survives culling. Lines follow the column-centre rule with the start pixel
    /// drawn and the end pixel not (see [`raster`](crate::raster)).
    pub fn draw_wireframe<D>(&self, target: &mut D) -> Result<Stats, D::Error>
    where
        D: DrawTarget,
        D::Color: From<Rgb888>,
    {
        let clip = PixelRect::from_rectangle(&target.bounding_box());
        self.wireframe(&mut Plain { target, clip })
    }

    /// [`draw_wireframe`](Self::draw_wireframe) into a z-buffered target: each line's pixels
    /// depth-tested against what the target holds (its stats count only what it draws).
    pub(crate) fn draw_wireframe_tested<T: LineSink>(
        &self,
        target: &mut T,
    ) -> Result<Stats, T::Error> {
        let mut all = self.wireframe(target)?;
        all.primitives = 0;
        all.invalid = 0;
        all.outside = 0;
        all.clipped = 0;
        all.culled = 0;
        all.degenerate = 0;
        Ok(all)
    }

    /// The wireframe walk, into any [`LineSink`].
    fn wireframe<L: LineSink>(&self, target: &mut L) -> Result<Stats, L::Error> {
        let mut stats = Stats::default();
        let map = ScreenMap::new(&self.frame.viewport, &self.frame.precision);
        for setup in self.objects(false) {
            let color = target.color(setup.object.color);
            let mut segment = |i: u16, j: u16, stats: &mut Stats| -> Result<(), L::Error> {
                let (Some(a), Some(b)) = (
                    setup.vertices.get(i as usize),
                    setup.vertices.get(j as usize),
                ) else {
                    bump(&mut stats.invalid);
                    return Ok(());
                };
                if a.outcode & b.outcode != 0 {
                    bump(&mut stats.outside);
                    return Ok(());
                }
                let (pa, pb) = if a.outcode | b.outcode == 0 {
                    ((a.point(), a.z), (b.point(), b.z))
                } else {
                    bump(&mut stats.clipped);
                    let Some((ca, cb)) = clip_segment(
                        setup.clip_vertex(i),
                        setup.clip_vertex(j),
                        a.outcode | b.outcode,
                        &map,
                    ) else {
                        return Ok(());
                    };
                    let (Some(pa), Some(pb)) = (project(ca.c, &map), project(cb.c, &map)) else {
                        return Ok(());
                    };
                    (pa, pb)
                };
                bump(&mut stats.drawn);
                target.line(pa, pb, color, stats)
            };
            if let Some(edges) = setup.object.mesh.edges() {
                add_count(&mut stats.primitives, edges.len());
                for e in edges {
                    segment(e[0], e[1], &mut stats)?;
                }
                continue;
            }
            let triangles = setup.object.mesh.triangles();
            add_count(&mut stats.primitives, triangles.len());
            for tri in triangles {
                let Some([a, b, c]) = setup.corners(tri) else {
                    bump(&mut stats.invalid);
                    continue;
                };
                // Inside every plane first (the usual case), then outside one of them.
                let planes = a.outcode | b.outcode | c.outcode;
                let area = if planes == 0 {
                    inside_area2(&[a.point(), b.point(), c.point()])
                } else if a.outcode & b.outcode & c.outcode != 0 {
                    bump(&mut stats.outside);
                    continue;
                } else {
                    let poly = clip_polygon(tri.map(|i| setup.clip_vertex(i)), planes, &map);
                    polygon_area(&poly, &map)
                };
                if !kept(self.frame.cull, area, &mut stats) {
                    continue;
                }
                segment(tri[0], tri[1], &mut stats)?;
                segment(tri[1], tri[2], &mut stats)?;
                segment(tri[2], tri[0], &mut stats)?;
            }
        }
        Ok(stats)
    }
}

/// Where the wireframe walk puts its lines: any `DrawTarget` as it is ([`Plain`]), or a
/// z-buffered target that depth-tests each pixel.
pub(crate) trait LineSink {
    /// The error a write can return.
    type Error;
    /// A colour as the lines take it (converted once per object).
    type Color: Copy;
    /// `rgb` as the lines take it.
    fn color(&self, rgb: Rgb888) -> Self::Color;
    /// Draws the line from `a` to `b` (snapped position and Q1.30 depth), counting its
    /// fragments and writes.
    fn line(
        &mut self,
        a: (ScreenPoint, i32),
        b: (ScreenPoint, i32),
        color: Self::Color,
        stats: &mut Stats,
    ) -> Result<(), Self::Error>;
}

/// A `DrawTarget` taking lines with no depth test, clipped to its bounding box.
struct Plain<'t, D> {
    target: &'t mut D,
    clip: PixelRect,
}

impl<D> LineSink for Plain<'_, D>
where
    D: DrawTarget,
    D::Color: From<Rgb888>,
{
    type Error = D::Error;
    type Color = D::Color;

    fn color(&self, rgb: Rgb888) -> D::Color {
        D::Color::from(rgb)
    }

    fn line(
        &mut self,
        (a, _): (ScreenPoint, i32),
        (b, _): (ScreenPoint, i32),
        color: D::Color,
        stats: &mut Stats,
    ) -> Result<(), D::Error> {
        let pixels = line_pixels(a, b, self.clip);
        let n = pixels.len() as u32;
        stats.fragments = stats.fragments.saturating_add(n);
        stats.written = stats.written.saturating_add(n);
        self.target.draw_iter(pixels.map(|p| Pixel(p, color)))
    }
}

impl<C, D, Q, T, K> LineSink for ColorDepth<'_, '_, C, D, Q, T, K>
where
    C: TargetColor,
    D: DepthFormat,
    Q: Quantize<C>,
    T: DepthTest,
    K: FragmentCount,
{
    type Error = core::convert::Infallible;
    type Color = Rgb888;

    fn color(&self, rgb: Rgb888) -> Rgb888 {
        rgb
    }

    fn line(
        &mut self,
        a: (ScreenPoint, i32),
        b: (ScreenPoint, i32),
        color: Rgb888,
        stats: &mut Stats,
    ) -> Result<(), Self::Error> {
        self.depth_line(a, b, color, stats);
        Ok(())
    }
}

type Projected = heapless::Vec<(ScreenPoint, i32, [i32; 3], [i32; 2]), 9>;

/// Projects a clipped polygon; `None` if it is empty or a vertex has w ≤ 0.
fn project_polygon(poly: &Polygon, map: &ScreenMap) -> Option<Projected> {
    if poly.len() < 3 {
        return None;
    }
    let mut out = Projected::new();
    for v in poly {
        let (p, z) = project(v.c, map)?;
        let _ = out.push((p, z, v.rgb(), v.uv()));
    }
    Some(out)
}

/// Doubled signed screen area of a clipped polygon (0 if it is empty).
fn polygon_area(poly: &Polygon, map: &ScreenMap) -> i64 {
    project_polygon(poly, map).map_or(0, |p| fan_area(&p))
}

/// Doubled signed area of a projected polygon (the sum over its fan).
fn fan_area(p: &Projected) -> i64 {
    let Some((first, rest)) = p.split_first() else {
        return 0;
    };
    rest.windows(2)
        .filter_map(|w| Some(area2(&[first.0, w.first()?.0, w.get(1)?.0])))
        .fold(0i64, |s, a| s.saturating_add(a))
}

#[cfg(test)]
mod tests {
    use std::vec;

    use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};

    use super::*;
    use crate::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
    use crate::camera::LookAt;
    use crate::math::{Angle, Scalar, Vec3};
    use crate::mesh::CUBE;
    use crate::pipeline::vertex::GUARD;
    use crate::pipeline::Frame;
    use crate::projection::{Projection, Viewport};
    use crate::raster::short_sides_area;
    use crate::scene::{LightColor, Scene};
    use crate::shade::Flat;

    /// The cross product in words of triangles whose vertices lie within `GUARD` of a screen
    /// centre (every vertex inside every clip plane) is the exact doubled area: at random
    /// and at the band's corners, whose sides are the longest (2·`GUARD`).
    #[test]
    fn inside_triangles_take_their_area_in_words() {
        let g = GUARD as i32;
        let centre = ScreenPoint::new(2560, 1920);
        let at = |x: i32, y: i32| ScreenPoint::new(centre.x + x, centre.y + y);
        let corners = [at(-g, -g), at(g, -g), at(g, g), at(-g, g)];
        let mut triangles = vec::Vec::new();
        for a in corners {
            for b in corners {
                for c in corners {
                    triangles.push([a, b, c]);
                }
            }
        }
        let mut rng = crate::testing::XorShift(0x5DEE_CE66_D1CE_4E5Bu64);
        for _ in 0..100_000 {
            let mut point = || {
                let mut coordinate = || (rng.next_u64() % (2 * g as u64 + 1)) as i32 - g;
                at(coordinate(), coordinate())
            };
            triangles.push([point(), point(), point()]);
        }
        for p in triangles {
            assert_eq!(short_sides_area(p[0], p[1], p[2]), area2(&p), "{p:?}");
        }
    }

    /// Binning writes each block's first and last rows into its first two bins, blocks counted
    /// from each object's first bin; a band reads only the blocks that meet its rows, and draws
    /// what it draws reading every bin: three objects (two tori, one turned to face the
    /// camera, and a cube) in bands of 4 to 48 rows, some blocks outside some bands.
    #[test]
    fn bands_skip_the_blocks_of_bins_outside_their_rows() {
        let viewport = Viewport::new(64, 48).unwrap_or_else(|_| unreachable!());
        let view = LookAt::new(Vec3::from_int(0, 0, 4), Vec3::ZERO, Vec3::Y).view();
        let (near, far) = (Scalar::from_num(1), Scalar::from_num(10));
        let projection =
            Projection::perspective(Angle::from_degrees(60), viewport.aspect(), near, far);
        let frame = Frame::new(
            &view.unwrap_or_else(|_| unreachable!()),
            &projection.unwrap_or_else(|_| unreachable!()),
            viewport,
        );
        let (mut p, mut n) = (vec![Vec3::ZERO; 24 * 12], vec![Vec3::ZERO; 24 * 12]);
        let mut t = vec![Triangle::default(); 2 * 24 * 12];
        let (major, minor) = (Scalar::from_num(1), Scalar::from_bits(1 << 15));
        let torus = crate::mesh::torus(major, minor, 24, 12, &mut p, &mut n, &mut t);
        let torus = torus.unwrap_or_else(|_| unreachable!());
        let objects = [
            Object::new(
                &torus,
                Mat4::rotation_x(Angle::from_degrees(70)),
                Rgb888::RED,
            ),
            Object::new(&CUBE, Mat4::IDENTITY, Rgb888::WHITE),
            Object::new(
                &torus,
                Mat4::rotation_x(Angle::from_degrees(10)),
                Rgb888::BLUE,
            ),
        ];
        let scene: Scene<'_, 1> = Scene::new(
            &objects,
            Lighting::new(LightColor::gray(Scalar::from_num(1))),
        );
        let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
        let prepared = frame.prepare(&scene, &mut cache, Flat);
        let prepared = prepared.unwrap_or_else(|_| unreachable!());
        let (mut bins, mut len) = (vec![Bin::EMPTY; 2 * 2 * 24 * 12 + 12], 0);
        assert!(prepared.bin(0, &mut bins, &mut len, &mut Stats::default()));
        bins.truncate(len);
        let blocks = || {
            bins.chunk_by(|a, b| a.object == b.object)
                .flat_map(|run| run.chunks(BIN_BLOCK))
        };
        for block in blocks() {
            let first = block.iter().map(|b| b.top).min();
            let last = block.iter().map(|b| b.bottom).max();
            assert_eq!(Some(block_rows(block)), first.zip(last));
        }
        assert!(blocks().count() > 2 * objects.len(), "{len} bins");
        // The same bins with every block marked as meeting every row.
        let mut every = bins.clone();
        for run in every.chunk_by_mut(|a, b| a.object == b.object) {
            for block in run.chunks_mut(BIN_BLOCK) {
                if let [first, second, ..] = block {
                    (first.block_row, second.block_row) = (0, u16::MAX);
                }
            }
        }
        let mut skipped = 0;
        for rows in [4, 5, 8, 12, 48] {
            for y0 in (0..48).step_by(rows) {
                let meets = |(first, last): (u16, u16)| {
                    i32::from(first) < y0 as i32 + rows as i32 && i32::from(last) >= y0 as i32
                };
                skipped += blocks().filter(|b| !meets(block_rows(b))).count();
                let band = |bins: &[Bin]| {
                    let (mut c, mut d) =
                        (vec![Rgb565::BLACK; 64 * rows], vec![u16::MAX; 64 * rows]);
                    let color = FrameBuffer::new(&mut c, 64, rows as u32);
                    let mut color = color.unwrap_or_else(|_| unreachable!());
                    let depth = DepthBuffer::new(&mut d, 64, rows as u32);
                    let mut depth = depth.unwrap_or_else(|_| unreachable!());
                    let target = ColorDepth::band(&mut color, &mut depth, y0 as u32);
                    let mut target = target.unwrap_or_else(|_| unreachable!());
                    let stats = prepared.draw_binned(&mut target, 0, bins, &mut ());
                    (stats.unwrap_or_else(|e| match e {}), c)
                };
                let drawn = band(&bins);
                assert!(drawn == band(&every), "rows {y0} to {}", y0 + rows);
            }
        }
        assert!(skipped > 0);
    }

    /// The frame's pixels and statistics, drawn into fresh 64x48 buffers.
    fn drawn(p: &Prepared<'_, '_, 1, Flat>) -> (Stats, vec::Vec<Rgb565>) {
        let (mut c, mut d) = (vec![Rgb565::BLACK; 64 * 48], vec![u16::MAX; 64 * 48]);
        let mut color = FrameBuffer::new(&mut c, 64, 48).unwrap_or_else(|_| unreachable!());
        let mut depth = DepthBuffer::new(&mut d, 64, 48).unwrap_or_else(|_| unreachable!());
        let target = ColorDepth::new(&mut color, &mut depth);
        let stats = p.draw(&mut target.unwrap_or_else(|_| unreachable!()));
        (stats.unwrap_or_else(|e| match e {}), c)
    }

    /// An object whose every vertex lies inside every clip plane is marked so by `prepare`,
    /// and the triangle walk reads none of its outcodes; an object across the near plane is
    /// not marked, and is clipped. With every mark cleared (each triangle's outcodes read),
    /// the frame and its statistics are the same. Of 70 objects, the first 64 are marked.
    #[test]
    fn objects_inside_every_plane_skip_their_outcodes() {
        let viewport = Viewport::new(64, 48).unwrap_or_else(|_| unreachable!());
        let eye = Vec3::from_int(0, 0, 3);
        let view = LookAt::new(eye, Vec3::ZERO, Vec3::Y).view();
        let view = view.unwrap_or_else(|_| unreachable!());
        let (near, far) = (Scalar::from_num(1), Scalar::from_num(10));
        let projection =
            Projection::perspective(Angle::from_degrees(60), viewport.aspect(), near, far);
        let frame = Frame::new(
            &view,
            &projection.unwrap_or_else(|_| unreachable!()),
            viewport,
        );
        // The second cube spans view depths 0 to 2: across the near plane.
        let objects = [
            Object::new(&CUBE, Mat4::IDENTITY, Rgb888::WHITE),
            Object::new(
                &CUBE,
                Mat4::translation(Vec3::from_int(1, 0, 2)),
                Rgb888::RED,
            ),
        ];
        let scene = Scene::new(
            &objects,
            Lighting::new(LightColor::gray(Scalar::from_num(1))),
        );
        let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
        let prepared = frame.prepare(&scene, &mut cache, Flat);
        let prepared = prepared.unwrap_or_else(|_| unreachable!());
        assert_eq!(prepared.inside, 0b01);
        let marked = drawn(&prepared);
        let unmarked = Prepared {
            inside: 0,
            ..prepared
        };
        assert!(marked.0.clipped > 0 && marked.0.drawn > 0, "{:?}", marked.0);
        assert!(marked == drawn(&unmarked));
        // Only the first 64 objects have a bit: the others read their outcodes.
        let many = [Object::new(&CUBE, Mat4::IDENTITY, Rgb888::WHITE); 70];
        let scene = Scene::new(&many, Lighting::new(LightColor::gray(Scalar::from_num(1))));
        let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
        let prepared = frame.prepare(&scene, &mut cache, Flat);
        let prepared = prepared.unwrap_or_else(|_| unreachable!());
        assert_eq!(prepared.inside, u64::MAX);
        assert_eq!(prepared.objects(false).filter(|o| o.inside).count(), 64);
        let marked = drawn(&prepared);
        assert_eq!(marked.0.primitives, 70 * 12);
        let unmarked = Prepared {
            inside: 0,
            ..prepared
        };
        assert!(marked == drawn(&unmarked));
    }
}

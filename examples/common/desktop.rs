//! Desktop helpers shared by the render tool, the viewer and the model golden tests: owned
//! models (loaded from OBJ files or generated), and rendering a scene into an RGB888 image in
//! one of four modes. Desktop code: it allocates, the library does not.
#![allow(dead_code)]

use std::fmt;
use std::io::Read;
use std::time::{Duration, Instant};

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, Direct, FrameBuffer};
use fixed3d::camera::{Framing, LookAt};
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{self, vertex_normals, Mesh, Object, Specular, Triangle, Uv};
use fixed3d::obj::{
    self, Aabb, ObjBuffers, ObjCounts, ObjError, ObjErrorKind, ObjStream, Placement, SplitBuffers,
    WideBounds, NO_INDEX,
};
use fixed3d::pipeline::{Cull, Frame, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{Light, Lighting, Scene};
use fixed3d::shade::{Flat, Gouraud, PerspectiveGouraud, Textured, Unlit};
use fixed3d::texture::Texture;

/// Lights a desktop scene holds at most.
pub const MAX_LIGHTS: usize = 8;

/// A mesh with owned storage and per-vertex normals.
#[derive(Clone, Debug)]
pub struct Model {
    pub name: String,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    /// One per position where the file gives texture coordinates (vertices split at seams),
    /// else none.
    pub uvs: Vec<Uv>,
    pub triangles: Vec<Triangle>,
    pub bounds: Aabb,
    /// Set when the file was outside the Q16.16 range and had to be recentred and rescaled.
    pub rescaled: Option<Placement>,
}

/// Why a model could not be loaded.
#[derive(Debug)]
pub enum LoadError {
    Io(String),
    Obj(ObjError),
    /// A file that parsed but holds no triangle (its name).
    NoTriangles(String),
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Io(e) => write!(f, "{e}"),
            LoadError::Obj(e) => write!(f, "invalid OBJ: {e}"),
            LoadError::NoTriangles(name) => write!(f, "no triangles in {name}"),
        }
    }
}

/// The longest line an OBJ file may have.
const LINE: usize = 1 << 14;
/// Bytes read at a time.
const CHUNK: usize = 1 << 16;

/// What one streamed parse of a file kept.
struct Parsed {
    positions: Vec<Vec3>,
    texcoords: Vec<Uv>,
    normals: Vec<Vec3>,
    triangles: Vec<Triangle>,
    triangle_texcoords: Vec<Triangle>,
    triangle_normals: Vec<Triangle>,
    counts: ObjCounts,
}

/// `v` grown (by doubling) to hold at least `n` elements.
fn reserve<T: Copy>(v: &mut Vec<T>, n: usize, fill: T) {
    if v.len() < n {
        let len = n.max(v.len().saturating_mul(2));
        v.resize(len, fill);
    }
}

/// Reads all of `r`, retrying interrupted reads, into `buf` up to its length; 0 at the end.
fn read_some(r: &mut impl Read, buf: &mut [u8]) -> Result<usize, LoadError> {
    loop {
        match r.read(buf) {
            Ok(n) => return Ok(n),
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(LoadError::Io(e.to_string())),
        }
    }
}

/// Parses `r` piece by piece: storage grows with what the file holds, never with its size
/// (a piece of `n` bytes ends at most `n` lines, and its lines hold at most `(n + LINE) / 2`
/// elements of any kind), and the first error ends the read.
fn parse_stream(mut r: impl Read, placement: Placement) -> Result<Parsed, LoadError> {
    let mut stream = Box::new(ObjStream::<LINE>::new(placement));
    let mut p = Parsed {
        positions: Vec::new(),
        texcoords: Vec::new(),
        normals: Vec::new(),
        triangles: Vec::new(),
        triangle_texcoords: Vec::new(),
        triangle_normals: Vec::new(),
        counts: ObjCounts::EMPTY,
    };
    let mut chunk = vec![0u8; CHUNK];
    loop {
        let n = read_some(&mut r, &mut chunk)?;
        let c = stream.counts();
        let more = (n + LINE) / 2 + 1;
        // Meshes index positions in 16 bits: the parser stops at 65,536.
        reserve(
            &mut p.positions,
            (c.positions + more).min(65_537),
            Vec3::ZERO,
        );
        reserve(&mut p.texcoords, c.texcoords + more, [Scalar::ZERO; 2]);
        reserve(&mut p.normals, c.normals + more, Vec3::ZERO);
        reserve(&mut p.triangles, c.triangles + more, [0; 3]);
        reserve(&mut p.triangle_texcoords, c.triangles + more, [0; 3]);
        reserve(&mut p.triangle_normals, c.triangles + more, [0; 3]);
        let mut out = ObjBuffers {
            positions: &mut p.positions,
            texcoords: &mut p.texcoords,
            normals: &mut p.normals,
            triangles: &mut p.triangles,
            triangle_texcoords: &mut p.triangle_texcoords,
            triangle_normals: &mut p.triangle_normals,
        };
        if n == 0 {
            p.counts = stream.finish(&mut out).map_err(LoadError::Obj)?;
            break;
        }
        let piece = chunk.get(..n).unwrap_or_default();
        stream.push(piece, &mut out).map_err(LoadError::Obj)?;
    }
    p.positions.truncate(p.counts.positions);
    p.texcoords.truncate(p.counts.texcoords);
    p.normals.truncate(p.counts.normals);
    p.triangles.truncate(p.counts.triangles);
    p.triangle_texcoords.truncate(p.counts.triangles);
    p.triangle_normals.truncate(p.counts.triangles);
    Ok(p)
}

/// The bounding box of a file's positions as written, read piece by piece: [`obj::bounds`]
/// of each `v` line (lines end as the parser ends them; one longer than `LINE` is left to the
/// parser to report).
fn stream_bounds(mut r: impl Read) -> Result<WideBounds, LoadError> {
    let mut chunk = vec![0u8; CHUNK];
    let (mut line, mut line_no, mut after_cr) = (Vec::new(), 0u32, false);
    let mut all: Option<WideBounds> = None;
    let mut end_line = |line: &mut Vec<u8>, line_no: &mut u32| -> Result<(), LoadError> {
        *line_no = line_no.saturating_add(1);
        let text = line.trim_ascii_start();
        let position =
            text.first() == Some(&b'v') && text.get(1).is_some_and(u8::is_ascii_whitespace);
        if position && line.len() <= LINE {
            let b = obj::bounds(line).map_err(|e| {
                LoadError::Obj(ObjError {
                    line: *line_no,
                    ..e
                })
            })?;
            all = Some(match all {
                None => b,
                Some(a) => WideBounds {
                    min: std::array::from_fn(|k| a.min[k].min(b.min[k])),
                    max: std::array::from_fn(|k| a.max[k].max(b.max[k])),
                },
            });
        }
        line.clear();
        Ok(())
    };
    loop {
        let n = read_some(&mut r, &mut chunk)?;
        if n == 0 {
            break;
        }
        for &b in chunk.get(..n).unwrap_or_default() {
            if std::mem::take(&mut after_cr) && b == b'\n' {
                continue;
            }
            if b == b'\n' || b == b'\r' {
                after_cr = b == b'\r';
                end_line(&mut line, &mut line_no)?;
            } else if line.len() <= LINE {
                line.push(b);
            }
        }
    }
    if !line.is_empty() {
        end_line(&mut line, &mut line_no)?;
    }
    Ok(all.unwrap_or(WideBounds {
        min: [0; 3],
        max: [0; 3],
    }))
}

impl Model {
    /// Loads an OBJ file, read piece by piece: as written when it fits Q16.16, otherwise
    /// recentred and scaled to a half-size of 100 units. Normals come from the file's `vn`
    /// where every corner has one, otherwise they are computed (area-weighted). A file without
    /// triangles is an error.
    pub fn load_obj(path: &str) -> Result<Model, LoadError> {
        let name = std::path::Path::new(path)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let open = || std::fs::File::open(path).map_err(|e| LoadError::Io(format!("{path}: {e}")));
        let model = Self::read_obj(&name, open).map_err(|e| match e {
            LoadError::Io(e) if !e.starts_with(path) => LoadError::Io(format!("{path}: {e}")),
            other => other,
        })?;
        if model.triangles.is_empty() {
            return Err(LoadError::NoTriangles(path.into()));
        }
        Ok(model)
    }

    /// [`load_obj`](Self::load_obj) of a file held in memory (a file without triangles gives
    /// an empty model).
    pub fn from_obj_bytes(name: &str, bytes: &[u8]) -> Result<Model, LoadError> {
        Self::read_obj(name, || Ok(bytes))
    }

    /// A model from the OBJ file `open` reads (opened a second time if the file must be
    /// rescaled).
    fn read_obj<R: Read>(
        name: &str,
        open: impl Fn() -> Result<R, LoadError>,
    ) -> Result<Model, LoadError> {
        let (parsed, rescaled) = match parse_stream(open()?, Placement::AsIs) {
            Err(LoadError::Obj(e)) if e.kind == ObjErrorKind::NumberOutOfRange => {
                let b = stream_bounds(open()?)?;
                let placement = Placement::fit(&b, Scalar::from_num(100));
                (parse_stream(open()?, placement)?, Some(placement))
            }
            other => (other?, None),
        };
        let Parsed {
            positions,
            texcoords,
            normals: file_normals,
            triangles,
            triangle_texcoords,
            triangle_normals: tri_normals,
            counts,
        } = parsed;
        // Texture coordinates: a vertex per distinct (position, UV) of the corners.
        let (positions, uvs, triangles) = if texcoords.is_empty() {
            (positions, Vec::new(), triangles)
        } else {
            let most = 3 * triangles.len();
            let (mut p, mut uv, mut t) = (
                vec![Vec3::ZERO; most],
                vec![[Scalar::ZERO; 2]; most],
                vec![[0u16; 3]; triangles.len()],
            );
            let (mut first, mut next) = (vec![0u16; positions.len()], vec![0u16; most]);
            let mut out = SplitBuffers {
                positions: &mut p,
                uvs: &mut uv,
                triangles: &mut t,
                first: &mut first,
                next: &mut next,
            };
            let n = obj::split_corners(
                &positions,
                &triangles,
                &texcoords,
                &triangle_texcoords,
                &mut out,
            )
            .map_err(LoadError::Obj)?;
            p.truncate(n);
            uv.truncate(n);
            (p, uv, t)
        };
        let mut normals = vec![Vec3::ZERO; positions.len()];
        let complete =
            !file_normals.is_empty() && tri_normals.iter().flatten().all(|&n| n != NO_INDEX);
        if complete {
            obj::corner_normals_to_vertices(&triangles, &tri_normals, &file_normals, &mut normals);
        }
        if !complete || normals.contains(&Vec3::ZERO) {
            let mut computed = vec![Vec3::ZERO; positions.len()];
            let _ = vertex_normals(&positions, &triangles, &mut computed);
            for (n, c) in normals.iter_mut().zip(computed) {
                if *n == Vec3::ZERO {
                    *n = c;
                }
            }
        }
        Ok(Model {
            name: name.into(),
            positions,
            normals,
            uvs,
            triangles,
            bounds: counts.bounds,
            rescaled,
        })
    }

    /// A built-in shape by name: cube, tetrahedron, octahedron, sphere or torus.
    pub fn shape(name: &str) -> Option<Model> {
        let from = |m: &Mesh<'_>| {
            let mut normals = vec![Vec3::ZERO; m.positions().len()];
            let _ = vertex_normals(m.positions(), m.triangles(), &mut normals);
            Model::owned(
                name,
                m.positions().to_vec(),
                normals,
                m.triangles().to_vec(),
            )
        };
        match name {
            "cube" => Some(from(&mesh::CUBE)),
            "tetrahedron" => Some(from(&mesh::TETRAHEDRON)),
            "octahedron" => Some(from(&mesh::OCTAHEDRON)),
            "sphere" => {
                let (nv, nt) = mesh::uv_sphere_counts(32, 16);
                let (mut p, mut n, mut t) = (
                    vec![Vec3::ZERO; nv],
                    vec![Vec3::ZERO; nv],
                    vec![[0u16; 3]; nt],
                );
                mesh::uv_sphere(Scalar::ONE, 32, 16, &mut p, &mut n, &mut t).ok()?;
                Some(Model::owned(name, p, n, t))
            }
            "torus" => {
                let (nv, nt) = mesh::torus_counts(48, 24);
                let (mut p, mut n, mut t) = (
                    vec![Vec3::ZERO; nv],
                    vec![Vec3::ZERO; nv],
                    vec![[0u16; 3]; nt],
                );
                mesh::torus(
                    Scalar::ONE,
                    Scalar::from_num(0.4),
                    48,
                    24,
                    &mut p,
                    &mut n,
                    &mut t,
                )
                .ok()?;
                Some(Model::owned(name, p, n, t))
            }
            _ => None,
        }
    }

    /// A built-in shape with UVs, for a texture: the textured cube (a face's normal at each of
    /// its corners), or the sphere or torus with their seams' vertices doubled; the shapes
    /// without UVs otherwise.
    pub fn shape_with_uvs(name: &str) -> Option<Model> {
        let with = |positions: Vec<Vec3>, normals: Vec<Vec3>, uvs: Vec<Uv>, t| {
            let mut m = Model::owned(name, positions, normals, t);
            m.uvs = uvs;
            m
        };
        match name {
            "cube" => {
                let c = &mesh::TEXTURED_CUBE;
                let (n, uv) = (c.normals()?.to_vec(), c.uvs()?.to_vec());
                Some(with(c.positions().to_vec(), n, uv, c.triangles().to_vec()))
            }
            "sphere" | "torus" => {
                let (nv, nt) = if name == "sphere" {
                    mesh::textured_uv_sphere_counts(32, 16)
                } else {
                    mesh::textured_torus_counts(48, 24)
                };
                let (mut p, mut n, mut t) = (
                    vec![Vec3::ZERO; nv],
                    vec![Vec3::ZERO; nv],
                    vec![[0u16; 3]; nt],
                );
                let mut uv = vec![[Scalar::ZERO; 2]; nv];
                let (one, minor) = (Scalar::ONE, Scalar::from_num(0.4));
                if name == "sphere" {
                    mesh::textured_uv_sphere(one, 32, 16, &mut p, &mut n, &mut uv, &mut t).ok()?;
                } else {
                    mesh::textured_torus(one, minor, 48, 24, &mut p, &mut n, &mut uv, &mut t)
                        .ok()?;
                }
                Some(with(p, n, uv, t))
            }
            _ => Model::shape(name),
        }
    }

    /// The reference torus of the benchmarks: the torus above turned 20 degrees about x, then
    /// 30 about y (returned as its model matrix).
    pub fn reference_torus() -> (Model, Mat4) {
        let model =
            Model::shape("torus").unwrap_or_else(|| Model::owned("torus", vec![], vec![], vec![]));
        (
            model,
            Mat4::rotation_y(Angle::from_degrees(30)) * Mat4::rotation_x(Angle::from_degrees(20)),
        )
    }

    /// A model over owned storage (indices must be valid for `positions`).
    pub fn owned(
        name: &str,
        positions: Vec<Vec3>,
        normals: Vec<Vec3>,
        triangles: Vec<Triangle>,
    ) -> Model {
        let mut bounds = Aabb::default();
        if let Some(first) = positions.first() {
            bounds = Aabb {
                min: *first,
                max: *first,
            };
        }
        for p in &positions {
            bounds.min = Vec3::new(
                bounds.min.x.min(p.x),
                bounds.min.y.min(p.y),
                bounds.min.z.min(p.z),
            );
            bounds.max = Vec3::new(
                bounds.max.x.max(p.x),
                bounds.max.y.max(p.y),
                bounds.max.z.max(p.z),
            );
        }
        Model {
            name: name.into(),
            positions,
            normals,
            uvs: Vec::new(),
            triangles,
            bounds,
            rescaled: None,
        }
    }

    /// The mesh over this model's storage (indices were checked when it was built).
    pub fn mesh(&self) -> Mesh<'_> {
        let mesh = Mesh::new(&self.positions, &self.triangles)
            .and_then(|m| m.with_normals(&self.normals))
            .unwrap_or(Mesh::EMPTY);
        mesh.with_uvs(&self.uvs).unwrap_or(mesh)
    }
}

/// How triangles are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Wire,
    Flat,
    Gouraud,
    /// Gouraud interpolated perspective-correctly.
    Perspective,
}

impl Mode {
    pub fn parse(s: &str) -> Option<Mode> {
        match s {
            "wire" => Some(Mode::Wire),
            "flat" => Some(Mode::Flat),
            "gouraud" => Some(Mode::Gouraud),
            "perspective-gouraud" => Some(Mode::Perspective),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Mode::Wire => "wire",
            Mode::Flat => "flat",
            Mode::Gouraud => "gouraud",
            Mode::Perspective => "perspective-gouraud",
        }
    }

    pub fn next(self) -> Mode {
        match self {
            Mode::Wire => Mode::Flat,
            Mode::Flat => Mode::Gouraud,
            Mode::Gouraud => Mode::Perspective,
            Mode::Perspective => Mode::Wire,
        }
    }
}

/// One placed model.
#[derive(Clone, Copy, Debug)]
pub struct Placed<'m> {
    pub model: &'m Model,
    pub matrix: Mat4,
    pub color: Rgb888,
    /// Mapped through the model's UVs (lit by the mode; wireframes leave it out).
    pub texture: Option<&'m Texture<'m>>,
}

/// Everything about a frame but the models.
#[derive(Clone, Debug)]
pub struct View {
    pub width: u32,
    pub height: u32,
    pub mode: Mode,
    pub view: Mat4,
    pub projection: Projection,
    pub ambient: Scalar,
    /// Directional and point lights (beside the ambient light).
    pub lights: Vec<Light>,
    pub background: Rgb888,
    pub cull: bool,
    pub depth: bool,
    /// Render in horizontal bands of this many rows (0: the whole frame at once).
    pub bands: u32,
    /// The highlights of every untextured model (Gouraud modes show them).
    pub specular: Option<Specular>,
}

/// What rendering a frame produced.
pub struct Rendered {
    pub pixels: Vec<Rgb888>,
    pub stats: Stats,
    /// Render time only (vertex stage and drawing, clears excluded).
    pub time: Duration,
}

impl Rendered {
    pub fn covered(&self, background: Rgb888) -> usize {
        self.pixels.iter().filter(|&&p| p != background).count()
    }
}

/// A perspective projection and look-at camera framing `bounds` from a direction, or an error
/// message.
pub fn framed(
    bounds: &Aabb,
    direction: Vec3,
    fov: Angle,
    aspect: Scalar,
) -> Result<(LookAt, Projection), String> {
    let f = Framing::of_box(bounds.min, bounds.max, direction, fov, aspect)
        .map_err(|e| e.to_string())?;
    let p = Projection::perspective(fov, aspect, f.near, f.far).map_err(|e| e.to_string())?;
    Ok((f.look_at, p))
}

/// The union of the models' bounding boxes, moved by their matrices' translations (rotation
/// and scale are bounded by the box's corners).
pub fn scene_bounds(objects: &[Placed<'_>]) -> Aabb {
    let mut out: Option<Aabb> = None;
    for o in objects {
        let b = o.model.bounds;
        for corner in 0..8 {
            let pick = |bit: usize, lo: Scalar, hi: Scalar| if corner & bit == 0 { lo } else { hi };
            let c = Vec3::new(
                pick(1, b.min.x, b.max.x),
                pick(2, b.min.y, b.max.y),
                pick(4, b.min.z, b.max.z),
            );
            let p = o.matrix.transform_point(c);
            out = Some(match out {
                None => Aabb { min: p, max: p },
                Some(a) => Aabb {
                    min: Vec3::new(a.min.x.min(p.x), a.min.y.min(p.y), a.min.z.min(p.z)),
                    max: Vec3::new(a.max.x.max(p.x), a.max.y.max(p.y), a.max.z.max(p.z)),
                },
            });
        }
    }
    out.unwrap_or_default()
}

/// Renders the objects as seen through `view` into an RGB888 image: the untextured objects in
/// one pass of the mode's shading, the textured ones in a pass per texture, sharing the depth
/// buffer band by band.
pub fn render(objects: &[Placed<'_>], view: &View) -> Result<Rendered, String> {
    let viewport = Viewport::new(view.width, view.height).map_err(|e| e.to_string())?;
    let meshes: Vec<Mesh<'_>> = objects.iter().map(|o| o.model.mesh()).collect();
    let wire = view.mode == Mode::Wire;
    // The passes: the untextured objects, then each texture's (wireframes ignore textures).
    let mut passes: Vec<(Option<&Texture<'_>>, Vec<Object<'_>>)> = vec![(None, Vec::new())];
    for (o, m) in objects.iter().zip(&meshes) {
        let texture = o.texture.filter(|_| !wire);
        let object = match texture {
            // A textured surface is lit white: the light then scales its texels.
            Some(_) => Object::new(m, o.matrix, Rgb888::WHITE),
            None => Object::new(m, o.matrix, o.color).with_specular(view.specular.as_ref()),
        };
        let same = |p: &&mut (Option<&Texture<'_>>, Vec<Object<'_>>)| match (p.0, texture) {
            (Some(a), Some(b)) => std::ptr::eq(a, b),
            (a, b) => a.is_none() && b.is_none(),
        };
        match passes.iter_mut().find(same) {
            Some(pass) => pass.1.push(object),
            None => passes.push((texture, vec![object])),
        }
    }
    let ambient = [Light::ambient(view.ambient)];
    let lights: Vec<Light> = ambient.iter().chain(&view.lights).copied().collect();
    let lighting =
        Lighting::<MAX_LIGHTS>::from_lights(&lights).map_err(|e| format!("light: {e}"))?;
    let scenes: Vec<(Option<&Texture<'_>>, Scene<'_, MAX_LIGHTS>)> = passes
        .iter()
        .filter(|(_, objects)| !objects.is_empty())
        .map(|(t, objects)| (*t, Scene::new(objects, lighting.clone())))
        .collect();
    let frame = Frame::new(&view.view, &view.projection, viewport).with_cull(if view.cull {
        Cull::Back
    } else {
        Cull::None
    });
    let mut caches: Vec<Vec<ScreenVertex>> = scenes
        .iter()
        .map(|(_, s)| vec![ScreenVertex::DEFAULT; s.vertex_count()])
        .collect();
    let (w, h) = (view.width, view.height);
    let mut pixels = vec![view.background; (w * h) as usize];
    let started = Instant::now();
    if wire {
        let mut stats = Stats::default();
        for ((_, scene), cache) in scenes.iter().zip(&mut caches) {
            let prepared = frame
                .prepare(scene, cache, Unlit)
                .map_err(|e| e.to_string())?;
            let mut color = FrameBuffer::new(&mut pixels, w, h).map_err(|e| e.to_string())?;
            stats = stats
                + prepared
                    .draw_wireframe(&mut color)
                    .map_err(|e| format!("{e:?}"))?;
        }
        return Ok(Rendered {
            pixels,
            stats,
            time: started.elapsed(),
        });
    }
    let mut prepared: Vec<Box<dyn Pass + '_>> = Vec::new();
    for ((texture, scene), cache) in scenes.iter().zip(&mut caches) {
        let err = |e: fixed3d::pipeline::PrepareError| e.to_string();
        prepared.push(match (texture, view.mode) {
            (Some(texture), Mode::Flat) => {
                let light = Flat;
                Box::new(
                    frame
                        .prepare(scene, cache, Textured { texture, light })
                        .map_err(err)?,
                )
            }
            (Some(texture), _) => {
                let light = Gouraud;
                Box::new(
                    frame
                        .prepare(scene, cache, Textured { texture, light })
                        .map_err(err)?,
                )
            }
            (None, Mode::Gouraud) => Box::new(frame.prepare(scene, cache, Gouraud).map_err(err)?),
            (None, Mode::Perspective) => Box::new(
                frame
                    .prepare(scene, cache, PerspectiveGouraud)
                    .map_err(err)?,
            ),
            (None, _) => Box::new(frame.prepare(scene, cache, Flat).map_err(err)?),
        });
    }
    let stats = draw(&prepared, &mut pixels, view)?;
    Ok(Rendered {
        pixels,
        stats,
        time: started.elapsed(),
    })
}

/// A prepared pass of `render`, whatever its shading: drawn through a band's depth buffer, or
/// straight into the frame.
trait Pass {
    fn draw_band(&self, target: &mut ColorDepth<'_, '_, Rgb888, u16>) -> Result<Stats, String>;
    fn draw_direct(
        &self,
        target: &mut Direct<'_, FrameBuffer<'_, Rgb888>>,
    ) -> Result<Stats, String>;
}

impl<const N: usize, S: fixed3d::shade::Shading> Pass
    for fixed3d::pipeline::Prepared<'_, '_, N, S>
{
    fn draw_band(&self, target: &mut ColorDepth<'_, '_, Rgb888, u16>) -> Result<Stats, String> {
        self.draw(target).map_err(|e| format!("{e:?}"))
    }

    fn draw_direct(
        &self,
        target: &mut Direct<'_, FrameBuffer<'_, Rgb888>>,
    ) -> Result<Stats, String> {
        self.draw(target).map_err(|e| format!("{e:?}"))
    }
}

/// Draws the passes into `pixels`: straight, without depth, or band by band (one pass when
/// `view.bands` is 0) through a depth buffer they share.
fn draw(
    passes: &[Box<dyn Pass + '_>],
    pixels: &mut [Rgb888],
    view: &View,
) -> Result<Stats, String> {
    let (w, h) = (view.width, view.height);
    let mut total = Stats::default();
    if !view.depth {
        let mut color = FrameBuffer::new(pixels, w, h).map_err(|e| e.to_string())?;
        for pass in passes {
            total = total + pass.draw_direct(&mut Direct::new(&mut color))?;
        }
        return Ok(total);
    }
    let rows = if view.bands == 0 {
        h
    } else {
        view.bands.min(h)
    };
    let mut depth = vec![0u16; (w * rows) as usize];
    let mut y0 = 0;
    while y0 < h {
        let n = rows.min(h - y0);
        let start = (y0 * w) as usize;
        let band = &mut pixels[start..start + (n * w) as usize];
        let mut color = FrameBuffer::new(band, w, n).map_err(|e| e.to_string())?;
        let mut z = DepthBuffer::new(&mut depth, w, n).map_err(|e| e.to_string())?;
        z.clear();
        let mut target = ColorDepth::band(&mut color, &mut z, y0).map_err(|e| e.to_string())?;
        let mut s = Stats::default();
        for pass in passes {
            s = s + pass.draw_band(&mut target)?;
        }
        // The same in every band.
        total.primitives = s.primitives;
        total.culled = s.culled;
        total.degenerate = s.degenerate;
        total.outside = s.outside;
        total.clipped = s.clipped;
        total.invalid = s.invalid;
        total.fragments += s.fragments;
        total.written += s.written;
        y0 += n;
    }
    // Triangles that survived clipping, culling and snapping, whichever band they fell in.
    total.drawn =
        total.primitives - total.invalid - total.outside - total.culled - total.degenerate;
    Ok(total)
}

/// Texels read from a PNG file (any colour type the decoder expands to 8-bit RGB or RGBA,
/// alpha dropped), row after row from the top, and the image's size.
pub fn load_texels(path: &str) -> Result<(Vec<Rgb888>, u16, u16), String> {
    let file = std::fs::File::open(path).map_err(|e| format!("{path}: {e}"))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| format!("{path}: {e}"))?;
    let mut buf = vec![
        0;
        reader
            .output_buffer_size()
            .ok_or(format!("{path}: too large"))?
    ];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{path}: {e}"))?;
    let channels = info.color_type.samples();
    let side = |v: u32| {
        u16::try_from(v)
            .ok()
            .filter(|&v| v <= fixed3d::texture::MAX_SIDE)
            .ok_or(format!(
                "{path}: a texture is at most {} texels a side, this one is {}x{}",
                fixed3d::texture::MAX_SIDE,
                info.width,
                info.height
            ))
    };
    let (w, h) = (side(info.width)?, side(info.height)?);
    let texels = buf[..info.buffer_size()]
        .chunks_exact(channels)
        .map(|c| match c {
            [l] | [l, _] => Rgb888::new(*l, *l, *l),
            [r, g, b, ..] => Rgb888::new(*r, *g, *b),
            _ => Rgb888::BLACK,
        })
        .collect();
    Ok((texels, w, h))
}

/// The texture an OBJ file names: the first `map_Kd` of the first `mtllib` file it uses,
/// relative to the OBJ file's folder; `None` when it names none. Files are read a line at a
/// time, each cut at `LINE` bytes, as the parser reads them.
pub fn obj_texture_path(obj: &str) -> Option<std::path::PathBuf> {
    let first_value = |path: &std::path::Path, key: &str| -> Option<String> {
        let mut reader = std::io::BufReader::new(std::fs::File::open(path).ok()?);
        let mut line = Vec::new();
        loop {
            line.clear();
            let n = std::io::BufRead::read_until(
                &mut std::io::Read::take(&mut reader, LINE as u64),
                b'\n',
                &mut line,
            )
            .ok()?;
            if n == 0 {
                return None;
            }
            let text = String::from_utf8_lossy(&line);
            let mut words = text.split_whitespace();
            if words.next() == Some(key) {
                return words.next().map(String::from);
            }
        }
    };
    let obj = std::path::Path::new(obj);
    let dir = obj.parent()?;
    let mtl = dir.join(first_value(obj, "mtllib")?);
    let map = first_value(&mtl, "map_Kd")?;
    Some(mtl.parent().unwrap_or(dir).join(map))
}

/// The default lighting of the desktop tools: one white light towards (−1, 1, 1) at 0.8.
pub fn default_lights() -> Vec<Light> {
    vec![Light::directional([-1, 1, 1], 0.8)]
}

/// Writes an RGB888 image as PNG.
pub fn save_png(path: &str, w: u32, h: u32, pixels: &[Rgb888]) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{path}: {e}"))?;
    save_png_to(file, path, w, h, pixels)
}

/// [`save_png`] into an open `file` (named `path` in errors).
pub fn save_png_to(
    file: std::fs::File,
    path: &str,
    w: u32,
    h: u32,
    pixels: &[Rgb888],
) -> Result<(), String> {
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(|e| format!("{path}: {e}"))?;
    let data: Vec<u8> = pixels.iter().flat_map(|c| [c.r(), c.g(), c.b()]).collect();
    writer
        .write_image_data(&data)
        .map_err(|e| format!("{path}: {e}"))
}

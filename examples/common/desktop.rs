//! Desktop helpers shared by the render tool, the viewer and the model golden tests: owned
//! models (loaded from OBJ files or generated), and rendering a scene into an RGB888 image in
//! one of three modes. Desktop code: it allocates, the library does not.
#![allow(dead_code)]

use std::fmt;
use std::time::{Duration, Instant};

use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, Direct, FrameBuffer};
use fixed3d::camera::{Framing, LookAt};
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{self, vertex_normals, Mesh, Object, Triangle};
use fixed3d::obj::{self, Aabb, ObjBuffers, ObjError, ObjErrorKind, Placement, NO_INDEX};
use fixed3d::pipeline::{Cull, Frame, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::scene::{DirectionalLight, LightColor, Lighting, Scene};
use fixed3d::shade::{Flat, Gouraud, Unlit};

/// Lights a desktop scene holds at most.
pub const MAX_LIGHTS: usize = 8;

/// A mesh with owned storage and per-vertex normals.
#[derive(Clone, Debug)]
pub struct Model {
    pub name: String,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
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
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadError::Io(e) => write!(f, "{e}"),
            LoadError::Obj(e) => write!(f, "invalid OBJ: {e}"),
        }
    }
}

impl Model {
    /// Loads an OBJ file: as written when it fits Q16.16, otherwise recentred and scaled to a
    /// half-size of 100 units. Normals come from the file's `vn` where every corner has one,
    /// otherwise they are computed (area-weighted).
    pub fn load_obj(path: &str) -> Result<Model, LoadError> {
        let bytes = std::fs::read(path).map_err(|e| LoadError::Io(format!("{path}: {e}")))?;
        let name = std::path::Path::new(path)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        Self::from_obj_bytes(&name, &bytes)
    }

    pub fn from_obj_bytes(name: &str, bytes: &[u8]) -> Result<Model, LoadError> {
        // Upper bounds on what the file can hold: a position needs a line, a triangle at least
        // two bytes of face.
        let lines = bytes.iter().filter(|&&b| b == b'\n' || b == b'\r').count() + 1;
        let (cap_v, cap_t) = (lines.min(65_536), bytes.len() / 2 + 1);
        let attempt = |placement: Placement| {
            let mut positions = vec![Vec3::ZERO; cap_v];
            let mut normals = vec![Vec3::ZERO; lines];
            let mut triangles = vec![[0u16; 3]; cap_t];
            let mut tri_normals = vec![[0u16; 3]; cap_t];
            let counts = obj::parse(
                bytes,
                &mut ObjBuffers {
                    positions: &mut positions,
                    texcoords: &mut [],
                    normals: &mut normals,
                    triangles: &mut triangles,
                    triangle_texcoords: &mut [],
                    triangle_normals: &mut tri_normals,
                },
                placement,
            )?;
            positions.truncate(counts.positions);
            normals.truncate(counts.normals);
            triangles.truncate(counts.triangles);
            tri_normals.truncate(counts.triangles);
            Ok::<_, ObjError>((positions, normals, triangles, tri_normals, counts))
        };
        let (result, rescaled) = match attempt(Placement::AsIs) {
            Err(e) if e.kind == ObjErrorKind::NumberOutOfRange => {
                let b = obj::bounds(bytes).map_err(LoadError::Obj)?;
                let placement = Placement::fit(&b, Scalar::from_num(100));
                (attempt(placement), Some(placement))
            }
            other => (other, None),
        };
        let (positions, file_normals, triangles, tri_normals, counts) =
            result.map_err(LoadError::Obj)?;
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
            triangles,
            bounds,
            rescaled: None,
        }
    }

    /// The mesh over this model's storage (indices were checked when it was built).
    pub fn mesh(&self) -> Mesh<'_> {
        Mesh::new(&self.positions, &self.triangles)
            .and_then(|m| m.with_normals(&self.normals))
            .unwrap_or(Mesh::EMPTY)
    }
}

/// How triangles are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Wire,
    Flat,
    Gouraud,
}

impl Mode {
    pub fn parse(s: &str) -> Option<Mode> {
        match s {
            "wire" => Some(Mode::Wire),
            "flat" => Some(Mode::Flat),
            "gouraud" => Some(Mode::Gouraud),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Mode::Wire => "wire",
            Mode::Flat => "flat",
            Mode::Gouraud => "gouraud",
        }
    }

    pub fn next(self) -> Mode {
        match self {
            Mode::Wire => Mode::Flat,
            Mode::Flat => Mode::Gouraud,
            Mode::Gouraud => Mode::Wire,
        }
    }
}

/// One placed model.
#[derive(Clone, Copy, Debug)]
pub struct Placed<'m> {
    pub model: &'m Model,
    pub matrix: Mat4,
    pub color: Rgb888,
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
    /// Direction towards each light, and its colour.
    pub lights: Vec<(Vec3, LightColor)>,
    pub background: Rgb888,
    pub cull: bool,
    pub depth: bool,
    /// Render in horizontal bands of this many rows (0: the whole frame at once).
    pub bands: u32,
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

/// Renders the objects as seen through `view` into an RGB888 image.
pub fn render(objects: &[Placed<'_>], view: &View) -> Result<Rendered, String> {
    let viewport = Viewport::new(view.width, view.height).map_err(|e| e.to_string())?;
    let meshes: Vec<Mesh<'_>> = objects.iter().map(|o| o.model.mesh()).collect();
    let scene_objects: Vec<Object<'_>> = objects
        .iter()
        .zip(&meshes)
        .map(|(o, m)| Object::new(m, o.matrix, o.color))
        .collect();
    let mut lighting = Lighting::<MAX_LIGHTS>::new(LightColor::gray(view.ambient));
    for (dir, color) in &view.lights {
        lighting
            .push(DirectionalLight::new(*dir, *color))
            .map_err(|e| format!("light: {e}"))?;
    }
    let scene = Scene::new(&scene_objects, lighting);
    let frame = Frame::new(&view.view, &view.projection, viewport).with_cull(if view.cull {
        Cull::Back
    } else {
        Cull::None
    });
    let mut cache = vec![ScreenVertex::DEFAULT; scene.vertex_count()];
    let (w, h) = (view.width, view.height);
    let mut pixels = vec![view.background; (w * h) as usize];
    let started = Instant::now();
    let stats = match view.mode {
        Mode::Wire => {
            let prepared = frame
                .prepare(&scene, &mut cache, Unlit)
                .map_err(|e| e.to_string())?;
            let mut color = FrameBuffer::new(&mut pixels, w, h).map_err(|e| e.to_string())?;
            prepared
                .draw_wireframe(&mut color)
                .map_err(|e| format!("{e:?}"))?
        }
        Mode::Flat => draw(
            &frame
                .prepare(&scene, &mut cache, Flat)
                .map_err(|e| e.to_string())?,
            &mut pixels,
            view,
        )?,
        Mode::Gouraud => draw(
            &frame
                .prepare(&scene, &mut cache, Gouraud)
                .map_err(|e| e.to_string())?,
            &mut pixels,
            view,
        )?,
    };
    Ok(Rendered {
        pixels,
        stats,
        time: started.elapsed(),
    })
}

fn draw<const N: usize, S: fixed3d::shade::Shading>(
    prepared: &fixed3d::pipeline::Prepared<'_, '_, N, S>,
    pixels: &mut [Rgb888],
    view: &View,
) -> Result<Stats, String> {
    let (w, h) = (view.width, view.height);
    if !view.depth {
        let mut color = FrameBuffer::new(pixels, w, h).map_err(|e| e.to_string())?;
        return prepared
            .draw(&mut Direct::new(&mut color))
            .map_err(|e| format!("{e:?}"));
    }
    let rows = if view.bands == 0 {
        h
    } else {
        view.bands.min(h)
    };
    let mut depth = vec![0u16; (w * rows) as usize];
    let mut total = Stats::default();
    let mut y0 = 0;
    while y0 < h {
        let n = rows.min(h - y0);
        let start = (y0 * w) as usize;
        let band = &mut pixels[start..start + (n * w) as usize];
        let mut color = FrameBuffer::new(band, w, n).map_err(|e| e.to_string())?;
        let mut z = DepthBuffer::new(&mut depth, w, n).map_err(|e| e.to_string())?;
        z.clear();
        let s = prepared
            .draw(&mut ColorDepth::band(&mut color, &mut z, y0).map_err(|e| e.to_string())?)
            .map_err(|e| format!("{e:?}"))?;
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

/// The default lighting of the desktop tools: one white light towards (−1, 1, 1) at 0.8.
pub fn default_lights() -> Vec<(Vec3, LightColor)> {
    vec![(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(Scalar::from_num(0.8)),
    )]
}

/// Writes an RGB888 image as PNG.
pub fn save_png(path: &str, w: u32, h: u32, pixels: &[Rgb888]) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{path}: {e}"))?;
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().map_err(|e| e.to_string())?;
    let data: Vec<u8> = pixels.iter().flat_map(|c| [c.r(), c.g(), c.b()]).collect();
    writer.write_image_data(&data).map_err(|e| e.to_string())
}

//! The error-against-run-time report's engine, shared by `examples/accuracy.rs` (the full
//! report) and `tests/accuracy.rs` (a reduced run with the required limits asserted).
//!
//! Each scene is rendered by the crate in each configuration and compared with two references:
//! REF_EXACT (`exact.rs`: the same snapped vertices through i128 edge functions, for M1) and
//! REF_IDEAL (`reference.rs`: f64 matrices from the exact angles, f64 near/far clipping, no
//! snapping, per-pixel edge functions, f64 Lambert, perspective-correct Gouraud). Inputs are
//! the same numbers for both: the Q16.16 mesh, scale, translation and camera positions, and
//! the exact binary angles; every difference is the renderer's.
//!
//! The partial band of M2 follows dEQP: a pixel is PARTIAL when its centre lies within `tol`
//! of a polygon's edge, with `tol` how far the crate's default configuration may move an edge:
//! half a snapping cell in x and in y, plus the default Q16.16 clip-from-model matrix's
//! rounding carried to the screen (its entries' differences from the f64 matrix times the
//! vertex coordinates, plus 2⁻¹⁵ for the products and clipping). Configurations with a coarser
//! snapping grid get their own grid's half cell; the other knobs get no extra tolerance, so
//! what they cost shows up as missing and unexpected pixels.
#![allow(dead_code)]

use std::collections::BTreeSet;
use std::time::Instant;

use crate::desktop::Model;
use crate::exact::model_triangle;
use crate::reference::{
    apply4, clip_near_far, cross, dot, inside_distance, mul4, norm, polygon_area, sub, Camera, V3,
};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use fixed3d::buffer::{ColorDepth, DepthBuffer, DepthFormat, FrameBuffer};
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Normalize, Scalar, Trig, Vec3};
use fixed3d::mesh::{Mesh, Object, Specular, Transform};
use fixed3d::pipeline::{Frame, MatrixFormat, Precision, ScreenVertex};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::raster::{triangle_spans, PixelRect};
use fixed3d::scene::{Attenuation, DirectionalLight, LightColor, Lighting, PointLight, Scene};
use fixed3d::shade::{Flat, Gouraud, PerspectiveGouraud, Shading, Textured};
use fixed3d::texture::{Mapping, Texels, Texture};

/// How a configuration shades.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shade {
    Flat,
    Gouraud,
    Perspective,
}

/// One point of the sweep: every knob set.
#[derive(Clone, Copy, Debug)]
pub struct Config {
    pub name: &'static str,
    /// The knob this configuration changes from the default ("" for the default).
    pub knob: &'static str,
    pub precision: Precision,
    pub trig: Trig,
    pub depth32: bool,
    pub shade: Shade,
    /// How the textured scenes are mapped: affine, or perspective-correct with an exact
    /// division every `run` pixels along a span.
    pub affine: bool,
    pub run: u8,
}

impl Config {
    pub const DEFAULT: Config = Config {
        name: "default",
        knob: "",
        precision: Precision::DEFAULT,
        trig: Trig::Polynomial,
        depth32: false,
        shade: Shade::Flat,
        affine: false,
        run: fixed3d::texture::RUN,
    };

    pub fn describe(&self) -> String {
        format!(
            "{} sub-pixel bits, {} matrix, {:?} sine, {:?} normalisation, u{} depth, {}",
            self.precision.subpixel_bits(),
            match self.precision.matrix() {
                MatrixFormat::Normalized => "normalised (24 significant bits)".to_string(),
                MatrixFormat::Fixed(b) => format!("Q{}.{b}", 32 - b),
            },
            self.trig,
            self.precision.normalize(),
            if self.depth32 { 32 } else { 16 },
            match self.shade {
                Shade::Flat => "flat",
                Shade::Gouraud => "Gouraud (affine)",
                Shade::Perspective => "Gouraud (perspective-correct)",
            }
        ) + &if self.affine {
            ", textures affine".to_string()
        } else {
            format!(", textures perspective-correct every {} pixels", self.run)
        }
    }
}

/// The sweep: the default, then each knob moved alone.
pub fn configs() -> Vec<Config> {
    let d = Config::DEFAULT;
    let p = Precision::DEFAULT;
    vec![
        d,
        Config {
            name: "subpixel-2",
            knob: "sub-pixel bits",
            precision: p.with_subpixel_bits(2),
            ..d
        },
        Config {
            name: "subpixel-0",
            knob: "sub-pixel bits",
            precision: p.with_subpixel_bits(0),
            ..d
        },
        Config {
            name: "matrix-q16.16",
            knob: "transform format",
            precision: p.with_matrix(MatrixFormat::Fixed(16)),
            ..d
        },
        Config {
            name: "matrix-q24.8",
            knob: "transform format",
            precision: p.with_matrix(MatrixFormat::Fixed(8)),
            ..d
        },
        Config {
            name: "depth-u32",
            knob: "depth width",
            depth32: true,
            ..d
        },
        Config {
            name: "trig-table",
            knob: "sin/cos",
            trig: Trig::Table,
            ..d
        },
        #[cfg(feature = "micromath")]
        Config {
            name: "trig-micromath",
            knob: "sin/cos",
            trig: Trig::Micromath,
            ..d
        },
        Config {
            name: "normalize-exact",
            knob: "normalisation",
            precision: p.with_normalize(Normalize::Exact),
            ..d
        },
        #[cfg(feature = "micromath")]
        Config {
            name: "normalize-micromath",
            knob: "normalisation",
            precision: p.with_normalize(Normalize::Micromath),
            ..d
        },
        Config {
            name: "gouraud-affine",
            knob: "shading",
            shade: Shade::Gouraud,
            ..d
        },
        Config {
            name: "gouraud-perspective",
            knob: "perspective correction",
            shade: Shade::Perspective,
            ..d
        },
        Config {
            name: "texture-affine",
            knob: "texture mapping",
            affine: true,
            ..d
        },
        Config {
            name: "texture-run-1",
            knob: "texture run",
            run: 1,
            ..d
        },
        Config {
            name: "texture-run-4",
            knob: "texture run",
            run: 4,
            ..d
        },
        Config {
            name: "texture-run-16",
            knob: "texture run",
            run: 16,
            ..d
        },
        Config {
            name: "texture-run-64",
            knob: "texture run",
            run: 64,
            ..d
        },
    ]
}

/// The texture of the textured scenes: 64x64 texels, each a colour no other has, so that a
/// pixel tells which texel it shows (red and green are its column and row, four steps each).
pub fn texels() -> Vec<Rgb888> {
    (0..64 * 64)
        .map(|i| texel((i % 64) as u8, (i / 64) as u8))
        .collect()
}

/// Texel (x, y) of [`texels`], each coordinate below 64.
fn texel(x: u8, y: u8) -> Rgb888 {
    Rgb888::new(x * 4, y * 4, (x ^ y) * 4 + 1)
}

/// The colour of [`texels`] at texel coordinates `st` (nearest, repeating).
fn texel_color(st: [f64; 2]) -> [f64; 3] {
    let [x, y] = st.map(|c| c.floor().rem_euclid(64.0) as u8);
    let c = texel(x, y);
    [c.r(), c.g(), c.b()].map(f64::from)
}

/// The texel a colour of [`texels`] is, if it is one.
fn texel_of(c: Rgb888) -> Option<[f64; 2]> {
    let (x, y) = (c.r() / 4, c.g() / 4);
    (texel(x, y) == c).then_some([x as f64, y as f64])
}

/// A point light of a scene, beside the ambient and directional light every scene has.
#[derive(Clone, Copy, Debug)]
pub struct Lamp {
    pub position: Vec3,
    pub intensity: Scalar,
    pub attenuation: Attenuation,
}

impl Lamp {
    /// The unit direction from world point `at` towards the lamp, and its intensity there
    /// (attenuated); `None` at the lamp.
    fn towards(&self, at: V3) -> Option<(V3, f64)> {
        let l = sub(f3(self.position), at);
        let d = dot(l, l).sqrt();
        if d == 0.0 {
            return None;
        }
        let fall = match self.attenuation {
            Attenuation::Linear => 1.0 / (1.0 + d),
            Attenuation::InverseSquare => 1.0 / (1.0 + d * d),
            _ => 1.0,
        };
        Some((l.map(|c| c / d), f(self.intensity) * fall))
    }

    /// Its term of Lambert's sum at world point `at` for a unit normal `n`, in f64.
    fn term(&self, n: V3, at: V3) -> f64 {
        self.towards(at)
            .map_or(0.0, |(l, i)| i * dot(n, l).max(0.0))
    }
}

/// A glossy scene's highlights: colour and shininess (see `fixed3d::mesh::Specular`).
#[derive(Clone, Copy, Debug)]
pub struct Gloss {
    pub color: [u8; 3],
    pub shininess: u16,
}

impl Gloss {
    /// The highlight (per channel, 8-bit units) at a vertex of unit normal `n` at world point
    /// `at`, for a viewer far along `towards_viewer` (unit), in f64.
    fn at(&self, n: V3, at: V3, towards_viewer: V3, lamp: Option<&Lamp>) -> [f64; 3] {
        let sun = (norm(LIGHT.0), LIGHT.1);
        let lights = std::iter::once(sun).chain(lamp.and_then(|l| l.towards(at)));
        let s: f64 = lights
            .filter(|(l, _)| dot(n, *l) > 0.0)
            .map(|(l, i)| {
                let h = norm([0, 1, 2].map(|k| l[k] + towards_viewer[k]));
                i * dot(n, h).max(0.0).powi(self.shininess as i32)
            })
            .sum();
        self.color.map(|c| c as f64 * s.clamp(0.0, 1.0))
    }
}

/// A scene: one model placed as `translate · Ry · Rx · scale`, seen by a look-at camera, lit by
/// [`AMBIENT`], [`LIGHT`] and, in some, a point light.
#[derive(Clone, Debug)]
pub struct SceneDef {
    pub lamp: Option<Lamp>,
    pub gloss: Option<Gloss>,
    /// Covered by [`texels`] through the model's UVs, under a white ambient light of 1 alone
    /// (each pixel its texel).
    pub textured: bool,
    pub name: &'static str,
    pub what: &'static str,
    pub model: Model,
    pub rot_x: Angle,
    pub rot_y: Angle,
    pub scale: Scalar,
    pub translate: Vec3,
    pub eye: Vec3,
    pub target: Vec3,
    pub fov: Angle,
    pub near: Scalar,
    pub far: Scalar,
    pub width: u32,
    pub height: u32,
}

fn f(v: Scalar) -> f64 {
    v.to_num::<f64>()
}

fn f3(v: Vec3) -> V3 {
    [f(v.x), f(v.y), f(v.z)]
}

fn radians(a: Angle) -> f64 {
    a.to_bits() as f64 / 4_294_967_296.0 * std::f64::consts::TAU
}

/// A disc of `n` needle-thin triangles fanned from its centre (case T09's slivers).
pub fn sliver_fan(n: u16) -> Model {
    let mut positions = vec![Vec3::ZERO];
    let mut normals = vec![Vec3::Z];
    let mut triangles = Vec::new();
    for i in 0..n {
        let t = i as f64 / n as f64 * std::f64::consts::TAU;
        positions.push(Vec3::from_f32(t.cos() as f32, t.sin() as f32, 0.0).unwrap_or_default());
        normals.push(Vec3::Z);
        triangles.push([0, 1 + i, 1 + (i + 1) % n]);
    }
    Model::owned("slivers", positions, normals, triangles)
}

/// The model recentred on its bounding box's centre (exact integer moves of the input).
fn centred(mut m: Model) -> (Model, Scalar) {
    let c = |a: Scalar, b: Scalar| {
        Scalar::from_bits(((a.to_bits() as i64 + b.to_bits() as i64) / 2) as i32)
    };
    let centre = Vec3::new(
        c(m.bounds.min.x, m.bounds.max.x),
        c(m.bounds.min.y, m.bounds.max.y),
        c(m.bounds.min.z, m.bounds.max.z),
    );
    for p in &mut m.positions {
        *p = *p - centre;
    }
    let radius = m
        .positions
        .iter()
        .map(|p| f(p.x).powi(2) + f(p.y).powi(2) + f(p.z).powi(2))
        .fold(0.0, f64::max)
        .sqrt()
        .max(1e-3);
    (m, Scalar::from_num(1.3 / radius))
}

/// The report's scenes. `models` is the folder of the shared OBJ files (`None` leaves them
/// out); `reduced` renders at 160x120 for the test suite.
pub fn scenes(models: Option<&str>, reduced: bool) -> Vec<SceneDef> {
    let (width, height) = if reduced { (160, 120) } else { (320, 240) };
    let s = |v: f64| Scalar::from_num(v);
    let torus = Model::shape("torus").unwrap_or_else(|| sliver_fan(3));
    let base = SceneDef {
        lamp: None,
        gloss: None,
        textured: false,
        name: "torus",
        what: "the reference scene of docs/reference-scene.md (48x24 torus turned 20° about x, 30° about y)",
        model: torus.clone(),
        rot_x: Angle::from_degrees(20),
        rot_y: Angle::from_degrees(30),
        scale: Scalar::ONE,
        translate: Vec3::ZERO,
        eye: Vec3::new(s(0.0), s(0.0), s(2.6)),
        target: Vec3::ZERO,
        fov: Angle::from_degrees(60),
        near: s(1.0),
        far: s(10.0),
        width,
        height,
    };
    let mut out = vec![base.clone()];
    if let Some(dir) = models {
        for (name, what) in [
            ("teapot", "Utah teapot (models/)"),
            ("suzanne", "Blender's Suzanne (models/)"),
            ("spot", "Keenan Crane's Spot (models/)"),
            ("beetle", "Alec Jacobson's beetle (models/)"),
        ] {
            let Ok(model) = Model::load_obj(&format!("{dir}/{name}.obj")) else {
                continue;
            };
            let (model, scale) = centred(model);
            out.push(SceneDef {
                name,
                what,
                model,
                scale,
                rot_x: Angle::from_degrees(15),
                rot_y: Angle::from_degrees(-35),
                ..base.clone()
            });
        }
    }
    out.push(SceneDef {
        name: "near-crossing",
        what: "the torus crossing the near plane (eye 1.2 from its centre, near 0.9)",
        eye: Vec3::new(s(0.0), s(0.2), s(1.2)),
        near: s(0.9),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "far-near-1e4",
        what: "the torus with near 0.01 and far 100: far/near = 10⁴",
        near: s(0.01),
        far: s(100.0),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "huge",
        what: "the torus scaled by 8000 (coordinates to 20,800, far 32,000: the edge of Q16.16)",
        scale: s(8000.0),
        eye: Vec3::new(s(0.0), s(0.0), s(20800.0)),
        near: s(1000.0),
        far: s(32000.0),
        ..base.clone()
    });
    let mut small = torus.clone();
    for p in &mut small.positions {
        let q = |v: Scalar| Scalar::from_bits((v.to_bits() + 512).div_euclid(1024));
        *p = Vec3::new(q(p.x), q(p.y), q(p.z));
    }
    out.push(SceneDef {
        name: "tiny",
        what: "the torus with its vertices divided by 1024 (then rounded to Q16.16), camera \
               2.6/1024 away, near 1/1024",
        model: small,
        eye: Vec3::new(s(0.0), s(0.0), Scalar::from_bits(166)),
        near: Scalar::from_bits(64),
        far: Scalar::from_bits(640),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "tiny-matrix",
        what: "the torus scaled by 1/1024 in its model matrix, camera 2.6/1024 away, near 1/1024 \
               (a Q16.16 matrix keeps 6 significant bits of a rotation so scaled)",
        scale: Scalar::from_bits(64),
        eye: Vec3::new(s(0.0), s(0.0), Scalar::from_bits(166)),
        near: Scalar::from_bits(64),
        far: Scalar::from_bits(640),
        ..base.clone()
    });
    let v = |x: f32, y: f32, z: f32| Vec3::from_f32(x, y, z).unwrap_or_default();
    let floor = Model::owned(
        "floor",
        vec![
            v(-2.0, -1.0, 1.5),
            v(2.0, -1.0, 1.5),
            v(2.0, -1.0, -30.0),
            v(-2.0, -1.0, -30.0),
        ],
        vec![
            v(-1.0, 1.0, 1.0),
            v(-1.0, 1.0, 1.0),
            v(1.0, 1.0, -1.0),
            v(1.0, 1.0, -1.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    let mut tiled = floor.clone();
    // Two repeats across, sixteen away.
    let uv = |u: f32, v: f32| [Scalar::from_num(u), Scalar::from_num(v)];
    tiled.uvs = vec![uv(0.0, 0.0), uv(2.0, 0.0), uv(2.0, 16.0), uv(0.0, 16.0)];
    out.push(SceneDef {
        name: "floor",
        what: "two triangles receding from 1.1 to 32.6 away, lit bright near and dark far: \
               where perspective-correct interpolation matters",
        model: floor,
        rot_x: Angle::ZERO,
        rot_y: Angle::ZERO,
        far: s(40.0),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "floor-textured",
        what: "the floor textured (two repeats across and sixteen away of a 64x64 texture \
               whose texels all differ) and turned 70° about y, so that depth changes steeply \
               along each row: where perspective-correct mapping and its run length matter",
        textured: true,
        model: tiled,
        rot_x: Angle::ZERO,
        rot_y: Angle::from_degrees(70),
        far: s(40.0),
        ..base.clone()
    });
    if let Some(torus) = Model::shape_with_uvs("torus") {
        out.push(SceneDef {
            name: "torus-textured",
            what: "the reference torus with UVs (its seams doubled), textured",
            textured: true,
            model: torus,
            ..base.clone()
        });
    }
    out.push(SceneDef {
        name: "lamp-near",
        what: "the torus beside a point light falling off with the square of the distance, \
               0.3 from its nearest point: strong fall-off across each face",
        lamp: Some(Lamp {
            position: Vec3::new(s(-0.6), s(0.5), s(0.9)),
            intensity: s(1.5),
            attenuation: Attenuation::InverseSquare,
        }),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "lamp-far",
        what: "the torus under a point light 60 away, falling off with the square of the \
               distance at an intensity of 3,000: large distances in Q16.16",
        lamp: Some(Lamp {
            position: Vec3::new(s(-30.0), s(40.0), s(30.0)),
            intensity: s(3000.0),
            attenuation: Attenuation::InverseSquare,
        }),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "glossy",
        what: "the torus with white highlights of shininess 32 (Gouraud shading shows them) \
               under the scene's light and a point light falling off linearly",
        lamp: Some(Lamp {
            position: Vec3::new(s(1.2), s(-0.4), s(1.0)),
            intensity: s(1.0),
            attenuation: Attenuation::Linear,
        }),
        gloss: Some(Gloss {
            color: [255, 255, 255],
            shininess: 32,
        }),
        ..base.clone()
    });
    out.push(SceneDef {
        name: "slivers",
        what: "a disc of 1024 needle triangles (under a pixel wide at the rim), tilted 60°",
        model: sliver_fan(1024),
        rot_x: Angle::from_degrees(-60),
        rot_y: Angle::from_degrees(10),
        ..base
    });
    out
}

pub const AMBIENT: f64 = 0.2;
pub const LIGHT: (V3, f64) = ([-1.0, 1.0, 1.0], 0.8);
pub const BASE: [u8; 3] = [255, 160, 64];

impl SceneDef {
    /// The crate's model matrix, its sines by `trig`.
    pub fn model_matrix(&self, trig: Trig) -> Mat4 {
        Mat4::translation(self.translate)
            * Transform::new().rotated_y(self.rot_y).matrix_by(trig)
            * Transform::new().rotated_x(self.rot_x).matrix_by(trig)
            * Mat4::scaling(Vec3::new(self.scale, self.scale, self.scale))
    }

    /// The ideal model matrix (rotation part and full matrix) in f64.
    fn ideal_model(&self) -> ([[f64; 3]; 3], [[f64; 4]; 4]) {
        let (a, b) = (radians(self.rot_x), radians(self.rot_y));
        let rx = [
            [1.0, 0.0, 0.0],
            [0.0, a.cos(), -a.sin()],
            [0.0, a.sin(), a.cos()],
        ];
        let ry = [
            [b.cos(), 0.0, b.sin()],
            [0.0, 1.0, 0.0],
            [-b.sin(), 0.0, b.cos()],
        ];
        let mut r = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                r[i][j] = (0..3).map(|k| ry[i][k] * rx[k][j]).sum();
            }
        }
        let (s, t) = (f(self.scale), f3(self.translate));
        let mut m = [[0.0; 4]; 4];
        for i in 0..3 {
            for j in 0..3 {
                m[i][j] = r[i][j] * s;
            }
            m[i][3] = t[i];
        }
        m[3][3] = 1.0;
        (r, m)
    }

    fn camera(&self) -> Camera {
        let fov_deg = radians(self.fov).to_degrees();
        Camera::new(
            f3(self.eye),
            f3(self.target),
            [0.0, 1.0, 0.0],
            fov_deg,
            f(self.near),
            f(self.far),
            self.width,
            self.height,
        )
    }

    /// Ideal clip from model.
    fn ideal_clip_from_model(&self) -> [[f64; 4]; 4] {
        let cam = self.camera();
        let (_, m) = self.ideal_model();
        mul4(&cam.m, &m)
    }

    fn frame(&self, precision: Precision) -> Option<Frame> {
        let viewport = Viewport::new(self.width, self.height).ok()?;
        let view = LookAt::new(self.eye, self.target, Vec3::Y).view().ok()?;
        let projection =
            Projection::perspective(self.fov, viewport.aspect(), self.near, self.far).ok()?;
        Some(Frame::new(&view, &projection, viewport).with_precision(precision))
    }
}

/// Lambert's intensity for a normal of any length (ambient only for a zero normal) at world
/// point `at` (read by the scene's point light).
fn lambert(n: V3, at: V3, lamp: Option<&Lamp>) -> f64 {
    let len = dot(n, n).sqrt();
    if len == 0.0 {
        return AMBIENT;
    }
    let n = n.map(|c| c / len);
    let point = lamp.map_or(0.0, |l| l.term(n, at));
    (AMBIENT + LIGHT.1 * dot(n, norm(LIGHT.0)).max(0.0) + point).clamp(0.0, 1.0)
}

/// What the ideal renderer knows about one pixel centre.
#[derive(Clone, Copy, Debug, Default)]
pub struct IdealPixel {
    /// Some front-facing polygon covers the centre by more than its tolerance.
    pub full: bool,
    /// Some polygon's edge passes within its tolerance of the centre.
    pub partial: bool,
    /// A polygon cut by the near or far plane comes within a pixel (its depth plane is not the
    /// one through the snapped vertices of a whole triangle).
    pub clipped: bool,
    /// A polygon so thin that moving its vertices within the tolerance could turn it to face
    /// the other way covers the centre (within the tolerance): whether it is drawn is open.
    pub ambiguous: bool,
    /// The nearest polygon covering the centre: its depth z/w, colour, and whether the centre
    /// is inside it by more than the tolerance.
    pub nearest: Option<(f64, [f64; 3], bool)>,
    /// In a textured scene, the exact texel coordinates (s, t) of the nearest polygon there,
    /// and how far each moves from one pixel to the next (texels per pixel, the larger of x
    /// and y).
    pub texel: Option<([f64; 2], [f64; 2])>,
    /// How far the nearest polygon's depth may move at this pixel when its edges move by the
    /// tolerance (depth gradient times tolerance).
    pub slack: f64,
    /// The depth of the second-nearest polygon covering the centre, and its slack.
    pub second: Option<(f64, f64)>,
    /// The nearest depth (less its slack) of a polygon whose edge passes within the
    /// tolerance: in front of the visible surface, the renderer may show it instead.
    pub partial_z: f64,
}

/// The ideal image of a scene.
pub struct Ideal {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<IdealPixel>,
    /// Ideal screen position (pixels) of every model vertex in front of the camera, with the
    /// bound on the default configuration's transform error there (pixels, before snapping).
    pub vertices: Vec<Option<([f64; 2], f64)>>,
}

/// The difference of the crate's default clip-from-model matrix from the ideal one, entry by
/// entry, and the value of one raw unit of the crate's clip coordinates.
fn matrix_error(scene: &SceneDef) -> ([[f64; 4]; 4], f64) {
    let ideal = scene.ideal_clip_from_model();
    let Some(frame) = scene.frame(Precision::DEFAULT) else {
        return ([[f64::INFINITY; 4]; 4], 0.0);
    };
    let extent = scene
        .model
        .positions
        .iter()
        .flat_map(|p| p.to_bits())
        .map(i32::unsigned_abs)
        .max()
        .unwrap_or(0);
    let m = frame
        .clip_from_model_within(&scene.model_matrix(Trig::Polynomial), extent)
        .to_bits();
    // The crate's matrix is scaled by a power of two (homogeneous coordinates): find it.
    let max = |f: &dyn Fn(usize, usize) -> f64| {
        (0..16).map(|k| f(k / 4, k % 4).abs()).fold(0.0, f64::max)
    };
    let ratio = max(&|i, j| m[i][j] as f64) / max(&|i, j| ideal[i][j]);
    let unit = 2f64.powi(ratio.log2().round() as i32);
    let mut e = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            e[i][j] = (m[i][j] as f64 / unit - ideal[i][j]).abs();
        }
    }
    (e, 1.0 / unit)
}

/// Bound on the clip-space error of a model point under the default configuration: the
/// matrix's error times the point, plus two raw units (the transform's rounding, and the
/// clipper's for points it creates).
fn clip_error((e, raw): &([[f64; 4]; 4], f64), p: V3) -> f64 {
    let v = [p[0].abs(), p[1].abs(), p[2].abs(), 1.0];
    let row = |i: usize| (0..4).map(|k| e[i][k] * v[k]).sum::<f64>();
    [0, 1, 3].map(row).into_iter().fold(0.0, f64::max) + 2.0 * raw
}

/// Screen-space bound (pixels, Euclidean) of a clip-space error `d` at clip point `c`.
fn screen_error(c: &[f64], d: f64, width: f64, height: f64) -> f64 {
    let w = c[3];
    let bx = width / 2.0 * d * (1.0 + (c[0] / w).abs()) / w;
    let by = height / 2.0 * d * (1.0 + (c[1] / w).abs()) / w;
    (bx * bx + by * by).sqrt()
}

/// Renders the ideal image: `shade` picks flat or (perspective-correct) Gouraud colours,
/// `subpixel_bits` the snapping grid the tolerance allows for.
pub fn ideal(scene: &SceneDef, shade: Shade, subpixel_bits: u32) -> Ideal {
    let (w, h) = (scene.width as usize, scene.height as usize);
    let mut pixels = vec![
        IdealPixel {
            partial_z: f64::INFINITY,
            ..IdealPixel::default()
        };
        w * h
    ];
    let m = scene.ideal_clip_from_model();
    let (rot, model) = scene.ideal_model();
    let towards_viewer = norm(sub(f3(scene.eye), f3(scene.target)));
    let world = |p: V3| {
        let c = apply4(&model, p);
        [c[0], c[1], c[2]]
    };
    let err = matrix_error(scene);
    let cell = (1u32 << (4 - subpixel_bits.min(4))) as f64 / 16.0;
    let snap = cell / 2.0 * std::f64::consts::SQRT_2;
    let positions: Vec<V3> = scene.model.positions.iter().map(|p| f3(*p)).collect();
    let colors: Vec<[f64; 3]> = scene
        .model
        .normals
        .iter()
        .zip(&positions)
        .map(|(n, p)| {
            let n = f3(*n);
            let wn = [0, 1, 2].map(|i| (0..3).map(|k| rot[i][k] * n[k]).sum::<f64>());
            let (at, lamp) = (world(*p), scene.lamp.as_ref());
            let diffuse = BASE.map(|b| b as f64 * lambert(wn, at, lamp));
            let len = dot(wn, wn).sqrt();
            let highlight = match scene.gloss {
                Some(g) if len > 0.0 => g.at(wn.map(|c| c / len), at, towards_viewer, lamp),
                _ => [0.0; 3],
            };
            [0, 1, 2].map(|k| (diffuse[k] + highlight[k]).min(255.0))
        })
        .collect();
    let clip: Vec<[f64; 4]> = positions.iter().map(|p| apply4(&m, *p)).collect();
    let vertex_err: Vec<f64> = positions.iter().map(|p| clip_error(&err, *p)).collect();
    let vertices = clip
        .iter()
        .zip(&vertex_err)
        .map(|(c, e)| {
            (c[2] > 0.0 && c[2] <= c[3]).then(|| {
                (
                    [
                        (c[0] / c[3] + 1.0) * w as f64 / 2.0,
                        (1.0 - c[1] / c[3]) * h as f64 / 2.0,
                    ],
                    screen_error(c, *e, w as f64, h as f64),
                )
            })
        })
        .collect();
    for tri in &scene.model.triangles {
        let idx = tri.map(|i| i as usize);
        let (Some(_), Some(_), Some(_)) = (clip.get(idx[0]), clip.get(idx[1]), clip.get(idx[2]))
        else {
            continue;
        };
        let flat = {
            let p = idx.map(|i| world(positions[i]));
            let centre = [0, 1, 2].map(|k| (p[0][k] + p[1][k] + p[2][k]) / 3.0);
            let n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
            let s = lambert(n, centre, scene.lamp.as_ref());
            BASE.map(|b| (b as f64 * s).floor())
        };
        // Clip-space vertices carrying their colours, clipped, projected.
        let poly: Vec<[f64; 7]> = idx
            .iter()
            .map(|&i| {
                let c = clip[i];
                // A textured scene carries the UVs instead of a colour.
                let uv = |i: usize| scene.model.uvs.get(i).map_or([0.0; 2], |uv| uv.map(f));
                let rgb = match shade {
                    _ if scene.textured => [uv(i)[0], uv(i)[1], 0.0],
                    Shade::Flat => flat,
                    _ => colors.get(i).copied().unwrap_or(flat),
                };
                [c[0], c[1], c[2], c[3], rgb[0], rgb[1], rgb[2]]
            })
            .collect();
        let cut = idx
            .iter()
            .any(|&i| !(clip[i][2] > 0.0 && clip[i][2] <= clip[i][3]));
        let poly = clip_near_far(&poly);
        if poly.len() < 3 {
            continue;
        }
        let d = idx.iter().map(|&i| vertex_err[i]).fold(0.0, f64::max);
        let tol = snap
            + poly
                .iter()
                .map(|c| screen_error(c, d, w as f64, h as f64))
                .fold(0.0, f64::max);
        // Screen x, y, z/w, 1/w, r/w, g/w, b/w: all affine in screen space.
        let s: Vec<[f64; 7]> = poly
            .iter()
            .map(|c| {
                let iw = 1.0 / c[3];
                [
                    (c[0] * iw + 1.0) * w as f64 / 2.0,
                    (1.0 - c[1] * iw) * h as f64 / 2.0,
                    c[2] * iw,
                    iw,
                    c[4] * iw,
                    c[5] * iw,
                    c[6] * iw,
                ]
            })
            .collect();
        let area = polygon_area(&s);
        // Moving each vertex by `tol` changes the doubled area by at most `tol` times the
        // perimeter (to first order): a polygon within twice that may face either way.
        let perimeter: f64 = (0..s.len())
            .map(|i| {
                let (a, b) = (s[i], s[(i + 1) % s.len()]);
                ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt()
            })
            .sum();
        let flippable = area.abs() <= 2.0 * tol * perimeter;
        let orient = if area < 0.0 { 1.0 } else { -1.0 };
        if area >= 0.0 && !flippable {
            continue; // back-facing (y down: front faces are negative)
        }
        // The three vertices spanning the largest area define the attribute planes.
        let (mut best, mut plane) = (0.0, (0, 1, 2));
        for j in 1..s.len() - 1 {
            let a = tri_area(&s[0], &s[j], &s[j + 1]).abs();
            if a > best {
                best = a;
                plane = (0, j, j + 1);
            }
        }
        let (pa, pb, pc) = (s[plane.0], s[plane.1], s[plane.2]);
        let det = tri_area(&pa, &pb, &pc);
        // |∇z| in depth per pixel, times the tolerance.
        let gx = ((pb[2] - pa[2]) * (pc[1] - pa[1]) - (pc[2] - pa[2]) * (pb[1] - pa[1])) / det;
        let gy = ((pb[0] - pa[0]) * (pc[2] - pa[2]) - (pc[0] - pa[0]) * (pb[2] - pa[2])) / det;
        let slack = (gx * gx + gy * gy).sqrt() * tol;
        let margin = tol + 1.0;
        let xs = s.iter().map(|v| v[0]);
        let ys = s.iter().map(|v| v[1]);
        let x0 = (xs.clone().fold(f64::INFINITY, f64::min) - margin)
            .floor()
            .max(0.0) as usize;
        let x1 = (xs.fold(f64::NEG_INFINITY, f64::max) + margin)
            .ceil()
            .min(w as f64) as usize;
        let y0 = (ys.clone().fold(f64::INFINITY, f64::min) - margin)
            .floor()
            .max(0.0) as usize;
        let y1 = (ys.fold(f64::NEG_INFINITY, f64::max) + margin)
            .ceil()
            .min(h as f64) as usize;
        for py in y0..y1 {
            for px in x0..x1 {
                let (x, y) = (px as f64 + 0.5, py as f64 + 0.5);
                // Signed distance inside the convex polygon (front faces wind negatively).
                let dist = inside_distance(&s, -orient, x, y);
                let pix = &mut pixels[py * w + px];
                if cut && dist >= -tol - 1.0 {
                    pix.clipped = true;
                }
                if dist < -tol {
                    continue;
                }
                if flippable {
                    pix.ambiguous = true;
                    if area >= 0.0 {
                        continue;
                    }
                }
                let l1 = ((x - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (y - pa[1])) / det;
                let l2 = ((pb[0] - pa[0]) * (y - pa[1]) - (x - pa[0]) * (pb[1] - pa[1])) / det;
                let at = |k: usize| pa[k] + l1 * (pb[k] - pa[k]) + l2 * (pc[k] - pa[k]);
                let z = at(2);
                if dist > tol {
                    pix.full = true;
                } else {
                    pix.partial = true;
                    pix.partial_z = pix.partial_z.min(z - slack);
                }
                if dist < 0.0 {
                    continue;
                }
                let iw = at(3);
                // Texel coordinates s = u·64, t = (1 − v)·64, perspective-correct, here and a
                // pixel to the right and below.
                let st_at = |x: f64, y: f64| {
                    let l1 = ((x - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (y - pa[1])) / det;
                    let l2 = ((pb[0] - pa[0]) * (y - pa[1]) - (x - pa[0]) * (pb[1] - pa[1])) / det;
                    let at = |k: usize| pa[k] + l1 * (pb[k] - pa[k]) + l2 * (pc[k] - pa[k]);
                    [at(4) / at(3) * 64.0, (1.0 - at(5) / at(3)) * 64.0]
                };
                let st = st_at(x, y);
                let rgb = match shade {
                    _ if scene.textured => texel_color(st),
                    Shade::Flat => flat,
                    _ => [at(4) / iw, at(5) / iw, at(6) / iw],
                };
                let texel = scene.textured.then(|| {
                    let (dx, dy) = (st_at(x + 1.0, y), st_at(x, y + 1.0));
                    let grad = [0, 1].map(|k| (dx[k] - st[k]).abs().max((dy[k] - st[k]).abs()));
                    (st, grad)
                });
                match pix.nearest {
                    Some((nz, _, _)) if nz <= z => {
                        if pix.second.is_none_or(|s| z < s.0) {
                            pix.second = Some((z, slack));
                        }
                    }
                    Some((nz, _, _)) => {
                        pix.second = Some((nz, pix.slack));
                        pix.nearest = Some((z, rgb, dist > tol));
                        pix.texel = texel;
                        pix.slack = slack;
                    }
                    None => {
                        pix.nearest = Some((z, rgb, dist > tol));
                        pix.texel = texel;
                        pix.slack = slack;
                    }
                }
            }
        }
    }
    Ideal {
        width: scene.width,
        height: scene.height,
        pixels,
        vertices,
    }
}

fn tri_area(a: &[f64; 7], b: &[f64; 7], c: &[f64; 7]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])
}

/// The crate's image of a scene in one configuration.
pub struct Rendered {
    pub color: Vec<Rgb888>,
    /// Depth as a fraction of the far plane, `None` where nothing was drawn.
    pub depth: Vec<Option<f64>>,
    /// One unit of the depth format, as a fraction.
    pub lsb: f64,
    pub vertices: Vec<ScreenVertex>,
    pub frame: Frame,
}

/// The crate's frame, as a measured function: vertex stage, culling, shading and filling
/// (buffer clears excluded), into a target that counts no fragments (nothing reads them; the
/// firmware's `knobs` preset draws the same way). `#[inline(never)]` so that callgrind can
/// count it alone.
#[inline(never)]
pub fn measured_frame<'a, S: Shading, D: DepthFormat>(
    frame: &Frame,
    scene: &Scene<'_, 2>,
    shading: S,
    cache: &mut [ScreenVertex],
    color: &mut FrameBuffer<'a, Rgb888>,
    depth: &mut DepthBuffer<'a, D>,
) {
    if let (Ok(prepared), Ok(target)) = (
        frame.prepare(scene, cache, shading),
        ColorDepth::new(color, depth),
    ) {
        let _ = prepared.draw(&mut target.uncounted());
    }
}

fn draw_with<D: DepthFormat + Into<f64>>(
    scene: &SceneDef,
    config: &Config,
    zero: D,
    scale: f64,
    repeat: usize,
) -> Option<(Rendered, f64)> {
    let frame = scene.frame(config.precision)?;
    let mesh = Mesh::new(&scene.model.positions, &scene.model.triangles)
        .and_then(|m| m.with_normals(&scene.model.normals))
        .ok()?;
    let mesh = if scene.textured {
        mesh.with_uvs(&scene.model.uvs).ok()?
    } else {
        mesh
    };
    let texels = texels();
    let texture = Texture::new(Texels::Rgb888(&texels), 64, 64).ok()?;
    let texture = if config.affine {
        texture.with_mapping(Mapping::Affine)
    } else {
        texture.with_run(config.run)
    };
    let specular = scene.gloss.map(|g| {
        let [r, g_, b] = g.color;
        Specular::new(Rgb888::new(r, g_, b), g.shininess)
    });
    // A textured surface is white under a white ambient light of 1 alone: its texels as they
    // are.
    let base = if scene.textured {
        Rgb888::new(255, 255, 255)
    } else {
        Rgb888::new(BASE[0], BASE[1], BASE[2])
    };
    let objects =
        [Object::new(&mesh, scene.model_matrix(config.trig), base)
            .with_specular(specular.as_ref())];
    let mut lighting = Lighting::<2>::new(LightColor::WHITE);
    if !scene.textured {
        lighting = Lighting::new(LightColor::gray(Scalar::from_num(AMBIENT)));
        lighting
            .push(DirectionalLight::new(
                Vec3::from_f32(LIGHT.0[0] as f32, LIGHT.0[1] as f32, LIGHT.0[2] as f32)?,
                LightColor::gray(Scalar::from_num(LIGHT.1)),
            ))
            .ok()?;
    }
    if let Some(lamp) = &scene.lamp {
        let light = PointLight::new(lamp.position, lamp.intensity).attenuated(lamp.attenuation);
        lighting.push_point(light).ok()?;
    }
    let world = Scene::new(&objects, lighting);
    let (w, h) = (scene.width, scene.height);
    let mut cache = vec![ScreenVertex::DEFAULT; world.vertex_count()];
    let mut pixels = vec![Rgb888::BLACK; (w * h) as usize];
    let mut depth = vec![zero; (w * h) as usize];
    let mut times = Vec::new();
    for _ in 0..repeat.max(1) {
        let mut color = FrameBuffer::new(&mut pixels, w, h).ok()?;
        let mut z = DepthBuffer::new(&mut depth, w, h).ok()?;
        color.fill(Rgb888::BLACK);
        z.clear();
        let started = Instant::now();
        let (flat, smooth) = (
            Textured {
                texture: &texture,
                light: Flat,
            },
            Textured {
                texture: &texture,
                light: Gouraud,
            },
        );
        match config.shade {
            _ if scene.textured && config.shade == Shade::Flat => {
                measured_frame(&frame, &world, flat, &mut cache, &mut color, &mut z)
            }
            _ if scene.textured => {
                measured_frame(&frame, &world, smooth, &mut cache, &mut color, &mut z)
            }
            Shade::Flat => measured_frame(&frame, &world, Flat, &mut cache, &mut color, &mut z),
            Shade::Gouraud => {
                measured_frame(&frame, &world, Gouraud, &mut cache, &mut color, &mut z)
            }
            Shade::Perspective => measured_frame(
                &frame,
                &world,
                PerspectiveGouraud,
                &mut cache,
                &mut color,
                &mut z,
            ),
        }
        times.push(started.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    let median = times.get(times.len() / 2).copied().unwrap_or(0.0);
    let far = D::FAR;
    let rendered = Rendered {
        color: pixels,
        depth: depth
            .iter()
            .map(|d| (*d != far).then(|| (*d).into() / scale))
            .collect(),
        lsb: 1.0 / scale,
        vertices: cache,
        frame,
    };
    Some((rendered, median))
}

/// Renders `scene` in `config`; `repeat` frames are timed and the median returned (seconds).
pub fn render(scene: &SceneDef, config: &Config, repeat: usize) -> Option<(Rendered, f64)> {
    if config.depth32 {
        draw_with(scene, config, 0u32, 4_294_967_296.0, repeat)
    } else {
        draw_with(scene, config, 0u16, 65_536.0, repeat)
    }
}

/// The metrics of one scene in one configuration (named as in docs/cases.md).
#[derive(Clone, Copy, Debug, Default)]
pub struct Metrics {
    /// Covered pixels (the crate's).
    pub covered: usize,
    /// M1: pixels where the crate's triangles differ from REF_EXACT's.
    pub m1: usize,
    /// M2: FULL pixels not drawn, NONE pixels drawn, and PARTIAL pixels.
    pub missing: usize,
    pub unexpected: usize,
    pub partial: usize,
    /// M5: pixels showing a surface the ideal image hides (reference depths more than 2 LSB
    /// apart).
    pub occlusion: usize,
    /// M4: interpolation error against the plane through the snapped vertices (LSB, max), and
    /// total error against the ideal depth (LSB, max and mean).
    pub depth_plane_max: f64,
    pub depth_max: f64,
    pub depth_mean: f64,
    /// M6: colour error per channel in 8-bit units over pixels inside the ideal surface.
    pub color_max: f64,
    pub color_mean: f64,
    pub psnr: f64,
    /// Colour RMSE over the whole image, background included (what a viewer sees).
    pub image_rmse: f64,
    /// M7: largest vertex error in sub-pixels (1/16 pixel), and how many vertices exceed the
    /// documented bound (half a snapping cell per axis plus the transform bound).
    pub vertex_max: f64,
    pub vertex_over_bound: usize,
    /// Textured scenes, over the pixels compared for colour whose texel is plain (see
    /// `measure`): how far (in texels) the exact texel coordinates lie outside the texel
    /// shown, at most, and how many of them show another texel.
    pub texel_max: f64,
    pub texel_over: usize,
    pub texel_compared: usize,
}

/// Compares one configuration's image with the references.
pub fn measure(scene: &SceneDef, config: &Config, ideal: &Ideal, r: &Rendered) -> Metrics {
    let (w, h) = (scene.width as usize, scene.height as usize);
    let mut m = Metrics::default();
    let rect = PixelRect::of_size(scene.width, scene.height);
    // M1, and the snapped planes of the triangles drawn without clipping (for M4).
    let mut plane_err = vec![f64::INFINITY; w * h];
    for tri in &scene.model.triangles {
        let v = tri.map(|i| r.vertices.get(i as usize).copied().unwrap_or_default());
        if !v.iter().all(|v| v.is_inside()) {
            continue;
        }
        let p = v.map(|v| v.point());
        let exact = model_triangle(p, rect);
        let mut ours = BTreeSet::new();
        for span in triangle_spans(p, rect) {
            for x in span.x0..span.x1 {
                ours.insert((x, span.y));
            }
        }
        m.m1 += exact.symmetric_difference(&ours).count();
        let a2 = (p[1].x as f64 - p[0].x as f64) * (p[2].y as f64 - p[0].y as f64)
            - (p[2].x as f64 - p[0].x as f64) * (p[1].y as f64 - p[0].y as f64);
        if a2 >= 0.0 {
            continue; // culled
        }
        let z = v.map(|v| v.depth() as f64 / (1u64 << 30) as f64);
        for (px, py) in exact {
            let i = py as usize * w + px as usize;
            let Some(Some(zi)) = r.depth.get(i) else {
                continue;
            };
            let (x, y) = (px as f64 * 16.0 + 8.0, py as f64 * 16.0 + 8.0);
            let pf = p.map(|q| (q.x as f64, q.y as f64));
            let l1 =
                ((x - pf[0].0) * (pf[2].1 - pf[0].1) - (pf[2].0 - pf[0].0) * (y - pf[0].1)) / a2;
            let l2 =
                ((pf[1].0 - pf[0].0) * (y - pf[0].1) - (x - pf[0].0) * (pf[1].1 - pf[0].1)) / a2;
            let zp = (z[0] + l1 * (z[1] - z[0]) + l2 * (z[2] - z[0])).clamp(0.0, 1.0);
            let e = (zi - zp).abs() / r.lsb;
            plane_err[i] = plane_err[i].min(e);
        }
    }
    let (mut depth_sum, mut depth_n) = (0.0, 0usize);
    let (mut col_sum, mut col_sq, mut col_n) = (0.0, 0.0, 0usize);
    let mut image_sq = 0.0;
    for (i, ip) in ideal.pixels.iter().enumerate() {
        let drawn = r.depth[i].is_some();
        let c = r.color[i];
        let got = [c.r(), c.g(), c.b()].map(f64::from);
        let want = ip.nearest.map_or([0.0; 3], |n| n.1);
        image_sq += (0..3).map(|k| (got[k] - want[k]).powi(2)).sum::<f64>();
        if drawn {
            m.covered += 1;
            if plane_err[i].is_finite() && !ip.clipped {
                m.depth_plane_max = m.depth_plane_max.max(plane_err[i]);
            }
        }
        if ip.full && !drawn {
            m.missing += 1;
        }
        if !ip.full && !ip.partial && !ip.ambiguous && drawn {
            m.unexpected += 1;
        }
        if (ip.partial || ip.ambiguous) && !ip.full {
            m.partial += 1;
        }
        if ip.ambiguous {
            continue;
        }
        let (Some(zi), Some((z1, rgb, true))) = (r.depth[i], ip.nearest) else {
            continue;
        };
        if ip.partial_z <= z1 + ip.slack + 2.0 * r.lsb {
            continue; // a polygon in front may legitimately cover it
        }
        if let Some((z2, slack2)) = ip.second {
            if z2 - z1 <= 2.0 * r.lsb + ip.slack + slack2 {
                continue; // too close to call
            }
            if (zi - z2).abs() < (zi - z1).abs() {
                m.occlusion += 1;
                continue;
            }
        }
        // Pixels whose texel is plain: the exact point stays in one texel when the pixel's
        // sample moves by 1/8 pixel (its snapped vertices' reach) and the texel coordinates by
        // 1/16 texel. Where texels are smaller than that, which one nearest sampling shows is
        // aliasing, not error.
        if let Some((st, grad)) = ip.texel {
            let plain = (0..2).all(|k| {
                let f = st[k] - st[k].floor();
                f.min(1.0 - f) > grad[k] / 8.0 + 1.0 / 16.0
            });
            if plain {
                // Another colour than a texel's counts as the farthest texel.
                let e = texel_of(c).map_or(32.0, |shown| {
                    let off = |k: usize| {
                        let d = (shown[k] + 0.5 - st[k] + 32.0).rem_euclid(64.0) - 32.0;
                        (d.abs() - 0.5).max(0.0)
                    };
                    off(0).max(off(1))
                });
                m.texel_max = m.texel_max.max(e);
                m.texel_over += (e > 0.0) as usize;
                m.texel_compared += 1;
            }
        }
        let e = (zi - z1).abs() / r.lsb;
        m.depth_max = m.depth_max.max(e);
        depth_sum += e;
        depth_n += 1;
        for k in 0..3 {
            let d = (got[k] - rgb[k]).abs();
            m.color_max = m.color_max.max(d);
            col_sum += d;
            col_sq += d * d;
            col_n += 1;
        }
    }
    m.depth_mean = depth_sum / depth_n.max(1) as f64;
    m.color_mean = col_sum / col_n.max(1) as f64;
    let rmse = (col_sq / col_n.max(1) as f64).sqrt();
    m.psnr = if rmse > 0.0 {
        20.0 * (255.0 / rmse).log10()
    } else {
        f64::INFINITY
    };
    m.image_rmse = (image_sq / (3 * w * h) as f64).sqrt();
    // M7.
    let cell = (1u32 << (4 - config.precision.subpixel_bits().min(4))) as f64;
    for (v, ideal) in r.vertices.iter().zip(&ideal.vertices) {
        let (Some((p, bound)), true) = (ideal, v.is_inside()) else {
            continue;
        };
        let q = v.point();
        let e = (q.x as f64 - p[0] * 16.0)
            .abs()
            .max((q.y as f64 - p[1] * 16.0).abs());
        m.vertex_max = m.vertex_max.max(e);
        // Half a cell per axis from snapping plus the transform bound (in sub-pixels).
        if e > cell / 2.0 + bound * 16.0 + 1e-9 {
            m.vertex_over_bound += 1;
        }
    }
    m
}

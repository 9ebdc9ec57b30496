//! Scene files for the render tool (`--scene FILE`): several objects, lights and a camera in
//! TOML, drawn through fixed3d's `Renderer` (per-object shading, style, texture and highlights,
//! wireframes depth-tested against solids). The format is in docs/tools.md; paths in a file
//! are relative to it.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use embedded_graphics::geometry::Size;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics_simulator::SimulatorDisplay;
use fixed3d::camera::Camera;
use fixed3d::math::{Scalar, Vec3};
use fixed3d::mesh::{Mesh, Specular};
use fixed3d::pipeline::{Bin, ScreenVertex, Stats};
use fixed3d::render::{Model as Placed, Renderer, Shade};
use fixed3d::scene::{Attenuation, Light, LightColor, PointLight};
use fixed3d::texture::{Texels, Texture};
use serde::Deserialize;

use crate::desktop::{load_texels, Model};

/// A scene file as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// White ambient light, 0 to 1 (default 0.2).
    #[serde(default)]
    pub ambient: Option<f32>,
    pub camera: CameraDef,
    #[serde(default)]
    pub lights: Vec<LightDef>,
    pub objects: Vec<ObjectDef>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraDef {
    pub eye: [f32; 3],
    #[serde(default)]
    pub target: [f32; 3],
    /// Vertical field of view in degrees (default 60), unless `ortho` gives a height.
    pub fov: Option<f32>,
    /// An orthographic view this many units high.
    pub ortho: Option<f32>,
    pub near: Option<f32>,
    pub far: Option<f32>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightDef {
    /// A directional light: the direction from the surface towards it.
    pub direction: Option<[f32; 3]>,
    /// A point light: where it is.
    pub position: Option<[f32; 3]>,
    /// White of this strength (default 1 for point lights, 0.8 for directional ones)...
    pub intensity: Option<f32>,
    /// ...or a strength per channel.
    pub color: Option<[f32; 3]>,
    /// For point lights: none (default), linear or inverse-square.
    pub attenuation: Option<String>,
    /// For point lights: the distance from which it lights nothing.
    pub range: Option<f32>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectDef {
    /// A built-in shape: cube, tetrahedron, octahedron, sphere or torus...
    pub shape: Option<String>,
    /// ...or an OBJ file.
    pub obj: Option<String>,
    #[serde(default)]
    pub position: [f32; 3],
    /// Degrees about x, then y, then z.
    #[serde(default)]
    pub rotation: [f32; 3],
    pub scale: Option<f32>,
    /// 0 to 255 a channel (default 255, 160, 64).
    pub color: Option<[u8; 3]>,
    /// unlit, flat (default), gouraud or perspective-gouraud.
    pub shade: Option<String>,
    /// solid (default) or wire.
    pub style: Option<String>,
    /// A PNG mapped through the model's UVs (a shape's: the cube's faces, the sphere as a
    /// globe, round the torus and its tube).
    pub texture: Option<String>,
    /// White highlights: strength (0 to 1) and shininess (Gouraud shades).
    pub specular: Option<(f32, u16)>,
}

/// A scene file read, its models and textures loaded.
pub struct LoadedScene {
    file: SceneFile,
    models: Vec<Model>,
    /// Per object: the index of its texture in `texels`, if any.
    textures: Vec<Option<usize>>,
    texels: Vec<(Vec<Rgb888>, u16, u16)>,
}

/// What rendering a scene file produced.
pub struct SceneFrame {
    pub pixels: Vec<Rgb888>,
    pub stats: Stats,
    pub time: Duration,
}

fn scalar(v: f32, what: &str) -> Result<Scalar, String> {
    Scalar::checked_from_num(v).ok_or_else(|| format!("{what}: {v} is outside ±32768"))
}

fn vec3(v: [f32; 3], what: &str) -> Result<Vec3, String> {
    Ok(Vec3::new(
        scalar(v[0], what)?,
        scalar(v[1], what)?,
        scalar(v[2], what)?,
    ))
}

/// The value of `choices` named `v`, or an error naming them.
fn choice<T: Copy>(v: &str, what: &str, choices: &[(&str, T)]) -> Result<T, String> {
    let found = choices.iter().find(|(name, _)| *name == v).map(|&(_, c)| c);
    found.ok_or_else(|| {
        let names: Vec<&str> = choices.iter().map(|(name, _)| *name).collect();
        format!("{what} is {}, got {v:?}", names.join(", "))
    })
}

impl LoadedScene {
    /// Reads and checks `path`, loading its OBJ files and textures (relative to it).
    pub fn load(path: &str) -> Result<LoadedScene, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
        let file: SceneFile = toml::from_str(&text).map_err(|e| format!("{path}: {e}"))?;
        let dir = Path::new(path).parent().unwrap_or(Path::new("."));
        let near = |p: &str| -> PathBuf { dir.join(p) };
        if file.objects.is_empty() {
            return Err(format!("{path}: no objects"));
        }
        let (mut models, mut textures, mut texels) = (Vec::new(), Vec::new(), Vec::new());
        for (k, o) in file.objects.iter().enumerate() {
            let what = format!("{path}: object {}", k + 1);
            let shape = |name: &str| match o.texture {
                Some(_) => Model::shape_with_uvs(name),
                None => Model::shape(name),
            };
            let model = match (&o.shape, &o.obj) {
                (Some(name), None) => shape(name).ok_or_else(|| {
                    format!(
                        "{what}: unknown shape {name:?}: cube, tetrahedron, octahedron, sphere \
                         or torus"
                    )
                })?,
                (None, Some(obj)) => {
                    let p = near(obj);
                    Model::load_obj(&p.to_string_lossy()).map_err(|e| format!("{what}: {e}"))?
                }
                _ => return Err(format!("{what}: give one of `shape` and `obj`")),
            };
            models.push(model);
            textures.push(match &o.texture {
                Some(t) => {
                    let loaded = load_texels(&near(t).to_string_lossy())
                        .map_err(|e| format!("{what}: {e}"))?;
                    texels.push(loaded);
                    Some(texels.len() - 1)
                }
                None => None,
            });
        }
        Ok(LoadedScene {
            file,
            models,
            textures,
            texels,
        })
    }

    /// The scene's lights: the ambient light, then the file's in order.
    fn lights(&self) -> Result<Vec<Light>, String> {
        let ambient = self.file.ambient.unwrap_or(0.2);
        if !(0.0..=1.0).contains(&ambient) {
            return Err(format!("ambient is between 0 and 1, got {ambient}"));
        }
        let mut out = vec![Light::ambient(scalar(ambient, "ambient")?)];
        for (k, l) in self.file.lights.iter().enumerate() {
            let what = format!("light {}", k + 1);
            let color = |default: f32| -> Result<LightColor, String> {
                match (l.intensity, l.color) {
                    (Some(_), Some(_)) => Err(format!("{what}: give `intensity` or `color`")),
                    (None, Some([r, g, b])) => Ok(LightColor::new(
                        scalar(r, &what)?,
                        scalar(g, &what)?,
                        scalar(b, &what)?,
                    )),
                    (i, None) => Ok(LightColor::gray(scalar(i.unwrap_or(default), &what)?)),
                }
            };
            out.push(match (l.direction, l.position) {
                (Some(d), None) => {
                    if l.attenuation.is_some() || l.range.is_some() {
                        return Err(format!(
                            "{what}: `attenuation` and `range` are for point lights"
                        ));
                    }
                    Light::directional(vec3(d, &what)?, color(0.8)?)
                }
                (None, Some(p)) => {
                    let choices = [
                        ("none", Attenuation::None),
                        ("linear", Attenuation::Linear),
                        ("inverse-square", Attenuation::InverseSquare),
                    ];
                    let a = l.attenuation.as_deref().unwrap_or("none");
                    let mut point = PointLight::new(vec3(p, &what)?, color(1.0)?)
                        .attenuated(choice(a, &format!("{what}: attenuation"), &choices)?);
                    if let Some(r) = l.range {
                        point = point.within(scalar(r, &what)?);
                    }
                    point.into()
                }
                _ => return Err(format!("{what}: give one of `direction` and `position`")),
            });
        }
        Ok(out)
    }

    /// The camera, for a viewport of aspect `width / height`.
    fn camera(&self) -> Result<Camera, String> {
        let c = &self.file.camera;
        let near = scalar(c.near.unwrap_or(0.1), "camera near")?;
        let far = scalar(c.far.unwrap_or(100.0), "camera far")?;
        let lens = match (c.fov, c.ortho) {
            (_, Some(height)) => Camera::orthographic(scalar(height, "camera ortho")?, near, far),
            (fov, None) => Camera::perspective(fov.unwrap_or(60.0), near, far),
        };
        Ok(lens.looking_at(vec3(c.eye, "camera eye")?, vec3(c.target, "camera target")?))
    }

    /// Draws the scene at `width` x `height` over `background`, in bands of `band_rows` rows
    /// (0: one pass).
    pub fn render(
        &self,
        width: u32,
        height: u32,
        background: Rgb888,
        band_rows: u32,
    ) -> Result<SceneFrame, String> {
        let lights = self.lights()?;
        let camera = self.camera()?;
        let meshes: Vec<Mesh<'_>> = self.models.iter().map(Model::mesh).collect();
        let mut textures = Vec::new();
        for (texels, w, h) in &self.texels {
            textures.push(Texture::new(Texels::Rgb888(texels), *w, *h).map_err(|e| e.to_string())?);
        }
        let glosses: Vec<Option<Specular>> = self
            .file
            .objects
            .iter()
            .map(|o| {
                o.specular.map(|(strength, shininess)| {
                    let grey = (strength.clamp(0.0, 1.0) * 255.0).round() as u8;
                    Specular::new(Rgb888::new(grey, grey, grey), shininess)
                })
            })
            .collect();
        let mut placed = Vec::new();
        for (k, o) in self.file.objects.iter().enumerate() {
            let what = format!("object {}", k + 1);
            let [r, g, b] = o.color.unwrap_or([255, 160, 64]);
            let [rx, ry, rz] = o.rotation;
            let mut m = Placed::new(&meshes[k], Rgb888::new(r, g, b))
                .scaled(scalar(o.scale.unwrap_or(1.0), &what)?)
                .rotated_x(rx)
                .rotated_y(ry)
                .rotated_z(rz)
                .translated(vec3(o.position, &what)?);
            let shades = [
                ("unlit", Shade::Unlit),
                ("flat", Shade::Flat),
                ("gouraud", Shade::Gouraud),
                ("perspective-gouraud", Shade::PerspectiveGouraud),
            ];
            let shade = o.shade.as_deref().unwrap_or("flat");
            m = m.shaded(choice(shade, &format!("{what}: shade"), &shades)?);
            match o.style.as_deref().unwrap_or("solid") {
                "solid" => {}
                "wire" => m = m.wireframe(),
                s => return Err(format!("{what}: style is solid or wire, got {s:?}")),
            }
            if let Some(t) = self.textures[k] {
                m = m.textured(&textures[t]);
            }
            if let Some(gloss) = &glosses[k] {
                m = m.glossy(gloss);
            }
            placed.push(m);
        }
        let vertices: usize = meshes.iter().map(|m| m.positions().len()).sum();
        let triangles: usize = meshes.iter().map(|m| m.triangles().len()).sum();
        let rows = if band_rows == 0 {
            height
        } else {
            band_rows.min(height)
        };
        let cells = (width * rows) as usize;
        let (mut cache, mut bins) = (
            vec![ScreenVertex::DEFAULT; vertices],
            vec![Bin::EMPTY; triangles],
        );
        let (mut color, mut depth) = (vec![background; cells], vec![0u16; cells]);
        let mut renderer = Renderer::from_slices(&mut cache, &mut bins, &mut color, &mut depth)
            .with_background(background);
        let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(width, height));
        let started = Instant::now();
        let stats = renderer
            .render(&placed, &lights, &camera, &mut display)
            .map_err(|e| e.to_string())?;
        let time = started.elapsed();
        let pixels = (0..height as i32)
            .flat_map(|y| (0..width as i32).map(move |x| (x, y)))
            .map(|(x, y)| display.get_pixel(embedded_graphics::geometry::Point::new(x, y)))
            .collect();
        Ok(SceneFrame {
            pixels,
            stats,
            time,
        })
    }
}

//! The headless render tool: one frame of an OBJ model or a built-in shape to a PNG file, for
//! scripts, documentation and tests. No window, no SDL.
//!
//! ```text
//! cargo run --release --example render -- [OPTIONS]
//!   --obj PATH | --shape NAME        mesh; NAME is cube, tetrahedron, octahedron, sphere or torus
//!   --scene FILE                     objects, lights and camera from a TOML scene file (see
//!                                    docs/tools.md); only --out, --size, --bg and --bands go
//!                                    with it
//!   --out PATH                       PNG to write (default target/render/frame.png in the
//!                                    checkout)
//!   --size WxH                       default 320x240
//!   --mode wire|flat|gouraud|perspective-gouraud
//!                                    default flat
//!   --eye X,Y,Z --target X,Y,Z --up X,Y,Z
//!                                    look-at camera (up defaults to 0,1,0); without --eye the
//!                                    model's bounding box is framed
//!   --fov DEG                        vertical field of view, default 60
//!   --ortho                          orthographic: no perspective, the model filling the height
//!   --near N --far F                 clip planes (defaults derived from the framing)
//!   --color R,G,B                    object colour 0-255 (default 255,160,64)
//!   --ambient A                      ambient intensity 0-1 (default 0.2)
//!   --light X,Y,Z[,I | ,R,G,B]       direction towards a directional light and its intensity,
//!                                    white or per channel (default one light (-1,1,1) at 0.8,
//!                                    unless --ambient or --point-light is given); repeatable
//!   --point-light X,Y,Z[,I | ,R,G,B] a point light at world position X,Y,Z (intensity default
//!                                    1); repeatable
//!   --attenuation none|linear|inverse-square
//!                                    how point lights fall off with distance d: 1, 1/(1+d) or
//!                                    1/(1+d²) (default none)
//!   --range R                        point lights light nothing from distance R on
//!   --specular S,SHININESS           white highlights of strength S (0-1) and exponent
//!                                    SHININESS (1-65535) on untextured models, in the Gouraud
//!                                    modes
//!   --bg R,G,B                       background (default 0,0,0)
//!   --no-cull  --no-depth
//!   --bands ROWS                     render in horizontal bands of ROWS rows (same image)
//!   --texture PATH                   PNG mapped through the OBJ's `vt` (without it, the
//!                                    `map_Kd` of the OBJ's `mtllib`, if any and readable),
//!                                    lit by --mode
//!   --filter nearest|bilinear        texture sampling (default nearest)
//!   --wrap repeat|clamp              outside UVs [0, 1) (default repeat)
//!   --affine                         map UVs linearly on screen (default perspective-correct)
//! ```
//!
//! Prints `rendered WxH in T us: covered N pixels, drew K of M triangles`. Exit status 0 on
//! success, 2 for bad arguments, 1 for an unreadable or invalid OBJ file (or an unwritable PNG).

#[path = "common/desktop.rs"]
mod desktop;
#[path = "common/scene_file.rs"]
mod scene_file;

use desktop::{framed, render, save_png, Mode, Model, Placed, View};
use embedded_graphics::pixelcolor::Rgb888;
use fixed3d::camera::LookAt;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::Specular;
use fixed3d::projection::{Projection, ProjectionError, Viewport};
use fixed3d::scene::{Attenuation, Light, LightColor};
use fixed3d::texture::{Filter, Mapping, Texels, Texture, Wrap};

const USAGE: &str = "usage: render [--obj PATH | --shape cube|tetrahedron|octahedron|sphere|torus | --scene FILE] [--out PATH] \
[--size WxH] [--mode wire|flat|gouraud|perspective-gouraud] [--ortho] [--eye X,Y,Z] [--target X,Y,Z] [--up X,Y,Z] [--fov DEG] [--near N] [--far F] \
[--color R,G,B] [--ambient A] [--light X,Y,Z[,I|,R,G,B]]... [--point-light X,Y,Z[,I|,R,G,B]]... \
[--attenuation none|linear|inverse-square] [--range R] [--specular S,SHININESS] [--bg R,G,B] [--no-cull] [--no-depth] [--bands ROWS] \
[--texture PATH] [--filter nearest|bilinear] [--wrap repeat|clamp] [--affine]";

/// Where the PNG goes without `--out`: under the checkout's `target/`, never beside the sources.
const DEFAULT_OUT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/target/render/frame.png");

/// The largest coordinate Q16.16 holds, for messages about the fixed-point range.
const RANGE: f64 = 32767.0;

/// A failure and the exit status it earns.
enum Failure {
    Usage(String),
    Input(String),
}

struct Options {
    source: Option<Source>,
    /// `--scene FILE`: objects, lights and camera from a scene file.
    scene: Option<String>,
    /// The flags given that a scene file replaces.
    scene_flags: Vec<String>,
    out: String,
    size: (u32, u32),
    mode: Mode,
    eye: Option<Vec3>,
    target: Option<Vec3>,
    up: Vec3,
    fov: f32,
    near: Option<Scalar>,
    far: Option<Scalar>,
    color: Rgb888,
    ambient: Scalar,
    lights: Vec<Light>,
    /// How every point light falls off, and where it stops.
    attenuation: Attenuation,
    range: Option<Scalar>,
    ortho: bool,
    /// White highlights on every untextured model (Gouraud modes).
    specular: Option<Specular>,
    background: Rgb888,
    cull: bool,
    depth: bool,
    bands: u32,
    /// `--ambient` was given (no default directional light then).
    ambient_given: bool,
    texture: Option<String>,
    filter: Filter,
    wrap: Wrap,
    mapping: Mapping,
}

enum Source {
    Obj(String),
    Shape(String),
}

fn numbers(s: &str, what: &str, min: usize, max: usize) -> Result<Vec<f32>, Failure> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() < min || parts.len() > max {
        return Err(Failure::Usage(format!(
            "{what} takes {min} to {max} comma-separated numbers, got {s:?}"
        )));
    }
    parts
        .iter()
        .map(|p| match p.trim().parse::<f32>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(Failure::Usage(format!(
                "{what}: {p:?} is not a finite number"
            ))),
        })
        .collect()
}

fn scalar(v: f32, what: &str) -> Result<Scalar, Failure> {
    Scalar::checked_from_num(v)
        .ok_or_else(|| Failure::Usage(format!("{what}: {v} is outside ±32768")))
}

fn vec3(s: &str, what: &str) -> Result<Vec3, Failure> {
    let n = numbers(s, what, 3, 3)?;
    Ok(Vec3::new(
        scalar(n[0], what)?,
        scalar(n[1], what)?,
        scalar(n[2], what)?,
    ))
}

fn rgb(s: &str, what: &str) -> Result<Rgb888, Failure> {
    let n = numbers(s, what, 3, 3)?;
    let ch = |v: f32| {
        if (0.0..=255.0).contains(&v) && v.fract() == 0.0 {
            Ok(v as u8)
        } else {
            Err(Failure::Usage(format!(
                "{what}: channels are whole numbers 0-255, got {v}"
            )))
        }
    };
    Ok(Rgb888::new(ch(n[0])?, ch(n[1])?, ch(n[2])?))
}

fn parse_args(args: &[String]) -> Result<Options, Failure> {
    let mut o = Options {
        source: None,
        scene: None,
        scene_flags: Vec::new(),
        out: DEFAULT_OUT.into(),
        size: (320, 240),
        mode: Mode::Flat,
        eye: None,
        target: None,
        up: Vec3::Y,
        fov: 60.0,
        near: None,
        far: None,
        color: Rgb888::new(255, 160, 64),
        ambient: Scalar::from_num(0.2),
        lights: Vec::new(),
        background: Rgb888::new(0, 0, 0),
        cull: true,
        depth: true,
        bands: 0,
        ambient_given: false,
        attenuation: Attenuation::None,
        range: None,
        ortho: false,
        specular: None,
        texture: None,
        filter: Filter::Nearest,
        wrap: Wrap::Repeat,
        mapping: Mapping::Perspective,
    };
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let mut value = || {
            it.next()
                .cloned()
                .ok_or_else(|| Failure::Usage(format!("{flag} needs a value")))
        };
        if ![
            "--scene", "--out", "--size", "--bg", "--bands", "-h", "--help",
        ]
        .contains(&flag.as_str())
        {
            o.scene_flags.push(flag.clone());
        }
        match flag.as_str() {
            "--scene" => o.scene = Some(value()?),
            "--obj" => o.source = Some(Source::Obj(value()?)),
            "--shape" => o.source = Some(Source::Shape(value()?)),
            "--out" => o.out = value()?,
            "--size" => {
                let v = value()?;
                let (w, h) = v
                    .split_once(['x', 'X'])
                    .ok_or_else(|| Failure::Usage(format!("--size takes WxH, got {v:?}")))?;
                let dim = |s: &str| {
                    s.trim()
                        .parse::<u32>()
                        .ok()
                        .filter(|d| (1..=Viewport::MAX_SIZE).contains(d))
                };
                match (dim(w), dim(h)) {
                    (Some(w), Some(h)) => o.size = (w, h),
                    _ => {
                        return Err(Failure::Usage(format!(
                            "--size: each dimension is 1 to {}, got {v:?}",
                            Viewport::MAX_SIZE
                        )))
                    }
                }
            }
            "--mode" => {
                let v = value()?;
                o.mode = Mode::parse(&v).ok_or_else(|| {
                    Failure::Usage(format!(
                        "--mode is wire, flat, gouraud or perspective-gouraud, got {v:?}"
                    ))
                })?;
            }
            "--eye" => o.eye = Some(vec3(&value()?, "--eye")?),
            "--target" => o.target = Some(vec3(&value()?, "--target")?),
            "--up" => o.up = vec3(&value()?, "--up")?,
            "--fov" => {
                let v = numbers(&value()?, "--fov", 1, 1)?[0];
                if !(v > 0.0 && v < 180.0) {
                    return Err(Failure::Usage(format!(
                        "--fov is between 0 and 180 degrees, got {v}"
                    )));
                }
                o.fov = v;
            }
            "--near" => o.near = Some(scalar(numbers(&value()?, "--near", 1, 1)?[0], "--near")?),
            "--far" => o.far = Some(scalar(numbers(&value()?, "--far", 1, 1)?[0], "--far")?),
            "--color" => o.color = rgb(&value()?, "--color")?,
            "--ambient" => {
                let v = numbers(&value()?, "--ambient", 1, 1)?[0];
                if !(0.0..=1.0).contains(&v) {
                    return Err(Failure::Usage(format!(
                        "--ambient is between 0 and 1, got {v}"
                    )));
                }
                o.ambient = scalar(v, "--ambient")?;
                o.ambient_given = true;
            }
            "--light" => {
                let n = numbers(&value()?, "--light", 3, 6)?;
                let towards = vec3_of(&n, "--light")?;
                if towards == Vec3::ZERO {
                    return Err(Failure::Usage(
                        "--light: the direction must not be zero".into(),
                    ));
                }
                let color = light_color(n.get(3..).unwrap_or(&[]), 0.8, "--light")?;
                push_light(&mut o.lights, Light::directional(towards, color))?;
            }
            "--point-light" => {
                let n = numbers(&value()?, "--point-light", 3, 6)?;
                let at = vec3_of(&n, "--point-light")?;
                let color = light_color(n.get(3..).unwrap_or(&[]), 1.0, "--point-light")?;
                push_light(&mut o.lights, Light::point(at, color))?;
            }
            "--attenuation" => {
                let choices = [
                    ("none", Attenuation::None),
                    ("linear", Attenuation::Linear),
                    ("inverse-square", Attenuation::InverseSquare),
                ];
                o.attenuation = choice(&value()?, "--attenuation", &choices)?;
            }
            "--range" => {
                let v = numbers(&value()?, "--range", 1, 1)?[0];
                if v <= 0.0 {
                    return Err(Failure::Usage(format!("--range is above 0, got {v}")));
                }
                o.range = Some(scalar(v, "--range")?);
            }
            "--bg" => o.background = rgb(&value()?, "--bg")?,
            "--texture" => o.texture = Some(value()?),
            "--filter" => {
                let choices = [("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)];
                o.filter = choice(&value()?, "--filter", &choices)?;
            }
            "--wrap" => {
                let choices = [("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp)];
                o.wrap = choice(&value()?, "--wrap", &choices)?;
            }
            "--affine" => o.mapping = Mapping::Affine,
            "--ortho" => o.ortho = true,
            "--specular" => {
                let n = numbers(&value()?, "--specular", 2, 2)?;
                let (strength, shininess) = (n[0], n[1]);
                if !(0.0..=1.0).contains(&strength) {
                    return Err(Failure::Usage(format!(
                        "--specular: the strength is between 0 and 1, got {strength}"
                    )));
                }
                if !(1.0..=65_535.0).contains(&shininess) || shininess.fract() != 0.0 {
                    return Err(Failure::Usage(format!(
                        "--specular: the shininess is a whole number from 1 to 65535, got \
                         {shininess}"
                    )));
                }
                let grey = (strength * 255.0).round() as u8;
                let white = Rgb888::new(grey, grey, grey);
                o.specular = Some(Specular::new(white, shininess as u16));
            }
            "--no-cull" => o.cull = false,
            "--no-depth" => o.depth = false,
            "--bands" => {
                let v = value()?;
                o.bands = v.parse::<u32>().ok().filter(|&b| b >= 1).ok_or_else(|| {
                    Failure::Usage(format!(
                        "--bands takes a row count of at least 1, got {v:?}"
                    ))
                })?;
            }
            "-h" | "--help" => return Err(Failure::Usage(String::new())),
            other => return Err(Failure::Usage(format!("unknown option {other:?}"))),
        }
    }
    if o.scene.is_some() {
        if let Some(flag) = o.scene_flags.first() {
            return Err(Failure::Usage(format!(
                "{flag}: with --scene, the scene file gives the objects, lights and camera \
                 (only --out, --size, --bg and --bands go with it)"
            )));
        }
        return Ok(o);
    }
    if o.source.is_none() {
        return Err(Failure::Usage(
            "give a mesh with --obj PATH or --shape NAME, or a scene with --scene FILE".into(),
        ));
    }
    // The default light joins the default ambient light only: `--ambient A` alone lights by
    // A alone (`--ambient 1` shows a texture's texels as they are).
    if o.lights.is_empty() && !o.ambient_given {
        o.lights = desktop::default_lights();
    }
    // --attenuation and --range apply to every point light, wherever they were given.
    for light in &mut o.lights {
        if let Light::Point(p) = light {
            p.attenuation = o.attenuation;
            p.range = o.range;
        }
    }
    Ok(o)
}

/// The first three of `n` as a vector.
fn vec3_of(n: &[f32], flag: &str) -> Result<Vec3, Failure> {
    let c = |k: usize| scalar(n.get(k).copied().unwrap_or(0.0), flag);
    Ok(Vec3::new(c(0)?, c(1)?, c(2)?))
}

/// A light's colour from nothing (white at `default`), one intensity or three per channel,
/// each from 0 to 100.
fn light_color(n: &[f32], default: f32, flag: &str) -> Result<LightColor, Failure> {
    if n.iter().any(|i| !(0.0..=100.0).contains(i)) {
        return Err(Failure::Usage(format!(
            "{flag}: intensities are between 0 and 100, got {n:?}"
        )));
    }
    match *n {
        [] => Ok(LightColor::gray(scalar(default, flag)?)),
        [i] => Ok(LightColor::gray(scalar(i, flag)?)),
        [r, g, b] => Ok(LightColor::new(
            scalar(r, flag)?,
            scalar(g, flag)?,
            scalar(b, flag)?,
        )),
        _ => Err(Failure::Usage(format!(
            "{flag} takes X,Y,Z, X,Y,Z,I or X,Y,Z,R,G,B"
        ))),
    }
}

/// Adds a directional or point light, or says there are too many.
fn push_light(lights: &mut Vec<Light>, light: Light) -> Result<(), Failure> {
    if lights.len() == desktop::MAX_LIGHTS {
        return Err(Failure::Usage(format!(
            "at most {} directional and point lights",
            desktop::MAX_LIGHTS
        )));
    }
    lights.push(light);
    Ok(())
}

/// The value of `choices` named `v`, or a usage error naming them.
fn choice<T: Copy>(v: &str, flag: &str, choices: &[(&str, T)]) -> Result<T, Failure> {
    choices
        .iter()
        .find(|(name, _)| *name == v)
        .map(|&(_, c)| c)
        .ok_or_else(|| {
            let names: Vec<&str> = choices.iter().map(|(name, _)| *name).collect();
            Failure::Usage(format!("{flag} is {}, got {v:?}", names.join(" or ")))
        })
}

fn run(args: &[String]) -> Result<String, Failure> {
    let o = parse_args(args)?;
    if let Some(path) = &o.scene {
        return run_scene(path, &o);
    }
    let model = match &o.source {
        Some(Source::Obj(path)) => {
            Model::load_obj(path).map_err(|e| Failure::Input(e.to_string()))?
        }
        Some(Source::Shape(name)) => match o.texture {
            // A texture needs the shape's UVs.
            Some(_) => Model::shape_with_uvs(name),
            None => Model::shape(name),
        }
        .ok_or_else(|| {
            Failure::Usage(format!(
                "unknown shape {name:?}: cube, tetrahedron, octahedron, sphere or torus"
            ))
        })?,
        None => return Err(Failure::Usage("no mesh".into())),
    };
    let (w, h) = o.size;
    let viewport = Viewport::new(w, h).map_err(|e| Failure::Usage(e.to_string()))?;
    let fov = Angle::from_degrees_f32(o.fov);
    let objects = [Placed {
        model: &model,
        matrix: Mat4::IDENTITY,
        color: o.color,
        texture: None,
    }];
    let bounds = desktop::scene_bounds(&objects);
    let centre = Vec3::new(
        (bounds.min.x + bounds.max.x) / Scalar::from_num(2),
        (bounds.min.y + bounds.max.y) / Scalar::from_num(2),
        (bounds.min.z + bounds.max.z) / Scalar::from_num(2),
    );
    let radius_f = (bounds.max - bounds.min).length().to_num::<f64>() / 2.0 + 0.01;
    let mut framed_projection = None;
    let look = match o.eye {
        // Default camera: framed from the front, a little above.
        None => {
            // Framing fits the model's sphere in the narrower half-angle: its distance.
            let half = (o.fov as f64).to_radians() / 2.0;
            let narrower = half.tan().min(half.tan() * w as f64 / h as f64).atan();
            let distance = 1.05 * radius_f / narrower.sin();
            // Past the range, or too far for the depth range that the model's size gives.
            let framing = framed(&bounds, Vec3::from_int(0, 1, 3), fov, viewport.aspect());
            let (look, projection) = match framing {
                Ok(f) if distance + radius_f < RANGE => f,
                _ => {
                    return Err(Failure::Usage(format!(
                        "--fov {}: too narrow for the fixed-point range: framing puts the camera \
                         {distance:.0} units from a model of radius {radius_f:.2}, where Q16.16 \
                         cannot hold or resolve its depth range; widen --fov (or give --eye, \
                         --near and --far)",
                        o.fov
                    )))
                }
            };
            framed_projection = Some(projection);
            LookAt { up: o.up, ..look }
        }
        Some(eye) => {
            let f = |v: Vec3| [v.x, v.y, v.z].map(|c| c.to_num::<f64>());
            let (e, c) = (f(eye), f(centre));
            let distance = (0..3).map(|k| (e[k] - c[k]).powi(2)).sum::<f64>().sqrt();
            let far = distance + 1.1 * radius_f;
            if o.far.is_none() && far >= RANGE {
                return Err(Failure::Usage(format!(
                    "--eye: the automatic far plane ({far:.0} units: the eye's distance to the \
                     model plus its radius) lies beyond the fixed-point range ({RANGE:.0}); move \
                     --eye closer, or give --far"
                )));
            }
            LookAt::new(eye, o.target.unwrap_or(centre), o.up)
        }
    };
    let view = look
        .view()
        .map_err(|e| Failure::Usage(format!("camera: {e}")))?;
    // An explicit eye, near or far keeps the framing's depth range around the model.
    let projection = match framed_projection {
        Some(p) if o.near.is_none() && o.far.is_none() => p,
        _ => {
            let radius = Scalar::from_num(radius_f);
            let distance = (look.eye - centre).length();
            let near = o.near.unwrap_or_else(|| {
                (distance - radius * Scalar::from_num(1.1))
                    .max(Projection::MIN_NEAR.max(distance / Scalar::from_num(1000)))
            });
            let far = o.far.unwrap_or_else(|| {
                distance
                    .saturating_add(radius.saturating_mul(Scalar::from_num(1.1)))
                    .max(near.saturating_add(Scalar::ONE))
            });
            let (n, f) = (near.to_num::<f64>(), far.to_num::<f64>());
            Projection::perspective(fov, viewport.aspect(), near, far).map_err(|e| {
                let resolution = n * f / (f - n);
                Failure::Usage(match e {
                    ProjectionError::FarNotBeyondNear if o.near.is_none() && o.far.is_none() => {
                        format!(
                            "--eye: the eye is {:.0} units from a model of radius {radius_f:.2}, \
                             too far for the fixed-point depth range (near·far/(far−near) is \
                             {resolution:.0}, at most {RANGE:.0}); move --eye closer, or give \
                             --near and --far",
                            distance.to_num::<f64>()
                        )
                    }
                    ProjectionError::FarNotBeyondNear if f > n => format!(
                        "projection: --near {n} and --far {f} are too close for the fixed-point \
                         depth range (near·far/(far−near) is {resolution:.0}, at most \
                         {RANGE:.0}); move --far away from --near"
                    ),
                    e => format!("projection: {e}"),
                })
            })?
        }
    };
    // --ortho: the same camera, without perspective, the model's sphere filling the height.
    let projection = if o.ortho {
        let (radius, distance) = (Scalar::from_num(radius_f), (look.eye - centre).length());
        let reach = radius.saturating_mul(Scalar::from_num(1.1));
        let near = o.near.unwrap_or(distance.saturating_sub(reach));
        let far = o.far.unwrap_or(distance.saturating_add(reach));
        let height = radius.saturating_mul(Scalar::from_num(2.2));
        Projection::orthographic(height, viewport.aspect(), near, far)
            .map_err(|e| Failure::Usage(format!("--ortho: {e}")))?
    } else {
        projection
    };
    // The texture: --texture, else the one the OBJ's material names (for a model with UVs;
    // one that cannot be read is then left out, with a warning).
    let texels = match (&o.texture, &o.source) {
        (Some(path), _) => Some((
            path.clone(),
            desktop::load_texels(path).map_err(Failure::Input)?,
        )),
        (None, Some(Source::Obj(obj))) if !model.uvs.is_empty() => desktop::obj_texture_path(obj)
            .and_then(|path| {
                let path = path.to_string_lossy().into_owned();
                match desktop::load_texels(&path) {
                    Ok(t) => Some((path, t)),
                    Err(e) => {
                        eprintln!("warning: the material's texture is left out: {e}");
                        None
                    }
                }
            }),
        _ => None,
    };
    let texture = match &texels {
        Some((path, (texels, tw, th))) => {
            let t = Texture::new(Texels::Rgb888(texels), *tw, *th)
                .map_err(|e| Failure::Input(format!("{path}: {e}")))?;
            Some(
                t.with_filter(o.filter)
                    .with_wrap(o.wrap)
                    .with_mapping(o.mapping),
            )
        }
        None => None,
    };
    let frame_view = View {
        width: w,
        height: h,
        mode: o.mode,
        view,
        projection,
        ambient: o.ambient,
        lights: o.lights.clone(),
        background: o.background,
        cull: o.cull,
        depth: o.depth,
        bands: o.bands,
        specular: o.specular,
    };
    let textured = [Placed {
        texture: texture.as_ref(),
        ..objects[0]
    }];
    let r = render(&textured, &frame_view).map_err(Failure::Input)?;
    write_png(&o.out, w, h, &r.pixels)?;
    let drawn = if o.mode == Mode::Wire {
        r.stats.primitives - r.stats.invalid - r.stats.outside - r.stats.culled - r.stats.degenerate
    } else {
        r.stats.drawn
    };
    Ok(format!(
        "rendered {w}x{h} in {} us: covered {} pixels, drew {} of {} triangles",
        r.time.as_micros(),
        r.covered(o.background),
        drawn,
        r.stats.primitives
    ))
}

/// `--scene FILE`: the file's objects, lights and camera through the `Renderer`.
fn run_scene(path: &str, o: &Options) -> Result<String, Failure> {
    let scene = scene_file::LoadedScene::load(path).map_err(Failure::Input)?;
    let (w, h) = o.size;
    let frame = scene
        .render(w, h, o.background, o.bands)
        .map_err(|e| Failure::Input(format!("{path}: {e}")))?;
    write_png(&o.out, w, h, &frame.pixels)?;
    let covered = frame.pixels.iter().filter(|&&p| p != o.background).count();
    Ok(format!(
        "rendered {w}x{h} in {} us: covered {covered} pixels, drew {} of {} triangles",
        frame.time.as_micros(),
        frame.stats.drawn,
        frame.stats.primitives
    ))
}

/// Writes the PNG, making the default output's folder when it is the one written.
fn write_png(out: &str, w: u32, h: u32, pixels: &[Rgb888]) -> Result<(), Failure> {
    if out == DEFAULT_OUT {
        if let Some(dir) = std::path::Path::new(DEFAULT_OUT).parent() {
            std::fs::create_dir_all(dir).map_err(|e| Failure::Input(format!("{e}")))?;
        }
    }
    save_png(out, w, h, pixels).map_err(Failure::Input)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(line) => println!("{line}"),
        Err(Failure::Usage(msg)) => {
            if !msg.is_empty() {
                eprintln!("error: {msg}");
            }
            eprintln!("{USAGE}");
            std::process::exit(2);
        }
        Err(Failure::Input(msg)) => {
            eprintln!("error: {msg}");
            std::process::exit(1);
        }
    }
}

//! The viewer: fly a camera around lit models in the embedded-graphics simulator window.
//!
//! ```text
//! cargo run --release --features window --example viewer -- [MODEL.obj ...]
//! ```
//!
//! Opens on the given OBJ files (or a bundled teapot among a few shapes, the sphere a textured
//! globe), framed by their bounding box, lit by an ambient colour and three coloured lights
//! (and a point light that L drops where the camera is). An OBJ file with `vt` whose material
//! names a PNG is drawn textured. Keys (also shown by H):
//!
//! | key | does |
//! |---|---|
//! | W / S | forward / back |
//! | A / D | strafe left / right |
//! | Q / E, Ctrl / Space | down / up |
//! | arrow keys | turn (yaw and pitch) |
//! | + / - | field of view |
//! | M (or 1, 2, 3, 4) | wireframe / flat / Gouraud / perspective-correct Gouraud |
//! | Z | depth buffer on / off |
//! | C | back-face culling on / off |
//! | O | orthographic / perspective |
//! | Tab | spinning on / off |
//! | L | put a point light where the camera is (fly, then L again, to move it) |
//! | K | remove the point light |
//! | G | highlights on / off (Gouraud modes) |
//! | R | add an object: path, colour and position asked on the terminal |
//! | Backspace | remove the last object |
//! | P | save the frame as `target/screenshots/viewer-NNN.png`, never over an earlier file |
//! | H | key help on screen |
//! | Escape | quit |
//!
//! Held keys move the camera smoothly by elapsed time (key repeats are ignored); releasing one
//! prints the view (`view: fov …, eye x,y,z`). The render time of each frame is shown on screen
//! and printed to the terminal once per second, except while R waits for an answer. Without a
//! display the viewer exits with status 1.

#[path = "common/desktop.rs"]
mod desktop;

use std::collections::HashSet;
use std::io::BufRead;
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

use desktop::{render, save_png_to, Mode, Model, Placed, View};
use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::sdl2::Keycode;
use embedded_graphics_simulator::{
    OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent, Window,
};
use fixed3d::camera::FlyCamera;
use fixed3d::math::{Angle, Scalar, Vec3};
use fixed3d::mesh::{Specular, Transform};
use fixed3d::projection::Projection;
use fixed3d::scene::{Attenuation, Light, LightColor, PointLight};
use fixed3d::texture::{Texels as TexelFormat, Texture};

const WIDTH: u32 = 640;
const HEIGHT: u32 = 480;
const TITLE: &str = "fixed3d viewer";

const HELP: &[&str] = &[
    "W/S forward/back   A/D strafe   Q/E Ctrl/Space down/up",
    "arrows turn        +/- field of view",
    "M or 1/2/3/4 wire/flat/gouraud/perspective   Z depth   C culling",
    "O ortho/perspective   Tab spin   P save PNG",
    "L point light at the camera   K remove it   G highlights",
    "R add object (terminal)   Backspace remove last",
    "H help   Esc quit",
];

/// The keys that move or turn the camera or change its field of view.
const FLY_KEYS: [Keycode; 18] = [
    Keycode::W,
    Keycode::S,
    Keycode::A,
    Keycode::D,
    Keycode::Q,
    Keycode::E,
    Keycode::Space,
    Keycode::LCtrl,
    Keycode::RCtrl,
    Keycode::Left,
    Keycode::Right,
    Keycode::Up,
    Keycode::Down,
    Keycode::Plus,
    Keycode::Equals,
    Keycode::KpPlus,
    Keycode::Minus,
    Keycode::KpMinus,
];

/// One object of the scene: a model scaled to a radius of one unit around its position.
struct Item {
    model: usize,
    position: Vec3,
    color: Rgb888,
    spin: bool,
}

/// The terminal dialogue of R.
enum Prompt {
    Path,
    Color((Model, Option<Texels>)),
    Position((Model, Option<Texels>), Rgb888),
}

impl Prompt {
    fn question(&self) -> &'static str {
        match self {
            Prompt::Path => {
                "OBJ file (or cube, tetrahedron, octahedron, sphere, torus; 'exit' cancels): "
            }
            Prompt::Color(_) => "colour r,g,b (0-255; 'exit' cancels): ",
            Prompt::Position(..) => "position x,y,z ('exit' cancels): ",
        }
    }
}

/// A texture's texels, width and height.
type Texels = (Vec<Rgb888>, u16, u16);

struct App {
    models: Vec<Model>,
    /// Per model: the texture it is drawn with (an OBJ's `map_Kd`, or the globe's), if any.
    textures: Vec<Option<Texels>>,
    items: Vec<Item>,
    camera: FlyCamera,
    radius: f32,
    fov: f32,
    mode: Mode,
    depth: bool,
    cull: bool,
    ortho: bool,
    spinning: bool,
    spin: Angle,
    help: bool,
    /// Where the point light is, if there is one.
    lamp: Option<Vec3>,
    /// White highlights on every model (Gouraud modes).
    glossy: bool,
    held: HashSet<Keycode>,
    prompt: Option<Prompt>,
    message: String,
}

fn parse_numbers(s: &str) -> Option<[f32; 3]> {
    let v: Vec<f32> = s
        .split(',')
        .map(|p| p.trim().parse::<f32>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()?;
    <[f32; 3]>::try_from(v).ok()
}

impl App {
    fn model_transform(&self, item: &Item) -> fixed3d::math::Mat4 {
        let model = &self.models[item.model];
        let b = model.bounds;
        let half = (b.max - b.min).length().to_num::<f32>() / 2.0;
        let scale = if half > 0.0 { 1.0 / half } else { 1.0 };
        let centre = [
            (b.min.x + b.max.x).to_num::<f32>() / 2.0,
            (b.min.y + b.max.y).to_num::<f32>() / 2.0,
            (b.min.z + b.max.z).to_num::<f32>() / 2.0,
        ];
        let s = Scalar::from_num(scale);
        let spin = if item.spin { self.spin } else { Angle::ZERO };
        let recentre = fixed3d::math::Mat4::translation(
            Vec3::from_f32(-centre[0], -centre[1], -centre[2]).unwrap_or_default(),
        );
        Transform::new()
            .translated(item.position)
            .rotated_y(spin)
            .scaled(Vec3::new(s, s, s))
            .matrix()
            * recentre
    }

    fn view(&self) -> Result<View, String> {
        let aspect = Scalar::from_num(WIDTH as f32 / HEIGHT as f32);
        let r = self.radius;
        let projection = if self.ortho {
            Projection::orthographic(
                Scalar::from_num(r * 2.4),
                aspect,
                Scalar::from_num(-r * 20.0),
                Scalar::from_num(r * 20.0),
            )
        } else {
            Projection::perspective(
                Angle::from_degrees_f32(self.fov),
                aspect,
                Scalar::from_num((r / 200.0).max(0.002)),
                Scalar::from_num((r * 40.0).min(30000.0)),
            )
        }
        .map_err(|e| e.to_string())?;
        let s = |v: f32| Scalar::from_num(v);
        let third = s(0.45);
        Ok(View {
            width: WIDTH,
            height: HEIGHT,
            mode: self.mode,
            view: self.camera.view(),
            projection,
            ambient: Scalar::from_num(0.15),
            lights: [
                Light::directional([-1, 1, 1], LightColor::new(s(0.75), s(0.7), s(0.6))),
                Light::directional([1, 0, 1], LightColor::new(third, s(0.15), s(0.1))),
                Light::directional([0, -1, -1], LightColor::new(s(0.1), s(0.2), third)),
            ]
            .into_iter()
            .chain(self.lamp.map(|at| {
                // Warm, falling off with the square of the distance: at the scene's radius
                // from the lamp, a little over half strength.
                let k = (0.6 * (1.0 + r * r)).min(1000.0);
                let lamp = PointLight::new(at, LightColor::new(s(k), s(0.85 * k), s(0.6 * k)));
                Light::from(lamp.attenuated(Attenuation::InverseSquare))
            }))
            .collect(),
            background: Rgb888::new(12, 12, 20),
            cull: self.cull,
            depth: self.depth,
            bands: 0,
            specular: self
                .glossy
                .then(|| Specular::new(Rgb888::new(255, 255, 255), 32)),
        })
    }

    /// Applies held keys for `dt` seconds.
    fn fly(&mut self, dt: f32) {
        let step = Scalar::from_num(self.radius * 0.9 * dt);
        let turn = Angle::from_degrees_f32(70.0 * dt);
        let held = |k: Keycode| self.held.contains(&k);
        let (fwd, side, up) = (
            held(Keycode::W) as i32 - held(Keycode::S) as i32,
            held(Keycode::D) as i32 - held(Keycode::A) as i32,
            // Not Shift: on many layouts + is Shift and =, which would then move the camera.
            (held(Keycode::E) || held(Keycode::Space)) as i32
                - (held(Keycode::Q) || held(Keycode::LCtrl) || held(Keycode::RCtrl)) as i32,
        );
        let (yaw, pitch) = (
            held(Keycode::Left) as i32 - held(Keycode::Right) as i32,
            held(Keycode::Up) as i32 - held(Keycode::Down) as i32,
        );
        let times = |n: i32| Scalar::from_num(n) * step;
        self.camera.move_forward(times(fwd));
        self.camera.strafe_right(times(side));
        self.camera.move_up(times(up));
        let a = |n: i32| match n {
            1 => turn,
            -1 => -turn,
            _ => Angle::ZERO,
        };
        self.camera.turn(a(yaw), a(pitch));
        if held(Keycode::Plus) || held(Keycode::Equals) || held(Keycode::KpPlus) {
            self.fov = (self.fov + 40.0 * dt).min(150.0);
        }
        if held(Keycode::Minus) || held(Keycode::KpMinus) {
            self.fov = (self.fov - 40.0 * dt).max(10.0);
        }
    }

    fn key(&mut self, key: Keycode, frame: &[Rgb888]) {
        match key {
            Keycode::M => self.mode = self.mode.next(),
            Keycode::Num1 => self.mode = Mode::Wire,
            Keycode::Num2 => self.mode = Mode::Flat,
            Keycode::Num3 => self.mode = Mode::Gouraud,
            Keycode::Num4 => self.mode = Mode::Perspective,
            Keycode::Z => self.depth = !self.depth,
            Keycode::C => self.cull = !self.cull,
            Keycode::O => self.ortho = !self.ortho,
            Keycode::Tab => self.spinning = !self.spinning,
            Keycode::H => self.help = !self.help,
            Keycode::L => {
                let at = self.camera.position;
                self.lamp = Some(at);
                self.message = format!(
                    "point light at {:.2},{:.2},{:.2}",
                    at.x.to_num::<f32>(),
                    at.y.to_num::<f32>(),
                    at.z.to_num::<f32>()
                );
                println!("{}", self.message);
            }
            Keycode::G => {
                self.glossy = !self.glossy;
                self.message = format!("highlights {}", if self.glossy { "on" } else { "off" });
                println!("{}", self.message);
            }
            Keycode::K => {
                self.message = match self.lamp.take() {
                    Some(_) => "point light removed".into(),
                    None => "no point light to remove".into(),
                };
                println!("{}", self.message);
            }
            Keycode::Backspace => {
                self.message = match self.items.pop() {
                    Some(_) => format!("removed the last object, {} left", self.items.len()),
                    None => "no object to remove".into(),
                };
                println!("{}", self.message);
            }
            Keycode::P => {
                self.message = match save_screenshot(frame) {
                    Ok(path) => format!("saved {path}"),
                    Err(e) => format!("could not save: {e}"),
                };
                println!("{}", self.message);
            }
            Keycode::R if self.prompt.is_none() => {
                let p = Prompt::Path;
                print_prompt(&p);
                self.message = "answer in the terminal".into();
                self.prompt = Some(p);
            }
            _ => {}
        }
    }

    /// One line typed on the terminal while a prompt is open.
    fn answer(&mut self, line: &str) {
        let Some(prompt) = self.prompt.take() else {
            return;
        };
        let line = line.trim();
        if line == "exit" {
            println!("cancelled");
            self.message = "adding cancelled".into();
            return;
        }
        let next = match prompt {
            Prompt::Path => match Model::shape(line)
                .map(|m| Ok((m, None)))
                .unwrap_or_else(|| load_textured(line))
            {
                Ok(model) => Prompt::Color(model),
                Err(e) => {
                    println!("error: {e}");
                    Prompt::Path
                }
            },
            Prompt::Color(model) => match parse_numbers(line)
                .filter(|c| c.iter().all(|v| (0.0..=255.0).contains(v)))
            {
                Some([r, g, b]) => Prompt::Position(model, Rgb888::new(r as u8, g as u8, b as u8)),
                None => {
                    println!(
                        "error: give three numbers 0-255 separated by commas, like 255,160,64"
                    );
                    Prompt::Color(model)
                }
            },
            Prompt::Position(model, color) => {
                match parse_numbers(line).and_then(|[x, y, z]| Vec3::from_f32(x, y, z)) {
                    Some(position) => {
                        self.models.push(model.0);
                        self.textures.push(model.1);
                        self.items.push(Item {
                            model: self.models.len() - 1,
                            position,
                            color,
                            spin: false,
                        });
                        self.message = format!("added object {}", self.items.len());
                        println!("{}", self.message);
                        return;
                    }
                    None => {
                        println!("error: give three numbers separated by commas, like 0,1.5,-2");
                        Prompt::Position(model, color)
                    }
                }
            }
        };
        print_prompt(&next);
        self.prompt = Some(next);
    }
}

/// Where P saves unless `VIEWER_SCREENSHOTS` names a folder: under the checkout's `target/`,
/// never beside the sources.
const SCREENSHOTS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/target/screenshots");

/// Saves `frame` as the first `viewer-NNN.png` of the screenshot folder that does not exist
/// yet (created anew, so that no file is ever overwritten, from this run or an earlier one).
fn save_screenshot(frame: &[Rgb888]) -> Result<String, String> {
    let dir = std::env::var("VIEWER_SCREENSHOTS").unwrap_or_else(|_| SCREENSHOTS.into());
    std::fs::create_dir_all(&dir).map_err(|e| format!("{dir}: {e}"))?;
    for n in 1..=9999 {
        let path = format!("{dir}/viewer-{n:03}.png");
        match std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
        {
            Ok(file) => return save_png_to(file, &path, WIDTH, HEIGHT, frame).map(|()| path),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(format!("{path}: {e}")),
        }
    }
    Err(format!("{dir} holds 9999 screenshots already"))
}

fn print_prompt(p: &Prompt) {
    use std::io::Write;
    print!("{}", p.question());
    let _ = std::io::stdout().flush();
}

/// Lines from standard input, read on their own thread so the window keeps running.
fn terminal_lines() -> Receiver<String> {
    let (tx, rx) = channel();
    std::thread::spawn(move || {
        for line in std::io::stdin().lock().lines() {
            let Ok(line) = line else { break };
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    rx
}

/// A window showing `display`, or why none opens. SDL falls back to drawing nowhere when no
/// display server answers; on Linux it is held to X11 and Wayland (unless `SDL_VIDEODRIVER`
/// says otherwise), so that it fails instead, and the simulator's panic becomes the reason.
fn open_window(display: &SimulatorDisplay<Rgb888>) -> Result<Window, String> {
    if cfg!(target_os = "linux") && std::env::var_os("SDL_VIDEODRIVER").is_none() {
        let wayland = std::env::var_os("WAYLAND_DISPLAY").is_some();
        std::env::set_var(
            "SDL_VIDEODRIVER",
            if wayland { "wayland,x11" } else { "x11" },
        );
    }
    let mut window = Window::new(TITLE, &OutputSettingsBuilder::new().build());
    window.set_max_fps(60);
    let quiet = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let opened = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        window.update(display);
    }));
    std::panic::set_hook(quiet);
    match opened {
        Ok(()) => Ok(window),
        Err(panic) => {
            let why = panic
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| panic.downcast_ref::<&str>().copied())
                .unwrap_or("SDL could not open one");
            // The simulator unwraps SDL's error: keep SDL's own words.
            let why = why
                .rsplit("value: ")
                .next()
                .unwrap_or(why)
                .trim_matches('"');
            Err(format!(
                "{why} (the viewer needs an X11 or Wayland display; the render tool draws \
                 without one)"
            ))
        }
    }
}

/// An OBJ file and the texture its material names (`mtllib`, `map_Kd`), for a model with UVs;
/// one that cannot be read is left out with a warning.
fn load_textured(path: &str) -> Result<(Model, Option<Texels>), desktop::LoadError> {
    let model = Model::load_obj(path)?;
    let texture = desktop::obj_texture_path(path).filter(|_| !model.uvs.is_empty());
    let texels = texture.and_then(|t| match desktop::load_texels(&t.to_string_lossy()) {
        Ok(texels) => Some(texels),
        Err(e) => {
            println!("warning: the material's texture is left out: {e}");
            None
        }
    });
    Ok((model, texels))
}

/// The globe's texture: an equirectangular map of meridians and parallels over bands of
/// colour from pole to pole.
fn globe_texels() -> Texels {
    let (w, h) = (128u16, 64u16);
    let texels = (0..u32::from(w) * u32::from(h))
        .map(|i| {
            let (x, y) = (i % u32::from(w), i / u32::from(w));
            if x % 16 == 0 || y % 16 == 0 {
                Rgb888::new(250, 250, 240)
            } else {
                let t = y * 255 / u32::from(h);
                Rgb888::new((40 + t / 3) as u8, (90 + t / 2) as u8, (230 - t / 2) as u8)
            }
        })
        .collect();
    (texels, w, h)
}

#[allow(clippy::type_complexity)]
fn initial_scene(args: &[String]) -> Result<(Vec<Model>, Vec<Option<Texels>>, Vec<Item>), String> {
    let (mut models, mut textures) = (Vec::new(), Vec::new());
    let mut items = Vec::new();
    if args.is_empty() {
        let teapot = Model::from_obj_bytes("teapot", include_bytes!("../models/teapot.obj"))
            .map_err(|e| e.to_string())?;
        models.push(teapot);
        textures.push(None);
        items.push(Item {
            model: 0,
            position: Vec3::ZERO,
            color: Rgb888::new(230, 200, 150),
            spin: false,
        });
        for (name, pos, color) in [
            (
                "torus",
                Vec3::from_f32(-2.4, 0.0, -0.6),
                Rgb888::new(255, 160, 64),
            ),
            (
                "sphere",
                Vec3::from_f32(2.3, 0.1, -0.4),
                Rgb888::new(120, 200, 255),
            ),
            (
                "cube",
                Vec3::from_f32(0.2, 0.0, -2.8),
                Rgb888::new(160, 255, 140),
            ),
            (
                "octahedron",
                Vec3::from_f32(-0.6, 0.3, 2.4),
                Rgb888::new(255, 120, 200),
            ),
        ] {
            // The sphere is a textured globe.
            let (m, texture) = if name == "sphere" {
                (Model::shape_with_uvs(name), Some(globe_texels()))
            } else {
                (Model::shape(name), None)
            };
            let Some(m) = m else {
                continue;
            };
            models.push(m);
            textures.push(texture);
            items.push(Item {
                model: models.len() - 1,
                position: pos.unwrap_or_default(),
                color,
                spin: true,
            });
        }
    } else {
        for (k, path) in args.iter().enumerate() {
            let (m, texture) = load_textured(path).map_err(|e| e.to_string())?;
            if let Some(p) = &m.rescaled {
                println!("{path}: outside the fixed-point range, rescaled (one step = {:.3e} file units)", p.resolution());
            }
            models.push(m);
            textures.push(texture);
            let x = (k as f32 - (args.len() as f32 - 1.0) / 2.0) * 2.5;
            items.push(Item {
                model: k,
                position: Vec3::from_f32(x, 0.0, 0.0).unwrap_or_default(),
                color: Rgb888::new(230, 200, 150),
                spin: false,
            });
        }
    }
    Ok((models, textures, items))
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (models, textures, items) = match initial_scene(&args) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    // Every item has a radius of one unit; the scene spans their positions.
    let extent = items
        .iter()
        .map(|i| i.position.length().to_num::<f32>() + 1.0)
        .fold(1.0f32, f32::max);
    let fov = 60.0f32;
    let distance = extent / (fov.to_radians() / 2.0).sin() * 0.7;
    let eye = [0.0, distance * 0.35, distance];
    let mut camera = FlyCamera::new(Vec3::from_f32(eye[0], eye[1], eye[2]).unwrap_or_default());
    // Look at the origin: yaw 0 faces -z; pitch down towards it.
    camera.set_orientation(
        Angle::ZERO,
        -Angle::from_radians_f32((eye[1] / (eye[1].hypot(eye[2]))).asin()),
    );
    let mut app = App {
        models,
        textures,
        items,
        camera,
        radius: extent,
        fov,
        mode: Mode::Gouraud,
        depth: true,
        cull: true,
        ortho: false,
        spinning: true,
        spin: Angle::ZERO,
        help: false,
        lamp: None,
        glossy: false,
        held: HashSet::new(),
        prompt: None,
        message: "H for help".into(),
    };
    let lines = terminal_lines();
    let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(WIDTH, HEIGHT));
    let mut window = open_window(&display).unwrap_or_else(|e| {
        eprintln!("error: no window: {e}");
        std::process::exit(1);
    });
    let text = MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE);
    let mut last = Instant::now();
    let (mut second, mut frames, mut render_us) = (Instant::now(), 0u32, 0u128);
    let mut frame = vec![Rgb888::BLACK; (WIDTH * HEIGHT) as usize];
    loop {
        let now = Instant::now();
        let dt = now
            .duration_since(last)
            .min(Duration::from_millis(100))
            .as_secs_f32();
        last = now;
        app.fly(dt);
        if app.spinning {
            app.spin += Angle::from_degrees_f32(45.0 * dt);
        }
        let textures: Vec<Option<Texture<'_>>> = app
            .textures
            .iter()
            .map(|t| {
                let (texels, w, h) = t.as_ref()?;
                Texture::new(TexelFormat::Rgb888(texels), *w, *h).ok()
            })
            .collect();
        let placed: Vec<Placed<'_>> = app
            .items
            .iter()
            .map(|i| Placed {
                model: &app.models[i.model],
                matrix: app.model_transform(i),
                color: i.color,
                texture: textures.get(i.model).and_then(Option::as_ref),
            })
            .collect();
        let time = match app.view().and_then(|v| render(&placed, &v)) {
            Ok(r) => {
                frame = r.pixels;
                r.time
            }
            Err(e) => {
                app.message = e;
                Duration::ZERO
            }
        };
        let _ = display.fill_contiguous(
            &Rectangle::new(Point::zero(), Size::new(WIDTH, HEIGHT)),
            frame.iter().copied(),
        );
        frames += 1;
        render_us += time.as_micros();
        let fps = frames as f32 / second.elapsed().as_secs_f32().max(1e-3);
        let status = format!(
            "{} | render {} us | {:.0} fps | {} objects | depth {} | cull {} | {} | fov {:.0} | {}",
            app.mode.name(),
            time.as_micros(),
            fps,
            app.items.len(),
            if app.depth { "on" } else { "off" },
            if app.cull { "on" } else { "off" },
            if app.ortho { "ortho" } else { "persp" },
            app.fov,
            app.message
        );
        let _ =
            Text::with_baseline(&status, Point::new(4, 2), text, Baseline::Top).draw(&mut display);
        if app.help {
            let h = HELP.len() as u32 * 12 + 8;
            let _ = Rectangle::new(Point::new(8, 20), Size::new(420, h))
                .into_styled(PrimitiveStyle::with_fill(Rgb888::new(0, 0, 60)))
                .draw(&mut display);
            for (k, line) in HELP.iter().enumerate() {
                let _ = Text::with_baseline(
                    line,
                    Point::new(14, 24 + 12 * k as i32),
                    text,
                    Baseline::Top,
                )
                .draw(&mut display);
            }
        }
        // Paused while a question waits on the terminal, so that answers are not interleaved.
        if second.elapsed() >= Duration::from_secs(1) && app.prompt.is_none() {
            println!(
                "frame: render {} us on average, {:.0} fps",
                render_us / frames.max(1) as u128,
                fps
            );
            (second, frames, render_us) = (Instant::now(), 0, 0);
        }
        window.update(&display);
        for event in window.events() {
            match event {
                SimulatorEvent::Quit => return,
                SimulatorEvent::KeyDown {
                    keycode,
                    repeat: false,
                    ..
                } => {
                    app.held.insert(keycode);
                    app.key(keycode, &frame);
                }
                SimulatorEvent::KeyUp { keycode, .. } => {
                    app.held.remove(&keycode);
                    // What the keys that fly the camera left it at (for --eye and --fov of the
                    // render tool), unless a question waits on the terminal.
                    if FLY_KEYS.contains(&keycode) && app.prompt.is_none() {
                        let p = app.camera.position;
                        println!(
                            "view: fov {:.1}, eye {:.3},{:.3},{:.3}",
                            app.fov,
                            p.x.to_num::<f32>(),
                            p.y.to_num::<f32>(),
                            p.z.to_num::<f32>()
                        );
                    }
                }
                _ => {}
            }
        }
        while let Ok(line) = lines.try_recv() {
            app.answer(&line);
        }
    }
}

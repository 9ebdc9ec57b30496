//! The scenes of the firmware presets, shared by the firmware (no_std) and the host test that
//! checks its hashes (`tests/firmware.rs` includes this file): one definition, so host and
//! target render the same frames.

use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::{BinaryColor, IntoStorage, Rgb565, Rgb888, RgbColor};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Pixel;
use fixed3d::buffer::{
    Carried, ColorDepth, DepthBuffer, DepthFormat, Direct, FrameBuffer, LessOrEqual,
};
use fixed3d::camera::{Camera, LookAt};
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::{textured_torus, torus, Mesh, Object, Specular, Transform, Triangle, Uv, CUBE};
use fixed3d::pipeline::{Bin, Cull, Frame, Prepared, ScreenVertex, Stats};
use fixed3d::projection::{Projection, Viewport};
use fixed3d::render::{Model, Renderer};
use fixed3d::scene::{
    Attenuation, DirectionalLight, Light, LightColor, Lighting, PointLight, Scene,
};
use fixed3d::shade::{Flat, Gouraud, PerspectiveGouraud, Textured, Unlit};
use fixed3d::texture::{Mapping, Texels, Texture};

/// Frames per preset (the hash chains over them).
pub const FRAMES: u32 = 4;

/// The hash chain the firmware prints: `chain = chain.rotl(5) ^ hash(frame)` over `FRAMES`.
pub fn chain(mut frame_hash: impl FnMut(u32) -> u32) -> u32 {
    let mut c = 0u32;
    for f in 0..FRAMES {
        c = c.rotate_left(5) ^ frame_hash(f);
    }
    c
}

/// Frame size of every preset (the micro:bit runs `wire` at its own size).
pub const W: u32 = 320;
pub const H: u32 = 240;
/// Rows per band in the `bands` preset: 320 · 12 · (2 + 2) bytes = 15 KiB of buffers.
pub const BAND_ROWS: u32 = 12;
/// Torus resolution and sizes.
pub const TORUS_VERTICES: usize = 48 * 24;
pub const TORUS_TRIANGLES: usize = 2 * TORUS_VERTICES;
/// A small OBJ model in flash for the `obj` preset: an octahedron with a quad-split belly.
pub const OBJ_MODEL: &[u8] = b"# a small model parsed at start-up\no gem\nv 0 1.2 0\nv 1 0 0\nv 0 0 1\nv -1 0 0\nv 0 0 -1\nv 0 -1 0\n\
f 1 3 2\nf 1 4 3\nf 1 5 4\nf 1 2 5\nf 6 2 3\nf 6 3 4\nf 6 4 5\nf 6 5 2\n";

/// FNV-1a over 16-bit values: the hash the firmware prints and the host checks.
#[derive(Clone, Copy, Debug)]
pub struct Fnv(pub u32);

impl Fnv {
    pub const fn new() -> Self {
        Fnv(0x811c_9dc5)
    }
    #[inline]
    pub fn write(&mut self, v: u32) {
        for b in v.to_le_bytes() {
            self.0 = (self.0 ^ b as u32).wrapping_mul(0x0100_0193);
        }
    }
    /// Hashes `bytes` four at a time (little-endian words; a tail of fewer is left out).
    pub fn bytes(&mut self, bytes: &[u8]) {
        for w in bytes.chunks_exact(4) {
            self.write(u32::from_le_bytes([w[0], w[1], w[2], w[3]]));
        }
    }
    pub fn pixels(&mut self, px: &[Rgb565]) {
        for p in px {
            self.write(p.into_storage() as u32);
        }
    }
}

/// The hash of a colour frame.
pub fn frame_hash(px: &[Rgb565]) -> u32 {
    let mut h = Fnv::new();
    h.pixels(px);
    h.0
}

impl Default for Fnv {
    fn default() -> Self {
        Fnv::new()
    }
}

/// A display stand-in that keeps nothing but a hash of every pixel drawn, in order: what a
/// wireframe firmware draws straight into its display driver.
#[derive(Debug)]
pub struct HashDisplay {
    pub hash: Fnv,
    pub size: Size,
}

impl OriginDimensions for HashDisplay {
    fn size(&self) -> Size {
        self.size
    }
}

impl DrawTarget for HashDisplay {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            self.hash.write(p.x as u32);
            self.hash.write(p.y as u32);
            self.hash.write(c.into_storage() as u32);
        }
        Ok(())
    }
}

fn s(v: i32, den: i32) -> Scalar {
    Scalar::from_bits(((v as i64) << 16) as i32 / den)
}

/// The reference torus (R = 1, r = 0.4, 48 x 24) into the given storage.
pub fn torus_mesh<'a>(p: &'a mut [Vec3], n: &'a mut [Vec3], t: &'a mut [Triangle]) -> Mesh<'a> {
    torus(Scalar::ONE, s(2, 5), 48, 24, p, n, t).unwrap_or(Mesh::EMPTY)
}

/// The `wire` preset on the micro:bit (16 KiB of RAM): a 16 x 8 torus on a 64x48 display.
pub const SMALL_RING: u16 = 16;
pub const SMALL_TUBE: u16 = 8;
pub const SMALL_VERTICES: usize = 16 * 8;
pub const SMALL_TRIANGLES: usize = 2 * SMALL_VERTICES;
pub const SMALL_W: u32 = 64;
pub const SMALL_H: u32 = 48;

/// The micro:bit's smaller torus into the given storage.
pub fn small_torus_mesh<'a>(
    p: &'a mut [Vec3],
    n: &'a mut [Vec3],
    t: &'a mut [Triangle],
) -> Mesh<'a> {
    torus(Scalar::ONE, s(2, 5), SMALL_RING, SMALL_TUBE, p, n, t).unwrap_or(Mesh::EMPTY)
}

/// The benchmark camera: look-at from (0, 0, 2.6), 60 degrees, near 1, far 10.
pub fn frame(w: u32, h: u32) -> Option<Frame> {
    camera(w, h, Vec3::new(Scalar::ZERO, Scalar::ZERO, s(13, 5)))
}

fn camera(w: u32, h: u32, eye: Vec3) -> Option<Frame> {
    camera_to(w, h, eye, s(10, 1))
}

/// [`camera`] with its far plane at `far`.
fn camera_to(w: u32, h: u32, eye: Vec3, far: Scalar) -> Option<Frame> {
    let viewport = Viewport::new(w, h).ok()?;
    let view = LookAt::new(eye, Vec3::ZERO, Vec3::Y).view().ok()?;
    let projection =
        Projection::perspective(Angle::from_degrees(60), viewport.aspect(), Scalar::ONE, far)
            .ok()?;
    Some(Frame::new(&view, &projection, viewport))
}

/// Frame `f` turns the torus one more degree about y: (30 + f) degrees, after 20 about x.
pub fn torus_model(f: u32) -> Mat4 {
    Mat4::rotation_y(Angle::from_degrees(30).wrapping_add(Angle::from_degrees(f as i32)))
        * Mat4::rotation_x(Angle::from_degrees(20))
}

pub const ORANGE: Rgb888 = Rgb888::new(255, 160, 64);

/// Ambient 0.2 and one white light towards (−1, 1, 1) at 0.8.
pub fn sun() -> Lighting<1> {
    let mut l = Lighting::new(LightColor::gray(s(1, 5)));
    let _ = l.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(s(4, 5)),
    ));
    l
}

/// Ambient and three coloured lights.
pub fn three_lights() -> Lighting<3> {
    let mut l = Lighting::new(LightColor::gray(s(3, 20)));
    let _ = l.push(DirectionalLight::new(
        Vec3::from_int(-1, 0, 1),
        LightColor::new(s(9, 10), s(1, 5), s(1, 5)),
    ));
    let _ = l.push(DirectionalLight::new(
        Vec3::from_int(0, 1, 1),
        LightColor::new(s(1, 5), s(9, 10), s(3, 10)),
    ));
    let _ = l.push(DirectionalLight::new(
        Vec3::from_int(1, -1, 1),
        LightColor::new(s(1, 5), s(3, 10), s(9, 10)),
    ));
    l
}

/// Prepares `scene` through `frame` and lets `draw` fill it into a 320x240 framebuffer with a
/// depth buffer, through the target it makes of them.
fn with_depth_target<const N: usize, S: fixed3d::shade::Shading, D: DepthFormat>(
    frame: Frame,
    scene: &Scene<'_, N>,
    shading: S,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [D],
    draw: impl FnOnce(&Prepared<'_, '_, N, S>, ColorDepth<'_, '_, Rgb565, D>) -> Option<Stats>,
) -> Option<Stats> {
    let p = frame.prepare(scene, cache, shading).ok()?;
    let (mut c, mut d) = (
        FrameBuffer::new(color, W, H).ok()?,
        DepthBuffer::new(depth, W, H).ok()?,
    );
    draw(&p, ColorDepth::new(&mut c, &mut d).ok()?)
}

/// Draws `scene` through `frame` into a 320x240 framebuffer with a depth buffer, counting no
/// fragments (nothing reads the counts).
pub fn depth_frame<const N: usize, S: fixed3d::shade::Shading, D: DepthFormat>(
    frame: Frame,
    scene: &Scene<'_, N>,
    shading: S,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [D],
) -> Option<()> {
    with_depth_target(frame, scene, shading, cache, color, depth, |p, target| {
        p.draw(&mut target.uncounted()).ok()
    })
    .map(|_| ())
}

/// `full`: the torus, flat Lambert, u16 depth, into a 320x240 framebuffer, each face lit from
/// the normal the mesh keeps, or from its positions where it keeps none (the `full` firmware
/// built with its feature `per-frame-normals`).
pub fn full(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    let objects = [Object::new(mesh, torus_model(f), ORANGE)];
    let scene = Scene::new(&objects, sun());
    depth_frame(frame(W, H)?, &scene, Flat, cache, color, depth)
}

/// The `variants` preset's configurations: the depth tests and counts of `ColorDepth`, then
/// `clipped`, the strict counted target with the eye so close that the tori cross the near
/// plane and every side of the screen (spans clamped to the target's columns, polygons cut by
/// the near plane), then [`random_mesh`] drawn whole (`triangles`) and, shrunk inside every
/// clip plane, culled to its front faces (`front`), `full`'s vertex stage alone (`vertices`,
/// see [`torus_vertices`]), and last the receding [`floor`] textured and smooth, perspective-
/// correct (`floor-textured`, `floor-gouraud`: the spans' exact divisions), and `full`'s torus
/// solid with a second one through it as a depth-tested wireframe (`wire-depth`, drawn by
/// `wire_depth.rs` rather than [`variant`]: outside this library, its code moves no other
/// preset's).
pub const VARIANTS: [&str; 11] = [
    "less",
    "less-counted",
    "less-or-equal",
    "less-or-equal-counted",
    "clipped",
    "triangles",
    "front",
    "vertices",
    "floor-textured",
    "floor-gouraud",
    "wire-depth",
];

/// Triangles of the `triangles` variant's mesh ([`random_mesh`]), three vertices each.
pub const RANDOM_TRIANGLES: usize = 600;

/// The `triangles` variant's mesh: `RANDOM_TRIANGLES` triangles from a fixed xorshift seed,
/// of four kinds in turn: large ones with corners on a coarse grid (many share a row, or lie
/// behind the near plane, or beyond the screen's sides), small ones (the usual triangle of a
/// mesh), slivers (two corners a grid step apart), and triangles with a flat top or bottom
/// (two corners at one height and depth, so at one screen row). Every triangle's set-up case
/// comes up: corners tied in y in every order, the middle corner on the first row, on the
/// last or strictly between, both windings.
pub fn random_mesh<'a>(p: &'a mut [Vec3], t: &'a mut [Triangle]) -> Mesh<'a> {
    let mut x = 0x2545_F491u32;
    let mut next = move || {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        x
    };
    // A random multiple of `step` (Q16.16 bits) within ±`steps` steps.
    let mut on_grid = |steps: u32, step: i32| {
        let k = (next() % (2 * steps + 1)) as i32 - steps as i32;
        Scalar::from_bits(k * step)
    };
    let quarter = 1 << 14;
    for (k, (tri, corners)) in t.iter_mut().zip(p.chunks_exact_mut(3)).enumerate() {
        let big = |g: &mut dyn FnMut(u32, i32) -> Scalar| {
            Vec3::new(g(12, quarter), g(12, quarter), g(8, quarter))
        };
        match k % 4 {
            0 => {
                for c in corners.iter_mut() {
                    *c = big(&mut on_grid);
                }
            }
            1 | 2 => {
                let centre = big(&mut on_grid);
                // Small: offsets to 0.15 on a grid of 1/64; slivers: the first two corners
                // one grid step apart, the third further.
                let spread = if k % 4 == 1 { 10 } else { 40 };
                for c in corners.iter_mut() {
                    let d = Vec3::new(
                        on_grid(spread, 1 << 10),
                        on_grid(spread, 1 << 10),
                        on_grid(spread, 1 << 10),
                    );
                    *c = centre + d;
                }
                if k % 4 == 2 {
                    let d = Vec3::new(on_grid(1, 1 << 10), on_grid(1, 1 << 10), Scalar::ZERO);
                    corners[1] = corners[0] + d;
                }
            }
            _ => {
                let (a, c) = (big(&mut on_grid), big(&mut on_grid));
                let b = Vec3::new(on_grid(12, quarter), a.y, a.z);
                corners.copy_from_slice(&[a, b, c]);
            }
        }
        let v = (3 * k) as u16;
        *tri = [v, v + 1, v + 2];
    }
    Mesh::new(p, t).unwrap_or(Mesh::EMPTY)
}

/// The `clipped` variant's frame: the eye at (0, 1.2, 1.2), looking down at the ring from
/// 1.7 instead of 2.6, nearer than the torus's outer edge plus the near plane's distance.
pub fn clipped_frame(w: u32, h: u32) -> Option<Frame> {
    camera(w, h, Vec3::new(Scalar::ZERO, s(12, 10), s(12, 10)))
}

/// The receding floor of the accuracy report (docs/accuracy.md): a quad 4 wide at y = −1 from
/// z = 1.5 to z = −30 (1.1 to 32.6 away from `full`'s eye), its vertex normals leaning apart
/// (lit bright near and dark far), its texture repeated twice across and sixteen times away.
static FLOOR_POSITIONS: [Vec3; 4] = [
    Vec3::new(
        Scalar::from_bits(-2 << 16),
        Scalar::from_bits(-1 << 16),
        Scalar::from_bits(3 << 15),
    ),
    Vec3::new(
        Scalar::from_bits(2 << 16),
        Scalar::from_bits(-1 << 16),
        Scalar::from_bits(3 << 15),
    ),
    Vec3::new(
        Scalar::from_bits(2 << 16),
        Scalar::from_bits(-1 << 16),
        Scalar::from_bits(-30 << 16),
    ),
    Vec3::new(
        Scalar::from_bits(-2 << 16),
        Scalar::from_bits(-1 << 16),
        Scalar::from_bits(-30 << 16),
    ),
];
static FLOOR_NORMALS: [Vec3; 4] = [
    Vec3::from_int(-1, 1, 1),
    Vec3::from_int(-1, 1, 1),
    Vec3::from_int(1, 1, -1),
    Vec3::from_int(1, 1, -1),
];
static FLOOR_UVS: [Uv; 4] = [
    [Scalar::ZERO, Scalar::ZERO],
    [Scalar::from_bits(2 << 16), Scalar::ZERO],
    [Scalar::from_bits(2 << 16), Scalar::from_bits(16 << 16)],
    [Scalar::ZERO, Scalar::from_bits(16 << 16)],
];
static FLOOR_TRIANGLES: [Triangle; 2] = [[0, 1, 2], [0, 2, 3]];

/// The floor's mesh (see [`FLOOR_POSITIONS`]).
pub fn floor_mesh() -> Option<Mesh<'static>> {
    Mesh::new(&FLOOR_POSITIONS, &FLOOR_TRIANGLES)
        .and_then(|m| m.with_normals(&FLOOR_NORMALS))
        .and_then(|m| m.with_uvs(&FLOOR_UVS))
        .ok()
}

/// The floor in frame `f`, turned 70 + f degrees about y so that depth changes steeply along
/// each row, seen from `full`'s eye with the far plane at 40, u16 depth, in one of four ways:
/// `textured` ([`TEXELS`], perspective-correct, flat Lambert), `textured-affine` (the same
/// mapped affinely), `gouraud` (perspective-correct Gouraud, white) or `gouraud-affine`
/// (Gouraud interpolated affinely). The perspective ones are variants of their own; the
/// affine ones are there for the host test to tell them apart.
pub fn floor(
    kind: &str,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    let mesh = floor_mesh()?;
    let turn = Angle::from_degrees(70 + f as i32);
    let model = Transform::new().rotated_y(turn).matrix();
    let objects = [Object::new(&mesh, model, Rgb888::WHITE)];
    let scene = Scene::new(&objects, sun());
    let frame = camera_to(
        W,
        H,
        Vec3::new(Scalar::ZERO, Scalar::ZERO, s(13, 5)),
        s(40, 1),
    )?;
    let texture = Texture::new(Texels::Rgb565(&TEXELS), 64, 64).ok()?;
    let affine = texture.with_mapping(Mapping::Affine);
    let textured = |texture| Textured {
        texture,
        light: Flat,
    };
    match kind {
        "textured" => depth_frame(frame, &scene, textured(&texture), cache, color, depth),
        "textured-affine" => depth_frame(frame, &scene, textured(&affine), cache, color, depth),
        "gouraud" => depth_frame(frame, &scene, PerspectiveGouraud, cache, color, depth),
        "gouraud-affine" => depth_frame(frame, &scene, Gouraud, cache, color, depth),
        _ => None,
    }
}

/// `full`'s torus drawn twice in frame `f`, orange then blue at the very same depths (a tie at
/// every pixel: strictly nearer keeps the orange, nearer-or-equal shows the blue), through
/// variant `name` of the target (see [`VARIANTS`]). Returns the word to fold into the frame's
/// hash: the fragments and writes a counting target counted (0 otherwise).
pub fn variant(
    name: &str,
    mesh: &Mesh<'_>,
    random: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<u32> {
    if name == "triangles" {
        return random_triangles(random, f, cache, color, depth);
    }
    if name == "front" {
        return random_front_faces(random, f, cache, color, depth);
    }
    if name == "vertices" {
        return torus_vertices(mesh, f, cache);
    }
    if let Some(kind) = name.strip_prefix("floor-") {
        return floor(kind, f, cache, color, depth).map(|()| 0);
    }
    let objects = [
        Object::new(mesh, torus_model(f), ORANGE),
        Object::new(mesh, torus_model(f), Rgb888::new(40, 90, 255)),
    ];
    let scene = Scene::new(&objects, sun());
    let frame = if name == "clipped" {
        clipped_frame(W, H)?
    } else {
        frame(W, H)?
    };
    let stats = with_depth_target(
        frame,
        &scene,
        Flat,
        cache,
        color,
        depth,
        |p, target| match name {
            "less" => p.draw(&mut target.uncounted()).ok(),
            "less-counted" => {
                let mut target = target;
                p.draw(&mut target).ok()
            }
            "less-or-equal" => p.draw(&mut target.with_test(LessOrEqual).uncounted()).ok(),
            "less-or-equal-counted" => p.draw(&mut target.with_test(LessOrEqual)).ok(),
            _ => {
                let mut target = target;
                p.draw(&mut target).ok()
            }
        },
    )?;
    Some(stats.fragments.rotate_left(16) ^ stats.written)
}

/// The `vertices` variant: `full`'s torus in frame `f` through the vertex stage alone, the
/// word a hash of every vertex it left in the cache (its screen position and its depth):
/// the vertex loop's exact output, of which the
/// frame's colours show only part (a vertex's depth one unit off changes no colour).
fn torus_vertices(mesh: &Mesh<'_>, f: u32, cache: &mut [ScreenVertex]) -> Option<u32> {
    let objects = [Object::new(mesh, torus_model(f), ORANGE)];
    let scene = Scene::new(&objects, sun());
    frame(W, H)?.prepare(&scene, cache, Flat).ok()?;
    let mut h = Fnv::new();
    for v in cache.iter().take(mesh.positions().len()) {
        let p = v.point();
        h.write(p.x as u32);
        h.write(p.y as u32);
        h.write(v.depth() as u32);
    }
    Some(h.0)
}

/// The `triangles` variant: [`random_mesh`] turned by frame `f` about x, both windings drawn
/// (no culling), into a band of the frame from row 37 (its rows 37 to 276, the buffers'
/// 240), fragments counted. Returns a word of the counts and of the depth buffer (the depth
/// walks of triangles of every size and both windings, which change few colours).
fn random_triangles(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<u32> {
    let objects = [Object::new(mesh, random_turn(f), ORANGE)];
    let scene = Scene::new(&objects, sun());
    let frame = frame(W, H)?.with_cull(Cull::None);
    let p = frame.prepare(&scene, cache, Flat).ok()?;
    let (mut c, mut d) = (
        FrameBuffer::new(color, W, H).ok()?,
        DepthBuffer::new(depth, W, H).ok()?,
    );
    let stats = p
        .draw(&mut ColorDepth::band(&mut c, &mut d, 37).ok()?)
        .ok()?;
    Some(stats.fragments.rotate_left(16) ^ stats.written ^ depth_word(depth))
}

/// A word of every stored depth: a walk one unit off changes few colours.
fn depth_word(depth: &[u16]) -> u32 {
    let mut h = Fnv::new();
    depth.iter().for_each(|&z| h.write(z as u32));
    h.0
}

/// [`random_mesh`]'s turn at frame `f`: about x, so that corners apart only in x stay at one
/// height and depth.
fn random_turn(f: u32) -> Mat4 {
    Mat4::rotation_x(Angle::from_degrees(7 * f as i32))
}

/// The model matrix of the `front` variant at frame `f`: [`random_mesh`] turned as in
/// `triangles` and shrunk to a quarter, so that every vertex lies inside every clip plane.
pub fn front_model(f: u32) -> Mat4 {
    let quarter = Scalar::from_bits(1 << 14);
    random_turn(f) * Mat4::scaling(Vec3::new(quarter, quarter, quarter))
}

/// The `front` variant's drawing of frame `f` (see [`random_front_faces`]), fragments
/// counted: what it counted. The vertices stay in `cache`, the frame in `color` and `depth`.
pub fn random_front_stats(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<Stats> {
    let objects = [Object::new(mesh, front_model(f), ORANGE)];
    let scene = Scene::new(&objects, sun());
    with_depth_target(
        frame(W, H)?,
        &scene,
        Flat,
        cache,
        color,
        depth,
        |p, mut target| p.draw(&mut target).ok(),
    )
}

/// The `front` variant: [`random_mesh`] at [`front_model`], back faces culled, into the whole
/// frame, fragments counted: the triangle walk of an object inside every clip plane (with
/// `asm` in assembly on both cores), over triangles of both windings and of zero area.
/// Returns a word of every count of the drawing but the primitives (culled, degenerate, drawn,
/// fragments and writes) and of the depth buffer.
fn random_front_faces(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<u32> {
    let s = random_front_stats(mesh, f, cache, color, depth)?;
    let depths = depth_word(depth);
    let counts = [
        s.culled,
        s.degenerate,
        s.drawn,
        s.fragments,
        s.written,
        depths,
    ];
    Some(counts.iter().fold(0, |h, &k| h.rotate_left(7) ^ k))
}

/// `gouraud`: the torus with per-vertex normals, Gouraud shading, three coloured lights.
pub fn gouraud(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    let objects = [Object::new(mesh, torus_model(f), Rgb888::WHITE)];
    let scene = Scene::new(&objects, three_lights());
    depth_frame(frame(W, H)?, &scene, Gouraud, cache, color, depth)
}

/// The `phong` preset's highlights: white, shininess 32.
pub static GLOSS: Specular = Specular::new(Rgb888::WHITE, 32);

/// Ambient and one warm point light beside the torus, falling off linearly.
pub fn lamp() -> Lighting<1> {
    let mut l = Lighting::new(LightColor::gray(s(3, 20)));
    let light = PointLight::new(
        Vec3::new(s(-3, 2), s(1, 1), s(3, 2)),
        Rgb888::new(255, 230, 200),
    );
    let _ = l.push_point(light.attenuated(Attenuation::Linear));
    l
}

/// `phong`: `gouraud`'s torus, glossy, under one point light (the `point-light` and
/// `specular` features).
pub fn phong(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    let torus = Object::new(mesh, torus_model(f), Rgb888::new(60, 120, 220));
    let objects = [torus.with_specular(Some(&GLOSS))];
    let scene = Scene::new(&objects, lamp());
    depth_frame(frame(W, H)?, &scene, Gouraud, cache, color, depth)
}

/// The `textured` preset's torus: `full`'s with UVs, its seams' vertices doubled.
pub const TEXTURED_VERTICES: usize = 49 * 25;

/// The `textured` torus into the given storage.
pub fn textured_torus_mesh<'a>(
    p: &'a mut [Vec3],
    n: &'a mut [Vec3],
    uv: &'a mut [Uv],
    t: &'a mut [Triangle],
) -> Mesh<'a> {
    textured_torus(Scalar::ONE, s(2, 5), 48, 24, p, n, uv, t).unwrap_or(Mesh::EMPTY)
}

/// The `textured` preset's 64x64 texture, in flash: an 8x8 checker of two colour ramps.
pub static TEXELS: [Rgb565; 64 * 64] = checker();

const fn checker() -> [Rgb565; 64 * 64] {
    let mut t = [Rgb565::new(0, 0, 0); 64 * 64];
    let mut i = 0;
    while i < 64 * 64 {
        let (x, y) = ((i % 64) as u8, (i / 64) as u8);
        t[i] = if (x / 8 + y / 8) % 2 == 0 {
            Rgb565::new(31, x, 31 - y / 2)
        } else {
            Rgb565::new(y / 2, 20, x / 2)
        };
        i += 1;
    }
    t
}

/// `textured`: the torus under `full`'s light with [`TEXELS`] on it, perspective-correct,
/// flat Lambert, u16 depth.
pub fn textured(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    textured_by(mesh, f, cache, color, depth, |t| t)
}

/// [`textured`] with its texture's mapping changed by `configure` (the `knobs` preset's
/// texture knobs).
pub fn textured_by(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
    configure: impl FnOnce(Texture<'static>) -> Texture<'static>,
) -> Option<()> {
    let texture = configure(Texture::new(Texels::Rgb565(&TEXELS), 64, 64).ok()?);
    let objects = [Object::new(mesh, torus_model(f), Rgb888::WHITE)];
    let scene = Scene::new(&objects, sun());
    let shading = Textured {
        texture: &texture,
        light: Flat,
    };
    depth_frame(frame(W, H)?, &scene, shading, cache, color, depth)
}

/// `bands`: `full`'s torus drawn by the [`Renderer`] through `BAND_ROWS`-row buffers into
/// `display`, each band sent with one `fill_contiguous` whose colours are hashed on their way
/// (the frame's hash, as [`frame_hash`] gives it for `full`). Each band's write runs inside
/// `exclude`: the `bands` firmware leaves it out of the count (a real display takes the band
/// by DMA, and `full` leaves out its clears alike); the `display` firmware counts it.
#[allow(clippy::too_many_arguments)]
pub fn bands<D: DrawTarget<Color = Rgb565>>(
    mesh: &Mesh<'_>,
    f: u32,
    vertices: &mut [ScreenVertex],
    (bins, carried): (&mut [Bin], &mut [Carried]),
    color: &mut [Rgb565],
    depth: &mut [u16],
    display: &mut D,
    exclude: &mut dyn FnMut(&mut dyn FnMut()),
) -> Option<u32> {
    let models = [Model::new(mesh, ORANGE).with_matrix(torus_model(f))];
    let lights = [
        Light::ambient(s(1, 5)),
        Light::directional(Vec3::from_int(-1, 1, 1), s(4, 5)),
    ];
    let camera = Camera::perspective(60, 1, 10)
        .looking_at(Vec3::new(Scalar::ZERO, Scalar::ZERO, s(13, 5)), Vec3::ZERO);
    let mut sent = SentFrame {
        hash: Fnv::new(),
        display,
        exclude,
    };
    Renderer::from_slices(vertices, bins, color, depth)
        .with_carried(carried)
        .render(&models, &lights, &camera, &mut sent)
        .ok()?;
    Some(sent.hash.0)
}

/// Bins for `bands`: the torus's triangles that can face the camera at once (about half of a
/// closed mesh's), with room to spare.
pub const BAND_BINS: usize = TORUS_TRIANGLES / 2 + 256;

/// Room for `bands`' solid triangles that cross a band boundary: the torus has up to about
/// 90 across one.
pub const BAND_CARRIED: usize = 96;

/// A display that takes everything and keeps nothing (the `bands` preset's, 320x240).
pub struct NoDisplay;

impl OriginDimensions for NoDisplay {
    fn size(&self) -> Size {
        Size::new(W, H)
    }
}

impl DrawTarget for NoDisplay {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        _: I,
    ) -> Result<(), Self::Error> {
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        _: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        colors.into_iter().for_each(drop);
        Ok(())
    }
}

/// `display`, hashing the colours it is sent, in order, each write inside `exclude`.
pub struct SentFrame<'e, D> {
    pub hash: Fnv,
    pub display: &'e mut D,
    pub exclude: &'e mut dyn FnMut(&mut dyn FnMut()),
}

impl<D: DrawTarget<Color = Rgb565>> OriginDimensions for SentFrame<'_, D> {
    fn size(&self) -> Size {
        self.display.bounding_box().size
    }
}

impl<D: DrawTarget<Color = Rgb565>> DrawTarget for SentFrame<'_, D> {
    type Color = Rgb565;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), D::Error> {
        let (hash, display) = (&mut self.hash, &mut *self.display);
        let mut pixels = Some(pixels);
        let mut sent = Ok(());
        (self.exclude)(&mut || {
            if let Some(pixels) = pixels.take() {
                let hashed = pixels
                    .into_iter()
                    .inspect(|Pixel(_, c)| hash.write(c.into_storage() as u32));
                sent = display.draw_iter(hashed);
            }
        });
        sent
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), D::Error> {
        let (hash, display) = (&mut self.hash, &mut *self.display);
        let mut colors = Some(colors);
        let mut sent = Ok(());
        (self.exclude)(&mut || {
            if let Some(colors) = colors.take() {
                let hashed = colors
                    .into_iter()
                    .inspect(|c| hash.write(c.into_storage() as u32));
                sent = display.fill_contiguous(area, hashed);
            }
        });
        sent
    }
}

/// `flat`: a convex mesh (the cube) filled flat, back-face culling only, no depth buffer.
pub fn flat(f: u32, cache: &mut [ScreenVertex], color: &mut [Rgb565]) -> Option<()> {
    let model = Mat4::rotation_y(Angle::from_degrees(25 + f as i32))
        * Mat4::rotation_x(Angle::from_degrees(30));
    let objects = [Object::new(&CUBE, model, ORANGE)];
    let scene = Scene::new(&objects, sun());
    let p = camera(W, H, Vec3::from_int(0, 0, 5))?
        .prepare(&scene, cache, Flat)
        .ok()?;
    let mut c = FrameBuffer::new(color, W, H).ok()?;
    p.draw(&mut Direct::new(&mut c)).ok().map(|_| ())
}

/// `wire`: the torus's wireframe straight into a display: no framebuffer, depth or lighting.
pub fn wire(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    display: &mut HashDisplay,
) -> Option<()> {
    let objects = [Object::new(mesh, torus_model(f), Rgb888::WHITE)];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::WHITE));
    let size = display.size;
    let p = frame(size.width, size.height)?
        .prepare(&scene, cache, Unlit)
        .ok()?;
    p.draw_wireframe(display).ok().map(|_| ())
}

/// `obj`: a model parsed at start-up from OBJ text in flash (into the given storage).
pub fn obj_mesh<'a>(p: &'a mut [Vec3], t: &'a mut [Triangle]) -> Mesh<'a> {
    let parsed = fixed3d::obj::parse(
        OBJ_MODEL,
        &mut fixed3d::obj::ObjBuffers::new(&mut *p, &mut *t),
        fixed3d::obj::Placement::AsIs,
    );
    let (p, t): (&'a [Vec3], &'a [Triangle]) = (p, t);
    match parsed {
        Ok(c) => match (p.get(..c.positions), t.get(..c.triangles)) {
            (Some(p), Some(t)) => Mesh::new(p, t).unwrap_or(Mesh::EMPTY),
            _ => Mesh::EMPTY,
        },
        Err(_) => Mesh::EMPTY,
    }
}

/// `obj`: the parsed model, flat Lambert, u16 depth.
pub fn obj(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<()> {
    let model = Mat4::rotation_y(Angle::from_degrees(10 + 3 * f as i32))
        * Mat4::rotation_x(Angle::from_degrees(15));
    let objects = [Object::new(mesh, model, Rgb888::new(120, 200, 255))];
    let frame = camera(W, H, Vec3::from_int(0, 1, 4))?;
    depth_frame(
        frame,
        &Scene::new(&objects, sun()),
        Flat,
        cache,
        color,
        depth,
    )
}

/// The SSD1306 frame of the `display` preset: 128x64, one bit per pixel.
pub const MONO_W: u32 = 128;
pub const MONO_H: u32 = 64;

/// The torus on a 128x64 one-bit display: Gouraud shading through an ordered dither.
pub fn mono(
    mesh: &Mesh<'_>,
    f: u32,
    cache: &mut [ScreenVertex],
    color: &mut [BinaryColor],
    depth: &mut [u16],
) -> Option<()> {
    let objects = [Object::new(mesh, torus_model(f), Rgb888::WHITE)];
    let mut light = Lighting::<1>::new(LightColor::gray(s(1, 20)));
    let _ = light.push(DirectionalLight::new(
        Vec3::from_int(-1, 1, 1),
        LightColor::gray(s(19, 20)),
    ));
    let scene = Scene::new(&objects, light);
    let p = frame(MONO_W, MONO_H)?
        .prepare(&scene, cache, Gouraud)
        .ok()?;
    let (mut c, mut d) = (
        FrameBuffer::new(color, MONO_W, MONO_H).ok()?,
        DepthBuffer::new(depth, MONO_W, MONO_H).ok()?,
    );
    c.fill(BinaryColor::Off);
    d.clear();
    p.draw(&mut ColorDepth::new(&mut c, &mut d).ok()?.dithered().uncounted())
        .ok()
        .map(|_| ())
}

/// Hash of a one-bit frame.
pub fn mono_hash(px: &[BinaryColor]) -> u32 {
    let mut h = Fnv::new();
    for p in px {
        h.write(p.is_on() as u32);
    }
    h.0
}

/// The `display` preset's hash of one frame: the colour bands sent to the ILI9341 and the
/// one-bit frame sent to the SSD1306.
pub fn display_hash(bands: u32, mono: u32) -> u32 {
    bands ^ mono.rotate_left(16)
}

//! The `variants` preset's `wire-depth` configuration, compiled into its firmware and into the
//! host test `tests/firmware.rs` from this file, outside the `mcu_bench` library that every
//! preset links: there, its instance of the renderer moved the code LLVM generated for the
//! other presets that draw through one.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use fixed3d::camera::Camera;
use fixed3d::math::{Angle, Mat4, Scalar, Vec3};
use fixed3d::mesh::Mesh;
use fixed3d::pipeline::ScreenVertex;
use fixed3d::render::{Model, Renderer};
use fixed3d::scene::Light;

use super::scenes::{torus_model, NoDisplay, ORANGE};

/// `v / den` in Q16.16 (as the scenes' own helper).
fn s(v: i32, den: i32) -> Scalar {
    Scalar::from_bits(((v as i64) << 16) as i32 / den)
}

/// The wireframe's colour in the `wire-depth` variant.
pub const WIRE_BLUE: Rgb888 = Rgb888::new(40, 90, 255);

/// The `wire-depth` variant: `full`'s torus solid (unless `solid` is false) and a second one,
/// turned another way through it, as a wireframe that the first hides where it lies in front
/// (the lines' depth test), drawn by the [`Renderer`] in one pass into `color` and `depth`;
/// the word is the number of triangles and lines drawn.
pub fn wire_depth(
    mesh: &Mesh<'_>,
    f: u32,
    solid: bool,
    cache: &mut [ScreenVertex],
    color: &mut [Rgb565],
    depth: &mut [u16],
) -> Option<u32> {
    let both = [
        Model::new(mesh, WIRE_BLUE)
            .with_matrix(torus_model(f) * Mat4::rotation_x(Angle::from_degrees(90)))
            .wireframe(),
        Model::new(mesh, ORANGE).with_matrix(torus_model(f)),
    ];
    let models = if solid { &both[..] } else { &both[..1] };
    let lights = [
        Light::ambient(s(1, 5)),
        Light::directional(Vec3::from_int(-1, 1, 1), s(4, 5)),
    ];
    let camera = Camera::perspective(60, 1, 10)
        .looking_at(Vec3::new(Scalar::ZERO, Scalar::ZERO, s(13, 5)), Vec3::ZERO);
    let stats = Renderer::from_slices(cache, &mut [], color, depth)
        .render(models, &lights, &camera, &mut NoDisplay)
        .ok()?;
    Some(stats.drawn)
}

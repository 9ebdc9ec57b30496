#![doc = include_str!("../README.md")]
#![no_std]
#![deny(
    missing_docs,
    missing_debug_implementations,
    rustdoc::broken_intra_doc_links,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic
)]
#![forbid(unsafe_code)]
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic))]
#![doc(test(attr(deny(warnings))))]

#[cfg(test)]
extern crate std;

#[cfg(test)]
mod testing;

pub mod buffer;
pub mod camera;
pub mod math;
pub mod mesh;
pub mod obj;
pub mod pipeline;
pub mod projection;
pub mod raster;
pub mod render;
pub mod scene;
pub mod shade;
pub mod stats;
pub mod texture;

pub use camera::Camera;
pub use render::{Model, Renderer, Shade, Storage, Style, Wireframe};
pub use scene::Light;

/// The names of the common path, for `use fixed3d::prelude::*`: the renderer and what it
/// takes, the built-in shapes, and the number types of their arguments.
pub mod prelude {
    pub use crate::camera::Camera;
    pub use crate::math::{Angle, Number, Scalar, Vec3};
    pub use crate::mesh::{Mesh, Specular, CUBE, OCTAHEDRON, TETRAHEDRON};
    pub use crate::render::{Model, RenderError, Renderer, Shade, Storage, Style, Wireframe};
    pub use crate::scene::{Attenuation, Light, PointLight};
}

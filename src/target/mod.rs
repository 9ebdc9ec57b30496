//! Where pixels go: a framebuffer and a depth buffer over caller-supplied slices, and the
//! targets the filler writes spans into.
//!
//! - [`FrameBuffer`] is an embedded-graphics [`DrawTarget`](embedded_graphics::draw_target::DrawTarget)
//!   over `&mut [C]` for any colour `C`, presented to a display with one `fill_contiguous`.
//! - [`DepthBuffer`] holds `u16` or `u32` depth ([`DepthFormat`]), cleared to the far value.
//! - [`ColorDepth`] pairs the two for z-buffered filling, over a whole frame or one horizontal
//!   band of it; [`Direct`] fills any `DrawTarget` with no depth buffer at all, one
//!   `fill_solid` per span.
//! - [`Nearest`] and [`OrderedDither`] turn the shaded 24-bit colour into the target's colour;
//!   the dither keeps shading visible on 1-bit and grey displays.
//!
//! With the `asm` feature each core's hand-written code lives here too (thumb1.rs, thumb2.rs,
//! x86_64.rs, with asm_rows.rs the crate's only `unsafe`): the row and pixel loops, and for
//! the pipeline's earlier stages the triangle walk's skip of back faces (its state in
//! asm_faces.rs) and the vertex loop of an object known inside the clip planes on every core;
//! on Cortex-M a triangle's row set-up and a small triangle's depth walk (on the M4 and M7 the
//! row loop takes an uncounted span's pixels in pairs, with the DSP extension's halfword
//! instructions); on x86-64 the floor division of the edges' set-up (`floor_divide`, which
//! `raster` calls: the only assembly outside the target's own stages, kept here with the rest
//! of the crate's `unsafe`).

#[cfg(all(feature = "asm", fixed3d_asm_rows))]
mod asm_faces;
#[cfg(all(feature = "asm", fixed3d_asm_rows))]
mod asm_rows;
mod depth;
mod dither;
mod framebuffer;
mod grid;
mod surface;
#[cfg(all(feature = "asm", fixed3d_thumb1))]
mod thumb1;
#[cfg(all(feature = "asm", fixed3d_thumb2))]
mod thumb2;
#[cfg(all(feature = "asm", target_arch = "x86_64"))]
mod x86_64;

#[cfg(all(feature = "asm", fixed3d_asm_rows))]
pub(crate) use asm_faces::FrontFaces;
pub use depth::{
    Counted, DepthBuffer, DepthFormat, DepthTest, FragmentCount, Less, LessOrEqual, Uncounted,
};
pub use dither::{Nearest, OrderedDither, Quantize};
pub use framebuffer::FrameBuffer;
pub use grid::BufferError;
#[doc(hidden)]
pub use surface::solid_depth_walk;
pub use surface::{ColorDepth, Direct, RasterTarget, ScreenTriangle};
#[cfg(all(feature = "asm", fixed3d_thumb1))]
pub(crate) use thumb1::project_split_in_words;
#[cfg(all(feature = "asm", fixed3d_thumb2))]
pub(crate) use thumb2::project_known_in_words;
#[cfg(all(feature = "asm", target_arch = "x86_64"))]
pub(crate) use x86_64::{floor_divide, project_known_in_words};

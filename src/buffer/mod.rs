//! Where pixels go: a framebuffer and a depth buffer over caller-supplied slices, and the
//! targets the filler writes spans into.
//!
//! - [`FrameBuffer`] is an embedded-graphics [`DrawTarget`](embedded_graphics::draw_target::DrawTarget)
//!   over `&mut [C]` for any colour `C`, presented to a display with one `fill_contiguous`.
//! - [`DepthBuffer`] holds `u16` or `u32` depth ([`DepthFormat`]), cleared to the far value.
//! - [`ColorDepth`] pairs the two for z-buffered filling, over a whole frame or one horizontal
//!   band of it; [`Direct`] fills any `DrawTarget` with no depth buffer at all, one
//!   `fill_solid` per span.
//! - [`Carries`] takes the solid triangles a band stops at its last row on into the next band
//!   of a frame drawn top to bottom, in storage of the caller's ([`Carried`]).
//! - [`Nearest`] and [`OrderedDither`] turn the shaded 24-bit colour into the target's colour
//!   (a [`TargetColor`]); the dither keeps shading visible on 1-bit and grey displays. Smooth
//!   shading into a colour of channels (RGB565 and the like) is rounded straight to its depth.

mod carry;
mod depth;
mod dither;
mod framebuffer;
mod grid;
mod surface;

pub(crate) use carry::Carrier;
pub use carry::{Carried, Carries};
pub use depth::{
    Counted, DepthBuffer, DepthFormat, DepthTest, FragmentCount, Less, LessOrEqual, Uncounted,
};
pub use dither::{Nearest, OrderedDither, Quantize, TargetColor};
pub use framebuffer::FrameBuffer;
pub(crate) use grid::fill;
pub use grid::BufferError;
pub use surface::{ColorDepth, Direct, RasterTarget, ScreenTriangle};

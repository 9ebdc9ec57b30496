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
// Without the `asm` feature no `unsafe` at all; with it, only the row and pixel loops of
// target::thumb1, target::thumb2 and target::x86_64 (on Cortex-M3/M4 a triangle's row set-up
// and the vertex loop of objects known inside in words too) and their triangle walks' skip of
// back faces, and in target::asm_rows the read of a colour's bytes and the call of those loops.
#![cfg_attr(not(feature = "asm"), forbid(unsafe_code))]
#![cfg_attr(feature = "asm", deny(unsafe_code))]
#![cfg_attr(test, allow(clippy::unwrap_used, clippy::expect_used, clippy::panic))]
#![doc(test(attr(deny(warnings))))]

#[cfg(test)]
extern crate std;

#[cfg(test)]
mod testing;

pub mod camera;
pub mod math;
pub mod mesh;
pub mod obj;
pub mod pipeline;
pub mod projection;
pub mod raster;
pub mod scene;
pub mod shade;
pub mod target;

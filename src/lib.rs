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

#![no_std]
#![deny(
    missing_docs,
    missing_debug_implementations,
    rustdoc::broken_intra_doc_links
)]
#![forbid(unsafe_code)]
//! fixed3d

#[cfg(test)]
extern crate std;

pub mod camera;
pub mod math;
pub mod mesh;
pub mod pipeline;
pub mod projection;
pub mod raster;
pub mod scene;
pub mod shade;
pub mod target;

//! What the board firmwares under `boards/` draw (see [`scene`]'s items, re-exported here).
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod scene;

pub use scene::*;

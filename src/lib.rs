//! refraction-explorer: makes refraction visible.
//!
//! Layers, dependencies pointing down only (see `DESIGN.md`): [`kernel`] (glam only) is the
//! refraction math; [`oracle`] is its exact reference in double-double arithmetic; [`solve`] is
//! the JSON Lines interface of the `solve` command; [`diagram`] is what the explorer draws,
//! [`render`] draws it into a PNG and [`app`] is the explorer window.

pub mod app;
pub mod atomic;
pub mod bench;
pub mod diagram;
pub mod kernel;
pub mod oracle;
pub mod render;
pub mod solve;
pub mod state_file;

//! refraction-explorer: makes refraction visible.
//!
//! Layers, dependencies pointing down only (see `DESIGN.md`): [`kernel`] (glam only) is the
//! refraction math; [`oracle`] is its exact reference in double-double arithmetic; [`solve`] is
//! the JSON Lines interface of the `solve` command; [`scene`] (serde and the kernel) holds the
//! scenes of several interfaces and their tracer.

pub mod atomic;
pub mod kernel;
pub mod oracle;
pub mod scene;
pub mod solve;

//! refraction-explorer: makes refraction visible.
//!
//! Layers, dependencies pointing down only (see `DESIGN.md`): [`kernel`] (glam only) is the
//! refraction math; [`oracle`] is its exact reference in double-double arithmetic; [`bench`](mod@bench)
//! measures the kernel variants against it; [`scene`] (serde and the kernel) holds the scenes of
//! several interfaces and their tracer; [`diagram`] is what the explorer draws, [`render`] draws
//! it into a PNG and [`app`] is the explorer window; [`solve`] and [`check`] are the JSON Lines
//! interfaces of the `solve` and `check` commands, sharing [`jsonl`]'s loop.

pub mod app;
pub mod atomic;
pub mod bench;
pub mod check;
pub mod diagram;
pub mod jsonl;
pub mod kernel;
pub mod oracle;
pub mod render;
pub mod scene;
pub mod snippets;
pub mod solve;
pub mod state_file;

//! refraction-explorer: makes refraction visible.
//!
//! Layers, dependencies pointing down only (see `DESIGN.md`): [`kernel`] (glam only) is the
//! refraction math; [`oracle`] is its exact reference in double-double arithmetic; [`bench`]
//! measures the kernel variants against it; [`scene`] (serde and the kernel) holds the scenes of
//! several interfaces and their tracer; [`solve`] and [`check`] are the JSON Lines interfaces of
//! the `solve` and `check` commands, sharing [`jsonl`]'s loop.

pub mod atomic;
pub mod bench;
pub mod check;
pub mod jsonl;
pub mod kernel;
pub mod oracle;
pub mod scene;
pub mod snippets;
pub mod solve;

//! refraction-explorer: the explorer window and the JSON Lines commands, on top of the layer
//! crates (see `ARCHITECTURE.md`): [`refraction_kernel`] (the math), [`refraction_bench`] (its
//! accuracy against time), [`refraction_scene`] (scenes and their tracer),
//! [`refraction_diagram`] (what is drawn) and [`refraction_render`] (drawn off screen).
//!
//! - [`app`]: the explorer window (eframe, egui, egui_plot);
//! - [`lines`]: the `solve` and `check` commands' JSON Lines, and the explorer's state as one
//!   such line.

pub mod app;
pub mod lines;

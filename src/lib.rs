//! refraction-explorer: the explorer window, on top of the layer crates (see `ARCHITECTURE.md`):
//! [`refraction_kernel`] (the math), [`refraction_model`] (what is explored),
//! [`refraction_scene`] (scenes and their tracer), [`refraction_diagram`] (what is drawn),
//! [`refraction_render`] (drawn off screen) and [`refraction_tools`] (`solve`, `check` and
//! state files). The commands run in the binary (`src/main.rs`, `src/commands/`).
//!
//! - [`app`]: the explorer window (eframe, egui); its plots are the diagram crate's.
//! - [`cli`]: the command line's definitions (clap), which the binary parses and the `xtask`
//!   turns into man pages and shell completions (not in the web build, which has no command
//!   line: `crates/refraction-web` starts the window in a browser page).
//! - [`web_page`]: the HTML page that loads the web build, which `cargo xtask web` writes.

/// The window title: the program's name, the same in every language (so that a window
/// manager's rules and a teacher's shortcut find it), and the web page's title.
// untranslated: the program's name.
pub const TITLE: &str = "Refraction explorer";

pub mod app;
#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod web_page;

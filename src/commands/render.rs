//! `render` and the default command: the explorer's diagram as a PNG, or in a window.

use std::path::Path;
use std::process::ExitCode;

use refraction_explorer::diagram::{ExplorerState, Overlay};
use refraction_explorer::{app, render, state_file};

use super::fail;

fn initial_state(path: Option<&Path>) -> Result<ExplorerState, String> {
    path.map_or_else(|| Ok(ExplorerState::default()), state_file::load)
}

/// Draws the state in `state` (or the default) into the PNG `out`.
pub fn run(out: &Path, width: u32, height: u32, state: Option<&Path>) -> ExitCode {
    match initial_state(state).and_then(|s| {
        render::export(&s, &Overlay::default(), (width, height), out).map_err(|e| e.to_string())
    }) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail("render", &message),
    }
}

/// Opens the explorer window, on the state in `state` if given.
pub fn explorer(state: Option<&Path>) -> ExitCode {
    match state
        .map(state_file::load)
        .transpose()
        .and_then(|s| app::run(s).map_err(|e| e.to_string()))
    {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail("", &message),
    }
}

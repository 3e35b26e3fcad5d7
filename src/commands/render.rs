//! `render` and the default command: the explorer's diagram or a traced scene as a PNG, or the
//! explorer in a window.

use std::path::Path;
use std::process::ExitCode;

use refraction_diagram::{ExplorerState, Overlay};
use refraction_explorer::app;
use refraction_explorer::lines::state_file;
use refraction_render as render;
use refraction_scene::Scene;

use super::fail;

fn initial_state(path: Option<&Path>) -> Result<ExplorerState, String> {
    path.map_or_else(|| Ok(ExplorerState::default()), state_file::load)
}

/// Draws `scene` traced, or else the state in `state` (or the default), into the PNG `out`.
pub fn run(
    scene: Option<&str>,
    out: &Path,
    width: u32,
    height: u32,
    state: Option<&Path>,
) -> ExitCode {
    let drawn = match (scene, state) {
        (Some(scene), Some(state)) => Err(format!(
            "give a SCENE ({scene}) or --state ({}), not both: --state is the single-interface \
             problem, SCENE a traced scene",
            state.display()
        )),
        (Some(scene), None) => Scene::load(scene)
            .map_err(|e| e.to_string())
            .and_then(|s| render::export_scene(&s, width, height, out).map_err(|e| e.to_string())),
        (None, state) => initial_state(state).and_then(|s| {
            render::export(&s, &Overlay::default(), (width, height), out).map_err(|e| e.to_string())
        }),
    };
    match drawn {
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

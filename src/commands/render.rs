//! `render` and the default command: the explorer's diagram or a traced scene as a PNG, or the
//! explorer in a window.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use refraction_diagram::palette::Theme;
use refraction_diagram::{ExplorerState, Overlay};
use refraction_explorer::app::{self, Launch, View};
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

/// What the command line asked of the window.
pub struct Window {
    /// The state file to open on.
    pub state: Option<PathBuf>,
    /// Start in presentation mode.
    pub present: bool,
    /// The view to show.
    pub view: Option<View>,
    /// The theme.
    pub theme: Option<Theme>,
}

/// Opens the explorer window as `window` asks; a state file that cannot be read is refused
/// before any window opens.
pub fn explorer(window: &Window) -> ExitCode {
    let launch = window
        .state
        .as_deref()
        .map(state_file::load)
        .transpose()
        .map(|state| Launch {
            state,
            present: window.present,
            view: window.view,
            theme: window.theme,
        });
    match launch.and_then(|launch| app::run(launch).map_err(|e| e.to_string())) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail("", &message),
    }
}

//! `render` and the default command: the explorer's diagram or a traced scene as a PNG, or the
//! explorer in a window.

use std::io::{self, IsTerminal};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use refraction_diagram::palette::Theme;
use refraction_diagram::{ExplorerState, Overlay};
use refraction_explorer::app::{self, Launch, View};
use refraction_explorer::lines::state_file;
use refraction_render::{self as render, atomic, format::ImageFormat};
use refraction_scene::Scene;

use super::{fail, output, output_error};

/// Where an image goes: a file, written by [`atomic::write_atomically`], or stdout (`-`).
#[derive(Clone, Copy, Debug)]
pub enum Destination<'a> {
    /// A file (or a FIFO, or a device).
    File(&'a Path),
    /// Standard output.
    Stdout,
}

impl<'a> Destination<'a> {
    /// Checks `path` as an image destination before any work is done: its extension names a
    /// format written ([`ImageFormat::for_path`]); a file's folder exists and what is at the
    /// path can be written ([`atomic::check_writable`]); `-` means stdout where
    /// `stdout_allowed`, and stdout must then be neither a terminal nor closed.
    ///
    /// # Errors
    /// What is wrong with the path, in a sentence naming it.
    pub fn check(path: &'a Path, option: &str, stdout_allowed: bool) -> Result<Self, String> {
        ImageFormat::for_path(path).map_err(|e| e.to_string())?;
        if path != Path::new("-") {
            atomic::check_writable(path).map_err(|e| e.to_string())?;
            return Ok(Self::File(path));
        }
        if !stdout_allowed {
            return Err(format!(
                "{option} - is not allowed here: standard output has the command's own output; \
                 give a file name (./- for a file named -)"
            ));
        }
        if io::stdout().is_terminal() {
            return Err(format!(
                "{option} - writes PNG bytes to standard output, which is a terminal: redirect it \
                 (> file.png, | viewer) or give a file name"
            ));
        }
        if output::stdout_closed() {
            return Err(format!("{option} -: standard output is closed"));
        }
        Ok(Self::Stdout)
    }

    /// Writes `bytes` there; `command` names the command in a failure's message.
    pub fn write(self, command: &str, bytes: &[u8]) -> ExitCode {
        match self {
            Self::File(path) => atomic::write_atomically(path, bytes)
                .map_or_else(|e| fail(command, &e), |()| ExitCode::SUCCESS),
            Self::Stdout => output::to_stdout(bytes)
                .map_or_else(|e| output_error(command, &e), |()| ExitCode::SUCCESS),
        }
    }
}

fn initial_state(path: Option<&Path>) -> Result<ExplorerState, String> {
    path.map_or_else(|| Ok(ExplorerState::default()), state_file::load)
}

/// The PNG of `scene` traced, or else of the state in `state` (or the default). The size is
/// checked before the scene is traced.
fn png(
    scene: Option<&str>,
    (width, height): (u32, u32),
    state: Option<&Path>,
) -> Result<Vec<u8>, String> {
    render::check_size(width, height).map_err(|e| e.to_string())?;
    let pixmap = match (scene, state) {
        (Some(scene), Some(state)) => Err(format!(
            "give a SCENE ({scene}) or --state ({}), not both: --state is the single-interface \
             problem, SCENE a traced scene",
            state.display()
        )),
        (Some(scene), None) => Scene::load(scene)
            .map_err(|e| e.to_string())
            .and_then(|s| render::render_scene(&s, width, height).map_err(|e| e.to_string())),
        (None, state) => initial_state(state).and_then(|s| {
            render::render(&s, &Overlay::default(), width, height).map_err(|e| e.to_string())
        }),
    }?;
    render::encode(&pixmap).map_err(|e| e.to_string())
}

/// Draws `scene` traced, or else the state in `state` (or the default), into the PNG `out`
/// (`-`: stdout). The output path and the size are checked before anything is traced or drawn.
pub fn run(
    scene: Option<&str>,
    out: &Path,
    width: u32,
    height: u32,
    state: Option<&Path>,
) -> ExitCode {
    let drawn = Destination::check(out, "--out", true)
        .and_then(|to| png(scene, (width, height), state).map(|bytes| (to, bytes)));
    match drawn {
        Ok((to, bytes)) => to.write("render", &bytes),
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

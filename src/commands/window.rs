//! The explorer's window as the command line opens it: a state file or a lesson deck that
//! cannot be read is refused before any window opens.

use refraction_tools::open_state_file;
use std::path::PathBuf;
use std::process::ExitCode;

use refraction_diagram::palette::Theme;
use refraction_explorer::app::{self, Launch, View};
use refraction_i18n::Locale;

use super::fail;

/// What the command line asked of the window.
pub(crate) struct Window {
    /// The state file to open on.
    pub state: Option<PathBuf>,
    /// The lesson deck to open on (`--lesson`).
    pub lesson: Option<String>,
    /// Start in presentation mode.
    pub present: bool,
    /// The view to show.
    pub view: Option<View>,
    /// The theme.
    pub theme: Option<Theme>,
    /// The language (`--lang`).
    pub language: Option<Locale>,
    /// The web build's address for links (`--web-base`).
    pub web_base: Option<String>,
}

/// Opens the explorer window as `window` asks; a state file or a lesson deck that cannot be
/// read, or a web address that cannot start a link, is refused before any window opens.
pub(crate) fn open(window: &Window) -> ExitCode {
    if let Some(Err(e)) = window.lesson.as_deref().map(refraction_deck::Deck::load) {
        return fail("", &e);
    }
    let state = match window.state.as_deref().map(open_state_file).transpose() {
        Ok(state) => state,
        Err(e) => return fail("", &e),
    };
    let web_base = match super::web_base(window.web_base.as_deref()) {
        Ok(base) => base,
        Err(e) => return fail("", &e),
    };
    let launch = Launch {
        state,
        lesson: window.lesson.clone(),
        present: window.present,
        view: window.view,
        theme: window.theme,
        language: window.language,
        system_language: sys_locale::get_locale().and_then(|tag| Locale::from_tag(&tag)),
        web_base,
    };
    match app::run(launch) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail("", &e),
    }
}

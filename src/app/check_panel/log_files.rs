//! The files of a judged log: a log opened in the file dialog or dropped on the window (read
//! whole, with a cap, and judged in place of the text box), and its failing lines saved as a
//! file of tests in the renderer's language, asked about before a file is replaced and never
//! written over a file that is not one of these test files.

use std::path::{Path, PathBuf};

use egui::Ui;

use super::refusal::Refusal;
use crate::app::file_dialog::{self, FileDialog, Purpose, Target};
use crate::app::status::{self, Look, Status};
use refraction_check::AnyLanguage;
use refraction_check::tests_file::{self, TestLanguage};
use refraction_check::{Dialect, Options};
use refraction_check::{Failing, MAX_TESTS};
use refraction_i18n::t;

/// The most lines judged in the window (a log file can be longer: `check` takes any length).
pub(super) const MAX_JUDGED: usize = 100_000;

/// The largest log file the window reads (`check` reads any length from its input).
pub(super) const MAX_LOG_BYTES: u64 = 16 * 1024 * 1024;

/// The extensions the open dialog lists.
const LOG_EXTENSIONS: &[&str] = &["log", "txt", "csv", "jsonl", "json"];

/// A test language's button label.
fn label(language: TestLanguage) -> String {
    match language {
        TestLanguage::Api(language) => language.label().to_owned(),
        // untranslated: a programming language's name
        TestLanguage::Any(AnyLanguage::Cpp) => "C++".to_owned(),
        // untranslated: a programming language's name
        TestLanguage::Any(AnyLanguage::Python) => "Python".to_owned(),
    }
}

/// Whether tests in `language` may be written at `path`, as the file dialog's target.
fn tests_target(path: &Path, language: TestLanguage) -> Result<Target, Refusal> {
    Ok(if tests_file::replaces(path, language)? {
        Target::Replaces
    } else {
        Target::New
    })
}

/// A log file read whole, judged in place of the text box.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Opened {
    path: PathBuf,
    text: String,
}

/// What a file chosen in the dialog is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Use {
    /// A log to judge.
    Log,
    /// The failing lines' tests, in this language.
    Tests(TestLanguage),
}

/// The log opened, the dialog while it is up, and a test file waiting for the replace
/// question.
#[derive(Debug, Default)]
pub(super) struct LogFiles {
    opened: Option<Opened>,
    dialog: Option<(Use, FileDialog)>,
    /// A test file about to replace one, and its text.
    replacing: Option<(PathBuf, String)>,
    /// The path of `replacing` while the question is up (what [`file_dialog::answer_replace`]
    /// clears).
    replace: Option<PathBuf>,
    status: Option<Status>,
    /// A log opened since the last frame (dropped, or chosen), to judge now.
    fresh: bool,
}

impl LogFiles {
    /// The text of the log file opened, if one is.
    #[must_use]
    pub(super) fn opened_text(&self) -> Option<&str> {
        self.opened.as_ref().map(|o| o.text.as_str())
    }

    /// Reads the log at `path` to judge next, or says why it cannot.
    pub(super) fn open(&mut self, path: &Path) {
        let shown = path.display().to_string();
        match refraction_files::read_capped(path, MAX_LOG_BYTES, &t!("logs-what-log")) {
            Ok(text) => {
                self.opened = Some(Opened {
                    path: path.to_path_buf(),
                    text,
                });
                self.status = None;
                self.fresh = true;
            }
            Err(e) => {
                let reason = e.to_string();
                self.status = Some(Status::Refused(t!(
                    "logs-read-failed",
                    path = shown,
                    reason = reason
                )));
            }
        }
    }

    /// Whether a log was opened since the last call (it is judged then).
    pub(super) fn take_fresh(&mut self) -> bool {
        core::mem::take(&mut self.fresh)
    }

    /// What file is judged instead of the text box, with a button that goes back to the box;
    /// whether a file is.
    pub(super) fn opened_ui(&mut self, ui: &mut Ui) -> bool {
        let Some(opened) = &self.opened else {
            return false;
        };
        let lines = opened.text.lines().filter(|l| !l.trim().is_empty()).count();
        let path = opened.path.display().to_string();
        let most = MAX_JUDGED;
        ui.horizontal_wrapped(|ui| {
            ui.label(t!("logs-opened", path = path, lines = lines, most = most));
            if ui.button(t!("logs-close-file")).clicked() {
                self.opened = None;
            }
        });
        true
    }

    /// *Open log…*, which puts up the file dialog.
    pub(super) fn open_button(&mut self, ui: &mut Ui) {
        let button = ui
            .button(t!("logs-open"))
            .on_hover_text(t!("logs-open-hover", most = MAX_JUDGED));
        if button.clicked() {
            let start = self
                .opened
                .as_ref()
                .map(|o| o.path.display().to_string())
                .unwrap_or_default();
            let dialog = FileDialog::new(Purpose::Open, LOG_EXTENSIONS, &start);
            self.dialog = Some((Use::Log, dialog));
        }
    }

    /// The buttons that save `failing` lines as tests in each of `dialect`'s languages.
    pub(super) fn save_buttons(&mut self, ui: &mut Ui, dialect: Dialect, failing: &[Failing]) {
        if failing.is_empty() {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            let count = failing.len().min(MAX_TESTS);
            ui.label(t!("logs-save-tests", count = count));
            for language in TestLanguage::of(dialect) {
                if ui.button(format!("💾 {}", label(language))).clicked() {
                    let folder = std::env::current_dir().unwrap_or_default();
                    let extension = language.extension();
                    let name = file_dialog::numbered(&folder, "refract-regression", extension);
                    let start = name.display().to_string();
                    let dialog = FileDialog::new(Purpose::Save, Self::extensions(language), &start);
                    self.dialog = Some((Use::Tests(language), dialog));
                }
            }
        });
    }

    /// The dialog and the replace question while they are up, and what the last open or save
    /// said; a test file chosen is written from `failing` lines read with `options`.
    pub(super) fn dialogs(&mut self, ui: &mut Ui, failing: &[Failing], options: &Options) {
        self.dialog_ui(ui, failing, options);
        if let Some(path) = file_dialog::answer_replace(ui, &mut self.replace, &mut self.status)
            && let Some((_, text)) = self.replacing.take()
        {
            self.write(&path, &text);
        }
        // What the last open or save said.
        status::show(ui, self.status.as_ref(), Look::SmallDone);
    }

    /// The extensions a test file in `language` is listed with.
    fn extensions(language: TestLanguage) -> &'static [&'static str] {
        match language.extension() {
            "glsl" => &["glsl"],
            "cpp" => &["cpp"],
            _ => &["py"],
        }
    }

    /// Shows the dialog while it is up; when a file is chosen, opens the log or saves the tests.
    fn dialog_ui(&mut self, ui: &Ui, failing: &[Failing], options: &Options) {
        if let Some(((usage, _), path)) = file_dialog::chosen_file(ui, &mut self.dialog, |(_, d)| d)
        {
            match usage {
                Use::Log => self.open(&path),
                Use::Tests(language) => self.save(&path, language, failing, options),
            }
        }
    }

    /// Writes the tests of `failing` in `language` at `path`, or asks before replacing a test
    /// file there; never over anything else.
    fn save(
        &mut self,
        path: &Path,
        language: TestLanguage,
        failing: &[Failing],
        options: &Options,
    ) {
        let text = match tests_file::text(language, failing, options) {
            Ok(text) => text,
            Err(e) => {
                self.status = Some(Status::Refused(e.to_string()));
                return;
            }
        };
        match tests_target(path, language) {
            Ok(Target::New) => self.write(path, &text),
            Ok(Target::Replaces) => {
                self.replace = Some(path.to_path_buf());
                self.replacing = Some((path.to_path_buf(), text));
            }
            Err(e) => self.status = Some(Status::Refused(e.to_string())),
        }
    }

    fn write(&mut self, path: &Path, text: &str) {
        self.status = Some(
            match refraction_files::write_atomically(path, text.as_bytes()) {
                Ok(()) => status::wrote(path),
                Err(e) => Status::Refused(t!(
                    "logs-write-failed",
                    path = path.display().to_string(),
                    reason = e.to_string()
                )),
            },
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_test_file_of_ours_is_replaced_after_the_question_and_no_other_file_at_all() {
        let folder = std::env::temp_dir().join(format!("log-files-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let cpp = TestLanguage::Any(AnyLanguage::Cpp);
        assert_eq!(tests_target(&folder.join("new.cpp"), cpp), Ok(Target::New));
        let ours = folder.join("ours.cpp");
        let mark = tests_file::TESTS_MARK;
        std::fs::write(&ours, format!("// {mark}: the first 3 …\n")).unwrap();
        assert_eq!(tests_target(&ours, cpp), Ok(Target::Replaces));
        let theirs = folder.join("theirs.cpp");
        std::fs::write(&theirs, "int main() {}\n").unwrap();
        let e = tests_target(&theirs, cpp).unwrap_err();
        let not_ours = tests_file::TargetError::NotOurs { path: theirs };
        assert_eq!(e, Refusal::Target(not_ours));
        std::fs::remove_dir_all(&folder).unwrap();
    }
}

//! The files of a judged log: a log opened in the file dialog or dropped on the window (read
//! whole, with a cap, and judged in place of the text box), and its failing lines saved as a
//! file of tests in the renderer's language, asked about before a file is replaced and never
//! written over a file that is not one of these test files.

use std::path::{Path, PathBuf};

use egui::{RichText, Ui};

use super::refusal::Refusal;
use crate::app::file_dialog::{self, FileDialog, Purpose, Target};
use crate::app::typed::error_label;
use refraction_i18n::t;
use refraction_tools::api_check::physics::Case;
use refraction_tools::api_check::{Dialect, Judgement, Options, Record};
use refraction_tools::snippets::api::{self as api_snippets, Language, Name};
use refraction_tools::snippets::{self, AnyCase, AnyLanguage};

/// The most lines judged in the window (a log file can be longer: `check` takes any length).
pub(super) const MAX_JUDGED: usize = 100_000;

/// The most failing lines a saved test file holds.
pub(super) const MAX_SAVED_FAILING: usize = 100;

/// A failing line, kept to be saved as a test.
#[derive(Clone, Debug)]
pub(super) struct Failing {
    /// Its line number in the log, from 1.
    pub line: usize,
    /// The call read.
    pub record: Record,
    /// Its verdict.
    pub judgement: Judgement,
}

/// The largest log file the window reads (`check` reads any length from its input).
pub(super) const MAX_LOG_BYTES: u64 = 16 * 1024 * 1024;

/// The extensions the open dialog lists.
const LOG_EXTENSIONS: &[&str] = &["log", "txt", "csv", "jsonl", "json"];

/// The first line of every test file written, after the language's comment mark: how a file
/// this tool may replace is told from the student's own code.
// untranslated: a comment in generated code, which is written in English as the snippets are
pub(super) const TESTS_MARK: &str = "Regression tests written by refraction-explorer";

/// The language a test file is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum TestLanguage {
    /// A named API's language.
    Api(Language),
    /// Any renderer's own refraction.
    Any(AnyLanguage),
}

impl TestLanguage {
    /// The languages offered for `dialect`.
    fn of(dialect: Dialect) -> Vec<Self> {
        match dialect.api() {
            Some(api) => Language::of(api).iter().map(|l| Self::Api(*l)).collect(),
            None => vec![Self::Any(AnyLanguage::Cpp), Self::Any(AnyLanguage::Python)],
        }
    }

    /// The button's label.
    fn label(self) -> String {
        match self {
            Self::Api(language) => language.label().to_owned(),
            // untranslated: a programming language's name
            Self::Any(AnyLanguage::Cpp) => "C++".to_owned(),
            // untranslated: a programming language's name
            Self::Any(AnyLanguage::Python) => "Python".to_owned(),
        }
    }

    /// The file's extension.
    fn extension(self) -> &'static str {
        match self {
            Self::Api(Language::Glsl) => "glsl",
            Self::Api(Language::CppPbrt | Language::CppBook) | Self::Any(AnyLanguage::Cpp) => "cpp",
            Self::Api(Language::Python) | Self::Any(AnyLanguage::Python) => "py",
        }
    }

    /// The mark that starts a comment line.
    fn comment(self) -> &'static str {
        match self.extension() {
            "py" => "#",
            _ => "//",
        }
    }
}

/// The tests of `failing` lines in `language`, after the mark that tells the file as ours.
fn tests_text(
    language: TestLanguage,
    failing: &[Failing],
    options: &Options,
) -> Result<String, Refusal> {
    let body = match language {
        TestLanguage::Api(language) => {
            let cases: Vec<(Name, api_snippets::ApiCase<'_>)> = failing
                .iter()
                .filter_map(|f| match &f.judgement {
                    Judgement::Api(judged) => {
                        let (call, diagnosis) = &**judged;
                        Some((
                            Name::Line(f.line),
                            api_snippets::ApiCase::of(call, diagnosis),
                        ))
                    }
                    Judgement::Physics(_) => None,
                })
                .collect();
            api_snippets::file(language, &cases)
        }
        TestLanguage::Any(language) => {
            let cases: Vec<(usize, Case)> = failing
                .iter()
                .map(|f| Case::from_record(&f.record, options).map(|case| (f.line, case)))
                .collect::<Result<_, _>>()?;
            let cases: Vec<AnyCase<'_>> = cases
                .iter()
                .map(|(line, case)| AnyCase {
                    line: *line,
                    request: &case.request,
                    yours: case.yours,
                })
                .collect();
            snippets::any_renderer_tests(language, &cases)?
        }
    };
    let mark = language.comment();
    let count = failing.len();
    Ok(format!(
        // untranslated: a comment in generated code, in English as the snippets are
        "{mark} {TESTS_MARK}: the first {count} failing lines of a log, a test each.\n{body}"
    ))
}

/// Whether the tests in `language` may be written at `path`: its name must end in the
/// language's extension, and a file already there must be a test file this tool wrote (or
/// empty), never the student's own code.
///
/// # Errors
/// The name has another extension, the path is a folder, or the file there is not ours.
fn tests_target(path: &Path, language: TestLanguage) -> Result<Target, Refusal> {
    let extension = language.extension();
    if path.extension().and_then(|e| e.to_str()) != Some(extension) {
        return Err(Refusal::TestsExtension {
            path: path.to_path_buf(),
            extension,
        });
    }
    if path.is_dir() {
        return Err(Refusal::IsAFolder {
            path: path.to_path_buf(),
        });
    }
    let Ok(text) = std::fs::read(path) else {
        return Ok(Target::New);
    };
    let ours = format!("{} {TESTS_MARK}", language.comment());
    if text.is_empty() || text.starts_with(ours.as_bytes()) {
        Ok(Target::Replaces)
    } else {
        Err(Refusal::NotOurTests {
            path: path.to_path_buf(),
        })
    }
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
    status: Option<Result<String, String>>,
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
                self.status = Some(Err(t!("logs-read-failed", path = shown, reason = reason)));
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
            let count = failing.len().min(MAX_SAVED_FAILING);
            ui.label(t!("logs-save-tests", count = count));
            for language in TestLanguage::of(dialect) {
                if ui.button(format!("💾 {}", language.label())).clicked() {
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
        self.status_ui(ui);
    }

    /// The extensions a test file in `language` is listed with.
    fn extensions(language: TestLanguage) -> &'static [&'static str] {
        match language.extension() {
            "glsl" => &["glsl"],
            "cpp" => &["cpp"],
            _ => &["py"],
        }
    }

    /// What the last open or save said.
    fn status_ui(&self, ui: &mut Ui) {
        match &self.status {
            Some(Ok(said)) => {
                ui.label(RichText::new(said).small());
            }
            Some(Err(e)) => error_label(ui, e),
            None => {}
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
        let text = match tests_text(language, failing, options) {
            Ok(text) => text,
            Err(e) => {
                self.status = Some(Err(e.to_string()));
                return;
            }
        };
        match tests_target(path, language) {
            Ok(Target::New) => self.write(path, &text),
            Ok(Target::Replaces) => {
                self.replace = Some(path.to_path_buf());
                self.replacing = Some((path.to_path_buf(), text));
            }
            Err(e) => self.status = Some(Err(e.to_string())),
        }
    }

    fn write(&mut self, path: &Path, text: &str) {
        let shown = path.display().to_string();
        self.status = Some(
            match refraction_files::write_atomically(path, text.as_bytes()) {
                Ok(()) => Ok(t!("files-wrote", path = shown)),
                Err(e) => Err(t!(
                    "logs-write-failed",
                    path = shown,
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
    fn tests_replace_only_a_test_file_of_ours_of_their_language() {
        let folder = std::env::temp_dir().join(format!("log-files-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let cpp = TestLanguage::Any(AnyLanguage::Cpp);
        let new = folder.join("new.cpp");
        assert_eq!(tests_target(&new, cpp), Ok(Target::New));
        let ours = folder.join("ours.cpp");
        std::fs::write(&ours, format!("// {TESTS_MARK}: the first 3 …\n")).unwrap();
        assert_eq!(tests_target(&ours, cpp), Ok(Target::Replaces));
        let theirs = folder.join("theirs.cpp");
        std::fs::write(&theirs, "#include <cmath>\nint main() {}\n").unwrap();
        let e = tests_target(&theirs, cpp).unwrap_err();
        assert_eq!(e, Refusal::NotOurTests { path: theirs });
        assert!(e.to_string().contains("theirs.cpp"), "{e}");
        let e = tests_target(&folder.join("tests.txt"), cpp).unwrap_err();
        assert!(
            matches!(
                e,
                Refusal::TestsExtension {
                    extension: "cpp",
                    ..
                }
            ),
            "{e:?}"
        );
        assert!(e.to_string().contains(".cpp"), "{e}");
        let python = TestLanguage::Any(AnyLanguage::Python);
        assert!(
            tests_target(&ours, python).is_err(),
            "a .cpp is not a Python file"
        );
        std::fs::remove_dir_all(&folder).unwrap();
    }
}

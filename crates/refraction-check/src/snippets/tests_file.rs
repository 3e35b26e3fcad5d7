//! A log's failing lines as a file of unit tests in the renderer's language, as the window's
//! log section and `check --tests` write it: a first line that marks the file as one of
//! these (so that only such a file, or an empty one, is ever replaced), then a test per line.

use std::path::{Path, PathBuf};

use refraction_i18n::t;

use super::api::{self, ApiCase, Language, Name};
use super::{AnyCase, AnyLanguage, any_renderer_tests};
use crate::call_check::physics::Case;
use crate::call_check::{Dialect, Failing, Judgement, LineError, Options};

/// The first line of every test file written, after the language's comment mark: how a file
/// this tool may replace is told from the student's own code.
// untranslated: a comment in generated code, which is written in English as the snippets are
pub const TESTS_MARK: &str = "Regression tests written by refraction-explorer";

/// The language a test file is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TestLanguage {
    /// A named API's language.
    Api(Language),
    /// Any renderer's own refraction.
    Any(AnyLanguage),
}

impl TestLanguage {
    /// The languages offered for `dialect`.
    #[must_use]
    pub fn of(dialect: Dialect) -> Vec<Self> {
        match dialect.api() {
            Some(api) => Language::of(api).iter().map(|l| Self::Api(*l)).collect(),
            None => vec![Self::Any(AnyLanguage::Cpp), Self::Any(AnyLanguage::Python)],
        }
    }

    /// The language of `dialect` whose extension `path` has, if one has.
    #[must_use]
    pub fn for_path(dialect: Dialect, path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?;
        Self::of(dialect)
            .into_iter()
            .find(|l| l.extension() == extension)
    }

    /// The file's extension.
    #[must_use]
    pub fn extension(self) -> &'static str {
        match self {
            Self::Api(Language::Glsl) => "glsl",
            Self::Api(Language::CppPbrt | Language::CppBook) | Self::Any(AnyLanguage::Cpp) => "cpp",
            Self::Api(Language::Python) | Self::Any(AnyLanguage::Python) => "py",
        }
    }

    /// The mark a comment starts with.
    #[must_use]
    pub fn comment(self) -> &'static str {
        match self.extension() {
            "py" => "#",
            _ => "//",
        }
    }
}

/// The tests of `failing` lines (read with `options`) in `language`, after the mark that
/// tells the file as ours.
///
/// # Errors
/// A line of any renderer's log that is not a case (it was judged, so it is one).
pub fn text(
    language: TestLanguage,
    failing: &[Failing],
    options: &Options,
) -> Result<String, LineError> {
    let body = match language {
        TestLanguage::Api(language) => {
            let cases: Vec<(Name, ApiCase<'_>)> = failing
                .iter()
                .filter_map(|f| match &f.judgement {
                    Judgement::Api(judged) => {
                        let (call, verdict) = &**judged;
                        Some((Name::Line(f.line), ApiCase::of(call, verdict)))
                    }
                    Judgement::Physics(_) => None,
                })
                .collect();
            api::file(language, &cases)
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
            any_renderer_tests(language, &cases)?
        }
    };
    let mark = language.comment();
    let count = failing.len();
    Ok(format!(
        // untranslated: a comment in generated code, in English as the snippets are
        "{mark} {TESTS_MARK}: the first {count} failing lines of a log, a test each.\n{body}"
    ))
}

/// Why a test file may not be written where it was asked for.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TargetError {
    /// The name does not end in the language's extension.
    #[error("{}", t!("logs-tests-extension", path = path.display().to_string(), extension = *extension))]
    Extension {
        /// The file.
        path: PathBuf,
        /// The extension it needs.
        extension: &'static str,
    },
    /// The name is a folder's.
    #[error("{}", t!("files-is-a-folder", path = path.display().to_string()))]
    IsAFolder {
        /// The folder.
        path: PathBuf,
    },
    /// A file is there that this tool did not write: the student's own code, maybe.
    #[error("{}", t!("logs-tests-not-ours", path = path.display().to_string()))]
    NotOurs {
        /// The file.
        path: PathBuf,
    },
}

/// Whether tests in `language` may be written at `path`, and whether they replace a file: its
/// name must end in the language's extension, and a file already there must be a test file
/// this tool wrote (or empty), never the student's own code. `Ok(true)` when one is there.
///
/// # Errors
/// The name has another extension, the path is a folder, or the file there is not ours.
pub fn replaces(path: &Path, language: TestLanguage) -> Result<bool, TargetError> {
    let extension = language.extension();
    if path.extension().and_then(|e| e.to_str()) != Some(extension) {
        let path = path.to_path_buf();
        return Err(TargetError::Extension { path, extension });
    }
    if path.is_dir() {
        let path = path.to_path_buf();
        return Err(TargetError::IsAFolder { path });
    }
    let ours = format!("{} {TESTS_MARK}", language.comment());
    // Only the first bytes tell whether the file is ours (and a browser page has only the
    // files it was given: refraction_files reads those too).
    let Ok(Some(text)) = refraction_files::first_bytes(path, ours.len() as u64) else {
        return Ok(false);
    };
    if text.is_empty() || text.starts_with(ours.as_bytes()) {
        Ok(true)
    } else {
        let path = path.to_path_buf();
        Err(TargetError::NotOurs { path })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tests_replace_only_a_test_file_of_ours_of_their_language() {
        let folder = std::env::temp_dir().join(format!("tests-file-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let cpp = TestLanguage::Any(AnyLanguage::Cpp);
        let new = folder.join("new.cpp");
        assert_eq!(replaces(&new, cpp), Ok(false));
        let ours = folder.join("ours.cpp");
        std::fs::write(&ours, format!("// {TESTS_MARK}: the first 3 …\n")).unwrap();
        assert_eq!(replaces(&ours, cpp), Ok(true));
        let theirs = folder.join("theirs.cpp");
        std::fs::write(&theirs, "#include <cmath>\nint main() {}\n").unwrap();
        let e = replaces(&theirs, cpp).unwrap_err();
        assert_eq!(e, TargetError::NotOurs { path: theirs });
        assert!(e.to_string().contains("theirs.cpp"), "{e}");
        let e = replaces(&folder.join("tests.txt"), cpp).unwrap_err();
        assert!(
            matches!(
                e,
                TargetError::Extension {
                    extension: "cpp",
                    ..
                }
            ),
            "{e:?}"
        );
        assert!(e.to_string().contains(".cpp"), "{e}");
        let python = TestLanguage::Any(AnyLanguage::Python);
        assert!(
            replaces(&ours, python).is_err(),
            "a .cpp is not a Python file"
        );
        std::fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn the_language_is_the_one_of_the_dialect_with_the_files_extension() {
        use refraction_kernel::api::Api;
        let pbrt = Dialect::Api(Api::Pbrt);
        assert_eq!(
            TestLanguage::for_path(pbrt, Path::new("t.cpp")),
            Some(TestLanguage::Api(Language::CppPbrt))
        );
        assert_eq!(TestLanguage::for_path(pbrt, Path::new("t.glsl")), None);
        assert_eq!(
            TestLanguage::for_path(Dialect::Physics, Path::new("t.py")),
            Some(TestLanguage::Any(AnyLanguage::Python))
        );
    }
}

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
    /// Something is there that cannot be read, so that it cannot be told from the student's
    /// own code (a teammate's file of mode 0600, one's own at 0200).
    #[error("{}", t!("logs-tests-unreadable", path = path.display().to_string(), reason = reason.as_str()))]
    Unreadable {
        /// The file.
        path: PathBuf,
        /// Why, as the system says it.
        reason: String,
    },
    /// Something is there that is not a regular file: a FIFO, a device, a link to one.
    #[error("{}", t!("logs-tests-not-a-file", path = path.display().to_string()))]
    NotAFile {
        /// The path.
        path: PathBuf,
    },
}

/// Whether tests in `language` may be written at `path`, and whether they replace a file: its
/// name must end in the language's extension, and a file already there must be a test file
/// this tool wrote (or empty), never the student's own code. Only the first bytes of a regular
/// file are read to tell (a pipe is never opened, a device never read). `Ok(true)` when one is
/// there.
///
/// # Errors
/// The name has another extension, the path is a folder or something other than a regular
/// file, what is there cannot be read, or the file there is not ours.
pub fn replaces(path: &Path, language: TestLanguage) -> Result<bool, TargetError> {
    let extension = language.extension();
    let path_buf = || path.to_path_buf();
    if path.extension().and_then(|e| e.to_str()) != Some(extension) {
        let path = path_buf();
        return Err(TargetError::Extension { path, extension });
    }
    if path.is_dir() {
        return Err(TargetError::IsAFolder { path: path_buf() });
    }
    let ours = format!("{} {TESTS_MARK}", language.comment());
    let limit = u64::try_from(ours.len()).unwrap_or(u64::MAX);
    match refraction_files::first_bytes(path, limit) {
        Err(e) => Err(TargetError::Unreadable {
            path: path_buf(),
            reason: e.to_string(),
        }),
        Ok(Some(start)) if start.is_empty() || start == ours.as_bytes() => Ok(true),
        Ok(Some(_)) => Err(TargetError::NotOurs { path: path_buf() }),
        // Nothing there, or something that is not a regular file (which a browser's page
        // never has: its files are the page's own).
        Ok(None) if std::fs::metadata(path).is_ok() => {
            Err(TargetError::NotAFile { path: path_buf() })
        }
        Ok(None) => Ok(false),
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

    #[cfg(unix)]
    #[test]
    fn what_cannot_be_read_or_is_not_a_file_is_refused_without_reading_it() {
        // Issue 40: an unreadable file counted as "nothing there" and was replaced; a FIFO,
        // a link to /dev/zero or a huge file was read whole before deciding.
        let folder = std::env::temp_dir().join(format!("tests-guard-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let cpp = TestLanguage::Any(AnyLanguage::Cpp);
        let fifo = folder.join("fifo.cpp");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        assert_eq!(
            replaces(&fifo, cpp),
            Err(TargetError::NotAFile { path: fifo })
        );
        let zero = folder.join("zero.cpp");
        std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
        assert_eq!(
            replaces(&zero, cpp),
            Err(TargetError::NotAFile { path: zero })
        );
        // A path through a regular file cannot be examined: refused, not taken as empty.
        let file = folder.join("plain.cpp");
        std::fs::write(&file, "int x;\n").unwrap();
        let under = file.join("tests.cpp");
        let e = replaces(&under, cpp).unwrap_err();
        assert!(
            matches!(&e, TargetError::Unreadable { path, .. } if *path == under),
            "{e:?}"
        );
        assert!(e.to_string().contains("cannot be read"), "{e}");
        // A large file of someone else's is refused from its first bytes.
        let large = folder.join("large.cpp");
        let file = std::fs::File::create(&large).unwrap();
        file.set_len(1 << 30).unwrap();
        assert_eq!(
            replaces(&large, cpp),
            Err(TargetError::NotOurs { path: large })
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

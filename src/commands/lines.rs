//! `solve` and `check`: JSON Lines in, one answer per line out.

use std::fs::File;
use std::io::{self, BufRead, Read as _, Write as _};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use refraction_check::tests_file::{self, TestLanguage};
use refraction_check::{Dialect, Format, Options, Pattern, Session, suggest};
use refraction_check::{MAX_SUMMARY_BYTES, Verdict, looks_like_summary};
use refraction_i18n::t;
use refraction_tools::{self as jsonl, LinesError, solve_lines};

use super::{fail, output, output_error};

/// The exit status for a run that stopped early: a read error names `input`.
fn stopped(command: &str, input: &str, error: &LinesError) -> ExitCode {
    match error {
        LinesError::Read(e) => fail(command, &format!("cannot read {input}: {e}")),
        LinesError::Write(e) => output_error(command, e),
    }
}

/// Runs `solve` on stdin.
pub(crate) fn solve() -> ExitCode {
    match solve_lines(io::stdin().lock(), io::stdout().lock()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => stopped("solve", "standard input", &e),
    }
}

/// The exit status of a `check` run that judged no line (nothing matched the pattern, the input
/// was empty or blank, a CSV held only its header): not a pass, so that a typo in a CI job's
/// pattern fails it.
pub(crate) const NOTHING_JUDGED: u8 = 3;

/// The exit status of a `check` run whose lines are right as far as their API's rules go but
/// cannot be told right or wrong (the diagnosis's `unchecked`: no `entering`, no indices): not a
/// pass either, so that a CI job learns that its log checks nothing.
pub(crate) const UNCHECKED: u8 = 4;

/// The log `check` reads: `file`, or stdin when absent, with the name a message gives it.
struct Input {
    lines: Box<dyn BufRead>,
    name: String,
    /// The file read (stdin's, when it has one), to tell a `--summary` path that names it.
    file: Option<File>,
}

impl Input {
    fn open(file: Option<&Path>) -> Result<Self, StartError> {
        let Some(path) = file else {
            return Ok(Self {
                lines: Box::new(io::stdin().lock()),
                name: "standard input".to_owned(),
                file: refraction_files::standard_input(),
            });
        };
        let unreadable = |source| StartError::Read {
            path: path.to_path_buf(),
            source,
        };
        let opened = File::open(path).map_err(unreadable)?;
        Ok(Self {
            lines: Box::new(io::BufReader::new(opened.try_clone().map_err(unreadable)?)),
            name: path.display().to_string(),
            file: Some(opened),
        })
    }
}

/// Whether `--summary` may write at `path`: never over the log being read, and over a file
/// already there only if it is empty or a summary `check` wrote, unless `replace` says so.
fn summary_target(path: &Path, input: &Input, replace: bool) -> Result<(), StartError> {
    refraction_files::check_writable(path).map_err(StartError::Unwritable)?;
    let path_buf = || path.to_path_buf();
    if input
        .file
        .as_ref()
        .is_some_and(|f| refraction_files::names_open_file(path, f))
    {
        return Err(StartError::IsTheLog {
            option: "--summary",
            path: path_buf(),
            log: input.name.clone(),
        });
    }
    // One byte more than a summary may hold: a file that long is not one.
    let start = refraction_files::first_bytes(path, MAX_SUMMARY_BYTES + 1).map_err(|source| {
        StartError::Unreadable {
            path: path_buf(),
            source,
        }
    })?;
    match start {
        Some(bytes) if !replace && !bytes.is_empty() && !looks_like_summary(&bytes) => {
            Err(StartError::NotASummary(path_buf()))
        }
        _ => Ok(()),
    }
}

/// Whether `a` and `b` name the same place: the same path, the same file name in the same
/// folder (however the folder is named), or the same existing regular file under two names.
fn same_place(a: &Path, b: &Path) -> bool {
    let place = |p: &Path| {
        let folder = p
            .parent()
            .filter(|f| !f.as_os_str().is_empty())
            .unwrap_or_else(|| Path::new("."));
        folder
            .canonicalize()
            .ok()
            .zip(p.file_name().map(ToOwned::to_owned))
    };
    // A regular file only: a FIFO would wait for a writer when opened.
    let is_file = std::fs::metadata(a).is_ok_and(|m| m.is_file());
    a == b
        || place(a).is_some_and(|p| Some(p) == place(b))
        || (is_file && File::open(a).is_ok_and(|f| refraction_files::names_open_file(b, &f)))
}

/// Refuses `--tests` naming the log being read or the `--summary` file: one of them would be
/// lost (issue 40).
fn outputs_apart(input: &Input, reading: &Reading<'_>) -> Result<(), StartError> {
    let Some(tests) = reading.tests else {
        return Ok(());
    };
    if let Some(summary) = reading.summary.filter(|s| same_place(s, tests)) {
        return Err(StartError::Twice(summary.to_path_buf()));
    }
    if input
        .file
        .as_ref()
        .is_some_and(|f| refraction_files::names_open_file(tests, f))
    {
        return Err(StartError::IsTheLog {
            option: "--tests",
            path: tests.to_path_buf(),
            log: input.name.clone(),
        });
    }
    Ok(())
}

/// Why `check` cannot start: its log cannot be opened, or its `--summary` or `--tests` file may
/// not be written. Each message names the file, in the command line's English.
#[derive(Debug, thiserror::Error)]
enum StartError {
    /// The log cannot be opened.
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The log.
        path: PathBuf,
        /// Why.
        source: io::Error,
    },
    /// The summary's path cannot be written (its own message names it).
    #[error(transparent)]
    Unwritable(io::Error),
    /// The summary's (or the tests') path is the log being read.
    #[error("cannot write {}: it is the log being read ({log}); give {option} another file", path.display())]
    IsTheLog {
        /// The option that names it: `--summary` or `--tests`.
        option: &'static str,
        /// The summary's path.
        path: PathBuf,
        /// The log's name as messages give it.
        log: String,
    },
    /// What is at the summary's path cannot be read to tell whether it is a summary.
    #[error("cannot write {}: cannot read what is there: {source}", path.display())]
    Unreadable {
        /// The summary's path.
        path: PathBuf,
        /// Why.
        source: io::Error,
    },
    /// The summary's path holds something else, and `--replace` was not given.
    #[error(
        "cannot write {}: it holds something other than a summary of check's; give another \
         file, or add --replace to write over it",
        .0.display()
    )]
    NotASummary(PathBuf),
    /// `--summary` and `--tests` name the same file.
    #[error(
        "--summary and --tests both name {}: one would write over the other; give each its \
         own file",
        .0.display()
    )]
    Twice(PathBuf),
}

/// How `check` reads its lines and what it writes besides the answers.
pub(crate) struct Reading<'a> {
    /// `--pattern`.
    pub pattern: Option<&'a str>,
    /// `--csv`.
    pub csv: bool,
    /// `--strict`.
    pub strict: bool,
    /// `--paths`.
    pub paths: bool,
    /// `--summary`: the file the diagnosis of the whole log goes to.
    pub summary: Option<&'a Path>,
    /// `--replace`: `--summary` may write over a file that is not a summary.
    pub replace: bool,
    /// `--tests`: the file the first failing lines go to, as unit tests.
    pub tests: Option<&'a Path>,
}

/// The language of the tests `--tests` asks for at `path`, if they may be written there; else
/// the failure, said on stderr.
fn tests_language(path: &Path, dialect: Dialect) -> Result<TestLanguage, ExitCode> {
    let Some(language) = TestLanguage::for_path(dialect, path) else {
        let extensions: Vec<&str> = TestLanguage::of(dialect)
            .iter()
            .map(|l| l.extension())
            .collect();
        let (shown, extensions) = (path.display(), extensions.join(" or ."));
        let said =
            format!("--tests {shown}: name a .{extensions} file, the languages of its tests");
        return Err(fail("check", &said));
    };
    match tests_file::replaces(path, language) {
        Ok(_) => Ok(language),
        Err(e) => Err(fail("check", &e)),
    }
}

/// Writes the failing lines `session` kept as tests in `language` at `path`; what it did, for
/// the tally, or the failure, said on stderr.
fn write_tests(session: &Session, language: TestLanguage, path: &Path) -> Result<String, ExitCode> {
    let (failing, shown) = (session.failing(), path.display());
    if failing.is_empty() {
        return Ok(format!("no failing line: {shown} left as it was"));
    }
    let text =
        tests_file::text(language, failing, session.options()).map_err(|e| fail("check", &e))?;
    refraction_files::write_atomically(path, text.as_bytes()).map_err(|e| fail("check", &e))?;
    let count = failing.len();
    let lines = if count == 1 { "line" } else { "lines" };
    Ok(format!(
        "{count} failing {lines} written as tests to {shown}"
    ))
}

/// Refuses `--inside` and `--outside` that no line could be judged with, before a line is
/// read (issue 40: `--inside 1e308` failed every line instead).
fn usable_indices(options: &Options) -> Result<(), ExitCode> {
    options.usable_indices().map_err(|e| {
        let (inside, outside) = options.sides().unwrap_or_default();
        let precision = options.precision_or_usual().name();
        let said = format!(
            "--inside {inside:?} --outside {outside:?}: {e}; in {precision} no line could be judged \
             with them: give the indices of the two media"
        );
        fail("check", &said)
    })
}

/// Runs `check` (with `--api`, in that API's terms) on `file` or stdin: an answer per line on
/// stdout, the tally and the diagnosis of the whole log on stderr, and with `--summary` the
/// diagnosis as JSON in that file.
pub(crate) fn check(file: Option<&Path>, options: &Options, reading: &Reading<'_>) -> ExitCode {
    let format = match (reading.pattern, reading.csv) {
        (Some(text), _) => match Pattern::parse(options.dialect, text) {
            Ok(pattern) => Format::Pattern(pattern),
            Err(e) => return fail("check", &e),
        },
        (None, true) => Format::Csv,
        (None, false) => Format::JsonLines,
    };
    if let Err(status) = usable_indices(options) {
        return status;
    }
    let input = match Input::open(file) {
        Ok(input) => input,
        Err(e) => return fail("check", &e),
    };
    if let Err(e) = outputs_apart(&input, reading) {
        return fail("check", &e);
    }
    if let Some(path) = reading.summary
        && let Err(e) = summary_target(path, &input, reading.replace)
    {
        return fail("check", &e);
    }
    let tests = match reading.tests {
        Some(path) => match tests_language(path, options.dialect) {
            Ok(language) => Some((path, language)),
            Err(status) => return status,
        },
        None => None,
    };
    let (lines, name) = (input.lines, input.name);
    let mut session = Session::new(*options, format, reading.strict, reading.paths);
    if tests.is_some() {
        session.keep_failing();
    }
    let mut output = io::stdout().lock();
    let result = session
        .run(lines, &mut output, jsonl::threads())
        .and_then(|answered| {
            if let Some(summary) = session.finish() {
                writeln!(output, "{summary}").map_err(LinesError::Write)?;
                output.flush().map_err(LinesError::Write)?;
            }
            Ok(answered)
        });
    let answered = match result {
        Ok(answered) => answered,
        Err(e) => return stopped("check", &name, &e),
    };
    let summary = session.summary();
    if let Some(path) = reading.summary {
        let json = format!("{}\n", refraction_tools::json_line(&summary));
        if let Err(e) = refraction_files::write_atomically(path, json.as_bytes()) {
            return fail("check", &e);
        }
    }
    let counted = session.tally().summary();
    let mut tally: Vec<String> = Vec::new();
    if !counted.is_empty() {
        tally.push(format!("check: {counted}"));
    }
    tally.extend(summary.sentences().iter().map(|s| format!("check: {s}")));
    if let Some((path, language)) = tests {
        match write_tests(&session, language, path) {
            Ok(said) => tally.push(format!("check: {said}")),
            Err(status) => return status,
        }
    }
    let status = match summary.verdict() {
        Verdict::NothingJudged => ExitCode::from(NOTHING_JUDGED),
        _ if !answered || !session.all_ok() => ExitCode::from(1),
        Verdict::Mistake | Verdict::Unreadable => ExitCode::from(1),
        Verdict::Unchecked => ExitCode::from(UNCHECKED),
        Verdict::None => ExitCode::SUCCESS,
    };
    finished(&tally.join("\n"), status)
}

/// The exit status of a `check` run that read all its input: the tally goes to stderr (losing
/// it is a failure, status 2), then `status`.
fn finished(tally: &str, status: ExitCode) -> ExitCode {
    if output::to_stderr(tally).is_err() {
        // The tally is part of check's output: losing it is a failure.
        ExitCode::from(2)
    } else {
        status
    }
}

/// `text` as one shell word: as it is when it holds only characters no shell treats
/// specially, else in single quotes (a quote inside written `'\''`).
fn shell_word(text: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-+./,:=@%".contains(c);
    if !text.is_empty() && text.chars().all(plain) {
        text.to_owned()
    } else {
        format!("'{}'", text.replace('\'', "'\\''"))
    }
}

/// The command that reads the log with `suggestion`, with every option given beside
/// `--suggest-pattern` carried into it (none is dropped in silence).
fn suggested_command(
    file: Option<&Path>,
    options: &Options,
    reading: &Reading<'_>,
    suggestion: &suggest::Suggestion,
    with_pattern: bool,
) -> String {
    let mut words = vec!["refraction-explorer".to_owned(), "check".to_owned()];
    let mut add = |option: &str, value: Option<String>| {
        words.push(option.to_owned());
        words.extend(value);
    };
    if let Some(api) = options.dialect.api() {
        add("--api", Some(api.name().to_owned()));
    }
    if let (Some(inside), Some(outside)) = (options.inside, options.outside) {
        add("--inside", Some(inside.to_string()));
        add("--outside", Some(outside.to_string()));
    } else if let Some(inside) = &suggestion.inside {
        // The lines print `entering` and a ratio: the indices it gives save a round trip.
        add("--inside", Some(inside.clone()));
        add("--outside", Some("1".to_owned()));
    }
    if let Some(precision) = options.precision {
        add("--precision", Some(precision.name().to_owned()));
    }
    if let Some(renderer) = options.renderer {
        add("--renderer", Some(renderer.name().to_owned()));
    }
    if with_pattern {
        // Always quoted, as a pattern's words and braces read best.
        let pattern = format!("'{}'", suggestion.pattern.replace('\'', "'\\''"));
        add("--pattern", Some(pattern));
    }
    match options.convention {
        Some(convention) => add("--convention", Some(convention_name(convention).to_owned())),
        None if suggestion.toward_origin => add("--convention", Some("toward-origin".to_owned())),
        None => {}
    }
    if let Some(normal) = options.normal {
        add(
            "--normal",
            Some(shell_word(&normal.map(|c| c.to_string()).join(" "))),
        );
    }
    let path = |p: &Path| Some(shell_word(&p.display().to_string()));
    if let Some(summary) = reading.summary {
        add("--summary", path(summary));
    }
    if reading.replace {
        add("--replace", None);
    }
    if let Some(tests) = reading.tests {
        add("--tests", path(tests));
    }
    if let Some(file) = file {
        words.extend(path(file));
    }
    words.join(" ")
}

/// The name `--convention` takes for `convention`.
fn convention_name(convention: refraction_kernel::Convention) -> &'static str {
    match convention {
        refraction_kernel::Convention::AlongRay => "along-ray",
        refraction_kernel::Convention::TowardOrigin => "toward-origin",
    }
}

/// Runs `check --suggest-pattern` on `file` or stdin: the command with the pattern guessed
/// from the log's first lines (and every other option given) on stdout, what else it needs on
/// stderr; status 3 when no line looks like a refraction.
pub(crate) fn suggest_pattern(
    file: Option<&Path>,
    options: &Options,
    reading: &Reading<'_>,
) -> ExitCode {
    let dialect = options.dialect;
    let input = match Input::open(file) {
        Ok(input) => input,
        Err(e) => return fail("check", &e),
    };
    // The first lines, within 8 MiB (a line of another encoding read as it can be).
    let mut reader = input.lines.take(8 << 20);
    let mut lines = Vec::new();
    let mut bytes = Vec::new();
    while lines.len() < suggest::LINES_READ {
        bytes.clear();
        match reader.read_until(b'\n', &mut bytes) {
            Ok(0) => break,
            Ok(_) => lines.push(String::from_utf8_lossy(&bytes).trim_end().to_owned()),
            Err(e) => return fail("check", &format!("cannot read {}: {e}", input.name)),
        }
    }
    let texts: Vec<&str> = lines.iter().map(String::as_str).collect();
    let json_lines = texts
        .iter()
        .find(|l| !l.trim().is_empty())
        .is_some_and(|l| {
            serde_json::from_str::<serde_json::Map<String, serde_json::Value>>(l).is_ok()
        });
    if json_lines {
        // JSON Lines name their fields: the command without a pattern reads them.
        let plain = suggest::Suggestion::default();
        let command = suggested_command(file, options, reading, &plain, false);
        if let Err(e) = writeln!(io::stdout().lock(), "{command}") {
            return output_error("check", &e);
        }
        let said = t!("check-suggest-json-lines");
        return finished(&format!("check: {said}"), ExitCode::SUCCESS);
    }
    let Some(mut suggestion) = suggest::suggest(dialect, &texts) else {
        let message = if suggest::column_printed(&texts) {
            t!("check-suggest-column-vectors", lines = texts.len())
        } else {
            t!("check-suggest-none", lines = texts.len())
        };
        return finished(&format!("check: {message}"), ExitCode::from(NOTHING_JUDGED));
    };
    // Indices given are not guessed.
    if options.inside.is_some() || options.outside.is_some() {
        suggestion.inside = None;
    }
    let command = suggested_command(file, options, reading, &suggestion, true);
    if let Err(e) = writeln!(io::stdout().lock(), "{command}") {
        return output_error("check", &e);
    }
    // What the options given already say is not asked for again.
    suggestion.no_normal &= options.normal.is_none();
    let hints: Vec<String> = suggest::hints(&suggestion, dialect)
        .into_iter()
        .map(|h| format!("check: {h}"))
        .collect();
    if hints.is_empty() {
        return ExitCode::SUCCESS;
    }
    finished(&hints.join("\n"), ExitCode::SUCCESS)
}

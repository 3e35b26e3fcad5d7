//! `solve` and `check`: JSON Lines in, one answer per line out.

use std::io::{self, BufRead, Write as _};
use std::path::Path;
use std::process::ExitCode;

use refraction_tools::api_check::{Format, Options, Pattern, Session};
use refraction_tools::{self as jsonl, LinesError, solve as solver};

use super::{fail, output, output_error};

/// The exit status for a run that stopped early: a read error names `input`.
fn stopped(command: &str, input: &str, error: &LinesError) -> ExitCode {
    match error {
        LinesError::Read(e) => fail(command, &format!("cannot read {input}: {e}")),
        LinesError::Write(e) => output_error(command, e),
    }
}

/// Runs `solve` on stdin.
pub fn solve() -> ExitCode {
    match solver::run(io::stdin().lock(), io::stdout().lock()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => stopped("solve", "standard input", &e),
    }
}

/// `file`, or stdin when absent, with the name a message gives it.
fn open_input(file: Option<&Path>) -> Result<(Box<dyn BufRead>, String), ExitCode> {
    match file {
        None => Ok((Box::new(io::stdin().lock()), "standard input".to_owned())),
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => Ok((Box::new(io::BufReader::new(f)), path.display().to_string())),
            Err(e) => Err(fail(
                "check",
                &format!("cannot read {}: {e}", path.display()),
            )),
        },
    }
}

/// How `check` reads its lines and what it writes besides the answers.
pub struct Reading<'a> {
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
}

/// Runs `check` (with `--api`, in that API's terms) on `file` or stdin: an answer per line on
/// stdout, the tally and the diagnosis of the whole log on stderr, and with `--summary` the
/// diagnosis as JSON in that file.
pub fn check(file: Option<&Path>, options: &Options, reading: &Reading<'_>) -> ExitCode {
    let format = match (reading.pattern, reading.csv) {
        (Some(text), _) => match Pattern::parse(options.dialect, text) {
            Ok(pattern) => Format::Pattern(pattern),
            Err(e) => return fail("check", &e),
        },
        (None, true) => Format::Csv,
        (None, false) => Format::JsonLines,
    };
    if let Some(path) = reading.summary
        && let Err(e) = refraction_files::check_writable(path)
    {
        return fail("check", &format!("cannot write {}: {e}", path.display()));
    }
    let (input, name) = match open_input(file) {
        Ok(input) => input,
        Err(code) => return code,
    };
    let mut session = Session::new(*options, format, reading.strict, reading.paths);
    let mut output = io::stdout().lock();
    let result = session
        .run(input, &mut output, jsonl::threads())
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
        let json = format!("{}\n", serde_json::json!(summary));
        if let Err(e) = refraction_files::write_atomically(path, json.as_bytes()) {
            return fail("check", &format!("cannot write {}: {e}", path.display()));
        }
    }
    let mut tally = format!("check: {}", session.tally().summary());
    for sentence in summary.sentences() {
        tally = format!("{tally}\ncheck: {sentence}");
    }
    finished(&tally, answered && session.all_ok())
}

/// The exit status of a `check` run that read all its input: the tally goes to stderr (losing
/// it is a failure, status 2), then status 0 if `all_ok` and 1 if not.
fn finished(tally: &str, all_ok: bool) -> ExitCode {
    if output::to_stderr(tally).is_err() {
        // The tally is part of check's output: losing it is a failure.
        ExitCode::from(2)
    } else if all_ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

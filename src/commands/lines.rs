//! `solve` and `check`: JSON Lines in, one answer per line out.

use std::collections::BTreeMap;
use std::io::{self, BufRead};
use std::path::Path;
use std::process::ExitCode;

use refraction_explorer::lines::check::{self, Match};
use refraction_explorer::lines::{self as jsonl, LinesError, solve as solver};

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

/// Runs `check` on `file` or stdin, with a tally of the mistakes on stderr.
pub fn check(file: Option<&Path>) -> ExitCode {
    let (input, name): (Box<dyn BufRead>, String) = match file {
        None => (Box::new(io::stdin().lock()), "standard input".to_owned()),
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => (Box::new(io::BufReader::new(f)), path.display().to_string()),
            Err(e) => return fail("check", &format!("cannot read {}: {e}", path.display())),
        },
    };
    let mut tally: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut all_ok = true;
    let result = jsonl::answer_lines(input, io::stdout().lock(), |line| {
        let (kind, reply) = match check::answer(line) {
            Ok((text, verdict)) => {
                all_ok &= verdict.ok;
                let kind = match (verdict.ok, verdict.matches) {
                    (true, _) => "ok",
                    (false, Some(Match::Chosen)) => "not unit length",
                    (false, Some(m)) => m.name(),
                    (false, None) => "matching no candidate",
                };
                (kind, Ok(text))
            }
            Err(e) => ("unreadable", Err(e)),
        };
        *tally.entry(kind).or_default() += 1;
        reply
    });
    match result {
        Ok(answered) => {
            let summary: Vec<String> = tally.iter().map(|(k, n)| format!("{n} {k}")).collect();
            if output::to_stderr(&format!("check: {}", summary.join(", "))).is_err() {
                // The summary is part of check's output: losing it is a failure.
                ExitCode::from(2)
            } else if answered && all_ok {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) => stopped("check", &name, &e),
    }
}

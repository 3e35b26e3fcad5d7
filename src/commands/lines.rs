//! `solve` and `check`: JSON Lines in, one answer per line out.

use std::collections::BTreeMap;
use std::io::{self, BufRead};
use std::path::Path;
use std::process::ExitCode;

use refraction_explorer::lines::check::{self, Match};
use refraction_explorer::lines::{self as jsonl, solve as solver};

use super::{fail, output_error};

/// Runs `solve` on stdin.
pub fn solve() -> ExitCode {
    match solver::run(io::stdin().lock(), io::stdout().lock()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => output_error("solve", &e),
    }
}

/// Runs `check` on `file` or stdin, with a tally of the mistakes on stderr.
pub fn check(file: Option<&Path>) -> ExitCode {
    let input: Box<dyn BufRead> = match file {
        None => Box::new(io::stdin().lock()),
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => Box::new(io::BufReader::new(f)),
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
            eprintln!("check: {}", summary.join(", "));
            if answered && all_ok {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) => output_error("check", &e),
    }
}

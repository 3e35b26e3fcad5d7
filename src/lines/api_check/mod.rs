//! `check --api NAME`: a student's call checked in their own API's conventions. Each line
//! carries the API's own argument names and what came back (see [`fields`]), with optional
//! truth (`from`, `to`, `travel`, `entering`); the answer says whether the call is right, which
//! mistakes explain what came back ([`Code`]), what the API returns for these arguments and the
//! physically right T.
//!
//! The diagnosis tries every combination of the argument mistakes (`eta_inverted`,
//! `incident_reversed`, `normal_not_facing`, `not_unit_input`) against the API's contract and
//! the truth, keeps the fewest that fit (all of them when several fit equally, the likeliest
//! first), and compares what came back with what the API returns for the arguments as logged
//! (`not_the_api_result`, `missed_tir`), within the rounding of the logged digits.
//!
//! For the explorer: [`Record::from_texts`] reads the API's fields from text, [`Call::from_record`]
//! makes the call, [`diagnose()`] judges it; [`fields::names`] gives each API's field names.

pub mod call;
pub mod code;
pub mod csv;
pub mod diagnose;
mod explain;
pub mod fields;
pub mod paths;
pub mod pattern;
pub mod readings;
pub mod record;
pub mod result;

use std::collections::BTreeMap;

use serde::Serialize;

pub use call::{Call, Options};
pub use code::Code;
pub use diagnose::{Diagnosis, diagnose};
pub use pattern::Pattern;
pub use record::Record;

use crate::lines::check::{self, Match};

/// The JSON answer for one call.
#[derive(Serialize)]
struct Answer<'a> {
    #[serde(flatten)]
    verdict: check::Answer<'a>,
    api_result: &'a serde_json::Value,
    mistakes: Vec<&'static str>,
    alternatives: Vec<Vec<&'static str>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    path: Option<&'a str>,
}

/// The answer line for a judged call.
#[must_use]
pub fn answer_line(call: &Call, diagnosis: &Diagnosis) -> String {
    let names = |codes: &[Code]| codes.iter().map(|c| c.name()).collect::<Vec<_>>();
    let answer = Answer {
        verdict: check::Answer {
            ok: diagnosis.ok,
            matches: diagnosis.matches.map(Match::name),
            explanation: &diagnosis.explanation,
            t: diagnosis.t,
        },
        api_result: &diagnosis.api_result,
        mistakes: names(&diagnosis.mistakes),
        alternatives: diagnosis.alternatives.iter().map(|a| names(a)).collect(),
        path: call.path.as_deref(),
    };
    // Serialising this struct of plain fields cannot fail; a map key is never non-string.
    serde_json::to_string(&answer).unwrap_or_default()
}

/// Judges one record.
///
/// # Errors
/// The record is not a complete call (see [`Call::from_record`]) or does not fit the precision.
pub fn check_record(record: &Record, options: &Options) -> Result<(Call, Diagnosis), String> {
    let call = Call::from_record(record, options)?;
    let diagnosis = diagnose(&call)?;
    Ok((call, diagnosis))
}

/// Counts of verdicts by mistake, for the summary on stderr.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    counts: BTreeMap<&'static str, usize>,
}

impl Tally {
    /// Counts one more `kind`.
    pub fn add(&mut self, kind: &'static str) {
        *self.counts.entry(kind).or_default() += 1;
    }

    /// Counts a verdict: `ok`, or each mistake of its likeliest explanation (`unexplained`
    /// when none fits).
    pub fn add_verdict(&mut self, diagnosis: &Diagnosis) {
        match diagnosis.alternatives.first() {
            _ if diagnosis.ok => self.add("ok"),
            Some(codes) => codes.iter().for_each(|c| self.add(c.name())),
            None => self.add("unexplained"),
        }
    }

    /// `2 ok, 1 eta_inverted, ...`.
    #[must_use]
    pub fn summary(&self) -> String {
        let parts: Vec<String> = self
            .counts
            .iter()
            .map(|(k, n)| format!("{n} {k}"))
            .collect();
        parts.join(", ")
    }
}

/// How the lines are written.
#[derive(Clone, Debug, PartialEq)]
pub enum Format {
    /// One JSON object per line (the default).
    JsonLines,
    /// printf-style lines read with a `--pattern`.
    Pattern(Pattern),
    /// CSV with a header line naming the fields.
    Csv,
}

/// The tally's name for log lines that did not match the pattern.
const SKIPPED: &str = "skipped (not matching the pattern)";

/// One run of `check --api`: lines in, answer lines out, the tally kept.
#[derive(Debug)]
pub struct Session {
    options: Options,
    format: Format,
    strict: bool,
    header: Option<Result<csv::Header, String>>,
    paths: Option<paths::Paths>,
    /// The verdicts so far.
    pub tally: Tally,
    all_ok: bool,
}

impl Session {
    /// A run for `options` reading lines in `format`; with `strict`, a line that does not match
    /// the pattern is an error instead of skipped; with `paths`, a summary follows each path.
    #[must_use]
    pub fn new(options: Options, format: Format, strict: bool, paths: bool) -> Self {
        Self {
            options,
            format,
            strict,
            header: None,
            paths: paths.then(paths::Paths::new),
            tally: Tally::default(),
            all_ok: true,
        }
    }

    /// The record on one line, or `None` for a line that carries none (a CSV header, a log
    /// line the pattern does not match, counted as skipped). The explorer's pasted logs read
    /// their lines through it, so that they and the command agree.
    ///
    /// # Errors
    /// The line is not a record of the API's fields (the message says why), a log line does
    /// not match the pattern under `strict`, or the CSV header was unusable.
    pub fn record(&mut self, line: &str) -> Result<Option<Record>, String> {
        let api = self.options.api;
        match &self.format {
            Format::JsonLines => Record::from_json_line(api, line).map(Some),
            Format::Pattern(pattern) => match pattern.capture(line) {
                Some(texts) => Record::from_texts(api, texts).map(Some),
                None if self.strict => Err("the line does not match the pattern".to_owned()),
                None => {
                    self.tally.add(SKIPPED);
                    Ok(None)
                }
            },
            Format::Csv => match &self.header {
                None => {
                    let header = csv::Header::parse(api, line);
                    let reply = header.as_ref().map(|_| None).map_err(Clone::clone);
                    self.header = Some(header);
                    reply
                }
                Some(Ok(header)) => header.record(line).map(Some),
                Some(Err(e)) => Err(format!("no usable CSV header: {e}")),
            },
        }
    }

    /// Answers one line: a JSON answer, or nothing for a line without a call.
    ///
    /// # Errors
    /// Why the line cannot be judged; the loop answers it with `{"line", "error"}`.
    pub fn answer(&mut self, line: &str) -> Result<String, String> {
        let judged = match self.record(line) {
            Ok(None) => return Ok(String::new()),
            Ok(Some(record)) => check_record(&record, &self.options),
            Err(e) => Err(e),
        };
        let ended = match (&judged, &mut self.paths) {
            (Ok((call, diagnosis)), Some(paths)) => paths.hit(call, diagnosis),
            _ => Ok(None),
        };
        match judged.and_then(|judged| ended.map(|ended| (judged, ended))) {
            Ok(((call, diagnosis), ended)) => {
                self.tally.add_verdict(&diagnosis);
                self.all_ok &= diagnosis.ok;
                let text = answer_line(&call, &diagnosis);
                Ok(ended.map_or(text.clone(), |summary| format!("{summary}\n{text}")))
            }
            Err(e) => {
                self.tally.add("unreadable");
                self.all_ok = false;
                Err(e)
            }
        }
    }

    /// The summary of the last path (with `--paths`), once the input has ended.
    pub fn finish(&mut self) -> Option<String> {
        self.paths.as_mut().and_then(paths::Paths::finish)
    }

    /// Whether every line so far was right and every path finished left right.
    #[must_use]
    pub fn all_ok(&self) -> bool {
        self.all_ok && self.paths.as_ref().is_none_or(|p| p.all_exit_ok)
    }
}

#[cfg(test)]
mod tests;

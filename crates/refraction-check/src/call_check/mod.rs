//! One call, read in its own dialect ([`Dialect`]): an API's (`check --api NAME`) or physics'
//! (`check` without `--api`, any renderer's own refraction, in [`physics`]). A line is read
//! from JSON, a `--pattern` log or CSV into a [`Record`], judged on its own (a [`Judgement`]:
//! for an API's call, its [`verdict()`]), and counted toward the diagnosis of the whole log
//! ([`crate::diagnosis`], which names the one mistake behind all the wrong lines). Which of the
//! four candidates a T is comes from [`refraction_tools::check_t`].
//!
//! In an API's dialect, each line carries the API's own argument names and what came back (see
//! [`fields`]), with optional truth (`from`, `to`, `travel`, `entering`); the answer says
//! whether the call is right, which mistakes explain what came back ([`Code`]), what the API
//! returns for these arguments and the physically right T.
//!
//! The verdict on a call tries every combination of the argument mistakes (`eta_inverted`,
//! `incident_reversed`, `normal_not_facing`, `not_unit_input`) against the API's contract and
//! the truth, keeps the fewest that fit (all of them when several fit equally, the likeliest
//! first), and compares what came back with what the API returns for the arguments as logged
//! (`not_the_api_result`, `missed_tir`), within the rounding of the logged digits.
//!
//! For the explorer: [`Record::from_texts`] reads the API's fields from text, [`Call::from_record`]
//! makes the call, [`verdict()`] judges it; [`fields::names`] gives each API's field names.

pub(crate) mod call;
pub(crate) mod csv;
pub(crate) mod error;
mod explain;
pub mod fields;
pub(crate) mod gather;
pub(crate) mod limits;
pub(crate) mod paths;
pub(crate) mod pattern;
pub(crate) mod physics;
pub(crate) mod readings;
pub(crate) mod record;
pub(crate) mod result;
pub mod suggest;
pub(crate) mod verdict;

use std::collections::BTreeMap;

use serde::Serialize;

pub(crate) use crate::diagnosis::Code;
pub use call::{Call, Options};
pub use error::{CsvError, LineError, PatternError};
pub use fields::Dialect;
pub(crate) use pattern::Pattern;
pub use record::Record;
pub(crate) use verdict::{CallVerdict, verdict};

use crate::diagnosis::{Evidence, LogTally, Renderer, Summary};
use gather::Gather;
use refraction_kernel::api::Api;
use refraction_tools::{CheckAnswer, Match};

/// The JSON answer for one call.
#[derive(Serialize)]
struct Answer<'a> {
    #[serde(flatten)]
    verdict: CheckAnswer<'a>,
    api_result: &'a serde_json::Value,
    mistakes: Vec<&'static str>,
    alternatives: Vec<Vec<&'static str>>,
    // untranslated: serde's path of a function
    #[serde(skip_serializing_if = "Option::is_none")]
    path: Option<&'a str>,
}

/// The answer line for a judged call.
#[must_use]
pub(crate) fn answer_line(call: &Call, verdict: &CallVerdict) -> String {
    let names = |codes: &[Code]| codes.iter().map(|c| c.name()).collect::<Vec<_>>();
    let answer = Answer {
        verdict: CheckAnswer {
            ok: verdict.ok,
            matches: verdict.matches.map(Match::name),
            explanation: &verdict.explanation,
            t: verdict.t,
        },
        api_result: &verdict.api_result,
        mistakes: names(&verdict.mistakes),
        alternatives: verdict.alternatives.iter().map(|a| names(a)).collect(),
        path: call.path.as_deref(),
    };
    refraction_tools::json_line(&answer)
}

/// Judges one record.
///
/// # Errors
/// The record is not a complete call (see [`Call::from_record`]) or does not fit the precision.
pub fn check_record(record: &Record, options: &Options) -> Result<(Call, CallVerdict), LineError> {
    let call = Call::from_record(record, options)?;
    let verdict = verdict(&call)?;
    Ok((call, verdict))
}

/// The most failing lines a session keeps to be written as tests (a test file holds no more).
pub const MAX_TESTS: usize = 100;

/// A failing line, kept to be written as a test.
#[derive(Clone, Debug)]
pub struct Failing {
    /// Its line number in the log, from 1.
    pub line: usize,
    /// The call read.
    pub record: Record,
    /// Its verdict.
    pub judgement: Judgement,
}

/// Counts of verdicts by mistake, for the summary on stderr.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    counts: BTreeMap<String, usize>,
}

/// The tally's name for a line whose explanations tie: each explanation's codes joined by
/// `+`, the explanations by `|` (`eta_inverted|normal_not_facing`): one bug, which the line
/// alone cannot name.
// untranslated: the tally's codes, as `check` prints them on stderr
fn tied(alternatives: &[Vec<Code>]) -> String {
    let names: Vec<String> = alternatives
        .iter()
        .map(|codes| codes.iter().map(|c| c.name()).collect::<Vec<_>>().join("+"))
        .collect();
    names.join("|")
}

/// The tally's kind of a call's verdict: `ok`, a sampled reflection, or the line's
/// explanations as one kind, ties joined (`unexplained` when none fits).
fn verdict_kind(verdict: &CallVerdict) -> String {
    if verdict.ok && verdict.sampled.is_some() {
        SAMPLED.to_owned()
    } else if verdict.ok {
        "ok".to_owned()
    } else if verdict.undecided {
        UNDECIDED.to_owned()
    } else if verdict.alternatives.is_empty() {
        "unexplained".to_owned()
    } else {
        tied(&verdict.alternatives)
    }
}

impl Tally {
    /// Counts one more `kind`.
    pub fn add(&mut self, kind: &str) {
        match self.counts.get_mut(kind) {
            Some(count) => *count += 1,
            None => {
                self.counts.insert(kind.to_owned(), 1);
            }
        }
    }

    /// Counts a verdict: `ok`, a sampled reflection, or the line's explanations as one kind,
    /// ties joined (`unexplained` when none fits).
    pub fn add_verdict(&mut self, verdict: &CallVerdict) {
        self.add(&verdict_kind(verdict));
    }

    /// Each kind counted and its count, in the summary's order.
    pub fn counts(&self) -> impl Iterator<Item = (&str, usize)> + '_ {
        self.counts.iter().map(|(kind, n)| (kind.as_str(), *n))
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
// untranslated: the tally's name, as `check` prints it on stderr (the panel says it in words)
pub const SKIPPED: &str = "skipped (not matching the pattern)";

/// The tally's name for lines that logged nothing where the ray refracts, read as sampled
/// reflections (the diagnosis of the whole log checks that they are).
// untranslated: the tally's name, as `check` prints it on stderr (the panel says it in words)
pub const SAMPLED: &str = "reflected (sampled)";

/// The tally's name for calls whose printed digits cannot tell them right or wrong.
// untranslated: the tally's name, as `check` prints it on stderr (the code of the log's finding)
pub const UNDECIDED: &str = "too_few_digits";

/// A judged line: an API call and its [`CallVerdict`], or any renderer's refraction and its
/// verdict.
#[derive(Clone, Debug)]
pub enum Judgement {
    /// A call of a named API (boxed: a verdict is large).
    Api(Box<(Call, CallVerdict)>),
    /// Any renderer's own refraction (`check` without `--api`; boxed as the call is).
    Physics(Box<physics::Judged>),
}

impl Judgement {
    /// Whether the line is right.
    #[must_use]
    pub fn ok(&self) -> bool {
        match self {
            Self::Api(judged) => judged.1.ok,
            Self::Physics(judged) => judged.verdict.ok,
        }
    }

    /// Whether the line is wrong: not right, and not a call its printed digits cannot tell
    /// right or wrong.
    #[must_use]
    pub fn fails(&self) -> bool {
        match self {
            Self::Api(judged) => !judged.1.ok && !judged.1.undecided,
            Self::Physics(judged) => {
                !judged.verdict.ok
                    && judged.evidence.unchecked != Some(crate::diagnosis::Missing::Digits)
            }
        }
    }

    /// The answer line.
    #[must_use]
    pub fn answer_line(&self) -> String {
        match self {
            Self::Api(judged) => answer_line(&judged.0, &judged.1),
            Self::Physics(judged) => physics::answer_line(judged),
        }
    }

    /// What the diagnosis of the whole log needs from the line.
    #[must_use]
    pub fn evidence(&self) -> Evidence {
        match self {
            Self::Api(judged) => verdict::evidence(&judged.0, &judged.1),
            Self::Physics(judged) => judged.evidence(),
        }
    }

    /// Every mistake that explains the line, each once, the likeliest first (empty when the
    /// line is right, or when nothing explains it).
    #[must_use]
    pub fn mistakes(&self) -> Vec<Code> {
        match self {
            Self::Api(judged) => judged.1.mistakes.clone(),
            Self::Physics(judged) => judged.mistakes(),
        }
    }

    /// What happened on the line, in a sentence or two.
    #[must_use]
    pub fn explanation(&self) -> &str {
        match self {
            Self::Api(judged) => &judged.1.explanation,
            Self::Physics(judged) => &judged.verdict.explanation,
        }
    }

    /// The line on the log's failure map.
    #[must_use]
    pub fn point(&self) -> refraction_model::log_map::LinePoint {
        match self {
            Self::Api(judged) => verdict::point(&judged.0, &judged.1),
            Self::Physics(judged) => judged.point,
        }
    }

    /// The line's kind as the tally on stderr counts it: for a call `ok`, `reflected
    /// (sampled)`, its explanations (ties joined by `|`) or `unexplained`; for any renderer's
    /// refraction `ok`, the candidate it is (`wrong_side`...) or what else went wrong.
    #[must_use]
    pub fn kind(&self) -> String {
        match self {
            Self::Api(judged) => verdict_kind(&judged.1),
            Self::Physics(judged) => physics::tally_kind(judged).to_owned(),
        }
    }

    /// Counts the line in `tally`.
    fn count(&self, tally: &mut Tally) {
        tally.add(&self.kind());
    }
}

/// Judges one record in `options`' dialect.
///
/// # Errors
/// The record is not a complete call or case, or does not fit the precision.
pub fn judge_record(record: &Record, options: &Options) -> Result<Judgement, LineError> {
    match options.dialect {
        Dialect::Api(_) => check_record(record, options).map(|j| Judgement::Api(Box::new(j))),
        Dialect::Physics => physics::Case::from_record(record, options)
            .and_then(|case| physics::judge(&case))
            .map(|judged| Judgement::Physics(Box::new(judged))),
    }
}

/// A line's record and its judgement, or why it has none.
type JudgedLine = Result<(Record, Judgement), LineError>;

/// What a line holds, as far as it can be judged without the run's state (on any thread).
enum Judged {
    /// A judged line and the record it was read as, or why the line holds nothing that can be
    /// judged (boxed: a judgement is large, and the chunks hold many of the other kinds).
    Line(Box<JudgedLine>),
    /// A log line the pattern does not match on its own: it may be part of a record printed
    /// over several lines, gathered in order.
    Unmatched(String),
    /// A CSV line read before the header was known: read in order, with the run's state.
    Deferred(String),
}

/// How a run reads and judges its lines: everything about it that does not change once the
/// CSV header is known, so that lines can be judged on several threads.
#[derive(Debug)]
struct Reader {
    options: Options,
    format: Format,
    strict: bool,
    header: std::sync::OnceLock<Result<csv::Header, CsvError>>,
    /// Whether a line printed a vector as Rust's glam prints one (`Vec3(x, y, z)`, `{:?}`):
    /// the code is Rust on glam, whose fixes are in glam's words.
    glam: core::sync::atomic::AtomicBool,
}

/// What one line holds before it is judged.
enum Read {
    /// The fields of a call, or why the line holds none that can be read.
    Record(Result<Record, LineError>),
    /// A log line the pattern does not match.
    Unmatched,
    /// A CSV line read before the header was known.
    Deferred,
}

impl Reader {
    /// Reads one line's fields, as far as that can be done without the run's state.
    fn read(&self, line: &str) -> Read {
        let dialect = self.options.dialect;
        // untranslated: glam's Debug output, `Vec3(x, y, z)` (DVec3, Vec3A alike)
        if line.contains("Vec3(") || line.contains("Vec3A(") {
            self.glam.store(true, core::sync::atomic::Ordering::Relaxed);
        }
        Read::Record(match &self.format {
            Format::JsonLines => Record::from_json_line(dialect, line),
            Format::Pattern(pattern) => match pattern.capture(line) {
                Some(texts) => Record::from_texts(dialect, texts).map(|mut record| {
                    pattern.negated().for_each(|name| record.negate(name));
                    record
                }),
                None => return Read::Unmatched,
            },
            Format::Csv => match self.header.get() {
                None => return Read::Deferred,
                Some(Ok(header)) => header.record(line),
                Some(Err(e)) => Err(LineError::NoHeader(e.clone())),
            },
        })
    }

    /// Judges one line, or leaves it for [`Books::settle`] when it needs the run's state.
    fn judge(&self, line: &str) -> Judged {
        match self.read(line) {
            Read::Record(record) => Judged::Line(Box::new(record.and_then(|record| {
                judge_record(&record, &self.options).map(|judged| (record, judged))
            }))),
            Read::Unmatched => Judged::Unmatched(line.to_owned()),
            Read::Deferred => Judged::Deferred(line.to_owned()),
        }
    }

    /// Takes `line` as the CSV header (called in order, while none is known); why it is
    /// unusable, if it is.
    fn take_header(&self, line: &str) -> Option<LineError> {
        let header = csv::Header::parse(self.options.dialect, line);
        let failed = header.as_ref().err().cloned().map(LineError::Csv);
        // Only this thread sets the header, between chunks: it cannot be set already.
        self.header.set(header).ok();
        failed
    }

    /// A CSV line read in order: the header if none is known yet, else a record to judge.
    fn judge_in_order(&self, line: &str) -> Option<Judged> {
        if self.header.get().is_none() {
            return self
                .take_header(line)
                .map(|e| Judged::Line(Box::new(Err(e))));
        }
        Some(self.judge(line))
    }
}

/// What a run keeps as it goes: the paths followed, the tally, whether all was right, the
/// counts the diagnosis of the whole log is made from, and the first failing lines if asked.
#[derive(Debug)]
struct Books {
    paths: Option<paths::Paths>,
    /// Lines gathered toward a record printed over several lines (a `--pattern` log).
    gather: Option<Gather>,
    tally: Tally,
    all_ok: bool,
    log: LogTally,
    /// The first [`MAX_TESTS`] failing lines, when kept.
    failing: Option<Vec<Failing>>,
}

impl Books {
    /// The answer to a judged line `number`, in input order: nothing for a line without a call.
    fn answer(
        &mut self,
        reader: &Reader,
        number: usize,
        judged: Judged,
    ) -> Result<String, LineError> {
        let judged = match judged {
            Judged::Line(judged) => {
                self.forget_gathered();
                *judged
            }
            Judged::Unmatched(line) => match self.gathered(reader, &line)? {
                Some(judged) => judged,
                None => return Ok(String::new()),
            },
            Judged::Deferred(line) => match reader.judge_in_order(&line) {
                None => return Ok(String::new()),
                Some(judged) => return self.answer(reader, number, judged),
            },
        };
        let ended = match (&judged, &mut self.paths) {
            (Ok((_, Judgement::Api(judged))), Some(paths)) => paths.hit(&judged.0, &judged.1),
            _ => Ok(None),
        };
        match judged.and_then(|judged| ended.map(|ended| (judged, ended))) {
            Ok(((record, judgement), ended)) => {
                self.count(&judgement);
                self.keep(number, record, &judgement);
                let text = judgement.answer_line();
                Ok(ended.map_or_else(|| text.clone(), |summary| format!("{summary}\n{text}")))
            }
            Err(e) => {
                self.count_unreadable(&e);
                Err(e)
            }
        }
    }

    /// Counts a judged line in the tally and the diagnosis of the whole log.
    fn count(&mut self, judgement: &Judgement) {
        judgement.count(&mut self.tally);
        self.log.add(judgement.evidence());
        self.all_ok &= !judgement.fails();
    }

    /// Keeps line `number` to be written as a test, if failing lines are kept and it fails.
    fn keep(&mut self, number: usize, record: Record, judgement: &Judgement) {
        if let Some(failing) = &mut self.failing
            && judgement.fails()
            && failing.len() < MAX_TESTS
        {
            failing.push(Failing {
                line: number,
                record,
                judgement: judgement.clone(),
            });
        }
    }

    /// Counts a line that could not be read as a call, for `error`.
    fn count_unreadable(&mut self, error: &LineError) {
        self.tally.add("unreadable");
        self.log.unreadable_for(|| error.to_string());
        self.all_ok = false;
    }

    /// Counts `lines` log lines the pattern matched no part of: an error under `--strict`.
    fn skip(&mut self, reader: &Reader, lines: usize) -> Result<(), LineError> {
        if lines > 0 && reader.strict {
            return Err(LineError::NotMatching);
        }
        for _ in 0..lines {
            self.tally.add(SKIPPED);
            self.log.skip();
        }
        Ok(())
    }

    /// A line the pattern did not match on its own, gathered with the lines before it: the
    /// record it completes, read (not yet judged), if it completes one.
    fn gathered_record(
        &mut self,
        reader: &Reader,
        line: &str,
    ) -> Result<Option<Result<Record, LineError>>, LineError> {
        let (Some(gather), Format::Pattern(pattern)) = (&mut self.gather, &reader.format) else {
            self.skip(reader, 1)?;
            return Ok(None);
        };
        let step = gather.push(line, |text| pattern.capture(text).is_some());
        self.skip(reader, step.skipped)?;
        Ok(step.record.map(|record| match reader.read(&record) {
            Read::Record(record) => record,
            // The gathered text matched: it reads as a record.
            Read::Unmatched | Read::Deferred => Err(LineError::NotMatching),
        }))
    }

    /// [`Books::gathered_record`], judged.
    fn gathered(&mut self, reader: &Reader, line: &str) -> Result<Option<JudgedLine>, LineError> {
        Ok(self.gathered_record(reader, line)?.map(|record| {
            let record = record?;
            judge_record(&record, &reader.options).map(|judged| (record, judged))
        }))
    }

    /// Lines gathered toward a record that a line matched on its own (or the input's end)
    /// cuts short: skipped (an error under `--strict` was given for none of them yet, and
    /// the line that cut them short is answered).
    fn forget_gathered(&mut self) {
        let lines = self.gather.as_mut().map_or(0, Gather::clear);
        for _ in 0..lines {
            self.tally.add(SKIPPED);
            self.log.skip();
        }
    }
}

/// One run of `check --api`: lines in, answer lines out, the tally kept.
#[derive(Debug)]
pub struct Session {
    reader: Reader,
    books: Books,
}

impl Session {
    /// A run for `options` reading lines in `format`; with `strict`, a line that does not match
    /// the pattern is an error instead of skipped; with `paths`, a summary follows each path.
    #[must_use]
    pub fn new(options: Options, format: Format, strict: bool, paths: bool) -> Self {
        let gather = match &format {
            Format::Pattern(pattern) => Some(Gather::new(pattern.lines())),
            Format::JsonLines | Format::Csv => None,
        };
        Self {
            reader: Reader {
                options,
                format,
                strict,
                header: std::sync::OnceLock::new(),
                glam: core::sync::atomic::AtomicBool::new(false),
            },
            books: Books {
                paths: paths.then(paths::Paths::new),
                gather,
                tally: Tally::default(),
                all_ok: true,
                log: LogTally::default(),
                failing: None,
            },
        }
    }

    /// Answers line `number` (from 1): a JSON answer, or nothing for a line without a call.
    ///
    /// # Errors
    /// Why the line cannot be judged; the loop answers it with `{"line", "error"}`.
    pub fn answer(&mut self, number: usize, line: &str) -> Result<String, LineError> {
        let judged = self.reader.judge(line);
        self.books.answer(&self.reader, number, judged)
    }

    /// Keeps the first [`MAX_TESTS`] failing lines that [`Session::run`] and
    /// [`Session::answer`] judge from now on, to be written as tests ([`Session::failing`]).
    pub fn keep_failing(&mut self) {
        self.books.failing.get_or_insert_with(Vec::new);
    }

    /// The failing lines kept (see [`Session::keep_failing`]), in input order.
    #[must_use]
    pub fn failing(&self) -> &[Failing] {
        self.books.failing.as_deref().unwrap_or_default()
    }

    /// The options the lines are judged with.
    #[must_use]
    pub fn options(&self) -> &Options {
        &self.reader.options
    }

    /// Answers every non-empty line of `input` on `output` in order, the lines judged on
    /// `threads` threads (see [`refraction_tools::answer_lines`]); returns whether every line was
    /// answered. Call [`Session::finish`] after it.
    ///
    /// # Errors
    /// Reading `input` or writing `output` failed.
    pub fn run(
        &mut self,
        input: impl std::io::Read,
        output: impl std::io::Write,
        threads: usize,
    ) -> Result<bool, refraction_tools::LinesError> {
        let (reader, books) = (&self.reader, &mut self.books);
        let mut refused = 0;
        let answered = refraction_tools::answer_lines(
            input,
            output,
            threads,
            |line| reader.judge(line),
            |number, judged| books.answer(reader, number, judged),
            || refused += 1,
        );
        books.forget_gathered();
        // Lines the loop refused itself (not UTF-8, too long) are unreadable ones.
        for _ in 0..refused {
            books.tally.add("unreadable");
            books.log.unreadable();
        }
        books.all_ok &= refused == 0;
        answered
    }

    /// The record on one line, read in order, for the explorer's pasted logs (so that they
    /// and the command read lines alike): `None` for a line without a call (a CSV header; a log
    /// line the pattern does not match, counted as skipped). The caller judges the record.
    ///
    /// # Errors
    /// The line is not a record of the API's fields (the message says why), a log line does
    /// not match the pattern under `strict`, or the CSV header is unusable.
    pub fn record(&mut self, line: &str) -> Result<Option<Record>, LineError> {
        match self.reader.read(line) {
            Read::Record(record) => {
                self.books.forget_gathered();
                record.map(Some)
            }
            Read::Unmatched => self.books.gathered_record(&self.reader, line)?.transpose(),
            Read::Deferred => self.reader.take_header(line).map_or(Ok(None), Err),
        }
    }

    /// Ends the input of [`Session::record`] and [`Session::judge_line`]: lines gathered
    /// toward a record that never came are counted as skipped.
    pub fn end_of_input(&mut self) {
        self.books.forget_gathered();
    }

    /// Reads and judges one line, in order, for the explorer's pasted and opened logs, and
    /// counts it as the command does (in the tally and the diagnosis of the whole log): the
    /// record and its judgement, or `None` for a line without a call (a CSV header, a log line
    /// the pattern does not match).
    ///
    /// # Errors
    /// Why the line cannot be judged (counted as unreadable), as [`Session::record`] and
    /// [`judge_record`] say.
    pub fn judge_line(&mut self, line: &str) -> Result<Option<(Record, Judgement)>, LineError> {
        match self.record(line) {
            Ok(Some(record)) => self.judge(&record).map(|judged| Some((record, judged))),
            Ok(None) => Ok(None),
            Err(e) => {
                self.books.count_unreadable(&e);
                Err(e)
            }
        }
    }

    /// Judges a record read elsewhere (built in memory, [`Record::from_values`]) and counts
    /// it as a line of the log, as [`Session::judge_line`] does.
    ///
    /// # Errors
    /// Why the record cannot be judged (counted as unreadable), as [`judge_record`] says.
    pub fn judge(&mut self, record: &Record) -> Result<Judgement, LineError> {
        let judged = judge_record(record, &self.reader.options);
        match &judged {
            Ok(judgement) => self.books.count(judgement),
            Err(e) => self.books.count_unreadable(e),
        }
        judged
    }

    /// The summary of the last path (with `--paths`), once the input has ended.
    pub fn finish(&mut self) -> Option<String> {
        self.books.paths.as_mut().and_then(paths::Paths::finish)
    }

    /// The verdicts so far.
    #[must_use]
    pub fn tally(&self) -> &Tally {
        &self.books.tally
    }

    /// The counts the diagnosis of the lines so far is made from.
    #[must_use]
    pub(crate) fn log(&self) -> &LogTally {
        &self.books.log
    }

    /// The diagnosis of the lines so far, taken as one log, its fixes in the words of
    /// `--renderer`, else of the language the log's lines reveal (GLSL's calls printed as glam
    /// prints its vectors are Rust on glam), else of the API.
    #[must_use]
    pub fn summary(&self) -> Summary {
        let options = &self.reader.options;
        let api = options.dialect.api();
        let glam = self.reader.glam.load(core::sync::atomic::Ordering::Relaxed);
        let revealed = (glam && api == Some(Api::Glsl)).then_some(Renderer::Glam);
        let renderer = options.renderer.or(revealed).or_else(|| options.renderer());
        self.books.log.summary(api, renderer)
    }

    /// Whether every line so far was right and every path finished left right.
    #[must_use]
    pub fn all_ok(&self) -> bool {
        self.books.all_ok && self.books.paths.as_ref().is_none_or(|p| p.all_exit_ok)
    }
}

#[cfg(test)]
mod compound_tests;
#[cfg(test)]
mod ecosystem_tests;
#[cfg(test)]
mod tests;

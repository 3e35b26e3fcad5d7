//! The log diagnosis of a renderer's refraction: what `check` and `check --api` do, with no
//! window and no files of its own.
//!
//! - one call read in its own [`Dialect`], an API's (`--api glsl|pbrt|rtiow|mitsuba`) or any
//!   renderer's own refraction (physics), from JSON, a `--pattern` log or CSV into a [`Record`],
//!   and judged on its own ([`check_record`], [`Case`]); a [`Session`] judges a whole log, line
//!   by line or as JSON Lines streamed, and [`check_records`] judges calls held in memory
//!   ([`Record::from_values`]) as `check` does the same calls written as JSON Lines;
//! - the diagnosis of the whole log: the one mistake in the student's code that explains its
//!   wrong lines (a [`Summary`], as `check --summary` writes it), and the fix in the code's terms;
//! - a judged call or a log's failing lines as unit tests in the student's language
//!   ([`call_test`], [`tests_file`]).
//!
//! Which of the four candidates a T is comes from `refraction_tools::check_t`, which the
//! window's *Check my T* uses too.

mod call_check;
mod diagnosis;
mod records;
mod snippets;

pub use call_check::call::Got;
pub use call_check::limits::{MAX_PATTERN_BYTES, MAX_PATTERN_LINES, MAX_PLACEHOLDERS};
pub use call_check::pattern::Pattern;
pub use call_check::physics::Case;
pub use call_check::record::Value;
pub use call_check::verdict::CallVerdict;
pub use call_check::{
    Call, CsvError, Dialect, Failing, Format, Judgement, LineError, MAX_TESTS, Options,
    PatternError, Record, SAMPLED, SKIPPED, Session, Tally, UNDECIDED, check_record, fields,
    judge_record, suggest,
};
pub use diagnosis::{
    Code, LogTally, MAX_SUMMARY_BYTES, Renderer, Summary, Verdict, looks_like_summary,
};
pub use records::{CallResult, Checked, check_records};
pub use snippets::api::{ApiCase, Language, right_args, test as call_test};
pub use snippets::{AnyLanguage, tests_file};

//! Why a `check` line, a `--pattern` or a CSV header is refused, as types a caller can tell
//! apart. Each is worded once, by its `Display`, in the language of the thread that shows it
//! (`t!`): the lines may be judged on other threads, and the words are made where they are
//! read (the window in its user's language, `check`'s JSON in English).

use glam::DVec3;
use refraction_i18n::{decimal, t};
use refraction_kernel::api::Api;

use super::fields::{self, Dialect};
use super::limits::{MAX_PATTERN_BYTES, MAX_PATTERN_LINES, MAX_PLACEHOLDERS};
use refraction_tools::{JsonError, RequestError, VectorError};

/// Why a `--pattern` cannot be used.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PatternError {
    /// Longer than [`MAX_PATTERN_BYTES`].
    #[error("{}", t!("check-pattern-too-long", bytes = *bytes, limit = MAX_PATTERN_BYTES))]
    TooLong {
        /// Its length in bytes.
        bytes: usize,
    },
    /// More than [`MAX_PLACEHOLDERS`] placeholders.
    #[error("{}", t!("check-pattern-too-many", count = *count, limit = MAX_PLACEHOLDERS))]
    TooManyPlaceholders {
        /// How many it has.
        count: usize,
    },
    /// A record over more than [`MAX_PATTERN_LINES`] lines.
    #[error("{}", t!("check-pattern-too-many-lines", count = *count, limit = MAX_PATTERN_LINES))]
    TooManyLines {
        /// How many lines it takes.
        count: usize,
    },
    /// A `{` without its `}`.
    #[error("{}", t!("check-pattern-unclosed", pattern = pattern))]
    Unclosed {
        /// The pattern.
        pattern: String,
    },
    /// A field named twice.
    #[error("{}", t!("check-pattern-twice", field = *field, pattern = pattern))]
    Twice {
        /// The field.
        field: &'static str,
        /// The pattern.
        pattern: String,
    },
    /// Two fields with nothing between them.
    #[error("{}", t!("check-pattern-adjacent", pattern = pattern))]
    Adjacent {
        /// The pattern.
        pattern: String,
    },
    /// No field at all.
    #[error("{}", t!("check-pattern-no-field", pattern = pattern))]
    NoField {
        /// The pattern.
        pattern: String,
    },
    /// `{!name}` where `name` is not a flag.
    #[error("{}", t!("check-pattern-negated-not-flag", field = field))]
    NegatedNotFlag {
        /// The name written.
        field: String,
    },
    /// A placeholder that names none of the dialect's fields.
    #[error("{}", unknown_in_pattern(field, *dialect))]
    UnknownField {
        /// The name written.
        field: String,
        /// Whose fields were expected.
        dialect: Dialect,
    },
}

/// Why a CSV line, or the header naming its columns, cannot be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CsvError {
    /// A quote opened and never closed.
    #[error("{}", t!("check-csv-unclosed-quote"))]
    UnclosedQuote,
    /// The header names a column twice.
    #[error("{}", t!("check-csv-duplicate-column", column = column))]
    DuplicateColumn {
        /// The heading.
        column: String,
    },
    /// The header lacks a column the line needs.
    #[error("{}", no_column(field, names, *dialect))]
    NoColumn {
        /// The field without a column.
        field: &'static str,
        /// The header as written.
        names: String,
        /// Whose fields were expected.
        dialect: Dialect,
    },
    /// The header has some of a vector's components and not all three.
    #[error("{}", t!("check-csv-partial-vector", field = *field, count = *count))]
    PartialVector {
        /// The vector field.
        field: &'static str,
        /// How many of its components it has.
        count: usize,
    },
    /// A line with another number of cells than the header has columns.
    #[error("{}", t!("check-csv-cells", count = *count, columns = *columns))]
    Cells {
        /// The line's cells.
        count: usize,
        /// The header's columns.
        columns: usize,
    },
}

/// What a missing argument is, in the message that names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The incident vector.
    Incident,
    /// The surface normal.
    Normal,
    /// The index ratio.
    Eta,
    /// The student's T.
    YourT,
}

impl Role {
    /// The role in the current language: "the surface normal".
    #[must_use]
    pub fn words(self) -> String {
        match self {
            Self::Incident => t!("check-what-incident"),
            Self::Normal => t!("check-what-normal"),
            Self::Eta => t!("check-what-eta"),
            Self::YourT => t!("check-your-t-in-error"),
        }
    }
}

/// Why one line of `check` (a call of an API, or any renderer's refraction) cannot be judged.
/// A field is named as the line wrote it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LineError {
    /// Not JSON, in a JSON Lines input.
    #[error(transparent)]
    Json(#[from] JsonError),
    /// JSON that is not an object.
    #[error("{}", t!("check-json-not-object", fields = fields::listed(*dialect)))]
    NotAnObject {
        /// Whose fields were expected.
        dialect: Dialect,
    },
    /// A pattern or CSV header's name for a field the dialect does not have.
    #[error("{}", t!("check-unknown-field", field = field))]
    UnknownField {
        /// The name.
        field: String,
    },
    /// A field's text that is not a number or a vector.
    #[error("`{field}`: {error}")]
    Text {
        /// The field.
        field: String,
        /// Why the text cannot be read.
        #[source]
        error: VectorError,
    },
    /// A vector whose numbers were printed one a line (Eigen's `cout << v`, a column of a
    /// matrix): refused, as the lines cannot tell which numbers belong together.
    #[error("{}", t!("check-field-column-vector", field = field))]
    ColumnVector {
        /// The field.
        field: String,
    },
    /// A flag's text that is not true/false or 1/0.
    #[error("{}", t!("check-field-not-flag-got", field = field, text = text))]
    NotFlagText {
        /// The field.
        field: String,
        /// The text.
        text: String,
    },
    /// A JSON field that must be a number.
    #[error("{}", t!("check-field-not-number-json", field = field))]
    NotNumber {
        /// The field.
        field: String,
    },
    /// A JSON array with other than three numbers.
    #[error("{}", t!("check-field-not-three", field = field, count = *count))]
    NotThree {
        /// The field.
        field: String,
        /// How many items it has.
        count: usize,
    },
    /// A JSON vector field that is neither an array nor a string.
    #[error("{}", t!("check-field-not-a-vector", field = field))]
    NotAVector {
        /// The field.
        field: String,
    },
    /// A JSON flag that is neither a boolean, a number nor a string.
    #[error("{}", t!("check-field-not-flag", field = field))]
    NotFlag {
        /// The field.
        field: String,
    },
    /// A JSON label that is neither a string nor a number.
    #[error("{}", t!("check-field-not-label", field = field))]
    NotLabel {
        /// The field.
        field: String,
    },
    /// A field read as something else than the 3 numbers it must be.
    #[error("{}", t!("check-field-not-vector", field = field))]
    NotVector {
        /// The field.
        field: String,
    },
    /// A required argument is absent.
    #[error("{}", t!("check-field-missing", field = field, what = role.words()))]
    Missing {
        /// The field.
        field: String,
        /// What it is.
        role: Role,
    },
    /// An argument vector with a component NaN or infinite.
    #[error("{}", t!("check-field-not-finite", field = field, value = value.to_string()))]
    NotFinite {
        /// The field.
        field: String,
        /// Its value.
        value: DVec3,
    },
    /// An argument vector that is zero.
    #[error("{}", t!("check-field-zero-vector", field = field))]
    ZeroVector {
        /// The field.
        field: String,
    },
    /// An index or ratio that is not a finite number > 0.
    #[error("{}", t!("check-field-not-positive", field = field, value = decimal(&value.to_string())))]
    NotPositive {
        /// The field.
        field: String,
        /// Its value.
        value: f64,
    },
    /// `from` without `to`, or `to` without `from`.
    #[error("{}", t!("check-from-and-to-together"))]
    FromAndToApart,
    /// A `travel` that is not a finite non-zero vector.
    #[error("{}", t!("check-travel-not-finite"))]
    TravelNotFinite,
    /// The result is null although the call says it returned one.
    #[error("{}", t!("check-result-null", field = *field, returned = fields::RETURNED))]
    ResultNull {
        /// The result's field.
        field: &'static str,
    },
    /// What the call returned is absent.
    #[error("{}", t!("check-result-missing", field = *field, api = api.name()))]
    ResultMissing {
        /// The result's field.
        field: &'static str,
        /// The API.
        api: Api,
    },
    /// A `precision` that is not `f32` or `f64`.
    #[error("{}", t!("check-unknown-precision", text = text))]
    UnknownPrecision {
        /// The text.
        text: String,
    },
    /// A `convention` that is not `along_ray` or `toward_origin`.
    #[error("{}", t!("check-physics-unknown-convention", text = text))]
    UnknownConvention {
        /// The text.
        text: String,
    },
    /// Any renderer's line without the indices on either side.
    #[error("{}", t!("check-physics-no-indices"))]
    NoIndices,
    /// `--paths` and a hit without its `path`.
    #[error("{}", NO_PATH)]
    NoPath,
    /// A call judged without an API: a caller's mistake, never a user's.
    #[error("{}", NO_API)]
    NoApi,
    /// An argument too large for the student's precision.
    #[error("{}", t!("check-too-large", value = format!("{value:e}"), precision = *precision))]
    TooLarge {
        /// The argument.
        value: f64,
        /// The precision: `f32`.
        precision: &'static str,
    },
    /// A CSV line that cannot be read.
    #[error(transparent)]
    Csv(#[from] CsvError),
    /// A CSV line after a header that could not be used.
    #[error("{}", t!("check-csv-no-header", reason = .0.to_string()))]
    NoHeader(#[source] CsvError),
    /// A log line, or lines gathered, that the pattern does not match (under `--strict`).
    #[error("{}", t!("check-line-not-matching"))]
    NotMatching,
    /// The refraction problem of any renderer's line is refused (a zero vector, an index that
    /// is not positive).
    #[error(transparent)]
    Request(#[from] RequestError),
}

/// [`LineError::NoPath`]'s words.
// untranslated: `--paths` is the command's alone, and its JSON is English
const NO_PATH: &str = "missing field `path` (the ray this hit belongs to, with --paths)";

/// [`LineError::NoApi`]'s words.
// untranslated: a programmer's mistake, never a user's
const NO_API: &str = "a call needs an API: judge any renderer's lines with physics";

impl From<refraction_kernel::InputError> for LineError {
    fn from(error: refraction_kernel::InputError) -> Self {
        Self::Request(error.into())
    }
}

fn unknown_in_pattern(field: &str, dialect: Dialect) -> String {
    let (api, expected) = (dialect.name(), fields::listed(dialect));
    t!(
        "check-pattern-unknown-field",
        field = field,
        api = api,
        expected = expected
    )
}

fn no_column(field: &str, names: &str, dialect: Dialect) -> String {
    let expected = fields::listed(dialect);
    t!(
        "check-csv-no-column",
        field = field,
        names = names,
        expected = expected
    )
}

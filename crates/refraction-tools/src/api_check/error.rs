//! Why a `check` line, a `--pattern` or a CSV header is refused, as types a caller can tell
//! apart. Each is worded once, by its `Display`, in the language of the thread that shows it
//! (`t!`): the lines may be judged on other threads, and the words are made where they are
//! read (the window in its user's language, `check`'s JSON in English).

use core::fmt;

use glam::DVec3;
use refraction_i18n::{decimal, t};
use refraction_kernel::api::Api;

use super::fields::{self, Dialect};
use super::pattern::{MAX_PATTERN_BYTES, MAX_PATTERN_LINES, MAX_PLACEHOLDERS};
use crate::error::{JsonError, RequestError, VectorError};

/// Why a `--pattern` cannot be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PatternError {
    /// Longer than [`MAX_PATTERN_BYTES`].
    TooLong {
        /// Its length in bytes.
        bytes: usize,
    },
    /// More than [`MAX_PLACEHOLDERS`] placeholders.
    TooManyPlaceholders {
        /// How many it has.
        count: usize,
    },
    /// A record over more than [`MAX_PATTERN_LINES`] lines.
    TooManyLines {
        /// How many lines it takes.
        count: usize,
    },
    /// A `{` without its `}`.
    Unclosed {
        /// The pattern.
        pattern: String,
    },
    /// A field named twice.
    Twice {
        /// The field.
        field: &'static str,
        /// The pattern.
        pattern: String,
    },
    /// Two fields with nothing between them.
    Adjacent {
        /// The pattern.
        pattern: String,
    },
    /// No field at all.
    NoField {
        /// The pattern.
        pattern: String,
    },
    /// `{!name}` where `name` is not a flag.
    NegatedNotFlag {
        /// The name written.
        field: String,
    },
    /// A placeholder that names none of the dialect's fields.
    UnknownField {
        /// The name written.
        field: String,
        /// Whose fields were expected.
        dialect: Dialect,
    },
}

impl fmt::Display for PatternError {
    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let words = match self {
            Self::TooLong { bytes } => {
                t!("check-pattern-too-long", bytes = *bytes, limit = MAX_PATTERN_BYTES)
            }
            Self::TooManyPlaceholders { count } => {
                t!("check-pattern-too-many", count = *count, limit = MAX_PLACEHOLDERS)
            }
            Self::TooManyLines { count } => {
                t!("check-pattern-too-many-lines", count = *count, limit = MAX_PATTERN_LINES)
            }
            Self::Unclosed { pattern } => t!("check-pattern-unclosed", pattern = pattern),
            Self::Twice { field, pattern } => {
                t!("check-pattern-twice", field = *field, pattern = pattern)
            }
            Self::Adjacent { pattern } => t!("check-pattern-adjacent", pattern = pattern),
            Self::NoField { pattern } => t!("check-pattern-no-field", pattern = pattern),
            Self::NegatedNotFlag { field } => t!("check-pattern-negated-not-flag", field = field),
            Self::UnknownField { field, dialect } => {
                let (api, listed) = (dialect.name(), fields::listed(*dialect));
                t!("check-pattern-unknown-field", field = field, api = api, expected = listed)
            }
        };
        f.write_str(&words)
    }
}

impl core::error::Error for PatternError {}

/// Why a CSV line, or the header naming its columns, cannot be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CsvError {
    /// A quote opened and never closed.
    UnclosedQuote,
    /// The header names a column twice.
    DuplicateColumn {
        /// The heading.
        column: String,
    },
    /// The header lacks a column the line needs.
    NoColumn {
        /// The field without a column.
        field: &'static str,
        /// The header as written.
        names: String,
        /// Whose fields were expected.
        dialect: Dialect,
    },
    /// The header has some of a vector's components and not all three.
    PartialVector {
        /// The vector field.
        field: &'static str,
        /// How many of its components it has.
        count: usize,
    },
    /// A line with another number of cells than the header has columns.
    Cells {
        /// The line's cells.
        count: usize,
        /// The header's columns.
        columns: usize,
    },
}

impl fmt::Display for CsvError {
    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let words = match self {
            Self::UnclosedQuote => t!("check-csv-unclosed-quote"),
            Self::DuplicateColumn { column } => t!("check-csv-duplicate-column", column = column),
            Self::NoColumn { field, names, dialect } => {
                let expected = fields::listed(*dialect);
                t!("check-csv-no-column", field = *field, names = names, expected = expected)
            }
            Self::PartialVector { field, count } => {
                t!("check-csv-partial-vector", field = *field, count = *count)
            }
            Self::Cells { count, columns } => {
                t!("check-csv-cells", count = *count, columns = *columns)
            }
        };
        f.write_str(&words)
    }
}

impl core::error::Error for CsvError {}

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
#[derive(Clone, Debug, PartialEq)]
pub enum LineError {
    /// Not JSON, in a JSON Lines input.
    Json(JsonError),
    /// JSON that is not an object.
    NotAnObject {
        /// Whose fields were expected.
        dialect: Dialect,
    },
    /// A pattern or CSV header's name for a field the dialect does not have.
    UnknownField {
        /// The name.
        field: String,
    },
    /// A field's text that is not a number or a vector.
    Text {
        /// The field.
        field: String,
        /// Why the text cannot be read.
        error: VectorError,
    },
    /// A flag's text that is not true/false or 1/0.
    NotFlagText {
        /// The field.
        field: String,
        /// The text.
        text: String,
    },
    /// A JSON field that must be a number.
    NotNumber {
        /// The field.
        field: String,
    },
    /// A JSON array with other than three numbers.
    NotThree {
        /// The field.
        field: String,
        /// How many items it has.
        count: usize,
    },
    /// A JSON vector field that is neither an array nor a string.
    NotAVector {
        /// The field.
        field: String,
    },
    /// A JSON flag that is neither a boolean, a number nor a string.
    NotFlag {
        /// The field.
        field: String,
    },
    /// A JSON label that is neither a string nor a number.
    NotLabel {
        /// The field.
        field: String,
    },
    /// A field read as something else than the 3 numbers it must be.
    NotVector {
        /// The field.
        field: String,
    },
    /// A required argument is absent.
    Missing {
        /// The field.
        field: String,
        /// What it is.
        role: Role,
    },
    /// An argument vector with a component NaN or infinite.
    NotFinite {
        /// The field.
        field: String,
        /// Its value.
        value: DVec3,
    },
    /// An argument vector that is zero.
    ZeroVector {
        /// The field.
        field: String,
    },
    /// An index or ratio that is not a finite number > 0.
    NotPositive {
        /// The field.
        field: String,
        /// Its value.
        value: f64,
    },
    /// `from` without `to`, or `to` without `from`.
    FromAndToApart,
    /// A `travel` that is not a finite non-zero vector.
    TravelNotFinite,
    /// The result is null although the call says it returned one.
    ResultNull {
        /// The result's field.
        field: &'static str,
    },
    /// What the call returned is absent.
    ResultMissing {
        /// The result's field.
        field: &'static str,
        /// The API.
        api: Api,
    },
    /// A `precision` that is not `f32` or `f64`.
    UnknownPrecision {
        /// The text.
        text: String,
    },
    /// A `convention` that is not `along_ray` or `toward_origin`.
    UnknownConvention {
        /// The text.
        text: String,
    },
    /// Any renderer's line without the indices on either side.
    NoIndices,
    /// `--paths` and a hit without its `path`.
    NoPath,
    /// A call judged without an API: a caller's mistake, never a user's.
    NoApi,
    /// An argument too large for the student's precision.
    TooLarge {
        /// The argument.
        value: f64,
        /// The precision: `f32`.
        precision: &'static str,
    },
    /// A CSV line that cannot be read.
    Csv(CsvError),
    /// A CSV line after a header that could not be used.
    NoHeader(CsvError),
    /// A log line, or lines gathered, that the pattern does not match (under `--strict`).
    NotMatching,
    /// The refraction problem of any renderer's line is refused (a zero vector, an index that
    /// is not positive).
    Request(RequestError),
}

/// [`LineError::NoPath`]'s words.
// untranslated: `--paths` is the command's alone, and its JSON is English
const NO_PATH: &str = "missing field `path` (the ray this hit belongs to, with --paths)";

/// [`LineError::NoApi`]'s words.
// untranslated: a programmer's mistake, never a user's
const NO_API: &str = "a call needs an API: judge any renderer's lines with physics";

impl fmt::Display for LineError {
    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let words = match self {
            Self::Json(error) => return error.fmt(f),
            Self::Text { field, error } => return write!(f, "`{field}`: {error}"),
            Self::Csv(error) => return error.fmt(f),
            Self::Request(error) => return error.fmt(f),
            Self::NotAnObject { dialect } => {
                t!("check-json-not-object", fields = fields::listed(*dialect))
            }
            Self::UnknownField { field } => t!("check-unknown-field", field = field),
            Self::NotFlagText { field, text } => {
                t!("check-field-not-flag-got", field = field, text = text)
            }
            Self::NotNumber { field } => t!("check-field-not-number-json", field = field),
            Self::NotThree { field, count } => {
                t!("check-field-not-three", field = field, count = *count)
            }
            Self::NotAVector { field } => t!("check-field-not-a-vector", field = field),
            Self::NotFlag { field } => t!("check-field-not-flag", field = field),
            Self::NotLabel { field } => t!("check-field-not-label", field = field),
            Self::NotVector { field } => t!("check-field-not-vector", field = field),
            Self::Missing { field, role } => {
                t!("check-field-missing", field = field, what = role.words())
            }
            Self::NotFinite { field, value } => {
                t!("check-field-not-finite", field = field, value = value.to_string())
            }
            Self::ZeroVector { field } => t!("check-field-zero-vector", field = field),
            Self::NotPositive { field, value } => {
                t!("check-field-not-positive", field = field, value = decimal(&value.to_string()))
            }
            Self::FromAndToApart => t!("check-from-and-to-together"),
            Self::TravelNotFinite => t!("check-travel-not-finite"),
            Self::ResultNull { field } => {
                t!("check-result-null", field = *field, returned = fields::RETURNED)
            }
            Self::ResultMissing { field, api } => {
                t!("check-result-missing", field = *field, api = api.name())
            }
            Self::UnknownPrecision { text } => t!("check-unknown-precision", text = text),
            Self::UnknownConvention { text } => {
                t!("check-physics-unknown-convention", text = text)
            }
            Self::NoIndices => t!("check-physics-no-indices"),
            Self::NoPath => return f.write_str(NO_PATH),
            Self::NoApi => return f.write_str(NO_API),
            Self::TooLarge { value, precision } => {
                t!("check-too-large", value = format!("{value:e}"), precision = *precision)
            }
            Self::NoHeader(error) => t!("check-csv-no-header", reason = error.to_string()),
            Self::NotMatching => t!("check-line-not-matching"),
        };
        f.write_str(&words)
    }
}

impl core::error::Error for LineError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Json(error) => Some(error),
            Self::Text { error, .. } => Some(error),
            Self::Csv(error) | Self::NoHeader(error) => Some(error),
            Self::Request(error) => Some(error),
            _ => None,
        }
    }
}

impl From<JsonError> for LineError {
    fn from(error: JsonError) -> Self {
        Self::Json(error)
    }
}

impl From<CsvError> for LineError {
    fn from(error: CsvError) -> Self {
        Self::Csv(error)
    }
}

impl From<RequestError> for LineError {
    fn from(error: RequestError) -> Self {
        Self::Request(error)
    }
}

impl From<refraction_kernel::InputError> for LineError {
    fn from(error: refraction_kernel::InputError) -> Self {
        Self::Request(error.into())
    }
}

//! Why the tools refuse a line or a file, as types a caller can tell apart. Each is worded by
//! its `Display`: the request's and JSON's words in English, as the `solve` command's error
//! lines give them; the words a student reads in *Check my T* in the thread's language (`t!`).

use refraction_i18n::t;
use refraction_kernel::InputError;

/// A text that is not a JSON request object.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum JsonError {
    /// Not JSON: `serde_json`'s message, at a line (1 for a single line) and column.
    #[error("{}", malformed(*line, *column, message))]
    Malformed {
        /// The line of the text, from 1.
        line: usize,
        /// The column of the line, from 1.
        column: usize,
        /// What was wrong there.
        message: String,
    },
    /// Well-formed JSON of the wrong shape (an array, a number): the message says what it is.
    #[error("{0}")]
    NotAnObject(String),
}

fn malformed(line: usize, column: usize, message: &str) -> String {
    if line <= 1 {
        format!("malformed JSON at column {column}: {message}")
    } else {
        format!("malformed JSON at line {line}, column {column}: {message}")
    }
}

impl From<&serde_json::Error> for JsonError {
    fn from(error: &serde_json::Error) -> Self {
        let text = error.to_string();
        let message = text
            .rfind(" at line ")
            .map_or(text.as_str(), |i| &text[..i])
            .to_owned();
        match error.classify() {
            serde_json::error::Category::Data => Self::NotAnObject(message),
            _ => Self::Malformed {
                line: error.line(),
                column: error.column(),
                message,
            },
        }
    }
}

/// Why a refraction problem (a `solve` line, a state file, the problem in a `check` line) was
/// refused. Fields are checked in a fixed order, so a line with several problems always names
/// the same one.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RequestError {
    /// The text is not a JSON object.
    #[error(transparent)]
    Json(#[from] JsonError),
    /// A required field is absent.
    #[error("missing field `{0}`")]
    Missing(String),
    /// A field holds the wrong kind of value.
    #[error("`{field}` must be {expected}, got {got}")]
    WrongKind {
        /// The field (`w`, `w[1]`, `mu_i`).
        field: String,
        /// What it must be: "a number", "an array of 3 numbers", "a string".
        expected: &'static str,
        /// What it holds: "a string", "null", "an object".
        got: &'static str,
    },
    /// A vector with other than three components.
    #[error("`{field}` must be an array of exactly 3 numbers, got {len} element{}", plural(*len))]
    NotThree {
        /// The field.
        field: String,
        /// How many components it has.
        len: usize,
    },
    /// A `convention` that is neither `along_ray` nor `toward_origin`.
    #[error(
        "unknown convention \"{0}\": expected \"along_ray\" (W is the direction of travel) or \
         \"toward_origin\" (W points back to the ray's origin)"
    )]
    UnknownConvention(String),
    /// A `precision` that is neither `f32` nor `f64`.
    #[error("unknown precision \"{0}\": expected \"f64\" or \"f32\"")]
    UnknownPrecision(String),
    /// A number finite as written that overflows the precision asked for.
    #[error("{field} = {value:e} is too large for {precision}")]
    TooLarge {
        /// The field and component (`w[0]`).
        field: String,
        /// The number as written.
        value: f64,
        /// `"f32"`.
        precision: &'static str,
    },
    /// The kernel refuses the problem (a zero vector, an index that is not positive, NaN).
    #[error(transparent)]
    Refused(#[from] InputError),
}

fn plural(count: usize) -> &'static str {
    if count == 1 { "" } else { "s" }
}

/// Why a vector or a number written by a program could not be read.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VectorError {
    /// A word that is not a number.
    #[error("{}", t!("check-word-not-a-number", word = word))]
    NotANumber {
        /// The word.
        word: String,
    },
    /// `Vec3 { x: …, w: … }`: a component under another name than x, y, z in turn.
    #[error("{}", t!("check-vector-expected-named", expected = *expected, found = found))]
    ExpectedNamed {
        /// The name expected here.
        expected: &'static str,
        /// The component found.
        found: String,
    },
    /// Other than three numbers.
    #[error("{}", t!("check-vector-not-three", count = *count, text = text))]
    NotThree {
        /// How many were found.
        count: usize,
        /// The vector's text.
        text: String,
    },
    /// A problem with a component, in the vector's text.
    #[error("{}", t!("check-vector-within", error = error.to_string(), text = text))]
    Within {
        /// The component's problem.
        error: Box<Self>,
        /// The vector's text.
        text: String,
    },
    /// The student's T in JSON: an item of its array is neither a number nor null.
    #[error("{}", t!("check-t-yours-item-not-number", index = index.to_string()))]
    ItemNotNumber {
        /// The item's index.
        index: usize,
    },
    /// A vector field in JSON with other than three items.
    #[error("{}", t!("check-field-not-three", field = *field, count = *count))]
    FieldNotThree {
        /// The field.
        field: &'static str,
        /// How many items it has.
        count: usize,
    },
    /// A vector field in JSON that is neither an array nor a string.
    #[error("{}", t!("check-field-not-a-vector", field = *field))]
    FieldNotAVector {
        /// The field.
        field: &'static str,
    },
}

/// Why a `check` line could not be judged.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CheckError {
    /// The problem part of the line was refused.
    #[error(transparent)]
    Request(#[from] RequestError),
    /// The line has no `t_yours`.
    #[error("{}", t!("check-t-yours-missing"))]
    MissingYours,
    /// `t_yours` cannot be read as a vector.
    #[error(transparent)]
    Yours(#[from] VectorError),
}

impl From<JsonError> for CheckError {
    fn from(error: JsonError) -> Self {
        Self::Request(error.into())
    }
}

impl From<InputError> for CheckError {
    fn from(error: InputError) -> Self {
        Self::Request(error.into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn malformed_json_names_its_place_and_a_single_line_only_its_column() {
        let one = serde_json::from_str::<serde_json::Value>("{").unwrap_err();
        assert!(
            JsonError::from(&one)
                .to_string()
                .starts_with("malformed JSON at column 1: ")
        );
        let two = serde_json::from_str::<serde_json::Value>("{\n\"w\": }").unwrap_err();
        assert!(
            JsonError::from(&two)
                .to_string()
                .starts_with("malformed JSON at line 2, column 6: ")
        );
    }

    #[test]
    fn a_vector_problem_in_a_component_quotes_the_whole_vector() {
        let error = VectorError::Within {
            error: Box::new(VectorError::NotANumber { word: "x".into() }),
            text: "1, x, 2".into(),
        };
        assert_eq!(error.to_string(), "\"x\" is not a number (in \"1, x, 2\")");
    }
}

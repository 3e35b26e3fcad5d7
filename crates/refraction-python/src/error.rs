//! Why an argument of `refraction_check.check` cannot be used: each names the argument, says
//! what it holds and what is expected (Python raises it as `ValueError`).

use refraction_check::Dialect;
use refraction_check::fields;
use refraction_i18n::{decimal, t};

/// Why an argument cannot be used. Worded by its `Display` in the thread's language (English
/// unless chosen, as `check`'s answers are).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ArgumentError {
    /// An `api` that names none.
    #[error("{}", t!("python-unknown-api", name = name))]
    UnknownApi {
        /// The name given.
        name: String,
    },
    /// A keyword that is neither a field of the dialect nor an option.
    #[error("{}", unknown_argument(argument, *dialect))]
    UnknownArgument {
        /// The keyword.
        argument: String,
        /// Whose fields were expected.
        dialect: Dialect,
    },
    /// `inside` or `outside` that is not a finite number > 0.
    #[error("{}", t!("python-index", argument = *argument, value = decimal(value)))]
    Index {
        /// `inside` or `outside`.
        argument: &'static str,
        /// What was given, as Python writes it.
        value: String,
    },
    /// `inside` without `outside`, or the other way round.
    #[error("{}", t!("python-sides-apart", given = *given, missing = *missing))]
    SidesApart {
        /// The one given.
        given: &'static str,
        /// The one missing.
        missing: &'static str,
    },
    /// `normal` or `convention` (options of any renderer's own refraction) with an `api`.
    #[error("{}", t!("python-not-with-api", argument = *argument, api = api.name()))]
    NotWithApi {
        /// The option.
        argument: &'static str,
        /// The dialect given.
        api: Dialect,
    },
    /// A `normal` that is neither an axis nor three finite numbers other than zero.
    #[error("{}", t!("python-normal", value = value))]
    Normal {
        /// What was given, as Python writes it.
        value: String,
    },
    /// A word option (`convention`, `precision`, `renderer`) that names nothing known.
    #[error("{}", t!("python-unknown-word", argument = *argument, value = value, expected = *expected))]
    UnknownWord {
        /// The option.
        argument: &'static str,
        /// What was given.
        value: String,
        /// The words it takes.
        expected: &'static str,
    },
    /// An argument whose shape is none of those its field takes.
    #[error("{}", t!("python-shape", argument = argument, shape = shape_text(shape), expected = *expected))]
    Shape {
        /// The argument.
        argument: String,
        /// Its shape.
        shape: Vec<usize>,
        /// The shapes it may have, as Python writes them.
        expected: &'static str,
    },
    /// An argument that does not read as numbers (strings, complex numbers, objects).
    #[error("{}", t!("python-not-numbers", argument = argument, reason = reason))]
    NotNumbers {
        /// The argument.
        argument: String,
        /// Why, in numpy's words or the kind of values found.
        reason: String,
    },
    /// A flag (`entering`, `returned`...) with a value other than true/false or 1/0.
    #[error("{}", t!("python-not-flag", argument = argument, value = decimal(&value.to_string()), row = *row))]
    NotFlag {
        /// The argument.
        argument: String,
        /// The value found.
        value: f64,
        /// Its row, from 0.
        row: usize,
    },
    /// Two arguments with different numbers of rows.
    #[error("{}", t!("python-rows", argument = argument, rows = *rows, other = other, other_rows = *other_rows))]
    Rows {
        /// The argument.
        argument: String,
        /// Its rows.
        rows: usize,
        /// The first argument with rows.
        other: String,
        /// Its rows.
        other_rows: usize,
    },
    /// Arguments with no row at all: no call to check.
    #[error("{}", t!("python-no-rows", argument = argument))]
    NoRows {
        /// The argument.
        argument: String,
    },
    /// A call's values refused as `check` refuses a line's (the words name the field).
    #[error("{0}")]
    Record(String),
    /// No call could be judged, all for the same reason (an argument left out, most often).
    #[error("{}", t!("python-nothing-judged", calls = *calls, reason = reason))]
    NothingJudged {
        /// How many calls there were.
        calls: usize,
        /// Why, as `check` answers each of those lines.
        reason: String,
    },
}

/// A shape as Python writes it: `(4, 2)`, `(3,)`, `()`.
fn shape_text(shape: &[usize]) -> String {
    if let [one] = shape {
        return format!("({one},)");
    }
    let sizes: Vec<String> = shape.iter().map(ToString::to_string).collect();
    format!("({})", sizes.join(", "))
}

fn unknown_argument(argument: &str, dialect: Dialect) -> String {
    // untranslated: the keyword's value as Python writes it
    let api = dialect
        .api()
        .map_or_else(|| "None".to_owned(), |a| format!("'{}'", a.name()));
    let fields = fields::listed(dialect);
    t!(
        "python-unknown-argument",
        argument = argument,
        api = api,
        fields = fields
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::api::Api;

    #[test]
    fn shapes_are_written_as_python_writes_them() {
        assert_eq!(shape_text(&[4, 2]), "(4, 2)");
        assert_eq!(shape_text(&[3]), "(3,)");
        assert_eq!(shape_text(&[]), "()");
    }

    #[test]
    fn each_message_names_the_argument_and_what_it_may_be() {
        let unknown = ArgumentError::UnknownArgument {
            argument: "wt".to_owned(),
            dialect: Dialect::Api(Api::Mitsuba),
        }
        .to_string();
        assert!(
            unknown.contains("`wt`") && unknown.contains("wi, n, eta, wo"),
            "{unknown}"
        );
        let shape = ArgumentError::Shape {
            argument: "wi".to_owned(),
            shape: vec![4, 2],
            expected: "(N, 3) or (3,)",
        }
        .to_string();
        assert!(shape.contains("wi") && shape.contains("(4, 2)"), "{shape}");
        let rows = ArgumentError::Rows {
            argument: "wo".to_owned(),
            rows: 10,
            other: "wi".to_owned(),
            other_rows: 12,
        }
        .to_string();
        assert!(
            rows.contains("wo") && rows.contains("10") && rows.contains("12"),
            "{rows}"
        );
    }
}

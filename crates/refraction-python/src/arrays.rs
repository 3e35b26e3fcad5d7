//! An argument's numbers, as numpy hands them over (a shape and the values row after row), into
//! one value per call or one value for every call: a [`Column`].
//!
//! A row that logged nothing (all NaN, which is what numpy makes of Python's `None`) is JSON's
//! `null` on a `check` line: "nothing came back" for a result that may be null (Mitsuba's
//! `wo`, pbrt's `wt`, `t_yours`), an absent field elsewhere. A vector with only some of its
//! components NaN is read as JSON's `[0.1, null, 0]` is: a vector that is not finite, which the
//! call's verdict names.

use refraction_check::Value;
use refraction_check::fields::Kind;

use crate::ArgumentError;

/// An argument's numbers: its shape and its values in C order (the last axis fastest), as
/// `f64`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Array {
    /// The size of each axis: `[]` for one number, `[3]` for one vector, `[N, 3]` for N.
    pub shape: Vec<usize>,
    /// The values, row after row.
    pub values: Vec<f64>,
    /// Whether the first axis holds a vector's components: a Dr.Jit `Array3f` of N lanes
    /// (Mitsuba's `Vector3f` in a vectorised variant), which numpy sees as `(3, N)`.
    pub components_first: bool,
}

impl Array {
    /// One number, or a vector, or rows of either, as numpy would shape them.
    #[must_use]
    pub fn new(shape: &[usize], values: &[f64]) -> Self {
        Self {
            shape: shape.to_vec(),
            values: values.to_vec(),
            components_first: false,
        }
    }
}

/// One field's values: the same for every call, or one per call.
#[derive(Clone, Debug, PartialEq)]
pub enum Column {
    /// One value for every call (a number, a vector, a word).
    Every(Value),
    /// One value per call, in order.
    Rows(Vec<Value>),
}

impl Column {
    /// How many calls the column has values for; `None` when it has one for every call.
    #[must_use]
    pub fn rows(&self) -> Option<usize> {
        match self {
            Self::Every(_) => None,
            Self::Rows(rows) => Some(rows.len()),
        }
    }

    /// The value of call `row` (which must be below [`Column::rows`], when that is known).
    #[must_use]
    pub fn value(&self, row: usize) -> Value {
        match self {
            Self::Every(value) => value.clone(),
            Self::Rows(rows) => rows[row].clone(),
        }
    }
}

/// The shapes a vector argument takes, as messages write them.
// untranslated: shapes as Python writes them
const VECTOR_SHAPES: &str = "(N, 3) or (3,)";

/// The shapes a Dr.Jit vector argument takes.
// untranslated: shapes as Python writes them
const DRJIT_VECTOR_SHAPES: &str = "(3, N) or (3,)";

/// The shapes a number or flag argument takes.
// untranslated: shapes as Python writes them
const NUMBER_SHAPES: &str = "(N,), (N, 1) or ()";

/// A vector's value: `null` when all three components are NaN (nothing logged).
fn vector(components: [f64; 3]) -> Value {
    if components.iter().all(|c| c.is_nan()) {
        Value::Null
    } else {
        Value::Vector(components)
    }
}

/// A number's value: `null` when it is NaN (nothing logged).
fn number(x: f64) -> Value {
    if x.is_nan() {
        Value::Null
    } else {
        Value::Number(x)
    }
}

/// A flag's value: `null` when NaN, true for 1 and false for 0 (as numpy casts `bool`).
fn flag(argument: &str, row: usize, x: f64) -> Result<Value, ArgumentError> {
    match x {
        _ if x.is_nan() => Ok(Value::Null),
        1.0 => Ok(Value::Flag(true)),
        0.0 => Ok(Value::Flag(false)),
        _ => Err(ArgumentError::NotFlag {
            argument: argument.to_owned(),
            value: x,
            row,
        }),
    }
}

/// Reads a vector argument: `(3,)` for one vector for every call, `(N, 3)` for one a call (a
/// Dr.Jit array's `(3, N)`, its components first).
///
/// # Errors
/// Any other shape; the message names `argument`.
pub fn vectors(argument: &str, array: &Array) -> Result<Column, ArgumentError> {
    let v = &array.values;
    match (array.shape.as_slice(), array.components_first) {
        ([3], _) => Ok(Column::Every(vector([v[0], v[1], v[2]]))),
        (&[3, lanes], true) => Ok(Column::Rows(
            (0..lanes)
                .map(|i| vector([v[i], v[lanes + i], v[2 * lanes + i]]))
                .collect(),
        )),
        (&[_, 3], false) => Ok(Column::Rows(
            v.chunks_exact(3)
                .map(|row| vector([row[0], row[1], row[2]]))
                .collect(),
        )),
        (shape, components_first) => Err(ArgumentError::Shape {
            argument: argument.to_owned(),
            shape: shape.to_vec(),
            expected: if components_first {
                DRJIT_VECTOR_SHAPES
            } else {
                VECTOR_SHAPES
            },
        }),
    }
}

/// The numbers of a number or flag argument: `None` for one number for every call, else one a
/// call (`(N,)`, or a column `(N, 1)`).
fn scalars<'a>(argument: &str, array: &'a Array) -> Result<Option<&'a [f64]>, ArgumentError> {
    match array.shape.as_slice() {
        [] => Ok(None),
        [_] | [_, 1] => Ok(Some(&array.values)),
        shape => Err(ArgumentError::Shape {
            argument: argument.to_owned(),
            shape: shape.to_vec(),
            expected: NUMBER_SHAPES,
        }),
    }
}

/// Reads a number argument (`eta`, `mu_i`...): one number, or one a call.
///
/// # Errors
/// Any other shape; the message names `argument`.
pub fn numbers(argument: &str, array: &Array) -> Result<Column, ArgumentError> {
    Ok(match scalars(argument, array)? {
        None => Column::Every(number(array.values[0])),
        Some(rows) => Column::Rows(rows.iter().map(|&x| number(x)).collect()),
    })
}

/// Reads a flag argument (`entering`, `returned`): booleans, or 1 and 0; one, or one a call.
///
/// # Errors
/// Any other shape, or a number other than 1, 0 or NaN; the message names `argument`.
pub fn flags(argument: &str, array: &Array) -> Result<Column, ArgumentError> {
    Ok(match scalars(argument, array)? {
        None => Column::Every(flag(argument, 0, array.values[0])?),
        Some(rows) => Column::Rows(
            rows.iter()
                .enumerate()
                .map(|(row, &x)| flag(argument, row, x))
                .collect::<Result<_, _>>()?,
        ),
    })
}

/// A word's value from a number (a `path` given as numbers): integers without a decimal
/// point, as JSON's `7` reads; `null` when NaN.
fn word(x: f64) -> Value {
    match x {
        _ if x.is_nan() => Value::Null,
        _ if x.fract() == 0.0 && x.abs() < 9.0e15 => Value::Label(format!("{}", x as i64)),
        _ => Value::Label(x.to_string()),
    }
}

/// Reads the numbers of an argument of field kind `kind`; a word field (`path`) takes them as
/// words.
///
/// # Errors
/// A shape the kind does not take, or a flag that is not one.
pub fn column(kind: Kind, argument: &str, array: &Array) -> Result<Column, ArgumentError> {
    match kind {
        Kind::Vector | Kind::VectorOrNull => vectors(argument, array),
        Kind::Number => numbers(argument, array),
        Kind::Flag => flags(argument, array),
        Kind::Label => Ok(match scalars(argument, array)? {
            None => Column::Every(word(array.values[0])),
            Some(rows) => Column::Rows(rows.iter().map(|&x| word(x)).collect()),
        }),
    }
}

/// A word argument given as words (`path`, a call's own `precision` or `convention`), one a
/// call (`None` where nothing was logged).
#[must_use]
pub fn labels(rows: Vec<Option<String>>) -> Column {
    Column::Rows(
        rows.into_iter()
            .map(|word| word.map_or(Value::Null, Value::Label))
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const NAN: f64 = f64::NAN;

    #[test]
    fn vectors_are_rows_of_three_or_one_for_every_call() {
        let rows = Array::new(&[2, 3], &[0.6, -0.8, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(
            vectors("wi", &rows).unwrap(),
            Column::Rows(vec![
                Value::Vector([0.6, -0.8, 0.0]),
                Value::Vector([0.0, 0.0, 1.0])
            ])
        );
        let one = Array::new(&[3], &[0.0, 0.0, 1.0]);
        assert_eq!(
            vectors("n", &one).unwrap(),
            Column::Every(Value::Vector([0.0, 0.0, 1.0]))
        );
    }

    #[test]
    fn a_drjit_array_of_three_lanes_is_read_by_lanes_not_by_rows() {
        // Three vectors (1, 0, 0), (0, 1, 0), (0.6, 0, -0.8), their components first.
        let lanes = Array {
            components_first: true,
            ..Array::new(&[3, 3], &[1.0, 0.0, 0.6, 0.0, 1.0, 0.0, 0.0, 0.0, -0.8])
        };
        let Column::Rows(rows) = vectors("wi", &lanes).unwrap() else {
            panic!("one vector a lane")
        };
        assert_eq!(rows[2], Value::Vector([0.6, 0.0, -0.8]));
        let wrong = Array {
            components_first: true,
            ..Array::new(&[4, 3], &[0.0; 12])
        };
        let e = vectors("wi", &wrong).unwrap_err().to_string();
        assert!(e.contains("(3, N)") && e.contains("(4, 3)"), "{e}");
    }

    #[test]
    fn a_row_of_nan_logged_nothing_and_a_partial_one_is_a_vector_not_finite() {
        let rows = Array::new(&[2, 3], &[NAN, NAN, NAN, 0.1, NAN, 0.0]);
        let Column::Rows(rows) = vectors("wo", &rows).unwrap() else {
            panic!("rows")
        };
        assert_eq!(rows[0], Value::Null);
        assert!(matches!(rows[1], Value::Vector([x, y, _]) if x == 0.1 && y.is_nan()));
        let Column::Rows(etas) = numbers("eta", &Array::new(&[2], &[1.5, NAN])).unwrap() else {
            panic!("rows")
        };
        assert_eq!(etas, vec![Value::Number(1.5), Value::Null]);
    }

    #[test]
    fn shapes_a_field_does_not_take_are_refused_by_name() {
        for (shape, values) in [(vec![4, 2], vec![0.0; 8]), (vec![], vec![1.0])] {
            let e = vectors("wi", &Array::new(&shape, &values)).unwrap_err();
            assert!(matches!(&e, ArgumentError::Shape { argument, .. } if argument == "wi"));
            assert!(e.to_string().contains("(N, 3) or (3,)"), "{e}");
        }
        let e = numbers("eta", &Array::new(&[2, 3], &[1.5; 6])).unwrap_err();
        assert!(
            e.to_string().contains("eta") && e.to_string().contains("(2, 3)"),
            "{e}"
        );
        assert_eq!(
            numbers("eta", &Array::new(&[2, 1], &[1.5, 1.0])).unwrap(),
            Column::Rows(vec![Value::Number(1.5), Value::Number(1.0)]),
            "a column vector of numbers is one a call"
        );
    }

    #[test]
    fn flags_are_booleans_or_one_and_zero() {
        assert_eq!(
            flags("entering", &Array::new(&[3], &[1.0, 0.0, NAN])).unwrap(),
            Column::Rows(vec![Value::Flag(true), Value::Flag(false), Value::Null])
        );
        assert_eq!(
            flags("entering", &Array::new(&[], &[1.0])).unwrap(),
            Column::Every(Value::Flag(true))
        );
        let e = flags("entering", &Array::new(&[2], &[1.0, 2.0])).unwrap_err();
        assert_eq!(
            e,
            ArgumentError::NotFlag {
                argument: "entering".to_owned(),
                value: 2.0,
                row: 1
            }
        );
    }

    #[test]
    fn words_are_read_from_words_or_numbers() {
        assert_eq!(
            labels(vec![Some("7".to_owned()), None]),
            Column::Rows(vec![Value::Label("7".to_owned()), Value::Null])
        );
        assert_eq!(
            column(Kind::Label, "path", &Array::new(&[3], &[7.0, 2.5, NAN])).unwrap(),
            Column::Rows(vec![
                Value::Label("7".to_owned()),
                Value::Label("2.5".to_owned()),
                Value::Null
            ])
        );
    }
}

//! A call's fields as columns, into one [`Record`] per call, judged and diagnosed as one log by
//! [`check_records`]: the code `check` runs on the same calls written as JSON Lines.

use refraction_check::fields::{self, Kind};
use refraction_check::{Checked, Dialect, Options, Record, Value, check_records};

use crate::ArgumentError;
use crate::arrays::Column;

/// Python's spelling of the field `from`, a word Python keeps for itself.
// untranslated: a keyword's name
pub(crate) const FROM_KEYWORD: &str = "from_";

/// The field keyword `argument` names in `dialect`, with its kind: a field of the dialect's
/// lines (`wi`, `eta`, `entering`, the book's `front_face`...), `from_` for `from`.
///
/// # Errors
/// A keyword that is no field of the dialect; the message lists its fields.
pub fn field(dialect: Dialect, argument: &str) -> Result<(&'static str, Kind), ArgumentError> {
    let name = if argument == FROM_KEYWORD {
        "from"
    } else {
        argument
    };
    fields::find(dialect, name).ok_or_else(|| ArgumentError::UnknownArgument {
        argument: argument.to_owned(),
        dialect,
    })
}

/// The calls to judge: each field's column, with the keyword it was given as.
#[derive(Clone, Debug)]
pub struct Calls {
    dialect: Dialect,
    columns: Vec<(&'static str, String, Column)>,
}

impl Calls {
    /// No fields yet, in `dialect`.
    #[must_use]
    pub fn new(dialect: Dialect) -> Self {
        Self {
            dialect,
            columns: Vec::new(),
        }
    }

    /// Adds field `field`'s column, given as keyword `argument`.
    pub fn add(&mut self, field: &'static str, argument: &str, column: Column) {
        self.columns.push((field, argument.to_owned(), column));
    }

    /// How many calls the columns hold: the rows of those with rows, which must agree; one
    /// when every column has one value for every call.
    ///
    /// # Errors
    /// Two columns with different rows, or columns with none.
    pub fn count(&self) -> Result<usize, ArgumentError> {
        let mut first: Option<(&str, usize)> = None;
        for (_, argument, column) in &self.columns {
            match (column.rows(), first) {
                (None, _) => {}
                (Some(0), _) => {
                    return Err(ArgumentError::NoRows {
                        argument: argument.clone(),
                    });
                }
                (Some(rows), None) => first = Some((argument, rows)),
                (Some(rows), Some((other, other_rows))) if rows != other_rows => {
                    return Err(ArgumentError::Rows {
                        argument: argument.clone(),
                        rows,
                        other: other.to_owned(),
                        other_rows,
                    });
                }
                (Some(_), Some(_)) => {}
            }
        }
        Ok(first.map_or(1, |(_, rows)| rows))
    }

    /// One record per call, as the same values on a JSON line would be read.
    ///
    /// # Errors
    /// See [`Calls::count`].
    pub fn records(&self) -> Result<Vec<Record>, ArgumentError> {
        (0..self.count()?)
            .map(|row| {
                let values: Vec<(&str, Value)> = self
                    .columns
                    .iter()
                    .map(|(field, _, column)| (*field, column.value(row)))
                    .collect();
                // Each field is the dialect's and each value of its kind (the columns are read
                // by kind), so a record cannot be refused; were it, it would say why.
                Record::from_values(self.dialect, values)
                    .map_err(|e| ArgumentError::Record(e.to_string()))
            })
            .collect()
    }
}

/// Judges every call and diagnoses them as one log, as `check` does.
///
/// # Errors
/// The columns do not agree (see [`Calls::count`]), or no call could be judged and all for
/// the same reason (an argument left out, most often), which then is the error's.
pub fn check(options: &Options, calls: &Calls) -> Result<Checked, ArgumentError> {
    let checked = check_records(options, calls.records()?);
    let mut reasons = checked.calls.iter().map(|call| call.as_ref().err());
    if let Some(Some(first)) = reasons.next()
        && reasons.all(|reason| reason.is_some_and(|e| e == first))
    {
        return Err(ArgumentError::NothingJudged {
            calls: checked.calls.len(),
            reason: first.to_string(),
        });
    }
    Ok(checked)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arrays::{Array, column};
    use crate::options::{self, Given};
    use glam::Vec3;
    use refraction_kernel::api::Api;
    use refraction_kernel::api::mitsuba::{Fma, fresnel, refract_local};

    const MITSUBA: Dialect = Dialect::Api(Api::Mitsuba);

    /// Mitsuba's `fresnel` and `refract` in the local frame at `count` angles from each side,
    /// as a student's Python calls them, the ratio given to `fresnel` changed by `mistake`:
    /// (wi, eta as the BSDF holds it, wo or NaN where it would reflect).
    fn mitsuba_calls(count: usize, mistake: impl Fn(f32) -> f32) -> (Array, Array) {
        let (mut wi, mut wo) = (Vec::new(), Vec::new());
        for side in [1.0_f32, -1.0] {
            for i in 0..count {
                let theta = (i as f32 + 0.5) / count as f32 * core::f32::consts::FRAC_PI_2;
                let v = Vec3::new(theta.sin(), 0.0, side * theta.cos());
                let f = fresnel(v.z, mistake(1.5), Fma::Unfused);
                let out = if f.f < 1.0 {
                    refract_local::<f32>(v, f.cos_theta_t, f.eta_ti)
                } else {
                    Vec3::NAN
                };
                wi.extend(v.to_array().map(f64::from));
                wo.extend(out.to_array().map(f64::from));
            }
        }
        let shape = [2 * count, 3];
        (Array::new(&shape, &wi), Array::new(&shape, &wo))
    }

    fn judged(wi: &Array, wo: &Array) -> Result<Checked, ArgumentError> {
        let mut calls = Calls::new(MITSUBA);
        for (argument, array) in [("wi", wi), ("wo", wo), ("eta", &Array::new(&[], &[1.5]))] {
            let (field, kind) = field(MITSUBA, argument)?;
            calls.add(field, argument, column(kind, argument, array)?);
        }
        let given = Given {
            inside: Some(1.5),
            outside: Some(1.0),
            ..Given::default()
        };
        check(&options::options(MITSUBA, &given)?, &calls)
    }

    #[test]
    fn mitsubas_own_calls_are_right_and_its_ratio_inverted_is_named() {
        let (wi, wo) = mitsuba_calls(40, |eta| eta);
        let right = judged(&wi, &wo).unwrap();
        assert_eq!(right.summary.diagnosis[0].code, "none");
        assert!(right.calls.iter().all(|c| c.as_ref().is_ok_and(|c| c.ok)));
        let (wi, wo) = mitsuba_calls(40, |eta| 1.0 / eta);
        let wrong = judged(&wi, &wo).unwrap();
        let verdict = &wrong.summary.diagnosis[0];
        assert_eq!(verdict.code, "eta_inverted", "{:?}", wrong.summary);
        // In the script's words: its call of mi.fresnel, not Mitsuba's C++.
        assert!(verdict.fix.contains("mi.fresnel("), "{}", verdict.fix);
        assert!(!verdict.fix.contains("fresnel.h"), "{}", verdict.fix);
    }

    #[test]
    fn columns_of_different_rows_or_none_are_refused_by_name() {
        let mut calls = Calls::new(MITSUBA);
        let vectors = |rows: usize| Column::Rows(vec![Value::Vector([0.0, 0.0, 1.0]); rows]);
        calls.add("wi", "wi", vectors(3));
        calls.add("eta", "eta", Column::Every(Value::Number(1.5)));
        calls.add("wo", "wo", vectors(2));
        let e = calls.count().unwrap_err();
        assert_eq!(
            e,
            ArgumentError::Rows {
                argument: "wo".to_owned(),
                rows: 2,
                other: "wi".to_owned(),
                other_rows: 3
            }
        );
        let mut empty = Calls::new(MITSUBA);
        empty.add("wi", "wi", vectors(0));
        assert!(matches!(empty.count(), Err(ArgumentError::NoRows { .. })));
    }

    #[test]
    fn one_value_each_is_one_call_and_an_argument_left_out_is_named() {
        let mut calls = Calls::new(MITSUBA);
        calls.add("wi", "wi", Column::Every(Value::Vector([0.6, 0.0, 0.8])));
        calls.add("eta", "eta", Column::Every(Value::Number(1.5)));
        assert_eq!(calls.count(), Ok(1));
        let e = check(&Options::new(MITSUBA), &calls)
            .unwrap_err()
            .to_string();
        assert!(e.contains("wo"), "{e}");
    }

    #[test]
    fn from_is_spelt_from_underscore_and_unknown_keywords_list_the_fields() {
        assert_eq!(field(MITSUBA, "from_").unwrap().0, "from");
        assert_eq!(
            field(Dialect::Api(Api::Rtiow), "front_face").unwrap().0,
            "entering"
        );
        let e = field(Dialect::Physics, "wo").unwrap_err().to_string();
        assert!(e.contains("`wo`") && e.contains("t_yours"), "{e}");
    }
}

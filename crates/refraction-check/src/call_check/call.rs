//! A logged call made ready to judge: the arguments in the API's own convention, what came
//! back, the truth the line (or the command line) gives, the precision and the rounding of the
//! logged numbers.

use glam::DVec3;
use refraction_kernel::Convention;
use refraction_kernel::api::{Api, Args};

use super::error::{LineError, Role};
use super::fields::{self, Dialect, names};
use super::record::{Record, Value};
use crate::diagnosis::Renderer;
use refraction_tools::Precision;

/// What the command line adds to every line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// The API the lines were logged from, or any renderer's own refraction.
    pub dialect: Dialect,
    /// `--inside`: the index inside the object, so that `entering` gives `from` and `to`.
    pub inside: Option<f64>,
    /// `--outside`: the index outside the object.
    pub outside: Option<f64>,
    /// `--precision`: the student's working precision, unless a line says otherwise.
    pub precision: Option<Precision>,
    /// `--convention`: how any renderer's `w` points, unless a line says (`check` without
    /// `--api`).
    pub convention: Option<Convention>,
    /// `--normal`: the normal of lines that print none (a local frame's +z), taken as the
    /// outward one, so that with `--inside` and `--outside` each ray's side follows from it.
    pub normal: Option<[f64; 3]>,
    /// `--renderer`: whose code the log comes from, for the words of the fixes.
    pub renderer: Option<Renderer>,
}

impl Options {
    /// Options for `dialect` (an API, or [`Dialect::Physics`]) with nothing else given.
    #[must_use]
    pub fn new(dialect: impl Into<Dialect>) -> Self {
        Self {
            dialect: dialect.into(),
            inside: None,
            outside: None,
            precision: None,
            convention: None,
            normal: None,
            renderer: None,
        }
    }

    /// Whose code the log comes from: `--renderer`, else the API's.
    #[must_use]
    pub fn renderer(&self) -> Option<Renderer> {
        self.renderer
            .or_else(|| self.dialect.api().map(Renderer::of_api))
    }

    /// `--inside` and `--outside`, when both are given.
    #[must_use]
    pub fn sides(&self) -> Option<(f64, f64)> {
        self.inside.zip(self.outside)
    }

    /// The precision lines are judged in unless they say: `--precision`, else the dialect's
    /// usual one.
    #[must_use]
    pub fn precision_or_usual(&self) -> Precision {
        self.precision
            .unwrap_or_else(|| fields::usual_precision(self.dialect))
    }

    /// Whether the kernel refracts with `--inside` and `--outside` in
    /// [`Options::precision_or_usual`], both ways: otherwise every line would fail.
    ///
    /// # Errors
    /// The kernel's reason (an index that is not finite in that precision, or a ratio beyond
    /// what it refracts).
    pub fn usable_indices(&self) -> Result<(), refraction_kernel::InputError> {
        let Some((inside, outside)) = self.sides() else {
            return Ok(());
        };
        for (mu_i, mu_t) in [(inside, outside), (outside, inside)] {
            match self.precision_or_usual() {
                Precision::F64 => probe(mu_i, mu_t)?,
                // The indices as the code holds them: f32's range is narrower.
                #[expect(
                    clippy::cast_possible_truncation,
                    reason = "f32 is the student's precision"
                )]
                Precision::F32 => probe(mu_i as f32, mu_t as f32)?,
            }
        }
        Ok(())
    }
}

/// Refracts a ray at normal incidence with indices `mu_i` and `mu_t`, to learn whether the
/// kernel takes them.
fn probe<S: refraction_kernel::Real>(
    mu_i: S,
    mu_t: S,
) -> Result<(), refraction_kernel::InputError> {
    use refraction_kernel::Vector3 as _;
    let down = S::Vec3::new(S::ZERO, -S::ONE, S::ZERO);
    let up = S::Vec3::new(S::ZERO, S::ONE, S::ZERO);
    let incidence = refraction_kernel::Incidence {
        w: down,
        n: up,
        mu_i,
        mu_t,
        convention: Convention::AlongRay,
    };
    refraction_kernel::refract(&incidence).map(|_| ())
}

/// What the line says about the ray beyond the call's own arguments.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Truth {
    /// The index of the medium the ray travels in and of the one it enters.
    pub from_to: Option<(f64, f64)>,
    /// The ray's direction of travel as the tracer holds it.
    pub travel: Option<DVec3>,
    /// Whether the ray enters the object.
    pub entering: Option<bool>,
    /// Whether `from_to` came from `entering` with `--inside` and `--outside`.
    pub from_entering: bool,
    /// Whether `entering` was not logged but taken from the normal, as the outward one (pbrt
    /// and Mitsuba with `--inside` and `--outside`: their eta is the index behind the normal
    /// over the one in front, `n_inside/n_outside` for the outward normal).
    pub entering_from_normal: bool,
    /// Whether `--inside` and `--outside` were given.
    pub sides_given: bool,
}

impl Truth {
    /// μ = from/to, when known.
    #[must_use]
    pub fn mu(&self) -> Option<f64> {
        self.from_to.map(|(from, to)| from / to)
    }

    /// Whether the line gives no truth at all.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.from_to.is_none() && self.travel.is_none() && self.entering.is_none()
    }
}

/// What came back from the call.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Got {
    /// A vector (possibly zero, NaN or infinite).
    Vector(DVec3),
    /// Nothing: pbrt's `false`, or a null `wo` from Mitsuba (it reflected).
    Nothing,
}

/// The significant digits a call's numbers were logged with (0: exact): each number is
/// trusted as far as its own digits go, so a ratio printed in full beside vectors printed
/// with 6 digits does not make the vectors look wrong.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Digits {
    /// The incident vector's.
    pub incident: u32,
    /// The normal's.
    pub normal: u32,
    /// The index ratio's.
    pub eta: u32,
    /// What came back.
    pub result: u32,
    /// The ray's direction of travel, when logged.
    pub travel: u32,
    /// Which of them show a decimal point or an exponent: their one- or two-digit numbers
    /// (`0.6`, `1.5`) may be a fixed format's rounding (`%.1f`) rather than the values they say.
    pub decimal: Decimals,
}

/// Which of a call's numbers were written with a decimal point or an exponent (see
/// [`Digits::decimal`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Decimals {
    /// The incident vector's.
    pub incident: bool,
    /// The normal's.
    pub normal: bool,
    /// The index ratio's.
    pub eta: bool,
    /// What came back.
    pub result: bool,
    /// The ray's direction of travel.
    pub travel: bool,
}

impl Digits {
    /// Every number written with `digits` digits and a decimal point.
    #[must_use]
    pub fn all(digits: u32) -> Self {
        Self {
            incident: digits,
            normal: digits,
            eta: digits,
            result: digits,
            travel: digits,
            decimal: Decimals {
                incident: true,
                normal: true,
                eta: true,
                result: true,
                travel: true,
            },
        }
    }

    /// The digits of `record`'s fields `incident`, `normal`, `eta` and `result` (and
    /// `travel`).
    fn of(record: &Record, incident: &str, normal: &str, eta: &str, result: &str) -> Self {
        let [incident, normal, eta, result, travel] =
            [incident, normal, eta, result, "travel"].map(|name| record.written(name));
        Self {
            incident: incident.digits,
            normal: normal.digits,
            eta: eta.digits,
            result: result.digits,
            travel: travel.digits,
            decimal: Decimals {
                incident: incident.decimal,
                normal: normal.decimal,
                eta: eta.decimal,
                result: result.decimal,
                travel: travel.decimal,
            },
        }
    }
}

/// One logged call.
#[derive(Clone, Debug, PartialEq)]
pub struct Call {
    /// The API.
    pub api: Api,
    /// The arguments as logged, in the API's convention.
    pub args: Args<f64>,
    /// What came back.
    pub got: Got,
    /// The truth given.
    pub truth: Truth,
    /// The precision the student's code computes in.
    pub precision: Precision,
    /// The significant digits each number was logged with.
    pub digits: Digits,
    /// The path this hit belongs to (`--paths`).
    pub path: Option<String>,
    /// Where the hit is, if logged.
    pub point: Option<DVec3>,
    /// pbrt's `etap` as logged: the ratio `Refract` says it used.
    pub etap: Option<f64>,
}

fn vector(record: &Record, name: &str) -> Result<Option<DVec3>, LineError> {
    match record.get(name) {
        None => Ok(None),
        Some(Value::Vector(v)) => Ok(Some(DVec3::from_array(*v))),
        Some(_) => Err(LineError::NotVector {
            field: name.to_owned(),
        }),
    }
}

/// The argument vector `name` (`role` says what it is), finite and not zero.
fn required_vector(record: &Record, name: &str, role: Role) -> Result<DVec3, LineError> {
    let field = || name.to_owned();
    let missing = || LineError::Missing {
        field: field(),
        role,
    };
    let value = vector(record, name)?.ok_or_else(missing)?;
    if !value.is_finite() {
        return Err(LineError::NotFinite {
            field: field(),
            value,
        });
    }
    if value == DVec3::ZERO {
        return Err(LineError::ZeroVector { field: field() });
    }
    Ok(value)
}

fn number(record: &Record, name: &str) -> Result<Option<f64>, LineError> {
    let field = || name.to_owned();
    match record.get(name) {
        None => Ok(None),
        Some(Value::Number(x)) if x.is_finite() && *x > 0.0 => Ok(Some(*x)),
        Some(Value::Number(x)) => Err(LineError::NotPositive {
            field: field(),
            value: *x,
        }),
        Some(_) => Err(LineError::NotNumber { field: field() }),
    }
}

fn flag(record: &Record, name: &str) -> Option<bool> {
    match record.get(name) {
        Some(Value::Flag(b)) => Some(*b),
        _ => None,
    }
}

fn label(record: &Record, name: &str) -> Option<String> {
    match record.get(name) {
        Some(Value::Label(text)) => Some(text.clone()),
        _ => None,
    }
}

/// Whether the ray enters, from the normal taken as the outward one: pbrt's and Mitsuba's
/// `wi` (back along the ray) on the side the normal points to.
fn entering_from_normal(record: &Record, options: &Options) -> Result<Option<bool>, LineError> {
    let Dialect::Api(api @ (Api::Pbrt | Api::Mitsuba)) = options.dialect else {
        return Ok(None);
    };
    if options.sides().is_none() {
        return Ok(None);
    }
    let n = names(api);
    let normal = match vector(record, n.normal)? {
        Some(normal) => normal,
        None if api == Api::Mitsuba => DVec3::Z,
        None => return Ok(None),
    };
    Ok(vector(record, n.incident)?.map(|wi| wi.dot(normal) > 0.0))
}

fn truth(record: &Record, options: &Options) -> Result<Truth, LineError> {
    let logged = flag(record, "entering");
    let given = match (number(record, "from")?, number(record, "to")?) {
        (Some(from), Some(to)) => Some((from, to)),
        (None, None) => None,
        _ => return Err(LineError::FromAndToApart),
    };
    let assumed = match (logged, given) {
        (None, None) => entering_from_normal(record, options)?,
        _ => None,
    };
    let entering = logged.or(assumed);
    let sides = options.sides();
    let from_sides = entering.zip(sides).map(|(entering, (inside, outside))| {
        if entering {
            (outside, inside)
        } else {
            (inside, outside)
        }
    });
    let travel = vector(record, "travel")?;
    if travel.is_some_and(|t| !t.is_finite() || t == DVec3::ZERO) {
        return Err(LineError::TravelNotFinite);
    }
    Ok(Truth {
        from_to: given.or(from_sides),
        travel,
        entering,
        from_entering: given.is_none() && from_sides.is_some(),
        entering_from_normal: assumed.is_some(),
        sides_given: sides.is_some(),
    })
}

fn got(record: &Record, api: Api) -> Result<Got, LineError> {
    let field = names(api).result;
    let returned = flag(record, fields::RETURNED);
    match (record.get(field), returned) {
        (_, Some(false)) => Ok(Got::Nothing),
        (Some(Value::Null), Some(true)) => Err(LineError::ResultNull { field }),
        (Some(Value::Null), None) => Ok(Got::Nothing),
        (Some(Value::Vector(v)), _) => Ok(Got::Vector(DVec3::from_array(*v))),
        (None, _) => Err(LineError::ResultMissing { field, api }),
        (Some(_), _) => Err(LineError::NotVector {
            field: field.to_owned(),
        }),
    }
}

/// Whether `record`'s vectors `names` were printed as single-precision floats print
/// themselves: every component the shortest text that reads back as its `f32` (Rust's `{}`
/// and `{:?}` of an `f32`, `core::fmt::float`'s `float_to_decimal_display` through
/// `flt2dec::strategy::grisu::format_shortest`; C#'s `float.ToString()`), one of them with
/// more than 7 significant digits, which a fixed format (`%g`, `%.6f`) would not print.
fn printed_as_f32(record: &Record, names: &[&str]) -> bool {
    let components: Vec<f64> = names
        .iter()
        .filter_map(|name| match record.get(name) {
            Some(Value::Vector(v)) => Some(*v),
            _ => None,
        })
        .flatten()
        .collect();
    #[expect(clippy::cast_possible_truncation)]
    let shortest_f32 = |x: f64| {
        let single = x as f32;
        single.is_finite() && single.to_string().parse::<f64>().is_ok_and(|y| y == x)
    };
    let long = |x: f64| format!("{x:.6e}").parse::<f64>().is_ok_and(|y| y != x);
    !components.is_empty()
        && components.iter().all(|&x| shortest_f32(x))
        && components.iter().any(|&x| long(x))
}

/// The student's precision: the line's `precision`, `--precision`, single where the vectors
/// were printed as `f32`s print themselves (issue 43: f32 code read as f64 was "not unit
/// length" on half its lines), else the dialect's usual one.
fn precision(record: &Record, options: &Options, vectors: &[&str]) -> Result<Precision, LineError> {
    match label(record, "precision").as_deref() {
        None => Ok(options.precision.unwrap_or_else(|| {
            if printed_as_f32(record, vectors) {
                Precision::F32
            } else {
                fields::usual_precision(options.dialect)
            }
        })),
        Some("f32" | "float") => Ok(Precision::F32),
        Some("f64" | "double") => Ok(Precision::F64),
        Some(other) => Err(LineError::UnknownPrecision {
            text: other.to_owned(),
        }),
    }
}

impl Call {
    /// The call a record describes.
    ///
    /// # Errors
    /// A missing or ill-typed field, a non-finite or zero argument vector, an eta that is not
    /// a finite number > 0; the message names the field.
    pub fn from_record(record: &Record, options: &Options) -> Result<Self, LineError> {
        let Dialect::Api(api) = options.dialect else {
            return Err(LineError::NoApi);
        };
        let n = names(api);
        let normal = if api == Api::Mitsuba && record.get(n.normal).is_none() {
            DVec3::Z
        } else {
            required_vector(record, n.normal, Role::Normal)?
        };
        let args = Args {
            incident: required_vector(record, n.incident, Role::Incident)?,
            normal,
            eta: number(record, n.eta)?.ok_or_else(|| LineError::Missing {
                field: n.eta.to_owned(),
                role: Role::Eta,
            })?,
        };
        Ok(Self {
            api,
            args,
            got: got(record, api)?,
            truth: truth(record, options)?,
            precision: precision(record, options, &[n.incident, n.normal, n.result])?,
            digits: Digits::of(record, n.incident, n.normal, n.eta, n.result),
            path: label(record, "path"),
            point: vector(record, "point")?,
            // Judged only where Refract returned true: on false pbrt leaves it unwritten.
            etap: match record.get(fields::ETAP) {
                Some(Value::Number(x)) if x.is_finite() => Some(*x),
                _ => None,
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(api: Api, line: &str, options: &Options) -> Result<Call, LineError> {
        Call::from_record(&Record::from_json_line(api, line)?, options)
    }

    #[test]
    fn entering_gives_from_and_to_with_the_sides() {
        let options = Options {
            inside: Some(1.5),
            outside: Some(1.0),
            ..Options::new(Api::Rtiow)
        };
        let line =
            r#"{"uv":[0,-1,0],"n":[0,1,0],"etai_over_etat":1.5,"refracted":[0,-1,0],"entering":0}"#;
        let c = call(Api::Rtiow, line, &options).unwrap();
        assert_eq!(c.truth.from_to, Some((1.5, 1.0)));
        assert!(c.truth.from_entering);
        assert_eq!(c.precision, Precision::F64);
    }

    #[test]
    fn each_api_says_what_is_missing() {
        let cases = [
            (
                Api::Pbrt,
                r#"{"wi":[0,1,0],"n":[0,1,0],"eta":1.5}"#,
                "\"returned\": false",
            ),
            (
                Api::Glsl,
                r#"{"I":[0,0,0],"N":[0,1,0],"eta":1,"result":[0,0,0]}"#,
                "`I` is the zero vector",
            ),
            (
                Api::Glsl,
                r#"{"I":[0,-1,0],"N":[0,1,0],"eta":-1,"result":[0,0,0]}"#,
                "`eta` must be a finite number > 0",
            ),
            (
                Api::Mitsuba,
                r#"{"wi":[0,0,1],"eta":1.5}"#,
                "null when it reflected",
            ),
        ];
        for (api, line, message) in cases {
            let e = call(api, line, &Options::new(api)).unwrap_err();
            assert!(e.to_string().contains(message), "{e}");
        }
        let pbrt = r#"{"wi":[0,1,0],"n":[0,1,0],"eta":1.5,"returned":false}"#;
        assert_eq!(
            call(Api::Pbrt, pbrt, &Options::new(Api::Pbrt)).unwrap().got,
            Got::Nothing
        );
        let mitsuba = r#"{"wi":[0,0,1],"eta":1.5,"wo":null}"#;
        let c = call(Api::Mitsuba, mitsuba, &Options::new(Api::Mitsuba)).unwrap();
        assert_eq!(c.args.normal, DVec3::Z);
    }
}

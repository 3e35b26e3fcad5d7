//! The `solve` command's contract: JSON Lines in, one JSON line out per non-empty input line.
//!
//! Input object: `w`, `n` (arrays of exactly 3 numbers), `mu_i`, `mu_t` (numbers), optional
//! `convention` (`"along_ray"`, the default, or `"toward_origin"`) and `precision` (`"f64"`, the
//! default, or `"f32"`). Other fields are ignored. A line that cannot be solved is answered with
//! `{"line": K, "error": "..."}` and the run goes on.

use std::io::{Read, Write};

use serde::Serialize;
use serde::de::IgnoredAny;
use serde_json::Value;

use crate::error::RequestError;
use crate::fields::{self, Field, Fields};
use refraction_kernel::{Convention, Fresnel, Incidence, Real, Refraction, Vector3, refract};
use refraction_model::SpecialAngles;

/// The floating-point precision a problem is solved in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Precision {
    /// Single precision (`f32`, glam `Vec3`).
    F32,
    /// Double precision (`f64`, glam `DVec3`).
    #[default]
    F64,
}

impl Precision {
    /// The name used in JSON: `"f32"` or `"f64"`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        }
    }
}

/// One refraction problem as read from a JSON line (numbers as written, in f64).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Request {
    /// The incoming vector W.
    pub w: [f64; 3],
    /// The surface normal N.
    pub n: [f64; 3],
    /// Index of the medium the ray travels in.
    pub mu_i: f64,
    /// Index of the medium the ray enters.
    pub mu_t: f64,
    /// Which way W points.
    pub convention: Convention,
    /// The precision to solve in.
    pub precision: Precision,
}

fn wrong_kind(field: &str, expected: &'static str, got: &Field) -> RequestError {
    RequestError::WrongKind {
        field: field.to_owned(),
        expected,
        got: got.kind(),
    }
}

fn number(field: &Field, name: &str) -> Result<f64, RequestError> {
    match field {
        Field::Number(x) => Ok(*x),
        Field::Absent => Err(RequestError::Missing(name.to_owned())),
        other => Err(wrong_kind(name, "a number", other)),
    }
}

fn vector(field: &Field, name: &str) -> Result<[f64; 3], RequestError> {
    let (items, len) = match field {
        Field::Array { items, len } => (items, *len),
        Field::Absent => return Err(RequestError::Missing(name.to_owned())),
        other => return Err(wrong_kind(name, "an array of 3 numbers", other)),
    };
    if len != 3 {
        return Err(RequestError::NotThree {
            field: name.to_owned(),
            len,
        });
    }
    let mut out = [0.0; 3];
    for (i, item) in items.iter().enumerate() {
        out[i] = number(item, &format!("{name}[{i}]"))?;
    }
    Ok(out)
}

fn optional_name<'a>(field: &'a Field, name: &str) -> Result<Option<&'a str>, RequestError> {
    match field {
        Field::Absent | Field::Null => Ok(None),
        Field::Text(s) => Ok(Some(s)),
        other => Err(wrong_kind(name, "a string", other)),
    }
}

impl Request {
    /// Reads a request from a parsed JSON value.
    ///
    /// # Errors
    /// A message naming the field that is missing or ill-typed.
    pub fn from_value(value: &Value) -> Result<Self, RequestError> {
        Self::from_fields(&fields::from_value::<IgnoredAny>(value)?)
    }

    /// The request in fields read from a line, checked in a fixed order (convention,
    /// precision, w, n, `mu_i`, `mu_t`) so that a line with several problems always names the same
    /// one.
    pub(crate) fn from_fields<X>(fields: &Fields<X>) -> Result<Self, RequestError> {
        let convention = match optional_name(&fields.convention, "convention")? {
            None => Convention::default(),
            Some(name) => Convention::from_name(name)
                .ok_or_else(|| RequestError::UnknownConvention(name.to_owned()))?,
        };
        let precision = match optional_name(&fields.precision, "precision")? {
            None => Precision::default(),
            Some("f64") => Precision::F64,
            Some("f32") => Precision::F32,
            Some(name) => return Err(RequestError::UnknownPrecision(name.to_owned())),
        };
        Ok(Self {
            w: vector(&fields.w, "w")?,
            n: vector(&fields.n, "n")?,
            mu_i: number(&fields.mu_i, "mu_i")?,
            mu_t: number(&fields.mu_t, "mu_t")?,
            convention,
            precision,
        })
    }

    /// Parses one JSON line (or a whole state file: JSON may span lines). Unknown fields are
    /// skipped without being built.
    ///
    /// # Errors
    /// Malformed JSON (with its column, and its line when there are several), or a message
    /// naming the field that is missing or ill-typed.
    pub fn parse(line: &str) -> Result<Self, RequestError> {
        Self::from_fields(&fields::read::<IgnoredAny>(line)?)
    }

    /// The request as one `solve` input line. Numbers are written in their shortest form that
    /// reads back to the same bits, so the line reproduces the problem exactly anywhere.
    #[must_use]
    pub fn to_json_line(&self) -> String {
        serde_json::json!({
            "w": self.w,
            "n": self.n,
            "mu_i": self.mu_i,
            "mu_t": self.mu_t,
            "convention": self.convention.name(),
            "precision": self.precision.name(),
        })
        .to_string()
    }

    /// The problem in precision `S`.
    ///
    /// # Errors
    /// A number that is finite as written but overflows `S`.
    pub fn incidence<S: Real>(&self) -> Result<Incidence<S>, RequestError> {
        let convert = |value: f64, field: String| {
            let converted = S::from_f64(value);
            if value.is_finite() && !converted.is_finite() {
                Err(RequestError::TooLarge {
                    field,
                    value,
                    precision: S::NAME,
                })
            } else {
                Ok(converted)
            }
        };
        let vec = |v: [f64; 3], name: &str| -> Result<S::Vec3, RequestError> {
            Ok(S::Vec3::new(
                convert(v[0], format!("{name}[0]"))?,
                convert(v[1], format!("{name}[1]"))?,
                convert(v[2], format!("{name}[2]"))?,
            ))
        };
        Ok(Incidence {
            w: vec(self.w, "w")?,
            n: vec(self.n, "n")?,
            mu_i: convert(self.mu_i, "mu_i".into())?,
            mu_t: convert(self.mu_t, "mu_t".into())?,
            convention: self.convention,
        })
    }
}

/// One candidate in the JSON answer.
#[derive(Serialize)]
struct CandidateAnswer<S> {
    a: S,
    b: S,
    t: [S; 3],
    chosen: bool,
    rejected_because: Option<&'static str>,
    rule: Option<&'static str>,
}

/// The Fresnel power fractions in the JSON answer.
#[derive(Serialize)]
struct FresnelAnswer<S> {
    r_s: S,
    r_p: S,
    t_s: S,
    t_p: S,
}

impl<S: Real> From<Fresnel<S>> for FresnelAnswer<S> {
    fn from(f: Fresnel<S>) -> Self {
        Self {
            r_s: f.rs,
            r_p: f.rp,
            t_s: f.ts,
            t_p: f.tp,
        }
    }
}

/// The JSON answer to one request.
#[derive(Serialize)]
struct Answer<S> {
    t: Option<[S; 3]>,
    tir: bool,
    reflected: [S; 3],
    a: Option<S>,
    b: Option<S>,
    k: S,
    cos_i: S,
    cos_t: Option<S>,
    normal_flipped: bool,
    warnings: Vec<String>,
    candidates: Vec<CandidateAnswer<S>>,
    fresnel: FresnelAnswer<S>,
    brewster_deg: Option<S>,
    critical_deg: Option<S>,
    precision: &'static str,
}

impl<S: Real> From<&Refraction<S>> for Answer<S> {
    fn from(r: &Refraction<S>) -> Self {
        let angles = SpecialAngles::for_ratio(r.mu.to_f64());
        Self {
            t: r.t().map(Vector3::to_array),
            tir: r.is_tir(),
            reflected: r.reflected.to_array(),
            a: r.transmission.map(|t| t.a),
            b: r.transmission.map(|t| t.b),
            k: r.k,
            cos_i: r.cos_i,
            cos_t: r.transmission.map(|t| t.cos_t),
            normal_flipped: r.normal_flipped,
            warnings: r.warnings.iter().map(ToString::to_string).collect(),
            candidates: r
                .candidates
                .iter()
                .map(|c| CandidateAnswer {
                    a: c.a,
                    b: c.b,
                    t: c.t.to_array(),
                    chosen: c.is_chosen(),
                    rejected_because: c.rejection.map(|r| r.name()),
                    rule: c.rejection.map(|r| r.rule()),
                })
                .collect(),
            fresnel: Fresnel::of(r).into(),
            brewster_deg: angles.brewster_deg.map(S::from_f64),
            critical_deg: angles.critical_deg.map(S::from_f64),
            precision: S::NAME,
        }
    }
}

fn answer_in<S: Real + Serialize>(request: &Request) -> Result<String, RequestError> {
    let refraction = refract(&request.incidence::<S>()?)?;
    // serde_json fails only on a map with keys that are not strings or on a Serialize that
    // fails: the answer has neither.
    // untranslated: a message for a developer, never shown
    Ok(crate::json_line(&Answer::from(&refraction)))
}

/// The JSON answer (without newline) to one input line, or the message for its error line.
///
/// # Errors
/// Why the line cannot be solved, naming the offending field or value.
pub fn solve_line(line: &str) -> Result<String, RequestError> {
    let request = Request::parse(line)?;
    match request.precision {
        Precision::F32 => answer_in::<f32>(&request),
        Precision::F64 => answer_in::<f64>(&request),
    }
}

/// Answers every non-empty line of `input` on `output`, on every core
/// ([`crate::threads`]) and in input order (see [`crate::answer_lines`]).
/// Returns whether every line was solved.
///
/// # Errors
/// Reading `input` or writing `output` failed.
pub fn solve_lines(input: impl Read, output: impl Write) -> Result<bool, crate::LinesError> {
    crate::answer_lines(input, output, crate::threads(), solve_line, |_, r| r, || {})
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error_of(line: &str) -> String {
        solve_line(line).unwrap_err().to_string()
    }

    #[test]
    fn every_kind_of_bad_line_names_what_is_wrong() {
        let good = r#""w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5"#;
        assert!(error_of("{").starts_with("malformed JSON at column 1"));
        assert!(error_of("[1,2]").contains("got an array"));
        assert_eq!(error_of(r#"{"w":[1,0,0]}"#), "missing field `n`");
        assert_eq!(
            error_of(r#"{"w":[1,0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#),
            "`w` must be an array of exactly 3 numbers, got 2 elements"
        );
        assert_eq!(
            error_of(r#"{"w":[1,"x",0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#),
            "`w[1]` must be a number, got a string"
        );
        assert_eq!(
            error_of(r#"{"w":[0,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#),
            "w is the zero vector, which has no direction"
        );
        assert!(
            error_of(&format!(r#"{{{good},"convention":"up"}}"#)).starts_with("unknown convention")
        );
        assert!(
            error_of(&format!(r#"{{{good},"precision":"f16"}}"#)).starts_with("unknown precision")
        );
        assert!(
            error_of(r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":0,"mu_t":1}"#).starts_with("mu_i is 0")
        );
        assert_eq!(
            error_of(r#"{"w":[1e39,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1,"precision":"f32"}"#),
            "w[0] = 1e39 is too large for f32"
        );
    }

    #[test]
    fn a_request_round_trips_through_its_json_line_bit_for_bit() {
        let request = Request {
            w: [0.1, -1.0 / 3.0, 1e-300],
            n: [f64::MIN_POSITIVE, 1.0, -0.0],
            mu_i: 1.000_293,
            mu_t: core::f64::consts::E,
            convention: Convention::TowardOrigin,
            precision: Precision::F32,
        };
        let back = Request::parse(&request.to_json_line()).unwrap();
        assert_eq!(back, request);
        assert_eq!(back.n[2].to_bits(), (-0.0_f64).to_bits());
    }

    #[test]
    fn answers_carry_the_fresnel_fractions_and_the_angles_that_matter() {
        let into_glass: Value = serde_json::from_str(
            &solve_line(r#"{"w":[0,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#).unwrap(),
        )
        .unwrap();
        let f = &into_glass["fresnel"];
        for (r, t) in [("r_s", "t_s"), ("r_p", "t_p")] {
            let (r, t) = (f[r].as_f64().unwrap(), f[t].as_f64().unwrap());
            assert!(
                (r - 0.04).abs() < 1e-15 && (r + t - 1.0).abs() < 1e-15,
                "{f}"
            );
        }
        let brewster = into_glass["brewster_deg"].as_f64().unwrap();
        assert!((brewster - 56.31).abs() < 1e-2);
        assert!(into_glass["critical_deg"].is_null());
        // Out of glass past the critical angle, in f32: all reflected.
        let tir: Value = serde_json::from_str(
            &solve_line(r#"{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"precision":"f32"}"#)
                .unwrap(),
        )
        .unwrap();
        assert_eq!(tir["fresnel"]["r_p"], 1.0);
        assert_eq!(tir["fresnel"]["t_s"], 0.0);
        assert!((tir["critical_deg"].as_f64().unwrap() - 41.81).abs() < 1e-2);
        let same: Value = serde_json::from_str(
            &solve_line(r#"{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1.5}"#).unwrap(),
        )
        .unwrap();
        assert!(same["brewster_deg"].is_null() && same["critical_deg"].is_null());
        assert_eq!(same["fresnel"]["t_p"], 1.0);
    }

    #[test]
    fn run_answers_every_line_in_order_and_skips_blank_ones() {
        let input = b"{\"w\":[0,-1,0],\"n\":[0,1,0],\"mu_i\":1,\"mu_t\":1.5}\n\nnot json\n\xff\n";
        let mut out = Vec::new();
        assert!(!solve_lines(&input[..], &mut out).unwrap());
        let lines: Vec<Value> = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        assert_eq!(lines.len(), 3);
        assert_eq!(lines[0]["tir"], false);
        assert_eq!(lines[1]["line"], 3);
        assert_eq!(lines[2]["line"], 4);
    }
}

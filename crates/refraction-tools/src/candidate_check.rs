//! One T against the four candidates: which of them a student's refracted ray is, in the
//! physics convention (W, N, μ: the `solve` fields), and the sign choice or convention mix-up
//! that produces it, in words a student understands. This is the verdict of "Check my T" and of
//! a `check` line; the log diagnosis (the crate `refraction-check`) reads a whole call in its own
//! dialect (an API's, or physics') and asks this module which candidate the physically meant T
//! is.

use serde::{Deserialize, Serialize};
use serde_json::Value;

use crate::error::{CheckError, RequestError, VectorError};
use crate::fields;
use crate::solve::{Precision, Request};
use crate::vector_text;
use refraction_i18n::{decimal, t};
use refraction_kernel::{Incidence, Real, Rejection, Vector3 as _, refract};

/// Largest angle (radians) between a student's T and a candidate for them to count as the same
/// ray: logged numbers are often printed with only a few digits.
pub const MATCH_ANGLE: f64 = 2e-3;

/// Relative length error beyond which a student's T is reported as not unit length.
pub const LENGTH_TOLERANCE: f64 = 1e-3;

/// What a student's T turned out to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Match {
    /// The physical refracted ray.
    Chosen,
    /// One of the three rejected candidates.
    Rejected(Rejection),
    /// On total internal reflection: the reflected ray, or the zero vector GLSL returns.
    TotalInternalReflection,
}

impl Match {
    /// The short name used in JSON: `chosen`, `wrong_side`, `wrong_bend`, `reversed` or
    /// `total_internal_reflection`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Chosen => "chosen",
            Self::Rejected(r) => r.name(),
            Self::TotalInternalReflection => "total_internal_reflection",
        }
    }
}

/// The verdict on one student's T.
#[derive(Clone, Debug, PartialEq)]
pub struct TVerdict {
    /// Whether the student's T is right (the physical ray, unit length; or a correct answer to
    /// total internal reflection).
    pub ok: bool,
    /// Which candidate it is, if any.
    pub matches: Option<Match>,
    /// What happened and the likely cause, in a sentence or two.
    pub explanation: String,
    /// The correct T (`None` on total internal reflection).
    pub correct: Option<[f64; 3]>,
}

fn explain(rejection: Rejection) -> String {
    match rejection {
        Rejection::WrongSide => t!("check-verdict-wrong-side"),
        Rejection::WrongBend => t!("check-verdict-wrong-bend"),
        Rejection::Reversed => t!("check-verdict-reversed"),
    }
}

/// The angle between two vectors of any finite length (a T of length 1e201 or 4e-320 too).
fn angle(a: glam::DVec3, b: glam::DVec3) -> f64 {
    vector_text::angle(a, b)
}

fn wide<S: Real>(v: S::Vec3) -> glam::DVec3 {
    glam::DVec3::from_array(v.to_array().map(Real::to_f64))
}

fn verdict_in<S: Real>(
    incidence: &Incidence<S>,
    yours: [f64; 3],
) -> Result<TVerdict, RequestError> {
    let r = refract(incidence)?;
    let (ok, matches, explanation) = if yours.iter().any(|c| !c.is_finite()) {
        (false, None, not_finite(r.is_tir()))
    } else if r.is_tir() {
        totally_reflected::<S>(&r, glam::DVec3::from_array(yours))
    } else {
        refracted::<S>(incidence, &r, glam::DVec3::from_array(yours))
    };
    Ok(TVerdict {
        ok,
        matches,
        explanation,
        correct: r.t().map(|t| wide::<S>(t).to_array()),
    })
}

/// A verdict before the correct T is added: whether the T is right, what it matches, and why.
type Judgement = (bool, Option<Match>, String);

/// Why a T with NaN or infinite components is wrong, for a ray that is totally internally
/// reflected (`tir`) or not.
fn not_finite(tir: bool) -> String {
    if tir {
        t!("check-verdict-not-finite-tir")
    } else {
        t!("check-verdict-not-finite-refracts")
    }
}

/// A finite T for a totally internally reflected ray: right when it is the reflection or zero.
fn totally_reflected<S: Real>(
    r: &refraction_kernel::Refraction<S>,
    yours: glam::DVec3,
) -> Judgement {
    let reflected = wide::<S>(r.reflected);
    if yours.length() == 0.0 || angle(yours, reflected) <= MATCH_ANGLE {
        return (
            true,
            Some(Match::TotalInternalReflection),
            t!("check-verdict-tir-right"),
        );
    }
    let k = decimal(&format!("{:.4}", r.k.to_f64()));
    (false, None, t!("check-verdict-tir-but-refracted", k = k))
}

/// A finite T for a ray that refracts: the candidate it matches or why it matches none, with a
/// note when it is not unit length.
fn refracted<S: Real>(
    incidence: &Incidence<S>,
    r: &refraction_kernel::Refraction<S>,
    yours: glam::DVec3,
) -> Judgement {
    let length = vector_text::length(yours);
    if length == 0.0 {
        return (false, None, t!("check-verdict-zero-vector"));
    }
    let unit_note = ((length - 1.0).abs() > LENGTH_TOLERANCE).then(|| {
        // The note follows the verdict's sentence, one space after it.
        let written = vector_text::spoken(length);
        format!(" {}", t!("check-verdict-not-unit", length = written))
    });
    let nearest = r
        .candidates
        .iter()
        .map(|c| (c, angle(yours, wide::<S>(c.t))))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let (ok, matches, text) = match nearest.filter(|(_, off)| *off <= MATCH_ANGLE) {
        Some((candidate, off)) => {
            let (ok, matches, text) = matched(candidate.rejection, off, unit_note.is_some());
            (ok, Some(matches), text)
        }
        None => (false, None, why_unmatched::<S>(incidence, r, yours)),
    };
    let note = unit_note.unwrap_or_default();
    (ok, matches, format!("{text}{note}"))
}

/// The verdict on a T within [`MATCH_ANGLE`] (`off` radians) of the candidate that breaks
/// `rejection` (`None`: the refracted ray), and that is or is not unit length.
fn matched(rejection: Option<Rejection>, off: f64, not_unit: bool) -> (bool, Match, String) {
    let off = decimal(&format!("{off:.1e}"));
    match rejection {
        None if not_unit => (
            false,
            Match::Chosen,
            t!("check-verdict-along-refracted", off = off),
        ),
        None => (true, Match::Chosen, t!("check-verdict-right", off = off)),
        Some(rejection) => (false, Match::Rejected(rejection), explain(rejection)),
    }
}

/// Why a T that matches no candidate is wrong: a swapped index ratio, a T outside the plane of
/// incidence, or simply how far it is from the right answer.
fn why_unmatched<S: Real>(
    incidence: &Incidence<S>,
    r: &refraction_kernel::Refraction<S>,
    yours: glam::DVec3,
) -> String {
    let swapped = Incidence {
        mu_i: incidence.mu_t,
        mu_t: incidence.mu_i,
        ..*incidence
    };
    let swapped_t = refract(&swapped).ok().and_then(|s| s.t());
    if swapped_t.is_some_and(|t| angle(yours, wide::<S>(t)) <= MATCH_ANGLE) {
        return t!("check-verdict-ratio-upside-down");
    }
    let plane = wide::<S>(r.travel).cross(wide::<S>(r.facing_normal));
    let out_of_plane = vector_text::unit(yours).dot(plane).abs();
    if plane.length() > 1e-9 && out_of_plane > MATCH_ANGLE * plane.length() {
        // Rounding can put the ratio just above 1 for a T normal to the plane.
        let off = (out_of_plane / plane.length()).min(1.0).asin();
        let off = decimal(&format!("{off:.3}"));
        return t!("check-verdict-out-of-plane", off = off);
    }
    let off = r.t().map_or(f64::NAN, |t| angle(yours, wide::<S>(t)));
    let degrees = decimal(&format!("{:.2}", off.to_degrees()));
    t!("check-verdict-no-candidate", degrees = degrees)
}

/// Judges `yours` as the refraction asked for by `request`.
///
/// # Errors
/// The request cannot be refracted (see [`Request::incidence`] and [`refract`]).
pub fn check_t(request: &Request, yours: [f64; 3]) -> Result<TVerdict, RequestError> {
    match request.precision {
        Precision::F32 => verdict_in(&request.incidence::<f32>()?, yours),
        Precision::F64 => verdict_in(&request.incidence::<f64>()?, yours),
    }
}

/// Reads a 3-vector written the way programs print them: `0.1, -0.9, 0`, `[0.1,-0.9,0]`,
/// `(0.1 -0.9 0)`, `vec3(0.1, -0.9, 0.0)`, `Vec3 { x: 0.1, y: -0.9, z: 0.0 }`, with `nan`,
/// `inf` and `f` suffixes allowed (see [`vector_text`]).
///
/// # Errors
/// A message saying what was found instead of three numbers.
pub fn parse_t(text: &str) -> Result<[f64; 3], VectorError> {
    vector_text::parse_vector(text).map(|v| v.value)
}

/// Reads the student's T from a JSON value: an array of 3 numbers (`null` entries count as NaN,
/// as loggers write it) or a string in any form [`parse_t`] accepts.
///
/// # Errors
/// A message naming what was found instead.
pub(crate) fn vector_from_json(value: &Value) -> Result<[f64; 3], VectorError> {
    match value {
        Value::String(text) => parse_t(text),
        Value::Array(items) if items.len() == 3 => {
            let mut out = [0.0; 3];
            for (i, (slot, item)) in out.iter_mut().zip(items).enumerate() {
                *slot = match item {
                    Value::Null => f64::NAN,
                    other => other
                        .as_f64()
                        .ok_or(VectorError::ItemNotNumber { index: i })?,
                };
            }
            Ok(out)
        }
        Value::Array(items) => Err(VectorError::FieldNotThree {
            field: "t_yours",
            count: items.len(),
        }),
        _ => Err(VectorError::FieldNotAVector { field: "t_yours" }),
    }
}

/// The JSON answer of the `check` command for one verdict (also the first fields of a
/// `check --api` answer).
#[derive(Serialize)]
pub struct CheckAnswer<'a> {
    /// Whether the T is the right one.
    pub ok: bool,
    /// The candidate it is (`chosen`, `wrong_side`, ...), or `None` when it is none of them.
    pub matches: Option<&'static str>,
    /// Why, in words.
    pub explanation: &'a str,
    /// The right T, `None` on total internal reflection.
    pub t: Option<[f64; 3]>,
}

/// Reads one line of the `check` command: the `solve` fields plus `t_yours`.
///
/// # Errors
/// Malformed JSON, or a missing or ill-typed field; the message names it.
pub fn parse_check_line(line: &str) -> Result<(Request, [f64; 3]), CheckError> {
    let fields = fields::read::<Given>(line)?;
    let request = Request::from_fields(&fields)?;
    let yours = fields
        .extra
        .0
        .ok_or(CheckError::MissingYours)
        .and_then(|value| Ok(vector_from_json(&value)?))?;
    Ok((request, yours))
}

/// `t_yours` as given, `null` included (`None` only when the field is absent). It is the one
/// field read whole: [`vector_from_json`] needs the value.
#[derive(Default)]
struct Given(Option<Value>);

impl<'de> Deserialize<'de> for Given {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        Value::deserialize(deserializer).map(|value| Self(Some(value)))
    }
}

/// Answers one line of the `check` command: the `solve` fields plus `t_yours`.
///
/// # Errors
/// Why the line cannot be judged (malformed JSON, a missing or ill-typed field, bad input).
pub fn check_line(line: &str) -> Result<(String, TVerdict), CheckError> {
    let (request, yours) = parse_check_line(line)?;
    let verdict = check_t(&request, yours)?;
    let answer = CheckAnswer {
        ok: verdict.ok,
        matches: verdict.matches.map(Match::name),
        explanation: &verdict.explanation,
        t: verdict.correct,
    };
    // serde_json fails only on a map with keys that are not strings or on a Serialize that
    // fails: the answer has neither.
    // untranslated: a message for a developer, never shown
    let text = crate::json_line(&answer);
    Ok((text, verdict))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_are_read_as_programs_print_them() {
        for text in [
            "0.1, -0.9, 0",
            "[0.1,-0.9,0]",
            "vec3(0.1, -0.9, 0.0)",
            "Vec3(0.1 -0.9 0)",
            "(0.1f, -0.9f, 0.0f);",
            "glm::vec3(0.1, -0.9, 0)",
        ] {
            assert_eq!(parse_t(text), Ok([0.1, -0.9, 0.0]), "{text}");
        }
        assert!(parse_t("nan, 0, 1").unwrap()[0].is_nan());
        assert!(parse_t("1, 2").unwrap_err().to_string().contains("found 2"));
        assert!(
            parse_t("1, x, 2")
                .unwrap_err()
                .to_string()
                .contains("\"x\" is not a number")
        );
    }

    fn along_ray(yours: [f64; 3]) -> TVerdict {
        let request = Request {
            w: [0.6, -0.8, 0.0],
            n: [0.0, 1.0, 0.0],
            mu_i: 1.0,
            mu_t: 1.5,
            convention: refraction_kernel::Convention::AlongRay,
            precision: Precision::F64,
        };
        check_t(&request, yours).unwrap()
    }

    #[test]
    fn vectors_of_any_length_are_judged_by_direction() {
        assert_eq!(parse_t("inf, 0, 0"), Ok([f64::INFINITY, 0.0, 0.0]));
        let right = glam::DVec3::from_array(along_ray([0.4, -0.9, 0.0]).correct.unwrap());
        // 6e-6 rad off and 1e201 long: near the refracted ray, not 90 degrees from it.
        let off = (right + glam::DVec3::new(right.y, -right.x, 0.0) * 6e-6) * 1e201;
        let verdict = along_ray(off.to_array());
        assert_eq!(
            verdict.matches,
            Some(Match::Chosen),
            "{}",
            verdict.explanation
        );
        assert!(
            verdict.explanation.contains("length 1e201"),
            "{}",
            verdict.explanation
        );
        let tiny = along_ray((right * 4e-320).to_array());
        assert_eq!(tiny.matches, Some(Match::Chosen), "{}", tiny.explanation);
        assert!(!tiny.explanation.contains("zero vector"));
    }

    #[test]
    fn a_verdict_is_explained_in_the_threads_language_with_its_decimal_comma() {
        let right = glam::DVec3::from_array(along_ray([0.4, -0.9, 0.0]).correct.unwrap());
        let long = (right * 1.5).to_array();
        refraction_i18n::set_locale(refraction_i18n::Locale::De);
        let german = along_ray(long);
        let wrong_side = along_ray([right.x, -right.y, 0.0]);
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
        assert_eq!(german.matches, Some(Match::Chosen));
        assert!(
            german
                .explanation
                .starts_with("Dein T zeigt entlang des gebrochenen Strahls")
                && german
                    .explanation
                    .contains("hat dein T die Länge 1,5, nicht 1"),
            "{}",
            german.explanation
        );
        assert!(
            wrong_side
                .explanation
                .starts_with("Dein T läuft zurück in das Medium"),
            "{}",
            wrong_side.explanation
        );
        let english = along_ray(long);
        assert!(
            english.explanation.contains("your T has length 1.5, not 1"),
            "{}",
            english.explanation
        );
    }

    #[test]
    fn a_t_normal_to_the_plane_of_incidence_has_a_finite_angle() {
        for k in 1..400 {
            let angle = f64::from(k) * 0.22_f64.to_radians();
            let (w, n) = ([angle.sin(), -angle.cos(), 0.0], [0.0, 1.0, 0.0]);
            let request = Request {
                w,
                n,
                mu_i: 1.0,
                mu_t: 1.33,
                convention: refraction_kernel::Convention::AlongRay,
                precision: Precision::F64,
            };
            let verdict = check_t(&request, [0.0, 0.0, 1.0 + f64::from(k) * 1e-3]).unwrap();
            assert!(
                !verdict.explanation.contains("NaN"),
                "{}",
                verdict.explanation
            );
        }
    }
}

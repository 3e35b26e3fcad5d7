//! "Check my T": which of the four candidates a student's refracted ray is, and the sign choice
//! or convention mix-up that produces it, in words a student understands.

use serde::Serialize;
use serde_json::Value;

use crate::lines::solve::{Precision, Request};
use refraction_kernel::{Incidence, Real, Rejection, Vector3, refract};

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
pub struct Verdict {
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

fn explain(rejection: Rejection) -> &'static str {
    match rejection {
        Rejection::WrongSide => {
            "Your T goes back into the medium the ray came from: the other root for b (+ where \
             the square root needs -). The usual cause is a normal that points along the ray, \
             such as a sphere's outward normal where the ray leaves it, used without flipping."
        }
        Rejection::WrongBend => {
            "Your T bends the wrong way: the sign of a is flipped, so it would not become the \
             incoming ray as mu -> 1. The usual cause is mixing the conventions: W pointing back \
             to the origin (Section 1, a = -mu) fed to the along-the-ray formula (Section 2, \
             a = +mu), or the other way round."
        }
        Rejection::Reversed => {
            "Your T is -T, pointing back where the ray came from: both signs are wrong. The \
             usual cause is returning the direction toward the origin instead of the direction \
             of travel, or negating W twice."
        }
    }
}

fn angle(a: glam::DVec3, b: glam::DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

fn wide<S: Real>(v: S::Vec3) -> glam::DVec3 {
    glam::DVec3::from_array(v.to_array().map(Real::to_f64))
}

fn verdict_in<S: Real>(incidence: &Incidence<S>, yours: [f64; 3]) -> Result<Verdict, String> {
    let r = refract(incidence).map_err(|e| e.to_string())?;
    let (ok, matches, explanation) = if yours.iter().any(|c| !c.is_finite()) {
        (false, None, not_finite(r.is_tir()).to_owned())
    } else if r.is_tir() {
        totally_reflected::<S>(&r, glam::DVec3::from_array(yours))
    } else {
        refracted::<S>(incidence, &r, glam::DVec3::from_array(yours))
    };
    Ok(Verdict {
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
fn not_finite(tir: bool) -> &'static str {
    if tir {
        "Your T has NaN or infinite components. This ray is totally internally reflected \
         (k < 0): your code took the square root of a negative k instead of checking k first."
    } else {
        "Your T has NaN or infinite components although this ray refracts normally (k >= 0): \
         look for a division by zero or an un-initialised vector."
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
            "Right: this ray is totally internally reflected (k < 0) and your code returned \
             the reflection (or the zero vector GLSL uses to say so)."
                .to_owned(),
        );
    }
    (
        false,
        None,
        format!(
            "This ray is totally internally reflected (k = {:.4} < 0): there is no refracted \
             ray, but your code returned one. Check k before taking its square root.",
            r.k.to_f64()
        ),
    )
}

/// A finite T for a ray that refracts: the candidate it matches or why it matches none, with a
/// note when it is not unit length.
fn refracted<S: Real>(
    incidence: &Incidence<S>,
    r: &refraction_kernel::Refraction<S>,
    yours: glam::DVec3,
) -> Judgement {
    let length = yours.length();
    if length == 0.0 {
        return (
            false,
            None,
            "Your T is the zero vector, which GLSL returns for total internal reflection, but \
             this ray refracts (k >= 0). Check the sign of k and the index ratio."
                .to_owned(),
        );
    }
    let unit_note = ((length - 1.0).abs() > LENGTH_TOLERANCE).then(|| {
        format!(
            " Also, your T has length {length:.4}, not 1: normalise W and N before refracting \
             (the formula assumes unit vectors) or T after."
        )
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
        None => (false, None, diagnose_unmatched::<S>(incidence, r, yours)),
    };
    (ok, matches, text + unit_note.as_deref().unwrap_or(""))
}

/// The verdict on a T within [`MATCH_ANGLE`] (`off` radians) of the candidate that breaks
/// `rejection` (`None`: the refracted ray), and that is or is not unit length.
fn matched(rejection: Option<Rejection>, off: f64, not_unit: bool) -> (bool, Match, String) {
    match rejection {
        None if not_unit => (
            false,
            Match::Chosen,
            format!("Your T points along the refracted ray (within {off:.1e} rad)."),
        ),
        None => (
            true,
            Match::Chosen,
            format!("Right: your T is the refracted ray (within {off:.1e} rad)."),
        ),
        Some(rejection) => (
            false,
            Match::Rejected(rejection),
            explain(rejection).to_owned(),
        ),
    }
}

/// Why a T that matches no candidate is wrong: a swapped index ratio, a T outside the plane of
/// incidence, or simply how far it is from the right answer.
fn diagnose_unmatched<S: Real>(
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
        return "Your T is the refraction with the index ratio upside down: mu must be mu_i/mu_t \
                (the medium the ray leaves over the one it enters), and your code used mu_t/mu_i."
            .to_owned();
    }
    let plane = wide::<S>(r.travel).cross(wide::<S>(r.facing_normal));
    let out_of_plane = yours.normalize().dot(plane).abs();
    if plane.length() > 1e-9 && out_of_plane > MATCH_ANGLE * plane.length() {
        return format!(
            "Your T leaves the plane of incidence (the plane of W and N) by {:.3} rad: T must be \
             a combination a*W + b*N of the two.",
            (out_of_plane / plane.length()).asin()
        );
    }
    let off = r.t().map_or(f64::NAN, |t| angle(yours, wide::<S>(t)));
    format!(
        "Your T matches none of the four sign choices: it is {:.2} degrees from the refracted \
         ray. Check mu, and which way W and N point.",
        off.to_degrees()
    )
}

/// Judges `yours` as the refraction asked for by `request`.
///
/// # Errors
/// The request cannot be refracted (see [`Request::incidence`] and [`refract`]).
pub fn check(request: &Request, yours: [f64; 3]) -> Result<Verdict, String> {
    match request.precision {
        Precision::F32 => verdict_in(&request.incidence::<f32>()?, yours),
        Precision::F64 => verdict_in(&request.incidence::<f64>()?, yours),
    }
}

/// Reads a 3-vector written the way programs print them: `0.1, -0.9, 0`, `[0.1,-0.9,0]`,
/// `(0.1 -0.9 0)`, `vec3(0.1, -0.9, 0.0)`, `Vec3(0.1, -0.9, 0.0)`, with `nan` and `inf` allowed.
///
/// # Errors
/// A message saying what was found instead of three numbers.
pub fn parse_vector(text: &str) -> Result<[f64; 3], String> {
    let trimmed = text.trim();
    let body = trimmed
        .find(['(', '['])
        .filter(|&open| {
            trimmed[..open]
                .chars()
                .all(|c| c.is_alphanumeric() || c == ':' || c == '_')
        })
        .map_or(trimmed, |open| &trimmed[open + 1..]);
    let body = body.trim_end().trim_end_matches([')', ']', ';']);
    let numbers: Vec<&str> = body
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|s| !s.is_empty())
        .collect();
    if numbers.len() != 3 {
        return Err(format!(
            "expected 3 numbers such as `0.1, -0.9, 0` or `vec3(0.1, -0.9, 0.0)`, found {} in \
             \"{trimmed}\"",
            numbers.len()
        ));
    }
    let mut out = [0.0; 3];
    for (slot, word) in out.iter_mut().zip(&numbers) {
        let cleaned = word
            .trim_end_matches(['f', 'F'])
            .trim_end_matches("_f32")
            .trim_end_matches("_f64");
        *slot = cleaned
            .parse::<f64>()
            .map_err(|_| format!("\"{word}\" is not a number (in \"{trimmed}\")"))?;
    }
    Ok(out)
}

/// Reads the student's T from a JSON value: an array of 3 numbers (`null` entries count as NaN,
/// as loggers write it) or a string in any form [`parse_vector`] accepts.
///
/// # Errors
/// A message naming what was found instead.
pub fn vector_from_json(value: &Value) -> Result<[f64; 3], String> {
    match value {
        Value::String(text) => parse_vector(text),
        Value::Array(items) if items.len() == 3 => {
            let mut out = [0.0; 3];
            for (i, (slot, item)) in out.iter_mut().zip(items).enumerate() {
                *slot = match item {
                    Value::Null => f64::NAN,
                    other => other
                        .as_f64()
                        .ok_or_else(|| format!("`t_yours[{i}]` must be a number or null"))?,
                };
            }
            Ok(out)
        }
        Value::Array(items) => Err(format!(
            "`t_yours` must have exactly 3 numbers, got {}",
            items.len()
        )),
        _ => Err(
            "`t_yours` must be an array of 3 numbers or a string like \"0.1, -0.9, 0\"".to_owned(),
        ),
    }
}

/// The JSON answer of the `check` command for one verdict.
#[derive(Serialize)]
struct Answer<'a> {
    ok: bool,
    matches: Option<&'static str>,
    explanation: &'a str,
    t: Option<[f64; 3]>,
}

/// Reads one line of the `check` command: the `solve` fields plus `t_yours`.
///
/// # Errors
/// Malformed JSON, or a missing or ill-typed field; the message names it.
pub fn parse_line(line: &str) -> Result<(Request, [f64; 3]), String> {
    let value: Value =
        serde_json::from_str(line).map_err(|e| crate::lines::solve::json_error(&e))?;
    let request = Request::from_value(&value)?;
    let yours = value
        .get("t_yours")
        .ok_or_else(|| "missing field `t_yours` (the T your code produced)".to_owned())
        .and_then(vector_from_json)?;
    Ok((request, yours))
}

/// Answers one line of the `check` command: the `solve` fields plus `t_yours`.
///
/// # Errors
/// Why the line cannot be judged (malformed JSON, a missing or ill-typed field, bad input).
pub fn answer(line: &str) -> Result<(String, Verdict), String> {
    let (request, yours) = parse_line(line)?;
    let verdict = check(&request, yours)?;
    let text = serde_json::to_string(&Answer {
        ok: verdict.ok,
        matches: verdict.matches.map(Match::name),
        explanation: &verdict.explanation,
        t: verdict.correct,
    })
    .map_err(|e| e.to_string())?;
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
            assert_eq!(parse_vector(text), Ok([0.1, -0.9, 0.0]), "{text}");
        }
        assert!(parse_vector("nan, 0, 1").unwrap()[0].is_nan());
        assert!(parse_vector("1, 2").unwrap_err().contains("found 2"));
        assert!(
            parse_vector("1, x, 2")
                .unwrap_err()
                .contains("\"x\" is not a number")
        );
    }
}

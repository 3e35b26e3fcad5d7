//! Any renderer's own refraction (`check` without `--api`), judged against the physics: a line
//! carries the `solve` fields (`w`, `n`, `mu_i`, `mu_t`, or `entering` with `--inside` and
//! `--outside`), the T the student's code produced (`t_yours`, or nothing where it reported
//! total internal reflection) and, if logged, the `ratio` it used.
//!
//! The verdict is `check`'s (which of the four candidates the T is). The mistakes are the ones
//! whose refraction reproduces the T: with T = μ·d + b·n for the normal n facing the ray and
//! b = μ·cosθi − √k, eta upside down is μ → 1/μ, the other root (or an outward normal where the
//! ray leaves) is b → μ·cosθi + √k, the term along the normal with the wrong sign is b → −b,
//! a reversed incident vector mirrors T across the normal, and a ray from inside refracted
//! without turning the normal and inverting the ratio is the other root at 1/μ.

use glam::DVec3;
use refraction_i18n::t;
use refraction_kernel::{Convention, Incidence, Refraction, refract};
use serde::Serialize;

use super::call::Options;
use super::error::{LineError, Role};
use super::record::{Record, Value};
use crate::diagnosis::Code;
use crate::diagnosis::formula::{self, Outcome, Situation};
use crate::diagnosis::{self, Codes, Evidence, Missing, Readings, Side, Told};
use refraction_model::log_map::{self, LinePoint};
use refraction_tools::vector_text::{angle, length, spoken};
use refraction_tools::{
    CheckAnswer, LENGTH_TOLERANCE, MATCH_ANGLE, Match, Precision, Request, TVerdict, check_t,
};

/// One line of any renderer's log, ready to judge.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The problem: W, N, the indices, the convention and the precision.
    pub request: Request,
    /// The T the student's code produced; `None` where it reported total internal reflection
    /// (a null `t_yours`).
    pub yours: Option<[f64; 3]>,
    /// The ratio the code used, if logged.
    pub ratio: Option<f64>,
    /// Whether the ray enters the object, if logged.
    pub entering: Option<bool>,
    /// The coarsest relative rounding of the printed `w`, `n` and `t_yours` (half a unit in
    /// their last digit; 0 where they say exact values).
    pub rounding: f64,
}

fn vector(record: &Record, name: &str) -> Option<[f64; 3]> {
    match record.get(name) {
        Some(Value::Vector(v)) => Some(*v),
        _ => None,
    }
}

fn number(record: &Record, name: &str) -> Option<f64> {
    match record.get(name) {
        Some(Value::Number(x)) => Some(*x),
        _ => None,
    }
}

fn label(record: &Record, name: &str) -> Option<String> {
    match record.get(name) {
        Some(Value::Label(text)) => Some(text.clone()),
        _ => None,
    }
}

/// The indices a line gives: `mu_i` and `mu_t`, else `from` and `to`, else `entering` with the
/// indices inside and outside.
fn indices(
    record: &Record,
    entering: Option<bool>,
    sides: Option<(f64, f64)>,
) -> Option<(f64, f64)> {
    let given = |a, b| number(record, a).zip(number(record, b));
    given("mu_i", "mu_t")
        .or_else(|| given("from", "to"))
        .or_else(|| {
            let (inside, outside) = sides?;
            Some(if entering? {
                (outside, inside)
            } else {
                (inside, outside)
            })
        })
}

impl Case {
    /// The case a record describes, with `--inside`, `--outside` and `--precision` from
    /// `options`.
    ///
    /// # Errors
    /// A missing `w`, `n` or `t_yours`, no indices, or an unknown convention or precision.
    pub fn from_record(record: &Record, options: &Options) -> Result<Self, LineError> {
        let required = |name: &str, role| {
            vector(record, name).ok_or_else(|| LineError::Missing {
                field: name.to_owned(),
                role,
            })
        };
        let w = required("w", Role::Incident)?;
        let convention = match label(record, "convention") {
            None => options.convention.unwrap_or_default(),
            Some(name) => {
                Convention::from_name(&name).ok_or(LineError::UnknownConvention { text: name })?
            }
        };
        // A normal the line does not print is `--normal`'s, the outward one: it tells the side.
        let (n, outward) = match (vector(record, "n"), options.normal) {
            (Some(n), _) => (n, None),
            (None, Some(n)) => (n, Some(n)),
            (None, None) => (required("n", Role::Normal)?, None),
        };
        let entering = match record.get("entering") {
            Some(Value::Flag(b)) => Some(*b),
            _ => outward.map(|n| {
                let along = DVec3::from_array(w).dot(DVec3::from_array(n));
                (along < 0.0) == (convention == Convention::AlongRay)
            }),
        };
        let (mu_i, mu_t) =
            indices(record, entering, options.sides()).ok_or(LineError::NoIndices)?;
        let precision = match label(record, "precision").as_deref() {
            None => options.precision.unwrap_or_default(),
            Some("f64" | "double") => Precision::F64,
            Some("f32" | "float") => Precision::F32,
            Some(other) => {
                let text = other.to_owned();
                return Err(LineError::UnknownPrecision { text });
            }
        };
        let yours = match record.get("t_yours") {
            Some(Value::Null) => None,
            _ => Some(required("t_yours", Role::YourT)?),
        };
        Ok(Self {
            request: Request {
                w,
                n,
                mu_i,
                mu_t,
                convention,
                precision,
            },
            yours,
            ratio: number(record, "ratio"),
            entering,
            rounding: rounding(record),
        })
    }
}

/// The coarsest relative rounding of `record`'s printed `w`, `n` and `t_yours`: a short
/// number (`0.6`) beside longer vectors is the value it says (see
/// [`Tolerance::loose`](super::readings::Tolerance::loose)).
fn rounding(record: &Record) -> f64 {
    let written = ["w", "n", "t_yours"].map(|name| record.written(name));
    let finest = written.iter().map(|w| w.digits).filter(|&d| d < 17).max();
    let fixed = finest.unwrap_or(0) <= super::readings::FIXED_FORMAT_DIGITS;
    written
        .iter()
        .map(|w| {
            let decimal = w.decimal && (w.digits > 2 || fixed);
            super::readings::loose_rounding(w.digits, decimal)
        })
        .fold(0.0, f64::max)
}

/// The refraction for ratio `mu` of a ray travelling along unit `d` onto the unit normal `n`
/// facing it (cosθi = `c`): T = μ·d + b·n, with b from `root` (−1: the physical root).
fn transmitted(d: DVec3, n: DVec3, c: f64, mu: f64, root: f64) -> Option<DVec3> {
    let k = 1.0 - mu * mu * (1.0 - c * c);
    (k >= 0.0).then(|| mu * d + (mu * c + root * k.sqrt()) * n)
}

/// What the code gives with each mistake, for the right refraction `r` (the ray from inside
/// when `leaving`): the mistakes and the direction (`None`: total internal reflection).
fn predictions(r: &Refraction<f64>, leaving: bool) -> Vec<(Vec<Code>, Option<DVec3>)> {
    let (d, n, c, mu) = (r.travel, r.facing_normal, r.cos_i, r.mu);
    let bend = |t: Option<DVec3>| t.map(|t| 2.0 * t.dot(n) * n - t);
    let term = |m: f64| transmitted(d, n, c, m, -1.0).map(|t| 2.0 * m * d - t);
    let mut out = vec![
        (
            vec![Code::EtaInverted],
            transmitted(d, n, c, 1.0 / mu, -1.0),
        ),
        (vec![Code::OtherRoot], transmitted(d, n, c, mu, 1.0)),
        (vec![Code::NormalNotFacing], transmitted(d, n, c, mu, 1.0)),
        (vec![Code::NormalTermSign], term(mu)),
        (
            vec![Code::IncidentReversed],
            bend(transmitted(d, n, c, mu, -1.0)),
        ),
        (
            vec![Code::IncidentReversed, Code::NormalNotFacing],
            transmitted(d, n, c, mu, -1.0).map(|t| -t),
        ),
        (
            vec![Code::EtaInverted, Code::OtherRoot],
            transmitted(d, n, c, 1.0 / mu, 1.0),
        ),
        (
            vec![Code::EtaInverted, Code::IncidentReversed],
            bend(transmitted(d, n, c, 1.0 / mu, -1.0)),
        ),
        (
            vec![Code::EtaInverted, Code::NormalTermSign],
            term(1.0 / mu),
        ),
    ];
    if leaving {
        out.push((
            vec![Code::NoFlipInside],
            transmitted(d, n, c, 1.0 / mu, 1.0),
        ));
    }
    out
}

/// Whether `yours` is direction `t` (any length), or "nothing" where `t` is `None`.
fn same(yours: Option<DVec3>, t: Option<DVec3>) -> bool {
    match (yours, t) {
        (Some(y), Some(t)) => length(y) > 0.0 && angle(y, t) <= MATCH_ANGLE,
        (None, None) => true,
        _ => false,
    }
}

/// Whether `yours` is the refraction `r` done twice at one crossing: μ applied twice, T
/// refracted with μ².
fn refracted_twice(yours: Option<DVec3>, r: &Refraction<f64>) -> bool {
    let squared = transmitted(r.travel, r.facing_normal, r.cos_i, r.mu * r.mu, -1.0);
    same(yours, squared)
}

/// The explanations of a line that is wrong: the mistakes whose refraction reproduces what
/// came back, the fewest first; a missed or false total internal reflection where nothing
/// else does; the ratio the code logged, where it is the inverse of the right one.
fn alternatives(case: &Case, r: &Refraction<f64>, verdict: &TVerdict) -> Vec<Vec<Code>> {
    let yours = case
        .yours
        .map(DVec3::from_array)
        .filter(|y| *y != DVec3::ZERO && !(r.is_tir() && verdict.ok));
    let leaving = case.entering == Some(false);
    let twice = refracted_twice(yours, r);
    let mut found: Vec<Vec<Code>> = predictions(r, leaving)
        .into_iter()
        .filter(|(_, t)| same(yours, *t))
        .map(|(codes, _)| codes)
        .collect();
    found.sort_by_key(Vec::len);
    if let Some(fewest) = found.first().map(Vec::len) {
        found.retain(|codes| codes.len() == fewest);
    }
    let inverse_ratio = case.ratio.is_some_and(|ratio| {
        r.mu != 1.0 && (ratio * r.mu - 1.0).abs() <= 1e-4 * ratio.abs().max(1.0)
    });
    if inverse_ratio {
        found.retain(|codes| codes.contains(&Code::EtaInverted));
        if found.is_empty() {
            found.push(vec![Code::EtaInverted]);
        }
    }
    if found.is_empty() && !(twice && yours.is_some()) {
        let unit_length = yours.is_some_and(|y| {
            (length(y) - 1.0).abs() > LENGTH_TOLERANCE && verdict.matches == Some(Match::Chosen)
        });
        found.push(vec![match (r.is_tir(), yours) {
            _ if unit_length => Code::NotTheApiResult,
            (true, Some(_)) => Code::MissedTir,
            (false, None) => Code::FalseTir,
            _ => Code::NotTheApiResult,
        }]);
    }
    if twice && !inverse_ratio {
        found.push(vec![Code::RefractedTwice]);
    }
    found
}

/// The verdict on one line of any renderer's log.
#[derive(Clone, Debug, PartialEq)]
pub struct Judged {
    /// `check`'s verdict: the candidate the T is, or why it is none.
    pub verdict: TVerdict,
    /// The mistakes that explain it, each set a reading, the likeliest first (empty when
    /// right).
    pub alternatives: Vec<Vec<Code>>,
    /// What the diagnosis of the whole log needs from it, but its views ([`Judged::evidence`]).
    pub evidence: Evidence,
    /// What its views are made from.
    pub readings: Readings,
    /// The line on the log's failure map.
    pub point: LinePoint,
}

impl Judged {
    /// What the diagnosis of the whole log needs from the line, its views worked out.
    #[must_use]
    pub fn evidence(&self) -> Evidence {
        Evidence {
            views: self.readings.views(),
            ..self.evidence.clone()
        }
    }

    /// Every mistake of every reading, each once.
    #[must_use]
    pub fn mistakes(&self) -> Vec<Code> {
        let mut all: Vec<Code> = Vec::new();
        for code in self.alternatives.iter().flatten() {
            if !all.contains(code) {
                all.push(*code);
            }
        }
        all
    }
}

/// The case on the log's failure map: the student's code sends the ray along its T, or
/// reflects it where it reported total internal reflection.
fn map_point(case: &Case, r: &Refraction<f64>, evidence: &Evidence) -> LinePoint {
    let sent = case.yours.map_or(r.reflected, DVec3::from_array);
    let right = r.t().unwrap_or(r.reflected);
    LinePoint {
        incidence_deg: log_map::incidence_deg(r.travel, r.facing_normal),
        error_deg: log_map::angle_deg(sent, right),
        side: evidence.side,
        past_critical: evidence.past_critical,
        ok: evidence.ok,
    }
}

/// What a line's views are made from: the ratio the code logged, if upside down, as its
/// argument mistake, the situation, and what the code sent the ray along.
fn readings(case: &Case, r: &Refraction<f64>, right: bool, logged: Outcome) -> Readings {
    let situation = Situation {
        travel: r.travel,
        normal: r.facing_normal,
        mu: r.mu,
    };
    let arguments = match case.ratio {
        Some(ratio) if (ratio * r.mu - 1.0).abs() <= 1e-4 * ratio.abs().max(1.0) && r.mu != 1.0 => {
            Codes::of(&[Code::EtaInverted])
        }
        Some(ratio) if (ratio / r.mu - 1.0).abs() > 1e-4 => Codes::of(&[Code::NotTheApiResult]),
        _ => Codes::default(),
    };
    Readings {
        situations: vec![(arguments, situation)],
        outcome: logged,
        right,
        tolerance: MATCH_ANGLE,
    }
}

/// What the code sent the ray along: nothing for a null, zero or non-finite T.
fn logged(case: &Case) -> Outcome {
    match case.yours.map(DVec3::from_array) {
        Some(y) if y.is_finite() && y != DVec3::ZERO => Outcome::Direction(y),
        _ => Outcome::Nothing,
    }
}

/// The sentence for a judged case: a sampled reflection's chance (`sampled`, when the line
/// is right), the mistakes that would give the wrong line (`first`, the likeliest), or the
/// verdict's own words.
fn explanation(
    verdict: &TVerdict,
    ok: bool,
    first: Option<&Vec<Code>>,
    sampled: Option<f64>,
) -> String {
    match (first, sampled) {
        (_, Some(f)) if ok => t!("check-physics-sampled", f = spoken(f)),
        (Some(codes), None) if !ok && verdict.matches.is_none() => {
            let meanings: Vec<String> = codes.iter().map(|c| c.meaning()).collect();
            let mistakes = meanings.join("; ");
            let said = t!("check-physics-explained", mistakes = mistakes);
            format!("{} {said}", verdict.explanation)
        }
        _ => verdict.explanation.clone(),
    }
}

/// Judges one case.
///
/// # Errors
/// The problem cannot be refracted (a zero vector, an index that is not positive).
pub(crate) fn judge(case: &Case) -> Result<Judged, LineError> {
    let nothing = [0.0; 3];
    let verdict = check_t(&case.request, case.yours.unwrap_or(nothing))?;
    let r = refract(&Incidence::<f64> {
        w: DVec3::from_array(case.request.w),
        n: DVec3::from_array(case.request.n),
        mu_i: case.request.mu_i,
        mu_t: case.request.mu_t,
        convention: case.request.convention,
    })?;
    let wrong_ratio = case
        .ratio
        .is_some_and(|ratio| (ratio / r.mu - 1.0).abs() > 1e-4);
    let logged = logged(case);
    // Nothing where the ray refracts: a reflection the renderer may have sampled.
    let sampled = (!r.is_tir() && logged == Outcome::Nothing).then(|| {
        formula::reflectance(&Situation {
            travel: r.travel,
            normal: r.facing_normal,
            mu: r.mu,
        })
    });
    let ok = (verdict.ok || sampled.is_some()) && !wrong_ratio;
    let undecided = !ok && !wrong_ratio && digits_allow(case, logged);
    let alternatives = if ok || undecided {
        Vec::new()
    } else {
        alternatives(case, &r, &verdict)
    };
    let evidence = Evidence {
        // Not a wrong line: counted with the lines its log cannot check.
        ok: ok || undecided,
        alternatives: if ok && sampled.is_some() {
            diagnosis::sampled_alternatives(refracted_twice(None, &r))
        } else {
            alternatives.clone()
        },
        views: Vec::new(),
        side: case
            .entering
            .map(|e| if e { Side::Outside } else { Side::Inside }),
        past_critical: r.is_tir(),
        normal_outward: None,
        normal_faces: None,
        band: diagnosis::band(log_map::incidence_deg(r.travel, r.facing_normal)),
        transmitted: matches!(logged, Outcome::Direction(_)) && !(r.is_tir() && verdict.ok),
        sample: sampled.map(f64::ln),
        unchecked: undecided.then_some(Missing::Digits),
        told: Told {
            entering: case.entering.is_some(),
            travel: true,
        },
    };
    let explanation = if undecided {
        super::explain::undecided("")
    } else {
        explanation(&verdict, ok, alternatives.first(), sampled)
    };
    let point = map_point(case, &r, &evidence);
    let readings = readings(case, &r, ok && sampled.is_none(), logged);
    Ok(Judged {
        verdict: TVerdict {
            ok,
            explanation,
            matches: if ok && sampled.is_some() {
                None
            } else {
                verdict.matches
            },
            ..verdict
        },
        alternatives,
        evidence,
        readings,
        point,
    })
}

/// Whether the printed digits allow `case`'s line to be right: some `w` and `n` within their
/// rounding (each component moved both ways, and `w` along the normal, which moves cosθi and
/// k the most) refract to what was logged, within the spread that rounding makes and the
/// result's own rounding. Lines printed with their exact values (rounding 0) are not looked
/// at again.
fn digits_allow(case: &Case, logged: Outcome) -> bool {
    let step = 2.0 * case.rounding;
    if step == 0.0 {
        return false;
    }
    let (w, n) = (
        DVec3::from_array(case.request.w),
        DVec3::from_array(case.request.n),
    );
    let nudged = |v: DVec3, axis: DVec3| v + axis * (step * v.length());
    let mut moved = vec![(w, n)];
    for axis in [DVec3::X, DVec3::Y, DVec3::Z, n.normalize_or_zero()] {
        for sign in [1.0, -1.0] {
            moved.push((nudged(w, sign * axis), n));
            moved.push((w, nudged(n, sign * axis)));
        }
    }
    let results: Vec<Option<DVec3>> = moved
        .iter()
        .map(|&(w, n)| {
            let r = refract(&Incidence::<f64> {
                w,
                n,
                mu_i: case.request.mu_i,
                mu_t: case.request.mu_t,
                convention: case.request.convention,
            })
            .ok()?;
            r.transmission.map(|t| t.t)
        })
        .collect();
    let directions: Vec<DVec3> = results.iter().flatten().copied().collect();
    match logged {
        Outcome::Nothing => results.iter().any(Option::is_none),
        Outcome::Direction(v) => {
            let spread = directions
                .iter()
                .flat_map(|a| directions.iter().map(move |b| (*a - *b).length()))
                .fold(0.0, f64::max);
            let allowed = spread + 4.0 * case.rounding * v.length().max(1.0);
            directions.iter().any(|t| (v - *t).length() <= allowed)
        }
    }
}

/// The JSON answer for one line: `check`'s fields and the mistakes.
#[derive(Serialize)]
struct Answer<'a> {
    #[serde(flatten)]
    verdict: CheckAnswer<'a>,
    mistakes: Vec<&'static str>,
    alternatives: Vec<Vec<&'static str>>,
}

/// The answer line for a judged case.
#[must_use]
pub(crate) fn answer_line(judged: &Judged) -> String {
    let v = &judged.verdict;
    let answer = Answer {
        verdict: CheckAnswer {
            ok: v.ok,
            matches: v.matches.map(Match::name),
            explanation: &v.explanation,
            t: v.correct,
        },
        mistakes: judged.mistakes().iter().map(|c| c.name()).collect(),
        alternatives: judged
            .alternatives
            .iter()
            .map(|a| a.iter().map(|c| c.name()).collect())
            .collect(),
    };
    // serde_json fails only on a map with keys that are not strings or on a Serialize that
    // fails: the answer has neither.
    // untranslated: a message for a developer, never shown
    refraction_tools::json_line(&answer)
}

/// The kind of a verdict as `check`'s tally counts it: `ok`, the candidate it matches, or why
/// it matches none.
#[must_use]
pub(crate) fn tally_kind(judged: &Judged) -> &'static str {
    let v = &judged.verdict;
    match (v.ok, v.matches) {
        (false, _) if judged.evidence.unchecked == Some(Missing::Digits) => super::UNDECIDED,
        (true, _) if judged.evidence.sample.is_some() => super::SAMPLED,
        (true, _) => "ok",
        // The right direction from the wrong logged ratio, or of the wrong length.
        (false, Some(Match::Chosen)) if judged.mistakes().contains(&Code::EtaInverted) => {
            Code::EtaInverted.name()
        }
        (false, Some(Match::Chosen)) => "not unit length",
        (false, Some(m)) => m.name(),
        (false, None) => "matching no candidate",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call_check::fields::Dialect;
    use refraction_tools::vector_text::unit;

    fn case(text: &str) -> Case {
        let record = Record::from_json_line(Dialect::Physics, text).unwrap();
        let options = Options {
            inside: Some(1.5),
            outside: Some(1.0),
            ..Options::new(Dialect::Physics)
        };
        Case::from_record(&record, &options).unwrap()
    }

    /// A ray at `degrees` from the normal, from glass (`leaving`) or into it, and what each
    /// mistake gives.
    fn logged(degrees: f64, leaving: bool, mistake: &[Code]) -> String {
        let a = degrees.to_radians();
        let d = DVec3::new(a.sin(), if leaving { a.cos() } else { -a.cos() }, 0.0);
        let n = DVec3::Y; // the outward normal
        let (mu_i, mu_t) = if leaving { (1.5, 1.0) } else { (1.0, 1.5) };
        let r = refract(&Incidence::<f64> {
            w: d,
            n,
            mu_i,
            mu_t,
            convention: Convention::AlongRay,
        })
        .unwrap();
        let t = if mistake.is_empty() {
            r.t()
        } else {
            predictions(&r, leaving)
                .into_iter()
                .find(|(codes, _)| codes == mistake)
                .and_then(|(_, t)| t)
        };
        serde_json::json!({
            "w": d.to_array(), "n": n.to_array(), "entering": !leaving,
            "t_yours": t.map(|t| unit(t).to_array()),
        })
        .to_string()
    }

    #[test]
    fn a_right_line_is_ok_and_each_mistake_is_named() {
        for leaving in [false, true] {
            let judged = judge(&case(&logged(20.0, leaving, &[]))).unwrap();
            assert!(judged.verdict.ok, "{judged:?}");
            for mistake in [
                [Code::EtaInverted].as_slice(),
                &[Code::NormalTermSign],
                &[Code::IncidentReversed],
            ] {
                let judged = judge(&case(&logged(20.0, leaving, mistake))).unwrap();
                assert!(!judged.verdict.ok, "{mistake:?}");
                assert!(
                    judged.alternatives.contains(&mistake.to_vec()),
                    "{mistake:?} {leaving}: {:?}",
                    judged.alternatives
                );
            }
        }
    }

    #[test]
    fn each_line_lands_on_the_failure_map_at_its_incidence_and_error() {
        let right = judge(&case(&logged(20.0, true, &[]))).unwrap().point;
        assert!(right.ok && right.error_deg < 1e-6, "{right:?}");
        assert!((right.incidence_deg - 20.0).abs() < 1e-9, "{right:?}");
        assert_eq!(right.side, Some(Side::Inside));
        let wrong = judge(&case(&logged(20.0, true, &[Code::NormalTermSign])))
            .unwrap()
            .point;
        assert!(!wrong.ok && wrong.error_deg > 10.0, "{wrong:?}");
        let past = judge(&case(&logged(60.0, true, &[]))).unwrap().point;
        assert!(
            past.ok && past.past_critical && past.error_deg < 1e-6,
            "{past:?}"
        );
    }

    #[test]
    fn the_other_root_ties_with_a_normal_that_does_not_face_the_ray() {
        let judged = judge(&case(&logged(30.0, false, &[Code::OtherRoot]))).unwrap();
        assert_eq!(
            judged.alternatives,
            [vec![Code::OtherRoot], vec![Code::NormalNotFacing]]
        );
    }

    #[test]
    fn no_flip_from_inside_is_the_other_root_at_the_entering_ratio() {
        let judged = judge(&case(&logged(20.0, true, &[Code::NoFlipInside]))).unwrap();
        assert!(
            judged.alternatives.contains(&vec![Code::NoFlipInside]),
            "{:?}",
            judged.alternatives
        );
        assert_eq!(judged.evidence.side, Some(Side::Inside));
    }

    #[test]
    fn a_t_past_the_critical_angle_is_a_missed_tir_unless_the_inverted_ratio_gives_it() {
        // Glass to air at 60°: the right answer is total internal reflection.
        let a = 60_f64.to_radians();
        let d = [a.sin(), a.cos(), 0.0];
        let straight = serde_json::json!({"w": d, "n": [0, 1, 0], "entering": false, "t_yours": d});
        let judged = judge(&case(&straight.to_string())).unwrap();
        assert_eq!(judged.alternatives, [vec![Code::MissedTir]]);
        assert!(judged.evidence.past_critical);
        let inverted = logged(60.0, true, &[Code::EtaInverted]);
        let judged = judge(&case(&inverted)).unwrap();
        assert_eq!(judged.alternatives, [vec![Code::EtaInverted]]);
        // Nothing came back where the ray refracts: a sampled reflection on the line (the
        // whole log tells), a false TIR for the diagnosis if the log never transmits there.
        let nothing = serde_json::json!({"w": [0.6, -0.8, 0], "n": [0, 1, 0], "entering": true, "t_yours": null});
        let judged = judge(&case(&nothing.to_string())).unwrap();
        assert!(
            judged.verdict.ok && judged.alternatives.is_empty(),
            "{judged:?}"
        );
        assert!(judged.verdict.explanation.contains("sampled"), "{judged:?}");
        assert_eq!(judged.evidence.alternatives, [vec![Code::FalseTir]]);
        assert!(judged.evidence.sample.is_some_and(|ln_f| ln_f < 0.0));
        assert_eq!(tally_kind(&judged), crate::call_check::SAMPLED);
    }

    #[test]
    fn a_logged_ratio_upside_down_is_wrong_even_where_t_is_right() {
        let mut line: serde_json::Value = serde_json::from_str(&logged(0.0, false, &[])).unwrap();
        line["ratio"] = serde_json::json!(1.5);
        let judged = judge(&case(&line.to_string())).unwrap();
        assert!(!judged.verdict.ok);
        assert_eq!(judged.alternatives, [vec![Code::EtaInverted]]);
    }

    #[test]
    fn indices_come_from_the_line_or_from_entering_and_the_sides() {
        let given = case(r#"{"w":[0,-1,0],"n":[0,1,0],"mu_i":1.33,"mu_t":1,"t_yours":[0,-1,0]}"#);
        assert_eq!((given.request.mu_i, given.request.mu_t), (1.33, 1.0));
        let sided = case(r#"{"w":[0,-1,0],"n":[0,1,0],"entering":0,"t_yours":[0,-1,0]}"#);
        assert_eq!((sided.request.mu_i, sided.request.mu_t), (1.5, 1.0));
        let record = Record::from_json_line(
            Dialect::Physics,
            r#"{"w":[0,-1,0],"n":[0,1,0],"t_yours":[0,-1,0]}"#,
        )
        .unwrap();
        assert!(Case::from_record(&record, &Options::new(Dialect::Physics)).is_err());
    }
}

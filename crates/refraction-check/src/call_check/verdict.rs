//! The verdict on one API call ([`verdict()`]): the result mistake (if any) and what the result
//! resembles, the readings of the arguments, the physically right T, and the answer's fields.
//! It judges the call alone; the evidence it gives ([`evidence`]) goes to
//! [`crate::diagnosis`], which names the one mistake behind the whole log.

use glam::DVec3;
use refraction_kernel::api::{Api, Args, Meaning};
use refraction_kernel::{Convention, Real};
use serde_json::Value as Json;

use super::call::{Call, Got};
use super::error::LineError;
use super::explain;
use super::readings::{Reading, Tolerance, readings, undo};
use super::result::{Resemblance, Returns, Seen, returns, transmitted_by};
use crate::diagnosis::Code;
use crate::diagnosis::formula::{self, Situation};
use crate::diagnosis::{self, Codes, Evidence, Missing, Readings, Side, Told};
use refraction_model::log_map::{self, LinePoint};
use refraction_tools::vector_text::{angle, length};
use refraction_tools::{MATCH_ANGLE, Match, Precision, Request, check_t};

/// The verdict on one API call, as [`check_record`](crate::check_record) gives it (the whole
/// log's mistake is the diagnosis's to name).
#[derive(Clone, Debug, PartialEq)]
pub struct CallVerdict {
    /// Whether the call is right: no mistakes.
    pub ok: bool,
    /// The mistakes of every equally good explanation, the likeliest first.
    pub mistakes: Vec<Code>,
    /// The equally good explanations, each a set of mistakes, the likeliest first.
    pub alternatives: Vec<Vec<Code>>,
    /// What happened, in the API's language.
    pub explanation: String,
    /// Which candidate of the physical refraction the result is.
    pub matches: Option<Match>,
    /// The physically right T (`None` on total internal reflection or when unknown).
    pub t: Option<[f64; 3]>,
    /// What the API returns for these arguments, in its own shape.
    pub api_result: Json,
    /// The right call's meaning under the likeliest explanation.
    pub right: Meaning<f64>,
    /// The direction the ray leaves this hit in, as the student's code sent it.
    pub outgoing: DVec3,
    /// What the line's views are made from, for the diagnosis of the whole log.
    pub readings: Readings,
    /// Mitsuba's F where `wo` is null although the API refracts: a sampled reflection if the
    /// call is right (the whole log tells whether it is one).
    pub sampled: Option<f64>,
    /// Whether the code sent the ray along a direction (not the API's "nothing transmitted").
    pub transmitted: bool,
    /// Whether the call cannot be told right or wrong from its printed digits: wrong as
    /// printed, but right for numbers within their rounding (a sign of N·I, of k or of a root
    /// that the digits do not decide). Never a mistake: `ok` is false and `mistakes` empty.
    pub undecided: bool,
}

/// The result mistake and what the result resembles, or `None` when it is the API's answer
/// (or, for a `sampled` null, may be).
fn finding<S: Real>(
    call: &Call,
    r: &Returns,
    seen: Seen,
    sampled: bool,
    tolerance: &Tolerance,
) -> Option<(Code, Resemblance)> {
    let direction = match seen {
        Seen::Nothing(_) if r.may_reflect() || sampled => None,
        Seen::Direction(v) if r.is_transmitted(v) => None,
        _ if without_flip(call, r, seen) => Some((Code::NoFlipInside, Resemblance::NoFlip)),
        Seen::NotFinite(_) if r.may_reflect() => Some((Code::MissedTir, Resemblance::NotFinite)),
        Seen::Direction(v) if r.transmitted.is_none() => {
            let formula = r.formula.is_some_and(|f| r.same(v, f));
            let looks = if formula {
                Resemblance::Formula
            } else {
                Resemblance::Direction
            };
            Some((Code::MissedTir, looks))
        }
        Seen::Nothing(what) => Some((Code::FalseTir, Resemblance::Nothing(what))),
        Seen::NotFinite(_) => Some((Code::NotTheApiResult, Resemblance::NotFinite)),
        Seen::Direction(v) => {
            let looks = resemblance::<S>(call, r, v);
            let code = match looks {
                Resemblance::OtherRoot => Code::OtherRoot,
                Resemblance::NormalTerm => Code::NormalTermSign,
                _ => Code::NotTheApiResult,
            };
            Some((code, looks))
        }
    };
    direction.or_else(|| etap_finding(call, r, tolerance))
}

/// What a formula returns: a direction, or that nothing is transmitted.
enum Outcome {
    Direction(DVec3),
    Nothing,
}

/// What pbrt's `Refract` returns for `args` without its `if (cosTheta_i < 0)` flip, for a ray
/// from the normal's far side; `None` otherwise or for another API.
fn unflipped(call: &Call) -> Option<Outcome> {
    let Args {
        incident: wi,
        normal: n,
        eta,
    } = call.args;
    let cos_i = n.dot(wi);
    if call.api != Api::Pbrt || cos_i >= 0.0 {
        return None;
    }
    let sin2_t = (1.0 - cos_i * cos_i).max(0.0) / (eta * eta);
    if sin2_t >= 1.0 {
        return Some(Outcome::Nothing);
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(Outcome::Direction(-wi / eta + n * (cos_i / eta - cos_t)))
}

/// Whether what came back is what the API gives without its flip, and not what it gives.
fn without_flip(call: &Call, r: &Returns, seen: Seen) -> bool {
    match (unflipped(call), seen) {
        (Some(Outcome::Direction(w)), Seen::Direction(v)) => r.same(v, w),
        (Some(Outcome::Nothing), Seen::Nothing(_)) => r.transmitted.is_some(),
        _ => false,
    }
}

/// pbrt's logged `etap` against the one its `Refract` used, where the direction is right.
fn etap_finding(call: &Call, r: &Returns, tolerance: &Tolerance) -> Option<(Code, Resemblance)> {
    let (logged, used) = (call.etap?, r.etap?);
    if tolerance.same_ratio(logged, used) {
        return None;
    }
    let never_inverted = unflipped(call).is_some() && tolerance.same_ratio(logged, call.args.eta);
    Some(if never_inverted {
        (Code::NoFlipInside, Resemblance::NoFlip)
    } else {
        (Code::NotTheApiResult, Resemblance::Etap { logged, used })
    })
}

/// What a wrong direction `v` is, where the API refracts.
fn resemblance<S: Real>(call: &Call, r: &Returns, v: DVec3) -> Resemblance {
    let p = r
        .transmitted
        .or_else(|| r.nearby.iter().flatten().next().copied())
        .unwrap_or(DVec3::ZERO);
    let n = refraction_tools::vector_text::unit(call.api.meaning(call.args).normal);
    let along = n * (2.0 * p.dot(n));
    let shapes = [
        (p - along, Resemblance::OtherRoot),
        (along - p, Resemblance::WrongBend),
        (-p, Resemblance::Reversed),
        (r.reflection, Resemblance::Reflection),
    ];
    if let Some((_, shape)) = shapes.iter().find(|(w, _)| r.same(v, *w)) {
        return *shape;
    }
    // μ·d + b·n with b negated: μ·d − b·n = 2μ·d − (μ·d + b·n), as written or normalised.
    let meaning = call.api.meaning(call.args);
    let term = 2.0 * meaning.mu * refraction_tools::vector_text::unit(meaning.travel) - p;
    if r.same(v, term) || r.same(v, refraction_tools::vector_text::unit(term)) {
        return Resemblance::NormalTerm;
    }
    let variants = [
        Code::EtaInverted,
        Code::NormalNotFacing,
        Code::IncidentReversed,
    ];
    for code in variants {
        let other = transmitted_by::<S>(call.api, undo(&[code], call.args));
        if other.is_some_and(|w| r.same(v, w)) {
            return Resemblance::Variant(code);
        }
    }
    if angle(v, p) <= r.distance {
        Resemblance::Length(length(v) / length(p))
    } else {
        Resemblance::Off(angle(v, p).to_degrees())
    }
}

/// The candidate the result is and the right T, from the project's own kernel.
fn physical(meaning: &Meaning<f64>, got: Got) -> (Option<Match>, Option<[f64; 3]>) {
    let request = Request {
        w: meaning.travel.to_array(),
        n: meaning.normal.to_array(),
        mu_i: meaning.mu,
        mu_t: 1.0,
        convention: Convention::AlongRay,
        precision: Precision::F64,
    };
    let yours = match got {
        Got::Vector(v) => v.to_array(),
        Got::Nothing => [0.0; 3],
    };
    check_t(&request, yours).map_or((None, None), |v| (v.matches, v.correct))
}

/// The explanations as sets of codes, and all their codes in order.
fn alternatives(readings: &[Reading], result: Option<Code>) -> (Vec<Vec<Code>>, Vec<Code>) {
    let mut sets: Vec<Vec<Code>> = readings
        .iter()
        .map(|r| r.codes.iter().copied().chain(result).collect())
        .collect();
    if sets.is_empty() {
        sets.push(result.into_iter().collect());
    }
    sets.retain(|s| !s.is_empty());
    let mut all: Vec<Code> = Vec::new();
    for code in sets.iter().flatten() {
        if !all.contains(code) {
            all.push(*code);
        }
    }
    (sets, all)
}

/// Mitsuba's reflectance F where its `wo` is logged null although the API transmits: the
/// dielectric BSDF samples reflection with probability F on every call.
fn sampled_reflection(call: &Call, returns: &Returns) -> Option<f64> {
    let mitsuba = call.api == Api::Mitsuba && call.got == Got::Nothing;
    (mitsuba && returns.transmitted.is_some()).then(|| {
        let m = call.api.meaning(call.args);
        formula::reflectance(&Situation {
            travel: m.travel,
            normal: m.normal,
            mu: m.mu,
        })
    })
}

/// What the call's views are made from: for each reading, its argument mistakes and the
/// situation it makes, and what came back.
fn formula_readings(readings: &[Reading], seen: Seen, right: bool, tolerance: f64) -> Readings {
    Readings {
        situations: readings
            .iter()
            .map(|reading| {
                let m = reading.meaning;
                let situation = Situation {
                    travel: m.travel,
                    normal: m.normal,
                    mu: m.mu,
                };
                (Codes::of(&reading.codes), situation)
            })
            .collect(),
        outcome: match seen {
            Seen::Direction(v) => formula::Outcome::Direction(v),
            Seen::Nothing(_) | Seen::NotFinite(_) => formula::Outcome::Nothing,
        },
        right,
        tolerance,
    }
}

/// Whether what came back (`seen`) is the call refracted twice at its crossing: the API's
/// formula with its ratio squared, within `tolerance` radians (at least [`MATCH_ANGLE`]).
fn refracted_twice(call: &Call, seen: Seen, tolerance: f64) -> bool {
    let m = call.api.meaning(call.args);
    let squared = Situation {
        travel: m.travel,
        normal: m.normal,
        mu: m.mu * m.mu,
    };
    let outcome = match seen {
        Seen::Direction(v) => formula::Outcome::Direction(v),
        Seen::Nothing(_) => formula::Outcome::Nothing,
        Seen::NotFinite(_) => return false,
    };
    let tolerance = tolerance.max(MATCH_ANGLE);
    formula::reproducing(&squared, outcome, tolerance) & formula::Variant::RIGHT.bit() != 0
}

/// Judges `call` in precision `S`; a call wrong as printed is looked at again with each
/// number trusted only to its printed digits, and is undecided if that makes it right.
fn verdict_in<S: Real>(call: &Call) -> Result<CallVerdict, LineError> {
    let epsilon = S::EPSILON.to_f64();
    let tight = judge_with::<S>(call, &Tolerance::new(&call.digits, epsilon))?;
    if tight.ok {
        return Ok(tight);
    }
    let loose = judge_with::<S>(call, &Tolerance::loose(&call.digits, epsilon))?;
    Ok(if loose.ok { undecided(tight) } else { tight })
}

/// The verdict on a call that its printed digits cannot tell right or wrong: what it would
/// be as printed, and that numbers within their rounding make it right.
fn undecided(tight: CallVerdict) -> CallVerdict {
    let shown: Vec<&str> = tight.mistakes.iter().map(|c| c.name()).collect();
    let explanation = explain::undecided(&shown.join(", "));
    CallVerdict {
        ok: false,
        mistakes: Vec::new(),
        alternatives: Vec::new(),
        explanation,
        undecided: true,
        readings: Readings::default(),
        ..tight
    }
}

fn judge_with<S: Real>(call: &Call, tolerance: &Tolerance) -> Result<CallVerdict, LineError> {
    let returns = returns::<S>(call, tolerance)?;
    let seen = returns.see(call.got);
    let sampled = sampled_reflection(call, &returns);
    let finding = finding::<S>(call, &returns, seen, sampled.is_some(), tolerance);
    let readings = readings(call, tolerance);
    let twice = finding.is_some() && refracted_twice(call, seen, 2.0 * returns.distance);
    // A direction nothing else explains, refracted with the ratio squared, is that.
    let finding = finding.map(|(code, looks)| match code {
        Code::NotTheApiResult if twice => (Code::RefractedTwice, looks),
        _ => (code, looks),
    });
    let right = readings
        .first()
        .map_or_else(|| call.api.meaning(call.args), |r| r.meaning);
    let (matches, t) = physical(&right, call.got);
    let (mut alternatives, mut mistakes) = alternatives(&readings, finding.map(|(code, _)| code));
    // Nothing transmitted where the ratio squared is past its critical angle: refracting
    // twice is as good an explanation as a false total internal reflection.
    if twice && !mistakes.contains(&Code::RefractedTwice) {
        alternatives.push(vec![Code::RefractedTwice]);
        mistakes.push(Code::RefractedTwice);
    }
    let outgoing = match (seen, call.got) {
        (Seen::Direction(v) | Seen::NotFinite(v), _) => v,
        (Seen::Nothing("the reflection"), Got::Vector(v)) => v,
        (Seen::Nothing(_), _) => returns.reflection,
    };
    let ok = !readings.is_empty() && mistakes.is_empty();
    let explanation = explain::explanation(&explain::Context {
        call,
        readings: &readings,
        finding,
        returns: &returns,
        seen,
        sampled: sampled.filter(|_| ok),
    });
    // A sampled reflection's readings are of what it logged: nothing.
    let formula_readings = formula_readings(
        &readings,
        seen,
        ok && sampled.is_none(),
        MATCH_ANGLE.max(2.0 * returns.distance),
    );
    Ok(CallVerdict {
        ok,
        mistakes,
        alternatives,
        explanation,
        matches,
        t,
        api_result: returns.json,
        right,
        outgoing,
        readings: formula_readings,
        sampled,
        transmitted: matches!(seen, Seen::Direction(_)),
        undecided: false,
    })
}

/// What a judged call tells the diagnosis of the whole log: its explanations and readings,
/// the side the ray arrives from (as `entering` says, or for pbrt and Mitsuba, whose normal
/// may face either way, the normal's side), whether it is past the critical angle, where
/// `entering` is logged for pbrt or Mitsuba whether the normal is the outward one, whether it
/// is a sampled reflection, and, for a right call whose ratio nothing checks, what is missing.
#[must_use]
pub(crate) fn evidence(call: &Call, verdict: &CallVerdict) -> Evidence {
    let either_side = matches!(call.api, Api::Pbrt | Api::Mitsuba);
    // pbrt's and Mitsuba's wi points back along the ray: the normal is on the incoming side
    // when it points the way wi does. GLSL's I and the book's uv point along the ray.
    let toward_origin = if either_side {
        call.args.normal.dot(call.args.incident) > 0.0
    } else {
        call.args.normal.dot(call.args.incident) < 0.0
    };
    let side = match call.truth.entering {
        Some(true) => Some(Side::Outside),
        Some(false) => Some(Side::Inside),
        None if either_side && toward_origin => Some(Side::Outside),
        None if either_side => Some(Side::Inside),
        None => None,
    };
    let m = &verdict.right;
    let cos = m.travel.dot(m.normal) / (length(m.travel) * length(m.normal));
    let logged_entering = call
        .truth
        .entering
        .filter(|_| !call.truth.entering_from_normal);
    let unchecked = match (call.truth.mu(), call.truth.sides_given) {
        _ if verdict.undecided => Some(Missing::Digits),
        (Some(_), _) => None,
        (None, true) => Some(Missing::Entering),
        (None, false) => Some(Missing::Indices),
    };
    // A reflection read as sampled is a false total internal reflection if the log shows
    // that the code never transmits at its angles.
    let alternatives = if verdict.ok && verdict.sampled.is_some() {
        let twice = refracted_twice(call, Seen::Nothing("nothing"), 0.0);
        diagnosis::sampled_alternatives(twice)
    } else {
        verdict.alternatives.clone()
    };
    Evidence {
        // Not a wrong line: the diagnosis counts it with the lines its log cannot check.
        ok: verdict.ok || verdict.undecided,
        alternatives,
        views: verdict.readings.views(),
        side,
        past_critical: m.mu * m.mu * (1.0 - cos * cos) > 1.0,
        normal_outward: logged_entering
            .filter(|_| either_side)
            .map(|entering| toward_origin == entering),
        normal_faces: (!either_side).then_some(toward_origin),
        band: diagnosis::band(log_map::incidence_deg(m.travel, m.normal)),
        transmitted: verdict.transmitted,
        sample: verdict.sampled.map(f64::ln),
        unchecked,
        told: Told {
            entering: logged_entering.is_some(),
            travel: call.truth.travel.is_some(),
        },
    }
}

/// The call on the log's failure map: the angle of incidence of the right call, and how far
/// the direction the student's code sent the ray in is from the right one (T, or the
/// reflected ray past the critical angle; none is known when the call's ray is unknown).
#[must_use]
pub(crate) fn point(call: &Call, verdict: &CallVerdict) -> LinePoint {
    let evidence = evidence(call, verdict);
    let m = &verdict.right;
    let right = match verdict.t {
        Some(t) => Some(DVec3::from_array(t)),
        None => evidence
            .past_critical
            .then(|| log_map::reflected(m.travel, m.normal)),
    };
    LinePoint {
        incidence_deg: log_map::incidence_deg(m.travel, m.normal),
        error_deg: right.map_or(0.0, |right| log_map::angle_deg(verdict.outgoing, right)),
        side: evidence.side,
        past_critical: evidence.past_critical,
        ok: verdict.ok,
    }
}

/// Judges one call in the student's precision.
///
/// # Errors
/// An argument too large for that precision.
pub(crate) fn verdict(call: &Call) -> Result<CallVerdict, LineError> {
    match call.precision {
        Precision::F32 => verdict_in::<f32>(call),
        Precision::F64 => verdict_in::<f64>(call),
    }
}

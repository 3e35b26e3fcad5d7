//! The result side: what the API returns for the arguments as logged (in the student's
//! precision), how far rounding of the logged numbers can move it, and whether what came back
//! is that, the API's "nothing transmitted", or something else (and then what it resembles).

use glam::DVec3;
use refraction_kernel::api::{Api, Args, Returned};
use refraction_kernel::{Real, Vector3 as _};
use serde_json::{Value as Json, json};

use super::call::{Call, Got};
use super::error::LineError;
use super::readings::Tolerance;
use crate::diagnosis::Code;
use refraction_tools::vector_text::{angle, length, unit};

/// What the API returns for the logged arguments, and how sure that is.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Returns {
    /// The API's answer in its own shape, as JSON (`api_result`).
    pub json: Json,
    /// The transmitted direction, `None` where the API signals that nothing is transmitted.
    pub transmitted: Option<DVec3>,
    /// The vector the formula produces even past the critical angle (the book, Mitsuba).
    pub formula: Option<DVec3>,
    /// The transmitted directions for the arguments moved by their rounding.
    pub nearby: Vec<Option<DVec3>>,
    /// Whether rounding of the arguments can change total internal reflection into refraction
    /// or back.
    pub borderline: bool,
    /// How far a vector may be from the API's answer and still be it (Euclidean distance).
    pub distance: f64,
    /// The mirror reflection of the ray at this surface.
    pub reflection: DVec3,
    /// The relative index the API says it used (pbrt's `etap`), where it transmits.
    pub etap: Option<f64>,
}

fn wide<S: Real>(v: S::Vec3) -> DVec3 {
    DVec3::from_array(v.to_array().map(Real::to_f64))
}

fn narrow<S: Real>(args: Args<f64>) -> Result<Args<S>, LineError> {
    let convert = |x: f64| {
        let y = S::from_f64(x);
        if y.is_finite() {
            Ok(y)
        } else {
            Err(LineError::TooLarge {
                value: x,
                precision: S::NAME,
            })
        }
    };
    let vector = |v: DVec3| -> Result<S::Vec3, LineError> {
        Ok(S::Vec3::new(convert(v.x)?, convert(v.y)?, convert(v.z)?))
    };
    Ok(Args {
        incident: vector(args.incident)?,
        normal: vector(args.normal)?,
        eta: convert(args.eta)?,
    })
}

fn nullable(v: Option<DVec3>) -> Json {
    v.map_or(Json::Null, |v| json!(v.to_array()))
}

/// The API's answer in its own field names.
fn to_json<S: Real>(returned: &Returned<S>) -> Json {
    match returned {
        Returned::Glsl(v) => json!(wide::<S>(*v).to_array()),
        Returned::Pbrt(r) => json!({
            "returned": r.is_some(),
            "wt": nullable(r.map(|r| wide::<S>(r.wt))),
            "etap": r.map(|r| r.etap.to_f64()),
        }),
        Returned::Rtiow(a) => json!({
            "refracted": wide::<S>(a.refracted).to_array(),
            "cannot_refract": a.cannot_refract,
        }),
        Returned::Mitsuba(a) => json!({
            "wo": wide::<S>(a.wo).to_array(),
            "F": a.fresnel.f.to_f64(),
            "cos_theta_t": a.fresnel.cos_theta_t.to_f64(),
            "eta_it": a.fresnel.eta_it.to_f64(),
            "eta_ti": a.fresnel.eta_ti.to_f64(),
        }),
    }
}

/// The arguments moved by a relative `step`: eta both ways, each component of each vector
/// both ways.
fn moved(args: Args<f64>, step: f64) -> Vec<Args<f64>> {
    let mut out = vec![
        Args {
            eta: args.eta * (1.0 + step),
            ..args
        },
        Args {
            eta: args.eta * (1.0 - step),
            ..args
        },
    ];
    for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
        for sign in [1.0, -1.0] {
            let nudge = |v: DVec3| v + axis * (sign * step * v.abs().max_element());
            out.push(Args {
                incident: nudge(args.incident),
                ..args
            });
            out.push(Args {
                normal: nudge(args.normal),
                ..args
            });
        }
    }
    out
}

/// Where a second look finds that the printed digits cannot decide the sign of
/// k = 1 − μ²·(1 − cos²θi): the directions the API returns for a k from 0 up to what the
/// rounding allows, the root √k running along the normal, and how far apart they are (with
/// what the arguments' rounding moves each). Empty where the sign is decided.
fn undecided_roots(call: &Call, tolerance: &Tolerance) -> (Vec<Option<DVec3>>, f64) {
    if !tolerance.loose {
        return (Vec::new(), 0.0);
    }
    let m = call.api.meaning(call.args);
    let d = unit(m.travel);
    // The normal against the ray, whichever side the digits put it on.
    let n = unit(m.normal) * -d.dot(m.normal).signum();
    let (cos_i, mu) = (-d.dot(n), m.mu);
    let sin2 = 1.0 - cos_i * cos_i;
    let k = 1.0 - mu * mu * sin2;
    // How far each rounding moves k: through cosθi (each vector's rounding, on every
    // component) and through μ.
    let cos_error = 3f64.sqrt() * (tolerance.incident + tolerance.normal);
    let k_error =
        2.0 * mu * mu * (cos_i.abs() * cos_error + sin2 * tolerance.eta) + 16.0 * tolerance.epsilon;
    if !k.is_finite() || k.abs() > k_error {
        return (Vec::new(), 0.0);
    }
    let top = (k + k_error).max(0.0).sqrt();
    let roots = (0..=ROOT_STEPS)
        .map(|i| {
            let root = top * f64::from(i) / f64::from(ROOT_STEPS);
            Some(d * mu + n * (mu * cos_i - root))
        })
        .collect();
    let apart = top / f64::from(ROOT_STEPS) + 2.0 * mu * cos_error;
    (roots, apart)
}

/// How many steps [`undecided_roots`] takes from k = 0 to the largest k rounding allows.
const ROOT_STEPS: u32 = 16;

/// What `api` transmits for `args` in precision `S` (`None` also when they overflow `S`).
pub(crate) fn transmitted_by<S: Real>(api: Api, args: Args<f64>) -> Option<DVec3> {
    narrow::<S>(args)
        .ok()
        .and_then(|a| api.call(a).transmitted())
        .map(wide::<S>)
}

/// What `api` returns for `call`'s arguments in precision `S`, with the spread rounding allows.
///
/// # Errors
/// An argument too large for `S`.
pub(crate) fn returns<S: Real>(call: &Call, tolerance: &Tolerance) -> Result<Returns, LineError> {
    let returned = call.api.call(narrow::<S>(call.args)?);
    let transmitted = returned.transmitted().map(wide::<S>);
    let step = (2.0 * tolerance.arguments()).max(8.0 * tolerance.epsilon);
    let mut nearby: Vec<Option<DVec3>> = moved(call.args, step)
        .into_iter()
        .map(|args| transmitted_by::<S>(call.api, args))
        .collect();
    let (roots, apart) = undecided_roots(call, tolerance);
    let spread = transmitted.map_or(apart, |t| {
        nearby
            .iter()
            .flatten()
            .map(|other| (*other - t).length())
            .fold(apart, f64::max)
    });
    let borderline =
        !roots.is_empty() || nearby.iter().any(|t| t.is_some() != transmitted.is_some());
    nearby.extend(roots);
    let size = match call.got {
        Got::Vector(v) if v.is_finite() => v.abs().max_element().max(1.0),
        _ => 1.0,
    };
    let meaning = call.api.meaning(call.args);
    let (d, n) = (meaning.travel, meaning.normal);
    Ok(Returns {
        json: to_json(&returned),
        transmitted,
        formula: returned.formula().map(wide::<S>),
        nearby,
        borderline,
        distance: 2.0 * spread + 4.0 * tolerance.result * size + 16.0 * tolerance.epsilon,
        reflection: d - n * (2.0 * d.dot(n) / n.length_squared()),
        etap: match &returned {
            Returned::Pbrt(Some(r)) => Some(r.etap.to_f64()),
            _ => None,
        },
    })
}

/// What came back, as far as judging it goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Seen {
    /// A finite non-zero vector that is not an answer to total internal reflection.
    Direction(DVec3),
    /// The API's (or a tracer's) answer that nothing is transmitted: `false`, null, the zero
    /// vector, or the reflection where the API reflects.
    Nothing(&'static str),
    /// A vector with NaN or infinite components.
    NotFinite(DVec3),
}

impl Returns {
    /// Whether `v` is the API's transmitted direction (or one rounding allows).
    #[must_use]
    pub(crate) fn is_transmitted(&self, v: DVec3) -> bool {
        let close = |t: &DVec3| (v - *t).length() <= self.distance;
        self.transmitted.iter().any(close)
            || (self.borderline && self.nearby.iter().flatten().any(close))
    }

    /// Whether the API may say that nothing is transmitted here.
    #[must_use]
    pub(crate) fn may_reflect(&self) -> bool {
        self.transmitted.is_none() || self.borderline
    }

    /// Whether `v` is the same vector as `other` within the tolerance.
    #[must_use]
    pub(crate) fn same(&self, v: DVec3, other: DVec3) -> bool {
        (v - other).length() <= self.distance
    }

    /// How to judge what came back.
    #[must_use]
    pub(crate) fn see(&self, got: Got) -> Seen {
        match got {
            // untranslated: the answers' names; explain.rs puts them in the language's words
            Got::Nothing => Seen::Nothing("nothing (false or null)"),
            Got::Vector(v) if !v.is_finite() => Seen::NotFinite(v),
            // untranslated: as above
            Got::Vector(v) if v == DVec3::ZERO => Seen::Nothing("the zero vector"),
            Got::Vector(v)
                if self.may_reflect()
                    && !self.is_transmitted(v)
                    && angle(v, self.reflection) <= self.distance
                    && (length(v) - 1.0).abs() <= self.distance =>
            {
                // untranslated: as above
                Seen::Nothing("the reflection")
            }
            Got::Vector(v) => Seen::Direction(v),
        }
    }
}

/// What a wrong result looks like.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Resemblance {
    /// The other root: the API's answer mirrored across the surface.
    OtherRoot,
    /// The API's answer mirrored across the normal.
    WrongBend,
    /// Minus the API's answer.
    Reversed,
    /// The API's direction with this length ratio.
    Length(f64),
    /// The mirror reflection, although the ray refracts.
    Reflection,
    /// What the API returns with this argument mistake.
    Variant(Code),
    /// An answer that nothing is transmitted, although the API refracts.
    Nothing(&'static str),
    /// NaN or infinite components.
    NotFinite,
    /// None of these: this many degrees from the API's answer.
    Off(f64),
    /// Past the critical angle: the API formula's own vector (the book's and Mitsuba's refract).
    Formula,
    /// Past the critical angle: some other direction.
    Direction,
    /// The API's answer with the part along the normal negated: μ·d − b·n for μ·d + b·n.
    NormalTerm,
    /// What the API's formula gives without its flip for a ray from the normal's far side.
    NoFlip,
    /// The right direction, but a relative index other than the one the API used.
    Etap {
        /// The index logged.
        logged: f64,
        /// The index the API used.
        used: f64,
    },
}

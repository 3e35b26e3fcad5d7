//! The fields a line carries for each API (its own argument and result names, then the truth),
//! and the kind of value each holds.

use refraction_kernel::api::Api;

use crate::solve::Precision;

/// The kind of value a field holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Three numbers.
    Vector,
    /// Three numbers, or null (pbrt's `wt` after `false`, Mitsuba's `wo` when it reflected).
    VectorOrNull,
    /// One number.
    Number,
    /// true/false or 1/0.
    Flag,
    /// Any word or number, kept as text (`path`, `precision`).
    Label,
}

/// The names of one API's arguments and result.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Names {
    /// The incident vector: `I`, `wi`, `uv` or `wi`.
    pub incident: &'static str,
    /// The normal: `N` or `n`.
    pub normal: &'static str,
    /// The index ratio: `eta` or `etai_over_etat`.
    pub eta: &'static str,
    /// What came back: `result`, `wt`, `refracted` or `wo`.
    pub result: &'static str,
}

/// The field names of `api`'s lines.
#[must_use]
pub fn names(api: Api) -> Names {
    let (incident, normal, eta, result) = match api {
        Api::Glsl => ("I", "N", "eta", "result"),
        Api::Pbrt => ("wi", "n", "eta", "wt"),
        Api::Rtiow => ("uv", "n", "etai_over_etat", "refracted"),
        Api::Mitsuba => ("wi", "n", "eta", "wo"),
    };
    Names {
        incident,
        normal,
        eta,
        result,
    }
}

/// pbrt's return value.
pub const RETURNED: &str = "returned";

/// The relative index pbrt's `Refract` writes to `*etap`: the ratio it used, after its flip.
pub const ETAP: &str = "etap";

/// The book's name for whether the ray enters the object (`rec.front_face`), read as
/// `entering`.
pub const FRONT_FACE: &str = "front_face";

/// The truth and bookkeeping fields every API's lines may carry, with their kinds.
pub const COMMON: [(&str, Kind); 7] = [
    ("from", Kind::Number),
    ("to", Kind::Number),
    ("travel", Kind::Vector),
    ("entering", Kind::Flag),
    ("path", Kind::Label),
    ("point", Kind::Vector),
    ("precision", Kind::Label),
];

/// Every field `api`'s lines may carry, with its kind: the API's own first.
#[must_use]
pub fn all(api: Api) -> Vec<(&'static str, Kind)> {
    let n = names(api);
    let result = match api {
        Api::Glsl | Api::Rtiow => Kind::Vector,
        Api::Pbrt | Api::Mitsuba => Kind::VectorOrNull,
    };
    let mut fields = vec![
        (n.incident, Kind::Vector),
        (n.normal, Kind::Vector),
        (n.eta, Kind::Number),
        (n.result, result),
    ];
    if api == Api::Pbrt {
        fields.push((RETURNED, Kind::Flag));
        fields.push((ETAP, Kind::Number));
    }
    fields.extend(COMMON);
    fields
}

/// Field `name` of `api`'s lines with its kind, or `None` when they have no such field.
#[must_use]
pub fn find(api: Api, name: &str) -> Option<(&'static str, Kind)> {
    let name = match (api, name) {
        (Api::Rtiow, FRONT_FACE) => "entering",
        _ => name,
    };
    all(api).into_iter().find(|(field, _)| *field == name)
}

/// The field names of `api`, for messages: `I, N, eta, result, from, to, ...`.
#[must_use]
pub fn listed(api: Api) -> String {
    all(api)
        .iter()
        .map(|(name, _)| *name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The precision a student's `api` code usually runs in: `float` for shaders, glam's `Vec3`,
/// pbrt (without `PBRT_FLOAT_AS_DOUBLE`) and Mitsuba's `scalar_rgb`; `double` for the book.
#[must_use]
pub fn usual_precision(api: Api) -> Precision {
    match api {
        Api::Rtiow => Precision::F64,
        Api::Glsl | Api::Pbrt | Api::Mitsuba => Precision::F32,
    }
}

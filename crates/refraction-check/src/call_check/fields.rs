//! The fields a line carries for each API (its own argument and result names, then the truth),
//! and the kind of value each holds.

use refraction_kernel::api::Api;

use refraction_tools::Precision;

/// Whose fields a line carries: a call of a named API, or any renderer's own refraction,
/// judged against the physics (`check` without `--api`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dialect {
    /// The API's own argument and result names.
    Api(Api),
    /// `w`, `n`, `mu_i`, `mu_t` (the `solve` fields), the student's `t_yours`, and the `ratio`
    /// their code used.
    Physics,
}

impl From<Api> for Dialect {
    fn from(api: Api) -> Self {
        Self::Api(api)
    }
}

impl Dialect {
    /// The API, for a call of one.
    #[must_use]
    pub fn api(self) -> Option<Api> {
        match self {
            Self::Api(api) => Some(api),
            Self::Physics => None,
        }
    }

    /// The name messages give it: the API's (`glsl`), or `check` for any renderer's.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Api(api) => api.name(),
            Self::Physics => "check",
        }
    }
}

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

/// The fields of any renderer's lines (`check` without `--api`), besides [`COMMON`]: the
/// `solve` fields, the T the student's code produced and the ratio it used.
pub const PHYSICS: [(&str, Kind); 7] = [
    ("w", Kind::Vector),
    ("n", Kind::Vector),
    ("mu_i", Kind::Number),
    ("mu_t", Kind::Number),
    ("t_yours", Kind::VectorOrNull),
    ("ratio", Kind::Number),
    ("convention", Kind::Label),
];

/// Every field a line in `dialect` may carry, with its kind: the API's own first.
#[must_use]
pub fn all(dialect: impl Into<Dialect>) -> Vec<(&'static str, Kind)> {
    let api = match dialect.into() {
        Dialect::Api(api) => api,
        Dialect::Physics => return PHYSICS.iter().chain(&COMMON).copied().collect(),
    };
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

/// Field `name` of the lines in `dialect` with its kind, or `None` when they have no such
/// field.
#[must_use]
pub fn find(dialect: impl Into<Dialect>, name: &str) -> Option<(&'static str, Kind)> {
    let dialect = dialect.into();
    let name = match (dialect, name) {
        (Dialect::Api(Api::Rtiow), FRONT_FACE) => "entering",
        _ => name,
    };
    all(dialect).into_iter().find(|(field, _)| *field == name)
}

/// The field names of `dialect`, for messages: `I, N, eta, result, from, to, ...`.
#[must_use]
pub fn listed(dialect: impl Into<Dialect>) -> String {
    all(dialect)
        .iter()
        .map(|(name, _)| *name)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The precision a student's code usually runs in: `float` for shaders, glam's `Vec3`, pbrt
/// (without `PBRT_FLOAT_AS_DOUBLE`) and Mitsuba's `scalar_rgb`; `double` for the book and for
/// any renderer's own (`check`'s default, as `solve`'s).
#[must_use]
pub fn usual_precision(dialect: impl Into<Dialect>) -> Precision {
    match dialect.into() {
        Dialect::Api(Api::Rtiow) | Dialect::Physics => Precision::F64,
        Dialect::Api(Api::Glsl | Api::Pbrt | Api::Mitsuba) => Precision::F32,
    }
}

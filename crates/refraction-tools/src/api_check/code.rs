//! The mistake codes of `check --api`.

use refraction_i18n::t;

/// A mistake a call can contain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Code {
    /// The index ratio upside down for this API's convention.
    EtaInverted,
    /// The incident vector passed the wrong way round.
    IncidentReversed,
    /// The normal on the wrong side: not against the ray for GLSL and the book, pointing into
    /// the object for pbrt and Mitsuba.
    NormalNotFacing,
    /// The result is not what the API returns for these arguments: the student's own
    /// implementation differs.
    NotTheApiResult,
    /// A direction (or NaN) where the API signals total internal reflection.
    MissedTir,
    /// An incident vector or normal that is not unit length.
    NotUnitInput,
}

impl Code {
    /// Every code, in the order the README lists them.
    pub const ALL: [Self; 6] = [
        Self::EtaInverted,
        Self::IncidentReversed,
        Self::NormalNotFacing,
        Self::NotTheApiResult,
        Self::MissedTir,
        Self::NotUnitInput,
    ];

    /// The name used in JSON and in the tally.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::EtaInverted => "eta_inverted",
            Self::IncidentReversed => "incident_reversed",
            Self::NormalNotFacing => "normal_not_facing",
            Self::NotTheApiResult => "not_the_api_result",
            Self::MissedTir => "missed_tir",
            Self::NotUnitInput => "not_unit_input",
        }
    }

    /// What the mistake is, in one line (the README's table), for lists beside a verdict, in
    /// the current language.
    #[must_use]
    pub fn meaning(self) -> String {
        match self {
            Self::EtaInverted => t!("check-mistake-eta-inverted"),
            Self::IncidentReversed => t!("check-mistake-incident-reversed"),
            Self::NormalNotFacing => t!("check-mistake-normal-not-facing"),
            Self::NotTheApiResult => t!("check-mistake-not-the-api-result"),
            Self::MissedTir => t!("check-mistake-missed-tir"),
            Self::NotUnitInput => t!("check-mistake-not-unit-input"),
        }
    }
}

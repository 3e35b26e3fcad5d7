//! The mistake codes: what `check --api` names on a line, and what the diagnosis ranks.

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
    /// Code that must turn the normal round and invert the ratio for a ray arriving from the
    /// normal's far side does not (pbrt's `if (cosTheta_i < 0)` block).
    NoFlipInside,
    /// The part of the result along the normal has the wrong sign; the part across it is right.
    NormalTermSign,
    /// The other root: the square root's sign flipped, the result mirrored across the surface.
    OtherRoot,
    /// Total internal reflection reported where the ray refracts.
    FalseTir,
    /// The part of the result across the normal has the wrong sign; the part along it is right
    /// (the result mirrored across the normal).
    AcrossSign,
    /// Refracted twice at one surface crossing: T is what refracting with μ² gives.
    RefractedTwice,
    /// The code never transmits, at any angle, although k > 0: the cosine's sign lost where
    /// the Fresnel reflectance (or the choice to transmit) is computed, so F ≥ 1.
    FresnelCosSign,
    /// The side (entering, the ratio) decided with one normal (the geometric one) and the
    /// normal passed to `refract` turned by it although it is another (the shading one): on
    /// the lines where the two disagree, the normal passed does not face the ray.
    NormalsMixed,
}

impl Code {
    /// Every code, in the order the README lists them.
    pub const ALL: [Self; 14] = [
        Self::EtaInverted,
        Self::IncidentReversed,
        Self::NormalNotFacing,
        Self::NoFlipInside,
        Self::NormalTermSign,
        Self::AcrossSign,
        Self::OtherRoot,
        Self::MissedTir,
        Self::FalseTir,
        Self::NotUnitInput,
        Self::NotTheApiResult,
        Self::RefractedTwice,
        Self::FresnelCosSign,
        Self::NormalsMixed,
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
            Self::NoFlipInside => "no_flip_inside",
            Self::NormalTermSign => "normal_term_sign",
            Self::OtherRoot => "other_root",
            Self::FalseTir => "false_tir",
            Self::AcrossSign => "across_sign",
            Self::RefractedTwice => "refracted_twice",
            Self::FresnelCosSign => "fresnel_cos_sign",
            Self::NormalsMixed => "normals_mixed",
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
            Self::NoFlipInside => t!("check-mistake-no-flip-inside"),
            Self::NormalTermSign => t!("check-mistake-normal-term-sign"),
            Self::OtherRoot => t!("check-mistake-other-root"),
            Self::FalseTir => t!("check-mistake-false-tir"),
            Self::AcrossSign => t!("check-mistake-across-sign"),
            Self::RefractedTwice => t!("check-mistake-refracted-twice"),
            Self::FresnelCosSign => t!("check-mistake-fresnel-cos-sign"),
            Self::NormalsMixed => t!("check-mistake-normals-mixed"),
        }
    }

    /// The code's bit in a set of codes.
    #[must_use]
    pub fn bit(self) -> u16 {
        let index = Self::ALL.iter().position(|&c| c == self).unwrap_or(0);
        1 << index
    }

    /// The code named `name` in JSON, if there is one.
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|c| c.name() == name)
    }
}

//! The effects a scene asks the tracer to compute, and when to stop tracing.

use serde::{Deserialize, Serialize};

/// What the tracer computes besides refraction (which the media always imply). Each flag left
/// off is work the tracer does not do; [`super::Counts`] shows it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Effects {
    /// Spawn a reflected ray at every refracting hit (without it, rays reflect only on total
    /// internal reflection).
    pub partial_reflection: bool,
    /// Compute s and p Fresnel intensities at every hit and carry intensities along the rays.
    pub fresnel: bool,
    /// Trace white light once per wavelength (without it, once at the reference wavelength).
    pub dispersion: bool,
    /// Attenuate intensities by Beer–Lambert in absorbing media.
    pub absorption: bool,
    /// The most interface hits (kernel calls) along one ray and its ancestors.
    pub max_depth: u32,
    /// Rays whose intensity falls below this fraction of the source's are not traced further
    /// (only when intensities are computed).
    pub min_intensity: f64,
}

impl Default for Effects {
    fn default() -> Self {
        Self {
            partial_reflection: false,
            fresnel: false,
            dispersion: false,
            absorption: false,
            max_depth: 64,
            min_intensity: 1e-3,
        }
    }
}

impl Effects {
    /// The largest `max_depth` a scene may ask for.
    pub const MAX_DEPTH_LIMIT: u32 = 1000;

    /// Every effect on, with the same stopping rules: what a tracer that cannot leave anything
    /// out would compute.
    #[must_use]
    pub fn everything(self) -> Self {
        Self {
            partial_reflection: true,
            fresnel: true,
            dispersion: true,
            absorption: true,
            ..self
        }
    }

    /// Whether rays carry intensities (Fresnel or absorption asked for).
    #[must_use]
    pub fn intensities(&self) -> bool {
        self.fresnel || self.absorption
    }

    /// Why these effects cannot be traced, if they cannot.
    ///
    /// # Errors
    /// `max_depth` above [`Self::MAX_DEPTH_LIMIT`] or `min_intensity` outside [0, 1].
    pub fn check(&self) -> Result<(), EffectsError> {
        if self.max_depth > Self::MAX_DEPTH_LIMIT {
            return Err(EffectsError::MaxDepth(self.max_depth));
        }
        if !(0.0..=1.0).contains(&self.min_intensity) {
            return Err(EffectsError::MinIntensity(self.min_intensity));
        }
        Ok(())
    }
}

/// Why a scene's effects cannot be traced ([`Effects::check`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum EffectsError {
    /// `max_depth` is above [`Effects::MAX_DEPTH_LIMIT`]; the value asked for.
    #[error(
        "max_depth is {0}: at most {limit} hits per ray are traced",
        limit = Effects::MAX_DEPTH_LIMIT
    )]
    MaxDepth(u32),
    /// `min_intensity` is not a fraction from 0 to 1; the value asked for.
    #[error("min_intensity is {0}: expected a fraction from 0 to 1")]
    MinIntensity(f64),
}

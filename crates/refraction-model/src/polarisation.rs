//! The light the *Intensities* switch draws the rays for: one choice for the window, the
//! diagram and a deck's step (written in a deck file as `unpolarised`, `s` or `p`).

use refraction_i18n::t;
use serde::{Deserialize, Serialize};

/// The polarisation of the incoming light that Fresnel's shares are computed for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Polarisation {
    /// Polarised perpendicular to the plane of incidence.
    S,
    /// Polarised in the plane of incidence: not reflected at all at Brewster's angle.
    P,
    /// The mean of s and p, as from a lamp or the sun.
    #[default]
    Unpolarised,
}

impl Polarisation {
    /// Every choice, in the order of the menu.
    pub const ALL: [Self; 3] = [Self::Unpolarised, Self::S, Self::P];

    /// The name in the menu and in the labels, in the current language.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::S => t!("diagram-light-s"),
            Self::P => t!("diagram-light-p"),
            Self::Unpolarised => t!("diagram-light-unpolarised"),
        }
    }
}

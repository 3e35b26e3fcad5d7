//! Optical media: an index of refraction as a function of the vacuum wavelength, and an optional
//! Beer–Lambert absorption coefficient.

use serde::Serialize;

/// The wavelength at which catalogues quote `n_d` (helium d line, 587.56 nm): the one wavelength
/// traced when a scene does not ask for dispersion and its light is white.
pub const REFERENCE_WAVELENGTH_NM: f64 = 587.56;

/// The wavelengths that stand for white light when a scene asks for dispersion, in nm.
pub const WHITE_WAVELENGTHS_NM: [f64; 7] = [400.0, 450.0, 500.0, 550.0, 600.0, 650.0, 700.0];

/// How the index of refraction depends on the vacuum wavelength λ.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Dispersion {
    /// The same index at every wavelength.
    Constant(f64),
    /// Cauchy: n = A + B/λ² + C/λ⁴ with λ in µm (B in µm², C in µm⁴).
    Cauchy {
        /// A (dimensionless).
        a: f64,
        /// B in µm².
        b: f64,
        /// C in µm⁴.
        c: f64,
    },
    /// Sellmeier: n² = 1 + Σ Bᵢ·λ²/(λ² − Cᵢ) with λ in µm (Cᵢ in µm²).
    Sellmeier {
        /// The dimensionless Bᵢ.
        b: Vec<f64>,
        /// The Cᵢ in µm², one per Bᵢ.
        c: Vec<f64>,
    },
}

impl Dispersion {
    /// The index of refraction at the vacuum wavelength `wavelength_nm` (in nm). May be NaN or
    /// negative for coefficients that make no sense at that wavelength (a Sellmeier pole):
    /// scenes check every wavelength they trace when they load.
    #[must_use]
    pub fn index(&self, wavelength_nm: f64) -> f64 {
        let um = wavelength_nm * 1e-3;
        let um2 = um * um;
        match self {
            Self::Constant(n) => *n,
            Self::Cauchy { a, b, c } => a + b / um2 + c / (um2 * um2),
            Self::Sellmeier { b, c } => {
                let n2 = 1.0
                    + b.iter()
                        .zip(c)
                        .map(|(bi, ci)| bi * um2 / (um2 - ci))
                        .sum::<f64>();
                n2.sqrt()
            }
        }
    }

    /// Whether the index depends on the wavelength at all.
    #[must_use]
    pub fn is_dispersive(&self) -> bool {
        !matches!(self, Self::Constant(_))
    }
}

/// A named medium of a scene.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Medium {
    /// The name the scene file gives it.
    pub name: String,
    /// Its index of refraction as a function of wavelength.
    pub dispersion: Dispersion,
    /// The Beer–Lambert absorption coefficient α in 1/(world unit): intensity falls by e^(−α·L)
    /// over a path of length L. Applied only when the scene asks for absorption.
    pub absorption: f64,
}

impl Medium {
    /// Vacuum: n = 1 at every wavelength, no absorption. The background of a scene that names
    /// none.
    #[must_use]
    pub fn vacuum() -> Self {
        Self {
            name: "vacuum".to_owned(),
            dispersion: Dispersion::Constant(1.0),
            absorption: 0.0,
        }
    }

    /// The index of refraction at `wavelength_nm`; see [`Dispersion::index`].
    #[must_use]
    pub fn index(&self, wavelength_nm: f64) -> f64 {
        self.dispersion.index(wavelength_nm)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Schott N-BK7 (Schott optical glass data sheet), `n_d` = 1.5168.
    fn bk7() -> Dispersion {
        Dispersion::Sellmeier {
            b: vec![1.039_612_12, 0.231_792_344, 1.010_469_45],
            c: vec![0.006_000_698_67, 0.020_017_914_4, 103.560_653],
        }
    }

    #[test]
    fn sellmeier_bk7_matches_the_catalogue_n_d() {
        assert!((bk7().index(REFERENCE_WAVELENGTH_NM) - 1.5168).abs() < 1e-4);
        assert!(bk7().index(400.0) > bk7().index(700.0));
    }

    #[test]
    fn cauchy_and_constant_are_evaluated_in_micrometres() {
        let cauchy = Dispersion::Cauchy {
            a: 1.5046,
            b: 0.004_20,
            c: 0.0,
        };
        assert!((cauchy.index(500.0) - (1.5046 + 0.0042 / 0.25)).abs() < 1e-15);
        assert_eq!(Dispersion::Constant(1.333).index(400.0), 1.333);
        assert!(!Dispersion::Constant(1.0).is_dispersive() && cauchy.is_dispersive());
    }
}

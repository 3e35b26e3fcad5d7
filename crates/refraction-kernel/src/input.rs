//! What the kernel is asked: W, N, the two indices and the convention; and how bad input is
//! reported (errors) or noticed (warnings) before any refraction arithmetic runs.

use std::fmt;

use super::real::{Real, Vector3};

/// Which way the incoming vector W points, as in the paper.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Convention {
    /// W is the direction the ray travels in: the paper's Section 2, as in GLSL and glam.
    #[default]
    AlongRay,
    /// W points back toward the ray's origin: the paper's Section 1, as in pbrt and Mitsuba.
    TowardOrigin,
}

impl Convention {
    /// The name used in JSON and on the command line.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Convention;
    /// assert_eq!(Convention::TowardOrigin.name(), "toward_origin");
    /// ```
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::AlongRay => "along_ray",
            Self::TowardOrigin => "toward_origin",
        }
    }

    /// Parses [`Convention::name`].
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Convention;
    /// assert_eq!(Convention::from_name("along_ray"), Some(Convention::AlongRay));
    /// assert_eq!(Convention::from_name("along"), None);
    /// ```
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        [Self::AlongRay, Self::TowardOrigin]
            .into_iter()
            .find(|c| c.name() == name)
    }

    /// The paper's section that derives this convention (1 or 2).
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Convention;
    /// assert_eq!(Convention::AlongRay.section(), 2);
    /// ```
    #[must_use]
    pub fn section(self) -> u8 {
        match self {
            Self::AlongRay => 2,
            Self::TowardOrigin => 1,
        }
    }

    /// +1 when W is the travel direction, −1 when it points back: the sign that turns W into
    /// the travel direction, and the sign of the chosen `a = ±μ`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::Convention;
    /// let w = Vec3::new(-0.6, 0.8, 0.0); // pbrt's wi: back toward the origin
    /// let d = w * Convention::TowardOrigin.travel_sign::<f32>();
    /// assert_eq!(d, Vec3::new(0.6, -0.8, 0.0));
    /// ```
    #[must_use]
    pub fn travel_sign<S: Real>(self) -> S {
        match self {
            Self::AlongRay => S::ONE,
            Self::TowardOrigin => -S::ONE,
        }
    }
}

/// One refraction problem: a hit point's incoming vector, normal and indices.
///
/// Nothing here needs to be normalised or oriented: [`super::refract`] checks and prepares it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incidence<S: Real> {
    /// The incoming vector W (any non-zero length; see [`Convention`] for its direction).
    pub w: S::Vec3,
    /// The surface normal N (any non-zero length, either side of the surface).
    pub n: S::Vec3,
    /// `μ_i`: the index of refraction of the medium the ray travels in (finite, > 0).
    pub mu_i: S,
    /// `μ_t`: the index of refraction of the medium the ray enters (finite, > 0).
    pub mu_t: S,
    /// Which way W points.
    pub convention: Convention,
}

/// The two vectors of an [`Incidence`], for naming them in messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VectorName {
    /// The incoming vector.
    W,
    /// The surface normal.
    N,
}

impl VectorName {
    fn field(self) -> &'static str {
        match self {
            Self::W => "w",
            Self::N => "n",
        }
    }
}

/// The two indices of an [`Incidence`], for naming them in messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IndexName {
    /// `μ_i`, the medium the ray travels in.
    MuI,
    /// `μ_t`, the medium the ray enters.
    MuT,
}

impl IndexName {
    fn field(self) -> &'static str {
        match self {
            Self::MuI => "mu_i",
            Self::MuT => "mu_t",
        }
    }
}

/// Why an [`Incidence`] cannot be refracted. Every variant names the offending input.
#[derive(Clone, Debug, PartialEq)]
pub enum InputError {
    /// A component of W or N is NaN or infinite (after conversion to the working precision).
    NonFiniteComponent {
        /// Which vector.
        vector: VectorName,
        /// Which component (0, 1, 2).
        component: usize,
        /// Its value, widened to f64.
        value: f64,
    },
    /// W or N has all components zero: it has no direction.
    ZeroVector(VectorName),
    /// An index of refraction is not a finite number > 0.
    BadIndex {
        /// Which index.
        index: IndexName,
        /// Its value, widened to f64.
        value: f64,
    },
    /// μ = `μ_i/μ_t` is so extreme that μ² would leave the working precision's range.
    RatioOutOfRange {
        /// `μ_i/μ_t` computed in f64.
        mu: f64,
        /// The precision's name.
        precision: &'static str,
        /// The largest ratio (and the reciprocal of the smallest) accepted.
        limit: f64,
    },
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFiniteComponent {
                vector,
                component,
                value,
            } => write!(
                f,
                "{}[{component}] is {value}: every component must be a finite number",
                vector.field()
            ),
            Self::ZeroVector(vector) => write!(
                f,
                "{} is the zero vector, which has no direction",
                vector.field()
            ),
            Self::BadIndex { index, value } => write!(
                f,
                "{} is {value}: an index of refraction must be a finite number > 0",
                index.field()
            ),
            Self::RatioOutOfRange {
                mu,
                precision,
                limit,
            } => write!(
                f,
                "the index ratio mu_i/mu_t = {mu:e} is outside what {precision} can refract \
                 ({:e} to {limit:e})",
                1.0 / limit
            ),
        }
    }
}

impl core::error::Error for InputError {}

/// Something about valid input that is probably a bug in the caller's code.
#[derive(Clone, Debug, PartialEq)]
pub enum Warning {
    /// W or N was not unit length (relative difference above 1e-6); the kernel normalised it.
    NotUnitLength {
        /// Which vector.
        vector: VectorName,
        /// Its length, widened to f64 (may be +∞ when the length overflows).
        length: f64,
    },
    /// N pointed along the travel direction (away from the incoming ray); the kernel used −N.
    NormalFlipped,
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotUnitLength { vector, length } => write!(
                f,
                "{} has length {length:e}, not 1: it was normalised (un-normalised vectors are \
                 a common ray-tracer bug)",
                vector.field()
            ),
            Self::NormalFlipped => f.write_str(
                "n points away from the incoming ray (as an outward normal does where a ray \
                 leaves a sphere): the kernel used -n, the normal that faces the ray",
            ),
        }
    }
}

/// Relative length difference above which a vector is reported as not unit length.
pub const UNIT_LENGTH_TOLERANCE: f64 = 1e-6;

/// A vector checked and brought to unit length.
///
/// Vectors whose computed length is within 2ε of 1 are kept bit for bit, so that `μ_i` == `μ_t`
/// returns W exactly; others are scaled by their largest component first (so that lengths near
/// 1e-30 or 1e30 neither underflow nor overflow) and then divided by their length.
pub(crate) fn normalise<S: Real>(
    v: S::Vec3,
    name: VectorName,
    warnings: &mut Vec<Warning>,
) -> Result<S::Vec3, InputError> {
    let components = v.to_array();
    if let Some(component) = components.iter().position(|c| !c.is_finite()) {
        return Err(InputError::NonFiniteComponent {
            vector: name,
            component,
            value: components[component].to_f64(),
        });
    }
    let largest = components.iter().fold(S::ZERO, |m, c| m.max(c.abs()));
    if largest == S::ZERO {
        return Err(InputError::ZeroVector(name));
    }
    let scaled = v.div_scalar(largest);
    let scaled_length = scaled.length();
    let length = scaled_length.to_f64() * largest.to_f64();
    if (length - 1.0).abs() > UNIT_LENGTH_TOLERANCE {
        warnings.push(Warning::NotUnitLength {
            vector: name,
            length,
        });
    }
    if (length - 1.0).abs() <= 2.0 * S::EPSILON.to_f64() {
        Ok(v)
    } else {
        Ok(scaled.div_scalar(scaled_length))
    }
}

/// Checks an index of refraction.
pub(crate) fn check_index<S: Real>(value: S, index: IndexName) -> Result<S, InputError> {
    if value.is_finite() && value > S::ZERO {
        Ok(value)
    } else {
        Err(InputError::BadIndex {
            index,
            value: value.to_f64(),
        })
    }
}

/// The largest index ratio precision `S` refracts, and the reciprocal of the smallest: 1/ε².
/// Beyond it μ² and the discriminant would leave the precision's range; no physical pair of
/// media comes close.
fn ratio_limit<S: Real>() -> f64 {
    1.0 / (S::EPSILON.to_f64() * S::EPSILON.to_f64())
}

/// Whether an index ratio (widened to f64) is one precision `S` refracts: from ε² to 1/ε²
/// (false for NaN).
pub(crate) fn is_accepted_ratio<S: Real>(wide: f64) -> bool {
    let limit = ratio_limit::<S>();
    (1.0 / limit..=limit).contains(&wide)
}

/// Whether `v` is unit length within [`UNIT_LENGTH_TOLERANCE`] (false for a non-finite `v`).
pub(crate) fn is_unit<V: Vector3>(v: V) -> bool {
    (v.length().to_f64() - 1.0).abs() <= UNIT_LENGTH_TOLERANCE
}

/// The index ratio μ = `μ_i/μ_t`, refused unless it is an accepted ratio ([`is_accepted_ratio`])
/// as computed in f64, and finite and non-zero as computed in `S`.
pub(crate) fn index_ratio<S: Real>(mu_i: S, mu_t: S) -> Result<S, InputError> {
    let limit = ratio_limit::<S>();
    let mu = mu_i / mu_t;
    let wide = mu_i.to_f64() / mu_t.to_f64();
    if !is_accepted_ratio::<S>(wide) || !mu.is_finite() || mu == S::ZERO {
        return Err(InputError::RatioOutOfRange {
            mu: wide,
            precision: S::NAME,
            limit,
        });
    }
    Ok(mu)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    #[test]
    fn unit_vectors_are_kept_bit_for_bit() {
        let v = DVec3::new(0.6, 0.8, 0.0);
        let mut warnings = Vec::new();
        assert_eq!(normalise::<f64>(v, VectorName::W, &mut warnings), Ok(v));
        assert!(warnings.is_empty());
    }

    #[test]
    fn tiny_and_huge_vectors_normalise_without_overflow() {
        for scale in [1e-30_f32, 1e30] {
            let mut warnings = Vec::new();
            let v = normalise::<f32>(
                Vec3::new(3.0, -4.0, 0.0) * scale,
                VectorName::N,
                &mut warnings,
            )
            .unwrap();
            assert!((v - Vec3::new(0.6, -0.8, 0.0)).length() < 2.0 * f32::EPSILON);
            assert!(matches!(
                warnings[..],
                [Warning::NotUnitLength {
                    vector: VectorName::N,
                    ..
                }]
            ));
        }
    }

    #[test]
    fn bad_vectors_and_indices_are_named() {
        let mut warnings = Vec::new();
        let err = normalise::<f64>(DVec3::new(0.0, f64::NAN, 1.0), VectorName::N, &mut warnings)
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "n[1] is NaN: every component must be a finite number"
        );
        let err = normalise::<f64>(DVec3::ZERO, VectorName::W, &mut warnings).unwrap_err();
        assert_eq!(err, InputError::ZeroVector(VectorName::W));
        let err = check_index(-1.5_f64, IndexName::MuT).unwrap_err();
        assert!(err.to_string().starts_with("mu_t is -1.5"));
        assert!(check_index(f64::INFINITY, IndexName::MuI).is_err());
        assert!(index_ratio(1e30_f32, 1e-10).is_err());
        assert_eq!(index_ratio(1.5_f64, 1.0), Ok(1.5));
    }
}

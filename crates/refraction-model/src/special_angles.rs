//! The physics' figures of an interface: the angles of incidence at which something happens.

/// The angles of incidence at which something happens for a pair of media, in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpecialAngles {
    /// Brewster's angle, tanθB = `μ_t/μ_i`, where p light is not reflected at all; `None` for
    /// equal indices (no interface).
    pub brewster_deg: Option<f64>,
    /// The critical angle, sinθc = `μ_t/μ_i`, beyond which all light is reflected; `None` unless
    /// the ray goes into a medium of lower index (μ = `μ_i/μ_t` > 1).
    pub critical_deg: Option<f64>,
}

impl SpecialAngles {
    /// The angles for μ = `μ_i/μ_t` (finite, > 0), as the kernel holds it.
    ///
    /// Both come from `atan2`, which keeps its digits where `asin` would not (the critical
    /// angle near 90° when μ is near 1): θB = atan2(1, μ), θc = atan2(1, √((μ − 1)(μ + 1))).
    #[must_use]
    pub fn for_ratio(mu: f64) -> Self {
        Self {
            brewster_deg: (mu != 1.0).then(|| 1.0_f64.atan2(mu).to_degrees()),
            critical_deg: (mu > 1.0)
                .then(|| 1.0_f64.atan2(((mu - 1.0) * (mu + 1.0)).sqrt()).to_degrees()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn air_and_glass_have_the_textbook_angles() {
        let into_glass = SpecialAngles::for_ratio(1.0 / 1.5);
        assert!((into_glass.brewster_deg.unwrap() - 56.3099).abs() < 1e-4);
        assert_eq!(into_glass.critical_deg, None);
        let out_of_glass = SpecialAngles::for_ratio(1.5);
        assert!((out_of_glass.brewster_deg.unwrap() - 33.6901).abs() < 1e-4);
        assert!((out_of_glass.critical_deg.unwrap() - 41.8103).abs() < 1e-4);
    }

    #[test]
    fn equal_indices_have_neither_and_near_equal_ones_keep_their_digits() {
        assert_eq!(
            SpecialAngles::for_ratio(1.0),
            SpecialAngles {
                brewster_deg: None,
                critical_deg: None
            }
        );
        // μ = 1 + 1e-12: 90° − θc = √(2e-12) rad, which asin(1/μ) would round to 0 or 1e-6°.
        let gap = 90.0 - SpecialAngles::for_ratio(1.0 + 1e-12).critical_deg.unwrap();
        let expected = (2e-12_f64).sqrt().to_degrees();
        assert!(
            (gap - expected).abs() < 1e-3 * expected,
            "{gap:e} vs {expected:e}"
        );
    }
}

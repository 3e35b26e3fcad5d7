//! Fresnel reflectance and transmittance for s and p polarisation, from the cosines the kernel
//! has already computed: no trigonometry.

use serde::Serialize;

/// The fractions of the incident intensity reflected and transmitted at one interface, for
/// light polarised perpendicular (s) and parallel (p) to the plane of incidence. In 2D every
/// interface shares the plane of the scene, so s and p stay meaningful from hit to hit.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Fresnel {
    /// Reflectance R_s.
    pub rs: f64,
    /// Reflectance R_p.
    pub rp: f64,
    /// Transmittance T_s = 1 − R_s.
    pub ts: f64,
    /// Transmittance T_p = 1 − R_p.
    pub tp: f64,
}

/// (R, T) for the two optical admittances of one polarisation, each ≥ 0:
/// R = ((a − b)/(a + b))², T = 4ab/(a + b)²; R + T = 1 identically, and each keeps its digits
/// where the other is near 1.
fn split(a: f64, b: f64) -> (f64, f64) {
    let sum = a + b;
    if sum > 0.0 {
        let r = (a - b) / sum;
        (r * r, 4.0 * a * b / (sum * sum))
    } else {
        // Grazing incidence at the critical angle: everything is reflected.
        (1.0, 0.0)
    }
}

impl Fresnel {
    /// The Fresnel intensities for μ = μ_i/μ_t and the kernel's cosθi, cosθt (both in [0, 1]).
    ///
    /// r_s = (μ·cosθi − cosθt)/(μ·cosθi + cosθt) and r_p = (cosθi − μ·cosθt)/(cosθi + μ·cosθt):
    /// the textbook amplitudes divided through by μ_t.
    #[must_use]
    pub fn new(mu: f64, cos_i: f64, cos_t: f64) -> Self {
        let (rs, ts) = split(mu * cos_i, cos_t);
        let (rp, tp) = split(cos_i, mu * cos_t);
        Self { rs, rp, ts, tp }
    }

    /// Total internal reflection: everything reflected.
    pub const TOTAL_REFLECTION: Self = Self {
        rs: 1.0,
        rp: 1.0,
        ts: 0.0,
        tp: 0.0,
    };

    /// The reflectance of unpolarised light: (R_s + R_p)/2.
    #[must_use]
    pub fn reflectance(&self) -> f64 {
        (self.rs + self.rp) / 2.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn normal_incidence_on_glass_reflects_four_percent() {
        let f = Fresnel::new(1.0 / 1.5, 1.0, 1.0);
        assert!((f.rs - 0.04).abs() < 1e-15 && (f.rp - 0.04).abs() < 1e-15);
    }

    #[test]
    fn brewster_angle_reflects_no_p_light() {
        // tanθB = 1.5: cosθi = 1/√3.25, and θi + θt = 90° so cosθt = sinθi.
        let cos_i = 1.0 / 3.25_f64.sqrt();
        let cos_t = 1.5 * cos_i;
        let f = Fresnel::new(1.0 / 1.5, cos_i, cos_t);
        assert!(f.rp < 1e-30 && f.rs > 0.1);
    }

    proptest! {
        #[test]
        fn reflected_and_transmitted_sum_to_one(
            mu in 0.1_f64..10.0, cos_i in 0.0_f64..=1.0, cos_t in 0.0_f64..=1.0
        ) {
            let f = Fresnel::new(mu, cos_i, cos_t);
            prop_assert!((f.rs + f.ts - 1.0).abs() <= 4.0 * f64::EPSILON);
            prop_assert!((f.rp + f.tp - 1.0).abs() <= 4.0 * f64::EPSILON);
            prop_assert!(f.rs >= 0.0 && f.ts >= 0.0 && f.rp >= 0.0 && f.tp >= 0.0);
        }
    }
}

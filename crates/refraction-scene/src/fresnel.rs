//! Fresnel reflectance and transmittance for s and p polarisation at a scene's hits: the
//! kernel's [`refraction_kernel::Fresnel`] at the tracer's precision, from the cosines the
//! kernel has already computed (no trigonometry, one implementation for the whole project).

/// The fractions of the incident intensity reflected and transmitted at one interface, for
/// light polarised perpendicular (s) and parallel (p) to the plane of incidence. In 2D every
/// interface shares the plane of the scene, so s and p stay meaningful from hit to hit.
pub type Fresnel = refraction_kernel::Fresnel<f64>;

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

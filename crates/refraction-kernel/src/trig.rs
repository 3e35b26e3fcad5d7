//! The textbook route through angles: θi = acos(cosθi), θt = asin(μ·sinθi), and T as −N rotated
//! by θt toward the surface. Kept as a variant to show what the trig-free form buys; not used
//! by the explorer.

use super::real::{Real, Vector3};
use super::stable::facing;

/// The refracted direction of travel for unit `d` and unit `n` (either side), or `None` on
/// total internal reflection, computed with acos, asin, sin and cos.
#[inline]
#[must_use]
pub fn transmit<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
    let n = facing::<S>(d, n);
    let theta_i = (-d.dot(n)).min(S::ONE).acos();
    let sin_t = mu * theta_i.sin_cos().0;
    if sin_t > S::ONE {
        return None;
    }
    let axis = d.cross(n);
    let sin_i = axis.length();
    if sin_i == S::ZERO {
        return Some(d);
    }
    let (sin_t, cos_t) = sin_t.asin().sin_cos();
    // Rodrigues' rotation of −n about the unit axis d × n; −n is perpendicular to the axis, so
    // only two of its three terms remain.
    let axis = axis.div_scalar(sin_i);
    Some(-n * cos_t + axis.cross(-n) * sin_t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn agrees_with_snell_at_a_textbook_angle() {
        let t = transmit(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0_f64 / 1.5).unwrap();
        assert!((t - DVec3::new(0.4, -(0.84_f64).sqrt(), 0.0)).length() < 1e-15);
        assert_eq!(
            transmit(DVec3::new(0.8, -0.6, 0.0), DVec3::Y, 1.5_f64),
            None
        );
    }
}

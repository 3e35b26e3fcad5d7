//! The textbook route through angles: θi = acos(cosθi), θt = asin(μ·sinθi), and T as −N rotated
//! by θt toward the surface. Kept as a variant ([`crate::Variant::Trig`]) to show what the
//! trig-free form buys; not used by the explorer.

use super::real::{Real, Vector3 as _, per_precision};
use super::stable::facing;

/// `single(x)` or `double(x)`, whichever is the precision of `S`: [`Real`] leaves the angle
/// functions out, since only this variant uses angles.
#[inline(always)]
fn angle_function<S: Real>(x: S, single: impl Fn(f32) -> f32, double: impl Fn(f64) -> f64) -> S {
    let [y] = per_precision([x], |[x]| [single(x)], |[x]| [double(x)]);
    y
}

/// The refracted direction of travel for unit `d` and unit `n` (either side), or `None` on
/// total internal reflection, computed with acos, asin, sin and cos.
#[inline]
#[must_use]
pub(crate) fn transmit<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
    let n = facing::<S>(d, n);
    let theta_i = angle_function((-d.dot(n)).min(S::ONE), f32::acos, f64::acos);
    let sin_t = mu * angle_function(theta_i, f32::sin, f64::sin);
    if sin_t > S::ONE {
        return None;
    }
    let axis = d.cross(n);
    let sin_i = axis.length();
    if sin_i == S::ZERO {
        return Some(d);
    }
    let theta_t = angle_function(sin_t, f32::asin, f64::asin);
    let (sin_t, cos_t) = (
        angle_function(theta_t, f32::sin, f64::sin),
        angle_function(theta_t, f32::cos, f64::cos),
    );
    // Rodrigues' rotation of −n about the unit axis d × n; −n is perpendicular to the axis, so
    // only two of its three terms remain.
    let axis = axis.div_scalar(sin_i);
    Some(-n * cos_t + axis.cross(-n) * sin_t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    #[test]
    fn agrees_with_snell_at_a_textbook_angle() {
        let t = transmit(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0_f64 / 1.5).unwrap();
        assert!((t - DVec3::new(0.4, -(0.84_f64).sqrt(), 0.0)).length() < 1e-15);
        assert_eq!(
            transmit(DVec3::new(0.8, -0.6, 0.0), DVec3::Y, 1.5_f64),
            None
        );
    }

    #[test]
    fn single_precision_angles_are_computed_in_single_precision() {
        let x = 0.3_f32;
        assert_eq!(
            angle_function(x, f32::acos, f64::acos).to_bits(),
            x.acos().to_bits()
        );
        assert_eq!(
            angle_function(x, f32::sin, f64::sin).to_bits(),
            x.sin().to_bits()
        );
        let d = Vec3::new(0.6, -0.8, 0.0);
        assert!((transmit(d, Vec3::Y, 1.0_f32 / 1.5).unwrap().x - 0.4).abs() < 1e-6);
    }
}

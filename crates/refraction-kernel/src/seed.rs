//! The paper's formula taken literally (eq. 1.21/1.22 and 2.21/2.22), kept as a
//! named variant so that what it loses can be shown beside the default kernel.
//!
//! It uses N exactly as given (no flip toward the incoming ray, which is the classic bug when a
//! ray leaves a sphere through its outward normal) and the discriminant μ²wn² − μ² + 1, which
//! cancels at grazing incidence between near-equal indices and near normal incidence at large μ.

use super::input::Convention;
use super::real::{Real as _, Vector3};

/// The paper's (a, b) for unit `w` and `n` in the given convention, or `None` when its
/// discriminant μ²wn² − μ² + 1 is negative (total internal reflection).
///
/// Section 1 (W toward the origin): a = −μ, b = μ·wn − √k. Section 2 (W along the ray): a = μ,
/// b = −μ·wn − √k.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::{Convention, seed};
/// // Air into glass, W along the ray: a = μ, b = −μ·wn − √k = 0.8/1.5 − √0.84.
/// let d = DVec3::new(0.6, -0.8, 0.0);
/// let (a, b) = seed::weights(d, DVec3::Y, 1.0 / 1.5, Convention::AlongRay).expect("no TIR here");
/// assert_eq!(a, 1.0 / 1.5);
/// assert!((b - (0.8 / 1.5 - 0.84_f64.sqrt())).abs() < 1e-15);
/// ```
#[inline]
#[must_use]
pub fn weights<V: Vector3>(
    w: V,
    n: V,
    mu: V::Scalar,
    convention: Convention,
) -> Option<(V::Scalar, V::Scalar)> {
    let wn = w.dot(n);
    let k = mu * mu * wn * wn - mu * mu + V::Scalar::ONE;
    if k < V::Scalar::ZERO {
        return None;
    }
    let a = convention.travel_sign::<V::Scalar>() * mu;
    Some((a, -a * wn - k.sqrt()))
}

/// The paper's T = a·W + b·N for unit `w` and `n`, or `None` on total internal reflection.
/// N is used as given: the formula assumes it faces the incoming ray.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::{Convention, seed};
/// let d = DVec3::new(0.6, -0.8, 0.0);
/// let t = seed::refract(d, DVec3::Y, 1.0 / 1.5, Convention::AlongRay).expect("no TIR here");
/// assert!((t.x - 0.4).abs() < 1e-15 && t.y < 0.0);
/// // The classic bug: the outward normal where the ray leaves glass sends it back inside.
/// let up = DVec3::new(0.4, 0.84_f64.sqrt(), 0.0);
/// let back = seed::refract(up, DVec3::Y, 1.5, Convention::AlongRay).expect("formula's answer");
/// assert!(back.y < 0.0);
/// ```
#[inline]
#[must_use]
pub fn refract<V: Vector3>(w: V, n: V, mu: V::Scalar, convention: Convention) -> Option<V> {
    weights(w, n, mu, convention).map(|(a, b)| w * a + n * b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn both_sections_give_the_same_ray() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let along = refract(d, DVec3::Y, 1.0_f64 / 1.5, Convention::AlongRay).unwrap();
        let toward = refract(-d, DVec3::Y, 1.0_f64 / 1.5, Convention::TowardOrigin).unwrap();
        assert!((along - toward).length() < 1e-15);
        assert!(along.y < 0.0);
    }

    #[test]
    fn the_outward_normal_bug_sends_the_ray_back() {
        // Leaving glass: d goes up through a surface whose given normal also points up.
        let d = DVec3::new(0.3, 0.9539392014169456, 0.0);
        let t = refract(d, DVec3::Y, 1.5_f64, Convention::AlongRay).unwrap();
        assert!(
            t.y < 0.0,
            "the literal formula with an un-flipped normal reflects: {t}"
        );
    }
}

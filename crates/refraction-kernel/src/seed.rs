//! The source derivation's formula taken literally (eq. 1.21/1.22 and 2.21/2.22), kept as a
//! named variant so that what it loses can be shown beside the default kernel.
//!
//! It uses N exactly as given (no flip toward the incoming ray, which is the classic bug when a
//! ray leaves a sphere through its outward normal) and the discriminant μ²wn² − μ² + 1, which
//! cancels at grazing incidence between near-equal indices and near normal incidence at large μ.

use super::input::Convention;
use super::real::{Real, Vector3};

/// The source's (a, b) for unit `w` and `n` in the given convention, or `None` when its
/// discriminant μ²wn² − μ² + 1 is negative (total internal reflection).
///
/// Section 1 (W toward the origin): a = −μ, b = μ·wn − √k. Section 2 (W along the ray): a = μ,
/// b = −μ·wn − √k.
#[inline]
#[must_use]
pub fn weights<S: Real>(w: S::Vec3, n: S::Vec3, mu: S, convention: Convention) -> Option<(S, S)> {
    let wn = w.dot(n);
    let k = mu * mu * wn * wn - mu * mu + S::ONE;
    if k < S::ZERO {
        return None;
    }
    let a = convention.travel_sign::<S>() * mu;
    Some((a, -a * wn - k.sqrt()))
}

/// The source's T = a·W + b·N for unit `w` and `n`, or `None` on total internal reflection.
#[inline]
#[must_use]
pub fn refract<S: Real>(w: S::Vec3, n: S::Vec3, mu: S, convention: Convention) -> Option<S::Vec3> {
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

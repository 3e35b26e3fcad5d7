//! The default refraction arithmetic: the source's T = a·W + b·N with the discriminant and the
//! b root rearranged so that nothing cancels where the problem itself is well-conditioned.
//!
//! Work in the travel form: `d` is the unit direction of travel, `n` the unit normal that faces
//! it (d·n ≤ 0), cosθi = −d·n, μ = μ_i/μ_t. The source's discriminant k = μ²wn² − μ² + 1 and the
//! GLSL form 1 − μ²(1 − cos²θi) lose accuracy in two places:
//! - equal or near-equal indices at grazing incidence: 1 − cos²θi is fine, but μ² − 1 and
//!   μ²cos²θi cancel. Here k = (μ·cosθi)² + (1 − μ)(1 + μ), where 1 − μ is exact (Sterbenz);
//! - large μ near normal incidence: 1 − cos²θi loses all its digits and μ² amplifies the loss.
//!   When cos²θi > ½, sin²θi comes from the tangential part |d + cosθi·n|² instead, and
//!   k = 1 − μ²·sin²θi.
//!
//! T itself is built as μ·(d + cosθi·n) − cosθt·n, the same vector as the source's μ·d + b·n
//! (b = μ·cosθi − cosθt, eq. 20–22 of Section 2, see `docs/derivation.md`) but without its two
//! terms of size μ cancelling when μ is large: T is unit length up to a few roundings for every
//! accepted μ (up to 1/ε² either way), where μ·d + b·n would return a zero or a long vector
//! from μ ≈ 1/ε. The weight b that the full answer reports is computed in its cancellation-free
//! form −(1 − μ)(1 + μ)/(μ·cosθi + cosθt), which is 0 exactly at μ = 1.
//! No fused multiply-add is needed for the error bound: where the sum in the grazing branch
//! cancels (μ > 1 near the critical angle) the problem's own condition number dominates, and
//! `f32::mul_add` without the `fma` target feature is a slow library call.
//!
//! Error bound (checked against a double-double oracle in the `refraction-bench` crate's
//! `tests/kernel_accuracy.rs`): for unit `d`, `n` the angle between the returned T and the exact
//! one is at most 32·ε·κ with κ from [`super::condition_number`]; |T| is within a few ε of 1;
//! T is exact when μ = 1. At grazing incidence, where |d·n| is below a few ε, which side of the
//! surface `n` lies on is decided by the sign of the rounded d·n: the problem is ill-posed there
//! (a rounding of the input moves the ray to the other side), so T may come out on either side.

use super::real::{Real, Vector3};

/// The transmitted ray of [`refract_facing`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transmitted<S: Real> {
    /// The refracted direction of travel T = μ·d + b·n, built as μ·(d + cosθi·n) − cosθt·n
    /// (unit length up to a few roundings).
    pub t: S::Vec3,
    /// cosθt = √k ≥ 0.
    pub cos_t: S,
    /// The weight of the facing normal: T = μ·d + b·n.
    pub b: S,
}

/// What [`refract_facing`] finds at one interface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facing<S: Real> {
    /// cosθi = −d·n (≥ 0 up to rounding).
    pub cos_i: S,
    /// The discriminant k = 1 − μ²(1 − cos²θi), computed stably. Negative on total internal
    /// reflection; never NaN for unit inputs and μ within the accepted range.
    pub k: S,
    /// The transmitted ray, or `None` on total internal reflection (k < 0).
    pub transmitted: Option<Transmitted<S>>,
}

/// cosθi = −d·n for a facing unit normal (d·n ≤ 0, so never below 0), kept at most 1: rounding
/// can take the dot product of two unit vectors a little past ±1, and a cosine above 1 would
/// give NaN angles.
#[inline(always)]
pub(crate) fn cos_incidence<S: Real>(d: S::Vec3, n: S::Vec3) -> S {
    (-d.dot(n)).min(S::ONE)
}

/// The part of `d` along the surface, d + cosθi·n (of length sinθi), from which T =
/// μ·(d + cosθi·n) − cosθt·n is built. Large μ multiplies its errors, so it is made orthogonal
/// to `n` once more: after d + cosθi·n its component along `n` is a few ε (the rounding of
/// cosθi), after the second projection a few ε·sinθi, which μ·sinθi ≤ 1 keeps below a few ε
/// in T. Its error along the surface (a few ε) is the problem's own: κ grows like μ.
#[inline(always)]
pub(crate) fn tangential<S: Real>(d: S::Vec3, n: S::Vec3, cos_i: S) -> S::Vec3 {
    let along = d + n * cos_i;
    along - n * along.dot(n)
}

/// k = 1 − μ²(1 − cos²θi) without cancellation: near normal incidence from μ²|d + cosθi·n|²
/// (the same tangential part T is built from, so that |T|² = μ²|d + cosθi·n|² + k = 1 up to a
/// few roundings however large μ is), otherwise from (μ·cosθi)² + (1 − μ)(1 + μ). Shared with
/// the batch kernel so both round alike.
#[inline(always)]
pub(crate) fn discriminant<S: Real>(along: S::Vec3, cos_i: S, mu: S, one_minus_mu2: S) -> S {
    if cos_i * cos_i > S::HALF {
        S::ONE - mu * mu * along.length_squared()
    } else {
        let mc = mu * cos_i;
        mc * mc + one_minus_mu2
    }
}

/// T = μ·(d + cosθi·n) − cosθt·n from the tangential part: unit length up to a few roundings
/// for every accepted μ.
#[inline(always)]
pub(crate) fn transmitted_direction<S: Real>(
    along: S::Vec3,
    n: S::Vec3,
    mu: S,
    cos_t: S,
) -> S::Vec3 {
    along * mu - n * cos_t
}

/// b = μ·cosθi − cosθt in its cancellation-free form −(1 − μ²)/(μ·cosθi + cosθt).
#[inline(always)]
pub(crate) fn normal_weight<S: Real>(mu: S, cos_i: S, cos_t: S, one_minus_mu2: S) -> S {
    -one_minus_mu2 / (mu * cos_i + cos_t)
}

/// Refracts the unit travel direction `d` at the unit normal `n`, which must face it (d·n ≤ 0),
/// with μ = μ_i/μ_t (finite, > 0, μ² finite).
///
/// μ = 1 returns T = d bit for bit, without refraction arithmetic. k = 0 transmits (grazing T).
#[inline]
#[must_use]
pub fn refract_facing<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Facing<S> {
    let cos_i = cos_incidence::<S>(d, n);
    if mu == S::ONE {
        return Facing {
            cos_i,
            k: cos_i * cos_i,
            transmitted: Some(Transmitted {
                t: d,
                cos_t: cos_i.abs(),
                b: S::ZERO,
            }),
        };
    }
    let one_minus_mu2 = (S::ONE - mu) * (S::ONE + mu);
    let along = tangential::<S>(d, n, cos_i);
    let k = discriminant(along, cos_i, mu, one_minus_mu2);
    let transmitted = (k >= S::ZERO).then(|| {
        let cos_t = k.sqrt();
        Transmitted {
            t: transmitted_direction(along, n, mu, cos_t),
            cos_t,
            b: normal_weight(mu, cos_i, cos_t, one_minus_mu2),
        }
    });
    Facing {
        cos_i,
        k,
        transmitted,
    }
}

/// The refracted direction of travel for a unit travel direction `d` and a unit normal `n` on
/// either side of the surface, or `None` on total internal reflection: the fast path of the
/// default kernel, with the error bound of this module. μ as in [`refract_facing`].
#[inline]
#[must_use]
pub fn transmit<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
    refract_facing(d, facing::<S>(d, n), mu)
        .transmitted
        .map(|t| t.t)
}

/// `n` or `−n`, whichever faces the travel direction `d` (d·n ≤ 0).
#[inline(always)]
pub(crate) fn facing<S: Real>(d: S::Vec3, n: S::Vec3) -> S::Vec3 {
    if d.dot(n) > S::ZERO { -n } else { n }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn normal_incidence_goes_straight_through() {
        let down = DVec3::new(0.0, -1.0, 0.0);
        let t = transmit(down, DVec3::Y, 1.5_f64).unwrap();
        assert!((t - down).length() < 1e-15);
    }

    #[test]
    fn equal_indices_return_d_exactly_even_at_grazing() {
        let d = DVec3::new(1.0, -1e-300, 0.0);
        assert_eq!(transmit(d, DVec3::Y, 1.0), Some(d));
    }

    #[test]
    fn beyond_the_critical_angle_is_total_internal_reflection() {
        let d = DVec3::new(0.8, -0.6, 0.0);
        assert_eq!(transmit(d, DVec3::Y, 1.5), None);
        assert!(refract_facing(d, DVec3::Y, 1.5).k < 0.0);
    }

    #[test]
    fn a_normal_on_the_far_side_is_turned_to_face_the_ray() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        assert_eq!(
            transmit(d, DVec3::Y, 1.0 / 1.5),
            transmit(d, -DVec3::Y, 1.0 / 1.5)
        );
    }
}

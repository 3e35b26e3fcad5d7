//! The default refraction arithmetic: the paper's T = a·W + b·N with the discriminant and the
//! b root rearranged so that nothing cancels where the problem itself is well-conditioned.
//!
//! Work in the travel form: `d` is the unit direction of travel, `n` the unit normal that faces
//! it (d·n ≤ 0), cosθi = −d·n, μ = `μ_i/μ_t`. The paper's discriminant k = μ²wn² − μ² + 1 and the
//! GLSL form 1 − μ²(1 − cos²θi) lose accuracy in two places:
//! - equal or near-equal indices at grazing incidence: 1 − cos²θi is fine, but μ² − 1 and
//!   μ²cos²θi cancel. Here k = (μ·cosθi)² + (1 − μ)(1 + μ), where 1 − μ is exact (Sterbenz);
//! - large μ near normal incidence: 1 − cos²θi loses all its digits and μ² amplifies the loss.
//!   When cos²θi > ½, sin²θi comes from the tangential part n × (d × n) instead, and
//!   k = 1 − μ²·sin²θi.
//!
//! T itself is built as μ·(d + cosθi·n) − cosθt·n, the same vector as the paper's μ·d + b·n
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
//! one is at most 32·ε·κ with κ from [`crate::condition_number`]; |T| is within a few ε of 1;
//! T is exact when μ = 1. At grazing incidence, where |d·n| is below a few ε, which side of the
//! surface `n` lies on is decided by the sign of the rounded d·n: the problem is ill-posed there
//! (a rounding of the input moves the ray to the other side), so T may come out on either side.

use super::real::{Real, Vector3};
use super::transmission::Transmission;

/// What [`refract_facing`] finds at one interface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facing<S: Real> {
    /// cosθi = −d·n (≥ 0 up to rounding, at most 1).
    pub cos_i: S,
    /// The discriminant k = 1 − μ²(1 − cos²θi), computed stably. Negative on total internal
    /// reflection; never NaN for inputs within [`refract_facing`]'s preconditions.
    pub k: S,
    /// The transmitted ray T = a·d + b·n (a = μ, b the weight of the facing normal, built as
    /// μ·(d + cosθi·n) − cosθt·n and unit length up to a few roundings), or `None` on total
    /// internal reflection (k < 0).
    pub transmitted: Option<Transmission<S>>,
}

/// cosθi = −d·n for a facing unit normal (d·n ≤ 0, so never below 0), kept at most 1: rounding
/// can take the dot product of two unit vectors a little past ±1, and a cosine above 1 would
/// give NaN angles.
#[inline(always)]
pub(crate) fn cos_incidence<S: Real>(d: S::Vec3, n: S::Vec3) -> S {
    (-d.dot(n)).min(S::ONE)
}

/// The part of `d` along the surface, n × (d × n) = d + cosθi·n for unit `n` (of length
/// sinθi), from which T = μ·(d + cosθi·n) − cosθt·n is built. Large μ multiplies its errors
/// along `n`: as a double cross product its component along `n` is a rounding of its own length
/// (a few ε·sinθi), which μ·sinθi ≤ 1 keeps below a few ε in T, where d + cosθi·n leaves a few
/// ε (the rounding of cosθi) that μ would multiply. Its error along the surface (a few ε) is
/// the problem's own: κ grows like μ. It needs neither cosθi nor the side `n` is on (`−n` gives
/// the same bits), so the processor starts on it at once: it is on the longest chain of
/// operations in the batch kernel's lane, which bounds how fast that runs.
#[inline(always)]
pub(crate) fn tangential<S: Real>(d: S::Vec3, n: S::Vec3) -> S::Vec3 {
    n.cross(d.cross(n))
}

/// k = 1 − μ²(1 − cos²θi) without cancellation, from `scaled` = μ·(the tangential part) and
/// `cos_i` = ±cosθi (only its square is used, and it need not be clamped to 1 either): near
/// normal incidence 1 − |scaled|², so that |T|² = |scaled|² + k = 1 up to a few roundings
/// however large μ is (sin²θi from d × n alone would not do: its component along `n`, a few ε
/// whatever sinθi, is not in the tangential part, and μ² multiplies its square); otherwise
/// (μ·cosθi)² + (1 − μ)(1 + μ). Shared with the batch kernel so both round alike.
#[inline(always)]
pub(crate) fn discriminant<S: Real>(scaled: S::Vec3, cos_i: S, mu: S, one_minus_mu2: S) -> S {
    if cos_i * cos_i > S::HALF {
        S::ONE - scaled.length_squared()
    } else {
        let mc = mu * cos_i;
        mc * mc + one_minus_mu2
    }
}

/// T = μ·(d + cosθi·n) − cosθt·n from `scaled` = μ·(the tangential part): unit length up to a
/// few roundings for every accepted μ.
#[inline(always)]
pub(crate) fn transmitted_direction<S: Real>(scaled: S::Vec3, n: S::Vec3, cos_t: S) -> S::Vec3 {
    scaled - n * cos_t
}

/// b = μ·cosθi − cosθt in its cancellation-free form −(1 − μ²)/(μ·cosθi + cosθt).
#[inline(always)]
pub(crate) fn normal_weight<S: Real>(mu: S, cos_i: S, cos_t: S, one_minus_mu2: S) -> S {
    -one_minus_mu2 / (mu * cos_i + cos_t)
}

/// Refracts the unit travel direction `d` at the unit normal `n` that faces it (d·n ≤ 0), with
/// μ = `μ_i/μ_t`, and returns the cosines and the discriminant with T: what a ray tracer needs
/// for [`crate::Fresnel::new`] as well.
///
/// The arithmetic and the error bound are [`crate::transmit`]'s, and so is T, bit for bit.
/// μ = 1 returns T = d bit for bit, without refraction arithmetic; k = 0 transmits (a grazing
/// T).
///
/// # Preconditions
///
/// `d` and `n` unit length, `n` facing `d`, μ finite with ε² ≤ μ ≤ 1/ε² (ε the precision's
/// machine epsilon). They are not checked: this is also the scene tracer's per-ray call, which
/// passes the indices a scene file holds. Outside them the answer is unspecified: an `n`
/// pointing along `d` sends T back into the incident medium, as the textbook formula does, and
/// other lengths give a wrong T or a false total internal reflection. [`crate::transmit`]
/// turns the normal and asserts the rest in debug builds; [`crate::refract`] accepts anything
/// and reports what it corrected.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::{Fresnel, refract_facing};
/// let mu = 1.0 / 1.5; // air into glass
/// let facing = refract_facing(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, mu);
/// assert_eq!(facing.cos_i, 0.8);
/// let transmitted = facing.transmitted.expect("air to glass always refracts");
/// assert!((transmitted.t.x - 0.4).abs() < 1e-15); // Snell: sinθt = μ·sinθi
/// assert!((transmitted.cos_t - 0.84_f64.sqrt()).abs() < 1e-15);
/// let fresnel = Fresnel::new(mu, facing.cos_i, transmitted.cos_t);
/// assert!(fresnel.reflectance() > 0.04 && fresnel.reflectance() < 0.06);
/// ```
#[inline]
#[must_use]
pub fn refract_facing<V: Vector3>(d: V, n: V, mu: V::Scalar) -> Facing<V::Scalar> {
    let cos_i = cos_incidence::<V::Scalar>(d, n);
    if mu == V::Scalar::ONE {
        return Facing {
            cos_i,
            k: cos_i * cos_i,
            transmitted: Some(Transmission {
                t: d,
                cos_t: cos_i.abs(),
                a: mu,
                b: V::Scalar::ZERO,
            }),
        };
    }
    let one_minus_mu2 = (V::Scalar::ONE - mu) * (V::Scalar::ONE + mu);
    let scaled = tangential::<V::Scalar>(d, n) * mu;
    let k = discriminant(scaled, cos_i, mu, one_minus_mu2);
    let transmitted = (k >= V::Scalar::ZERO).then(|| {
        let cos_t = k.sqrt();
        Transmission {
            t: transmitted_direction(scaled, n, cos_t),
            cos_t,
            a: mu,
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
/// either side of the surface, or `None` on total internal reflection (k < 0): the fast path of
/// the default kernel, behind [`crate::transmit`] (which documents it and checks its
/// preconditions in debug builds), the batch kernel's lanes and the variants.
///
/// Its T is [`refract_facing`]'s for the normal turned to face `d`, bit for bit, without turning
/// the normal (see `Unturned`).
#[inline]
#[must_use]
pub(crate) fn transmit<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
    if mu == S::ONE {
        return Some(d);
    }
    let unturned = Unturned::new(d, n, mu);
    (unturned.k >= S::ZERO).then(|| unturned.direction(unturned.k.sqrt()))
}

/// [`transmit`] for a ray that must cross the surface: `None` also at k = 0, where T would lie
/// in the surface (pbrt-v4's `sin2Theta_t >= 1`); at μ = 1 that is d·n = 0.
#[inline]
#[must_use]
pub(crate) fn transmit_crossing<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
    if mu == S::ONE {
        return (d.dot(n) != S::ZERO).then_some(d);
    }
    let unturned = Unturned::new(d, n, mu);
    (unturned.k > S::ZERO).then(|| unturned.direction(unturned.k.sqrt()))
}

/// The pieces of T for a normal on either side, computed without turning it to face the ray:
/// every quantity is the one [`refract_facing`] computes for the turned normal n′ = ±n, to the
/// bit, because negation is exact. With dn = d·n (d·n′ = −|dn|):
/// - cosθi = min(|dn|, 1), but the discriminant only uses cos²θi (to choose its branch) and
///   (μ·cosθi)² where cos²θi ≤ ½, both the same bits for dn itself, so dn is passed as is;
/// - the tangential part n′ × (d × n′) = n × (d × n);
/// - cosθt·n′ = n·s with s = cosθt when n faces d (dn ≤ 0, n′ = n) and −cosθt otherwise.
///
/// This saves the turned normal's three selects and the second dot product that finding
/// cosθi from it takes, and shortens the chain of operations each ray waits on.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Unturned<S: Real> {
    /// μ·(the tangential part).
    scaled: S::Vec3,
    n: S::Vec3,
    /// The discriminant, as [`refract_facing`] finds it.
    pub(crate) k: S,
    /// Whether `n` points along the travel direction (dn > 0): the turned normal is −n.
    away: bool,
}

impl<S: Real> Unturned<S> {
    /// The pieces for unit `d` and `n` (either side) and μ ≠ 1 as accepted by
    /// [`refract_facing`].
    #[inline(always)]
    pub(crate) fn new(d: S::Vec3, n: S::Vec3, mu: S) -> Self {
        let dn = d.dot(n);
        let scaled = tangential::<S>(d, n) * mu;
        let one_minus_mu2 = (S::ONE - mu) * (S::ONE + mu);
        Self {
            scaled,
            n,
            k: discriminant(scaled, dn, mu, one_minus_mu2),
            away: dn > S::ZERO,
        }
    }

    /// T = μ·(d + cosθi·n′) − cosθt·n′ for cosθt = `cos_t` (√k).
    #[inline(always)]
    pub(crate) fn direction(&self, cos_t: S) -> S::Vec3 {
        let signed = if self.away { -cos_t } else { cos_t };
        transmitted_direction(self.scaled, self.n, signed)
    }
}

/// `n` or `−n`, whichever faces the travel direction `d` (d·n ≤ 0).
#[cfg(feature = "variants")]
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

//! The kernel's full answer for one interface: T, the reflection, the paper's numbers, the four
//! candidates and the warnings.

use super::candidates::{Candidate, candidates};
use super::checks::{Checks, condition_number};
use super::input::{
    Convention, Incidence, IndexName, InputError, VectorName, Warning, check_index, index_ratio,
    normalise,
};
use super::real::{Real, Vector3 as _};
use super::stable::refract_facing;
use super::transmission::Transmission;

/// Everything the kernel knows about one refraction. Built by [`refract`].
#[derive(Clone, Debug, PartialEq)]
pub struct Refraction<S: Real> {
    /// Ŵ: W normalised, pointing as given.
    pub w: S::Vec3,
    /// N̂: N normalised, pointing as given.
    pub n: S::Vec3,
    /// d: the unit direction the incoming ray travels in (Ŵ or −Ŵ by convention).
    pub travel: S::Vec3,
    /// The unit normal that faces the incoming ray (d·n ≤ 0): N̂ or −N̂.
    pub facing_normal: S::Vec3,
    /// μ = `μ_i/μ_t` (exactly 1 when `μ_i` == `μ_t`).
    pub mu: S,
    /// Which way W points.
    pub convention: Convention,
    /// Whether N̂ pointed away from the incoming ray and was turned around.
    pub normal_flipped: bool,
    /// cosθi = −d·n for the facing normal (≥ 0).
    pub cos_i: S,
    /// The discriminant k = 1 − μ²(1 − cos²θi); negative on total internal reflection.
    pub k: S,
    /// The transmitted ray, or `None` on total internal reflection.
    pub transmission: Option<Transmission<S>>,
    /// The mirror-reflected direction of travel d + 2·cosθi·n.
    pub reflected: S::Vec3,
    /// The four solutions of the squared constraints (empty on total internal reflection).
    pub candidates: Vec<Candidate<S>>,
    /// Probable mistakes in the input that the kernel corrected.
    pub warnings: Vec<Warning>,
}

impl<S: Real> Refraction<S> {
    /// The refracted direction of travel, or `None` on total internal reflection.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let air = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.5, mu_t: 1.0, convention: Convention::AlongRay,
    /// };
    /// let t = refract(&air(DVec3::new(0.6, 0.8, 0.0)))?.t().expect("below the critical angle");
    /// assert!((t.x - 0.9).abs() < 1e-15);
    /// assert_eq!(refract(&air(DVec3::new(0.8, 0.6, 0.0)))?.t(), None);
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn t(&self) -> Option<S::Vec3> {
        self.transmission.map(|t| t.t)
    }

    /// Whether the ray is totally internally reflected.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let air = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.5, mu_t: 1.0, convention: Convention::AlongRay,
    /// };
    /// let r = refract(&air(DVec3::new(0.8, 0.6, 0.0)))?; // 53.13° > 41.8°
    /// assert!(r.is_tir() && r.candidates.is_empty());
    /// assert_eq!(r.reflected, DVec3::new(0.8, -0.6, 0.0));
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn is_tir(&self) -> bool {
        self.transmission.is_none()
    }

    /// wn = Ŵ·N̂ as in the paper (with the vectors as given).
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let glass = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.0, mu_t: 1.5, convention: Convention::AlongRay,
    /// };
    /// let r = refract(&glass(DVec3::new(0.6, -0.8, 0.0)))?;
    /// assert_eq!((r.wn(), r.cos_i), (-0.8, 0.8));
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn wn(&self) -> S {
        self.w.dot(self.n)
    }

    /// The problem's condition number κ (see [`condition_number`]).
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let glass = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.0, mu_t: 1.5, convention: Convention::AlongRay,
    /// };
    /// let easy = refract(&glass(DVec3::NEG_Y))?;
    /// assert_eq!(easy.condition_number(), 1.0 + 1.0 / 1.5);
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn condition_number(&self) -> f64 {
        let cos_t = self.transmission.map_or(0.0, |t| t.cos_t.to_f64());
        condition_number(
            self.mu.to_f64(),
            self.cos_i.to_f64(),
            cos_t,
            S::EPSILON.to_f64(),
        )
    }

    /// The tolerance for [`Checks`] on this refraction: 32·ε·κ.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let glass = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.0, mu_t: 1.5, convention: Convention::AlongRay,
    /// };
    /// let r = refract(&glass(DVec3::new(0.6, -0.8, 0.0)))?;
    /// assert!(r.checks(r.t().unwrap()).obeys_snell(r.tolerance()));
    /// assert!(r.tolerance() < 1e-12);
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        32.0 * S::EPSILON.to_f64() * self.condition_number()
    }

    /// The residuals of any direction `t` as the refraction of this incoming ray.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::DVec3;
    /// # use refraction_kernel::{Convention, Incidence, refract};
    /// let glass = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.0, mu_t: 1.5, convention: Convention::AlongRay,
    /// };
    /// let r = refract(&glass(DVec3::new(0.6, -0.8, 0.0)))?;
    /// let unbent = r.checks(r.travel); // a ray that ignored the surface
    /// assert!(unbent.is_on_correct_side(0.0) && !unbent.obeys_snell(r.tolerance()));
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn checks(&self, t: S::Vec3) -> Checks {
        Checks::of(t, self.travel, self.facing_normal, self.mu)
    }
}

/// Refracts one incoming ray with the default (stable) kernel.
///
/// W and N may have any non-zero finite length (a length more than 1e-6 away from 1 is a
/// [`Warning`]) and N may face either way: the kernel uses the side that faces the incoming ray
/// and says so. `μ_i` == `μ_t` returns T = the travel direction exactly. The angular error of T is
/// at most 32·ε·κ ([`Refraction::condition_number`]); no output is NaN.
///
/// # Errors
/// A non-finite or all-zero W or N, an index that is not finite and > 0, or an index ratio
/// beyond 1/ε² either way: see [`InputError`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::{Convention, Incidence, InputError, VectorName, Warning, refract};
/// // pbrt's convention (W = wi, back toward the origin), a normal of length 2 on the far side.
/// let incidence = Incidence::<f64> {
///     w: DVec3::new(-0.6, 0.8, 0.0),
///     n: DVec3::new(0.0, -2.0, 0.0),
///     mu_i: 1.0,
///     mu_t: 1.5,
///     convention: Convention::TowardOrigin,
/// };
/// let r = refract(&incidence)?;
/// assert!((r.t().unwrap() - DVec3::new(0.4, -(0.84_f64).sqrt(), 0.0)).length() < 1e-15);
/// assert_eq!(r.warnings.len(), 2); // N was not unit length, and it was turned round
/// assert_eq!(r.warnings[1], Warning::NormalFlipped);
/// let no_normal = refract(&Incidence { n: DVec3::ZERO, ..incidence });
/// assert_eq!(no_normal, Err(InputError::ZeroVector(VectorName::N)));
/// # Ok::<(), InputError>(())
/// ```
pub fn refract<S: Real>(incidence: &Incidence<S>) -> Result<Refraction<S>, InputError> {
    let mut warnings = Vec::new();
    let mu_i = check_index(incidence.mu_i, IndexName::MuI)?;
    let mu_t = check_index(incidence.mu_t, IndexName::MuT)?;
    let w = normalise::<S>(incidence.w, VectorName::W, &mut warnings)?;
    let n = normalise::<S>(incidence.n, VectorName::N, &mut warnings)?;
    let mu = if mu_i == mu_t {
        S::ONE
    } else {
        index_ratio(mu_i, mu_t)?
    };
    let sign = incidence.convention.travel_sign::<S>();
    let travel = w * sign;
    let normal_flipped = travel.dot(n) > S::ZERO;
    let facing_normal = if normal_flipped { -n } else { n };
    if normal_flipped {
        warnings.push(Warning::NormalFlipped);
    }
    let facing = refract_facing(travel, facing_normal, mu);
    // From d and the facing normal back to Ŵ and N̂ as given.
    let transmission = facing.transmitted.map(|tr| Transmission {
        a: sign * tr.a,
        b: if normal_flipped { -tr.b } else { tr.b },
        ..tr
    });
    let candidates = transmission.map_or_else(Vec::new, |tr| {
        candidates((tr.a, tr.b), tr.t, w.dot(n), n, normal_flipped).to_vec()
    });
    Ok(Refraction {
        w,
        n,
        travel,
        facing_normal,
        mu,
        convention: incidence.convention,
        normal_flipped,
        cos_i: facing.cos_i,
        k: facing.k,
        transmission,
        reflected: travel + facing_normal * (S::TWO * facing.cos_i),
        candidates,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rejection;
    use glam::DVec3;

    fn incidence(w: DVec3, n: DVec3, convention: Convention) -> Incidence<f64> {
        Incidence {
            w,
            n,
            mu_i: 1.0,
            mu_t: 1.5,
            convention,
        }
    }

    #[test]
    fn weights_reproduce_t_in_both_conventions() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        for (w, convention) in [(d, Convention::AlongRay), (-d, Convention::TowardOrigin)] {
            for n in [DVec3::Y, -DVec3::Y] {
                let r = refract(&incidence(w, n, convention)).unwrap();
                let tr = r.transmission.unwrap();
                assert!((r.w * tr.a + r.n * tr.b - tr.t).length() < 1e-15);
                assert_eq!(r.normal_flipped, n == -DVec3::Y);
                assert!(tr.t.y < 0.0);
            }
        }
    }

    #[test]
    fn the_source_chooses_the_second_b_root_in_both_sections() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        for (w, convention, a_sign) in [
            (d, Convention::AlongRay, 1.0),
            (-d, Convention::TowardOrigin, -1.0),
        ] {
            let r = refract(&incidence(w, DVec3::Y, convention)).unwrap();
            let chosen: Vec<_> = r.candidates.iter().map(Candidate::is_chosen).collect();
            let expected = if a_sign > 0.0 {
                [false, true, false, false]
            } else {
                [false, false, false, true]
            };
            assert_eq!(chosen, expected);
            let (mu, wn, k) = (r.mu, r.wn(), r.k);
            for c in &r.candidates {
                let root = c.b + c.a * wn;
                assert!((root.abs() - k.sqrt()).abs() < 1e-15, "{c:?}");
                assert!((c.a.abs() - mu).abs() < 1e-15);
                assert!((r.w * c.a + r.n * c.b - c.t).length() < 1e-15);
            }
        }
    }

    #[test]
    fn each_rejected_candidate_breaks_its_rule() {
        let r = refract(&incidence(
            DVec3::new(0.6, -0.8, 0.0),
            DVec3::Y,
            Convention::AlongRay,
        ))
        .unwrap();
        let tol = r.tolerance();
        for c in &r.candidates {
            let checks = r.checks(c.t);
            assert!(checks.is_unit(tol) && checks.obeys_squared_snell(tol));
            let expected_side = !matches!(
                c.rejection,
                Some(Rejection::WrongSide | Rejection::Reversed)
            );
            let expected_bend = !matches!(
                c.rejection,
                Some(Rejection::WrongBend | Rejection::Reversed)
            );
            assert_eq!(checks.is_on_correct_side(tol), expected_side, "{c:?}");
            assert_eq!(checks.bends_correctly(tol), expected_bend, "{c:?}");
        }
    }

    #[test]
    fn tir_has_reflection_but_no_candidates() {
        let r = refract(&Incidence::<f64> {
            w: DVec3::new(0.8, -0.6, 0.0),
            n: DVec3::Y,
            mu_i: 1.5,
            mu_t: 1.0,
            convention: Convention::AlongRay,
        })
        .unwrap();
        assert!(r.is_tir() && r.candidates.is_empty() && r.k < 0.0);
        assert!((r.reflected - DVec3::new(0.8, 0.6, 0.0)).length() < 1e-15);
    }
}

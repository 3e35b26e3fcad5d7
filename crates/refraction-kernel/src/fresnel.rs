//! How much of the light is reflected and how much transmitted: the Fresnel power fractions for
//! light polarised perpendicular (s) and parallel (p) to the plane of incidence, from the
//! cosines the kernel has already computed. No trigonometry.
//!
//! # The forms and why
//!
//! With μ = `μ_i/μ_t`, a = μ·cosθi and c = cosθt (both ≥ 0), the textbook amplitudes divided
//! through by `μ_t` are `r_s` = (a − c)/(a + c) and `r_p` = (cosθi − μ·cosθt)/(cosθi + μ·cosθt), and
//! the power fractions are R = r², T = 1 − R. Taken literally these lose digits in three
//! places: `r_s`'s numerator cancels when μ is near 1, `r_p`'s at Brewster's angle, and T = 1 − R
//! keeps none of its relative accuracy where T is small (near grazing incidence and near the
//! critical angle, exactly where a class looks at how the transmitted light fades). Instead:
//!
//! - **`R_s`.** The numerator is rewritten with its conjugate, as the kernel's weight b is:
//!   a − c = (a² − c²)/(a + c) and, since c² = cos²θt = μ²cos²θi + 1 − μ²,
//!   a² − c² = −(1 − μ)(1 + μ). So `r_s` = −(1 − μ)(1 + μ)/(a + c)²: a product and quotient of
//!   terms that do not cancel (1 − μ is exact for ½ ≤ μ ≤ 2 by Sterbenz's lemma), zero exactly
//!   at μ = 1.
//! - **`R_p`.** Fresnel's sine and tangent laws, `r_s` = −sin(θi − θt)/sin(θi + θt) and
//!   `r_p` = tan(θi − θt)/tan(θi + θt), give `r_p` = −`r_s·q` with
//!   q = cos(θi + θt)/cos(θi − θt) = (cosθi·cosθt − μ·sin²θi)/(cosθi·cosθt + μ·sin²θi), using
//!   sinθt = μ·sinθi. The zero of `r_p` at Brewster's angle (θi + θt = 90°) is the zero of q's
//!   numerator alone, where it belongs; the denominator cos(θi − θt) is at least min(μ, 1/μ).
//!   μ·sin²θi comes from the cosine of the larger angle, which keeps the digits:
//!   μ·(1 − cosθi)(1 + cosθi) for μ ≤ 1, (1 − cosθt)(1 + cosθt)/μ for μ > 1 (for large μ near
//!   normal incidence cosθi rounds to 1 and only cosθt still knows the angle).
//! - **T.** `T_s` = 4ac/(a + c)² and `T_p` = 4·cosθi·μcosθt/(cosθi + μcosθt)²: products and sums
//!   of non-negative numbers, accurate relative to themselves however small.
//! - **R + T = 1.** Of each pair the smaller share is kept as computed and the larger is
//!   1 − smaller: subtracting at most ½ from 1 costs the larger at most ½ε more, and the two
//!   then sum to 1 within ½ε for any cosines (also ones that no refraction produces).
//!
//! # Error bound
//!
//! Counting roundings (u = ε/2 each): `r_s` carries at most 9u relative error, so `R_s` (kept only
//! when ≤ ½) is within 5ε; `T_s` and `T_p` likewise within 4ε; q is within about 11u absolute, which
//! puts `R_p` within 16ε in the worst case. These assume cosines that satisfy Snell's law
//! exactly. The kernel's satisfy it to a few ε (near normal incidence cosθt comes from the
//! tangential part of W, not from cosθi), and the forms, trusting μ, read that slack
//! differently from the textbook, which trusts cosθt: up to about 2ε more. The
//! `refraction-bench` crate's `tests/fresnel_accuracy.rs` measures, against a double-double
//! oracle and for the kernel's own cosines, at most 3.8ε (f64) and 1.3ε (f32) at normal
//! incidence, near Brewster's angle, near grazing, near the critical angle and for μ from 1e-6
//! to 1e6. Against the exact fractions for the *input* W, N and indices, the rounding of μ
//! and of the cosines adds the fractions' own sensitivity to their input: a few ε almost
//! everywhere, unbounded at the critical angle, where R has an infinite slope
//! (R = 1 − O(√(θc − θi))), and large near grazing incidence between near-equal indices,
//! which is close to it. There the problem, not the formula, decides the digits.

use super::real::Real;
use super::refraction::Refraction;

/// The fractions of the incident power reflected and transmitted at one interface, for light
/// polarised perpendicular (s) and parallel (p) to the plane of incidence. Each in [0, 1];
/// `rs + ts` and `rp + tp` are 1 within ½ε.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Fresnel<S> {
    /// Reflectance `R_s`.
    pub rs: S,
    /// Reflectance `R_p`.
    pub rp: S,
    /// Transmittance `T_s`.
    pub ts: S,
    /// Transmittance `T_p`.
    pub tp: S,
}

/// (R, T) of one polarisation from its accurately computed shares: the smaller kept, the
/// larger as 1 − smaller, so that R + T = 1 within ½ε and both stay in [0, 1].
fn complement<S: Real>(r: S, t: S) -> (S, S) {
    if r <= t {
        (r, S::ONE - r)
    } else {
        let t = t.max(S::ZERO).min(S::ONE);
        (S::ONE - t, t)
    }
}

/// 4xy/(x + y)² for x, y ≥ 0 with x + y > 0: the transmitted share of admittances x and y.
fn transmitted<S: Real>(x: S, y: S) -> S {
    let sum = x + y;
    (S::TWO + S::TWO) * x * y / (sum * sum)
}

/// μ·sin²θi = sinθi·sinθt from the cosine of the larger angle (see the module docs).
fn mu_sin2<S: Real>(mu: S, cos_i: S, cos_t: S) -> S {
    if mu <= S::ONE {
        mu * ((S::ONE - cos_i) * (S::ONE + cos_i))
    } else {
        (S::ONE - cos_t) * (S::ONE + cos_t) / mu
    }
}

impl<S: Real> Fresnel<S> {
    /// Total internal reflection: everything reflected.
    pub const TOTAL_REFLECTION: Self = Self {
        rs: S::ONE,
        rp: S::ONE,
        ts: S::ZERO,
        tp: S::ZERO,
    };

    /// Equal indices: there is no interface, nothing is reflected.
    const NO_INTERFACE: Self = Self {
        rs: S::ZERO,
        rp: S::ZERO,
        ts: S::ONE,
        tp: S::ONE,
    };

    /// The Fresnel fractions for μ = `μ_i/μ_t` (> 0, finite) and the kernel's cosθi, cosθt of a
    /// transmitted ray (both in [0, 1], as in [`crate::Facing`] and [`crate::Transmission`]),
    /// with the error bound of the module docs. μ = 1 reflects nothing. Never NaN for inputs in
    /// range, whatever the cosines.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Fresnel;
    /// // Normal incidence from air on glass: 4% reflected in either polarisation.
    /// let f = Fresnel::new(1.0_f64 / 1.5, 1.0, 1.0);
    /// assert!((f.rs - 0.04).abs() < 1e-15 && (f.rp - 0.04).abs() < 1e-15);
    /// assert_eq!(f.rs + f.ts, 1.0);
    /// ```
    #[must_use]
    pub fn new(mu: S, cos_i: S, cos_t: S) -> Self {
        if mu == S::ONE {
            return Self::NO_INTERFACE;
        }
        let a = mu * cos_i;
        let sum_s = a + cos_t;
        if sum_s <= S::ZERO {
            // cosθi = cosθt = 0 needs μ = 1; other indices get here only from cosines no
            // refraction has. Grazing at the critical angle is the limit: all reflected.
            return Self::TOTAL_REFLECTION;
        }
        let r_s = -((S::ONE - mu) * (S::ONE + mu)) / (sum_s * sum_s);
        let x = cos_i * cos_t;
        let y = mu_sin2(mu, cos_i, cos_t);
        // x + y = cos(θi − θt) ≥ min(μ, 1/μ) > 0 for a refraction; 0 only for cosθi = 1 with
        // cosθt = 0 (or the reverse), which no refraction has: take q = 1 there.
        let q = if x + y > S::ZERO {
            (x - y) / (x + y)
        } else {
            S::ONE
        };
        let r_p = r_s * q;
        let (rs, ts) = complement(r_s * r_s, transmitted(a, cos_t));
        let (rp, tp) = complement(r_p * r_p, transmitted(cos_i, mu * cos_t));
        Self { rs, rp, ts, tp }
    }

    /// The Fresnel fractions of the kernel's answer: [`Self::TOTAL_REFLECTION`] on total
    /// internal reflection, otherwise [`Self::new`] with its μ, cosθi and cosθt.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::{Convention, Fresnel, Incidence, refract};
    /// let from_glass = |w| Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.5, mu_t: 1.0, convention: Convention::AlongRay,
    /// };
    /// let steep = Fresnel::of(&refract(&from_glass(DVec3::new(0.3, 0.91_f64.sqrt(), 0.0)))?);
    /// assert!(steep.transmittance() > 0.9);
    /// let past_critical = refract(&from_glass(DVec3::new(0.8, 0.6, 0.0)))?;
    /// assert_eq!(Fresnel::of(&past_critical), Fresnel::TOTAL_REFLECTION);
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn of(refraction: &Refraction<S>) -> Self {
        refraction.transmission.map_or(Self::TOTAL_REFLECTION, |t| {
            Self::new(refraction.mu, refraction.cos_i, t.cos_t)
        })
    }

    /// The reflectance of unpolarised light: (`R_s` + `R_p)/2`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Fresnel;
    /// let f = Fresnel { rs: 0.25, rp: 0.05, ts: 0.75, tp: 0.95 };
    /// assert_eq!(f.reflectance(), 0.15);
    /// ```
    #[must_use]
    pub fn reflectance(&self) -> S {
        (self.rs + self.rp) * S::HALF
    }

    /// The transmittance of unpolarised light: (`T_s` + `T_p)/2`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Fresnel;
    /// assert_eq!(Fresnel::<f32>::TOTAL_REFLECTION.transmittance(), 0.0);
    /// let f = Fresnel { rs: 0.25, rp: 0.05, ts: 0.75, tp: 0.95 };
    /// assert_eq!(f.transmittance(), 0.85);
    /// ```
    #[must_use]
    pub fn transmittance(&self) -> S {
        (self.ts + self.tp) * S::HALF
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// cosθt for μ and cosθi by Snell's law in f64.
    fn cos_t(mu: f64, cos_i: f64) -> f64 {
        (1.0 - mu * mu * (1.0 - cos_i * cos_i)).sqrt()
    }

    #[test]
    fn normal_incidence_on_glass_reflects_four_percent_in_both_polarisations() {
        let f = Fresnel::new(1.0_f64 / 1.5, 1.0, 1.0);
        assert!((f.rs - 0.04).abs() < 1e-16 && (f.rp - 0.04).abs() < 1e-16);
        assert!((f.ts - 0.96).abs() < 1e-15 && (f.reflectance() - 0.04).abs() < 1e-16);
    }

    #[test]
    fn brewster_angle_reflects_no_p_light_and_the_zero_is_sharp() {
        // tanθB = 1.5 from air into glass: cosθi = 1/√3.25.
        let mu = 1.0 / 1.5;
        let cos_i = 1.0 / 3.25_f64.sqrt();
        let f = Fresnel::new(mu, cos_i, cos_t(mu, cos_i));
        assert!(f.rp < 1e-30, "R_p = {:e}", f.rp);
        assert!((f.rs - 0.1479).abs() < 1e-4 && f.tp == 1.0);
    }

    #[test]
    fn near_equal_indices_keep_relative_accuracy_in_the_reflectance() {
        // μ = 1 − 1e-12: R_s at normal incidence is ((1 − μ)/(1 + μ))² = 2.5e-25 to 12 digits.
        let mu = 1.0 - 1e-12;
        let f = Fresnel::new(mu, 1.0, cos_t(mu, 1.0));
        let exact = ((1.0 - mu) / (1.0 + mu)).powi(2);
        assert!(
            ((f.rs - exact) / exact).abs() < 1e-10,
            "{:e} vs {exact:e}",
            f.rs
        );
        assert!(
            ((f.rp - exact) / exact).abs() < 1e-10,
            "{:e} vs {exact:e}",
            f.rp
        );
    }

    #[test]
    fn transmission_fades_smoothly_to_the_critical_angle() {
        // Glass to air, cosθt = 1e-9: T ≈ 4·cosθt·a/a², small but with all its digits.
        let mu = 1.5;
        let ct = 1e-9;
        let cos_i = ((ct * ct + mu * mu - 1.0) / (mu * mu)).sqrt();
        let f = Fresnel::new(mu, cos_i, ct);
        let a = mu * cos_i;
        let exact_ts = 4.0 * a * ct / ((a + ct) * (a + ct));
        assert!(((f.ts - exact_ts) / exact_ts).abs() < 1e-14);
        assert!(f.rs < 1.0 && f.rs + f.ts == 1.0);
    }

    #[test]
    fn equal_indices_reflect_nothing_even_at_grazing_incidence() {
        assert_eq!(Fresnel::new(1.0_f32, 0.0, 0.0), Fresnel::NO_INTERFACE);
        assert_eq!(Fresnel::new(1.0_f64, 0.3, 0.3).rp, 0.0);
    }

    #[test]
    fn total_internal_reflection_reflects_everything() {
        use crate::{Convention, Incidence, refract};
        let r = refract(&Incidence::<f32> {
            w: glam::Vec3::new(0.8, -0.6, 0.0),
            n: glam::Vec3::Y,
            mu_i: 1.5,
            mu_t: 1.0,
            convention: Convention::AlongRay,
        })
        .unwrap();
        assert_eq!(Fresnel::of(&r), Fresnel::TOTAL_REFLECTION);
    }

    #[test]
    fn cosines_no_refraction_has_still_give_shares_in_range() {
        for (mu, ci, ct) in [
            (2.0, 1.0, 0.0),
            (0.5, 0.0, 1.0),
            (3.0, 0.0, 0.0),
            (0.1, 1.0, 0.0),
        ] {
            let f = Fresnel::new(mu, ci, ct);
            for x in [f.rs, f.rp, f.ts, f.tp] {
                assert!((0.0..=1.0).contains(&x), "{mu} {ci} {ct}: {f:?}");
            }
        }
    }
}

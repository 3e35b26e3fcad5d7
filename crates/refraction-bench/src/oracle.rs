//! The exact answer the kernel is measured against: the textbook refraction formula evaluated in
//! double-double arithmetic (`twofloat`, about 106 bits) from the kernel's own input values.
//!
//! With roughly 32 decimal digits, the oracle's own rounding is some 1e-16 times smaller than
//! anything an f64 kernel can resolve, except within about 1e-30 of the critical angle.

use twofloat::TwoFloat;

use refraction_kernel::{Convention, condition_number};

/// A 3D vector of double-doubles.
pub type Vec3DD = [TwoFloat; 3];

/// The exact refraction of one input, as far as double-double can tell.
#[derive(Clone, Copy, Debug)]
pub struct Exact {
    /// The unit refracted direction of travel, or `None` on total internal reflection.
    pub t: Option<Vec3DD>,
    /// The discriminant k = 1 − μ²·sin²θi.
    pub k: TwoFloat,
    /// cosθi ≥ 0, with the normal facing the incoming ray.
    pub cos_i: TwoFloat,
    /// cosθt = √k, or 0 on total internal reflection.
    pub cos_t: TwoFloat,
    /// μ = `μ_i/μ_t`.
    pub mu: TwoFloat,
}

impl Exact {
    /// The condition number κ of the problem (see [`condition_number`]) for a precision with
    /// machine epsilon `epsilon`.
    #[must_use]
    pub fn condition_number(&self, epsilon: f64) -> f64 {
        condition_number(self.mu.hi(), self.cos_i.hi(), self.cos_t.hi(), epsilon)
    }

    /// Whether the ray is totally internally reflected.
    #[must_use]
    pub fn is_tir(&self) -> bool {
        self.t.is_none()
    }

    /// The exact Fresnel fractions of this refraction (all reflected on total internal
    /// reflection).
    #[must_use]
    pub fn fresnel(&self) -> ExactFresnel {
        if self.is_tir() {
            ExactFresnel::TOTAL_REFLECTION
        } else {
            fresnel_of(self.mu, self.cos_i, self.cos_t)
        }
    }
}

/// The exact Fresnel fractions for μ and cosθi in double-double (cosθt from Snell's law; all
/// reflected on total internal reflection): for measuring how sensitive the fractions are to
/// their input. `cos_i` must be in [0, 1], `mu` > 0.
#[must_use]
pub fn fresnel_at(mu: TwoFloat, cos_i: TwoFloat) -> ExactFresnel {
    let k = discriminant(mu, cos_i);
    if k < 0.0 {
        ExactFresnel::TOTAL_REFLECTION
    } else {
        fresnel_of(mu, cos_i, k.sqrt())
    }
}

/// The Fresnel power fractions in double-double, for s and p polarisation.
#[derive(Clone, Copy, Debug)]
pub struct ExactFresnel {
    /// Reflectance `R_s`.
    pub rs: TwoFloat,
    /// Reflectance `R_p`.
    pub rp: TwoFloat,
    /// Transmittance `T_s`.
    pub ts: TwoFloat,
    /// Transmittance `T_p`.
    pub tp: TwoFloat,
}

impl ExactFresnel {
    /// Total internal reflection: everything reflected.
    const TOTAL_REFLECTION: Self = Self {
        rs: TwoFloat::from_f64(1.0),
        rp: TwoFloat::from_f64(1.0),
        ts: TwoFloat::from_f64(0.0),
        tp: TwoFloat::from_f64(0.0),
    };

    /// The four fractions in the order `R_s`, `R_p`, `T_s`, `T_p`.
    #[must_use]
    pub fn to_array(&self) -> [TwoFloat; 4] {
        [self.rs, self.rp, self.ts, self.tp]
    }
}

/// The textbook Fresnel fractions, R = ((x − y)/(x + y))² and T = 4xy/(x + y)² with
/// (x, y) = (μ·cosθi, cosθt) for s and (cosθi, μ·cosθt) for p, evaluated in double-double
/// from `mu`, `cos_i` and `cos_t` taken as exact. The literal form is the point: with some 32
/// digits its cancellations cost the oracle nothing an f64 can see. μ = 1 reflects nothing;
/// otherwise the cosines must be ≥ 0 and not both zero.
#[must_use]
pub fn fresnel(mu: f64, cos_i: f64, cos_t: f64) -> ExactFresnel {
    fresnel_of(
        TwoFloat::from(mu),
        TwoFloat::from(cos_i),
        TwoFloat::from(cos_t),
    )
}

fn fresnel_of(mu: TwoFloat, cos_i: TwoFloat, cos_t: TwoFloat) -> ExactFresnel {
    if mu == 1.0 {
        // Equal indices: no interface, nothing reflected (also at grazing incidence, where
        // both admittances vanish).
        return ExactFresnel {
            rs: TwoFloat::from(0.0),
            rp: TwoFloat::from(0.0),
            ts: TwoFloat::from(1.0),
            tp: TwoFloat::from(1.0),
        };
    }
    let split = |x: TwoFloat, y: TwoFloat| {
        let inverse = reciprocal(x + y);
        let r = (x - y) * inverse;
        (r * r, x * y * inverse * inverse * 4.0)
    };
    let (rs, ts) = split(mu * cos_i, cos_t);
    let (rp, tp) = split(cos_i, mu * cos_t);
    ExactFresnel { rs, rp, ts, tp }
}

/// 1/x for x > 0, to double-double accuracy: one Newton step from the f64 estimate (see
/// [`reciprocal_sqrt`] for why the oracle never divides by a double-double).
fn reciprocal(x: TwoFloat) -> TwoFloat {
    let r = TwoFloat::from(1.0 / x.hi());
    r + r * (TwoFloat::from(1.0) - x * r)
}

fn dd(v: [f64; 3]) -> Vec3DD {
    v.map(TwoFloat::from)
}

fn dot(a: &Vec3DD, b: &Vec3DD) -> TwoFloat {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn scale(a: &Vec3DD, s: TwoFloat) -> Vec3DD {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn add(a: &Vec3DD, b: &Vec3DD) -> Vec3DD {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// 1/√x for x > 0, to double-double accuracy: one Newton step from the f64 estimate.
///
/// twofloat's double-double ÷ double-double leaves out the fused multiply-add of its source
/// algorithm (Joldes et al. 2017, Algorithm 18) and is only f64-accurate, so the oracle never
/// divides by a double-double: it divides by f64 values (Algorithm 15, accurate) or multiplies
/// by this reciprocal square root.
fn reciprocal_sqrt(x: TwoFloat) -> TwoFloat {
    let r = TwoFloat::from(1.0 / x.hi().sqrt());
    r + r * (TwoFloat::from(1.0) - x * r * r) * 0.5
}

/// `v` scaled to unit length (by its largest component first, so no square over- or
/// underflows). `v` must be finite and non-zero.
fn unit(v: &Vec3DD) -> Vec3DD {
    let largest = v.iter().map(|c| c.hi().abs()).fold(0.0, f64::max);
    let scaled = v.map(|c| c / largest);
    scale(&scaled, reciprocal_sqrt(dot(&scaled, &scaled)))
}

/// k = 1 − μ²(1 − cos²θi), arranged so that μ = 1 gives cos²θi ≥ 0 exactly.
fn discriminant(mu: TwoFloat, cos_i: TwoFloat) -> TwoFloat {
    mu * mu * cos_i * cos_i + (TwoFloat::from(1.0) - mu) * (TwoFloat::from(1.0) + mu)
}

/// The exact refraction of `w` at `n` with indices `mu_i`, `mu_t` in `convention`, the normal
/// turned to face the incoming ray. Inputs must be valid for the kernel (finite, non-zero
/// vectors, indices > 0).
#[must_use]
pub fn refract(w: [f64; 3], n: [f64; 3], mu_i: f64, mu_t: f64, convention: Convention) -> Exact {
    let d = travel(w, convention);
    let facing = if dot(&d, &dd(n)) > 0.0 {
        n.map(|c| -c)
    } else {
        n
    };
    refract_facing(w, facing, mu_i, mu_t, convention)
}

fn travel(w: [f64; 3], convention: Convention) -> Vec3DD {
    scale(
        &unit(&dd(w)),
        TwoFloat::from(convention.travel_sign::<f64>()),
    )
}

/// As [`refract`], but with `n` used as given even if it points slightly along the ray: for
/// grazing rays, whose side of the surface is decided by the rounding of the dot product.
#[must_use]
pub fn refract_facing(
    w: [f64; 3],
    n: [f64; 3],
    mu_i: f64,
    mu_t: f64,
    convention: Convention,
) -> Exact {
    let d = travel(w, convention);
    let n = unit(&dd(n));
    let mu = TwoFloat::new_div(mu_i, mu_t);
    let cos_i = -dot(&d, &n);
    let k = discriminant(mu, cos_i);
    if k < 0.0 {
        return Exact {
            t: None,
            k,
            cos_i,
            cos_t: TwoFloat::from(0.0),
            mu,
        };
    }
    let cos_t = k.sqrt();
    let tangential = add(&d, &scale(&n, cos_i));
    let t = add(&scale(&tangential, mu), &scale(&n, -cos_t));
    Exact {
        t: Some(unit(&t)),
        k,
        cos_i,
        cos_t,
        mu,
    }
}

/// The angle in radians between a computed direction `t` (any non-zero length) and the exact
/// unit direction `exact`; `f64::INFINITY` when `t` is zero or not finite.
#[must_use]
pub fn angular_error(t: [f64; 3], exact: &Vec3DD) -> f64 {
    if t.iter().any(|c| !c.is_finite()) || t.iter().all(|&c| c == 0.0) {
        return f64::INFINITY;
    }
    let diff = add(&unit(&dd(t)), &scale(exact, TwoFloat::from(-1.0)));
    let chord = dot(&diff, &diff).sqrt().hi();
    2.0 * (chord / 2.0).min(1.0).asin()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snell_at_a_textbook_angle() {
        let exact = refract(
            [0.6, -0.8, 0.0],
            [0.0, 1.0, 0.0],
            1.0,
            1.5,
            Convention::AlongRay,
        );
        let t = exact.t.unwrap().map(|c| c.hi());
        assert!((t[0] - 0.4).abs() < 1e-16);
        assert!((t[1] + (1.0_f64 - 0.16).sqrt()).abs() < 1e-16);
    }

    #[test]
    fn angular_error_of_a_known_rotation() {
        let exact = dd([1.0, 0.0, 0.0]);
        let err = angular_error([1.0, 1e-9, 0.0], &exact);
        assert!((err - 1e-9).abs() < 1e-20);
        assert_eq!(angular_error([0.0; 3], &exact), f64::INFINITY);
    }

    #[test]
    fn fresnel_at_normal_incidence_and_brewster() {
        let f = fresnel(1.0 / 1.5, 1.0, 1.0);
        let four_percent = TwoFloat::new_div(1.0, 25.0);
        // μ = 1/1.5 is rounded, so 0.04 holds to f64 accuracy, not beyond.
        assert!((f.rs - four_percent).abs() < 1e-16 && (f.rp - four_percent).abs() < 1e-16);
        assert!((f.rs + f.ts - 1.0).abs() < 1e-30);
        let exact = refract(
            [1.5, -1.0, 0.0],
            [0.0, 1.0, 0.0],
            1.0,
            1.5,
            Convention::AlongRay,
        );
        assert!(exact.fresnel().rp.hi() < 1e-30);
    }

    #[test]
    fn reciprocal_is_accurate_to_double_double() {
        let x = TwoFloat::from(3.0) + TwoFloat::from(1e-20);
        assert!((reciprocal(x) * x - 1.0).abs() < 1e-30);
    }

    #[test]
    fn normalisation_is_accurate_to_double_double() {
        let s = 0.999_999_999_999_f64;
        let u = unit(&dd([s, -(1.0 - s * s).sqrt(), 0.0]));
        let error = (dot(&u, &u) - 1.0).abs();
        assert!(error < 1e-30, "|u|^2 - 1 = {error:e}");
    }
}

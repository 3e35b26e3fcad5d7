//! Mitsuba 3's `fresnel(cos_theta_i, eta)` and `refract`, as its dielectric BSDF uses them.
//!
//! Source: Mitsuba 3 (commit b45b0a9), `include/mitsuba/render/fresnel.h`, `fresnel`: with
//! `outside = cos_theta_i >= 0`, `eta_it = outside ? eta : 1/eta`, `eta_ti = outside ? 1/eta :
//! eta`, `cos_theta_t_sqr = fnmadd(fnmadd(cos_theta_i, cos_theta_i, 1), eta_ti * eta_ti, 1)`,
//! `cos_theta_t = mulsign_neg(safe_sqrt(cos_theta_t_sqr), cos_theta_i)` and the Fresnel
//! reflectance `F` (1 on total internal reflection, 0 when `eta == 1`, 1 at `cos_theta_i == 0`);
//! `refract(wi, cos_theta_t, eta_ti)` = `(-eta_ti * wi.x, -eta_ti * wi.y, cos_theta_t)` in the
//! local frame (normal +z), and `refract(wi, m, cos_theta_t, eta_ti)` =
//! `fmsub(m, fmadd(dot(wi, m), eta_ti, cos_theta_t), wi * eta_ti)`. `src/bsdfs/dielectric.cpp`,
//! `SmoothDielectric::sample`, calls `fresnel(Frame3f::cos_theta(si.wi), m_eta)` with
//! `m_eta = int_ior / ext_ior` and takes `refract(si.wi, cos_theta_t, eta_ti)` unless it samples
//! reflection (with probability F). `si.wi` points away from the surface, back along the ray.
//!
//! Dr.Jit (`include/drjit/array_router.h`, `array_utils.h`): `fmadd(a, b, c)` is a true fused
//! multiply-add in the JIT variants (LLVM, CUDA) and in scalar builds for a CPU with FMA, and
//! `a * b + c` otherwise; `fnmadd(a, b, c) = fmadd(-a, b, c)`, `fmsub(a, b, c) = fmadd(a, b, -c)`,
//! `safe_sqrt(a) = sqrt(maximum(a, 0))` (NaN passes through), `rcp(a) = 1 / a`, and
//! `mulsign_neg(v, s)` negates v unless s has its sign bit set. A scalar vector's `dot` sums
//! `(x·x′ + y·y′) + z·z′`; the JIT variants' starts with `x·x′` and fuses the rest.
//!
//! The docstrings disagree with the code in one place: `refract(wi, m, cos_theta_t, eta_ti)`
//! calls `eta_ti` "transmitted / incident", but `fresnel` returns, and the code uses,
//! `n_incident/n_transmitted` (μ).

use super::Meaning;
use crate::real::{Real, Vector3 as _};

/// Whether Dr.Jit's `fmadd` is fused (one rounding) or a multiply then an add.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Fma {
    /// A true fused multiply-add: the LLVM and CUDA variants, or a scalar build with FMA.
    Fused,
    /// `a * b + c` rounded twice: a scalar variant (such as `scalar_rgb`) built without FMA,
    /// as the generic x86-64 wheels are.
    #[default]
    Unfused,
}

impl Fma {
    fn fmadd<S: Real>(self, a: S, b: S, c: S) -> S {
        match self {
            Self::Fused => a.mul_add(b, c),
            Self::Unfused => a * b + c,
        }
    }

    fn fnmadd<S: Real>(self, a: S, b: S, c: S) -> S {
        self.fmadd(-a, b, c)
    }

    fn fmsub<S: Real>(self, a: S, b: S, c: S) -> S {
        self.fmadd(a, b, -c)
    }

    /// Dr.Jit's `dot` of two 3-vectors in this kind of variant.
    fn dot<S: Real>(self, a: [S; 3], b: [S; 3]) -> S {
        match self {
            Self::Fused => self.fmadd(a[2], b[2], self.fmadd(a[1], b[1], a[0] * b[0])),
            Self::Unfused => a[0] * b[0] + a[1] * b[1] + a[2] * b[2],
        }
    }
}

/// The four values `fresnel(cos_theta_i, eta)` returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fresnel<S: Real> {
    /// F, the Fresnel reflectance: the probability that the BSDF samples reflection (1 on total
    /// internal reflection, so it never transmits there).
    pub f: S,
    /// cosθt, negative when the ray enters (`cos_theta_i` ≥ +0), ±0 on total internal reflection.
    pub cos_theta_t: S,
    /// `n_transmitted/n_incident` along the ray.
    pub eta_it: S,
    /// `n_incident/n_transmitted` along the ray: μ, the scale of the tangential part.
    pub eta_ti: S,
}

/// Dr.Jit's `safe_sqrt`: `sqrt(maximum(a, 0))`, where `maximum_(a, b)` keeps a NaN `a`.
fn safe_sqrt<S: Real>(a: S) -> S {
    if a > S::ZERO || a.is_nan() {
        a.sqrt()
    } else {
        S::ZERO
    }
}

/// Dr.Jit's `mulsign_neg(v, s)`: v with its sign flipped unless s has its sign bit set.
fn mulsign_neg<S: Real>(v: S, s: S) -> S {
    if s.is_sign_negative() { v } else { -v }
}

/// What Mitsuba 3's `fresnel(cos_theta_i, eta)` returns, bit for bit for the given `fma`.
///
/// `cos_theta_i` is the cosine between the shading normal and `wi` (positive on the exterior
/// side the normal points to), `eta` = `n_interior/n_exterior`.
///
/// # Examples
///
/// ```
/// use refraction_kernel::api::mitsuba::{Fma, fresnel};
/// // From outside onto glass at normal incidence: 4% reflected, cosθt = −1 (entering).
/// let f = fresnel::<f64>(1.0, 1.5, Fma::Unfused);
/// assert!((f.f - 0.04).abs() < 1e-15);
/// assert_eq!((f.cos_theta_t, f.eta_ti), (-1.0, 1.0 / 1.5));
/// ```
#[must_use]
pub fn fresnel<S: Real>(cos_theta_i: S, eta: S, fma: Fma) -> Fresnel<S> {
    let outside = cos_theta_i >= S::ZERO;
    let rcp_eta = S::ONE / eta;
    let (eta_it, eta_ti) = if outside {
        (eta, rcp_eta)
    } else {
        (rcp_eta, eta)
    };
    let sin2 = fma.fnmadd(cos_theta_i, cos_theta_i, S::ONE);
    let cos_theta_t_sqr = fma.fnmadd(sin2, eta_ti * eta_ti, S::ONE);
    let cos_i = cos_theta_i.abs();
    let cos_t = safe_sqrt(cos_theta_t_sqr);
    let index_matched = eta == S::ONE;
    let a_s = fma.fnmadd(eta_it, cos_t, cos_i) / fma.fmadd(eta_it, cos_t, cos_i);
    let a_p = fma.fnmadd(eta_it, cos_i, cos_t) / fma.fmadd(eta_it, cos_i, cos_t);
    let f = if index_matched {
        S::ZERO
    } else if cos_i == S::ZERO {
        S::ONE
    } else {
        S::HALF * (a_s * a_s + a_p * a_p)
    };
    Fresnel {
        f,
        cos_theta_t: mulsign_neg(cos_t, cos_theta_i),
        eta_it,
        eta_ti,
    }
}

/// Mitsuba 3's local-frame `refract(wi, cos_theta_t, eta_ti)`:
/// `(-eta_ti * wi.x, -eta_ti * wi.y, cos_theta_t)`, the transmitted direction of travel (the
/// normal is +z).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::mitsuba::refract_local;
/// let wo = refract_local::<f64>(DVec3::new(-0.6, 0.0, 0.8), -0.84_f64.sqrt(), 1.0 / 1.5);
/// assert!((wo - DVec3::new(0.4, 0.0, -0.84_f64.sqrt())).length() < 1e-15);
/// ```
#[must_use]
pub fn refract_local<S: Real>(wi: S::Vec3, cos_theta_t: S, eta_ti: S) -> S::Vec3 {
    let [x, y, _] = wi.to_array();
    S::Vec3::new(-eta_ti * x, -eta_ti * y, cos_theta_t)
}

/// Mitsuba 3's `refract(wi, m, cos_theta_t, eta_ti)` about the normal `m`:
/// `m·(dot(wi, m)·eta_ti + cos_theta_t) − wi·eta_ti`, bit for bit for the given `fma`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::mitsuba::{Fma, fresnel, refract};
/// let (wi, m) = (Vec3::new(-0.6, 0.8, 0.0), Vec3::Y);
/// let f = fresnel::<f32>(wi.dot(m), 1.5, Fma::Unfused);
/// let wo = refract::<f32>(wi, m, f.cos_theta_t, f.eta_ti, Fma::Unfused);
/// // Without FMA it rounds as glam's (GLSL's) refract does.
/// assert_eq!(wo, (-wi).refract(m, 1.0 / 1.5));
/// ```
#[must_use]
pub fn refract<S: Real>(wi: S::Vec3, m: S::Vec3, cos_theta_t: S, eta_ti: S, fma: Fma) -> S::Vec3 {
    let (w, n) = (wi.to_array(), m.to_array());
    let scale = fma.fmadd(fma.dot(w, n), eta_ti, cos_theta_t);
    let out = [0, 1, 2].map(|c| fma.fmsub(n[c], scale, w[c] * eta_ti));
    S::Vec3::new(out[0], out[1], out[2])
}

/// Mitsuba 3's `reflect(wi, m)`: `fmsub(m, 2·dot(wi, m), wi)`.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::mitsuba::{Fma, reflect};
/// let r = reflect::<f64>(DVec3::new(-0.6, 0.8, 0.0), DVec3::Y, Fma::Fused);
/// assert_eq!(r, DVec3::new(0.6, 0.8, 0.0));
/// ```
#[must_use]
pub fn reflect<S: Real>(wi: S::Vec3, m: S::Vec3, fma: Fma) -> S::Vec3 {
    let (w, n) = (wi.to_array(), m.to_array());
    let twice = S::TWO * fma.dot(w, n);
    let out = [0, 1, 2].map(|c| fma.fmsub(n[c], twice, w[c]));
    S::Vec3::new(out[0], out[1], out[2])
}

/// What the dielectric BSDF computes for one direction: `fresnel`'s four values and the
/// refracted `wo` (which it uses only when it samples transmission, never when F = 1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Answer<S: Real> {
    /// `fresnel(cos_theta_i, eta)`.
    pub fresnel: Fresnel<S>,
    /// `refract(wi, cos_theta_t, eta_ti)`, or the overload about `m`.
    pub wo: S::Vec3,
}

/// `fresnel` then `refract` for `wi` about the normal `m`. With `m` = +z exactly this is the
/// local-frame pair the dielectric BSDF calls (`cos_theta_i = wi.z`, `refract(wi, cos_theta_t,
/// eta_ti)`); any other `m` uses `cos_theta_i = dot(wi, m)` and `refract(wi, m, …)`.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::mitsuba::{Fma, answer};
/// // Inside glass at 45° from the normal: past the critical angle, F = 1.
/// let wi = Vec3::new(-0.5_f32.sqrt(), 0.0, -0.5_f32.sqrt());
/// assert_eq!(answer::<f32>(wi, Vec3::Z, 1.5, Fma::Fused).fresnel.f, 1.0);
/// ```
#[must_use]
pub fn answer<S: Real>(wi: S::Vec3, m: S::Vec3, eta: S, fma: Fma) -> Answer<S> {
    let local = m.to_array() == [S::ZERO, S::ZERO, S::ONE];
    if local {
        let fresnel = fresnel(wi.to_array()[2], eta, fma);
        let wo = refract_local(wi, fresnel.cos_theta_t, fresnel.eta_ti);
        Answer { fresnel, wo }
    } else {
        let fresnel = fresnel(fma.dot(wi.to_array(), m.to_array()), eta, fma);
        let wo = refract(wi, m, fresnel.cos_theta_t, fresnel.eta_ti, fma);
        Answer { fresnel, wo }
    }
}

/// What a `fresnel`/`refract` pair for `wi`, normal `m` and `eta` means in this project's
/// terms: the ray travels along −wi; the facing normal is m when wi is on m's side
/// (`cos_theta_i` ≥ 0, the exterior) and −m otherwise; μ = `eta_ti`. Every such call is within
/// Mitsuba's contract (for unit vectors).
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::mitsuba::meaning;
/// let inside = meaning::<f32>(Vec3::new(-0.6, 0.0, -0.8), Vec3::Z, 1.5);
/// assert_eq!((inside.normal, inside.mu), (-Vec3::Z, 1.5));
/// ```
#[must_use]
pub fn meaning<S: Real>(wi: S::Vec3, m: S::Vec3, eta: S) -> Meaning<S> {
    let outside = Fma::Unfused.dot(wi.to_array(), m.to_array()) >= S::ZERO;
    Meaning {
        travel: -wi,
        normal: if outside { m } else { -m },
        mu: if outside { S::ONE / eta } else { eta },
        normal_on_incident_side: outside,
        within_contract: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn wi(degrees: f64, inside: bool) -> Vec3 {
        let angle = degrees.to_radians();
        let z = if inside { -angle.cos() } else { angle.cos() };
        Vec3::new(-angle.sin() as f32, 0.0, z as f32)
    }

    #[test]
    fn entering_at_40_degrees_f_depends_on_fma() {
        let fused = fresnel::<f32>(wi(40.0, false).z, 1.5, Fma::Fused);
        let unfused = fresnel::<f32>(wi(40.0, false).z, 1.5, Fma::Unfused);
        assert_eq!(f64::from(fused.f), 0.045_733_641_833_066_94);
        assert_eq!(f64::from(unfused.f), 0.045_733_645_558_357_24);
        assert_eq!(fused.cos_theta_t.to_bits(), 0xbf67_4dbc);
        assert_eq!((fused.eta_it, fused.eta_ti.to_bits()), (1.5, 0x3f2a_aaab));
        let wo = refract_local(wi(40.0, false), fused.cos_theta_t, fused.eta_ti);
        assert_eq!(
            wo.to_array().map(f32::to_bits),
            [0x3edb_67a4, 0x8000_0000, 0xbf67_4dbc]
        );
    }

    #[test]
    fn total_internal_reflection_gives_f_one_and_a_signed_zero_cosine() {
        let answer = answer::<f32>(wi(45.0, true), Vec3::Z, 1.5, Fma::Fused);
        assert_eq!(answer.fresnel.f, 1.0);
        assert_eq!(answer.fresnel.cos_theta_t.to_bits(), 0);
        assert_eq!(answer.fresnel.eta_ti, 1.5);
        assert_eq!(answer.wo.to_array()[1].to_bits(), 0x8000_0000);
        assert!(answer.wo.length() > 1.0);
    }

    #[test]
    fn leaving_glass_at_20_degrees() {
        let answer = answer::<f32>(wi(20.0, true), Vec3::Z, 1.5, Fma::Fused);
        assert_eq!(answer.fresnel.f, 0.041_728_51);
        assert_eq!(answer.wo, Vec3::new(0.513_030_23, -0.0, 0.858_370_54));
        let m = meaning::<f32>(wi(20.0, true), Vec3::Z, 1.5);
        assert_eq!((m.normal, m.mu), (-Vec3::Z, 1.5));
    }
}

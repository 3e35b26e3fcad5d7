//! pbrt-v4's `Refract(wi, n, eta, &etap, &wt)`.
//!
//! Source: pbrt-v4 (commit 5f7a606), `src/pbrt/util/scattering.h`, `Refract`: it flips `n` and
//! inverts `eta` when `Dot(n, wi) < 0`, computes `sin2Theta_i = max(0, 1 - Sqr(cosTheta_i))`,
//! `sin2Theta_t = sin2Theta_i / Sqr(eta)`, returns `false` when `sin2Theta_t >= 1`, and otherwise
//! writes `*wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * n` with
//! `cosTheta_t = sqrt(1 - sin2Theta_t)` and `*etap = eta`. `Dot(Normal3, Vector3)`
//! (`src/pbrt/util/vecmath.h`) is `FMA(n.x, v.x, SumOfProducts(n.y, v.y, n.z, v.z))`, and
//! `SumOfProducts` (`src/pbrt/util/math.h`) is the compensated `FMA(a, b, c·d) + FMA(c, d, −c·d)`;
//! `FMA` is `std::fma`. pbrt's `Float` is `float` unless built with `PBRT_FLOAT_AS_DOUBLE`.

use super::Meaning;
use crate::real::{Real, Vector3 as _};

/// What `Refract` writes when it returns `true`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refracted<S: Real> {
    /// `*wt`: the transmitted direction of travel (not normalised).
    pub wt: S::Vec3,
    /// `*etap`: the relative index along the ray, `n_to/n_from` (eta, or 1/eta after the flip).
    pub etap: S,
}

/// pbrt's `Dot(Normal3f n, Vector3f v)`: fused and compensated.
fn dot<S: Real>(n: [S; 3], v: [S; 3]) -> S {
    let cd = n[2] * v[2];
    let sum_of_products = n[1].mul_add(v[1], cd) + n[2].mul_add(v[2], -cd);
    n[0].mul_add(v[0], sum_of_products)
}

/// What pbrt-v4's `Refract(wi, n, eta, &etap, &wt)` returns, bit for bit: `None` for `false`
/// (total internal reflection, including sin²θt = 1 exactly; `*wt` and `*etap` are then not
/// written), otherwise what it writes to `*wt` and `*etap`.
///
/// `wi` points back toward where the ray came from (−ray.d), `n` may face either way and `eta`
/// is the index on the side `n` points away from over the index on the side it points to (the
/// material's `n_inside/n_outside` for an outward `n`). Nothing is normalised.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::pbrt;
/// // Leaving glass through its outward normal: pbrt flips n and inverts eta.
/// let wi = -Vec3::new(0.4, 0.84_f32.sqrt(), 0.0);
/// let r = pbrt::refract::<f32>(wi, Vec3::Y, 1.5).expect("below the critical angle");
/// assert_eq!(r.etap, 1.0 / 1.5);
/// assert!((r.wt - Vec3::new(0.6, 0.8, 0.0)).length() < 1e-6);
/// // Grazing with eta = 1: sin²θt = 1, which pbrt treats as total internal reflection.
/// assert_eq!(pbrt::refract::<f32>(-Vec3::X, Vec3::Y, 1.0), None);
/// ```
#[must_use]
pub fn refract<S: Real>(wi: S::Vec3, n: S::Vec3, eta: S) -> Option<Refracted<S>> {
    let (wi, mut n, mut eta) = (wi.to_array(), n.to_array(), eta);
    let mut cos_i = dot(n, wi);
    if cos_i < S::ZERO {
        eta = S::ONE / eta;
        cos_i = -cos_i;
        n = n.map(|c| -c);
    }
    let one_minus = S::ONE - cos_i * cos_i;
    // std::max<Float>(0, x) returns x only when 0 < x: zero for NaN.
    let sin2_i = if S::ZERO < one_minus {
        one_minus
    } else {
        S::ZERO
    };
    let sin2_t = sin2_i / (eta * eta);
    if sin2_t >= S::ONE {
        return None;
    }
    let cos_t = (S::ONE - sin2_t).sqrt();
    let scale = cos_i / eta - cos_t;
    let wt = [0, 1, 2].map(|c| -wi[c] / eta + scale * n[c]);
    Some(Refracted {
        wt: S::Vec3::new(wt[0], wt[1], wt[2]),
        etap: eta,
    })
}

/// What a call `Refract(wi, n, eta)` means in this project's terms: the ray travels along −wi;
/// the facing normal is n when wi is on n's side (Dot(n, wi) ≥ 0) and −n otherwise, and μ is
/// 1/eta or eta accordingly. Every such call is within pbrt's contract (for unit vectors).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::pbrt;
/// let wi = DVec3::new(-0.6, 0.8, 0.0);
/// let m = pbrt::meaning::<f64>(wi, -DVec3::Y, 1.5); // the normal below: pbrt flips it
/// assert_eq!((m.travel, m.normal, m.mu), (-wi, DVec3::Y, 1.5));
/// ```
#[must_use]
pub fn meaning<S: Real>(wi: S::Vec3, n: S::Vec3, eta: S) -> Meaning<S> {
    let above = dot(n.to_array(), wi.to_array()) >= S::ZERO;
    Meaning {
        travel: -wi,
        normal: if above { n } else { -n },
        mu: if above { S::ONE / eta } else { eta },
        normal_on_incident_side: above,
        within_contract: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    #[test]
    fn worked_examples_entering_and_leaving_glass() {
        // Air to glass at 40° in f32: wi = −d, the outward normal, the material's eta.
        let wi = Vec3::new(
            f32::from_bits(0xbf24_8dbb),
            f32::from_bits(0x3f44_1b7d),
            0.0,
        );
        let r = refract::<f32>(wi, Vec3::Y, 1.5).unwrap();
        assert_eq!(
            (r.wt.x.to_bits(), r.wt.y.to_bits()),
            (0x3edb_67a4, 0xbf67_4dbc)
        );
        assert_eq!(r.etap, 1.5);
        // Glass to air at 20°: wi below the outward normal, so pbrt flips it and inverts eta.
        let angle = 20_f64.to_radians();
        let wi = -DVec3::new(angle.sin(), angle.cos(), 0.0).as_vec3();
        let r = refract::<f32>(wi, Vec3::Y, 1.5).unwrap();
        assert_eq!(r.etap.to_bits(), 0x3f2a_aaab);
        assert_eq!(
            (r.wt.x.to_bits(), r.wt.y.to_bits()),
            (0x3f03_55f3, 0x3f5b_be2c)
        );
    }

    #[test]
    fn false_on_total_internal_reflection_and_at_sin2_one_exactly() {
        let wi = -DVec3::new(0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0);
        assert_eq!(refract::<f64>(wi, DVec3::Y, 1.5), None);
        // Grazing with eta = 1: sin²θt = 1 is total internal reflection for pbrt.
        assert_eq!(refract::<f64>(DVec3::X, DVec3::Y, 1.0), None);
    }

    #[test]
    fn meaning_follows_the_flip() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let m = meaning::<f64>(-d, -DVec3::Y, 1.5);
        assert_eq!((m.travel, m.normal, m.mu), (d, DVec3::Y, 1.5));
        let m = meaning::<f64>(-d, DVec3::Y, 1.5);
        assert_eq!((m.normal, m.mu), (DVec3::Y, 1.0 / 1.5));
    }
}

//! Ray Tracing in One Weekend's `refract(uv, n, etai_over_etat)` and the test its caller makes.
//!
//! Source: Ray Tracing in One Weekend (v4, `RayTracing/raytracing.github.io`),
//! `src/InOneWeekend/vec3.h`, `refract`: `cos_theta = fmin(dot(-uv, n), 1.0)`,
//! `r_out_perp = etai_over_etat * (uv + cos_theta*n)`,
//! `r_out_parallel = -sqrt(fabs(1.0 - r_out_perp.length_squared())) * n`, their sum; and
//! `src/InOneWeekend/material.h`, `dielectric::scatter`: `ri = rec.front_face ?
//! (1.0/refraction_index) : refraction_index`, `unit_direction = unit_vector(r_in.direction())`,
//! `sin_theta = sqrt(1.0 - cos_theta*cos_theta)`, and `cannot_refract = ri * sin_theta > 1.0`
//! chooses `reflect(unit_direction, rec.normal)` instead. `hittable.h`'s
//! `hit_record::set_face_normal` makes `rec.normal` face the ray. The book uses `double`
//! throughout, without fused operations.

use super::Meaning;
use crate::real::{Real, Vector3 as _};

/// The book's `dot(u, v)`: `u.e[0]*v.e[0] + u.e[1]*v.e[1] + u.e[2]*v.e[2]`, left to right.
fn dot<S: Real>(u: [S; 3], v: [S; 3]) -> S {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// What the book's `refract(uv, n, etai_over_etat)` returns, bit for bit. It has no total
/// internal reflection test (`fabs` hides a negative radicand): past the critical angle it
/// returns a vector longer than 1 that still crosses the surface, which `dielectric::scatter`
/// never uses because [`cannot_refract`] holds there.
///
/// `uv` is the unit direction of travel, `n` a unit normal facing it (the hit record's
/// `normal` after `set_face_normal`), `etai_over_etat` = `n_from/n_to`. Nothing is normalised.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// let t = rtiow::refract::<f64>(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0 / 1.5);
/// assert!((t.x - 0.4).abs() < 1e-15);
/// // Past the critical angle it still returns a vector, longer than 1.
/// assert!(rtiow::refract::<f64>(DVec3::new(0.8, 0.6, 0.0), -DVec3::Y, 1.5).length() > 1.0);
/// ```
#[must_use]
pub fn refract<S: Real>(uv: S::Vec3, n: S::Vec3, etai_over_etat: S) -> S::Vec3 {
    let (u, n) = (uv.to_array(), n.to_array());
    let cos_theta = dot(u.map(|c| -c), n).min(S::ONE);
    let perp = [0, 1, 2].map(|c| etai_over_etat * (u[c] + cos_theta * n[c]));
    let length_squared = perp[0] * perp[0] + perp[1] * perp[1] + perp[2] * perp[2];
    let parallel = -(S::ONE - length_squared).abs().sqrt();
    let out = [0, 1, 2].map(|c| perp[c] + parallel * n[c]);
    S::Vec3::new(out[0], out[1], out[2])
}

/// `dielectric::scatter`'s test `ri * sin_theta > 1.0`, with the same `cos_theta` as
/// [`refract`]: when it holds the book reflects instead of refracting (a strict `>`, so
/// `ri·sinθ = 1` exactly still refracts).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// assert!(rtiow::cannot_refract::<f64>(DVec3::new(0.8, 0.6, 0.0), -DVec3::Y, 1.5));
/// assert!(!rtiow::cannot_refract::<f64>(DVec3::new(0.6, 0.8, 0.0), -DVec3::Y, 1.5));
/// ```
#[must_use]
pub fn cannot_refract<S: Real>(unit_direction: S::Vec3, normal: S::Vec3, ri: S) -> bool {
    let (u, n) = (unit_direction.to_array(), normal.to_array());
    let cos_theta = dot(u.map(|c| -c), n).min(S::ONE);
    let sin_theta = (S::ONE - cos_theta * cos_theta).sqrt();
    ri * sin_theta > S::ONE
}

/// The book's `reflect(v, n)`: `v - 2*dot(v,n)*n`.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// let r = rtiow::reflect::<f64>(DVec3::new(0.6, -0.8, 0.0), DVec3::Y);
/// assert_eq!(r, DVec3::new(0.6, 0.8, 0.0));
/// ```
#[must_use]
pub fn reflect<S: Real>(v: S::Vec3, n: S::Vec3) -> S::Vec3 {
    let (v, n) = (v.to_array(), n.to_array());
    let twice = S::TWO * dot(v, n);
    let out = [0, 1, 2].map(|c| v[c] - twice * n[c]);
    S::Vec3::new(out[0], out[1], out[2])
}

/// The book's `unit_vector(v)`: `v / v.length()`, where `operator/` multiplies by `1/t`.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// // It multiplies by 1/5 rather than dividing by 5: x is not 3/5 = 0.6 but one ulp above.
/// let v = rtiow::unit_vector::<f64>(DVec3::new(3.0, -4.0, 0.0));
/// assert_eq!((v.x, v.y), (0.600_000_000_000_000_1, -0.8));
/// ```
#[must_use]
pub fn unit_vector<S: Real>(v: S::Vec3) -> S::Vec3 {
    let a = v.to_array();
    let inverse = S::ONE / dot(a, a).sqrt();
    S::Vec3::new(inverse * a[0], inverse * a[1], inverse * a[2])
}

/// What the book's refraction step gives for one call: `refract`'s vector and whether
/// `dielectric::scatter` would have reflected instead.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Answer<S: Real> {
    /// `refract(uv, n, etai_over_etat)`, computed whatever the test says.
    pub refracted: S::Vec3,
    /// [`cannot_refract`]: the book reflects and never uses `refracted`.
    pub cannot_refract: bool,
}

/// [`refract`] and [`cannot_refract`] for one set of arguments.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// let a = rtiow::answer::<f64>(DVec3::new(0.8, 0.6, 0.0), -DVec3::Y, 1.5);
/// assert!(a.cannot_refract); // the book reflects and never uses `a.refracted`
/// ```
#[must_use]
pub fn answer<S: Real>(uv: S::Vec3, n: S::Vec3, etai_over_etat: S) -> Answer<S> {
    Answer {
        refracted: refract(uv, n, etai_over_etat),
        cannot_refract: cannot_refract(uv, n, etai_over_etat),
    }
}

/// What a call `refract(uv, n, etai_over_etat)` means in this project's terms: uv is the
/// direction of travel, n is taken as the normal facing it and `etai_over_etat` as μ. Within the
/// book's contract only when n faces uv (dot(uv, n) ≤ 0), as `set_face_normal` ensures.
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::api::rtiow;
/// let uv = DVec3::new(0.6, 0.8, 0.0);
/// assert!(rtiow::meaning::<f64>(uv, -DVec3::Y, 1.5).within_contract);
/// assert!(!rtiow::meaning::<f64>(uv, DVec3::Y, 1.5).within_contract); // set_face_normal skipped
/// ```
#[must_use]
pub fn meaning<S: Real>(uv: S::Vec3, n: S::Vec3, etai_over_etat: S) -> Meaning<S> {
    let faces = n.dot(uv) <= S::ZERO;
    Meaning {
        travel: uv,
        normal: n,
        mu: etai_over_etat,
        normal_on_incident_side: faces,
        within_contract: faces,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn at_40_degrees() -> DVec3 {
        let angle = 40_f64.to_radians();
        DVec3::new(angle.sin(), -angle.cos(), 0.0)
    }

    #[test]
    fn worked_examples_from_the_book_s_formula() {
        let t = refract::<f64>(at_40_degrees(), DVec3::Y, 1.0 / 1.5);
        assert_eq!(t.x.to_bits(), 0x3fdb_6cf4_6da5_72d0);
        assert_eq!(t.y.to_bits(), 0xbfec_e9b7_83f0_5aa7);
        // The scatter path normalises first, which moves the last bit of x.
        let unit = unit_vector::<f64>(at_40_degrees());
        assert_eq!(unit.x, 0.642_787_609_686_539_4);
        assert!(!cannot_refract::<f64>(unit, DVec3::Y, 1.0 / 1.5));
        assert_eq!(
            refract::<f64>(unit, DVec3::Y, 1.0 / 1.5),
            DVec3::new(0.428_525_073_124_359_56, -0.903_529_889_767_772, 0.0)
        );
    }

    #[test]
    fn past_the_critical_angle_refract_returns_a_long_vector_and_scatter_reflects() {
        let angle = 45_f64.to_radians();
        let up = DVec3::new(angle.sin(), angle.cos(), 0.0);
        let down = -DVec3::Y;
        assert!(cannot_refract::<f64>(up, down, 1.5));
        let t = refract::<f64>(up, down, 1.5);
        assert_eq!(
            t,
            DVec3::new(1.060_660_171_779_821_2, 0.353_553_390_593_273_45, 0.0)
        );
        assert!(t.length() > 1.1 && t.y > 0.0);
        // v - 2·dot(v, n)·n with n = -y: y - 2y is -y exactly.
        assert_eq!(reflect::<f64>(up, down), DVec3::new(up.x, -up.y, 0.0));
    }
}

//! GLSL's `refract(I, N, eta)`, which HLSL, WGSL, glm and glam define the same way.
//!
//! Source: the GLSL 4.60 specification, `chapters/builtinfunctions.adoc`, built-in function
//! `refract`: `k = 1.0 - eta * eta * (1.0 - dot(N, I) * dot(N, I))`, the zero vector when
//! `k < 0.0`, otherwise `eta * I - (eta * dot(N, I) + sqrt(k)) * N`; "the input parameters for
//! the incident vector I and the surface normal N must already be normalized". glam 0.34,
//! `src/f32/vec3.rs` and `src/f64/dvec3.rs`, `refract`, has the same body with the test turned
//! round (`k >= 0.0` refracts, anything else returns zero, so a NaN k gives zero), its `dot` sums
//! `((x·x′) + (y·y′)) + (z·z′)` and nothing is fused; glm, `glm/detail/func_geometric.inl`,
//! `compute_refract`, is the same for vectors. HLSL's `refract` and WGSL's `refract` (which names
//! `GLSLstd450Refract`) document the same formula.
//!
//! On a GPU the shader compiler may fuse or reorder these operations unless the code says
//! `precise`, so only glam's and glm's (without `-ffp-contract`) bits are defined; this is
//! glam's.

use super::Meaning;
use crate::real::{Real, Vector3 as _};

/// What GLSL's `refract(I, N, eta)` returns, bit for bit as glam's `Vec3::refract` /
/// `DVec3::refract` computes it: `eta·I − (eta·dot(N, I) + √k)·N` with
/// k = 1 − eta²·(1 − dot(N, I)²), or the zero vector when k is negative or NaN (total internal
/// reflection, or NaN input).
///
/// Nothing is normalised or flipped: I is the unit direction of travel, N a unit normal facing
/// against it (dot(N, I) < 0), eta = `n_from/n_to`. Other inputs give whatever the formula gives.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::glsl;
/// let (i, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
/// assert_eq!(glsl::refract::<f32>(i, n, 1.0 / 1.5), i.refract(n, 1.0 / 1.5));
/// // Total internal reflection: the zero vector.
/// assert_eq!(glsl::refract::<f32>(Vec3::new(0.8, -0.6, 0.0), n, 1.5), Vec3::ZERO);
/// ```
#[must_use]
pub fn refract<S: Real>(i: S::Vec3, n: S::Vec3, eta: S) -> S::Vec3 {
    let [ix, iy, iz] = i.to_array();
    let [nx, ny, nz] = n.to_array();
    let n_dot_i = nx * ix + ny * iy + nz * iz;
    let k = S::ONE - eta * eta * (S::ONE - n_dot_i * n_dot_i);
    if k >= S::ZERO {
        let scale = eta * n_dot_i + k.sqrt();
        S::Vec3::new(
            eta * ix - scale * nx,
            eta * iy - scale * ny,
            eta * iz - scale * nz,
        )
    } else {
        S::Vec3::new(S::ZERO, S::ZERO, S::ZERO)
    }
}

/// What a call `refract(I, N, eta)` means in this project's terms: I is the direction of travel,
/// N is taken as the normal facing it and eta as μ. The call is within GLSL's contract only
/// when N faces I (dot(N, I) ≤ 0): GLSL does not flip N, and with N on the far side the formula
/// returns a vector back on the incident side.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::api::glsl;
/// let i = Vec3::new(0.6, -0.8, 0.0);
/// assert!(glsl::meaning::<f32>(i, Vec3::Y, 1.0 / 1.5).within_contract);
/// // An outward normal where the ray leaves: GLSL does not flip it.
/// assert!(!glsl::meaning::<f32>(-i, Vec3::Y, 1.5).within_contract);
/// ```
#[must_use]
pub fn meaning<S: Real>(i: S::Vec3, n: S::Vec3, eta: S) -> Meaning<S> {
    let faces = n.dot(i) <= S::ZERO;
    Meaning {
        travel: i,
        normal: n,
        mu: eta,
        normal_on_incident_side: faces,
        within_contract: faces,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    #[test]
    fn air_to_glass_at_40_degrees_in_both_precisions() {
        // Inputs and bits of the worked example: d = (sin 40°, −cos 40°, 0), N = +y, eta = 1/1.5.
        let d = DVec3::new(
            f64::from_bits(0x3fe4_91b7_523c_161c),
            f64::from_bits(0xbfe8_836f_a2cf_5039),
            0.0,
        );
        let t = refract::<f64>(d, DVec3::Y, 1.0 / 1.5);
        assert_eq!(t.x.to_bits(), 0x3fdb_6cf4_6da5_72d0);
        assert_eq!(t.y.to_bits(), 0xbfec_e9b7_83f0_5aa7);
        let d32 = Vec3::new(
            f32::from_bits(0x3f24_8dbb),
            f32::from_bits(0xbf44_1b7d),
            0.0,
        );
        let t32 = refract::<f32>(d32, Vec3::Y, 1.0 / 1.5);
        assert_eq!(
            (t32.x.to_bits(), t32.y.to_bits()),
            (0x3edb_67a4, 0xbf67_4dbc)
        );
    }

    #[test]
    fn total_internal_reflection_and_nan_give_zero_and_grazing_k_zero_refracts() {
        let up = DVec3::new(0.5_f64.sqrt(), 0.5_f64.sqrt(), 0.0);
        assert_eq!(refract::<f64>(up, -DVec3::Y, 1.5), DVec3::ZERO);
        assert_eq!(refract::<f64>(up, -DVec3::Y, f64::NAN), DVec3::ZERO);
        // Exactly grazing with eta = 1: k = 0 refracts along the surface.
        assert_eq!(refract::<f64>(DVec3::X, DVec3::Y, 1.0), DVec3::X);
    }

    #[test]
    fn an_unflipped_normal_sends_the_ray_back_and_is_outside_the_contract() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let t = refract::<f64>(d, -DVec3::Y, 1.0 / 1.5);
        assert!(t.y > 0.0, "{t}");
        assert!(!meaning::<f64>(d, -DVec3::Y, 1.0 / 1.5).within_contract);
        assert!(meaning::<f64>(d, DVec3::Y, 1.0 / 1.5).within_contract);
    }
}

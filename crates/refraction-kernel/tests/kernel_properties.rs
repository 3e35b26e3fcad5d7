//! Property tests of the default kernel's invariants, at both precisions.

use glam::{DQuat, DVec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use refraction_kernel::{Convention, Fresnel, Incidence, Real, Refraction, Vector3 as _, refract};

fn unit_vector() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(-1.0..1.0_f64)
        .prop_map(DVec3::from_array)
        .prop_filter("not too short", |v| v.length() > 0.1)
        .prop_map(DVec3::normalize)
}

/// Indices of real media, and a wide logarithmic range.
fn index() -> impl Strategy<Value = f64> {
    prop_oneof![1.0..2.5_f64, (-3.0..3.0_f64).prop_map(|e| 10f64.powf(e))]
}

fn convention() -> impl Strategy<Value = Convention> {
    prop_oneof![Just(Convention::AlongRay), Just(Convention::TowardOrigin)]
}

fn to_s<S: Real>(v: DVec3) -> S::Vec3 {
    S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z))
}

fn wide<S: Real>(v: S::Vec3) -> DVec3 {
    DVec3::from_array(v.to_array().map(Real::to_f64))
}

fn solve<S: Real>(w: DVec3, n: DVec3, mu_i: f64, mu_t: f64, c: Convention) -> Refraction<S> {
    refract(&Incidence {
        w: to_s::<S>(w),
        n: to_s::<S>(n),
        mu_i: S::from_f64(mu_i),
        mu_t: S::from_f64(mu_t),
        convention: c,
    })
    .expect("valid input")
}

fn laws_hold<S: Real>(
    w: DVec3,
    n: DVec3,
    mu_i: f64,
    mu_t: f64,
    c: Convention,
) -> Result<(), TestCaseError> {
    let r = solve::<S>(w, n, mu_i, mu_t, c);
    let numbers = [r.k, r.cos_i].into_iter().chain(r.reflected.to_array());
    prop_assert!(
        numbers.into_iter().all(Real::is_finite),
        "NaN or ∞ in {r:?}"
    );
    let Some(t) = r.t() else { return Ok(()) };
    prop_assert!(t.to_array().into_iter().all(Real::is_finite));
    let checks = r.checks(t);
    let tol = r.tolerance();
    prop_assert!(checks.is_unit(tol), "{checks:?} tol {tol:e}");
    prop_assert!(checks.obeys_snell(tol), "{checks:?} tol {tol:e}");
    prop_assert!(checks.is_coplanar(tol), "{checks:?} tol {tol:e}");
    prop_assert!(checks.is_on_correct_side(tol), "{checks:?} tol {tol:e}");
    Ok(())
}

/// The angle between two directions, accurate for tiny angles (glam's `angle_between` uses
/// acos, which cannot resolve angles below about 1e-8).
fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

fn reversible<S: Real>(w: DVec3, n: DVec3, mu_i: f64, mu_t: f64) -> Result<(), TestCaseError> {
    let forward = solve::<S>(w, n, mu_i, mu_t, Convention::AlongRay);
    let Some(t) = forward.t() else { return Ok(()) };
    let back = solve::<S>(-wide::<S>(t), n, mu_t, mu_i, Convention::AlongRay);
    let back_t = back.t().map(wide::<S>);
    let eps = S::EPSILON.to_f64();
    let tol = 64.0 * eps * forward.condition_number() * back.condition_number();
    match back_t {
        Some(b) => prop_assert!(
            angle(b, -wide::<S>(forward.travel)) <= tol,
            "back {b} vs {} tol {tol:e}",
            -wide::<S>(forward.travel)
        ),
        // Only a grazing T can be turned back into total internal reflection by rounding.
        None => prop_assert!(back.k.to_f64().abs() <= 64.0 * eps * (1.0 + back.mu.to_f64())),
    }
    Ok(())
}

fn equal_indices_return_w<S: Real>(w: DVec3, n: DVec3, mu: f64) -> Result<(), TestCaseError> {
    let r = solve::<S>(w, n, mu, mu, Convention::AlongRay);
    prop_assert_eq!(r.t(), Some(r.travel));
    if r.w == to_s::<S>(w) {
        prop_assert_eq!(r.t(), Some(to_s::<S>(w)));
    }
    Ok(())
}

fn tir_iff_past_critical<S: Real>(
    w: DVec3,
    n: DVec3,
    mu_i: f64,
    mu_t: f64,
) -> Result<(), TestCaseError> {
    let r = solve::<S>(w, n, mu_i, mu_t, Convention::AlongRay);
    let mu_sin = mu_i / mu_t * wide::<S>(r.w).cross(wide::<S>(r.n)).length();
    let margin = 1e3 * S::EPSILON.to_f64();
    if mu_sin > 1.0 + margin {
        prop_assert!(r.is_tir(), "μ·sinθi = {mu_sin} but T = {:?}", r.t());
    } else if mu_sin < 1.0 - margin {
        prop_assert!(!r.is_tir(), "μ·sinθi = {mu_sin} but TIR");
    }
    Ok(())
}

fn rotation_equivariant<S: Real>(
    w: DVec3,
    n: DVec3,
    mu_i: f64,
    mu_t: f64,
    q: DQuat,
) -> Result<(), TestCaseError> {
    let plain = solve::<S>(w, n, mu_i, mu_t, Convention::AlongRay);
    let turned = solve::<S>(q * w, q * n, mu_i, mu_t, Convention::AlongRay);
    if let (Some(a), Some(b)) = (plain.t(), turned.t()) {
        let tol = 64.0 * S::EPSILON.to_f64() * plain.condition_number();
        let angle = angle(q * wide::<S>(a), wide::<S>(b));
        prop_assert!(angle <= tol, "angle {angle:e} tol {tol:e}");
    }
    Ok(())
}

/// Energy is conserved, every share is in [0, 1], s light is reflected at least as much as p
/// (|`r_p`| = |`r_s|·|cos(θi` + θt)/cos(θi − θt)|), and the light going back the way it came is
/// transmitted in the same share (reciprocity: T₁₂(θi) = T₂₁(θt)), checked away from grazing.
fn fresnel_laws<S: Real>(w: DVec3, n: DVec3, mu_i: f64, mu_t: f64) -> Result<(), TestCaseError> {
    let forward = solve::<S>(w, n, mu_i, mu_t, Convention::AlongRay);
    let f = Fresnel::of(&forward);
    let eps = S::EPSILON.to_f64();
    for (r, t) in [(f.rs, f.ts), (f.rp, f.tp)] {
        let (r, t) = (r.to_f64(), t.to_f64());
        prop_assert!(
            (0.0..=1.0).contains(&r) && (0.0..=1.0).contains(&t),
            "{f:?}"
        );
        prop_assert!((r + t - 1.0).abs() <= eps, "{f:?}");
    }
    prop_assert!(f.rp.to_f64() <= f.rs.to_f64() + 8.0 * eps, "{f:?}");
    // Reciprocity away from grazing on either side: the reversed ray's cosines carry the
    // forward T's error, which the shares amplify by their slope, unbounded as either cosine
    // goes to 0 (the critical angle seen from the other side).
    let Some(tr) = forward.transmission else {
        return Ok(());
    };
    if forward.cos_i.to_f64() < 0.1 || tr.cos_t.to_f64() < 0.1 {
        return Ok(());
    }
    let back = solve::<S>(-wide::<S>(tr.t), n, mu_t, mu_i, Convention::AlongRay);
    let b = Fresnel::of(&back);
    let tol = 256.0 * eps * forward.condition_number() * back.condition_number();
    for (x, y) in [(f.ts, b.ts), (f.tp, b.tp)] {
        prop_assert!((x.to_f64() - y.to_f64()).abs() <= tol, "{f:?} back {b:?}");
    }
    Ok(())
}

fn rotation() -> impl Strategy<Value = DQuat> {
    prop::array::uniform4(-1.0..1.0_f64)
        .prop_filter("not degenerate", |v| {
            v.iter().map(|x| x * x).sum::<f64>() > 0.01
        })
        .prop_map(|v| DQuat::from_array(v).normalize())
}

macro_rules! properties_at {
    ($module:ident, $s:ty) => {
        mod $module {
            use super::*;
            proptest! {
                #![proptest_config(ProptestConfig::with_cases(2000))]
                #[test]
                fn laws_of_refraction(w in unit_vector(), n in unit_vector(), mu_i in index(), mu_t in index(), c in convention()) {
                    laws_hold::<$s>(w, n, mu_i, mu_t, c)?;
                }
                #[test]
                fn refracting_back_returns_the_incoming_ray(w in unit_vector(), n in unit_vector(), mu_i in 1.0..2.5_f64, mu_t in 1.0..2.5_f64) {
                    reversible::<$s>(w, n, mu_i, mu_t)?;
                }
                #[test]
                fn mu_one_returns_w(w in unit_vector(), n in unit_vector(), mu in index()) {
                    equal_indices_return_w::<$s>(w, n, mu)?;
                }
                #[test]
                fn tir_exactly_past_the_critical_angle(w in unit_vector(), n in unit_vector(), mu_i in index(), mu_t in index()) {
                    tir_iff_past_critical::<$s>(w, n, mu_i, mu_t)?;
                }
                #[test]
                fn fresnel_conserves_energy_and_is_reciprocal(w in unit_vector(), n in unit_vector(), mu_i in index(), mu_t in index()) {
                    fresnel_laws::<$s>(w, n, mu_i, mu_t)?;
                }
                #[test]
                fn rotating_the_inputs_rotates_t(w in unit_vector(), n in unit_vector(), mu_i in 1.0..2.5_f64, mu_t in 1.0..2.5_f64, q in rotation()) {
                    rotation_equivariant::<$s>(w, n, mu_i, mu_t, q)?;
                }
            }
        }
    };
}

properties_at!(single_precision, f32);
properties_at!(double_precision, f64);

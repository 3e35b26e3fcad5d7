//! The ray tracer's calls on everything they accept: `transmit` and `transmit_pbrt` with d and n
//! unit within `UNIT_LENGTH_TOLERANCE` (normals on either side, any angle, near normal and near
//! grazing incidence) and μ anywhere from ε² to 1/ε² give a unit T or `None`, never NaN; and
//! `transmit_pbrt` is `transmit` in pbrt's convention.

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use refraction_kernel::{Real, UNIT_LENGTH_TOLERANCE, Vector3 as _, transmit, transmit_pbrt};

fn unit_vector() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(-1.0..1.0_f64)
        .prop_map(DVec3::from_array)
        .prop_filter("not too short", |v| v.length() > 0.1)
        .prop_map(DVec3::normalize)
}

/// A relative length error a little inside the tolerance (rounding to f32 must not carry it
/// past), either way.
fn length_error() -> impl Strategy<Value = f64> {
    prop_oneof![Just(0.0), -0.9..0.9_f64].prop_map(|x| x * UNIT_LENGTH_TOLERANCE)
}

/// A direction within about 10^`spread_exp` radians of −n (10^1: any direction).
fn around_normal(n: DVec3, off: DVec3, spread_exp: f64) -> DVec3 {
    (-n + off * 10f64.powf(spread_exp)).normalize()
}

fn to_s<S: Real>(v: DVec3) -> S::Vec3 {
    S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z))
}

/// μ = ε^(2·`fraction`) for `fraction` in [−1, 1]: across the whole accepted range.
fn ratio<S: Real>(fraction: f64) -> S {
    let eps = S::EPSILON.to_f64();
    S::from_f64(eps.powf(2.0 * fraction))
}

/// T is `None` or finite and unit within 6 tolerances and a few roundings.
fn sane<S: Real>(t: Option<S::Vec3>) -> Result<(), TestCaseError> {
    let Some(t) = t else { return Ok(()) };
    prop_assert!(t.to_array().into_iter().all(Real::is_finite), "{t:?}");
    let off = (t.length().to_f64() - 1.0).abs();
    let bound = 6.0 * UNIT_LENGTH_TOLERANCE + 8.0 * S::EPSILON.to_f64();
    prop_assert!(off <= bound, "|T| - 1 = {off:e} for {t:?}");
    Ok(())
}

fn accepted_input_gives_a_unit_t_or_none<S: Real>(
    d: DVec3,
    n: DVec3,
    (d_error, n_error): (f64, f64),
    fraction: f64,
) -> Result<(), TestCaseError> {
    let (d, n) = (
        to_s::<S>(d * (1.0 + d_error)),
        to_s::<S>(n * (1.0 + n_error)),
    );
    let mu = ratio::<S>(fraction);
    sane::<S>(transmit(d, n, mu))?;
    sane::<S>(transmit_pbrt(-d, n, mu).map(|r| r.t))
}

/// pbrt's `eta` belongs to the surface and flips with the side: `transmit_pbrt(wi, n, eta)` is
/// `transmit(−wi, n, μ)` with μ = 1/eta on the side n points to and eta on the other, bit for
/// bit, except that a T in the surface (k = 0) is `None`; etap = 1/μ.
fn pbrt_is_transmit_in_pbrt_terms<S: Real>(
    d: DVec3,
    n: DVec3,
    fraction: f64,
) -> Result<(), TestCaseError> {
    let (d, n, eta) = (to_s::<S>(d), to_s::<S>(n), ratio::<S>(fraction));
    let leaving = d.dot(n) > S::ZERO;
    let mu = if leaving { eta } else { S::ONE / eta };
    let ours = transmit(d, n, mu);
    match transmit_pbrt(-d, n, eta) {
        Some(pbrt) => {
            prop_assert_eq!(Some(pbrt.t), ours);
            prop_assert_eq!(pbrt.etap, if leaving { S::ONE / eta } else { eta });
        }
        // Only total internal reflection, or a T in the surface (perpendicular to n).
        None => prop_assert!(ours.is_none_or(|t| t.dot(n) == S::ZERO), "{ours:?}"),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn every_accepted_input_gives_a_unit_t_or_none(
        n in unit_vector(), off in unit_vector(), spread_exp in -12.0..1.0_f64,
        far in any::<bool>(), errors in (length_error(), length_error()),
        fraction in -1.0..1.0_f64,
    ) {
        let d = around_normal(n, off, spread_exp);
        let n = if far { -n } else { n };
        accepted_input_gives_a_unit_t_or_none::<f32>(d, n, errors, fraction)?;
        accepted_input_gives_a_unit_t_or_none::<f64>(d, n, errors, fraction)?;
    }

    #[test]
    fn transmit_pbrt_is_transmit_with_pbrt_s_eta(
        d in unit_vector(), n in unit_vector(), fraction in -0.3..0.3_f64,
    ) {
        pbrt_is_transmit_in_pbrt_terms::<f32>(d, n, fraction)?;
        pbrt_is_transmit_in_pbrt_terms::<f64>(d, n, fraction)?;
    }
}

#[test]
fn at_the_critical_angle_exactly_transmit_grazes_and_transmit_pbrt_refuses() {
    // μ = 1 and d in the surface: k = cos²θi = 0 exactly.
    let d = DVec3::X;
    assert_eq!(transmit(d, DVec3::Y, 1.0), Some(d));
    assert_eq!(transmit_pbrt(-d, DVec3::Y, 1.0), None);
    // μ = 2 at 30°: k = 1 − 4·¼ = 0 exactly.
    let d = DVec3::new(0.5, -(0.75_f64).sqrt(), 0.0);
    let t = transmit(d, DVec3::Y, 2.0).expect("k = 0 transmits");
    assert_eq!(t.y, 0.0);
    assert_eq!(transmit_pbrt(-d, -DVec3::Y, 2.0), None);
}

#[test]
fn a_normal_on_the_far_side_flips_pbrt_s_eta_and_not_transmit_s_mu() {
    // Glass (1.5) to air: transmit takes μ = 1.5 whichever way n points ...
    let up = DVec3::new(0.4, 0.84_f64.sqrt(), 0.0);
    let outward = transmit(up, DVec3::Y, 1.5).unwrap();
    assert_eq!(transmit(up, -DVec3::Y, 1.5), Some(outward));
    // ... pbrt takes the surface's eta = 1.5 and reads the side from n.
    let leaving = transmit_pbrt(-up, DVec3::Y, 1.5).unwrap();
    assert_eq!((leaving.t, leaving.etap), (outward, 1.0 / 1.5));
    let inward = transmit_pbrt(-up, -DVec3::Y, 1.0 / 1.5).unwrap();
    assert_eq!((inward.t, inward.etap), (outward, 1.0 / 1.5));
}

//! The whole accepted range of index ratios (up to 1/ε² either way) gives a unit T or total
//! internal reflection, never a zero, long or NaN vector; cosθi stays within [0, 1].

use glam::{DVec3, Vec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use refraction_kernel::{
    Convention, Incidence, Real, Refraction, Vector3 as _, refract, refract_facing, transmit,
};

fn solve<S: Real>(w: S::Vec3, n: S::Vec3, mu_i: S, mu_t: S) -> Refraction<S> {
    refract(&Incidence {
        w,
        n,
        mu_i,
        mu_t,
        convention: Convention::AlongRay,
    })
    .expect("an accepted input")
}

/// |T| − 1 within a few roundings.
fn assert_unit<S: Real>(r: &Refraction<S>) {
    let t = r.t().expect("transmitted");
    let length = t.length().to_f64();
    let epsilon = S::EPSILON.to_f64();
    assert!(
        (length - 1.0).abs() <= 8.0 * epsilon,
        "|T| = {length} for {r:?}"
    );
}

#[test]
fn a_huge_ratio_at_normal_incidence_goes_straight_through_at_unit_length() {
    let down = DVec3::NEG_Y;
    for mu in [1e16, 1e30, 2e31] {
        let r = solve::<f64>(down, DVec3::Y, mu, 1.0);
        assert!(!r.is_tir(), "μ = {mu:e}");
        assert_unit(&r);
        assert_eq!(r.t(), Some(down), "μ = {mu:e}");
    }
    for mu in [2e7_f32, 1e10, 7e13] {
        let r = solve::<f32>(Vec3::NEG_Y, Vec3::Y, mu, 1.0);
        assert_unit(&r);
        assert_eq!(r.t(), Some(Vec3::NEG_Y), "μ = {mu:e}");
    }
}

#[test]
fn the_cosine_of_incidence_stays_within_zero_and_one() {
    let w = DVec3::new(-0.53, 0.99, -0.06);
    let r = solve::<f64>(w, -w, 1.0, 1.5);
    assert!((0.0..=1.0).contains(&r.cos_i), "cos_i = {:e}", r.cos_i);
    let wf = Vec3::new(-0.53, 0.99, -0.06);
    let rf = solve::<f32>(wf, -wf, 1.0, 1.5);
    assert!((0.0..=1.0).contains(&rf.cos_i), "cos_i = {:e}", rf.cos_i);
}

/// A direction within about `spread` radians of −n.
fn near_normal(n: DVec3, off: DVec3, spread: f64) -> DVec3 {
    (-n + off * spread).normalize()
}

fn unit_vector() -> impl Strategy<Value = DVec3> {
    prop::array::uniform3(-1.0..1.0_f64)
        .prop_map(DVec3::from_array)
        .prop_filter("not too short", |v| v.length() > 0.1)
        .prop_map(DVec3::normalize)
}

fn unit_or_tir<S: Real>(w: DVec3, n: DVec3, mu: f64, inverse: bool) {
    let to_s = |v: DVec3| S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z));
    let (mu_i, mu_t) = if inverse { (1.0, mu) } else { (mu, 1.0) };
    let r = solve::<S>(to_s(w), to_s(n), S::from_f64(mu_i), S::from_f64(mu_t));
    assert!((0.0..=1.0).contains(&r.cos_i.to_f64()), "cos θi in [0, 1]");
    if r.t().is_some() {
        assert_unit(&r);
    }
}

/// The bits of T's components (widened exactly), so that −0 and +0 differ.
fn bits<S: Real>(t: S::Vec3) -> [u64; 3] {
    t.to_array().map(|c| c.to_f64().to_bits())
}

/// `transmit`, which never turns the normal round, returns the full answer's T for the turned
/// normal bit for bit: the batch kernel equals `transmit`, so all three agree.
fn transmit_is_the_full_answer<S: Real>(
    d: DVec3,
    n: DVec3,
    mu: f64,
    inverse: bool,
) -> Result<(), TestCaseError> {
    let to_s = |v: DVec3| S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z));
    let (d, n) = (to_s(d), to_s(n));
    let mu = S::from_f64(if inverse { 1.0 / mu } else { mu });
    let facing = if d.dot(n) > S::ZERO { -n } else { n };
    let full = refract_facing(d, facing, mu).transmitted.map(|t| t.t);
    prop_assert_eq!(transmit(d, n, mu).map(bits::<S>), full.map(bits::<S>));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn transmit_equals_the_full_answer_bit_for_bit(
        n in unit_vector(), off in unit_vector(), spread_exp in -20.0..1.0_f64,
        mu_exp in -1.0..31.0_f64, inverse in any::<bool>(), far in any::<bool>(),
    ) {
        // spread 10: any angle, the normal on the ray's side or not (`far`).
        let d = near_normal(n, off, 10f64.powf(spread_exp));
        let n = if far { -n } else { n };
        let mu = 10f64.powf(mu_exp);
        transmit_is_the_full_answer::<f64>(d, n, mu, inverse)?;
        transmit_is_the_full_answer::<f32>(d, n, mu.min(1e13), inverse)?;
        transmit_is_the_full_answer::<f32>(d, n, 1.0, inverse)?;
    }

    #[test]
    fn every_accepted_ratio_gives_a_unit_t_in_f64(
        n in unit_vector(), off in unit_vector(), spread_exp in -20.0..0.0_f64,
        mu_exp in 0.0..31.0_f64, inverse in any::<bool>(),
    ) {
        unit_or_tir::<f64>(near_normal(n, off, 10f64.powf(spread_exp)), n, 10f64.powf(mu_exp), inverse);
    }

    #[test]
    fn every_accepted_ratio_gives_a_unit_t_in_f32(
        n in unit_vector(), off in unit_vector(), spread_exp in -10.0..0.0_f64,
        mu_exp in 0.0..13.5_f64, inverse in any::<bool>(),
    ) {
        unit_or_tir::<f32>(near_normal(n, off, 10f64.powf(spread_exp)), n, 10f64.powf(mu_exp), inverse);
    }
}

//! The default kernel against the double-double oracle on the hard cases, at both precisions,
//! in an axis-aligned frame and in many random rotations of it.
#![expect(
    clippy::unwrap_used,
    reason = "test helpers: a failed unwrap is a failed test, with its message"
)]

use glam::{DQuat, DVec3};
use refraction_bench::oracle;
use refraction_bench::sets::{self, Problem};
use refraction_kernel::{Convention, Incidence, Real, Vector3 as _, refract};

/// The bench's hard cases, plus two the bench leaves out because only the full kernel API
/// accepts them: normals on the far side and inputs far from unit length.
fn hard_cases() -> Vec<Problem> {
    let mut cases = sets::hard_cases();
    for sin_i in [0.2, 0.6, 0.95] {
        let d = DVec3::new(sin_i, -(1.0 - sin_i * sin_i).sqrt(), 0.0);
        cases.push(Problem {
            what: "normal on the far side",
            d,
            n: -DVec3::Y,
            mu_i: 1.0,
            mu_t: 1.5,
        });
        for scale in [1e-30, 1e30] {
            cases.push(Problem {
                what: "inputs of length 1e-30 and 1e30",
                d: d * scale,
                n: DVec3::Y * scale,
                mu_i: 1.5,
                mu_t: 1.0,
            });
        }
    }
    cases
}

/// Checks the kernel at precision `S` on `case` rotated by `rotation`, in `convention`, against
/// the oracle evaluated on exactly the values the kernel received.
fn check<S: Real>(case: &Problem, rotation: DQuat, convention: Convention) {
    let sign = convention.travel_sign::<f64>();
    let to_s = |v: DVec3| {
        let r = rotation * v;
        S::Vec3::new(S::from_f64(r.x), S::from_f64(r.y), S::from_f64(r.z))
    };
    let incidence = Incidence::<S> {
        w: to_s(case.d * sign),
        n: to_s(case.n),
        mu_i: S::from_f64(case.mu_i),
        mu_t: S::from_f64(case.mu_t),
        convention,
    };
    let wide = |v: S::Vec3| v.to_array().map(Real::to_f64);
    let context = format!(
        "{} at {}: {case:?} rotated by {rotation:?}, {convention:?}",
        case.what,
        S::NAME
    );
    let r = refract(&incidence).unwrap_or_else(|e| panic!("{context}: {e}"));
    let (w, n) = (wide(incidence.w), wide(incidence.n));
    let (mu_i, mu_t) = (incidence.mu_i.to_f64(), incidence.mu_t.to_f64());
    let eps = S::EPSILON.to_f64();
    let mut exact = oracle::refract(w, n, mu_i, mu_t, convention);
    // A ray within rounding of grazing may be seen from either side: judge the kernel's
    // answer for the side it chose.
    if exact.cos_i.hi().abs() <= 4.0 * eps {
        let facing = if r.normal_flipped { n.map(|c| -c) } else { n };
        exact = oracle::refract_facing(w, facing, mu_i, mu_t, convention);
    }
    for x in [r.k, r.cos_i]
        .into_iter()
        .chain(wide(r.reflected).map(S::from_f64))
    {
        assert!(x.is_finite(), "{context}: non-finite output {r:?}");
    }
    if incidence.mu_i == incidence.mu_t {
        let t = r
            .t()
            .unwrap_or_else(|| panic!("{context}: equal indices must transmit"));
        assert_eq!(t, r.travel, "{context}: T must be W bit for bit");
        if convention == Convention::AlongRay && r.w == incidence.w {
            assert_eq!(
                t, incidence.w,
                "{context}: T must be the given W bit for bit"
            );
        }
        let err = oracle::angular_error(wide(t), &exact.t.unwrap());
        assert!(err <= 8.0 * eps, "{context}: error {err:e} > 8 eps");
        return;
    }
    // Whether transmission happens is itself ill-conditioned within a few ε of k = 0.
    let decision_margin = 32.0 * eps * (1.0 + exact.mu.hi());
    match (r.t(), exact.t) {
        (Some(t), Some(exact_t)) => {
            let kappa = exact.condition_number(eps);
            let err = oracle::angular_error(wide(t), &exact_t);
            assert!(
                err <= 32.0 * eps * kappa,
                "{context}: error {err:e} = {:.1} eps*kappa (kappa {kappa:e})",
                err / (eps * kappa)
            );
            assert!(wide(t).iter().all(|c| c.is_finite()), "T is finite");
        }
        (None, None) => {}
        (mine, _) => assert!(
            exact.k.hi().abs() <= decision_margin,
            "{context}: TIR decision differs (kernel transmits: {}) with exact k = {:e}",
            mine.is_some(),
            exact.k.hi()
        ),
    }
}

fn check_all<S: Real>() {
    let cases = hard_cases();
    for rotation in sets::rotations(41, 0x5eed) {
        for case in &cases {
            for convention in [Convention::AlongRay, Convention::TowardOrigin] {
                check::<S>(case, rotation, convention);
            }
        }
    }
}

#[test]
fn hard_cases_in_f64() {
    check_all::<f64>();
}

#[test]
fn hard_cases_in_f32() {
    check_all::<f32>();
}

#[test]
fn the_seed_formula_loses_accuracy_where_the_default_kernel_does_not() {
    use refraction_kernel::seed;
    // Large μ near normal incidence: the seed's μ²wn² − μ² + 1 amplifies the rounding of wn².
    let d = DVec3::new(1e-7, -1.0, 0.0).normalize();
    let (mu_i, mu_t) = (1e6, 1.0);
    let exact = oracle::refract(
        d.to_array(),
        [0.0, 1.0, 0.0],
        mu_i,
        mu_t,
        Convention::AlongRay,
    );
    let exact_t = exact.t.unwrap();
    let seed_t = seed::refract(d, DVec3::Y, mu_i / mu_t, Convention::AlongRay).unwrap();
    let r = refract(&Incidence {
        w: d,
        n: DVec3::Y,
        mu_i,
        mu_t,
        convention: Convention::AlongRay,
    })
    .unwrap();
    let eps_kappa = f64::EPSILON * exact.condition_number(f64::EPSILON);
    let seed_err = oracle::angular_error(seed_t.to_array(), &exact_t) / eps_kappa;
    let stable_err = oracle::angular_error(r.t().unwrap().to_array(), &exact_t) / eps_kappa;
    assert!(stable_err <= 32.0, "stable: {stable_err} eps*kappa");
    assert!(seed_err > 1000.0, "seed: only {seed_err} eps*kappa");
}

//! The kernel's Fresnel fractions against the double-double oracle, at both precisions, on the
//! bench's hard cases (normal and grazing incidence, near the critical angle, μ near 1 and far
//! from it) and near Brewster's angle, in an axis-aligned frame and in random rotations of it.
//!
//! Two errors are measured, in units of the precision's ε, as absolute differences of power
//! fractions:
//! - **own**: the kernel's R and T against the exact ones for the kernel's own μ, cosθi and
//!   cosθt: the error of the Fresnel forms themselves, within a few ε everywhere;
//! - **end to end**: against the exact fractions for the input W, N and indices. The rounding
//!   of μ and of the cosines adds the fractions' sensitivity to their input, which the test
//!   measures with the oracle as `κ_F` (below): end to end is within a few ε plus a few `κ_F·ε`.
//!   `κ_F` is near 1 almost everywhere and unbounded at the critical angle, where R has an
//!   infinite slope, and near grazing incidence between near-equal indices, which is close to
//!   it: there the problem, not the formula, decides the digits.

use std::collections::BTreeMap;

use glam::{DQuat, DVec3};
use refraction_bench::oracle::{self, ExactFresnel};
use refraction_bench::sets::{self, Problem};
use refraction_kernel::{Convention, Fresnel, Incidence, Real, Refraction, Vector3 as _, refract};
use twofloat::TwoFloat;

/// The bound on the own error, in ε. The kernel's `fresnel` module docs count roundings; on
/// top of them its forms trust μ where the textbook trusts cosθt, and the kernel's cosines
/// agree with Snell's law only to a few ε (cosθt comes from the tangential part of W near
/// normal incidence, not from cosθi), which the two read differently by up to about 2ε.
const OWN_BOUND: f64 = 6.0;
/// The end-to-end bound, in ε, is this plus [`SENSITIVITY_FACTOR`]·`κ_F`.
const END_TO_END_BOUND: f64 = 4.0;
/// How many ε of input error the kernel's μ and cosines carry, at most (the kernel's own
/// accuracy test bounds them). The worst seen is 4.4ε, in f32 just inside the critical angle at
/// μ = 1e6, where the tangential part of W (n×(d×n), shared with the batch lane) carries the
/// rounding of the two cross products.
const SENSITIVITY_FACTOR: f64 = 5.0;

/// Index pairs whose Brewster's angle is probed, from either side.
const PAIRS: [(f64, f64); 5] = [
    (1.0, 1.5),
    (1.5, 1.0),
    (1.0, 2.417),
    (1.333, 1.0),
    (1.0, 1.000_293),
];

/// Rays at Brewster's angle (tanθB = `μ_t/μ_i`) and 1e-3 to 1e-12 (relative) either side of it.
fn brewster_cases() -> Vec<Problem> {
    let mut cases = Vec::new();
    for (mu_i, mu_t) in PAIRS {
        let brewster = (mu_t / mu_i).atan();
        let mut push = |what, angle: f64| {
            cases.push(Problem {
                what,
                d: DVec3::new(angle.sin(), -angle.cos(), 0.0),
                n: DVec3::Y,
                mu_i,
                mu_t,
            });
        };
        push("Brewster", brewster);
        for exponent in [3, 6, 9, 12] {
            let delta = 10f64.powi(-exponent);
            push("near Brewster", brewster * (1.0 - delta));
            push("near Brewster", brewster * (1.0 + delta));
        }
    }
    cases
}

/// The largest errors seen in each family of cases, in ε: own, end to end, and end to end
/// divided by 1 + `κ_F`.
type Worst = BTreeMap<&'static str, [f64; 3]>;

fn wide<S: Real>(v: S::Vec3) -> [f64; 3] {
    v.to_array().map(Real::to_f64)
}

/// The largest absolute difference between two sets of exact fractions, in `eps`.
fn difference_in_eps(a: &ExactFresnel, b: &ExactFresnel, eps: f64) -> f64 {
    a.to_array()
        .into_iter()
        .zip(b.to_array())
        .map(|(x, y)| (x - y).abs().hi() / eps)
        .fold(0.0, f64::max)
}

/// `κ_F`: how far the exact fractions move, in `eps`, when μ moves by `eps` (relative) or cosθi
/// by `eps` (absolute) either way: the problem's own sensitivity to the kernel's roundings.
fn sensitivity(mu: TwoFloat, cos_i: TwoFloat, eps: f64) -> f64 {
    let at = oracle::fresnel_at(mu, cos_i);
    let clamp = |c: TwoFloat| {
        if c > 1.0 {
            TwoFloat::from(1.0)
        } else if c < 0.0 {
            TwoFloat::from(0.0)
        } else {
            c
        }
    };
    [
        (mu * (1.0 + eps), cos_i),
        (mu * (1.0 - eps), cos_i),
        (mu, clamp(cos_i + eps)),
        (mu, clamp(cos_i - eps)),
    ]
    .into_iter()
    .map(|(m, c)| difference_in_eps(&oracle::fresnel_at(m, c), &at, eps))
    .fold(0.0, f64::max)
}

/// The largest absolute difference between the kernel's fractions and exact ones, in `eps`.
fn error_in_eps<S: Real>(f: &Fresnel<S>, exact: &ExactFresnel, eps: f64) -> f64 {
    [f.rs, f.rp, f.ts, f.tp]
        .into_iter()
        .zip(exact.to_array())
        .map(|(x, e)| (TwoFloat::from(x.to_f64()) - e).abs().hi() / eps)
        .fold(0.0, f64::max)
}

/// The kernel's refraction of `case` rotated by `rotation` at precision `S`, and the incidence
/// it was given (in f64, exactly as the kernel received it).
fn kernel<S: Real>(case: &Problem, rotation: DQuat) -> (Refraction<S>, Incidence<f64>) {
    let to_s = |v: DVec3| {
        let r = rotation * v;
        S::Vec3::new(S::from_f64(r.x), S::from_f64(r.y), S::from_f64(r.z))
    };
    let incidence = Incidence::<S> {
        w: to_s(case.d),
        n: to_s(case.n),
        mu_i: S::from_f64(case.mu_i),
        mu_t: S::from_f64(case.mu_t),
        convention: Convention::AlongRay,
    };
    let r = refract(&incidence).unwrap_or_else(|e| panic!("{case:?}: {e}"));
    let given = Incidence {
        w: DVec3::from_array(wide::<S>(incidence.w)),
        n: DVec3::from_array(wide::<S>(incidence.n)),
        mu_i: incidence.mu_i.to_f64(),
        mu_t: incidence.mu_t.to_f64(),
        convention: Convention::AlongRay,
    };
    (r, given)
}

/// Checks one case and records its errors in `worst`.
fn check<S: Real>(case: &Problem, rotation: DQuat, worst: &mut Worst) {
    let eps = S::EPSILON.to_f64();
    let (r, given) = kernel::<S>(case, rotation);
    let f = Fresnel::of(&r);
    let context = format!(
        "{} at {}: {case:?} rotated by {rotation:?}",
        case.what,
        S::NAME
    );
    for (reflected, transmitted) in [(f.rs, f.ts), (f.rp, f.tp)] {
        let sum = TwoFloat::from(reflected.to_f64()) + transmitted.to_f64();
        assert!(
            (sum - 1.0).abs().hi() <= eps / 2.0,
            "{context}: R + T = {sum:?}"
        );
        assert!(
            reflected >= S::ZERO && transmitted >= S::ZERO,
            "{context}: {f:?}"
        );
    }
    let own = r.transmission.map_or(0.0, |t| {
        let exact = oracle::fresnel(r.mu.to_f64(), r.cos_i.to_f64(), t.cos_t.to_f64());
        error_in_eps(&f, &exact, eps)
    });
    assert!(own <= OWN_BOUND, "{context}: own error {own} eps: {f:?}");
    let facing = if r.normal_flipped { -given.n } else { given.n };
    let exact = oracle::refract_facing(
        given.w.to_array(),
        facing.to_array(),
        given.mu_i,
        given.mu_t,
        Convention::AlongRay,
    );
    let end_to_end = if r.is_tir() == exact.is_tir() {
        error_in_eps(&f, &exact.fresnel(), eps)
    } else {
        // Within rounding of the critical angle the TIR decision itself may differ (the
        // kernel's accuracy test bounds where); R is within √ε of 1 either way.
        assert!(
            exact.k.abs().hi() <= 32.0 * eps * (1.0 + given.mu_i / given.mu_t),
            "a graze: k is zero within its rounding"
        );
        0.0
    };
    let kappa = sensitivity(exact.mu, exact.cos_i, eps);
    assert!(
        end_to_end <= END_TO_END_BOUND + SENSITIVITY_FACTOR * kappa,
        "{context}: end-to-end error {end_to_end} eps with kappa_F {kappa}: {f:?} vs {:?}",
        exact.fresnel()
    );
    let entry = worst.entry(case.what).or_insert([0.0; 3]);
    for (worst, e) in entry
        .iter_mut()
        .zip([own, end_to_end, end_to_end / (1.0 + kappa)])
    {
        *worst = worst.max(e);
    }
}

#[expect(clippy::print_stdout, reason = "the table, for --nocapture")]
fn check_all<S: Real>() -> Worst {
    let mut cases = sets::hard_cases();
    cases.extend(brewster_cases());
    let mut worst = Worst::new();
    for rotation in sets::rotations(41, 0xf7e5) {
        for case in &cases {
            check::<S>(case, rotation, &mut worst);
        }
    }
    println!(
        "{}: worst errors in eps (own, end to end, end to end / (1 + kappa_F))",
        S::NAME
    );
    for (what, [own, end, relative]) in &worst {
        println!("  {what:<24} {own:>6.2} {end:>12.2} {relative:>8.2}");
    }
    worst
}

#[test]
fn fresnel_in_f64() {
    let worst = check_all::<f64>();
    assert!(worst.contains_key("near Brewster") && worst.contains_key("just inside critical"));
}

#[test]
fn fresnel_in_f32() {
    let worst = check_all::<f32>();
    assert!(worst.contains_key("grazing") && worst.contains_key("normal incidence"));
}

#[test]
fn p_light_at_brewster_is_not_reflected_in_either_precision() {
    for case in brewster_cases().iter().filter(|c| c.what == "Brewster") {
        let (r64, _) = kernel::<f64>(case, DQuat::IDENTITY);
        let (r32, _) = kernel::<f32>(case, DQuat::IDENTITY);
        let (f64_, f32_) = (Fresnel::of(&r64), Fresnel::of(&r32));
        // The rounded input sits a few ε from Brewster's angle: r_p is a few ε, R_p its square.
        assert!(f64_.rp <= f64::EPSILON, "{case:?}: R_p = {:e}", f64_.rp);
        assert!(f32_.rp <= f32::EPSILON, "{case:?}: R_p = {:e}", f32_.rp);
        // s light still is (R_s ≈ 9e-8 for air against air at 1.000293).
        assert!(f64_.rs > 1e-8, "{case:?}: R_s = {:e}", f64_.rs);
    }
}

#[test]
fn total_internal_reflection_reflects_everything_in_both_precisions() {
    let past: Vec<_> = sets::hard_cases()
        .into_iter()
        .filter(|c| c.what == "just past critical")
        .collect();
    assert!(!past.is_empty());
    for case in &past {
        let exact = oracle::refract(
            case.d.to_array(),
            case.n.to_array(),
            case.mu_i,
            case.mu_t,
            Convention::AlongRay,
        );
        // 1e-10 (relative) past the critical angle is far beyond f64's rounding of it.
        let (r, _) = kernel::<f64>(case, DQuat::IDENTITY);
        assert!(r.is_tir() && exact.is_tir(), "{case:?}");
        assert_eq!(Fresnel::of(&r), Fresnel::TOTAL_REFLECTION);
        assert_eq!(exact.fresnel().rs, 1.0);
    }
}

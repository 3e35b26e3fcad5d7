//! Angular errors of a variant against the double-double oracle.

use crate::oracle::{self, Exact};
use refraction_kernel::batch::{RayBatch, Transmissions};
use refraction_kernel::{Convention, Real, Variant, Vector3 as _};

use super::sets::Problem;

/// The oracle's answer for one problem as the kernel receives it (rounded to its precision).
#[derive(Clone, Copy, Debug)]
struct Reference {
    exact: Exact,
    /// For a ray within rounding of grazing, the answer for the normal's other side: which side
    /// the ray is on is then decided by rounding, and either answer is right.
    other_side: Option<Exact>,
}

/// Problems rounded to precision `S`, with the oracle's answers for exactly those values.
#[derive(Clone, Debug)]
pub struct Prepared<S: Real> {
    /// The rays as every variant receives them.
    pub rays: RayBatch<S>,
    references: Vec<Reference>,
}

fn round<S: Real>(v: glam::DVec3) -> S::Vec3 {
    S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z))
}

fn wide<S: Real>(v: S::Vec3) -> [f64; 3] {
    v.to_array().map(Real::to_f64)
}

/// Rounds `problems` to precision `S` and asks the oracle about each, calling `progress` with
/// the fraction done now and then.
pub fn prepare<S: Real>(problems: &[Problem], progress: &mut dyn FnMut(f64)) -> Prepared<S> {
    let mut rays = RayBatch::new();
    let mut references = Vec::with_capacity(problems.len());
    let eps = S::EPSILON.to_f64();
    for (i, p) in problems.iter().enumerate() {
        let (d, n) = (round::<S>(p.d), round::<S>(p.n));
        let (mu_i, mu_t) = (S::from_f64(p.mu_i), S::from_f64(p.mu_t));
        rays.push(d, n, mu_i / mu_t);
        let (w, n, mu_i, mu_t) = (wide::<S>(d), wide::<S>(n), mu_i.to_f64(), mu_t.to_f64());
        let exact = oracle::refract(w, n, mu_i, mu_t, Convention::AlongRay);
        let reference = if exact.cos_i.hi().abs() <= 4.0 * eps {
            let side = |n| oracle::refract_facing(w, n, mu_i, mu_t, Convention::AlongRay);
            Reference {
                exact: side(n),
                other_side: Some(side(n.map(|c| -c))),
            }
        } else {
            Reference {
                exact,
                other_side: None,
            }
        };
        references.push(reference);
        if i % 4096 == 0 {
            progress(i as f64 / problems.len() as f64);
        }
    }
    Prepared { rays, references }
}

/// How far a variant's answers are from the oracle's on one set.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Errors {
    /// Largest angular error in radians where both transmit (∞ if a variant returned a
    /// non-finite T; serialised as `null`).
    pub max: f64,
    /// Median angular error in radians where both transmit.
    pub median: f64,
    /// Largest error as a multiple of ε·κ (κ: the problem's condition number).
    pub max_eps_kappa: f64,
    /// Problems where the variant and the oracle disagree about total internal reflection.
    pub tir_mismatches: usize,
}

/// Runs `variant` on `prepared` and compares every answer with the oracle's.
#[must_use]
pub fn errors<S: Real>(variant: Variant, prepared: &Prepared<S>) -> Errors {
    let mut out = Transmissions::for_batch(&prepared.rays);
    variant.transmit_all(&prepared.rays, &mut out);
    errors_of(&out, prepared)
}

/// Compares answers `out` to the rays of `prepared` (one per ray, in order; a peer's, say) with
/// the oracle's.
///
/// # Panics
/// If `out` has fewer answers than `prepared` has rays.
#[must_use]
pub(crate) fn errors_of<S: Real>(out: &Transmissions<S>, prepared: &Prepared<S>) -> Errors {
    let eps = S::EPSILON.to_f64();
    let mut angles = Vec::with_capacity(out.len());
    let mut max_eps_kappa = 0.0_f64;
    let mut tir_mismatches = 0;
    for (i, reference) in prepared.references.iter().enumerate() {
        let candidates = core::iter::once(&reference.exact).chain(&reference.other_side);
        match (out.get(i), reference.exact.t) {
            (Some(t), Some(_)) => {
                let (angle, kappa) = candidates
                    .filter_map(|e: &Exact| {
                        e.t.map(|exact_t| {
                            (
                                oracle::angular_error(wide::<S>(t), &exact_t),
                                e.condition_number(eps),
                            )
                        })
                    })
                    .fold(
                        (f64::INFINITY, 1.0),
                        |best, x| if x.0 < best.0 { x } else { best },
                    );
                angles.push(angle);
                max_eps_kappa = max_eps_kappa.max(angle / (eps * kappa));
            }
            (None, None) => {}
            _ => tir_mismatches += 1,
        }
    }
    angles.sort_by(f64::total_cmp);
    Errors {
        max: angles.last().copied().unwrap_or(0.0),
        median: angles.get(angles.len() / 2).copied().unwrap_or(0.0),
        max_eps_kappa,
        tir_mismatches,
    }
}

//! The problems the variants are measured on: uniform random incidences between real media, and
//! the hard set where the literal formula loses accuracy or the problem is ill-conditioned.

use glam::{DQuat, DVec3};
use rand::rngs::SmallRng;
use rand::{RngExt as _, SeedableRng as _};

/// One refraction problem: a unit travel direction, a unit normal facing it, two indices.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Problem {
    /// Which family of hard case this is (or "random").
    pub what: &'static str,
    /// The travel direction.
    pub d: DVec3,
    /// The normal, facing the ray (d·n ≤ 0).
    pub n: DVec3,
    /// Index of the medium the ray travels in.
    pub mu_i: f64,
    /// Index of the medium the ray enters.
    pub mu_t: f64,
}

/// Refractive indices of common media (vacuum, air, water, crown glass, sapphire, diamond).
pub const REALISTIC_INDICES: [f64; 6] = [1.0, 1.000_293, 1.333, 1.5, 1.77, 2.417];

fn random_unit(rng: &mut SmallRng) -> DVec3 {
    loop {
        let v = DVec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let length = v.length();
        if length > 0.1 && length <= 1.0 {
            return v / length;
        }
    }
}

/// `count` problems with uniformly random 3D incidences and an ordered pair of realistic
/// indices, reproducible from `seed`.
#[must_use]
pub fn random_set(count: usize, seed: u64) -> Vec<Problem> {
    let mut rng = SmallRng::seed_from_u64(seed);
    (0..count)
        .map(|_| {
            let n = random_unit(&mut rng);
            let d = random_unit(&mut rng);
            let pick = |rng: &mut SmallRng| {
                REALISTIC_INDICES[rng.random_range(0..REALISTIC_INDICES.len())]
            };
            Problem {
                what: "random",
                d: if d.dot(n) > 0.0 { -d } else { d },
                n,
                mu_i: pick(&mut rng),
                mu_t: pick(&mut rng),
            }
        })
        .collect()
}

/// The travel direction at angle θi from the normal +y (going down) given sinθi.
fn down_at(sin_i: f64) -> DVec3 {
    DVec3::new(sin_i, -(1.0 - sin_i * sin_i).max(0.0).sqrt(), 0.0)
}

/// The hard cases in the frame where the normal is +y: normal and grazing incidence (down to
/// cosθi = ±0), 1e-4 to 1e-10 (relative) either side of the critical angle, equal indices,
/// μ = 1 ± 1 ulp, and μ from 1e-6 to 1e6.
#[must_use]
pub fn hard_cases() -> Vec<Problem> {
    let case = |what, d: DVec3, mu_i, mu_t| Problem {
        what,
        d: d.normalize(),
        n: DVec3::Y,
        mu_i,
        mu_t,
    };
    let mut cases = Vec::new();
    for (mu_i, mu_t) in [
        (1.0, 1.5),
        (1.5, 1.0),
        (1.0, 2.417),
        (1.333, 1.0),
        (1.0, 1.000_293),
    ] {
        cases.push(case("normal incidence", -DVec3::Y, mu_i, mu_t));
        for cos_i in [1e-3, 1e-8, 1e-15, 1e-300] {
            cases.push(case("grazing", DVec3::new(1.0, -cos_i, 0.0), mu_i, mu_t));
        }
        cases.push(case(
            "grazing, wn = -0",
            DVec3::new(1.0, -0.0, 0.0),
            mu_i,
            mu_t,
        ));
        cases.push(case("grazing, wn = +0", DVec3::X, mu_i, mu_t));
    }
    for (mu_i, mu_t) in [(1.5, 1.0), (2.417, 1.0), (1.333, 1.000_293), (1e6, 1.0)] {
        for exponent in 4..=10 {
            let delta = 10f64.powi(-exponent);
            let sin_critical = mu_t / mu_i;
            cases.push(case(
                "just inside critical",
                down_at(sin_critical * (1.0 - delta)),
                mu_i,
                mu_t,
            ));
            cases.push(case(
                "just past critical",
                down_at(sin_critical * (1.0 + delta)),
                mu_i,
                mu_t,
            ));
        }
    }
    let one_up = f64::from_bits(1.0f64.to_bits() + 1);
    let one_down = f64::from_bits(1.0f64.to_bits() - 1);
    for sin_i in [0.0, 0.1, 0.5, 0.9, 0.999, 1.0 - 1e-12, 1.0] {
        cases.push(case("equal indices", down_at(sin_i), 1.5, 1.5));
        cases.push(case("mu = 1 + 1 ulp", down_at(sin_i), one_up, 1.0));
        cases.push(case("mu = 1 - 1 ulp", down_at(sin_i), one_down, 1.0));
    }
    for exponent in -6..=6 {
        for sin_i in [0.0, 1e-9, 3e-4, 0.3, 0.99] {
            cases.push(case(
                "mu from 1e-6 to 1e6",
                down_at(sin_i),
                10f64.powi(exponent),
                1.0,
            ));
        }
    }
    cases
}

/// `count` random rotations (the identity first), reproducible from `seed`.
#[must_use]
pub fn rotations(count: usize, seed: u64) -> Vec<DQuat> {
    let mut rng = SmallRng::seed_from_u64(seed);
    core::iter::once(DQuat::IDENTITY)
        .chain((1..count).map(|_| {
            let v: [f64; 4] = core::array::from_fn(|_| rng.random_range(-1.0..1.0));
            DQuat::from_array(v).normalize()
        }))
        .collect()
}

/// [`hard_cases`] in the axis-aligned frame and in `rotations - 1` random orientations.
#[must_use]
pub fn hard_set(rotations_count: usize, seed: u64) -> Vec<Problem> {
    let cases = hard_cases();
    rotations(rotations_count, seed)
        .into_iter()
        .flat_map(|q| {
            cases.iter().map(move |c| Problem {
                d: q * c.d,
                n: q * c.n,
                ..*c
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn random_problems_face_their_normals_and_are_reproducible() {
        let set = random_set(1000, 7);
        assert!(
            set.iter()
                .all(|p| p.d.dot(p.n) <= 0.0 && (p.d.length() - 1.0).abs() < 1e-15)
        );
        assert_eq!(set, random_set(1000, 7));
    }

    #[test]
    fn the_hard_set_covers_every_family_in_every_orientation() {
        let set = hard_set(3, 1);
        assert_eq!(set.len(), 3 * hard_cases().len());
        assert!(set.iter().any(|p| p.what == "just past critical"));
    }
}

//! The default kernel over many rays at once: structure-of-arrays in, structure-of-arrays out,
//! written branch-free so that the compiler vectorises it, with an AVX2 build of the same loop
//! chosen at run time on x86-64 CPUs that have it.
//!
//! Every lane performs exactly the scalar kernel's operations (the shared pieces of
//! [`super::stable`]), so each T is bit for bit the one [`super::stable::transmit`] returns. A
//! lane in total internal reflection computes garbage that is then *selected* away (never
//! multiplied by a mask), so no NaN reaches its output or its neighbours.

use super::real::{Real, Vector3};
use super::stable::{cos_incidence, discriminant, facing, tangential, transmitted_direction};

/// Rays as structure-of-arrays: unit travel directions, unit normals (either side), μ = μ_i/μ_t.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RayBatch<S: Real> {
    d: [Vec<S>; 3],
    n: [Vec<S>; 3],
    mu: Vec<S>,
}

impl<S: Real> RayBatch<S> {
    /// An empty batch.
    #[must_use]
    pub fn new() -> Self {
        Self {
            d: [Vec::new(), Vec::new(), Vec::new()],
            n: [Vec::new(), Vec::new(), Vec::new()],
            mu: Vec::new(),
        }
    }

    /// Adds a ray: unit travel direction `d`, unit normal `n`, index ratio `mu` (as accepted by
    /// [`super::stable::refract_facing`]).
    pub fn push(&mut self, d: S::Vec3, n: S::Vec3, mu: S) {
        for (column, value) in self.d.iter_mut().zip(d.to_array()) {
            column.push(value);
        }
        for (column, value) in self.n.iter_mut().zip(n.to_array()) {
            column.push(value);
        }
        self.mu.push(mu);
    }

    /// The number of rays.
    #[must_use]
    pub fn len(&self) -> usize {
        self.mu.len()
    }

    /// Whether the batch holds no ray.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.mu.is_empty()
    }

    /// The columns: d's x, y, z; n's x, y, z; μ. All have [`RayBatch::len`] elements.
    #[must_use]
    pub fn columns(&self) -> ([&[S]; 3], [&[S]; 3], &[S]) {
        let [dx, dy, dz] = &self.d;
        let [nx, ny, nz] = &self.n;
        ([dx, dy, dz], [nx, ny, nz], &self.mu)
    }

    /// Ray `i`: (d, n, μ). Panics if `i >= len()`.
    #[must_use]
    pub fn get(&self, i: usize) -> (S::Vec3, S::Vec3, S) {
        let [dx, dy, dz] = &self.d;
        let [nx, ny, nz] = &self.n;
        (
            S::Vec3::new(dx[i], dy[i], dz[i]),
            S::Vec3::new(nx[i], ny[i], nz[i]),
            self.mu[i],
        )
    }
}

/// The results of a batch: T per ray (zero where totally internally reflected) and the TIR flags.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Transmissions<S: Real> {
    t: [Vec<S>; 3],
    tir: Vec<bool>,
}

impl<S: Real> Transmissions<S> {
    /// Room for the results of `rays`, every ray marked as not yet computed (zero, not TIR).
    #[must_use]
    pub fn for_batch(rays: &RayBatch<S>) -> Self {
        let zeros = vec![S::ZERO; rays.len()];
        Self {
            t: [zeros.clone(), zeros.clone(), zeros],
            tir: vec![false; rays.len()],
        }
    }

    /// The number of results.
    #[must_use]
    pub fn len(&self) -> usize {
        self.tir.len()
    }

    /// Whether there are no results.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.tir.is_empty()
    }

    /// Result `i`: T, or `None` on total internal reflection. Panics if `i >= len()`.
    #[must_use]
    pub fn get(&self, i: usize) -> Option<S::Vec3> {
        let [tx, ty, tz] = &self.t;
        (!self.tir[i]).then(|| S::Vec3::new(tx[i], ty[i], tz[i]))
    }

    /// The columns to write: T's x, y, z and the TIR flags, [`Transmissions::len`] each.
    pub fn columns_mut(&mut self) -> ([&mut [S]; 3], &mut [bool]) {
        let [tx, ty, tz] = &mut self.t;
        ([tx, ty, tz], &mut self.tir)
    }

    fn resize(&mut self, len: usize) {
        for column in &mut self.t {
            column.resize(len, S::ZERO);
        }
        self.tir.resize(len, false);
    }
}

/// One lane: [`super::stable::transmit`] without branches. Returns (T or zero, TIR).
#[inline(always)]
fn lane<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> (S::Vec3, bool) {
    let n = facing::<S>(d, n);
    let cos_i = cos_incidence::<S>(d, n);
    let one_minus_mu2 = (S::ONE - mu) * (S::ONE + mu);
    let along = tangential::<S>(d, n, cos_i);
    let k = discriminant(along, cos_i, mu, one_minus_mu2);
    let tir = k < S::ZERO;
    let cos_t = k.max(S::ZERO).sqrt();
    let t = transmitted_direction(along, n, mu, cos_t);
    let t = if mu == S::ONE { d } else { t };
    let zero = S::Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    (
        if tir && mu != S::ONE { zero } else { t },
        tir && mu != S::ONE,
    )
}

/// Runs `lane` on every ray of `rays`, writing `out` (which must have the same length): the
/// loop shared by the batch kernel and the scalar variants, sliced so that no bounds check is
/// left inside it. `index` sees every index before use: the identity lets the compiler
/// vectorise across rays; `std::hint::black_box` keeps each ray a call of its own.
#[inline(always)]
pub(crate) fn for_each_ray<S: Real>(
    rays: &RayBatch<S>,
    out: &mut Transmissions<S>,
    index: impl Fn(usize) -> usize,
    lane: impl Fn(S::Vec3, S::Vec3, S) -> (S::Vec3, bool),
) {
    let len = rays.len().min(out.len());
    let [dx, dy, dz] = rays.d.each_ref().map(|c| &c[..len]);
    let [nx, ny, nz] = rays.n.each_ref().map(|c| &c[..len]);
    let mu = &rays.mu[..len];
    let [tx, ty, tz] = out.t.each_mut().map(|c| &mut c[..len]);
    let tir = &mut out.tir[..len];
    for i in 0..len {
        let i = index(i).min(len - 1);
        let (t, reflected) = lane(
            S::Vec3::new(dx[i], dy[i], dz[i]),
            S::Vec3::new(nx[i], ny[i], nz[i]),
            mu[i],
        );
        [tx[i], ty[i], tz[i]] = t.to_array();
        tir[i] = reflected;
    }
}

#[inline(always)]
fn transmit_lanes<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    for_each_ray(rays, out, |i| i, |d, n, mu| lane(d, n, mu));
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn transmit_lanes_avx2<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    transmit_lanes(rays, out);
}

/// Refracts every ray of `rays` into `out` (resized to match), vectorised; each T equals
/// [`super::stable::transmit`]'s bit for bit.
pub fn transmit_batch<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    out.resize(rays.len());
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU supports AVX2, as checked just above.
        unsafe { transmit_lanes_avx2(rays, out) };
        return;
    }
    transmit_lanes(rays, out);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stable::transmit;
    use glam::Vec3;

    #[test]
    fn a_tir_lane_leaves_its_neighbours_alone() {
        let mut rays = RayBatch::<f32>::new();
        let n = Vec3::Y;
        let steep = Vec3::new(0.6, -0.8, 0.0);
        let shallow = Vec3::new(0.8, -0.6, 0.0);
        for (d, mu) in [
            (steep, 1.5),
            (shallow, 1.5),
            (steep, 1.0 / 1.5),
            (Vec3::X, 1.5),
            (Vec3::X, 1.0),
        ] {
            rays.push(d, n, mu);
        }
        let mut out = Transmissions::for_batch(&rays);
        transmit_batch(&rays, &mut out);
        for i in 0..rays.len() {
            let (d, n, mu) = rays.get(i);
            assert_eq!(out.get(i), transmit(d, n, mu), "lane {i}");
        }
        assert_eq!(out.get(1), None);
        assert_eq!(out.get(3), None);
        assert_eq!(out.get(4), Some(Vec3::X));
    }
}

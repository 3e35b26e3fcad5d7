//! Time per ray: repeated runs over an in-cache working set, median of the samples; and one
//! streaming figure beside the time of merely moving the same bytes.

use std::hint::black_box;
use std::time::{Duration, Instant};

use refraction_kernel::batch::{RayBatch, Transmissions};
use refraction_kernel::{Real, Variant};

/// How long one timing sample should run: long enough to dwarf the clock's resolution.
const SAMPLE_TIME: Duration = Duration::from_millis(2);

/// The median over `samples` samples of the time `pass` takes per ray on `len` rays, each
/// sample repeating `pass` enough times to last about [`SAMPLE_TIME`].
fn median_ns_per_ray(len: usize, samples: usize, mut pass: impl FnMut()) -> f64 {
    let start = Instant::now();
    pass();
    let once = start.elapsed().max(Duration::from_nanos(1));
    let repeats = (SAMPLE_TIME.as_nanos() / once.as_nanos()).clamp(1, 1_000_000) as u32;
    let mut per_ray: Vec<f64> = (0..samples.max(1))
        .map(|_| {
            let start = Instant::now();
            for _ in 0..repeats {
                pass();
            }
            start.elapsed().as_nanos() as f64 / (f64::from(repeats) * len.max(1) as f64)
        })
        .collect();
    per_ray.sort_by(f64::total_cmp);
    per_ray[per_ray.len() / 2]
}

/// Nanoseconds per ray of `variant` on `rays` (which should fit in cache): median of `samples`.
#[must_use]
pub fn ns_per_ray<S: Real>(variant: Variant, rays: &RayBatch<S>, samples: usize) -> f64 {
    let mut out = Transmissions::for_batch(rays);
    median_ns_per_ray(rays.len(), samples, || {
        variant.transmit_all(black_box(rays), &mut out);
        black_box(&mut out);
    })
}

/// What streaming many more rays than fit in cache costs.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Streaming {
    /// Rays per pass.
    pub rays: usize,
    /// The batch kernel's time per ray, f32.
    pub batch_ns_per_ray: f64,
    /// The time per ray of reading the same W, N, μ and writing T and the TIR flag with no
    /// refraction arithmetic: the memory limit.
    pub memory_limit_ns_per_ray: f64,
}

/// Reads every input column and writes every output column once, doing almost no arithmetic.
fn move_bytes(rays: &RayBatch<f32>, out: &mut Transmissions<f32>) {
    let ([dx, dy, dz], [nx, ny, nz], mu) = rays.columns();
    let ([tx, ty, tz], tir) = out.columns_mut();
    for i in 0..mu.len().min(tir.len()) {
        tx[i] = dx[i] + nx[i] * mu[i];
        ty[i] = dy[i] + ny[i] * mu[i];
        tz[i] = dz[i] + nz[i] * mu[i];
        tir[i] = false;
    }
}

/// Times the f32 batch kernel and the memory limit on `rays`, `samples` times each.
#[must_use]
pub fn streaming(rays: &RayBatch<f32>, samples: usize) -> Streaming {
    let mut out = Transmissions::for_batch(rays);
    let batch_ns_per_ray = median_ns_per_ray(rays.len(), samples, || {
        Variant::Batch.transmit_all(black_box(rays), &mut out);
        black_box(&mut out);
    });
    let memory_limit_ns_per_ray = median_ns_per_ray(rays.len(), samples, || {
        move_bytes(black_box(rays), &mut out);
        black_box(&mut out);
    });
    Streaming {
        rays: rays.len(),
        batch_ns_per_ray,
        memory_limit_ns_per_ray,
    }
}

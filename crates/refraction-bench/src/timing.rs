//! Time per ray: repeated runs over an in-cache working set, median of the samples; and one
//! streaming figure beside the time of merely moving the same bytes.

use core::hint::black_box;
use core::time::Duration;
use web_time::Instant;

use refraction_kernel::batch::{RayBatch, Transmissions};
use refraction_kernel::{Real, Variant};
use refraction_model::report::Streaming;

/// How long one timing sample should run: long enough to dwarf the clock's resolution.
const SAMPLE_TIME: Duration = Duration::from_millis(2);

/// One pass over a set of rays, to be timed.
pub type Pass<'a> = Box<dyn FnMut() + 'a>;

/// How many times `pass` must run to last about [`SAMPLE_TIME`]: it runs once to warm up (its
/// first run may touch fresh memory) and once more to find out.
fn repeats(pass: &mut Pass<'_>) -> u32 {
    pass();
    let start = Instant::now();
    pass();
    let once = start.elapsed().max(Duration::from_nanos(1));
    (SAMPLE_TIME.as_nanos() / once.as_nanos()).clamp(1, 1_000_000) as u32
}

/// For each of `passes` over the same `len` rays, the median over `samples` samples of its time
/// per ray, each sample repeating the pass to last about `SAMPLE_TIME` (2 ms). The samples are taken
/// in turn (A, B, C, A, B, C, ...), so that a change in the machine's speed during the run
/// (other work starting or stopping) touches every pass alike and their ratios stay meaningful.
#[must_use]
pub(crate) fn medians_ns_per_ray(len: usize, samples: usize, passes: &mut [Pass<'_>]) -> Vec<f64> {
    let repeats: Vec<u32> = passes.iter_mut().map(repeats).collect();
    let mut per_ray = vec![Vec::with_capacity(samples.max(1)); passes.len()];
    for _ in 0..samples.max(1) {
        for ((pass, &times), sampled) in passes.iter_mut().zip(&repeats).zip(&mut per_ray) {
            let start = Instant::now();
            for _ in 0..times {
                pass();
            }
            let ns = start.elapsed().as_nanos() as f64;
            sampled.push(ns / (f64::from(times) * len.max(1) as f64));
        }
    }
    per_ray
        .into_iter()
        .map(|mut sampled| {
            sampled.sort_by(f64::total_cmp);
            sampled[sampled.len() / 2]
        })
        .collect()
}

/// A timed pass of `variant` over `rays` into an output of its own.
#[must_use]
pub(crate) fn variant_pass<S: Real>(variant: Variant, rays: &RayBatch<S>) -> Pass<'_> {
    let mut out = Transmissions::for_batch(rays);
    Box::new(move || {
        variant.transmit_all(black_box(rays), &mut out);
        black_box(&mut out);
    })
}

/// Reads every input block and writes every output block once, doing almost no arithmetic.
fn move_bytes(rays: &RayBatch<f32>, out: &mut Transmissions<f32>) {
    let (answers, tir) = out.blocks_mut();
    for ((block, answer), flags) in rays.blocks().iter().zip(answers).zip(tir) {
        let ([dx, dy, dz], [nx, ny, nz], mu) = (&block.d, &block.n, &block.mu);
        let [tx, ty, tz] = &mut answer.t;
        for (j, flag) in flags.iter_mut().enumerate() {
            tx[j] = dx[j] + nx[j] * mu[j];
            ty[j] = dy[j] + ny[j] * mu[j];
            tz[j] = dz[j] + nz[j] * mu[j];
            *flag = false;
        }
    }
}

/// Times the f32 batch kernel and the memory limit on `rays`, `samples` times each, in turn.
#[must_use]
pub(crate) fn streaming(rays: &RayBatch<f32>, samples: usize) -> Streaming {
    let mut out = Transmissions::for_batch(rays);
    let memory_limit: Pass<'_> = Box::new(move || {
        move_bytes(black_box(rays), &mut out);
        black_box(&mut out);
    });
    let mut passes = [variant_pass(Variant::Batch, rays), memory_limit];
    let medians = medians_ns_per_ray(rays.len(), samples, &mut passes);
    Streaming {
        rays: rays.len(),
        batch_ns_per_ray: medians[0],
        memory_limit_ns_per_ray: medians[1],
    }
}

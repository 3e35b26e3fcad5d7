//! What accuracy costs in time: every [`Variant`] at both precisions, timed on this machine
//! and measured against the double-double oracle. Run by the `bench` command and by the
//! explorer's "Accuracy vs time" panel.

mod accuracy;
pub mod oracle;
#[cfg(not(target_arch = "wasm32"))]
mod peer;
pub mod sets;
mod timing;

pub use accuracy::{Errors, Prepared, errors, prepare};
#[cfg(not(target_arch = "wasm32"))]
pub use peer::Packed;
pub use timing::Pass;

use accuracy::errors_of;
#[cfg(target_arch = "x86_64")]
use refraction_kernel::batch::Build;
use refraction_kernel::batch::{RayBatch, Transmissions};
use refraction_kernel::{Real, Variant};
use refraction_model::report::{Report, Row};
use timing::{medians_ns_per_ray, streaming, variant_pass};

/// What a row of the report measures: a kernel [`Variant`], or a peer library
/// (`peer::Ultraviolet`, on a desktop) run on the same rays.
pub trait Subject<S: Real> {
    /// The name in reports and JSON.
    fn name(&self) -> &'static str;

    /// A pass over `rays` to time; any repacking the subject needs happens here, before it.
    fn pass<'a>(&self, rays: &'a RayBatch<S>) -> Pass<'a>;

    /// The answers for `rays`, one per ray in order.
    fn answers(&self, rays: &RayBatch<S>) -> Transmissions<S>;
}

impl<S: Real> Subject<S> for Variant {
    fn name(&self) -> &'static str {
        Self::name(*self)
    }

    fn pass<'a>(&self, rays: &'a RayBatch<S>) -> Pass<'a> {
        variant_pass(*self, rays)
    }

    fn answers(&self, rays: &RayBatch<S>) -> Transmissions<S> {
        let mut out = Transmissions::for_batch(rays);
        self.transmit_all(rays, &mut out);
        out
    }
}

/// How much work a run does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    /// Problems in the random set.
    pub random_rays: usize,
    /// Orientations of the hard cases (the axis-aligned one included).
    pub hard_rotations: usize,
    /// Rays in the in-cache timing set.
    pub timing_rays: usize,
    /// Timing samples per variant (the median is reported).
    pub samples: usize,
    /// Rays in the streaming measurement.
    pub streaming_rays: usize,
}

impl Config {
    /// Under 20 s on 2 cores (release build).
    pub const QUICK: Self = Self {
        random_rays: 20_000,
        hard_rotations: 4,
        timing_rays: 4096,
        samples: 7,
        streaming_rays: 2_000_000,
    };

    /// Steadier figures, about a minute.
    pub const FULL: Self = Self {
        random_rays: 200_000,
        hard_rotations: 24,
        timing_rays: 4096,
        samples: 101,
        streaming_rays: 8_000_000,
    };
}

/// The processor's model name, its thread count and its vector extensions.
#[must_use]
pub fn cpu_description() -> String {
    #[cfg(not(target_arch = "wasm32"))]
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|info| {
            info.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_owned())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_owned());
    // A browser page has no file system: the architecture (wasm32) names it.
    #[cfg(target_arch = "wasm32")]
    let model = std::env::consts::ARCH.to_owned();
    let threads = std::thread::available_parallelism().map_or(1, core::num::NonZero::get);
    #[cfg(target_arch = "x86_64")]
    let features: Vec<&str> = [
        ("avx2", std::arch::is_x86_feature_detected!("avx2")),
        ("fma", std::arch::is_x86_feature_detected!("fma")),
        ("avx512", Build::Avx512.is_available()),
    ]
    .into_iter()
    .filter_map(|(name, present)| present.then_some(name))
    .collect();
    // Elsewhere (a browser's WebAssembly) no extension is looked for.
    #[cfg(not(target_arch = "x86_64"))]
    let features: Vec<&str> = Vec::new();
    format!("{model}, {threads} threads, {}", features.join("+"))
}

/// The rows of `subjects` at precision `S`: all timed in one interleaved measurement (so that
/// their ratios hold however busy the machine is), then measured against the oracle.
fn rows_at<S: Real>(
    config: &Config,
    random: &Prepared<S>,
    hard: &Prepared<S>,
    subjects: &[&dyn Subject<S>],
    step: &mut dyn FnMut(),
) -> Vec<Row> {
    let mut timing_rays = RayBatch::new();
    for i in 0..config.timing_rays.min(random.rays.len()) {
        let (d, n, mu) = random.rays.get(i);
        timing_rays.push(d, n, mu);
    }
    let mut passes: Vec<Pass<'_>> = subjects.iter().map(|s| s.pass(&timing_rays)).collect();
    let times = medians_ns_per_ray(timing_rays.len(), config.samples, &mut passes);
    drop(passes);
    subjects
        .iter()
        .zip(times)
        .map(|(subject, ns)| {
            let on_random = errors_of(&subject.answers(&random.rays), random);
            let on_hard = errors_of(&subject.answers(&hard.rays), hard);
            step();
            Row {
                variant: subject.name(),
                precision: S::NAME,
                ns_per_ray: ns,
                rays_per_second: 1e9 / ns,
                max_err_random: on_random.max,
                median_err_random: on_random.median,
                max_err_hard: on_hard.max,
                median_err_hard: on_hard.median,
                max_err_hard_eps_kappa: on_hard.max_eps_kappa,
                tir_mismatches: on_random.tir_mismatches + on_hard.tir_mismatches,
            }
        })
        .collect()
}

/// The peer libraries measured beside the variants (f32 only).
#[cfg(not(target_arch = "wasm32"))]
const PEERS: [&dyn Subject<f32>; 1] = [&peer::Ultraviolet];

/// No peer in a browser: its SIMD library stays on the desktop side.
#[cfg(target_arch = "wasm32")]
const PEERS: [&dyn Subject<f32>; 0] = [];

/// Seeds of the problem sets, fixed so that every run measures the same problems.
const RANDOM_SEED: u64 = 0x5eed_0001;
const HARD_SEED: u64 = 0x5eed_0002;

/// Measures every variant at both precisions. `progress` receives the fraction done (0 to 1).
#[must_use]
pub fn run(config: &Config, progress: &mut dyn FnMut(f64)) -> Report {
    let random_set = sets::random_set(config.random_rays, RANDOM_SEED);
    let hard_set = sets::hard_set(config.hard_rotations, HARD_SEED);
    // Rough shares of the run: the oracle's answers 40 %, the rows 50 %, streaming 10 %.
    let random32 = prepare::<f32>(&random_set, &mut |f| progress(0.2 * f));
    let hard32 = prepare::<f32>(&hard_set, &mut |_| {});
    let random64 = prepare::<f64>(&random_set, &mut |f| progress(0.2 + 0.2 * f));
    let hard64 = prepare::<f64>(&hard_set, &mut |_| {});
    let subjects32: Vec<&dyn Subject<f32>> = Variant::ALL
        .iter()
        .map(|v| v as &dyn Subject<f32>)
        .chain(PEERS.iter().copied())
        .collect();
    let subjects64: Vec<&dyn Subject<f64>> = Variant::ALL
        .iter()
        .map(|v| v as &dyn Subject<f64>)
        .collect();
    let per_row = 0.5 / (subjects32.len() + subjects64.len()) as f64;
    let mut done = 0.4;
    let mut step = || {
        done += per_row;
        progress(done);
    };
    let mut rows = rows_at(config, &random32, &hard32, &subjects32, &mut step);
    rows.extend(rows_at(config, &random64, &hard64, &subjects64, &mut step));
    let mut streaming_rays = RayBatch::<f32>::new();
    for i in 0..config.streaming_rays {
        let (d, n, mu) = random32.rays.get(i % random32.rays.len());
        streaming_rays.push(d, n, mu);
    }
    let streaming = streaming(&streaming_rays, config.samples.min(9));
    progress(1.0);
    Report {
        rows,
        rays: random_set.len(),
        hard_rays: hard_set.len(),
        streaming,
        cpu: cpu_description(),
    }
}

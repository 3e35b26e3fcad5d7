//! Criterion benches of every refraction variant at both precisions, and the batch kernel against
//! ultraviolet's `Vec3x8::refracted` (the SIMD peer), on the same in-cache random rays that the
//! `bench` command times. Regressions show here in review; the README quotes the `bench` command's
//! figures.

use core::hint::black_box;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use refraction_bench::Packed;
use refraction_bench::prepare;
use refraction_bench::sets;
use refraction_kernel::batch::{Build, RayBatch, Transmissions, transmit_batch_with};
use refraction_kernel::{Real, Variant};

const RAYS: usize = 4096;

fn rays<S: Real>() -> RayBatch<S> {
    prepare(&sets::random_set(RAYS, 42), &mut |_| {}).rays
}

fn variants_at<S: Real>(c: &mut Criterion) {
    let rays = rays::<S>();
    let mut out = Transmissions::for_batch(&rays);
    let mut group = c.benchmark_group(format!("refract_{}", S::NAME));
    group.throughput(Throughput::Elements(RAYS as u64));
    for variant in Variant::ALL {
        group.bench_function(BenchmarkId::from_parameter(variant.name()), |b| {
            b.iter(|| variant.transmit_all(black_box(&rays), &mut out));
        });
    }
    group.finish();
}

/// The regression group of issue 14: the batch kernel against ultraviolet's 8-wide GLSL
/// refraction (normal turned to face the ray, as in the `bench` command) on the same rays, packed
/// eight at a time outside the timed loop. Batch should take at most ultraviolet's time; each
/// build of the batch loop and ultraviolet without the normal turn are there for comparison.
fn batch_against_ultraviolet(c: &mut Criterion) {
    let rays = rays::<f32>();
    let mut out = Transmissions::for_batch(&rays);
    let mut packed = Packed::new(&rays);
    let mut group = c.benchmark_group("batch_vs_ultraviolet_f32");
    group.throughput(Throughput::Elements(RAYS as u64));
    group.bench_function(BenchmarkId::from_parameter("batch"), |b| {
        b.iter(|| Variant::Batch.transmit_all(black_box(&rays), &mut out));
    });
    // Each build of the loop this CPU runs (the widest is what `batch` uses), for the README's
    // comparison of AVX2 and AVX-512.
    for build in Build::ALL.into_iter().filter(|b| b.is_available()) {
        let id = BenchmarkId::new("batch", build.name());
        group.bench_function(id, |b| {
            b.iter(|| transmit_batch_with(build, black_box(&rays), &mut out));
        });
    }
    group.bench_function(BenchmarkId::from_parameter("ultraviolet"), |b| {
        b.iter(|| black_box(&mut packed).transmit_all());
    });
    // ultraviolet's loop alone, the normals turned beforehand (not timed): its best case.
    packed.turn_normals();
    group.bench_function(BenchmarkId::from_parameter("ultraviolet_facing"), |b| {
        b.iter(|| black_box(&mut packed).transmit_all_facing());
    });
    group.finish();
}

criterion_group!(
    benches,
    variants_at::<f32>,
    variants_at::<f64>,
    batch_against_ultraviolet
);
criterion_main!(benches);

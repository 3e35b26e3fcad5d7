//! Criterion benches of every refraction variant at both precisions, plus ultraviolet's
//! `Vec3x8::refracted` as the SIMD peer, on the same in-cache random rays that the `bench`
//! command times. Regressions show here in review; the README quotes the `bench` command's
//! figures.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use refraction_bench::accuracy::prepare;
use refraction_bench::sets;
use refraction_kernel::batch::{RayBatch, Transmissions};
use refraction_kernel::{Real, Variant};
use std::hint::black_box;
use ultraviolet::{Vec3x8, f32x8};

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

/// ultraviolet's 8-wide GLSL refraction on the same rays, packed eight at a time.
fn ultraviolet_peer(c: &mut Criterion) {
    let rays = rays::<f32>();
    let ([dx, dy, dz], [nx, ny, nz], mu) = rays.columns();
    let pack =
        |column: &[f32], i: usize| f32x8::from(<[f32; 8]>::try_from(&column[i..i + 8]).unwrap());
    let lanes: Vec<(Vec3x8, Vec3x8, f32x8)> = (0..RAYS / 8)
        .map(|chunk| {
            let i = chunk * 8;
            (
                Vec3x8::new(pack(dx, i), pack(dy, i), pack(dz, i)),
                Vec3x8::new(pack(nx, i), pack(ny, i), pack(nz, i)),
                pack(mu, i),
            )
        })
        .collect();
    let mut out = vec![Vec3x8::zero(); lanes.len()];
    let mut group = c.benchmark_group("refract_f32");
    group.throughput(Throughput::Elements(RAYS as u64));
    group.bench_function(BenchmarkId::from_parameter("ultraviolet_vec3x8"), |b| {
        b.iter(|| {
            for (t, (d, n, eta)) in out.iter_mut().zip(black_box(&lanes)) {
                *t = d.refracted(*n, *eta);
            }
        });
    });
    group.finish();
}

criterion_group!(
    benches,
    variants_at::<f32>,
    variants_at::<f64>,
    ultraviolet_peer
);
criterion_main!(benches);

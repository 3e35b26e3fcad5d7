//! What tracing only the effects a scene asks for saves: each built-in scene with 1,000 source
//! rays, traced as its file says and with every effect on.

use criterion::{Criterion, criterion_group, criterion_main};
use refraction_explorer::scene::{Scene, catalogue};

fn trace(c: &mut Criterion) {
    let mut group = c.benchmark_group("trace_1000_rays");
    for info in catalogue() {
        let Ok(mut scene) = Scene::embedded(info.name) else {
            continue;
        };
        if scene.set_ray_count(1000).is_err() {
            continue;
        }
        let mut everything = scene.clone();
        if everything
            .set_effects(scene.effects().everything())
            .is_err()
        {
            continue;
        }
        group.bench_function(format!("{}/as_file", info.name), |b| {
            b.iter(|| std::hint::black_box(scene.trace()));
        });
        group.bench_function(format!("{}/every_effect", info.name), |b| {
            b.iter(|| std::hint::black_box(everything.trace()));
        });
    }
    group.finish();
}

criterion_group!(benches, trace);
criterion_main!(benches);

//! What tracing only the effects a scene asks for saves: each built-in scene with 1,000 source
//! rays (a single-ray source keeps its one ray), traced as its file says and with every effect
//! on, each into a reused `Trace` as an editor retraces; and as the file says into a fresh
//! one, to show what allocating costs. `cargo bench --bench trace`.

use criterion::{Criterion, criterion_group, criterion_main};
use refraction_scene::{Scene, catalogue};

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
        let name = format!("{}/{}_rays", info.name, scene.source().rays);
        let mut trace = scene.trace();
        group.bench_function(format!("{name}/as_file"), |b| {
            b.iter(|| scene.retrace(core::hint::black_box(&mut trace)));
        });
        group.bench_function(format!("{name}/every_effect"), |b| {
            b.iter(|| everything.retrace(core::hint::black_box(&mut trace)));
        });
        group.bench_function(format!("{name}/as_file_fresh"), |b| {
            b.iter(|| core::hint::black_box(scene.trace()));
        });
    }
    group.finish();
}

criterion_group!(benches, trace);
criterion_main!(benches);

//! The tracer computes what a scene asks for and nothing else; every scene file loads, traces
//! and renders; no input makes loading or tracing panic.

use std::path::Path;

use glam::DVec2;
use proptest::prelude::*;
use refraction_scene::{
    Counts, DEFAULT_SCENE, EditError, Effects, Outcome, Scene, Trace, catalogue,
};

fn scene(name: &str) -> Scene {
    Scene::embedded(name).unwrap_or_else(|e| panic!("{e}"))
}

/// Asserts that `trace` did none of the work `effects` leaves out.
fn computes_only_what_is_asked(name: &str, effects: &Effects, trace: &Trace) {
    let c: &Counts = &trace.counts;
    assert_eq!(c.kernel_calls, trace.hits.len(), "{name}");
    assert!(trace.hits.iter().all(|h| h.mu_i != h.mu_t), "{name}");
    if !effects.partial_reflection {
        assert_eq!(c.reflections_spawned, 0, "{name}");
        assert!(trace.paths.iter().all(|p| p.parent_hit.is_none()), "{name}");
    }
    if !effects.fresnel {
        assert_eq!(c.fresnel_evaluations, 0, "{name}");
        assert!(trace.hits.iter().all(|h| h.fresnel.is_none()), "{name}");
    }
    if !effects.dispersion {
        assert_eq!(c.wavelengths, 1, "{name}");
    }
    if !effects.absorption {
        assert_eq!(c.absorption_evaluations, 0, "{name}");
    }
    if !effects.intensities() {
        assert!(
            trace.segments.iter().all(|s| s.intensity.is_none()),
            "{name}"
        );
    }
    assert_eq!(c.segments, trace.segments.len(), "{name}");
    assert_eq!(c.paths, trace.paths.len(), "{name}");
    assert!(!c.truncated, "{name}");
}

#[test]
fn every_file_in_assets_is_built_in_loads_traces_and_renders() {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("../refraction-scene/assets/scenes");
    let mut files: Vec<String> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    files.sort();
    let mut built_in: Vec<String> = catalogue().iter().map(|i| i.name.to_owned()).collect();
    built_in.sort();
    assert_eq!(files, built_in);
    assert_eq!(catalogue()[0].name, DEFAULT_SCENE);
    for name in files {
        let path = folder.join(format!("{name}.toml"));
        let from_file = Scene::load(path.to_str().unwrap()).unwrap_or_else(|e| panic!("{e}"));
        let embedded = scene(&name);
        assert_eq!(from_file, embedded);
        assert!(!embedded.title().is_empty() && !embedded.description().is_empty());
        let trace = embedded.trace();
        assert!(trace.counts.kernel_calls > 0, "{name}");
        computes_only_what_is_asked(&name, embedded.effects(), &trace);
        for s in &trace.segments {
            assert!(s.from.is_finite() && s.to.is_finite(), "{name}");
        }
        let png =
            refraction_render::pixmap(refraction_render::Picture::Scene(&from_file), (640, 360))
                .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((png.width(), png.height()), (640, 360), "{name}");
    }
}

#[test]
fn a_single_interface_is_one_kernel_call_and_nothing_else() {
    let c = scene("interface").trace().counts;
    assert_eq!(
        c,
        Counts {
            wavelengths: 1,
            source_rays: 1,
            kernel_calls: 1,
            segments: 2,
            paths: 1,
            ..Counts::default()
        }
    );
}

#[test]
fn equal_indices_cost_no_kernel_call() {
    let trace = scene("fibre").trace();
    assert!(trace.counts.equal_index_skips > 0);
    let most_reflections = (0..trace.paths.len())
        .map(|p| {
            trace
                .hits
                .iter()
                .filter(|h| h.path == p && h.outcome == Outcome::TotalInternalReflection)
                .count()
        })
        .max();
    assert!(most_reflections >= Some(3), "{most_reflections:?}");
}

#[test]
fn asking_for_every_effect_computes_more() {
    for info in catalogue() {
        let file = scene(info.name);
        let mut everything = file.clone();
        everything.set_effects(file.effects().everything()).unwrap();
        let (lean, full) = (file.trace().counts, everything.trace().counts);
        assert!(
            full.fresnel_evaluations >= lean.fresnel_evaluations,
            "{}",
            info.name
        );
        assert!(full.wavelengths >= lean.wavelengths, "{}", info.name);
        assert!(
            full.reflections_spawned >= lean.reflections_spawned,
            "{}",
            info.name
        );
        assert!(full.kernel_calls >= lean.kernel_calls, "{}", info.name);
    }
    let prism = scene("dispersing-prism");
    let mut white_once = prism.clone();
    let mut effects = *prism.effects();
    effects.dispersion = false;
    white_once.set_effects(effects).unwrap();
    let (dispersed, once) = (prism.trace(), white_once.trace());
    assert_eq!(dispersed.counts.wavelengths, 7);
    assert_eq!(dispersed.counts.kernel_calls, 14);
    assert_eq!(once.counts.wavelengths, 1);
    assert_eq!(once.counts.kernel_calls, 2);
    assert_eq!(once.paths[0].light.wavelength_nm(), None);
}

#[test]
fn intensities_fall_by_fresnel_and_beer_lambert() {
    let slab = scene("slab");
    let trace = slab.trace();
    let path = &trace.paths[0];
    let [air_in, glass, air_out] = &trace.segments[path.segments.clone()] else {
        panic!("three segments");
    };
    let f = trace.hits[0].fresnel.unwrap();
    assert_eq!(air_in.intensity, Some(1.0));
    let after_entry = f64::midpoint(f.ts, f.tp);
    assert!((glass.intensity.unwrap() - after_entry).abs() < 1e-15);
    let absorption = slab.media()[glass.medium].absorption;
    let kept = (-absorption * glass.from.distance(glass.to)).exp();
    assert!((glass.intensity_end.unwrap() - after_entry * kept).abs() < 1e-15);
    assert!(air_out.intensity.unwrap() < glass.intensity_end.unwrap());
}

#[test]
fn an_editor_can_move_things_retrace_and_pick_a_hit() {
    let mut droplet = scene("droplet");
    let before = droplet.trace();
    droplet.move_shape(0, DVec2::new(0.0, 0.3)).unwrap();
    let after = droplet.trace();
    assert_ne!(before.hits[0].point, after.hits[0].point);
    let hit = after
        .nearest_hit(after.hits[3].point + DVec2::splat(1e-6))
        .unwrap();
    assert_eq!(hit.point, after.hits[3].point);
    assert_eq!(
        droplet.move_shape(5, DVec2::ONE),
        Err(EditError::NoSuchShape(5))
    );
    // Within the range a scene file may use, and no farther (coordinates beyond it once gave
    // null points in the JSON).
    let far = DVec2::new(refraction_scene::MAX_COORDINATE, 0.0);
    assert_eq!(droplet.move_shape(0, far), Ok(()));
    assert_eq!(droplet.move_shape(0, far), Err(EditError::OutOfRange));
    assert_eq!(
        droplet.move_shape(0, DVec2::new(f64::INFINITY, 0.0)),
        Err(EditError::NotFinite)
    );
    assert_eq!(
        droplet.set_source_origin(DVec2::new(-1.7e308, 0.0)),
        Err(EditError::OutOfRange)
    );
    assert_eq!(
        droplet.set_source_origin(DVec2::new(f64::NAN, 0.0)),
        Err(EditError::NotFinite)
    );
    assert_eq!(
        droplet.set_source_direction(DVec2::ZERO),
        Err(EditError::NoDirection)
    );
    assert_eq!(droplet.set_ray_count(0), Err(EditError::RayCount(0)));
    let mut effects = *droplet.effects();
    effects.min_intensity = 2.0;
    assert!(droplet.set_effects(effects).is_err());
    let outlines = droplet.outlines();
    assert_eq!(outlines.len(), 1);
    assert!(outlines[0].polyline(0.05).len() > 100);
    assert!(
        Scene::embedded("no-such-scene")
            .unwrap_err()
            .message
            .contains("droplet")
    );
}

#[test]
fn partial_reflection_without_intensities_stops_at_the_segment_budget() {
    let text = r#"
title = "Mirror box"
[media.glass]
index = 1.5
[[shapes]]
polygon = { points = [[0, 0], [1, 0], [1, 1], [0, 1]], medium = "glass" }
[source]
kind = "fan"
origin = [-1, 0.5]
direction = [1, 0.1]
rays = 1000
spread_deg = 30
[effects]
partial_reflection = true
max_depth = 1000
"#;
    let trace = Scene::from_toml(text, "box.toml", "box").unwrap().trace();
    assert!(trace.counts.truncated);
    assert!(trace.segments.len() <= refraction_scene::MAX_SEGMENTS);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mangled_scene_files_are_refused_without_panicking(
        which in 0_usize..7, cut in 0.0_f64..1.0, junk in "[ -~\n]{0,8}"
    ) {
        let info = &catalogue()[which];
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("../refraction-scene/assets/scenes/{}.toml", info.name));
        let text = std::fs::read_to_string(path).unwrap();
        let mut at = (text.len() as f64 * cut) as usize;
        while !text.is_char_boundary(at) {
            at -= 1;
        }
        let mangled = format!("{}{junk}{}", &text[..at], &text[at..]);
        if let Err(e) = Scene::from_toml(&mangled, "mangled.toml", "m") {
            prop_assert!(e.to_string().starts_with("mangled.toml"));
        }
    }

    #[test]
    fn any_source_position_and_direction_traces_to_finite_points(
        which in 0_usize..7,
        x in -10.0_f64..10.0, y in -10.0_f64..10.0, angle in 0.0_f64..6.3,
    ) {
        let mut s = scene(catalogue()[which].name);
        s.set_source_origin(DVec2::new(x, y)).unwrap();
        s.set_source_direction(DVec2::from_angle(angle)).unwrap();
        let trace = s.trace();
        prop_assert!(trace.segments.iter().all(|g| g.from.is_finite() && g.to.is_finite()));
        prop_assert!(trace.hits.iter().all(|h| h.w.is_finite() && h.n.is_finite()));
    }
}

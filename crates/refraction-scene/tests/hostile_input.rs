//! Scene files as a careless or hostile user writes them: extreme but accepted numbers trace to
//! finite JSON, runaway traces stop at their budget and say so, and no bytes make the loader
//! panic or hang.
#![expect(
    clippy::unwrap_used,
    reason = "test helpers: a failed unwrap is a failed test, with its message"
)]

use std::path::Path;

use glam::DVec2;
use proptest::prelude::*;
use refraction_scene::{
    Budget, MAX_COORDINATE, Progress, Scene, Stop, Trace, TraceReport, catalogue,
};
use serde_json::Value;

/// A budget small enough for hundreds of traces in a test run.
const SMALL: Budget = Budget {
    segments: 5_000,
    tests: 500_000,
};

/// The keys under which the JSON may hold `null`: everything else must be a number, a string,
/// a boolean or a collection.
const MAY_BE_NULL: [&str; 6] = [
    "wavelength_nm",
    "intensities",
    "fresnel",
    "parent_hit",
    "medium",
    "stopped",
];

/// Every `null` in `value` that is not one of [`MAY_BE_NULL`]'s, by path.
fn misplaced_nulls(value: &Value, path: &str, found: &mut Vec<String>) {
    match value {
        Value::Null => found.push(path.to_owned()),
        Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                misplaced_nulls(item, &format!("{path}[{i}]"), found);
            }
        }
        Value::Object(fields) => {
            for (key, item) in fields {
                if !(item.is_null() && MAY_BE_NULL.contains(&key.as_str())) {
                    misplaced_nulls(item, &format!("{path}.{key}"), found);
                }
            }
        }
        Value::Bool(_) | Value::Number(_) | Value::String(_) => {}
    }
}

fn traced(scene: &Scene, budget: Budget) -> Trace {
    let mut trace = scene.trace();
    scene.retrace_within(&mut trace, budget, &Progress::default());
    trace
}

/// Why the trace of `scene` is not all finite numbers, if it is not: a `null` where a number
/// belongs in its JSON (`serde_json` writes NaN and infinity as `null`), or a hit whose W or N is
/// not unit length.
fn not_finite(scene: &Scene, budget: Budget) -> Option<String> {
    let trace = traced(scene, budget);
    let json = serde_json::to_value(TraceReport::new(scene, &trace)).ok()?;
    let mut found = Vec::new();
    misplaced_nulls(&json, "", &mut found);
    let off_unit = trace
        .hits
        .iter()
        .find(|h| (h.w.length() - 1.0).abs() > 1e-9 || (h.n.length() - 1.0).abs() > 1e-9);
    match (found.first(), off_unit) {
        (Some(path), _) => Some(format!("null at {path} ({} in all)", found.len())),
        (None, Some(hit)) => Some(format!("a hit with |W| or |N| off 1: {hit:?}")),
        (None, None) => None,
    }
}

fn load(text: &str) -> Scene {
    Scene::from_toml(text, "hostile.toml", "hostile").unwrap_or_else(|e| panic!("{e}\n{text}"))
}

const GLASS: &str = r#"
title = "Hostile but accepted"
background = "air"
[media.air]
index = 1.0
[media.glass]
index = 1.5
absorption = 1e300
[media.dense]
index = 99
[effects]
partial_reflection = true
fresnel = true
absorption = true
max_depth = 1000
min_intensity = 0
"#;

#[test]
fn extreme_but_accepted_numbers_trace_to_finite_json() {
    let scenes = [
        // A circle as large as the range allows, a beam as wide, a direction of huge numbers.
        r#"[[shapes]]
circle = { center = [100000, 100000], radius = 100000, medium = "glass" }
[source]
kind = "beam"
origin = [-100000, 100000]
direction = [1e300, -1e300]
width = 100000
rays = 50"#,
        // A lens whose thin surface bulges past its rim, its other radius the largest.
        r#"[[shapes]]
lens = { center = [0, 0], thickness = 1.9, radii = [100000, 1], medium = "dense" }
[source]
kind = "fan"
origin = [-3, 0.2]
direction = [1, 0]
spread_deg = 360
rays = 200"#,
        // The smallest circle at the corner of the range, with a fan around it.
        r#"[[shapes]]
circle = { center = [100000, -100000], radius = 1e-6, medium = "dense" }
[source]
kind = "fan"
origin = [99999.99999, -100000]
direction = [1, 0]
spread_deg = 30
rays = 400"#,
        // A sliver of a polygon across the whole range, a line with a tiny normal, a view at
        // the limits.
        r#"[[shapes]]
polygon = { points = [[-100000, -100000], [100000, -100000], [100000, -99999.99999]], medium = "glass" }
[[shapes]]
line = { point = [100000, 100000], normal = [1e-300, 1e-300], medium = "dense" }
[source]
kind = "fan"
origin = [0, 0]
direction = [0, -1]
spread_deg = 360
rays = 100
[view]
min = [-100000, -100000]
max = [100000, 100000]"#,
    ];
    for body in scenes {
        let scene = load(&format!("{GLASS}{body}"));
        assert!(scene.trace().counts.kernel_calls > 0, "{body}");
        let problem = not_finite(&scene, Budget::DEFAULT);
        assert!(problem.is_none(), "{body}: {problem:?}");
    }
}

/// The droplet's text moved by `offset` in x and y.
fn droplet_at(offset: f64) -> Scene {
    let text = Scene::embedded("droplet").unwrap().to_toml().unwrap();
    let moved = text
        .replace(
            "center = [0.0, 0.0]",
            &format!("center = [{offset:?}, {offset:?}]"),
        )
        .replace(
            "origin = [-2.5, 0.5]",
            &format!("origin = [{:?}, {:?}]", offset - 2.5, offset + 0.5),
        )
        .replace(
            "min = [-3.0, -2.5]",
            &format!("min = [{:?}, {:?}]", offset - 3.0, offset - 2.5),
        )
        .replace(
            "max = [3.0, 2.5]",
            &format!("max = [{:?}, {:?}]", offset + 3.0, offset + 2.5),
        );
    assert!(
        offset == 0.0 || moved != text,
        "the droplet's numbers are where this test expects them"
    );
    load(&moved)
}

#[test]
fn a_droplet_at_the_edge_of_the_range_traces_as_at_the_origin() {
    let home = droplet_at(0.0).trace().counts;
    let far = droplet_at(MAX_COORDINATE - 3.0).trace().counts;
    assert_eq!(far, home);
    let e = Scene::from_toml(
        &droplet_at(0.0)
            .to_toml()
            .unwrap()
            .replace("center = [0.0, 0.0]", "center = [1e8, 1e8]"),
        "far.toml",
        "far",
    )
    .unwrap_err();
    assert!(e.message.contains("within ±100000"), "{e}");
}

#[test]
fn a_runaway_trace_stops_at_its_budget_and_says_why() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/deep-droplet.toml");
    let scene = Scene::load(path).unwrap_or_else(|e| panic!("{e}"));
    let trace = traced(&scene, SMALL);
    assert!(trace.counts.truncated);
    assert_eq!(trace.counts.stopped, Some(Stop::Segments(SMALL.segments)));
    assert_eq!(trace.segments.len(), SMALL.segments);
    // A droplet's segment costs a few tests (its one piece, the media on both sides).
    let few_tests = Budget {
        tests: 2_000,
        ..SMALL
    };
    let trace = traced(&scene, few_tests);
    assert_eq!(trace.counts.stopped, Some(Stop::Tests(2_000)));
    let json = serde_json::to_value(TraceReport::new(&scene, &trace)).unwrap();
    let message = json["counts"]["stopped"].as_str().unwrap();
    assert!(
        message.contains("budget of 2000 intersection tests"),
        "{message}"
    );
    assert!(trace.counts.to_string().contains(message));
    let progress = Progress::default();
    progress.cancel();
    let mut cancelled = scene.trace();
    scene.retrace_within(&mut cancelled, Budget::DEFAULT, &progress);
    assert_eq!(cancelled.counts.stopped, Some(Stop::Cancelled));
    assert!(cancelled.segments.is_empty());
    let full = droplet_at(0.0);
    let progress = Progress::default();
    let mut trace = full.trace();
    full.retrace_within(&mut trace, Budget::DEFAULT, &progress);
    assert_eq!(progress.fraction(), 1.0);
    assert_eq!(trace.counts.stopped, None);
}

/// Values a careless or hostile user might put where a number stands.
const NUMBERS: [&str; 22] = [
    "1e308",
    "-1.7e308",
    "1e-320",
    "0",
    "-0",
    "nan",
    "inf",
    "-inf",
    "1e200",
    "1e-300",
    "100000",
    "-100000",
    "100001",
    "1e-6",
    "9e-7",
    "360",
    "1000",
    "100000000",
    "-1",
    "0.5",
    "[1, 2, 3]",
    "\"x\"",
];

/// Lines a careless or hostile user might add.
const LINES: [&str; 9] = [
    "[[shapes]]",
    "polygon = { points = [[0, 0], [2, 2], [2, 0], [0, 1]], medium = \"air\" }",
    "circle = { center = [0, 0, 1], radius = 1, medium = \"air\" }",
    "[effects]\npartial_reflection = true\nmax_depth = 1000\nmin_intensity = 0",
    "rays = 100000",
    "spread_deg = 360",
    "[view]\nmin = [0, 0]\nmax = [1e-7, 1e-7]",
    "lens = { center = [0, 0], thickness = 1.99999, radii = [1, 100000], medium = \"air\" }",
    "white = true",
];

/// Byte ranges of the numbers in `text` (a digit run with its sign, point and exponent).
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if starts {
            let start = if i > 0 && bytes[i - 1] == b'-' {
                i - 1
            } else {
                i
            };
            let mut end = i;
            while end < bytes.len()
                && (bytes[end].is_ascii_digit() || b".eE+-_".contains(&bytes[end]))
            {
                end += 1;
            }
            found.push((start, end));
            i = end;
        } else {
            i += 1;
        }
    }
    found
}

/// One edit of a scene file's text.
#[derive(Clone, Debug)]
enum Mutation {
    Number(prop::sample::Index, usize),
    DeleteLine(prop::sample::Index),
    DuplicateLine(prop::sample::Index),
    InsertLine(prop::sample::Index, usize),
    Cut(prop::sample::Index),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let index = any::<prop::sample::Index>;
    prop_oneof![
        3 => (index(), 0..NUMBERS.len()).prop_map(|(i, n)| Mutation::Number(i, n)),
        1 => index().prop_map(Mutation::DeleteLine),
        1 => index().prop_map(Mutation::DuplicateLine),
        2 => (index(), 0..LINES.len()).prop_map(|(i, l)| Mutation::InsertLine(i, l)),
        1 => index().prop_map(Mutation::Cut),
    ]
}

fn apply(text: &str, mutation: &Mutation) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let rejoin = |lines: Vec<&str>| format!("{}\n", lines.join("\n"));
    match mutation {
        Mutation::Number(at, value) => {
            let spans = numbers(text);
            if spans.is_empty() {
                return text.to_owned();
            }
            let (start, end) = *at.get(&spans);
            format!("{}{}{}", &text[..start], NUMBERS[*value], &text[end..])
        }
        Mutation::DeleteLine(at) if !lines.is_empty() => {
            let mut lines = lines.clone();
            lines.remove(at.index(lines.len()));
            rejoin(lines)
        }
        Mutation::DuplicateLine(at) if !lines.is_empty() => {
            let mut lines = lines.clone();
            let i = at.index(lines.len());
            lines.insert(i, lines[i]);
            rejoin(lines)
        }
        Mutation::InsertLine(at, line) => {
            let mut lines = lines.clone();
            lines.insert(at.index(lines.len() + 1), LINES[*line]);
            rejoin(lines)
        }
        Mutation::Cut(at) => {
            let mut end = at.index(text.len() + 1);
            while !text.is_char_boundary(end) {
                end -= 1;
            }
            text[..end].to_owned()
        }
        Mutation::DeleteLine(_) | Mutation::DuplicateLine(_) => text.to_owned(),
    }
}

fn built_in_text(which: usize) -> String {
    let name = catalogue()[which % catalogue().len()].name;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("assets/scenes/{name}.toml"));
    std::fs::read_to_string(path).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn arbitrary_bytes_are_refused_or_loaded_without_panicking(
        bytes in prop::collection::vec(any::<u8>(), 0..1500),
    ) {
        match Scene::from_bytes(&bytes, "bytes.toml", "b") {
            Ok(scene) => prop_assert_eq!(not_finite(&scene, SMALL), None),
            Err(e) => prop_assert!(e.to_string().starts_with("bytes.toml")),
        }
    }

    #[test]
    fn mutated_scene_files_load_or_are_refused_and_every_accepted_one_traces_finite(
        which in 0_usize..64,
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let text = mutations.iter().fold(built_in_text(which), |t, m| apply(&t, m));
        match Scene::from_toml(&text, "mutated.toml", "m") {
            Ok(scene) => {
                prop_assert_eq!(not_finite(&scene, SMALL), None, "{}", text);
                let written = scene.to_toml().unwrap();
                let back = Scene::from_toml(&written, "written.toml", "m");
                prop_assert_eq!(back.as_ref().ok(), Some(&scene), "{:?}\n{}", back.as_ref().err(), written);
            }
            Err(e) => {
                let shown = e.to_string();
                prop_assert!(shown.starts_with("mutated.toml:"), "{}", shown);
                prop_assert!(!shown.contains("element"), "serde's words: {}", shown);
            }
        }
    }
}

#[test]
fn a_moved_source_stays_within_the_range() {
    let mut scene = droplet_at(0.0);
    assert!(
        scene
            .set_source_origin(DVec2::splat(MAX_COORDINATE))
            .is_ok()
    );
    assert!(
        scene
            .set_source_origin(DVec2::new(MAX_COORDINATE * 2.0, 0.0))
            .is_err()
    );
    assert_eq!(not_finite(&scene, SMALL), None);
}

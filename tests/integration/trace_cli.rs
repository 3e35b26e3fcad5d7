//! The `trace` command end to end: built-in scenes and files, JSON, and one-line errors.

use std::process::{Command, Output};

use refraction_scene::catalogue;
use serde_json::Value;

fn trace(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("trace")
        .args(args)
        .output()
        .expect("the binary starts")
}

fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).unwrap()
}

#[test]
fn json_has_paths_hits_outlines_bounds_and_counts() {
    let output = trace(&["droplet", "--json"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let report: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(report["scene"], "droplet");
    let counts = &report["counts"];
    assert_eq!(counts["wavelengths"], 7);
    let paths = report["paths"].as_array().unwrap();
    assert_eq!(paths.len() as u64, counts["paths"].as_u64().unwrap());
    let first = &paths[0];
    let points = first["points"].as_array().unwrap();
    assert_eq!(points.len(), first["media"].as_array().unwrap().len() + 1);
    assert!(first["wavelength_nm"].is_number());
    assert!(first["intensities"][0].is_number());
    let hits = report["hits"].as_array().unwrap();
    assert_eq!(hits.len() as u64, counts["kernel_calls"].as_u64().unwrap());
    for field in ["point", "w", "n", "mu_i", "mu_t", "side", "fresnel"] {
        assert!(!hits[0][field].is_null(), "{field}");
    }
    assert_eq!(report["outlines"][0]["pieces"][0]["kind"], "circle");
    assert!(report["bounds"]["min"][0].as_f64().unwrap() < 0.0);
}

#[test]
fn without_a_scene_it_traces_the_single_interface() {
    let output = trace(&[]);
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(text.starts_with("Single interface (interface)"), "{text}");
    assert!(text.contains("kernel calls                1"), "{text}");
}

#[test]
fn list_names_every_built_in_scene() {
    let output = trace(&["--list"]);
    let text = String::from_utf8(output.stdout).unwrap();
    for name in catalogue().iter().map(|info| info.name) {
        assert!(text.lines().any(|l| l.starts_with(name)), "{name}: {text}");
    }
}

#[test]
fn a_broken_file_is_one_line_naming_file_line_and_column() {
    let folder = std::env::temp_dir().join(format!("trace-cli-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let file = folder.join("broken.toml");
    std::fs::write(
        &file,
        "title = \"broken\"\n[source]\nkind = \"ray\"\norigin = [0, 0]\ndirection = [1, 0]\n\
         [[shapes]]\ncircle = { center = [0, 0], radius = -1, medium = \"vacuum\" }\n",
    )
    .unwrap();
    let output = trace(&[file.to_str().unwrap(), "--json"]);
    std::fs::remove_dir_all(&folder).unwrap();
    assert_eq!(output.status.code(), Some(1));
    assert!(output.stdout.is_empty());
    let message = stderr(&output);
    assert_eq!(message.lines().count(), 1, "{message}");
    assert!(
        // At the value itself (line 7, column 38), not at the [[shapes]] header above it.
        message.contains("broken.toml:7:38: a circle's `radius` is -1"),
        "{message}"
    );
}

#[test]
fn an_unknown_scene_lists_the_built_in_ones() {
    let output = trace(&["rainbow"]);
    assert_eq!(output.status.code(), Some(1));
    let message = stderr(&output);
    assert!(
        message.contains("rainbow: cannot read") && message.contains("droplet"),
        "{message}"
    );
}

#[test]
fn a_trace_that_stops_at_its_budget_says_why() {
    // The JSON's `counts.stopped` is tested on a small budget in the scene crate: here the
    // default budget, which one million segments of JSON would make slow to read back.
    let scene = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/refraction-scene/tests/data/deep-droplet.toml"
    );
    let output = trace(&[scene]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        text.contains("the trace stopped at its budget of 1000000 segments"),
        "{text}"
    );
    let finished: Value = serde_json::from_slice(&trace(&["droplet", "--json"]).stdout).unwrap();
    assert!(finished["counts"]["stopped"].is_null());
    assert_eq!(finished["counts"]["truncated"], false);
}

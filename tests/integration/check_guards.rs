//! `check`'s guards and options end to end, for issues 40 and 45: what `--summary` and
//! `--tests` may replace, options beside `--suggest-pattern`, and option values refused before
//! a line is read.

use std::process::{Command, Output};

use crate::cli;

/// smallpt's lines (docs/examples/smallpt.log's form): one right, one with the outward normal.
const SMALLPT: &str = "REFR d=(0.642788 -0.766044 0.000000) nl=(0.000000 1.000000 0.000000) \
                       into=1 tdir=(0.428525 -0.903530 0.000000)\n";

/// Runs the binary with `args` in `folder`.
fn run_in(folder: &std::path::Path, args: &[&str], input: &str) -> Output {
    use std::io::Write as _;
    let mut child = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .args(args)
        .current_dir(folder)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    child.wait_with_output().unwrap()
}

#[test]
fn suggest_pattern_carries_the_other_options_into_its_command() {
    // Issue 45: --suggest-pattern ignored --tests, --inside, --renderer and others in silence.
    let output = cli::run(
        &[
            "check",
            "--suggest-pattern",
            "--inside",
            "1.5",
            "--outside",
            "1",
            "--renderer",
            "smallpt",
            "--precision",
            "f32",
            "--normal",
            "0 1 0",
            "--summary",
            "my summary.json",
            "--tests",
            "it's.cpp",
        ],
        SMALLPT,
    );
    assert_eq!(output.status.code(), Some(0), "{output:?}");
    let command = String::from_utf8_lossy(&output.stdout);
    for part in [
        "refraction-explorer check --inside 1.5 --outside 1 --precision f32 --renderer smallpt \
         --pattern 'd={w} nl={n} into={entering} tdir={t_yours}'",
        "--normal '0 1 0' --summary 'my summary.json' --tests 'it'\\''s.cpp' ",
    ] {
        assert!(command.contains(part), "{part}\n{command}");
    }
    // What cannot be carried is refused, never dropped.
    for other in [["--pattern", "{w}"], ["--csv", "--strict"]] {
        let output = cli::run(&["check", "--suggest-pattern", other[0], other[1]], SMALLPT);
        assert_eq!(output.status.code(), Some(2), "{other:?}: {output:?}");
    }
}

#[test]
fn a_summary_with_its_keys_in_another_order_is_still_ours() {
    // Issue 45: a summary was known only by serde_json's sorted keys.
    let folder = cli::folder("check-guards", "summary-keys");
    let reordered = r#"{"lines": 1, "judged": 1, "ok": 1, "skipped": 0, "sampled": 0,
        "diagnosis": [{"code": "none", "lines": 1, "where": "", "fix": ""}]}"#;
    std::fs::write(folder.join("s.json"), reordered).unwrap();
    let args = [
        "check",
        "--inside",
        "1.5",
        "--outside",
        "1",
        "--summary",
        "s.json",
        "--pattern",
        "REFR d={w} nl={n} into={entering} tdir={t_yours}",
    ];
    let output = run_in(&folder, &args, SMALLPT);
    assert_ne!(output.status.code(), Some(2), "{output:?}");
    let written = std::fs::read_to_string(folder.join("s.json")).unwrap();
    assert!(
        written.starts_with(r#"{"lines":1,"judged":1,"#),
        "{written}"
    );
    std::fs::write(folder.join("s.json"), r#"{"lines": 1, "notes": "mine"}"#).unwrap();
    let output = run_in(&folder, &args, SMALLPT);
    assert_eq!(output.status.code(), Some(2), "{output:?}");
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(said.contains("something other than a summary"), "{said}");
}

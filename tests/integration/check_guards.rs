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
    // A run refused before it reads closes its input: then the write fails, which is what
    // the test expects of it, so the failure is dropped.
    child.stdin.take().unwrap().write_all(input.as_bytes()).ok();
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

/// The book's log line (docs/examples/rtiow.log's form), right.
const RTIOW: &str = "LOG 0.642788 -0.766044 0 | 0 1 0 | 0.666667 | 0.428525 -0.90353 0 | 1\n";
const RTIOW_PATTERN: &str = "LOG {uv} | {n} | {etai_over_etat} | {refracted} | {entering}";

#[test]
fn option_values_are_refused_before_a_line_is_read() {
    // Issue 40: `--normal -z` and `--inside -1` were "unexpected arguments"; `--inside 1e308`
    // failed every line; `--normal '5e-324 0 0'` read every ray as entering.
    let output = cli::run(
        &["check", "--normal", "-z", "--pattern", "{w} {t_yours}"],
        "",
    );
    let said = String::from_utf8_lossy(&output.stderr);
    assert!(!said.contains("unexpected argument"), "{said}");
    let output = cli::run(&["check", "--inside", "-1", "--outside", "1"], "");
    let said = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        said.contains("must be a finite number > 0, not -1"),
        "{said}"
    );
    for (inside, precision) in [("1e308", "f64"), ("1e20", "f32")] {
        let args = [
            "check",
            "--api",
            "rtiow",
            "--precision",
            precision,
            "--inside",
            inside,
        ];
        let mut args = args.to_vec();
        args.extend(["--outside", "1", "--pattern", RTIOW_PATTERN]);
        let output = cli::run(&args, RTIOW);
        let said = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{inside}: {said}");
        assert!(said.contains(&format!("--inside {inside}")), "{said}");
        assert!(output.stdout.is_empty(), "no line is read");
    }
    let output = cli::run(
        &[
            "check",
            "--normal",
            "5e-324 0 0",
            "--pattern",
            "{w} {t_yours}",
        ],
        "",
    );
    let said = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{said}");
    assert!(said.contains("too short"), "{said}");
}

#[test]
fn one_file_for_summary_and_tests_is_refused() {
    // Issue 40: `--summary X --tests X` wrote the tests and lost the summary in silence.
    let folder = cli::folder("check-guards", "twice");
    let args = [
        "check",
        "--api",
        "rtiow",
        "--inside",
        "1.5",
        "--outside",
        "1",
        "--pattern",
        RTIOW_PATTERN,
        "--summary",
        "t.cpp",
        "--tests",
        "./t.cpp",
    ];
    let output = run_in(&folder, &args, RTIOW);
    let said = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{said}");
    assert!(said.contains("--summary and --tests both name"), "{said}");
    assert!(!folder.join("t.cpp").exists());
}

#[cfg(unix)]
#[test]
fn tests_never_go_to_a_pipe_a_device_or_an_unreadable_place() {
    // Issue 40: a FIFO hung the run; a link to /dev/zero read until memory ran out.
    let folder = cli::folder("check-guards", "targets");
    let fifo = folder.join("fifo.cpp");
    if !fifo.exists() {
        assert!(
            Command::new("mkfifo")
                .arg(&fifo)
                .status()
                .unwrap()
                .success()
        );
    }
    let zero = folder.join("zero.cpp");
    if !zero.exists() {
        std::os::unix::fs::symlink("/dev/zero", &zero).unwrap();
    }
    for target in ["fifo.cpp", "zero.cpp"] {
        let args = [
            "check",
            "--inside",
            "1.5",
            "--outside",
            "1",
            "--tests",
            target,
        ];
        let output = run_in(&folder, &args, "");
        let said = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{target}: {said}");
        assert!(said.contains("not a regular file"), "{said}");
    }
}

#[test]
fn a_right_line_beside_an_unreadable_one_is_not_a_pass_anywhere() {
    // Issue 40: exit 1, but the summary's verdict was `none` and stderr said "No mistake".
    let folder = cli::folder("check-guards", "unreadable");
    let log = format!("{RTIOW}LOG 0 0 0 | 0 1 0 | 0.666667 | 0.4 -0.9 0 | 1\n");
    let args = [
        "check",
        "--api",
        "rtiow",
        "--inside",
        "1.5",
        "--outside",
        "1",
        "--pattern",
        RTIOW_PATTERN,
        "--summary",
        "s.json",
    ];
    let output = run_in(&folder, &args, &log);
    let said = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{said}");
    assert!(!said.contains("No mistake"), "{said}");
    assert!(said.contains("could not be read"), "{said}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(folder.join("s.json")).unwrap()).unwrap();
    assert_eq!(summary["diagnosis"][0]["code"], "unreadable", "{summary}");
}

#[test]
fn suggest_pattern_reads_json_lines_and_pbrt_s_eta_as_they_are() {
    // Issue 40: JSON Lines got pattern advice; pbrt's eta (inside over outside) was read as μ.
    let json = r#"{"I":[0.6,-0.8,0],"N":[0,1,0],"eta":0.666667,"result":[0.4,-0.916515,0]}"#;
    let output = cli::run(&["check", "--api", "glsl", "--suggest-pattern"], json);
    let (out, said) = (
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr),
    );
    assert_eq!(output.status.code(), Some(0), "{said}");
    assert!(
        out.starts_with("refraction-explorer check --api glsl /"),
        "{out}"
    );
    assert!(!out.contains("--pattern"), "{out}");
    assert!(said.contains("needs no pattern"), "{said}");
    let pbrt = "Refract wi=[ -0.6, 0.8, 0 ] n=[ 0, 1, 0 ] eta=1.5 -> wt=[ 0.4, -0.916515, 0 ]\n";
    let output = cli::run(&["check", "--suggest-pattern"], pbrt);
    let out = String::from_utf8_lossy(&output.stdout);
    assert!(out.contains("eta={_}"), "{out}");
}

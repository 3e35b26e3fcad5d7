//! `check --api` end to end: answers in the API's terms, the tally of mistakes by code on
//! stderr, the exit status, `--pattern` with `--strict`, and CSV.

use crate::cli;

use cli::{answers, run};

#[test]
fn glsl_lines_are_answered_with_the_api_result_and_a_tally_by_code() {
    let input = [
        // Right: air into glass at 40 degrees.
        r#"{"I":[0.642788,-0.766044,0],"N":[0,1,0],"eta":0.666667,"result":[0.428525,-0.90353,0],"from":1,"to":1.5}"#,
        // eta upside down, as GLSL computes it.
        r#"{"I":[0.3,-0.953939,0],"N":[0,1,0],"eta":1.5,"result":"vec3(0.45, -0.893029, 0)","from":1,"to":1.5}"#,
        // Past the critical angle: GLSL returns zero, the code normalised it.
        r#"{"I":[0.8,0.6,0],"N":[0,-1,0],"eta":1.5,"result":[null,null,null]}"#,
        r#"{"I":[1,0,0]}"#,
    ]
    .join("\n");
    let output = run(&["check", "--api", "hlsl"], &input);
    assert_eq!(output.status.code(), Some(1));
    let a = answers(&output);
    assert_eq!(a.len(), 4);
    assert_eq!(
        (a[0]["ok"].clone(), a[0]["mistakes"].clone()),
        (true.into(), serde_json::json!([]))
    );
    assert_eq!(a[1]["mistakes"], serde_json::json!(["eta_inverted"]));
    assert_eq!(a[1]["api_result"].as_array().unwrap().len(), 3);
    assert_eq!(a[2]["mistakes"], serde_json::json!(["missed_tir"]));
    assert_eq!(a[2]["api_result"], serde_json::json!([0.0, 0.0, 0.0]));
    assert_eq!(a[3]["line"], 4);
    assert!(
        a[3]["error"]
            .as_str()
            .unwrap()
            .contains("missing field `N`")
    );
    let tally = String::from_utf8_lossy(&output.stderr);
    for part in ["1 ok", "1 eta_inverted", "1 missed_tir", "1 unreadable"] {
        assert!(tally.contains(part), "{tally}");
    }
}

#[test]
fn a_right_pbrt_call_exits_zero_and_bad_names_are_refused() {
    let line = r#"{"wi":[-0.642788,0.766044,0],"n":[0,1,0],"eta":1.5,"returned":true,"wt":[0.428525,-0.90353,0],"entering":true}"#;
    let output = run(
        &[
            "check",
            "--api",
            "pbrt",
            "--inside",
            "1.5",
            "--outside",
            "1",
        ],
        line,
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stdout)
    );
    let refused = run(&["check", "--api", "optix"], "");
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("expected glsl"));
    let lonely = run(&["check", "--api", "pbrt", "--inside", "1.5"], "");
    assert_eq!(lonely.status.code(), Some(2));
}

const RTIOW_LOG: &str = "render start\n\
LOG 0.642788 -0.766044 0 | 0 1 0 | 0.666667 | 0.428525 -0.90353 0 | 1\n\
sky hit\n\
LOG vec3(0.642788, -0.766044, 0) | vec3(0, 1, 0) | 1.5 | vec3(0.964182, -0.265242, 0) | true\n";

const RTIOW_PATTERN: &str = "LOG {uv} | {n} | {etai_over_etat} | {refracted} | {entering}";

#[test]
fn a_printf_log_is_read_with_a_pattern_and_its_other_lines_skipped() {
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
    ];
    let output = run(&args, RTIOW_LOG);
    let a = answers(&output);
    assert_eq!(a.len(), 2, "{a:?}");
    assert_eq!(a[0]["ok"], true);
    assert_eq!(a[1]["mistakes"], serde_json::json!(["eta_inverted"]));
    let tally = String::from_utf8_lossy(&output.stderr);
    assert!(
        tally.contains("2 skipped (not matching the pattern)"),
        "{tally}"
    );
    let strict = run(&[&args[..], &["--strict"]].concat(), RTIOW_LOG);
    let a = answers(&strict);
    assert_eq!(a.len(), 4);
    assert_eq!(a[0]["line"], 1);
    assert!(
        a[0]["error"]
            .as_str()
            .unwrap()
            .contains("does not match the pattern")
    );
    assert_eq!(strict.status.code(), Some(1));
    let bad = run(&["check", "--api", "rtiow", "--pattern", "LOG {I}"], "");
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown field {I}"));
}

#[test]
fn a_csv_log_is_read_by_its_header() {
    let csv = "step,I.x,I.y,I.z,N,eta,result,from,to\n\
               1,0.642788,-0.766044,0,\"0, 1, 0\",0.666667,\"0.428525, -0.90353, 0\",1,1.5\n\
               2,0.642788,-0.766044,0,\"0, -1, 0\",0.666667,\"0.428525, 0.90353, 0\",1,1.5\n";
    let output = run(&["check", "--api", "glsl", "--csv"], csv);
    let a = answers(&output);
    assert_eq!(a.len(), 2, "{a:?}");
    assert_eq!(a[0]["ok"], true, "{}", a[0]);
    assert_eq!(a[1]["mistakes"][0], "normal_not_facing", "{}", a[1]);
    let headless = run(&["check", "--api", "glsl", "--csv"], "I,eta\n1 2 3,1.5\n");
    let a = answers(&headless);
    assert!(a[0]["error"].as_str().unwrap().contains("no column `N`"));
    assert!(
        a[1]["error"]
            .as_str()
            .unwrap()
            .contains("no usable CSV header")
    );
}

#[test]
fn tests_writes_the_failing_lines_as_tests_and_never_over_other_code() {
    // Issue 35: `check` writes the failing lines as tests, as the window's log section does.
    let folder = cli::folder("check-tests", "glsl");
    let tests = folder.join("regressions.glsl");
    let tests_arg = tests.to_str().unwrap();
    let input = [
        r#"{"I":[0.642788,-0.766044,0],"N":[0,1,0],"eta":0.666667,"result":[0.428525,-0.90353,0],"from":1,"to":1.5}"#,
        r#"{"I":[0.3,-0.953939,0],"N":[0,1,0],"eta":1.5,"result":"vec3(0.45, -0.893029, 0)","from":1,"to":1.5}"#,
    ]
    .join("\n");
    let output = run(&["check", "--api", "glsl", "--tests", tests_arg], &input);
    assert_eq!(output.status.code(), Some(1));
    let written = std::fs::read_to_string(&tests).unwrap();
    assert!(
        written.starts_with("// Regression tests written by refraction-explorer: the first 1 "),
        "{written}"
    );
    assert!(written.contains("line_2"), "{written}");
    assert!(
        !written.contains("line_1"),
        "only the failing line: {written}"
    );
    let tally = String::from_utf8_lossy(&output.stderr);
    assert!(
        tally.contains("1 failing line written as tests to"),
        "{tally}"
    );
    // Run again: the file is one of ours, so it is replaced.
    let again = run(&["check", "--api", "glsl", "--tests", tests_arg], &input);
    assert_eq!(again.status.code(), Some(1));
    // The student's own code is never written over, and a name must say the language.
    std::fs::write(&tests, "void main() {}\n").unwrap();
    let refused = run(&["check", "--api", "glsl", "--tests", tests_arg], &input);
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        answers(&refused).is_empty(),
        "refused before any line is read"
    );
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("is not a test file this tool wrote")
    );
    assert_eq!(std::fs::read_to_string(&tests).unwrap(), "void main() {}\n");
    let other = folder.join("t.rs");
    let refused = run(
        &["check", "--api", "glsl", "--tests", other.to_str().unwrap()],
        &input,
    );
    assert_eq!(refused.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("name a .glsl or .py file"),
        "{}",
        String::from_utf8_lossy(&refused.stderr)
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

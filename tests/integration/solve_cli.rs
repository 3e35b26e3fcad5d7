//! The `solve` command end to end: the binary reading JSON Lines on stdin.

use std::io::Write as _;
use std::process::{Command, Stdio};

use serde_json::Value;

/// `refraction-explorer solve` started with its stdin and stdout piped.
fn solve_process() -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("solve")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("the binary starts")
}

/// Runs `refraction-explorer solve` on `input`; returns the exit code and the parsed lines.
fn solve(input: &str) -> (i32, Vec<Value>) {
    let mut child = solve_process();
    let mut stdin = child.stdin.take().unwrap();
    let text = input.to_owned();
    let writer = std::thread::spawn(move || stdin.write_all(text.as_bytes()));
    let output = child.wait_with_output().unwrap();
    writer.join().unwrap().unwrap();
    let lines = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).expect("every output line is JSON"))
        .collect();
    (output.status.code().unwrap(), lines)
}

#[test]
fn a_textbook_refraction_answers_every_field() {
    let (code, lines) = solve(r#"{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#);
    assert_eq!(code, 0);
    let answer = &lines[0];
    let t: Vec<f64> = serde_json::from_value(answer["t"].clone()).unwrap();
    assert!((t[0] - 0.4).abs() < 1e-15 && (t[1] + 0.84_f64.sqrt()).abs() < 1e-15);
    assert_eq!(answer["tir"], false);
    assert_eq!(answer["normal_flipped"], false);
    assert_eq!(answer["warnings"], serde_json::json!([]));
    for field in ["reflected", "a", "b", "k", "cos_i", "cos_t"] {
        assert!(!answer[field].is_null(), "{field}");
    }
    let candidates = answer["candidates"].as_array().unwrap();
    assert_eq!(candidates.len(), 4);
    let chosen: Vec<_> = candidates.iter().filter(|c| c["chosen"] == true).collect();
    assert_eq!(chosen.len(), 1);
    assert_eq!(chosen[0]["t"], answer["t"]);
    let mut rules: Vec<_> = candidates
        .iter()
        .filter_map(|c| c["rejected_because"].as_str())
        .collect();
    rules.sort_unstable();
    assert_eq!(rules, ["reversed", "wrong_bend", "wrong_side"]);
}

#[test]
fn tir_flipped_normals_conventions_and_precision() {
    let input = [
        r#"{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}"#,
        r#"{"w":[0.6,0.8,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}"#,
        r#"{"w":[-0.6,0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"convention":"toward_origin"}"#,
        r#"{"w":[0.6,-0.8,0],"n":[0,2,0],"mu_i":1,"mu_t":1.5,"precision":"f32"}"#,
    ]
    .join("\n");
    let (code, lines) = solve(&input);
    assert_eq!(code, 0);
    assert_eq!(lines[0]["tir"], true);
    assert!(lines[0]["t"].is_null() && lines[0]["candidates"] == serde_json::json!([]));
    assert_eq!(lines[0]["reflected"], serde_json::json!([0.8, 0.6, 0.0]));
    assert_eq!(lines[1]["normal_flipped"], true);
    assert!(lines[1]["warnings"][0].as_str().unwrap().contains("-n"));
    assert_eq!(lines[2]["a"], -1.0 / 1.5);
    assert_eq!(lines[3]["precision"], "f32");
    assert!(
        lines[3]["warnings"][0]
            .as_str()
            .unwrap()
            .starts_with("n has length 2")
    );
}

#[test]
fn every_bad_line_is_answered_and_the_run_goes_on() {
    let good = r#"{"w":[0,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#;
    let bad = [
        ("{not json", "malformed JSON"),
        ("42", "expected a JSON object"),
        (r#"{"n":[0,1,0],"mu_i":1,"mu_t":1}"#, "missing field `w`"),
        (
            r#"{"w":"up","n":[0,1,0],"mu_i":1,"mu_t":1}"#,
            "`w` must be an array",
        ),
        (
            r#"{"w":[0,1],"n":[0,1,0],"mu_i":1,"mu_t":1}"#,
            "exactly 3 numbers",
        ),
        (
            r#"{"w":[0,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#,
            "zero vector",
        ),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":-1,"mu_t":1}"#,
            "mu_i is -1",
        ),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":1,"mu_t":"x"}"#,
            "`mu_t` must be a number",
        ),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1,"convention":1}"#,
            "`convention` must be a string",
        ),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1,"precision":"f16"}"#,
            "unknown precision",
        ),
    ];
    let mut input = String::new();
    for (line, _) in &bad {
        input.push_str(line);
        input.push('\n');
        input.push_str(good);
        input.push_str("\n\n");
    }
    let (code, lines) = solve(&input);
    assert_eq!(code, 1);
    assert_eq!(lines.len(), 2 * bad.len());
    for (i, (_, expected)) in bad.iter().enumerate() {
        let error = &lines[2 * i];
        assert_eq!(error["line"], 3 * i + 1, "{error}");
        assert!(
            error["error"].as_str().unwrap().contains(expected),
            "{error} lacks {expected}"
        );
        assert_eq!(lines[2 * i + 1]["tir"], false);
    }
}

#[test]
fn many_lines_stream_in_order() {
    let count = 20_000;
    let mut input = String::new();
    for i in 0..count {
        let x = f64::from(i) / 1000.0;
        input.push_str(&format!(
            "{{\"w\":[{x},-1,0],\"n\":[0,1,0],\"mu_i\":1,\"mu_t\":1.5}}\n"
        ));
    }
    let (code, lines) = solve(&input);
    assert_eq!(code, 0);
    assert_eq!(lines.len(), count as usize);
    let xs: Vec<f64> = lines.iter().map(|l| l["t"][0].as_f64().unwrap()).collect();
    assert!(xs.windows(2).all(|p| p[0] < p[1]), "answers out of order");
}

#[test]
fn fresnel_fractions_and_special_angles_in_both_precisions() {
    // W at Brewster's angle from air into glass (tanθi = 1.5; W need not be unit), then glass
    // to air at 30° (below the critical angle) and at 45° (beyond it).
    let input = [
        r#"{"w":[1.5,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#,
        r#"{"w":[1.5,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"precision":"f32"}"#,
        r#"{"w":[0.5,-0.8660254037844386,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}"#,
        r#"{"w":[1,-1,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1}"#,
    ]
    .join("\n");
    let (code, lines) = solve(&input);
    assert_eq!(code, 0);
    let share = |line: &Value, name: &str| line["fresnel"][name].as_f64().unwrap();
    for brewster in &lines[..2] {
        assert!(share(brewster, "r_p") < 1e-12, "{brewster}");
        assert!((share(brewster, "r_s") - 0.1479).abs() < 1e-4, "{brewster}");
        let angle = brewster["brewster_deg"].as_f64().unwrap();
        assert!((angle - 1.5_f64.atan().to_degrees()).abs() < 1e-4);
        assert!(brewster["critical_deg"].is_null());
    }
    for line in &lines[2..] {
        for (r, t) in [("r_s", "t_s"), ("r_p", "t_p")] {
            assert!(
                (share(line, r) + share(line, t) - 1.0).abs() < 1e-15,
                "{line}"
            );
        }
        let critical = line["critical_deg"].as_f64().unwrap();
        assert!((critical - (1.0_f64 / 1.5).asin().to_degrees()).abs() < 1e-12);
    }
    assert!(share(&lines[2], "t_s") > 0.8 && lines[2]["tir"] == false);
    assert_eq!(
        (share(&lines[3], "r_s"), share(&lines[3], "t_p")),
        (1.0, 0.0)
    );
}

#[test]
fn a_line_piped_in_is_answered_before_the_input_ends() {
    use std::io::{BufRead as _, BufReader};
    let mut child = solve_process();
    let mut stdin = child.stdin.take().unwrap();
    let mut answers = BufReader::new(child.stdout.take().unwrap());
    // As a renderer's log arrives: one line, then a pause with the pipe still open.
    for mu_t in ["1.5", "1.33"] {
        writeln!(
            stdin,
            r#"{{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":{mu_t}}}"#
        )
        .unwrap();
        stdin.flush().unwrap();
        let mut answer = String::new();
        answers.read_line(&mut answer).unwrap();
        let value: Value = serde_json::from_str(&answer).unwrap();
        assert_eq!(value["tir"], false, "{answer}");
    }
    drop(stdin);
    assert_eq!(child.wait().unwrap().code(), Some(0));
}

//! The `check` command end to end on a file mixing right, wrong and malformed lines, with the
//! wrong answers produced by the very mistakes the explanations name.

use std::process::Command;

use glam::DVec3;
use refraction_kernel::{Convention, seed};
use serde_json::{Value, json};

fn line(w: DVec3, n: DVec3, mu_i: f64, mu_t: f64, convention: &str, yours: &Value) -> String {
    json!({"w": w.to_array(), "n": n.to_array(), "mu_i": mu_i, "mu_t": mu_t,
           "convention": convention, "t_yours": yours})
    .to_string()
}

#[test]
fn check_names_each_mistake_and_goes_on_past_bad_lines() {
    let d = DVec3::new(0.6, -0.8, 0.0);
    let up = DVec3::Y;
    // Leaving glass upward through the outward normal, which the literal formula does not flip.
    let leaving = DVec3::new(0.3, (1.0_f64 - 0.09).sqrt(), 0.0);
    let outward_bug = seed::refract(leaving, up, 1.5_f64, Convention::AlongRay).unwrap();
    // W points back to the origin, but the code uses Section 2's along-the-ray formula.
    let mixed_conventions = seed::refract(-d, up, 1.0_f64 / 1.5, Convention::AlongRay).unwrap();
    let right = seed::refract(d, up, 1.0_f64 / 1.5, Convention::AlongRay).unwrap();
    let steep = DVec3::new(0.3, -(1.0_f64 - 0.09).sqrt(), 0.0);
    let swapped_ratio = seed::refract(steep, up, 1.5_f64, Convention::AlongRay).unwrap();
    // Glass to air at 53°: past the critical angle (41.8°).
    let tir = |yours: &Value| line(DVec3::new(0.8, -0.6, 0.0), up, 1.5, 1.0, "along_ray", yours);
    let lines = [
        (
            line(d, up, 1.0, 1.5, "along_ray", &json!(right.to_array())),
            Some("chosen"),
            true,
        ),
        (
            line(
                leaving,
                up,
                1.5,
                1.0,
                "along_ray",
                &json!(outward_bug.to_array()),
            ),
            Some("wrong_side"),
            false,
        ),
        (
            line(
                -d,
                up,
                1.0,
                1.5,
                "toward_origin",
                &json!(mixed_conventions.to_array()),
            ),
            Some("wrong_bend"),
            false,
        ),
        (
            line(d, up, 1.0, 1.5, "along_ray", &json!((-right).to_array())),
            Some("reversed"),
            false,
        ),
        (
            line(
                steep,
                up,
                1.0,
                1.5,
                "along_ray",
                &json!(format!(
                    "vec3({}, {}, {})",
                    swapped_ratio.x, swapped_ratio.y, swapped_ratio.z
                )),
            ),
            None,
            false,
        ),
        (tir(&json!([null, null, null])), None, false),
        (
            tir(&json!([0.8, 0.6, 0.0])),
            Some("total_internal_reflection"),
            true,
        ),
        (
            line(
                d,
                up,
                1.0,
                1.5,
                "along_ray",
                &json!((right * 2.0).to_array()),
            ),
            Some("chosen"),
            false,
        ),
    ];
    let mut input: String = lines
        .iter()
        .flat_map(|(l, _, _)| [l.as_str(), "\n"])
        .collect();
    input.push_str("{\"w\":[1,0,0]}\nnot json\n");
    let path = std::env::temp_dir().join(format!("check-{}.jsonl", std::process::id()));
    std::fs::write(&path, input).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("check")
        .arg(&path)
        .output()
        .unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(output.status.code(), Some(1));
    let answers: Vec<Value> = String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), lines.len() + 2);
    for ((_, matches, ok), answer) in lines.iter().zip(&answers) {
        assert_eq!(answer["matches"].as_str(), *matches, "{answer}");
        assert_eq!(answer["ok"], *ok, "{answer}");
        assert!(!answer["explanation"].as_str().unwrap().is_empty());
    }
    assert!(
        answers[4]["explanation"]
            .as_str()
            .unwrap()
            .contains("index ratio upside down")
    );
    assert!(
        answers[5]["explanation"]
            .as_str()
            .unwrap()
            .contains("square root of a negative k")
    );
    assert_eq!(answers[lines.len()]["line"], lines.len() + 1);
    assert!(
        answers[lines.len()]["error"]
            .as_str()
            .unwrap()
            .contains("missing field `n`")
    );
    assert_eq!(answers[lines.len() + 1]["line"], lines.len() + 2);
    let summary = String::from_utf8(output.stderr).unwrap();
    for expected in [
        "2 ok",
        "1 wrong_side",
        "1 wrong_bend",
        "1 reversed",
        "2 unreadable",
        "1 not unit length",
    ] {
        assert!(
            summary.contains(expected),
            "summary {summary:?} lacks {expected}"
        );
    }
}

#[test]
fn a_file_of_right_answers_exits_zero() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("check")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write as _;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(br#"{"w":[0,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"t_yours":"0, -1, 0"}"#)
        .unwrap();
    let output = child.wait_with_output().unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

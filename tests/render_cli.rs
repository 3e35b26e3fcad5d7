//! The `render` command end to end: a PNG of the diagram without a window.

use std::path::PathBuf;
use std::process::{Command, Output};

fn folder(name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("render-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("render")
        .args(args)
        .output()
        .expect("the binary starts")
}

#[test]
fn a_state_file_renders_at_the_requested_size() {
    let folder = folder("ok");
    let state = folder.join("state.json");
    std::fs::write(
        &state,
        r#"{"w":[0.5,0.8660254037844386,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"convention":"along_ray"}"#,
    )
    .unwrap();
    let out = folder.join("tir.png");
    let output = render(&[
        "--out",
        out.to_str().unwrap(),
        "--width",
        "640",
        "--height",
        "360",
        "--state",
        state.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{output:?}");
    let png = tiny_skia::Pixmap::load_png(&out).unwrap();
    assert_eq!((png.width(), png.height()), (640, 360));
    assert_eq!(
        std::fs::read_dir(&folder).unwrap().count(),
        2,
        "no temporary left"
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn bad_input_is_one_clear_line_and_a_non_zero_exit() {
    let folder = folder("bad");
    let state = folder.join("state.json");
    std::fs::write(&state, r#"{"w":[0,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#).unwrap();
    let out = folder.join("x.png");
    let out = out.to_str().unwrap();
    for (args, message) in [
        (
            vec!["--out", out, "--state", state.to_str().unwrap()],
            "w is the zero vector",
        ),
        (
            vec!["--out", out, "--state", "/nonexistent/state.json"],
            "cannot read state file /nonexistent/state.json",
        ),
        (vec!["--out", out, "--width", "0"], "0×1080 is not allowed"),
        (
            vec!["--out", "/nonexistent-folder/x.png"],
            "/nonexistent-folder/x.png",
        ),
    ] {
        let output = render(&args);
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(
            stderr.starts_with("refraction-explorer render: "),
            "{stderr}"
        );
        assert!(stderr.contains(message), "{stderr}");
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
    }
    assert!(!folder.join("x.png").exists());
    std::fs::remove_dir_all(&folder).unwrap();
}

//! The `render` command end to end: a PNG of the diagram or of a traced scene without a window.

use crate::cli;

use cli::render;
use std::path::PathBuf;

use refraction_diagram::wavelength_colour;

fn folder(name: &str) -> PathBuf {
    cli::folder("render-cli", name)
}

/// Runs `render` with `args` and checks it fails with exit status 2 and one line on stderr,
/// naming the command and containing `message`.
fn fails_in_one_line(args: &[&str], message: &str) {
    let output = render(args);
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(output.status.code(), Some(2), "{args:?}");
    assert!(
        stderr.starts_with("refraction-explorer render: "),
        "{stderr}"
    );
    assert!(stderr.contains(message), "{message}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
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
        fails_in_one_line(&args, message);
    }
    assert!(!folder.join("x.png").exists());
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_scene_renders_with_its_rays_in_their_wavelengths_colours() {
    let folder = folder("scene");
    let out = folder.join("prism.png");
    let output = render(&[
        "dispersing-prism",
        "--out",
        out.to_str().unwrap(),
        "--width",
        "800",
        "--height",
        "500",
    ]);
    assert!(output.status.success(), "{output:?}");
    let png = tiny_skia::Pixmap::load_png(&out).unwrap();
    assert_eq!((png.width(), png.height()), (800, 500));
    let red = wavelength_colour(700.0);
    let violet = wavelength_colour(400.0);
    for colour in [red, violet] {
        let count = png
            .pixels()
            .iter()
            .filter(|p| (p.red(), p.green(), p.blue()) == (colour.r, colour.g, colour.b))
            .count();
        assert!(count > 20, "{count} pixels of {colour:?}");
    }
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 1);
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_bad_scene_or_a_scene_with_a_state_is_one_clear_line() {
    let folder = folder("bad-scene");
    let scene = folder.join("broken.toml");
    std::fs::write(&scene, "title = \"x\"\n[source]\nkind = \"laser\"\n").unwrap();
    let out = folder.join("x.png");
    let out = out.to_str().unwrap();
    for (args, message) in [
        (
            vec!["droplet", "--out", out, "--state", "s.json"],
            "not both",
        ),
        (vec!["no-such-scene", "--out", out], "no-such-scene"),
        (
            vec![scene.to_str().unwrap(), "--out", out],
            "broken.toml:3:",
        ),
        (vec!["droplet", "--out", out, "--width", "9"], "9×1080"),
    ] {
        fails_in_one_line(&args, message);
    }
    assert!(!folder.join("x.png").exists());
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_fresnel_and_accuracy_views_render_as_the_window_draws_them() {
    // Issue 22: the plots the class sees are the plots it exports.
    let folder = folder("views");
    let state = folder.join("glass-to-air.json");
    std::fs::write(
        &state,
        r#"{"w":[0.8,-0.6,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"convention":"along_ray"}"#,
    )
    .unwrap();
    let svg = folder.join("fresnel.svg");
    let args = ["--view", "fresnel", "--state", state.to_str().unwrap()];
    let output = render(&[&args[..], &["--out", svg.to_str().unwrap()]].concat());
    assert!(output.status.success(), "{output:?}");
    let text = std::fs::read_to_string(&svg).unwrap();
    for words in ["Brewster", "critical angle θc = 41.8°", "Hecht"] {
        assert!(text.contains(words), "{words} in the SVG");
    }
    let png = folder.join("accuracy.png");
    let output = render(&["--view", "accuracy", "--out", png.to_str().unwrap()]);
    assert!(output.status.success(), "{output:?}");
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    fails_in_one_line(
        &["slab", "--view", "fresnel", "--out", "x.png"],
        "--view draws the single interface's views",
    );
    fails_in_one_line(
        &["--view", "fresnel", "--animate", "mu", "--out", "x.gif"],
        "leave out --view",
    );
}

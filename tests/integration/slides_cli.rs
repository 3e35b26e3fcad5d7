//! `render` for slides end to end: SVG by the file's extension (the diagram and a scene, labels
//! outlined, or as editable text with `--svg-text`), and `--animate` GIFs with the requested
//! size and frame count.

use crate::cli;

use cli::render;
use std::path::{Path, PathBuf};

fn folder(name: &str) -> PathBuf {
    cli::folder("slides-cli", name)
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The words of an outlined label: its group's `<title>`, unescaped.
fn titles(text: &str) -> Vec<String> {
    text.split("<title>")
        .skip(1)
        .map(|t| {
            let words = &t[..t.find("</title>").unwrap()];
            words
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&")
        })
        .collect()
}

/// The SVG at `file`: parsed (it must be well-formed SVG), its size, and its labels' words
/// (outlined labels' titles, or `<text>` contents).
fn svg(file: &Path) -> ((f32, f32), Vec<String>) {
    let text = std::fs::read_to_string(file).unwrap();
    let tree = resvg::usvg::Tree::from_str(&text, &resvg::usvg::Options::default())
        .expect("the SVG parses");
    let size = (tree.size().width(), tree.size().height());
    let mut labels = titles(&text);
    let texts = text
        .split("<text")
        .skip(1)
        .map(|element| {
            let body = &element[element.find('>').unwrap() + 1..element.find("</text>").unwrap()];
            // The tspans' contents, markup dropped.
            let mut words = String::new();
            let mut inside = false;
            for ch in body.chars() {
                match ch {
                    '<' => inside = true,
                    '>' => inside = false,
                    _ if !inside => words.push(ch),
                    _ => {}
                }
            }
            words
        })
        .collect::<Vec<String>>();
    labels.extend(texts);
    (size, labels)
}

#[test]
fn svg_text_writes_the_labels_as_editable_text() {
    let folder = folder("svg-text");
    let out = folder.join("diagram.svg");
    let output = render(&["--out", path(&out), "--svg-text"]);
    assert!(output.status.success(), "{output:?}");
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(
        text.contains("<text") && !text.contains("<title>"),
        "labels as text"
    );
    let (_, labels) = svg(&out);
    assert!(labels.iter().any(|l| l == "T"), "{labels:?}");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn an_svg_out_writes_the_diagram_as_svg_with_its_labels_outlined() {
    let folder = folder("svg");
    let out = folder.join("diagram.SVG");
    let output = render(&["--out", path(&out), "--width", "800", "--height", "450"]);
    assert!(output.status.success(), "{output:?}");
    let (size, labels) = svg(&out);
    assert_eq!(size, (800.0, 450.0));
    assert!(labels.iter().any(|l| l == "T"), "{labels:?}");
    assert!(labels.iter().any(|l| l.starts_with("θi = ")), "{labels:?}");
    assert!(
        labels.iter().any(|l| l.starts_with("μt = 1.5 (glass)")),
        "{labels:?}"
    );
    assert_eq!(
        std::fs::read_dir(&folder).unwrap().count(),
        1,
        "no temporary left"
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_scene_renders_to_svg_too() {
    let folder = folder("scene-svg");
    let out = folder.join("droplet.svg");
    let output = render(&[
        "droplet",
        "--out",
        path(&out),
        "--width",
        "640",
        "--height",
        "400",
    ]);
    assert!(output.status.success(), "{output:?}");
    let (size, labels) = svg(&out);
    assert_eq!(size, (640.0, 400.0));
    assert!(!labels.is_empty());
    std::fs::remove_dir_all(&folder).unwrap();
}

/// A decoded frame's width, height and delay (hundredths of a second).
type FrameSize = (u16, u16, u16);

/// The GIF at `file`: its size and its frames' sizes.
fn gif_frames(file: &Path) -> ((u16, u16), Vec<FrameSize>) {
    let bytes = std::fs::read(file).unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(bytes.as_slice())
        .expect("the GIF decodes");
    let size = (decoder.width(), decoder.height());
    let mut frames = Vec::new();
    while let Some(frame) = decoder.read_next_frame().expect("every frame decodes") {
        frames.push((frame.width, frame.height, frame.delay));
    }
    (size, frames)
}

#[test]
fn every_animation_writes_a_gif_of_the_requested_size_and_frames() {
    let folder = folder("gif");
    for (name, frames) in [("mu", "3"), ("sweep", "4"), ("wavefronts", "2")] {
        let out = folder.join(format!("{name}.gif"));
        let output = render(&[
            "--animate",
            name,
            "--out",
            path(&out),
            "--width",
            "160",
            "--height",
            "96",
            "--frames",
            frames,
            "--fps",
            "25",
        ]);
        assert!(output.status.success(), "{name}: {output:?}");
        assert!(
            output.stderr.is_empty(),
            "no progress bar off a terminal: {output:?}"
        );
        let (size, decoded) = gif_frames(&out);
        assert_eq!(size, (160, 96), "{name}");
        assert_eq!(decoded.len(), frames.parse::<usize>().unwrap(), "{name}");
        assert!(
            decoded.iter().all(|&f| f == (160, 96, 4)),
            "{name}: {decoded:?}"
        );
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_default_animation_has_at_least_24_frames() {
    let folder = folder("gif-default");
    let out = folder.join("sweep.gif");
    let output = render(&[
        "--animate",
        "sweep",
        "--out",
        path(&out),
        "--width",
        "64",
        "--height",
        "64",
    ]);
    assert!(output.status.success(), "{output:?}");
    let (size, frames) = gif_frames(&out);
    assert_eq!(size, (64, 64));
    assert!(frames.len() >= 24, "{} frames", frames.len());
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn bad_formats_frames_and_rates_are_one_clear_line_and_nothing_is_written() {
    let folder = folder("bad");
    let gif = folder.join("x.gif");
    let png = folder.join("x.png");
    let (gif, png) = (path(&gif), path(&png));
    for (args, message) in [
        (
            vec!["--animate", "mu", "--out", png],
            "give a name ending in .gif",
        ),
        (vec!["--out", gif], "render --animate"),
        (
            vec!["--out", "x.jpg"],
            "it writes PNG (.png), SVG (.svg), GIF (.gif)",
        ),
        (
            vec!["--animate", "spin", "--out", gif],
            "the animations are mu, sweep, wavefronts",
        ),
        (
            vec!["--animate", "mu", "--out", gif, "--frames", "1"],
            "2 to 600 frames",
        ),
        (
            vec!["--animate", "mu", "--out", gif, "--frames", "601"],
            "601 frames",
        ),
        (
            vec!["--animate", "mu", "--out", gif, "--fps", "0"],
            "1 to 50",
        ),
        (
            vec!["--animate", "mu", "--out", gif, "--width", "9"],
            "9×1080",
        ),
        (vec!["--frames", "30", "--out", png], "--animate"),
        (
            vec!["droplet", "--animate", "mu", "--out", gif],
            "not a scene",
        ),
    ] {
        let output = render(&args);
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains(message),
            "{args:?}: {message} not in {stderr}"
        );
    }
    assert_eq!(std::fs::read_dir(&folder).unwrap().count(), 0);
    std::fs::remove_dir_all(&folder).unwrap();
}

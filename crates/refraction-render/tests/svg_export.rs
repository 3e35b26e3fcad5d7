//! The SVG export against the PNG: it parses (usvg), has the requested size, holds every label
//! as text, and rasterised (resvg) looks like the PNG.
//!
//! How alike is measured per pixel as the largest difference of the four premultiplied RGBA
//! channels, 0–255. The two rasterisers are both tiny-skia underneath, but resvg fills the
//! text's glyph outlines it shapes itself and strokes each dashed line as one path rather than
//! piece by piece, so edges differ by antialiasing, most of all for light text on a strong
//! colour: a pixel counts as *different* only past [`VISIBLE`], a difference a viewer would
//! notice. Measured: at most 0.2% of the pixels (the white banner text over red in the total
//! internal reflection picture) and a mean difference of at most 0.53; the bounds
//! ([`MAX_DIFFERENT`], [`MAX_MEAN`]) sit two to three times above that, so that a change of
//! antialiasing does not fail the test while a missing label, a wrong colour or a shifted shape
//! (thousands of pixels, a mean of several levels) does.
#![expect(
    clippy::unwrap_used,
    reason = "test helpers: a failed unwrap is a failed test, with its message"
)]

use glam::Vec2;
use resvg::usvg::{self, Node};
use tiny_skia::{IntSize, Pixmap};

use refraction_diagram::{Diagram, Overlay, Primitive};
use refraction_model::ExplorerState;
use refraction_render::ImageFormat;
use refraction_render::svg::{self, Labels};
use refraction_render::{Picture, RenderError, pixmap, still};
use refraction_scene::Scene;

/// A channel difference a viewer would notice.
const VISIBLE: u8 = 64;
/// The largest share of pixels that may differ visibly.
const MAX_DIFFERENT: f64 = 0.005;
/// The largest mean channel difference.
const MAX_MEAN: f64 = 1.0;

/// usvg's options with the PNG's font (and no system fonts: the test must not depend on what
/// the machine has installed).
fn options() -> usvg::Options<'static> {
    let mut options = usvg::Options::default();
    let db = options.fontdb_mut();
    db.load_font_data(epaint_default_fonts::UBUNTU_LIGHT.to_vec());
    db.set_sans_serif_family("Ubuntu");
    options
}

fn parse(document: &str) -> usvg::Tree {
    usvg::Tree::from_str(document, &options()).expect("the SVG parses")
}

/// Every text chunk in the tree, in document order.
fn texts(group: &usvg::Group, out: &mut Vec<String>) {
    for node in group.children() {
        match node {
            Node::Group(g) => texts(g, out),
            Node::Text(t) => out.extend(t.chunks().iter().map(|c| c.text().to_owned())),
            Node::Path(_) | Node::Image(_) => {}
        }
    }
}

/// The share of visibly different pixels and the mean channel difference.
fn difference(a: &Pixmap, b: &Pixmap) -> (f64, f64) {
    assert_eq!(
        (a.width(), a.height()),
        (b.width(), b.height()),
        "the pictures have one size"
    );
    let (mut different, mut total) = (0_usize, 0_u64);
    for (p, q) in a.pixels().iter().zip(b.pixels()) {
        let d = [
            p.red().abs_diff(q.red()),
            p.green().abs_diff(q.green()),
            p.blue().abs_diff(q.blue()),
            p.alpha().abs_diff(q.alpha()),
        ]
        .into_iter()
        .max()
        .unwrap_or(0);
        different += usize::from(d > VISIBLE);
        total += u64::from(d);
    }
    let pixels = a.pixels().len() as f64;
    (different as f64 / pixels, total as f64 / pixels)
}

/// Rasterises `document` at its own size (with resvg's own tiny-skia, whose pixels then move
/// to the PNG's).
fn rasterise(tree: &usvg::Tree) -> Pixmap {
    let size = tree.size().to_int_size();
    let mut drawn = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        tree,
        resvg::tiny_skia::Transform::identity(),
        &mut drawn.as_mut(),
    );
    let area = IntSize::from_wh(size.width(), size.height()).unwrap();
    Pixmap::from_vec(drawn.take(), area).unwrap()
}

/// Checks the SVG against the PNG of the same drawing; returns the difference figures.
#[expect(clippy::print_stdout, reason = "the figures, for --nocapture")]
fn compare(what: &str, document: &str, png: &Pixmap, labels: &[String]) -> (f64, f64) {
    let tree = parse(document);
    let size = tree.size();
    assert_eq!(
        (size.width(), size.height()),
        (png.width() as f32, png.height() as f32),
        "{what}: size"
    );
    let mut found = Vec::new();
    texts(tree.root(), &mut found);
    for label in labels {
        for line in label.lines().filter(|l| !l.trim().is_empty()) {
            assert!(
                found.iter().any(|t| t == line),
                "{what}: label line {line:?} is not text in the SVG"
            );
        }
    }
    let (different, mean) = difference(&rasterise(&tree), png);
    println!(
        "{what}: {:.3}% of pixels differ by more than {VISIBLE}, mean difference {mean:.3}",
        different * 100.0
    );
    assert!(
        different <= MAX_DIFFERENT,
        "{what}: {different} of the pixels differ"
    );
    assert!(mean <= MAX_MEAN, "{what}: mean difference {mean}");
    (different, mean)
}

fn labels(primitives: &[Primitive]) -> Vec<String> {
    primitives
        .iter()
        .filter_map(|p| match p {
            Primitive::Text(label) => Some(label.text.clone()),
            _ => None,
        })
        .collect()
}

#[test]
fn the_interface_diagram_as_svg_looks_like_the_png_and_keeps_its_labels_as_text() {
    let mut tir = ExplorerState::default();
    tir.set_vectors(glam::DVec3::new(0.8, -0.6, 0.0), glam::DVec3::Y)
        .unwrap();
    tir.set_mu_i(1.5).unwrap();
    tir.set_mu_t(1.0).unwrap();
    assert!(tir.refraction().is_tir());
    for (what, state, (width, height)) in [
        (
            "air to glass, 1280×720",
            ExplorerState::default(),
            (1280, 720),
        ),
        ("total internal reflection, 800×800", tir, (800, 800)),
    ] {
        let overlay = Overlay::default();
        let size = Vec2::new(width as f32, height as f32);
        let primitives = Diagram::with_overlay(&state, size, &overlay).primitives();
        let document = text_svg(&primitives, (width, height));
        let picture = Picture::Interface {
            state: &state,
            overlay: &overlay,
        };
        let png = pixmap(picture, (width, height)).unwrap();
        let texts = labels(&primitives);
        assert!(texts.len() > 5, "{what}: only {} labels", texts.len());
        compare(what, &document, &png, &texts);
        // Outlined (the default), the labels are the PNG's glyphs as paths.
        let outlined = outlined_svg(picture, (width, height)).unwrap();
        assert!(!outlined.contains("<text"), "{what}");
        compare(&format!("{what}, outlined"), &outlined, &png, &[]);
    }
}

/// `picture` as an SVG document of `size` with its labels outlined (the default).
fn outlined_svg(picture: Picture<'_>, size: (u32, u32)) -> Result<String, RenderError> {
    let format = (ImageFormat::Svg, Labels::Outlined);
    let bytes = still(picture, format, size, std::path::Path::new("picture.svg"))?;
    Ok(String::from_utf8(bytes).expect("an SVG document is UTF-8"))
}

/// `primitives` as an SVG of `size` with its labels as text.
fn text_svg(primitives: &[Primitive], (width, height): (u32, u32)) -> String {
    svg::document(width, height, Labels::Text, |_, _| primitives.to_vec()).unwrap()
}

#[test]
fn scenes_export_to_svg_too() {
    for name in ["droplet", "dispersing-prism"] {
        let scene = Scene::embedded(name).unwrap();
        let document = outlined_svg(Picture::Scene(&scene), (960, 540)).unwrap();
        let png = pixmap(Picture::Scene(&scene), (960, 540)).unwrap();
        compare(name, &document, &png, &[]);
    }
}

#[test]
fn a_bad_size_is_refused_before_the_scene_is_traced() {
    let scene = Scene::embedded("droplet").unwrap();
    let err = outlined_svg(Picture::Scene(&scene), (9000, 540))
        .unwrap_err()
        .to_string();
    assert!(err.contains("9000×540"), "{err}");
}

/// Every text node's line widths as laid out, in document order.
fn laid_out_widths(group: &usvg::Group, out: &mut Vec<f32>) {
    for node in group.children() {
        match node {
            Node::Group(g) => laid_out_widths(g, out),
            Node::Text(t) => out.push(t.bounding_box().width()),
            Node::Path(_) | Node::Image(_) => {}
        }
    }
}

#[test]
fn on_a_machine_without_the_font_the_labels_keep_their_widths() {
    // Issue 22: the SVG named Ubuntu Light without carrying it, and a wider font overflowed
    // the labels' boxes. Here the only font is a monospace one, much wider than Ubuntu Light.
    let mut options = usvg::Options::default();
    let db = options.fontdb_mut();
    db.load_font_data(epaint_default_fonts::HACK_REGULAR.to_vec());
    db.set_sans_serif_family("Hack");
    let state = ExplorerState::default();
    let overlay = Overlay::default();
    let size = Vec2::new(1280.0, 720.0);
    let document = text_svg(
        &Diagram::with_overlay(&state, size, &overlay).primitives(),
        (1280, 720),
    );
    let tree = usvg::Tree::from_str(&document, &options).unwrap();
    let mut widths = Vec::new();
    laid_out_widths(tree.root(), &mut widths);
    let face = refraction_diagram::Typeface::egui_default();
    let expected: Vec<(String, f32)> = Diagram::with_overlay(&state, size, &overlay)
        .primitives()
        .iter()
        .filter_map(|p| match p {
            Primitive::Text(l) if !l.text.trim().is_empty() => {
                Some((l.text.clone(), face.measure(&l.text, l.size).x))
            }
            _ => None,
        })
        .collect();
    assert_eq!(widths.len(), expected.len());
    for (width, (text, wanted)) in widths.iter().zip(&expected) {
        // Glyphs' ink runs a little inside or past their advances: within 4 % and 2 px.
        assert!(
            (width - wanted).abs() <= wanted * 0.04 + 2.0,
            "{text:?}: {width} px wide in another font, {wanted} px in its box"
        );
    }
}

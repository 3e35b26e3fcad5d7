//! The diagram off screen: a PNG of [`Diagram::primitives`] drawn with tiny-skia, labels in
//! egui's own font ([`text`]); the same primitives as SVG ([`svg`]); animations as GIF
//! ([`animation`]); a lesson's handout as PDF ([`handout`]); every file written atomically ([`refraction_files::write_atomically`]).

pub mod animation;
pub mod format;
pub mod handout;
pub mod svg;
pub mod text;

use std::path::Path;

use glam::Vec2;
use tiny_skia::{FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Transform};

use crate::format::ImageFormat;
use refraction_diagram::font::{FontError, Typeface};
use refraction_diagram::geometry::Colour;
use refraction_diagram::{Diagram, Overlay, Primitive, SceneLayout, ScenePicture};
use refraction_files::write_atomically;
use refraction_model::ExplorerState;
use refraction_scene::{Scene, Trace};

/// The export size when none is given.
pub const DEFAULT_SIZE: (u32, u32) = (1920, 1080);

/// The smallest and largest accepted width or height, in pixels.
pub const SIZE_LIMITS: (u32, u32) = (64, 8192);

/// Why an image could not be made or written.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The width or height is outside [`SIZE_LIMITS`].
    #[error(
        "the image size {width}×{height} is not allowed: width and height must each be {} to {} \
         pixels",
        SIZE_LIMITS.0,
        SIZE_LIMITS.1
    )]
    BadSize {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// The embedded font could not be read.
    #[error(transparent)]
    Font(#[from] FontError),
    /// PNG encoding failed; the encoder's message.
    #[error("cannot encode the PNG: {0}")]
    Encode(String),
    /// The file could not be written.
    #[error(transparent)]
    Write(std::io::Error),
    /// GIF encoding failed; the encoder's message.
    #[error("cannot encode the GIF: {0}")]
    EncodeGif(String),
    /// An animation's frames or rate are outside their limits (the message says which).
    #[error("{0}")]
    BadAnimation(String),
    /// A handout's page could not be turned into PDF; the converter's message.
    #[error("cannot write the PDF: {0}")]
    Pdf(String),
    /// The work was cancelled before it was done; nothing was written.
    #[error("cancelled: nothing was written")]
    Cancelled,
    /// The path's extension names no format written.
    #[error(transparent)]
    Format(#[from] format::UnsupportedFormat),
    /// A still picture was asked for in a format that holds only animations (GIF).
    #[error(
        "cannot write {0}: a GIF holds an animation here; write the picture as .png or .svg, \
         or an animation (render --animate, Export animation) as .gif"
    )]
    NotStill(String),
}

fn paint(colour: Colour) -> Paint<'static> {
    let mut paint = Paint {
        anti_alias: true,
        ..Paint::default()
    };
    paint.set_color_rgba8(colour.r, colour.g, colour.b, colour.a);
    paint
}

fn path(points: &[Vec2], closed: bool) -> Option<tiny_skia::Path> {
    let (first, rest) = points.split_first()?;
    let mut path = PathBuilder::new();
    path.move_to(first.x, first.y);
    for p in rest {
        path.line_to(p.x, p.y);
    }
    if closed {
        path.close();
    }
    path.finish()
}

fn stroke(pixmap: &mut Pixmap, path: &tiny_skia::Path, width: f32, colour: Colour) {
    let stroke = tiny_skia::Stroke {
        width,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        ..tiny_skia::Stroke::default()
    };
    pixmap.stroke_path(path, &paint(colour), &stroke, Transform::identity(), None);
}

fn fill(pixmap: &mut Pixmap, path: &tiny_skia::Path, colour: Colour) {
    let rule = FillRule::Winding;
    pixmap.fill_path(path, &paint(colour), rule, Transform::identity(), None);
}

/// Draws one primitive.
fn draw(pixmap: &mut Pixmap, face: &Typeface, primitive: &Primitive) {
    match primitive {
        Primitive::Polygon { points, colour } => {
            if let Some(path) = path(points, true) {
                fill(pixmap, &path, *colour);
            }
        }
        Primitive::Polyline {
            points,
            width,
            colour,
        } => {
            if let Some(path) = path(points, false) {
                stroke(pixmap, &path, *width, *colour);
            }
        }
        Primitive::Disc {
            center,
            radius,
            fill: inside,
            outline_width,
            outline,
        } => {
            if let Some(path) = PathBuilder::from_circle(center.x, center.y, *radius) {
                fill(pixmap, &path, *inside);
                stroke(pixmap, &path, *outline_width, *outline);
            }
        }
        Primitive::Text(label) => {
            let size = face.measure(&label.text, label.size);
            let top_left = label.at - size * Vec2::new(label.h.fraction(), label.v.fraction());
            if let Some(background) = label.background {
                let pad = Vec2::splat(label.size * 0.2);
                let corners = [
                    top_left - pad,
                    Vec2::new(top_left.x + size.x + pad.x, top_left.y - pad.y),
                    top_left + size + pad,
                    Vec2::new(top_left.x - pad.x, top_left.y + size.y + pad.y),
                ];
                if let Some(path) = path(&corners, true) {
                    fill(pixmap, &path, background);
                }
            }
            if let Some(path) = text::outline(face, &label.text, top_left, label.size) {
                fill(pixmap, &path, label.colour);
            }
        }
    }
}

/// Checks a width and height against [`SIZE_LIMITS`], so that a command can refuse a bad size
/// before it traces or draws anything.
///
/// # Errors
/// [`RenderError::BadSize`] when either is outside the limits.
pub fn check_size(width: u32, height: u32) -> Result<(), RenderError> {
    let (low, high) = SIZE_LIMITS;
    if (low..=high).contains(&width) && (low..=high).contains(&height) {
        Ok(())
    } else {
        Err(RenderError::BadSize { width, height })
    }
}

/// A `width` × `height` pixmap with `primitives` drawn on it in order.
///
/// # Errors
/// A size outside [`SIZE_LIMITS`], or an unreadable embedded font.
pub fn draw_primitives(
    width: u32,
    height: u32,
    primitives: impl FnOnce(Vec2, &Typeface) -> Vec<Primitive>,
) -> Result<Pixmap, RenderError> {
    check_size(width, height)?;
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::BadSize { width, height })?;
    let face = Typeface::egui_default()?;
    for primitive in primitives(Vec2::new(width as f32, height as f32), &face) {
        draw(&mut pixmap, &face, &primitive);
    }
    Ok(pixmap)
}

/// The primitives of the diagram of `state` with `overlay`, for a canvas size: what the PNG
/// and the SVG both draw.
fn interface<'a>(
    state: &'a ExplorerState,
    overlay: &'a Overlay,
) -> impl FnOnce(Vec2, &Typeface) -> Vec<Primitive> + 'a {
    |size, _| Diagram::with_overlay(state, size, overlay).primitives()
}

/// The primitives of `scene` traced as `trace`, for a canvas size.
fn traced<'a>(
    scene: &'a Scene,
    trace: &'a Trace,
) -> impl FnOnce(Vec2, &Typeface) -> Vec<Primitive> + 'a {
    |size, _| ScenePicture::new(scene, trace, &SceneLayout::new(trace.bounds, size)).primitives
}

/// The diagram of `state` with `overlay` drawn on a `width` × `height` pixmap.
///
/// # Errors
/// A size outside [`SIZE_LIMITS`], or an unreadable embedded font.
pub fn render(
    state: &ExplorerState,
    overlay: &Overlay,
    width: u32,
    height: u32,
) -> Result<Pixmap, RenderError> {
    draw_primitives(width, height, interface(state, overlay))
}

/// The diagram of `state` with `overlay` as a `width` × `height` SVG document ([`svg`]).
///
/// # Errors
/// As [`render`].
pub fn interface_svg(
    state: &ExplorerState,
    overlay: &Overlay,
    width: u32,
    height: u32,
) -> Result<String, RenderError> {
    svg::document(
        width,
        height,
        svg::Labels::default(),
        interface(state, overlay),
    )
}

/// A pixmap as PNG bytes.
///
/// # Errors
/// The encoder failed.
pub fn encode(pixmap: &Pixmap) -> Result<Vec<u8>, RenderError> {
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))
}

/// The diagram of `state` with `overlay` as PNG bytes.
///
/// # Errors
/// As [`render`], or a failed encoding.
pub fn png(
    state: &ExplorerState,
    overlay: &Overlay,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, RenderError> {
    encode(&render(state, overlay, width, height)?)
}

/// A still picture drawn by `primitives` at `width` × `height` as the bytes of a `format`
/// file: PNG pixels or an SVG document, its labels written as `labels` says.
///
/// # Errors
/// As [`draw_primitives`], a failed encoding, or [`RenderError::NotStill`] for GIF (`path`
/// names the file in the message).
pub fn still(
    (format, labels): (ImageFormat, svg::Labels),
    (width, height): (u32, u32),
    path: &Path,
    primitives: impl FnOnce(Vec2, &Typeface) -> Vec<Primitive>,
) -> Result<Vec<u8>, RenderError> {
    match format {
        ImageFormat::Png => encode(&draw_primitives(width, height, primitives)?),
        ImageFormat::Svg => {
            svg::document(width, height, labels, primitives).map(String::into_bytes)
        }
        ImageFormat::Gif => Err(RenderError::NotStill(path.display().to_string())),
    }
}

/// The diagram of `state` with `overlay` as the bytes of a `format` file ([`still`]); `path`
/// only names the file in a message.
///
/// # Errors
/// As [`still`].
pub fn interface_file(
    state: &ExplorerState,
    overlay: &Overlay,
    format: (ImageFormat, svg::Labels),
    size: (u32, u32),
    path: &Path,
) -> Result<Vec<u8>, RenderError> {
    still(format, size, path, interface(state, overlay))
}

/// `scene`, traced, as the bytes of a `format` file ([`still`]); `path` only names the file
/// in a message. The size is checked before the scene is traced.
///
/// # Errors
/// As [`still`].
pub fn scene_file(
    scene: &Scene,
    format: (ImageFormat, svg::Labels),
    (width, height): (u32, u32),
    path: &Path,
) -> Result<Vec<u8>, RenderError> {
    check_size(width, height)?;
    still(format, (width, height), path, traced(scene, &scene.trace()))
}

/// Writes the diagram of `state` with `overlay` at `path`, atomically, as PNG or SVG by the
/// path's extension ([`ImageFormat::for_path`]).
///
/// # Errors
/// An extension that names no still format, as [`png`] or [`interface_svg`], or the file
/// cannot be written (the message names it).
pub fn export(
    state: &ExplorerState,
    overlay: &Overlay,
    size: (u32, u32),
    path: &Path,
) -> Result<(), RenderError> {
    let format = ImageFormat::for_path(path)?;
    let bytes = interface_file(state, overlay, (format, svg::Labels::default()), size, path)?;
    write_atomically(path, &bytes).map_err(RenderError::Write)
}

/// Writes the plot of a `bench` report at `path`, atomically, as PNG or SVG by the path's
/// extension.
///
/// # Errors
/// As [`still`], an extension that names no still format, or the file cannot be written (the
/// message names it).
pub fn export_accuracy_plot(
    report: &refraction_model::report::Report,
    width: u32,
    height: u32,
    path: &Path,
) -> Result<(), RenderError> {
    let format = ImageFormat::for_path(path)?;
    let bytes = still(
        (format, svg::Labels::default()),
        (width, height),
        path,
        |size, face| {
            let palette = refraction_diagram::palette::Palette::STANDARD;
            refraction_diagram::accuracy_plot::primitives(report, size, face, &palette)
        },
    )?;
    write_atomically(path, &bytes).map_err(RenderError::Write)
}

/// `scene`, traced, drawn on a `width` × `height` pixmap as the explorer's Scenes view shows
/// it.
///
/// # Errors
/// A size outside [`SIZE_LIMITS`], or an unreadable embedded font.
pub fn render_scene(scene: &Scene, width: u32, height: u32) -> Result<Pixmap, RenderError> {
    check_size(width, height)?;
    draw_primitives(width, height, traced(scene, &scene.trace()))
}

/// `scene`, traced, as a `width` × `height` SVG document, as [`render_scene`] draws it.
///
/// # Errors
/// As [`render_scene`].
pub fn scene_svg(scene: &Scene, width: u32, height: u32) -> Result<String, RenderError> {
    check_size(width, height)?;
    svg::document(
        width,
        height,
        svg::Labels::default(),
        traced(scene, &scene.trace()),
    )
}

/// Writes `scene`, traced, at `path`, atomically, as PNG or SVG by the path's extension.
///
/// # Errors
/// As [`scene_file`], an extension that names no still format, or the file cannot be written
/// (the message names it).
pub fn export_scene(
    scene: &Scene,
    width: u32,
    height: u32,
    path: &Path,
) -> Result<(), RenderError> {
    let format = ImageFormat::for_path(path)?;
    let bytes = scene_file(
        scene,
        (format, svg::Labels::default()),
        (width, height),
        path,
    )?;
    write_atomically(path, &bytes).map_err(RenderError::Write)
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_diagram::palette;

    #[test]
    fn the_png_decodes_at_the_requested_size_and_t_is_drawn_in_its_colour() {
        let state = ExplorerState::default();
        let bytes = png(&state, &Overlay::default(), 1920, 1080).unwrap();
        let decoded = Pixmap::decode_png(&bytes).unwrap();
        assert_eq!((decoded.width(), decoded.height()), (1920, 1080));
        let layout = refraction_diagram::Layout::new(Vec2::new(1920.0, 1080.0));
        let t = state.plane().project(state.refraction().t().unwrap());
        let mut on_t = 0;
        // From past the θt label to before the arrowhead.
        for i in 45..=85 {
            let world = t * (f64::from(i) / 100.0);
            let p = layout.view.to_canvas(world);
            let pixel = decoded
                .pixel(p.x.round() as u32, p.y.round() as u32)
                .unwrap();
            let c = palette::T;
            if (pixel.red(), pixel.green(), pixel.blue()) == (c.r, c.g, c.b) {
                on_t += 1;
            }
        }
        assert!(
            on_t >= 39,
            "only {on_t} of 41 pixels along T have T's colour"
        );
    }

    #[test]
    fn every_built_in_scene_renders_with_its_rays_in_their_colours() {
        for info in refraction_scene::catalogue() {
            let scene = Scene::embedded(info.name).unwrap();
            let pixmap = render_scene(&scene, 800, 500).unwrap();
            assert_eq!((pixmap.width(), pixmap.height()), (800, 500));
            let colours: Vec<_> = scene
                .source()
                .colours(scene.effects().dispersion)
                .into_iter()
                .map(refraction_diagram::spectrum::ray_colour)
                .collect();
            // Rays are translucent where the scene computes intensities: count pixels near a
            // ray colour rather than equal to it.
            let near = |p: &tiny_skia::PremultipliedColorU8, c: &Colour| {
                let d = |x: u8, y: u8| i32::from(x).abs_diff(i32::from(y));
                d(p.red(), c.r) + d(p.green(), c.g) + d(p.blue(), c.b) < 40
            };
            let on_rays = pixmap
                .pixels()
                .iter()
                .filter(|p| colours.iter().any(|c| near(p, c)))
                .count();
            assert!(on_rays > 100, "{}: {on_rays} ray pixels", info.name);
        }
    }

    #[test]
    fn bad_sizes_and_paths_are_errors_with_clear_messages() {
        let state = ExplorerState::default();
        let err = png(&state, &Overlay::default(), 0, 1080)
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("0×1080") && err.contains("64 to 8192"),
            "{err}"
        );
        let path = Path::new("/nonexistent-folder/x.png");
        let err = export(&state, &Overlay::default(), (640, 360), path).unwrap_err();
        assert!(err.to_string().contains("/nonexistent-folder/x.png"));
    }

    #[test]
    fn the_extension_picks_the_format_and_the_effects_switched_on_are_exported() {
        use refraction_diagram::intensities::Polarisation;
        use refraction_diagram::wavefronts::WaveOptions;
        let state = ExplorerState::default();
        let overlay = Overlay {
            intensities: Some(Polarisation::P),
            waves: Some(WaveOptions::default()),
            ..Overlay::default()
        };
        let path = Path::new("slide.svg");
        let svg = interface_file(
            &state,
            &overlay,
            (ImageFormat::Svg, svg::Labels::Text),
            (640, 360),
            path,
        )
        .unwrap();
        let svg = String::from_utf8(svg).unwrap();
        assert!(svg.contains("T: transmitted"), "the shares are in the SVG");
        assert!(
            svg.contains("fronts λ/1.50 apart"),
            "the wavefronts are in the SVG"
        );
        // Outlined (the default), the words are in each label's title.
        let plain = interface_file(
            &state,
            &Overlay::default(),
            (ImageFormat::Svg, svg::Labels::Outlined),
            (640, 360),
            path,
        );
        assert!(
            !String::from_utf8(plain.as_ref().unwrap().clone())
                .unwrap()
                .contains("fronts")
        );
        let plain = String::from_utf8(plain.unwrap()).unwrap();
        assert!(
            plain.contains("<title>T</title>") && !plain.contains("<text"),
            "{plain}"
        );
        let png = (ImageFormat::Png, svg::Labels::default());
        let png = interface_file(&state, &overlay, png, (640, 360), path).unwrap();
        assert!(Pixmap::decode_png(&png).is_ok());
        let gif = Path::new("x.gif");
        let format = (ImageFormat::Gif, svg::Labels::default());
        let err = interface_file(&state, &overlay, format, (640, 360), gif);
        assert!(
            err.unwrap_err()
                .to_string()
                .contains("x.gif: a GIF holds an animation")
        );
    }

    #[test]
    fn a_bad_size_says_the_size_and_the_limits_in_one_sentence() {
        let err = RenderError::BadSize {
            width: 20,
            height: 9000,
        };
        assert_eq!(
            err.to_string(),
            "the image size 20×9000 is not allowed: width and height must each be 64 to 8192 \
             pixels"
        );
    }
}

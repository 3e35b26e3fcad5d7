//! The diagram off screen. A [`Picture`] (the interface's diagram, a traced scene, a plot, or
//! any primitives) is drawn by [`pixmap`] with tiny-skia, its labels in egui's own font
//! outlined; [`still`] gives it as PNG or SVG ([`svg`]) bytes and [`write()`] writes it. Animations
//! are GIFs ([`animation`]) and a lesson's handout a PDF ([`handout`]); every file is written
//! atomically ([`refraction_files::write_atomically`]).

pub mod animation;
mod format;
pub mod handout;
pub mod svg;
mod text;

pub use format::{FORMATS, ImageFormat, UnsupportedFormat};

use std::path::Path;

use glam::Vec2;
use tiny_skia::{FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Transform};

use refraction_diagram::{
    Colour, Diagram, Overlay, Primitive, SceneLayout, ScenePicture, Typeface,
};
use refraction_files::write_atomically;
use refraction_model::ExplorerState;
use refraction_model::report::Report;
use refraction_scene::Scene;

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
    /// A handout's link is too long for a QR code that a phone reads on paper.
    #[error(
        "a step's link is {bytes} bytes, too long for a QR code that a phone reads on paper (it \
         would be wider than {most_mm} mm): give a shorter web address"
    )]
    LinkTooLong {
        /// The link's length in bytes.
        bytes: usize,
        /// The widest QR code a page holds, in millimetres.
        most_mm: u32,
    },
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
/// A size outside [`SIZE_LIMITS`].
pub(crate) fn draw_primitives(
    width: u32,
    height: u32,
    primitives: impl FnOnce(Vec2, &Typeface) -> Vec<Primitive>,
) -> Result<Pixmap, RenderError> {
    check_size(width, height)?;
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::BadSize { width, height })?;
    let face = Typeface::egui_default();
    for primitive in primitives(Vec2::new(width as f32, height as f32), &face) {
        draw(&mut pixmap, &face, &primitive);
    }
    Ok(pixmap)
}

/// What a still picture shows: the one thing every export, command and window draws off screen.
#[derive(Clone, Copy)]
pub enum Picture<'a> {
    /// The single interface's diagram of a state, with the overlay's extras switched on.
    Interface {
        /// The state drawn.
        state: &'a ExplorerState,
        /// What is drawn over it (intensities, wavefronts, the answer hidden, …).
        overlay: &'a Overlay,
    },
    /// A scene, traced, as the Scenes view shows it; traced only once the size is checked.
    Scene(&'a Scene),
    /// The plot of a `bench` report.
    AccuracyPlot(&'a Report),
    /// The Fresnel plot of a state's interface.
    FresnelPlot(&'a ExplorerState),
    /// Anything else drawn from the diagram's primitives (a QR code, a deck's step) for a
    /// canvas size, in egui's font.
    Drawn(&'a dyn Fn(Vec2, &Typeface) -> Vec<Primitive>),
}

impl Picture<'_> {
    /// Its primitives for a canvas of `size`, in drawing order.
    fn primitives(self, size: Vec2, face: &Typeface) -> Vec<Primitive> {
        let palette = refraction_diagram::palette::Palette::STANDARD;
        match self {
            Self::Interface { state, overlay } => {
                Diagram::with_overlay(state, size, overlay).primitives()
            }
            Self::Scene(scene) => {
                let trace = scene.trace();
                ScenePicture::new(scene, &trace, &SceneLayout::new(trace.bounds, size)).primitives
            }
            Self::AccuracyPlot(report) => {
                refraction_diagram::accuracy_plot(report, size, face, &palette)
            }
            Self::FresnelPlot(state) => {
                let plot = refraction_diagram::FresnelPlot::of(state);
                refraction_diagram::fresnel_plot(&plot, size, face, &palette)
            }
            Self::Drawn(draw) => draw(size, face),
        }
    }
}

/// `picture` drawn on a `width` × `height` pixmap.
///
/// # Errors
/// A size outside [`SIZE_LIMITS`] (checked before a scene is traced).
pub fn pixmap(picture: Picture<'_>, (width, height): (u32, u32)) -> Result<Pixmap, RenderError> {
    draw_primitives(width, height, |size, face| picture.primitives(size, face))
}

/// `picture` at `width` × `height` as the bytes of a `format` file: PNG pixels or an SVG
/// document, its labels written as `labels` says; `path` only names the file in a message.
///
/// # Errors
/// As [`pixmap`], a failed encoding, or [`RenderError::NotStill`] for GIF.
pub fn still(
    picture: Picture<'_>,
    (format, labels): (ImageFormat, svg::Labels),
    (width, height): (u32, u32),
    path: &Path,
) -> Result<Vec<u8>, RenderError> {
    match format {
        ImageFormat::Png => pixmap(picture, (width, height))?
            .encode_png()
            .map_err(|e| RenderError::Encode(e.to_string())),
        ImageFormat::Svg => svg::document(width, height, labels, |size, face| {
            picture.primitives(size, face)
        })
        .map(String::into_bytes),
        ImageFormat::Gif => Err(RenderError::NotStill(path.display().to_string())),
    }
}

/// Writes `picture` at `path`, atomically, as PNG or SVG by the path's extension
/// ([`ImageFormat::for_path`]), its SVG labels outlined.
///
/// # Errors
/// An extension that names no still format, as [`still`], or the file cannot be written (the
/// message names it).
pub fn write(picture: Picture<'_>, size: (u32, u32), path: &Path) -> Result<(), RenderError> {
    let format = ImageFormat::for_path(path)?;
    let bytes = still(picture, (format, svg::Labels::default()), size, path)?;
    write_atomically(path, &bytes).map_err(RenderError::Write)
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_diagram::palette;

    #[test]
    fn the_png_decodes_at_the_requested_size_and_t_is_drawn_in_its_colour() {
        let state = ExplorerState::default();
        let overlay = Overlay::default();
        let picture = Picture::Interface {
            state: &state,
            overlay: &overlay,
        };
        let bytes = still(
            picture,
            (ImageFormat::Png, svg::Labels::default()),
            (1920, 1080),
            Path::new("t.png"),
        )
        .unwrap();
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
            let pixmap = pixmap(Picture::Scene(&scene), (800, 500)).unwrap();
            assert_eq!((pixmap.width(), pixmap.height()), (800, 500));
            let colours: Vec<_> = scene
                .source()
                .colours(scene.effects().dispersion)
                .into_iter()
                .map(refraction_diagram::ray_colour)
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
        let overlay = Overlay::default();
        let picture = Picture::Interface {
            state: &state,
            overlay: &overlay,
        };
        let err = pixmap(picture, (0, 1080)).unwrap_err().to_string();
        assert!(
            err.contains("0×1080") && err.contains("64 to 8192"),
            "{err}"
        );
        let path = Path::new("/nonexistent-folder/x.png");
        let err = write(picture, (640, 360), path).unwrap_err();
        assert!(err.to_string().contains("/nonexistent-folder/x.png"));
    }

    #[test]
    fn the_extension_picks_the_format_and_the_effects_switched_on_are_exported() {
        use refraction_diagram::WaveOptions;
        use refraction_model::Polarisation;
        let state = ExplorerState::default();
        let overlay = Overlay {
            intensities: Some(Polarisation::P),
            waves: Some(WaveOptions::default()),
            ..Overlay::default()
        };
        let path = Path::new("slide.svg");
        let svg = still(
            Picture::Interface {
                state: &state,
                overlay: &overlay,
            },
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
        let plain = still(
            Picture::Interface {
                state: &state,
                overlay: &Overlay::default(),
            },
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
        let picture = Picture::Interface {
            state: &state,
            overlay: &overlay,
        };
        let png = still(picture, png, (640, 360), path).unwrap();
        assert!(Pixmap::decode_png(&png).is_ok());
        let gif = Path::new("x.gif");
        let format = (ImageFormat::Gif, svg::Labels::default());
        let err = still(picture, format, (640, 360), gif);
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

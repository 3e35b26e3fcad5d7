//! Draws the diagram's primitives with an egui painter, the screen twin of `render`.

use egui::emath::RectTransform;
use egui::epaint::{CircleShape, Mesh, Tessellator};
use egui::{
    Align2, Color32, Context, FontId, Id, Painter, Pos2, Rect, Response, Shape, Stroke, Ui,
};
use glam::Vec2;

use refraction_diagram::{Align, Colour, LABEL_PAD, Label, Primitive, palette::Palette};

/// The egui colour of a diagram colour.
#[must_use]
pub(super) fn color(c: Colour) -> Color32 {
    Color32::from_rgba_unmultiplied(c.r, c.g, c.b, c.a)
}

/// The diagram colour of an egui colour (its opacity kept).
#[must_use]
pub(super) fn colour(c: Color32) -> Colour {
    let [r, g, b, a] = c.to_srgba_unmultiplied();
    Colour { r, g, b, a }
}

/// Where this frame's palette is kept in the context's memory.
fn palette_id() -> Id {
    Id::unique("window-palette")
}

/// Keeps the palette the window shows this frame (its theme and colour-blind choice) where
/// every widget can read it with [`window_palette`].
pub(super) fn share_palette(ctx: &Context, palette: Palette) {
    ctx.data_mut(|d| d.insert_temp(palette_id(), palette));
}

/// The palette the window shows, as [`share_palette`] left it (the standard palette where no
/// explorer set one, as in a panel's own tests).
#[must_use]
pub(super) fn window_palette(ui: &Ui) -> Palette {
    ui.data(|d| d.get_temp(palette_id()))
        .unwrap_or(Palette::STANDARD)
}

/// The colour of text in the window's palette that warns (the alarm's hue) or approves (the
/// normal's), shaded to read on the window's background.
#[must_use]
pub(super) fn verdict_colour(ui: &Ui, ok: bool) -> Color32 {
    let palette = window_palette(ui);
    color(palette.text_shade(if ok { palette.n } else { palette.alarm }))
}

fn align(a: Align) -> egui::Align {
    match a {
        Align::Start => egui::Align::Min,
        Align::Center => egui::Align::Center,
        Align::End => egui::Align::Max,
    }
}

/// Paints `primitives` (canvas pixels) through `to_screen` (canvas → screen points), handing
/// them to egui in one batch (each separate `Painter::add` takes the context's lock).
pub(super) fn paint(painter: &Painter, to_screen: &RectTransform, primitives: &[Primitive]) {
    painter.extend(shapes(painter, to_screen, primitives));
}

/// The egui shapes [`paint`] paints for `primitives`.
pub(super) fn shapes(
    painter: &Painter,
    to_screen: &RectTransform,
    primitives: &[Primitive],
) -> Vec<Shape> {
    let at = |p: Vec2| to_screen.transform_pos(Pos2::new(p.x, p.y));
    let points = |ps: &[Vec2]| ps.iter().map(|p| at(*p)).collect::<Vec<_>>();
    let mut shapes = Vec::with_capacity(primitives.len());
    for primitive in primitives {
        match primitive {
            Primitive::Polygon { points: ps, colour } => {
                shapes.push(Shape::convex_polygon(
                    points(ps),
                    color(*colour),
                    Stroke::NONE,
                ));
            }
            Primitive::Polyline {
                points: ps,
                width,
                colour,
            } => {
                let stroke = Stroke::new(*width, color(*colour));
                // Most rays of a scene are single segments: no point list to allocate.
                shapes.push(if let [a, b] = ps.as_slice() {
                    Shape::line_segment([at(*a), at(*b)], stroke)
                } else {
                    Shape::line(points(ps), stroke)
                });
            }
            Primitive::Disc {
                center,
                radius,
                fill,
                outline_width,
                outline,
            } => {
                shapes.push(Shape::Circle(CircleShape {
                    center: at(*center),
                    radius: *radius,
                    fill: color(*fill),
                    stroke: Stroke::new(*outline_width, color(*outline)),
                }));
            }
            Primitive::Text(label) => {
                let galley = painter.layout_no_wrap(
                    label.text.clone(),
                    FontId::proportional(label.size),
                    color(label.colour),
                );
                let anchor = Align2([align(label.h), align(label.v)]);
                let rect = anchor.anchor_size(at(label.at), galley.size());
                if let Some(background) = label.background {
                    let back = rect.expand(label.size * LABEL_PAD);
                    shapes.push(Shape::rect_filled(back, 0.0, color(background)));
                }
                shapes.push(Shape::galley(rect.min, galley, color(label.colour)));
            }
        }
    }
    shapes
}

/// Shapes kept between frames, each with the clip rectangle it is painted with (see
/// [`meshed`]).
pub(super) type KeptShapes = Vec<(Shape, Rect)>;

/// `shapes` with each run of lines and polygons (a scene's thousands of rays) tessellated
/// once, into one mesh for `painter`'s pixels per point; discs and text are kept as they are,
/// in their places. Shapes kept between frames are then painted ([`paint_kept`]) without
/// tessellating every ray again: egui only copies a mesh.
///
/// Each mesh, and each run of other shapes between them, is clipped to the rectangle it covers
/// (and, when painted, to the painter's clip): no pixel changes, but a mesh is never followed by a shape of the
/// same clip rectangle. egui's tessellator appends every shape to the output mesh of the shape
/// before it when their clip rectangles are equal: the droplet's discs after its mesh of
/// 160,000 vertices (1,000 rays per colour) grew that mesh by doubling, copying it twice a
/// frame into 9 MB of memory that the system had to hand over afresh at every frame
/// (`cargo bench --bench frame`). Now it is copied once, into an output mesh of its exact size.
pub(super) fn meshed(ctx: &Context, shapes: Vec<Shape>) -> KeptShapes {
    let options = ctx.tessellation_options(|o| *o);
    // No text is tessellated here, so no font texture's size is needed.
    let mut tessellator = Tessellator::new(ctx.pixels_per_point(), options, [1, 1], Vec::new());
    let mut kept = Vec::new();
    let mut run = Mesh::default();
    let mut others = Vec::new();
    for shape in shapes {
        if matches!(shape, Shape::LineSegment { .. } | Shape::Path(_)) {
            keep(&mut kept, core::mem::take(&mut others));
            tessellator.tessellate_shape(shape, &mut run);
        } else {
            if !run.is_empty() {
                keep(&mut kept, vec![Shape::mesh(core::mem::take(&mut run))]);
            }
            others.push(shape);
        }
    }
    if !run.is_empty() {
        others.push(Shape::mesh(run));
    }
    keep(&mut kept, others);
    kept
}

/// Adds `shapes` to `kept`, clipped to the rectangle they cover (a point more each way: the
/// renderer rounds the clip rectangle to whole pixels).
fn keep(kept: &mut KeptShapes, shapes: Vec<Shape>) {
    let covered = shapes
        .iter()
        .fold(Rect::NOTHING, |r, s| r.union(s.visual_bounding_rect()));
    let clip = covered.expand(1.0);
    kept.extend(shapes.into_iter().map(|shape| (shape, clip)));
}

/// Paints shapes kept by [`meshed`] with `painter`, each run of them with its clip rectangle
/// within the painter's.
pub(super) fn paint_kept(painter: &Painter, kept: &KeptShapes) {
    for run in kept.chunk_by(|a, b| a.1 == b.1) {
        let shapes = run.iter().map(|(shape, _)| shape.clone());
        painter.with_clip_rect(run[0].1).extend(shapes);
    }
}

/// Room for a figure of the diagram crate's across `size` points of `ui`, named `about` for
/// screen readers: the response, the painter and the map from the canvas to the screen, to
/// [`paint`] the figure's primitives with, as the exports draw them.
pub(super) fn figure(
    ui: &mut Ui,
    size: Vec2,
    sense: egui::Sense,
    about: &str,
) -> (Response, Painter, RectTransform) {
    let (response, painter) = ui.allocate_painter(egui::vec2(size.x, size.y), sense);
    let canvas = egui::Rect::from_min_size(Pos2::ZERO, egui::vec2(size.x, size.y));
    let to_screen = RectTransform::from_to(canvas, response.rect);
    let about = about.to_owned();
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Figure, true, &about));
    (response, painter, to_screen)
}

/// Shows, beside the pointer, the text of the label the placer left out whose anchor is
/// nearest the pointer, when it is within `reach` canvas pixels: a label with no free spot is
/// not drawn over anything, but can still be read. `to_screen` maps canvas to screen points.
pub(super) fn hover_left_out(
    response: &Response,
    to_screen: &RectTransform,
    left_out: &[Label],
    reach: f32,
) {
    let Some(pointer) = response.hover_pos() else {
        return;
    };
    let p = to_screen.inverse().transform_pos(pointer);
    let p = Vec2::new(p.x, p.y);
    let nearest = left_out
        .iter()
        .map(|l| (l, l.at.distance(p)))
        .filter(|(_, d)| *d <= reach)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((label, _)) = nearest {
        response
            .clone()
            .on_hover_text_at_pointer(label.text.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_diagram::palette::Theme;

    #[test]
    fn warnings_and_verdicts_take_the_window_palette() {
        let dark = Palette::new(Theme::HighContrastDark, false);
        let mut harness = egui_kittest::Harness::builder().build_ui_state(
            |ui, seen: &mut Vec<Color32>| {
                seen.push(verdict_colour(ui, false));
                share_palette(ui.ctx(), Palette::new(Theme::HighContrastDark, false));
                seen.push(verdict_colour(ui, false));
                seen.push(verdict_colour(ui, true));
            },
            Vec::new(),
        );
        harness.run_steps(1);
        let seen = harness.state();
        let standard = Palette::STANDARD;
        assert_eq!(seen[0], color(standard.text_shade(standard.alarm)));
        assert_eq!(seen[1], color(dark.text_shade(dark.alarm)));
        assert_eq!(seen[2], color(dark.text_shade(dark.n)));
        assert_ne!(seen[0], seen[1]);
    }
}

//! Draws the diagram's primitives with an egui painter, the screen twin of `render`.

use egui::emath::RectTransform;
use egui::epaint::CircleShape;
use egui::{Align2, Color32, FontId, Painter, Pos2, Response, Shape, Stroke};
use glam::Vec2;

use refraction_diagram::Primitive;
use refraction_diagram::geometry::Colour;
use refraction_diagram::placer::PAD;
use refraction_diagram::shapes::{Align, Label};

/// The egui colour of a diagram colour.
#[must_use]
pub fn color(c: Colour) -> Color32 {
    Color32::from_rgba_unmultiplied(c.r, c.g, c.b, c.a)
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
pub fn paint(painter: &Painter, to_screen: &RectTransform, primitives: &[Primitive]) {
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
                    let back = rect.expand(label.size * PAD);
                    shapes.push(Shape::rect_filled(back, 0.0, color(background)));
                }
                shapes.push(Shape::galley(rect.min, galley, color(label.colour)));
            }
        }
    }
    painter.extend(shapes);
}

/// Shows, beside the pointer, the text of the label the placer left out whose anchor is
/// nearest the pointer, when it is within `reach` canvas pixels: a label with no free spot is
/// not drawn over anything, but can still be read. `to_screen` maps canvas to screen points.
pub fn hover_left_out(
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

//! The diagram's vocabulary: arrows, lines with dash patterns, filled polygons, discs and
//! labels; and their lowering to the few primitives a backend must draw, so that dashes and
//! arrowheads are computed once and look the same on screen and in the PNG.

use glam::Vec2;

use super::geometry::{Colour, Rect, arrowhead, dash};

/// A dash pattern, named so that a test (or a reader without colour vision) can tell the
/// strokes apart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dash {
    /// A continuous line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Dots.
    Dotted,
    /// Dash, dot, dash.
    DashDot,
    /// Long dashes with short gaps.
    LongDash,
    /// Dash, dot, dot.
    DashDotDot,
    /// Long dash, dot.
    LongDashDot,
}

impl Dash {
    /// The on/off lengths for a stroke `width` pixels wide (empty for [`Dash::Solid`]).
    #[must_use]
    pub fn pattern(self, width: f32) -> Vec<f32> {
        let w = width.max(1.0);
        match self {
            Self::Solid => Vec::new(),
            Self::Dashed => vec![6.0 * w, 4.0 * w],
            Self::Dotted => vec![1.2 * w, 2.6 * w],
            Self::DashDot => vec![6.0 * w, 2.5 * w, 1.2 * w, 2.5 * w],
            Self::LongDash => vec![11.0 * w, 3.0 * w],
            Self::DashDotDot => vec![6.0 * w, 2.2 * w, 1.2 * w, 2.2 * w, 1.2 * w, 2.2 * w],
            Self::LongDashDot => vec![11.0 * w, 2.5 * w, 1.2 * w, 2.5 * w],
        }
    }
}

/// How a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// Width in pixels.
    pub width: f32,
    /// Colour.
    pub colour: Colour,
    /// Dash pattern.
    pub dash: Dash,
}

/// Where a label's text sits relative to its anchor point, horizontally and vertically.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// The text starts (left) or hangs (top) at the point.
    Start,
    /// The text is centred on the point.
    Center,
    /// The text ends (right) or sits (bottom) at the point.
    End,
}

impl Align {
    /// The offset of the text box's start from the anchor, as a fraction of its extent.
    #[must_use]
    pub fn fraction(self) -> f32 {
        match self {
            Self::Start => 0.0,
            Self::Center => 0.5,
            Self::End => 1.0,
        }
    }

    /// The alignment that puts text on the far side of a point along a direction component:
    /// positive → [`Align::Start`], negative → [`Align::End`], near zero → [`Align::Center`].
    #[must_use]
    pub fn away(component: f32) -> Self {
        if component > 0.35 {
            Self::Start
        } else if component < -0.35 {
            Self::End
        } else {
            Self::Center
        }
    }
}

/// A piece of text (lines separated by `\n`).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The text.
    pub text: String,
    /// The anchor point.
    pub at: Vec2,
    /// Horizontal alignment of the text box on the anchor.
    pub h: Align,
    /// Vertical alignment of the text box on the anchor.
    pub v: Align,
    /// Font size in pixels.
    pub size: f32,
    /// Text colour.
    pub colour: Colour,
    /// A box behind the text, for legibility over lines and shading.
    pub background: Option<Colour>,
}

/// The margin drawn around a label's text (its background box), as a fraction of its size: the
/// painters draw the background this much larger than the text.
pub const LABEL_PAD: f32 = 0.2;

impl Label {
    /// The box the label covers with its anchor at `at`, when its text measures `extent`: the
    /// text and the background's margin ([`LABEL_PAD`]).
    #[must_use]
    pub fn boxed(&self, extent: Vec2, at: Vec2) -> Rect {
        let pad = Vec2::splat(self.size * LABEL_PAD);
        let min = at - extent * Vec2::new(self.h.fraction(), self.v.fraction()) - pad;
        Rect {
            min,
            max: min + extent + pad * 2.0,
        }
    }
}

/// One thing the diagram draws.
#[derive(Clone, Debug, PartialEq)]
pub enum Figure {
    /// A filled convex polygon.
    Fill {
        /// Its corners in order.
        points: Vec<Vec2>,
        /// Fill colour.
        colour: Colour,
    },
    /// A polyline.
    Line {
        /// Its points in order.
        points: Vec<Vec2>,
        /// How it is drawn.
        stroke: Stroke,
    },
    /// An arrow from `from` to `to` with its head at `to`.
    Arrow {
        /// Tail.
        from: Vec2,
        /// Tip.
        to: Vec2,
        /// How the shaft is drawn (the head is always solid).
        stroke: Stroke,
        /// What it is in the lesson: labels never lie on W, N or T.
        role: ArrowRole,
    },
    /// A filled circle with an outline.
    Disc {
        /// Centre.
        center: Vec2,
        /// Radius in pixels.
        radius: f32,
        /// Fill colour.
        fill: Colour,
        /// Outline (solid).
        outline: Stroke,
    },
    /// Text.
    Text(Label),
}

/// What an arrow is in the lesson, for the labels placed around it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArrowRole {
    /// W, N or T: the vectors the lesson is about; a label crosses one only where nothing
    /// else is left.
    Vector,
    /// Any other ray: the incoming and reflected rays, the candidates, a ghost drawn in a
    /// vector's colour (the normal the kernel uses), a student's T, a scene's aim.
    Ray,
}

/// What a backend draws: solid primitives only.
#[derive(Clone, Debug, PartialEq)]
pub enum Primitive {
    /// A filled convex polygon.
    Polygon {
        /// Corners.
        points: Vec<Vec2>,
        /// Fill colour.
        colour: Colour,
    },
    /// A solid polyline with round joins and caps.
    Polyline {
        /// Points.
        points: Vec<Vec2>,
        /// Width in pixels.
        width: f32,
        /// Colour.
        colour: Colour,
    },
    /// A filled circle with a solid outline.
    Disc {
        /// Centre.
        center: Vec2,
        /// Radius.
        radius: f32,
        /// Fill colour.
        fill: Colour,
        /// Outline width.
        outline_width: f32,
        /// Outline colour.
        outline: Colour,
    },
    /// Text.
    Text(Label),
}

/// The words of every text among `primitives`, in drawing order.
#[must_use]
pub fn primitive_texts(primitives: &[Primitive]) -> Vec<&str> {
    primitives
        .iter()
        .filter_map(|p| match p {
            Primitive::Text(label) => Some(label.text.as_str()),
            _ => None,
        })
        .collect()
}

fn polylines(points: &[Vec2], stroke: &Stroke, out: &mut Vec<Primitive>) {
    for piece in dash(points, &stroke.dash.pattern(stroke.width)) {
        out.push(Primitive::Polyline {
            points: piece,
            width: stroke.width,
            colour: stroke.colour,
        });
    }
}

impl Figure {
    /// The arrowhead length for a shaft `width` pixels wide.
    #[must_use]
    pub(crate) fn head_length(width: f32) -> f32 {
        (width * 4.0).max(9.0)
    }

    /// Appends this shape's primitives to `out`.
    pub fn lower(&self, out: &mut Vec<Primitive>) {
        match self {
            Self::Fill { points, colour } => out.push(Primitive::Polygon {
                points: points.clone(),
                colour: *colour,
            }),
            Self::Line { points, stroke } => polylines(points, stroke, out),
            Self::Arrow {
                from, to, stroke, ..
            } => {
                let direction = *to - *from;
                let head = Self::head_length(stroke.width).min(direction.length() * 0.6);
                let base = *to - direction.normalize_or_zero() * head * 0.8;
                polylines(&[*from, base], stroke, out);
                let points = arrowhead(*to, direction, head);
                if !points.is_empty() {
                    out.push(Primitive::Polygon {
                        points,
                        colour: stroke.colour,
                    });
                }
            }
            Self::Disc {
                center,
                radius,
                fill,
                outline,
            } => out.push(Primitive::Disc {
                center: *center,
                radius: *radius,
                fill: *fill,
                outline_width: outline.width,
                outline: outline.colour,
            }),
            Self::Text(label) => out.push(Primitive::Text(label.clone())),
        }
    }
}

/// The primitives of `shapes`, in drawing order.
#[must_use]
pub(crate) fn lower_all(shapes: &[Figure]) -> Vec<Primitive> {
    let mut out = Vec::new();
    for shape in shapes {
        shape.lower(&mut out);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dashed_arrow_lowers_to_dashes_and_one_solid_head() {
        let stroke = Stroke {
            width: 2.0,
            colour: Colour::hex(0x123456),
            dash: Dash::Dashed,
        };
        let arrow = Figure::Arrow {
            from: Vec2::ZERO,
            to: Vec2::new(200.0, 0.0),
            stroke,
            role: ArrowRole::Ray,
        };
        let primitives = lower_all(&[arrow]);
        let (polygons, lines): (Vec<_>, Vec<_>) = primitives
            .iter()
            .partition(|p| matches!(p, Primitive::Polygon { .. }));
        assert_eq!(polygons.len(), 1);
        assert!(lines.len() > 5);
        let solid = Figure::Arrow {
            from: Vec2::ZERO,
            to: Vec2::ZERO,
            stroke: Stroke {
                dash: Dash::Solid,
                ..stroke
            },
            role: ArrowRole::Ray,
        };
        assert_eq!(lower_all(&[solid]).len(), 1);
    }

    #[test]
    fn patterns_differ_without_colour() {
        let all = [
            Dash::Solid,
            Dash::Dashed,
            Dash::Dotted,
            Dash::DashDot,
            Dash::LongDash,
            Dash::DashDotDot,
            Dash::LongDashDot,
        ]
        .map(|d| d.pattern(2.0));
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert_eq!(Align::away(1.0), Align::Start);
        assert_eq!(Align::away(0.0), Align::Center);
    }
}

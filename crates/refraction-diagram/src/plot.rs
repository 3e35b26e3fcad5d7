//! What the explorer's plots share: a plotting area on a canvas with linear axes (ticks, grid,
//! frame), markers whose shapes tell series apart without colour, and legends in a row or a
//! column, their samples the series' markers or lines.

use glam::Vec2;

use super::font::Typeface;
use super::geometry::{Colour, Rect};
use super::numbers::number;
use super::palette::Palette;
use super::shapes::{Align, Dash, Figure, Label, Stroke};

/// The shape of a series' markers, so that no two series differ by colour alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Marker {
    /// A circle.
    Circle,
    /// A square.
    Square,
    /// A diamond.
    Diamond,
    /// An upward triangle.
    Triangle,
    /// A plus sign.
    Plus,
    /// A cross.
    Cross,
}

/// How one marker is drawn: its shape, colour and whether it is filled (hollow markers are
/// filled with the background).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct MarkerStyle {
    /// The shape.
    pub shape: Marker,
    /// The outline's (and a filled marker's) colour.
    pub colour: Colour,
    /// Whether the inside is the colour too.
    pub filled: bool,
}

impl MarkerStyle {
    /// The figures of this marker at `center`, `radius` pixels from centre to edge, over a
    /// `background`.
    #[must_use]
    pub(crate) fn figures(&self, center: Vec2, radius: f32, background: Colour) -> Vec<Figure> {
        let outline = Stroke {
            width: (radius / 3.0).max(1.5),
            colour: self.colour,
            dash: Dash::Solid,
        };
        let fill = if self.filled { self.colour } else { background };
        let corners = |points: &[(f32, f32)]| -> Vec<Vec2> {
            points
                .iter()
                .map(|&(x, y)| center + Vec2::new(x, y) * radius)
                .collect()
        };
        let polygon = |points: Vec<Vec2>| {
            let mut closed = points.clone();
            closed.push(points[0]);
            vec![
                Figure::Fill {
                    points,
                    colour: fill,
                },
                Figure::Line {
                    points: closed,
                    stroke: outline,
                },
            ]
        };
        let bars = |ends: [(f32, f32); 4]| {
            let e = corners(&ends);
            let stroke = Stroke {
                width: outline.width * 1.4,
                ..outline
            };
            vec![
                Figure::Line {
                    points: vec![e[0], e[1]],
                    stroke,
                },
                Figure::Line {
                    points: vec![e[2], e[3]],
                    stroke,
                },
            ]
        };
        match self.shape {
            Marker::Circle => vec![Figure::Disc {
                center,
                radius,
                fill,
                outline,
            }],
            Marker::Square => polygon(corners(&[
                (-0.85, -0.85),
                (0.85, -0.85),
                (0.85, 0.85),
                (-0.85, 0.85),
            ])),
            Marker::Diamond => {
                polygon(corners(&[(0.0, -1.2), (1.2, 0.0), (0.0, 1.2), (-1.2, 0.0)]))
            }
            Marker::Triangle => polygon(corners(&[(0.0, -1.15), (1.1, 0.85), (-1.1, 0.85)])),
            Marker::Plus => bars([(-1.1, 0.0), (1.1, 0.0), (0.0, -1.1), (0.0, 1.1)]),
            Marker::Cross => bars([(-0.8, -0.8), (0.8, 0.8), (-0.8, 0.8), (0.8, -0.8)]),
        }
    }
}

/// A linear axis: the values at its two ends and the step between its ticks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Axis {
    /// The value at the start (left or bottom).
    pub min: f64,
    /// The value at the end (right or top).
    pub max: f64,
    /// The distance between ticks.
    pub step: f64,
}

impl Axis {
    /// An axis from 0 to a round value at least `largest` (and at least `least`), in at most
    /// `most` steps (and at least two where `most` allows), 1, 2 or 5 times a power of ten.
    #[must_use]
    pub(crate) fn from_zero(largest: f64, least: f64, most: usize) -> Self {
        let largest = if largest.is_finite() {
            largest.max(least)
        } else {
            least
        };
        let rough = largest / most.max(1) as f64;
        let decade = 10_f64.powf(rough.log10().floor());
        let step = [1.0, 2.0, 5.0, 10.0]
            .into_iter()
            .map(|m| m * decade)
            .find(|s| largest / s <= most.max(1) as f64)
            .unwrap_or(10.0 * decade);
        Self {
            min: 0.0,
            max: (largest / step).ceil() * step,
            step,
        }
    }

    /// An axis covering `low` to `high` (any order), its ends on whole steps, in at most
    /// `most` steps of 1, 2 or 5 times a power of ten.
    #[must_use]
    pub(crate) fn covering(low: f64, high: f64, most: usize) -> Self {
        let (low, high) = (low.min(high), low.max(high));
        let span = Self::from_zero(
            high - low,
            f64::EPSILON.max((high - low) * 1e-9),
            most.max(1),
        );
        let step = span.step;
        let min = (low / step).floor() * step;
        let mut max = (high / step).ceil() * step;
        if max <= min {
            max = min + step;
        }
        Self { min, max, step }
    }

    /// The fraction of the way from `min` to `max` that `value` lies, clamped to [0, 1].
    #[must_use]
    pub(crate) fn fraction(&self, value: f64) -> f32 {
        let span = self.max - self.min;
        if span > 0.0 {
            ((value - self.min) / span).clamp(0.0, 1.0) as f32
        } else {
            0.0
        }
    }

    /// The tick values from `min` to `max`.
    #[must_use]
    pub(crate) fn ticks(&self) -> Vec<f64> {
        let count = ((self.max - self.min) / self.step).round().max(0.0) as usize;
        (0..=count)
            .map(|i| self.min + self.step * i as f64)
            .collect()
    }

    /// The decimals a tick label needs to tell the ticks apart.
    #[must_use]
    pub(crate) fn decimals(&self) -> usize {
        let places = -self.step.log10().floor();
        if places > 0.0 { places as usize } else { 0 }
    }
}

/// A plot's area on a canvas, its axes and its text size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Chart {
    /// The plotting area, in canvas pixels.
    pub area: Rect,
    /// The horizontal axis.
    pub x: Axis,
    /// The vertical axis (its minimum at the bottom).
    pub y: Axis,
    /// The size of the tick labels, in pixels.
    pub text: f32,
}

impl Chart {
    /// The canvas point of the value (`x`, `y`), clamped to the area.
    #[must_use]
    pub(crate) fn at(&self, x: f64, y: f64) -> Vec2 {
        let (min, max) = (self.area.min, self.area.max);
        Vec2::new(
            min.x + (max.x - min.x) * self.x.fraction(x),
            max.y - (max.y - min.y) * self.y.fraction(y),
        )
    }

    /// The grid, the frame and the tick labels with their `unit` suffixes (`°`, ` %`), in
    /// `palette`'s colours.
    #[must_use]
    pub(crate) fn axes(&self, units: (&str, &str), palette: &Palette) -> Vec<Figure> {
        let grid = Stroke {
            width: 1.0,
            colour: palette.guide.with_alpha(90),
            dash: Dash::Solid,
        };
        let mut figures = Vec::new();
        let label = |text: String, at: Vec2, h: Align, v: Align, size: f32| {
            Figure::Text(Label {
                text,
                at,
                h,
                v,
                size,
                colour: palette.ink,
                background: None,
            })
        };
        let (x0, x1, y0, y1) = (self.x.min, self.x.max, self.y.min, self.y.max);
        for x in self.x.ticks() {
            figures.push(Figure::Line {
                points: vec![self.at(x, y0), self.at(x, y1)],
                stroke: grid,
            });
            let text = format!("{}{}", number(x, self.x.decimals()), units.0);
            let below = self.at(x, y0) + Vec2::new(0.0, self.text * 0.35);
            figures.push(label(text, below, Align::Center, Align::Start, self.text));
        }
        for y in self.y.ticks() {
            figures.push(Figure::Line {
                points: vec![self.at(x0, y), self.at(x1, y)],
                stroke: grid,
            });
            let text = format!("{}{}", number(y, self.y.decimals()), units.1);
            let left = self.at(x0, y) - Vec2::new(self.text * 0.4, 0.0);
            // The lowest sits on the axis, clear of the first tick label under it.
            let lowest = (y - y0).abs() < self.y.step * 1e-6;
            let v = if lowest { Align::End } else { Align::Center };
            figures.push(label(text, left, Align::End, v, self.text));
        }
        figures.push(Figure::Line {
            points: vec![self.at(x0, y1), self.at(x0, y0), self.at(x1, y0)],
            stroke: Stroke {
                width: 1.5,
                colour: palette.ink,
                dash: Dash::Solid,
            },
        });
        figures
    }
}

/// What a legend entry shows of its series: a marker or a short piece of its line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sample {
    /// A marker of this style.
    Marker(MarkerStyle),
    /// A line drawn with this stroke.
    Line(Stroke),
}

impl Sample {
    /// How wide the sample is, for text `size` pixels high.
    fn width(self, size: f32) -> f32 {
        match self {
            Self::Marker(_) => size * 0.7,
            Self::Line(_) => size * 2.2,
        }
    }

    /// The sample's figures, its left end at `left`, centred on `left.y`.
    fn figures(self, left: Vec2, size: f32, background: Colour) -> Vec<Figure> {
        let width = self.width(size);
        match self {
            Self::Marker(style) => {
                let radius = width / 2.0;
                style.figures(left + Vec2::new(radius, 0.0), radius, background)
            }
            Self::Line(stroke) => vec![Figure::Line {
                points: vec![left, left + Vec2::new(width, 0.0)],
                stroke,
            }],
        }
    }
}

/// One entry of a legend: its sample and its words.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct LegendEntry {
    /// The sample drawn before the words.
    pub sample: Sample,
    /// The words.
    pub text: String,
}

impl LegendEntry {
    /// The entry's width with text `size` pixels high.
    #[must_use]
    pub(crate) fn width(&self, size: f32, face: &Typeface) -> f32 {
        self.sample.width(size) + size * 0.4 + face.width(&self.text, size)
    }

    /// The entry's figures from `left` (the middle of its left edge).
    fn figures(&self, left: Vec2, size: f32, palette: &Palette) -> Vec<Figure> {
        let mut figures = self.sample.figures(left, size, palette.background);
        figures.push(Figure::Text(Label {
            text: self.text.clone(),
            at: left + Vec2::new(self.sample.width(size) + size * 0.4, 0.0),
            h: Align::Start,
            v: Align::Center,
            size,
            colour: palette.ink,
            background: None,
        }));
        figures
    }
}

/// The legend of `entries` as a row from `at` (its top left), wrapped at `width`; its figures
/// and its height.
#[must_use]
pub(crate) fn legend_row(
    entries: &[LegendEntry],
    at: Vec2,
    width: f32,
    size: f32,
    face: &Typeface,
    palette: &Palette,
) -> (Vec<Figure>, f32) {
    let line = face.line_height(size);
    let gap = size * 1.2;
    let mut figures = Vec::new();
    let (mut pen, mut tallest) = (at, line);
    for entry in entries {
        // An entry wider than the row wraps its words under themselves.
        let room = width - entry.sample.width(size) - size * 0.4;
        let entry = LegendEntry {
            text: super::placer::wrap(face, &entry.text, size, room),
            ..entry.clone()
        };
        let extent = entry.width(size, face);
        if pen.x > at.x && pen.x + extent > at.x + width {
            pen = Vec2::new(at.x, pen.y + tallest + line * 0.2);
            tallest = line;
        }
        let height = face.measure(&entry.text, size).y;
        let mut drawn = entry.figures(pen + Vec2::new(0.0, line / 2.0), size, palette);
        // The words hang from the sample's line.
        if let Some(Figure::Text(label)) = drawn.last_mut() {
            label.v = Align::Start;
            label.at.y = pen.y;
        }
        figures.extend(drawn);
        tallest = tallest.max(height);
        pen.x += extent + gap;
    }
    (figures, pen.y + tallest + line * 0.2 - at.y)
}

/// The legend of `entries` as a column from `at` (its top left); its figures and its height.
#[must_use]
pub(crate) fn legend_column(
    entries: &[LegendEntry],
    at: Vec2,
    size: f32,
    face: &Typeface,
    palette: &Palette,
) -> (Vec<Figure>, f32) {
    let row = face.line_height(size) * 1.25;
    let mut figures = Vec::new();
    for (i, entry) in entries.iter().enumerate() {
        let left = at + Vec2::new(0.0, row * (i as f32 + 0.5));
        figures.extend(entry.figures(left, size, palette));
    }
    (figures, row * entries.len() as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_axis_from_zero_ends_on_a_round_value_with_a_few_ticks() {
        for (largest, max, step) in [
            (0.0, 1.0, 0.2),
            (0.7, 1.0, 0.2),
            (3.2, 4.0, 1.0),
            (28.5, 30.0, 5.0),
            (90.0, 100.0, 20.0),
            (180.0, 200.0, 50.0),
            (f64::NAN, 1.0, 0.2),
        ] {
            let axis = Axis::from_zero(largest, 1.0, 6);
            assert!((axis.max - max).abs() < 1e-9, "{largest}: {axis:?}");
            assert!((axis.step - step).abs() < 1e-9, "{largest}: {axis:?}");
            let ticks = axis.ticks();
            assert!((4..=9).contains(&ticks.len()), "{largest}: {ticks:?}");
        }
        assert_eq!(Axis::from_zero(0.7, 1.0, 6).decimals(), 1);
        assert_eq!(Axis::from_zero(30.0, 1.0, 6).decimals(), 0);
        let around = Axis::covering(-1.3, 0.4, 4);
        assert_eq!((around.min, around.max, around.step), (-1.5, 0.5, 0.5));
        // A short axis takes fewer, wider steps.
        assert_eq!(Axis::from_zero(180.0, 1.0, 2).ticks(), [0.0, 100.0, 200.0]);
    }

    #[test]
    fn every_marker_shape_is_drawn_and_a_hollow_one_takes_the_background() {
        let shapes = [
            Marker::Circle,
            Marker::Square,
            Marker::Diamond,
            Marker::Triangle,
            Marker::Plus,
            Marker::Cross,
        ];
        let drawn: Vec<Vec<Figure>> = shapes
            .iter()
            .map(|&shape| {
                let style = MarkerStyle {
                    shape,
                    colour: Colour::hex(0x0072B2),
                    filled: false,
                };
                style.figures(Vec2::new(10.0, 10.0), 5.0, Colour::hex(0xFFFFFF))
            })
            .collect();
        for (i, a) in drawn.iter().enumerate() {
            assert!(!a.is_empty());
            for b in &drawn[i + 1..] {
                assert_ne!(a, b, "two shapes look alike");
            }
        }
        assert!(matches!(
            drawn[1][0],
            Figure::Fill { colour, .. } if colour == Colour::hex(0xFFFFFF)
        ));
    }

    #[test]
    fn a_legend_row_wraps_its_entries_and_a_long_one_wraps_its_words() {
        let face = Typeface::egui_default();
        let entry = |text: &str| LegendEntry {
            sample: Sample::Marker(MarkerStyle {
                shape: Marker::Circle,
                colour: Colour::hex(0x0072B2),
                filled: true,
            }),
            text: text.to_owned(),
        };
        let entries = [
            entry("right"),
            entry("wrong"),
            entry("a very long name indeed for a legend"),
        ];
        let (_, one_row) = legend_row(
            &entries[..2],
            Vec2::ZERO,
            400.0,
            14.0,
            &face,
            &Palette::STANDARD,
        );
        let (figures, wrapped) =
            legend_row(&entries, Vec2::ZERO, 120.0, 14.0, &face, &Palette::STANDARD);
        assert!(wrapped > one_row * 3.0, "{one_row} {wrapped}");
        let canvas = Rect::from_min_size(Vec2::ZERO, Vec2::new(120.0, wrapped));
        let drawn = crate::shapes::lower_all(&figures);
        let problems = crate::placer::text_problems(&drawn, &face, &canvas);
        assert!(problems.is_empty(), "{problems:?}");
    }
}

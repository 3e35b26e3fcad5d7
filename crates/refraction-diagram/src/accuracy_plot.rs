//! The `bench` report as a picture: maximum hard-set error (in ε·κ) against time per ray, both
//! on log scales, one marker per variant and precision. Drawn by the PNG renderer for
//! `bench --plot`; the explorer's "Accuracy vs time" view plots the same numbers with egui_plot
//! and the same [`LogAxis`].

use glam::Vec2;

use super::Primitive;
use super::font::Typeface;
use super::geometry::{Colour, Rect};
use super::palette;
use super::shapes::{Align, Dash, Figure, Label, Stroke, lower_all};
use refraction_bench::{Report, Row};

/// The default kernel's documented bound, drawn as a reference line: 32·ε·κ.
pub const BOUND: f64 = 32.0;

/// Errors below this many ε·κ are drawn at it (an exact answer would sit at −∞ on a log axis).
pub const FLOOR: f64 = 0.1;

/// A base-10 logarithmic axis over whole decades that cover some values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogAxis {
    /// log10 of the lowest value shown.
    pub low: f64,
    /// log10 of the highest value shown.
    pub high: f64,
}

impl LogAxis {
    /// The decades covering every finite positive value of `values` (clamped below at
    /// `floor`) with a little room at both ends; one decade either side of 1 when there is
    /// none.
    #[must_use]
    pub fn covering(values: impl IntoIterator<Item = f64>, floor: f64) -> Self {
        let logs: Vec<f64> = values
            .into_iter()
            .filter(|v| v.is_finite())
            .map(|v| v.max(floor).log10())
            .collect();
        let low = logs.iter().copied().fold(f64::INFINITY, f64::min);
        let high = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if low.is_finite() && high.is_finite() {
            // A twentieth of a decade of room, so that no marker sits on the frame.
            let (low, high) = ((low - 0.05).floor(), (high + 0.05).ceil());
            Self {
                low,
                high: if high > low { high } else { low + 1.0 },
            }
        } else {
            Self {
                low: -1.0,
                high: 1.0,
            }
        }
    }

    /// Where `value` sits from 0 (low end) to 1 (high end); values at or below zero sit at the
    /// low end.
    #[must_use]
    pub fn fraction(&self, value: f64) -> f64 {
        let log = if value > 0.0 { value.log10() } else { self.low };
        ((log - self.low) / (self.high - self.low)).clamp(0.0, 1.0)
    }

    /// The powers of ten from low to high, as their exponents.
    pub fn decades(&self) -> impl Iterator<Item = i32> {
        (self.low as i32)..=(self.high as i32)
    }
}

/// A power of ten as a label: `1`, `10`, `100`, `1000`, then `1e4`, … and `0.1`, `0.01`,
/// `1e-3`, ….
#[must_use]
pub fn decade_label(exponent: i32) -> String {
    match exponent {
        0..=3 => format!("{}", 10_i64.pow(exponent.unsigned_abs())),
        -2..=-1 => format!("{}", 10f64.powi(exponent)),
        _ => format!("1e{exponent}"),
    }
}

/// The colour of a variant's markers (Okabe–Ito hues, as the diagram's rays).
#[must_use]
pub fn variant_colour(variant: &str) -> Colour {
    match variant {
        "seed" => palette::WARNING,
        "stable" => palette::T,
        "trig" => palette::CRITICAL,
        "glam" => palette::N,
        _ => palette::W,
    }
}

/// One marker's label: variant and precision.
#[must_use]
pub fn point_label(row: &Row) -> String {
    format!("{} {}", row.variant, row.precision)
}

/// Text sizes and margins, in pixels, for a canvas of a given height.
struct Metrics {
    text: f32,
    title: f32,
    plot: Rect,
}

impl Metrics {
    fn new(size: Vec2) -> Self {
        let text = (size.y / 50.0).clamp(11.0, 28.0);
        Self {
            text,
            title: text * 1.3,
            plot: Rect {
                min: Vec2::new(text * 7.0, text * 6.5),
                max: Vec2::new(size.x - text * 10.0, size.y - text * 4.5),
            },
        }
    }
}

fn text(text: String, at: Vec2, (h, v): (Align, Align), size: f32, colour: Colour) -> Figure {
    Figure::Text(Label {
        text,
        at,
        h,
        v,
        size,
        colour,
        background: None,
    })
}

/// The plot's axes: time per ray (x) and largest hard-set error in ε·κ (y, with room for the
/// [`BOUND`] line), each over the whole decades its values need.
#[must_use]
pub fn axes(report: &Report) -> (LogAxis, LogAxis) {
    let rows = &report.rows;
    (
        LogAxis::covering(rows.iter().map(|r| r.ns_per_ray), 1e-3),
        LogAxis::covering(
            rows.iter().map(|r| r.max_err_hard_eps_kappa).chain([BOUND]),
            FLOOR,
        ),
    )
}

/// The report's plot on a canvas of `size` pixels, as primitives for any backend.
#[must_use]
pub fn primitives(report: &Report, size: Vec2, face: &Typeface) -> Vec<Primitive> {
    let m = Metrics::new(size);
    let (x_axis, y_axis) = axes(report);
    let at = |ns: f64, err: f64| {
        Vec2::new(
            m.plot.min.x + (m.plot.max.x - m.plot.min.x) * x_axis.fraction(ns) as f32,
            m.plot.max.y - (m.plot.max.y - m.plot.min.y) * y_axis.fraction(err.max(FLOOR)) as f32,
        )
    };
    let grid = Stroke {
        width: 1.0,
        colour: palette::GUIDE.with_alpha(90),
        dash: Dash::Solid,
    };
    let mut shapes = vec![Figure::Fill {
        points: vec![
            Vec2::ZERO,
            Vec2::new(size.x, 0.0),
            size,
            Vec2::new(0.0, size.y),
        ],
        colour: palette::BACKGROUND,
    }];
    for e in x_axis.decades() {
        let x = at(10f64.powi(e), FLOOR).x;
        shapes.push(Figure::Line {
            points: vec![Vec2::new(x, m.plot.min.y), Vec2::new(x, m.plot.max.y)],
            stroke: grid,
        });
        let below = Vec2::new(x, m.plot.max.y + m.text * 0.4);
        shapes.push(text(
            decade_label(e),
            below,
            (Align::Center, Align::Start),
            m.text,
            palette::INK,
        ));
    }
    for e in y_axis.decades() {
        let y = at(10f64.powi(x_axis.low as i32), 10f64.powi(e)).y;
        shapes.push(Figure::Line {
            points: vec![Vec2::new(m.plot.min.x, y), Vec2::new(m.plot.max.x, y)],
            stroke: grid,
        });
        let left = Vec2::new(m.plot.min.x - m.text * 0.5, y);
        shapes.push(text(
            decade_label(e),
            left,
            (Align::End, Align::Center),
            m.text,
            palette::INK,
        ));
    }
    let bound_y = at(1.0, BOUND).y;
    shapes.push(Figure::Line {
        points: vec![
            Vec2::new(m.plot.min.x, bound_y),
            Vec2::new(m.plot.max.x, bound_y),
        ],
        stroke: Stroke {
            width: 1.5,
            colour: palette::ALARM,
            dash: Dash::Dashed,
        },
    });
    shapes.push(text(
        "the default kernel's bound, 32 ε·κ".to_owned(),
        Vec2::new(m.plot.max.x, bound_y - m.text * 0.3),
        (Align::End, Align::End),
        m.text * 0.9,
        palette::ALARM,
    ));
    shapes.push(Figure::Line {
        points: vec![
            Vec2::new(m.plot.min.x, m.plot.min.y),
            Vec2::new(m.plot.min.x, m.plot.max.y),
            Vec2::new(m.plot.max.x, m.plot.max.y),
        ],
        stroke: Stroke {
            width: 1.5,
            colour: palette::INK,
            dash: Dash::Solid,
        },
    });
    let titles = [
        (
            "Accuracy against time on this machine".to_owned(),
            Vec2::new(size.x / 2.0, m.text * 1.0),
            (Align::Center, Align::Start),
            m.title,
        ),
        (
            "largest hard-set error, in ε·κ (log)".to_owned(),
            Vec2::new(m.plot.min.x, m.plot.min.y - m.text * 0.6),
            (Align::Start, Align::End),
            m.text,
        ),
        (
            "time per ray, ns (log)".to_owned(),
            Vec2::new((m.plot.min.x + m.plot.max.x) / 2.0, size.y - m.text * 1.2),
            (Align::Center, Align::End),
            m.text,
        ),
    ];
    for (words, anchor, align, size) in titles {
        shapes.push(text(words, anchor, align, size, palette::INK));
    }
    let radius = m.text * 0.45;
    let points: Vec<Vec2> = report
        .rows
        .iter()
        .map(|row| at(row.ns_per_ray, row.max_err_hard_eps_kappa))
        .collect();
    // Labels go right of their marker, moved down until they cover no marker and no label.
    let mut taken: Vec<Rect> = points
        .iter()
        .map(|p| Rect::from_min_size(*p - Vec2::splat(radius), Vec2::splat(2.0 * radius)))
        .collect();
    for (row, p) in report.rows.iter().zip(&points) {
        let colour = variant_colour(row.variant);
        let filled = row.precision == "f64";
        shapes.push(Figure::Disc {
            center: *p,
            radius,
            fill: if filled { colour } else { palette::BACKGROUND },
            outline: Stroke {
                width: 2.0,
                colour,
                dash: Dash::Solid,
            },
        });
        let label = point_label(row);
        let extent = face.measure(&label, m.text);
        let mut corner = *p + Vec2::new(m.text * 0.8, -extent.y / 2.0);
        let mut rect = Rect::from_min_size(corner, extent);
        while taken.iter().any(|t| t.overlaps(&rect)) {
            corner.y += extent.y * 0.5;
            rect = Rect::from_min_size(corner, extent);
        }
        taken.push(rect);
        shapes.push(text(
            label,
            corner,
            (Align::Start, Align::Start),
            m.text,
            palette::Palette::STANDARD.text_shade(colour),
        ));
    }
    shapes.push(text(
        format!("{}    hollow: f32, filled: f64", report.verdict()),
        Vec2::new(size.x / 2.0, m.text * 1.2 + m.title * 1.3),
        (Align::Center, Align::Start),
        m.text * 0.9,
        palette::INK,
    ));
    lower_all(&shapes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_axes_cover_whole_decades() {
        let axis = LogAxis::covering([0.8, 1.5e8, f64::INFINITY], FLOOR);
        assert_eq!((axis.low, axis.high), (-1.0, 9.0));
        assert_eq!(axis.fraction(1e4), 0.5);
        assert_eq!(axis.fraction(0.0), 0.0);
        assert_eq!(
            LogAxis::covering([], FLOOR),
            LogAxis {
                low: -1.0,
                high: 1.0
            }
        );
        assert_eq!(
            LogAxis::covering([5.0], FLOOR),
            LogAxis {
                low: 0.0,
                high: 1.0
            }
        );
        let labels: Vec<_> = [-3, -1, 0, 2, 4].map(decade_label).into();
        assert_eq!(labels, ["1e-3", "0.1", "1", "100", "1e4"]);
    }
}

//! The `bench` report as a picture: maximum hard-set error (in ε·κ) against time per ray, both
//! on log scales, one marker per variant and precision. Drawn by the PNG renderer for
//! `bench --plot` and `render --view accuracy`, and painted by the explorer's "Accuracy vs
//! time" view: one plot for the screen and the exports.

use glam::Vec2;

use super::Primitive;
use super::font::Typeface;
use super::geometry::{Colour, Rect};
use super::layout::SMALLEST_TEXT;
use super::obstacle::Obstacle;
use super::palette::Palette;
use super::placer::{Need, Placer};
use super::plot::MarkerStyle;
use super::shapes::{Align, Dash, Figure, Label, Stroke, lower_all};
use refraction_i18n::t;
use refraction_model::report::{Report, Row};

/// The default kernel's documented bound, drawn as a reference line: 32·ε·κ.
pub(crate) const BOUND: f64 = 32.0;

/// Errors below this many ε·κ are drawn at it (an exact answer would sit at −∞ on a log axis).
pub(crate) const FLOOR: f64 = 0.1;

/// A base-10 logarithmic axis over whole decades that cover some values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct LogAxis {
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
    pub(crate) fn covering(values: impl IntoIterator<Item = f64>, floor: f64) -> Self {
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
    pub(crate) fn fraction(&self, value: f64) -> f64 {
        let log = if value > 0.0 { value.log10() } else { self.low };
        ((log - self.low) / (self.high - self.low)).clamp(0.0, 1.0)
    }

    /// The powers of ten from low to high, as their exponents.
    pub(crate) fn decades(&self) -> impl Iterator<Item = i32> {
        (self.low as i32)..=(self.high as i32)
    }
}

/// A power of ten as a label: `1`, `10`, `100`, `1000`, then `1e4`, … and `0.1`, `0.01`,
/// `1e-3`, ….
#[must_use]
pub(crate) fn decade_label(exponent: i32) -> String {
    match exponent {
        0..=3 => format!("{}", 10_i64.pow(exponent.unsigned_abs())),
        -2..=-1 => format!("{}", 10f64.powi(exponent)),
        _ => format!("1e{exponent}"),
    }
}

/// The colour of a variant's markers in `palette` (one of its [`Palette::series`], the hues of
/// the diagram's rays); the SIMD peer, ultraviolet, in ink, so that it stands apart from this
/// project's own variants.
#[must_use]
pub(crate) fn variant_colour(variant: &str, palette: &Palette) -> Colour {
    let series = match variant {
        "stable" => 1,
        "glam" => 2,
        "batch" => 3,
        "seed" => 4,
        "trig" => 5,
        "ultraviolet" => 6,
        _ => 0,
    };
    palette.series[series]
}

pub(crate) use super::plot::Marker;

/// The marker of a variant: each kernel variant and the peer its own.
#[must_use]
pub(crate) fn variant_marker(variant: &str) -> Marker {
    match variant {
        "stable" => Marker::Circle,
        "batch" => Marker::Square,
        "glam" => Marker::Triangle,
        "trig" => Marker::Plus,
        "ultraviolet" => Marker::Diamond,
        _ => Marker::Cross,
    }
}

/// One marker's label: variant and precision.
#[must_use]
pub fn accuracy_point_label(row: &Row) -> String {
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
        let text = (size.y / 50.0).clamp(SMALLEST_TEXT, 28.0);
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
pub(crate) fn axes(report: &Report) -> (LogAxis, LogAxis) {
    let rows = &report.rows;
    (
        LogAxis::covering(rows.iter().map(|r| r.ns_per_ray), 1e-3),
        LogAxis::covering(
            rows.iter().map(|r| r.max_err_hard_eps_kappa).chain([BOUND]),
            FLOOR,
        ),
    )
}

/// The report's plot on a canvas of `size` pixels in `palette`'s colours, as primitives for
/// any backend.
#[must_use]
pub fn accuracy_plot(
    report: &Report,
    size: Vec2,
    face: &Typeface,
    palette: &Palette,
) -> Vec<Primitive> {
    let plot = Plot::new(report, size, palette);
    let mut shapes = vec![Figure::Fill {
        points: vec![
            Vec2::ZERO,
            Vec2::new(size.x, 0.0),
            size,
            Vec2::new(0.0, size.y),
        ],
        colour: palette.background,
    }];
    shapes.extend(plot.grid());
    shapes.extend(plot.bound());
    shapes.push(plot.frame());
    shapes.extend(plot.titles(size));
    shapes.extend(plot.markers(report, face, Rect::from_min_size(Vec2::ZERO, size)));
    shapes.push(text(
        format!("{}    {}", report.verdict(), t!("diagram-accuracy-markers")),
        Vec2::new(size.x / 2.0, plot.m.text * 1.2 + plot.m.title * 1.3),
        (Align::Center, Align::Start),
        plot.m.text * 0.9,
        palette.ink,
    ));
    lower_all(&shapes)
}

/// Where each row of `report` is marked on a canvas of `size`, in the order of its rows: what
/// the window hovers over.
#[must_use]
pub fn accuracy_markers(report: &Report, size: Vec2) -> Vec<Vec2> {
    let plot = Plot::new(report, size, &Palette::STANDARD);
    report
        .rows
        .iter()
        .map(|row| plot.at(row.ns_per_ray, row.max_err_hard_eps_kappa))
        .collect()
}

/// The plot's area on the canvas and its two axes (where a time and an error are drawn),
/// and its colours.
struct Plot<'a> {
    m: Metrics,
    x: LogAxis,
    y: LogAxis,
    palette: &'a Palette,
}

impl<'a> Plot<'a> {
    fn new(report: &Report, size: Vec2, palette: &'a Palette) -> Self {
        let (x, y) = axes(report);
        Self {
            m: Metrics::new(size),
            x,
            y,
            palette,
        }
    }

    /// The canvas point of `ns` per ray and an error of `err` ε·κ (at least [`FLOOR`]).
    fn at(&self, ns: f64, err: f64) -> Vec2 {
        let plot = &self.m.plot;
        Vec2::new(
            plot.min.x + (plot.max.x - plot.min.x) * self.x.fraction(ns) as f32,
            plot.max.y - (plot.max.y - plot.min.y) * self.y.fraction(err.max(FLOOR)) as f32,
        )
    }

    /// A line and a label at every decade: times below the plot, errors left of it.
    fn grid(&self) -> Vec<Figure> {
        let (plot, size) = (&self.m.plot, self.m.text);
        let stroke = Stroke {
            width: 1.0,
            colour: self.palette.guide.with_alpha(90),
            dash: Dash::Solid,
        };
        let mut shapes = Vec::new();
        for e in self.x.decades() {
            let x = self.at(10f64.powi(e), FLOOR).x;
            shapes.push(Figure::Line {
                points: vec![Vec2::new(x, plot.min.y), Vec2::new(x, plot.max.y)],
                stroke,
            });
            let below = Vec2::new(x, plot.max.y + size * 0.4);
            let align = (Align::Center, Align::Start);
            shapes.push(text(decade_label(e), below, align, size, self.palette.ink));
        }
        for e in self.y.decades() {
            let y = self.at(10f64.powi(self.x.low as i32), 10f64.powi(e)).y;
            shapes.push(Figure::Line {
                points: vec![Vec2::new(plot.min.x, y), Vec2::new(plot.max.x, y)],
                stroke,
            });
            let left = Vec2::new(plot.min.x - size * 0.5, y);
            // The lowest sits on the axis, clear of the first time under it.
            let lowest = f64::from(e) <= self.y.low;
            let align = (Align::End, if lowest { Align::End } else { Align::Center });
            shapes.push(text(decade_label(e), left, align, size, self.palette.ink));
        }
        shapes
    }

    /// The [`BOUND`] as a dashed line across the plot, and its label.
    fn bound(&self) -> [Figure; 2] {
        let (plot, size) = (&self.m.plot, self.m.text);
        let y = self.at(1.0, BOUND).y;
        [
            Figure::Line {
                points: vec![Vec2::new(plot.min.x, y), Vec2::new(plot.max.x, y)],
                stroke: Stroke {
                    width: 1.5,
                    colour: self.palette.alarm,
                    dash: Dash::Dashed,
                },
            },
            text(
                t!("diagram-accuracy-bound"),
                Vec2::new(plot.max.x, y - size * 0.3),
                (Align::End, Align::End),
                (size * 0.9).max(SMALLEST_TEXT),
                self.palette.alarm,
            ),
        ]
    }

    /// The two axes' lines: left and bottom.
    fn frame(&self) -> Figure {
        let plot = &self.m.plot;
        Figure::Line {
            points: vec![
                Vec2::new(plot.min.x, plot.min.y),
                Vec2::new(plot.min.x, plot.max.y),
                Vec2::new(plot.max.x, plot.max.y),
            ],
            stroke: Stroke {
                width: 1.5,
                colour: self.palette.ink,
                dash: Dash::Solid,
            },
        }
    }

    /// The plot's title and the two axes' names, on a canvas of `size`.
    fn titles(&self, size: Vec2) -> impl Iterator<Item = Figure> + use<'_> {
        let (small, title, plot) = (self.m.text, self.m.title, self.m.plot);
        [
            (
                t!("diagram-accuracy-title"),
                Vec2::new(size.x / 2.0, small * 1.0),
                (Align::Center, Align::Start),
                title,
            ),
            (
                t!("diagram-accuracy-error-axis"),
                Vec2::new(plot.min.x, plot.min.y - small * 0.6),
                (Align::Start, Align::End),
                small,
            ),
            (
                t!("diagram-accuracy-time-axis"),
                Vec2::new(f32::midpoint(plot.min.x, plot.max.x), size.y - small * 1.2),
                (Align::Center, Align::End),
                small,
            ),
        ]
        .into_iter()
        .map(|(words, anchor, align, size)| text(words, anchor, align, size, self.palette.ink))
    }

    /// One marker a row (hollow for f32, filled for f64), then their labels to the right,
    /// placed by the [`Placer`] off every marker and other label, inside the canvas (a label
    /// with no free spot is left out: the table beside the plot has every row).
    fn markers(&self, report: &Report, face: &Typeface, canvas: Rect) -> Vec<Figure> {
        let size = self.m.text;
        let radius = size * 0.45;
        let points: Vec<Vec2> = report
            .rows
            .iter()
            .map(|row| self.at(row.ns_per_ray, row.max_err_hard_eps_kappa))
            .collect();
        let mut placer = Placer::new(face);
        for center in &points {
            placer.avoid(Obstacle::Disc {
                center: *center,
                radius,
            });
        }
        let mut shapes = Vec::new();
        let mut labels = Vec::new();
        for (row, p) in report.rows.iter().zip(&points) {
            let colour = variant_colour(row.variant, self.palette);
            let style = MarkerStyle {
                shape: variant_marker(row.variant),
                colour,
                filled: row.precision == "f64",
            };
            shapes.extend(style.figures(*p, radius, self.palette.background));
            let label = Label {
                text: accuracy_point_label(row),
                at: *p + Vec2::new(size * 0.8, 0.0),
                h: Align::Start,
                v: Align::Center,
                size,
                colour: self.palette.text_shade(colour),
                background: None,
            };
            labels.push((label, canvas, Need::Optional));
        }
        let placement = placer.place_all(labels);
        shapes.extend(placement.figures());
        shapes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_and_the_peer_has_its_own_colour_and_marker() {
        let names: Vec<&str> = refraction_kernel::Variant::ALL
            .iter()
            .map(|v| v.name())
            .chain(["ultraviolet"])
            .collect();
        let palettes = crate::palette::Theme::ALL
            .into_iter()
            .flat_map(|theme| [false, true].map(|safe| Palette::new(theme, safe)));
        for palette in palettes {
            for (i, a) in names.iter().enumerate() {
                for b in &names[i + 1..] {
                    let colours = [a, b].map(|v| variant_colour(v, &palette));
                    assert_ne!(colours[0], colours[1], "{a} and {b} in {palette:?}");
                    assert_ne!(variant_marker(a), variant_marker(b), "{a} and {b}");
                }
            }
        }
    }

    fn row(variant: &'static str, precision: &'static str, ns: f64, err: f64) -> Row {
        Row {
            variant,
            precision,
            ns_per_ray: ns,
            rays_per_second: 1e9 / ns,
            max_err_random: 1e-7,
            median_err_random: 1e-8,
            max_err_hard: 1e-6,
            median_err_hard: 1e-7,
            max_err_hard_eps_kappa: err,
            tir_mismatches: 0,
        }
    }

    /// A report of `rows`, measured on ten rays of each set.
    fn report(rows: Vec<Row>) -> Report {
        Report {
            rows,
            rays: 10,
            hard_rays: 10,
            streaming: refraction_model::report::Streaming {
                rays: 10,
                batch_ns_per_ray: 1.0,
                memory_limit_ns_per_ray: 0.5,
            },
            cpu: "test".to_owned(),
        }
    }

    #[test]
    fn the_plot_takes_the_palettes_colours() {
        let report = report(vec![
            row("stable", "f64", 3.0, 1.2),
            row("seed", "f32", 1.5, 900.0),
        ]);
        let face = Typeface::egui_default();
        let dark = Palette::new(crate::palette::Theme::HighContrastDark, true);
        let shapes = accuracy_plot(&report, Vec2::new(800.0, 500.0), &face, &dark);
        assert!(
            matches!(&shapes[0], Primitive::Polygon { colour, .. } if *colour == dark.background)
        );
        // The stable kernel's circle and the seed's cross (its two short bars), in the dark
        // palette's colours.
        let stable = variant_colour("stable", &dark);
        assert!(
            shapes
                .iter()
                .any(|p| matches!(p, Primitive::Disc { outline, .. } if *outline == stable))
        );
        let seed = variant_colour("seed", &dark);
        let bars = shapes
            .iter()
            .filter(|p| {
                matches!(p, Primitive::Polyline { colour, points, .. }
                if *colour == seed && points.len() == 2 && points[0].distance(points[1]) < 20.0)
            })
            .count();
        assert!(bars >= 2, "{bars}");
        assert_ne!(stable, variant_colour("stable", &Palette::STANDARD));
        for p in &shapes {
            if let Primitive::Text(label) = p {
                assert_ne!(label.colour, Palette::STANDARD.ink, "{}", label.text);
            }
        }
    }

    #[test]
    fn no_text_covers_another_in_any_language() {
        // Issue 22: at 1280 points the axis title was cut.
        let rows: Vec<Row> = [
            ("stable", "f64", 3.0, 1.2),
            ("stable", "f32", 2.0, 1.0),
            ("batch", "f32", 0.7, 1.1),
            ("glam", "f32", 1.9, 2.4e6),
            ("trig", "f64", 9.0, 3.0),
            ("seed", "f64", 2.6, 7.0e9),
            ("ultraviolet", "f32", 2.2, 2.4e6),
        ]
        .into_iter()
        .map(|(v, p, ns, err)| row(v, p, ns, err))
        .collect();
        let report = report(rows);
        let face = Typeface::egui_default();
        for locale in refraction_i18n::Locale::ALL {
            refraction_i18n::set_locale(locale);
            for size in [
                Vec2::new(1280.0, 480.0),
                Vec2::new(1600.0, 1000.0),
                Vec2::new(760.0, 420.0),
            ] {
                let drawn = accuracy_plot(&report, size, &face, &Palette::STANDARD);
                let canvas = Rect::from_min_size(Vec2::ZERO, size);
                let problems = crate::placer::text_problems(&drawn, &face, &canvas);
                assert!(problems.is_empty(), "{locale:?} {size}: {problems:?}");
            }
        }
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
    }

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

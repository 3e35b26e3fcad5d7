//! A judged log's failure map: for every judged line, how far the direction the student's code
//! sent the ray in is from the right one, against the angle of incidence, in one panel per side
//! the rays arrive from, with the lines whose right answer is total internal reflection marked.
//! A bug is one line of code, wrong the same way on every call it touches, so the map shows its
//! pattern at a glance: every ray from inside wrong, only those past the critical angle, or all.

use glam::Vec2;
use refraction_i18n::t;
use refraction_model::log_map::{LinePoint, Side};

use super::font::Typeface;
use super::geometry::Rect;
use super::layout::SMALLEST_TEXT;
use super::palette::Palette;
use super::plot::{Axis, Chart, LegendEntry, Marker, MarkerStyle, Sample, legend_row};
use super::shapes::{Align, Figure, Label, Primitive, lower_all};

/// The sides a map has a panel for, in order, where some line arrives from it.
const SIDES: [Option<Side>; 3] = [Some(Side::Outside), Some(Side::Inside), None];

/// How a line's marker is drawn: hollow in the normal's colour when right, filled in the
/// alarm colour when wrong; a square where the right answer is total internal reflection.
fn style(point: &LinePoint, palette: &Palette) -> MarkerStyle {
    MarkerStyle {
        shape: if point.past_critical {
            Marker::Square
        } else {
            Marker::Circle
        },
        colour: if point.ok { palette.n } else { palette.alarm },
        filled: !point.ok,
    }
}

/// The legend's entries, in the map's colours.
fn entries(palette: &Palette) -> [LegendEntry; 3] {
    let entry = |shape, colour, filled, text| LegendEntry {
        sample: Sample::Marker(MarkerStyle {
            shape,
            colour,
            filled,
        }),
        text,
    };
    [
        entry(
            Marker::Circle,
            palette.n,
            false,
            t!("diagram-failure-right"),
        ),
        entry(
            Marker::Circle,
            palette.alarm,
            true,
            t!("diagram-failure-wrong"),
        ),
        entry(
            Marker::Square,
            palette.ink,
            false,
            t!("diagram-failure-past-critical"),
        ),
    ]
}

/// A panel's title: the side, how many lines arrive from it and how many of them are wrong.
fn title(side: Option<Side>, lines: usize, wrong: usize) -> String {
    let side = match side {
        Some(Side::Outside) => "outside",
        Some(Side::Inside) => "inside",
        None => "unknown",
    };
    t!(
        "diagram-failure-panel",
        side = side,
        lines = lines,
        wrong = wrong
    )
}

/// The sides some line arrives from, in the order of the map's panels.
fn sides_of(points: &[LinePoint]) -> Vec<Option<Side>> {
    SIDES
        .into_iter()
        .filter(|side| points.iter().any(|p| p.side == *side))
        .collect()
}

/// How many panels the map of `points` has: one per side some line arrives from.
#[must_use]
pub(crate) fn sides(points: &[LinePoint]) -> usize {
    sides_of(points).len()
}

/// What the map of `points` shows, in words (its accessible name): each panel's title.
#[must_use]
pub fn describe(points: &[LinePoint]) -> String {
    let panels: Vec<String> = sides_of(points)
        .into_iter()
        .map(|side| {
            let mine = points.iter().filter(|p| p.side == side);
            let (lines, wrong) = mine.fold((0, 0), |(n, w), p| (n + 1, w + usize::from(!p.ok)));
            title(side, lines, wrong)
        })
        .collect();
    t!("diagram-failure-about", panels = panels.join("; "))
}

/// The text size of a map `width` pixels wide: a line of a panel's title fits.
#[must_use]
pub(crate) fn text_size(width: f32) -> f32 {
    (width / 45.0).clamp(SMALLEST_TEXT, 20.0)
}

/// The height a map of `points` wants on a canvas `width` pixels wide: its caption, its
/// legend and a panel per side, each tall enough to read its errors.
#[must_use]
pub fn height(points: &[LinePoint], width: f32) -> f32 {
    let text = text_size(width);
    text * 5.0 + sides(points).max(1) as f32 * (text * 5.5 + 110.0)
}

/// A text of the map in its ink.
fn words(text: String, at: Vec2, h: Align, size: f32, palette: &Palette) -> Figure {
    Figure::Text(Label {
        text,
        at,
        h,
        v: Align::Start,
        size,
        colour: palette.ink,
        background: None,
    })
}

/// The failure map of `points` on a canvas of `size` pixels, in `palette`'s colours, as
/// primitives for any backend: a caption saying what the axes are, the legend, and a panel per
/// side that some line arrives from, stacked, sharing one error axis.
#[must_use]
pub fn primitives(
    points: &[LinePoint],
    size: Vec2,
    face: &Typeface,
    palette: &Palette,
) -> Vec<Primitive> {
    let mut figures = vec![Figure::Fill {
        points: Rect::from_min_size(Vec2::ZERO, size).corners().to_vec(),
        colour: palette.background,
    }];
    let sides = sides_of(points);
    let text = text_size(size.x);
    if sides.is_empty() {
        let empty = t!("diagram-failure-empty");
        figures.push(words(
            empty,
            Vec2::new(size.x / 2.0, text),
            Align::Center,
            text,
            palette,
        ));
        return lower_all(&figures);
    }
    let margin = text * 0.5;
    let caption = t!("diagram-failure-caption");
    let caption = super::placer::wrap(face, &caption, text, size.x - 2.0 * margin);
    let caption_height = face.measure(&caption, text).y;
    figures.push(words(
        caption,
        Vec2::splat(margin),
        Align::Start,
        text,
        palette,
    ));
    let at = Vec2::new(margin, margin + caption_height + text * 0.3);
    let (legend, legend_height) = legend_row(
        &entries(palette),
        at,
        size.x - 2.0 * margin,
        text,
        face,
        palette,
    );
    figures.extend(legend);
    let top = at.y + legend_height + text * 0.4;
    let band = (size.y - top) / sides.len() as f32;
    let largest = points.iter().map(|p| p.error_deg).fold(0.0, f64::max);
    // A tick label every two text lines at the most.
    let area_height = band - text * 5.0;
    let most = (area_height / (text * 2.0)).floor().clamp(1.0, 6.0) as usize;
    let y = Axis::from_zero(largest, 1.0, most);
    let x = Axis {
        min: 0.0,
        max: 90.0,
        step: if size.x < text * 40.0 { 30.0 } else { 15.0 },
    };
    for (i, side) in sides.iter().enumerate() {
        let band_top = top + band * i as f32;
        let chart = Chart {
            area: Rect {
                min: Vec2::new(text * 3.6, band_top + text * 2.3),
                max: Vec2::new(size.x - text * 1.2, band_top + band - text * 2.6),
            },
            x,
            y,
            text,
        };
        let mine: Vec<&LinePoint> = points.iter().filter(|p| p.side == *side).collect();
        let wrong = mine.iter().filter(|p| !p.ok).count();
        let heading = title(*side, mine.len(), wrong);
        let at = Vec2::new(margin, band_top + text * 0.2);
        figures.push(words(heading, at, Align::Start, text, palette));
        figures.extend(panel(&chart, &mine, palette));
    }
    lower_all(&figures)
}

/// One side's panel: its axes and its lines' markers, the right ones first, so that the wrong
/// ones lie on top.
fn panel(chart: &Chart, mine: &[&LinePoint], palette: &Palette) -> Vec<Figure> {
    let mut figures = chart.axes(("°", "°"), palette);
    let radius = (chart.text * 0.3).max(3.5);
    for ok in [true, false] {
        for point in mine.iter().filter(|p| p.ok == ok) {
            let center = chart.at(point.incidence_deg, point.error_deg);
            figures.extend(style(point, palette).figures(center, radius, palette.background));
        }
    }
    figures
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::primitive_texts;

    fn point(incidence_deg: f64, error_deg: f64, side: Side, ok: bool) -> LinePoint {
        LinePoint {
            incidence_deg,
            error_deg,
            side: Some(side),
            past_critical: incidence_deg > 41.8 && side == Side::Inside,
            ok,
        }
    }

    #[test]
    fn a_panel_per_side_says_how_many_of_its_lines_are_wrong() {
        // A pbrt log without its flip: every ray from inside wrong, every one from outside right.
        let points: Vec<LinePoint> = (0..30)
            .flat_map(|i| {
                let deg = f64::from(i) * 3.0;
                [
                    point(deg, 0.0, Side::Outside, true),
                    point(deg, 20.0 + deg / 3.0, Side::Inside, false),
                ]
            })
            .collect();
        let face = Typeface::egui_default();
        let size = Vec2::new(480.0, height(&points, 480.0));
        let drawn = primitives(&points, size, &face, &Palette::STANDARD);
        let words = primitive_texts(&drawn);
        assert!(
            words.contains(&"Arriving from outside: 30 lines, none wrong"),
            "{words:?}"
        );
        assert!(
            words.contains(&"Arriving from inside: 30 lines, 30 wrong"),
            "{words:?}"
        );
        assert!(
            words.iter().filter(|w| **w == "wrong").count() == 1,
            "one legend: {words:?}"
        );
        assert!(
            words[0].starts_with("How far"),
            "the caption first: {words:?}"
        );
        let wrong_markers = drawn
            .iter()
            .filter(
                |p| matches!(p, Primitive::Disc { fill, .. } if *fill == Palette::STANDARD.alarm),
            )
            .count();
        // The ones past the critical angle are squares (polygons), the rest discs.
        let past = points.iter().filter(|p| p.past_critical).count();
        assert_eq!(
            wrong_markers,
            30 - past + 1,
            "the wrong discs and the legend's sample"
        );
        assert!(drawn.iter().all(|p| match p {
            Primitive::Text(label) => label.size >= SMALLEST_TEXT,
            _ => true,
        }));
        // No text covers another, and every text lies inside the canvas.
        let canvas = Rect::from_min_size(Vec2::ZERO, size);
        let problems = crate::placer::text_problems(&drawn, &face, &canvas);
        assert!(problems.is_empty(), "{problems:?}");
    }

    #[test]
    fn a_log_without_judged_lines_says_so() {
        let face = Typeface::egui_default();
        let drawn = primitives(&[], Vec2::new(300.0, 200.0), &face, &Palette::STANDARD);
        assert_eq!(primitive_texts(&drawn), ["No line was judged."]);
    }
}

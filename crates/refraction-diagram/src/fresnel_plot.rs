//! The Fresnel view: how much light is reflected and transmitted against the angle of
//! incidence, for the current media, with Brewster's and the critical angle marked and the
//! current θi as a cursor. Every value comes from the kernel ([`refraction_kernel::Fresnel`]
//! of the kernel's own cosines), drawn as primitives for the screen and the exports alike.

use glam::{DVec3, Vec2};

use super::font::Typeface;
use super::geometry::{Colour, Rect};
use super::layout::SMALLEST_TEXT;
use super::numbers::{number, percent};
use super::palette::Palette;
use super::placer::wrap;
use super::plot::{Axis, Chart, LegendEntry, Sample, legend_column, legend_row};
use super::shapes::{Align, Dash, Figure, Label, Primitive, Stroke, lower_all};
use refraction_i18n::t;
use refraction_kernel::Fresnel;
use refraction_kernel::refract_facing;
use refraction_model::{ExplorerState, SpecialAngles};

/// Where the formula comes from, in words (in the current language), shown under the plot.
#[must_use]
pub(crate) fn source() -> String {
    t!("diagram-fresnel-source")
}

/// The angles of incidence sampled, in degrees: every quarter degree, and ever closer to the
/// critical angle, where R climbs to 1 with an infinite slope.
fn sample_angles(critical_deg: Option<f64>) -> Vec<f64> {
    let mut angles: Vec<f64> = (0..=360).map(|i| f64::from(i) * 0.25).collect();
    if let Some(c) = critical_deg {
        angles.extend((1..=30).map(|j| c - 0.25 * 0.5_f64.powi(j)));
        angles.push(c);
    }
    angles.sort_by(f64::total_cmp);
    angles.dedup();
    angles
}

/// The kernel's Fresnel fractions for μ = `μ_i/μ_t` at `degrees` (0 to 90) from the normal.
#[must_use]
pub(crate) fn fresnel_at(mu: f64, degrees: f64) -> Fresnel<f64> {
    let (sin, cos) = degrees.to_radians().sin_cos();
    let facing = refract_facing(DVec3::new(sin, -cos, 0.0), DVec3::Y, mu);
    facing.transmitted.map_or(Fresnel::TOTAL_REFLECTION, |t| {
        Fresnel::new(mu, facing.cos_i, t.cos_t)
    })
}

/// One curve of the plot.
#[derive(Clone, Debug, PartialEq)]
pub struct FresnelCurve {
    /// Its name in the legend, in the current language.
    pub name: String,
    /// (θi in degrees, fraction) from 0° to 90°.
    pub points: Vec<(f64, f64)>,
}

/// What a curve takes from the fractions at one angle.
type Share = fn(&Fresnel<f64>) -> f64;

/// The four curves' names and what each takes from the fractions.
const CURVES: [(fn() -> String, Share); 4] = [
    (|| t!("diagram-curve-rs"), |f| f.rs),
    (|| t!("diagram-curve-rp"), |f| f.rp),
    (|| t!("diagram-curve-r"), Fresnel::reflectance),
    (|| t!("diagram-curve-t"), Fresnel::transmittance),
];

/// What the Fresnel view shows for one state.
#[derive(Clone, Debug, PartialEq)]
pub struct FresnelPlot {
    /// `μ_i`, the index the ray comes from.
    pub mu_i: f64,
    /// `μ_t`, the index it enters.
    pub mu_t: f64,
    /// Brewster's and the critical angle.
    pub angles: SpecialAngles,
    /// Rs, Rp, unpolarised R and T against θi, in that order.
    pub curves: Vec<FresnelCurve>,
    /// The current angle of incidence, in degrees.
    pub cursor_deg: f64,
    /// The fractions at the cursor (the kernel's, for the state's own W and N).
    pub at_cursor: Fresnel<f64>,
}

impl FresnelPlot {
    /// The plot for `state`'s media, with the cursor at its θi.
    #[must_use]
    pub fn of(state: &ExplorerState) -> Self {
        let r = state.refraction();
        let angles = SpecialAngles::for_ratio(r.mu);
        let samples: Vec<(f64, Fresnel<f64>)> = sample_angles(angles.critical_deg)
            .into_iter()
            .map(|deg| (deg, fresnel_at(r.mu, deg)))
            .collect();
        let curves = CURVES
            .iter()
            .map(|(name, take)| FresnelCurve {
                name: name(),
                points: samples.iter().map(|(deg, f)| (*deg, take(f))).collect(),
            })
            .collect();
        Self {
            mu_i: state.mu_i(),
            mu_t: state.mu_t(),
            angles,
            curves,
            cursor_deg: r.cos_i.clamp(0.0, 1.0).acos().to_degrees(),
            at_cursor: Fresnel::of(r),
        }
    }
}

/// Where the plot sits on a canvas, and the map between angles, fractions and pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotFrame {
    /// The plotting area (0° at the left, 90° at the right; 0 at the bottom, 1 at the top).
    pub area: Rect,
    /// The text size, in pixels.
    pub text: f32,
    /// Whether the legend and the values at the cursor stand right of the plot (a wide
    /// canvas) rather than under it (a narrow strip beside the diagram).
    pub wide: bool,
}

/// The rows of text between the title and the plot: the two landmarks' names.
const ROWS_OF_NAMES: f32 = 3.5;

/// The plot's title, wrapped to `width` at text `size`.
fn title(plot: &FresnelPlot, face: &Typeface, size: f32, width: f32) -> String {
    let [mu_i, mu_t] = [plot.mu_i, plot.mu_t].map(|mu| refraction_i18n::decimal(&mu.to_string()));
    let title = t!("diagram-fresnel-title", mu_i = mu_i, mu_t = mu_t);
    wrap(face, &title, size, width)
}

/// The size of the words around the plot (the legend, the values, the source) for text
/// `text` pixels high.
fn small(text: f32) -> f32 {
    (text * 0.85).max(SMALLEST_TEXT)
}

/// The legend's entries for curves drawn with text `text` pixels high.
fn legend_entries(plot: &FresnelPlot, palette: &Palette, text: f32) -> Vec<LegendEntry> {
    plot.curves
        .iter()
        .zip(curve_strokes(palette, text))
        .map(|(curve, stroke)| LegendEntry {
            sample: Sample::Line(stroke),
            text: curve.name.clone(),
        })
        .collect()
}

/// The values at the cursor, as the view writes them.
fn cursor_values(plot: &FresnelPlot) -> [String; 5] {
    let a = plot.at_cursor;
    // No-break spaces inside each value: a line breaks between values, never in one.
    // untranslated: symbols and numbers, the same in every language.
    [
        format!("θi = {}°", number(plot.cursor_deg, 1)),
        format!("Rs = {}", percent(a.rs)), // untranslated: a symbol
        format!("Rp = {}", percent(a.rp)), // untranslated: a symbol
        format!("R = {}", percent(a.reflectance())),
        format!("T = {}", percent(a.transmittance())),
    ]
    .map(|value| value.replace(' ', "\u{a0}"))
}

/// The room the words take around the plot of `plot` on a canvas `width` pixels wide with
/// text `text` pixels high: above it (the title and the landmarks' names), under it (the
/// axis, the source and, when not `wide`, the legend and the values) and right of it (the
/// legend and the values when `wide`, in a column as wide as its widest line).
fn margins(
    plot: &FresnelPlot,
    width: f32,
    text: f32,
    wide: bool,
    face: &Typeface,
) -> (f32, f32, f32) {
    let line = width - text;
    let measure = |words: &str, size: f32| face.measure(&wrap(face, words, size, line), size).y;
    let source_height = measure(&source(), small(text));
    let entries = legend_entries(plot, &Palette::STANDARD, text);
    let under = if wide {
        text * 3.4 + source_height
    } else {
        let (_, legend) = legend_row(
            &entries,
            Vec2::ZERO,
            line,
            small(text),
            face,
            &Palette::STANDARD,
        );
        let values = measure(&cursor_values(plot).join("   "), small(text));
        text * 3.4 + legend + values + source_height + text * 1.2
    };
    let title = title(plot, face, text * 1.1, line);
    let above = text * 0.4 + face.measure(&title, text * 1.1).y + text * ROWS_OF_NAMES;
    let right = if wide {
        let legend = entries.iter().map(|e| e.width(small(text), face));
        let values = cursor_values(plot).map(|v| face.width(&v, text * 0.9));
        text * 2.2 + legend.chain(values).fold(0.0, f32::max)
    } else {
        text * 1.5
    };
    (above, under, right)
}

impl PlotFrame {
    /// The frame of `plot` on a canvas of `size` pixels, its words measured in `face`: text
    /// that reads at a glance (never under the projector rules' 13 px), the legend beside the
    /// plot where the canvas is wide enough, else the legend, the values and the source under
    /// it, each where the one before ends.
    #[must_use]
    pub fn new(plot: &FresnelPlot, size: Vec2, face: &Typeface) -> Self {
        let text = (size.y / 30.0).min(size.x / 34.0).clamp(13.0, 30.0);
        let wide = size.x >= text * 48.0;
        let (above, under, right) = margins(plot, size.x, text, wide, face);
        Self {
            area: Rect {
                min: Vec2::new(text * 4.4, above),
                max: Vec2::new(size.x - right, (size.y - under).max(above + text * 3.0)),
            },
            text,
            wide,
        }
    }

    /// The least height at which the plot of `plot` reads on a canvas `width` pixels wide:
    /// its words at their size, and a plotting area ten lines of text high.
    #[must_use]
    pub fn height_for(plot: &FresnelPlot, width: f32, face: &Typeface) -> f32 {
        let text = (width / 34.0).clamp(13.0, 30.0);
        let wide = width >= text * 48.0;
        let (above, under, _) = margins(plot, width, text, wide, face);
        above + under + text * 10.0
    }

    /// The chart of the frame: θi from 0° to 90°, the fraction from 0 to 100 %.
    fn chart(&self) -> Chart {
        let narrow = self.area.size().x < self.text * 30.0;
        Chart {
            area: self.area,
            x: Axis {
                min: 0.0,
                max: 90.0,
                step: if narrow { 30.0 } else { 10.0 },
            },
            y: Axis {
                min: 0.0,
                max: 100.0,
                step: 20.0,
            },
            text: self.text,
        }
    }

    /// The canvas point of (θi in degrees, fraction).
    #[must_use]
    pub fn at(&self, degrees: f64, fraction: f64) -> Vec2 {
        self.chart().at(degrees, fraction * 100.0)
    }

    /// The angle of incidence, in degrees within [0, 90], under the canvas x coordinate `x`.
    #[must_use]
    pub fn degrees_at(&self, x: f32) -> f64 {
        let (min, max) = (self.area.min.x, self.area.max.x);
        (f64::from((x - min) / (max - min)) * 90.0).clamp(0.0, 90.0)
    }
}

/// The style of each curve, in the order of [`FresnelPlot::curves`], for text `text` pixels
/// high: colour, dash and width, so that they differ without colour too.
#[must_use]
pub(crate) fn curve_strokes(palette: &Palette, text: f32) -> [Stroke; 4] {
    let width = (text / 7.0).max(2.0);
    [
        (palette.reflected, Dash::Solid, width),
        (palette.n, Dash::Dashed, width),
        (palette.ink, Dash::Solid, width * 1.6),
        (palette.t, Dash::DashDot, width * 1.3),
    ]
    .map(|(colour, dash, width)| Stroke {
        width,
        colour,
        dash,
    })
}

/// Draws the plot into figures.
struct PlotPainter<'a> {
    frame: PlotFrame,
    size: Vec2,
    /// Where the legend ends, on a narrow canvas (the values start there).
    below_legend: f32,
    face: &'a Typeface,
    palette: &'a Palette,
    shapes: Vec<Figure>,
}

impl PlotPainter<'_> {
    fn text(&mut self, text: String, at: Vec2, (h, v): (Align, Align), scale: f32, colour: Colour) {
        self.shapes.push(Figure::Text(Label {
            text,
            at,
            h,
            v,
            size: (self.frame.text * scale).max(SMALLEST_TEXT),
            colour,
            background: None,
        }));
    }

    fn line(&mut self, points: Vec<Vec2>, width: f32, colour: Colour, dash: Dash) {
        let stroke = Stroke {
            width,
            colour,
            dash,
        };
        self.shapes.push(Figure::Line { points, stroke });
    }

    /// The grid, the axes and their labels.
    fn axes(&mut self) {
        let f = self.frame;
        self.shapes
            .extend(f.chart().axes(("°", " %"), self.palette));
        let under = Vec2::new(f.area.center().x, f.area.max.y + f.text * 1.7);
        let axis = t!("diagram-fresnel-axis");
        let ink = self.palette.ink;
        self.text(axis, under, (Align::Center, Align::Start), 1.0, ink);
    }

    /// A vertical marker at `degrees` across the plot, and its name above the plot on text row
    /// `row` (0: nearer the plot), centred on the marker but kept inside the canvas, so that
    /// the line never strikes its own name and two names never share a row.
    fn marker(&mut self, degrees: f64, text: &str, colour: Colour, dash: Dash, row: f32) {
        let f = self.frame;
        let (bottom, top) = (f.at(degrees, 0.0), f.at(degrees, 1.0));
        self.line(vec![bottom, top], 2.0, colour, dash);
        // Measured at the size it is drawn at (never under the smallest text).
        let size = (f.text * 0.9).max(SMALLEST_TEXT);
        let width = self.face.width(text, size);
        let margin = f.text * 0.4;
        let x = (top.x - width / 2.0).clamp(margin, (self.size.x - margin - width).max(margin));
        // Clear of the 100 % tick label, whose middle is at the plot's top.
        let above = Vec2::new(x, top.y - f.text * (0.8 + 1.35 * row));
        let shade = self.palette.text_shade(colour);
        self.text(
            text.to_owned(),
            above,
            (Align::Start, Align::End),
            0.9,
            shade,
        );
    }

    /// The landmarks: Brewster's angle nearer the plot, the critical angle above it, each
    /// named in full where the name fits the canvas, else in short.
    fn landmarks(&mut self, plot: &FresnelPlot) {
        let palette = self.palette;
        let (room, face, size) = (
            self.size.x - self.frame.text,
            self.face,
            (self.frame.text * 0.9).max(SMALLEST_TEXT),
        );
        let name = |long: String, short: String| {
            if face.width(&long, size) <= room {
                long
            } else {
                short
            }
        };
        if let Some(b) = plot.angles.brewster_deg {
            let angle = number(b, 1);
            let text = name(
                t!("diagram-fresnel-brewster", angle = &angle),
                t!("diagram-fresnel-brewster-short", angle = &angle),
            );
            self.marker(b, &text, palette.n, Dash::Dashed, 0.0);
        }
        if let Some(c) = plot.angles.critical_deg {
            let angle = number(c, 1);
            let text = name(
                t!("diagram-fresnel-critical", angle = &angle),
                t!("diagram-fresnel-critical-short", angle = &angle),
            );
            self.marker(c, &text, palette.critical, Dash::DashDot, 1.0);
        }
    }

    /// The curves, and their legend beside the plot (wide) or under it (narrow).
    fn curves(&mut self, plot: &FresnelPlot) {
        let f = self.frame;
        let strokes = curve_strokes(self.palette, f.text);
        for (curve, stroke) in plot.curves.iter().zip(strokes) {
            let points = curve.points.iter().map(|&(d, v)| f.at(d, v)).collect();
            self.shapes.push(Figure::Line { points, stroke });
        }
        let entries = legend_entries(plot, self.palette, f.text);
        let size = small(f.text);
        let (legend, height) = if f.wide {
            let at = Vec2::new(f.area.max.x + f.text * 1.2, f.area.min.y);
            legend_column(&entries, at, size, self.face, self.palette)
        } else {
            let at = Vec2::new(f.text * 0.5, f.area.max.y + f.text * 3.4);
            legend_row(
                &entries,
                at,
                self.size.x - f.text,
                size,
                self.face,
                self.palette,
            )
        };
        self.below_legend = f.area.max.y + f.text * 3.4 + height;
        self.shapes.extend(legend);
    }

    /// The cursor at the current θi, with the fractions there beside the plot (wide) or on a
    /// line under the legend (narrow).
    fn cursor(&mut self, plot: &FresnelPlot) {
        let f = self.frame;
        let colour = self.palette.w;
        let deg = plot.cursor_deg;
        self.line(
            vec![f.at(deg, 0.0), f.at(deg, 1.0)],
            2.5,
            colour,
            Dash::Solid,
        );
        let a = plot.at_cursor;
        let values = [a.rs, a.rp, a.reflectance(), a.transmittance()];
        for (value, stroke) in values.into_iter().zip(curve_strokes(self.palette, f.text)) {
            self.shapes.push(Figure::Disc {
                center: f.at(deg, value),
                radius: f.text * 0.3,
                fill: stroke.colour,
                outline: Stroke {
                    width: 1.5,
                    colour: self.palette.background,
                    dash: Dash::Solid,
                },
            });
        }
        let parts = cursor_values(plot);
        let shade = self.palette.text_shade(colour);
        if f.wide {
            let at = Vec2::new(f.area.max.x + f.text * 1.2, f.area.min.y + f.text * 6.5);
            self.text(
                parts.join("\n"),
                at,
                (Align::Start, Align::Start),
                0.9,
                shade,
            );
        } else {
            let line = wrap(
                self.face,
                &parts.join("   "),
                small(f.text),
                self.size.x - f.text,
            );
            let at = Vec2::new(f.text * 0.5, self.below_legend + f.text * 0.3);
            self.text(line, at, (Align::Start, Align::Start), 0.85, shade);
        }
    }
}

/// The Fresnel view of `plot` on a canvas of `size`, in `palette`, back to front: the title,
/// the landmarks named above the plot, the curves, the cursor with the values there, the
/// legend (beside the plot on a wide canvas, under it on a narrow one) and the source.
#[must_use]
pub fn fresnel_plot(
    plot: &FresnelPlot,
    size: Vec2,
    face: &Typeface,
    palette: &Palette,
) -> Vec<Primitive> {
    let frame = PlotFrame::new(plot, size, face);
    let mut p = PlotPainter {
        frame,
        size,
        below_legend: 0.0,
        face,
        palette,
        shapes: vec![Figure::Fill {
            points: Rect::from_min_size(Vec2::ZERO, size).corners().to_vec(),
            colour: palette.background,
        }],
    };
    let title = title(plot, face, frame.text * 1.1, size.x - frame.text);
    let top = Vec2::new(size.x / 2.0, frame.text * 0.4);
    p.text(title, top, (Align::Center, Align::Start), 1.1, palette.ink);
    p.axes();
    p.landmarks(plot);
    p.curves(plot);
    p.cursor(plot);
    let size_small = (frame.text * 0.75).max(SMALLEST_TEXT);
    let source = wrap(face, &source(), size_small, size.x - frame.text);
    let bottom = Vec2::new(frame.text * 0.5, size.y - frame.text * 0.3);
    p.text(
        source,
        bottom,
        (Align::Start, Align::End),
        0.75,
        palette.ink,
    );
    lower_all(&p.shapes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette::Theme;
    use crate::shapes::primitive_texts;

    fn state(w: DVec3, mu_i: f64, mu_t: f64) -> ExplorerState {
        let mut s = ExplorerState::default();
        s.set_vectors(w, DVec3::Y).unwrap();
        s.set_mu_i(mu_i).unwrap();
        s.set_mu_t(mu_t).unwrap();
        s
    }

    #[test]
    fn the_curves_run_from_normal_incidence_to_grazing_with_their_landmarks() {
        let plot = FresnelPlot::of(&state(DVec3::new(0.6, -0.8, 0.0), 1.0, 1.5));
        assert_eq!(plot.curves.len(), 4);
        let rp = &plot.curves[1].points;
        let (first, last) = (rp[0], rp[rp.len() - 1]);
        assert_eq!((first.0, last.0), (0.0, 90.0));
        // Normal incidence: 4 %; grazing: everything reflected.
        assert!((first.1 - 0.04).abs() < 1e-12 && (last.1 - 1.0).abs() < 1e-12);
        // Rp dips to zero at Brewster's angle, and nowhere else.
        let brewster = plot.angles.brewster_deg.unwrap();
        assert!(fresnel_at(1.0 / 1.5, brewster).rp < 1e-20);
        let lowest = rp.iter().min_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
        assert!(
            (lowest.0 - brewster).abs() < 0.25,
            "{lowest:?} vs {brewster}"
        );
        assert!((plot.cursor_deg - 36.8699).abs() < 1e-3);
        for (r, t) in plot.curves[2].points.iter().zip(&plot.curves[3].points) {
            assert!((r.1 + t.1 - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn past_the_critical_angle_everything_is_reflected() {
        let plot = FresnelPlot::of(&state(DVec3::new(0.8, -0.6, 0.0), 1.5, 1.0));
        let critical = plot.angles.critical_deg.unwrap();
        let r = &plot.curves[2].points;
        assert!(r.iter().filter(|p| p.0 > critical).all(|p| p.1 == 1.0));
        // Sampled ever closer to θc: the steep climb is drawn, not cut off.
        let closest = r
            .iter()
            .filter(|p| p.0 < critical)
            .map(|p| critical - p.0)
            .fold(1.0, f64::min);
        assert!(closest < 1e-6, "{closest}");
        assert_eq!(plot.at_cursor, Fresnel::TOTAL_REFLECTION);
    }

    #[test]
    fn no_text_covers_another_wide_or_narrow_in_any_language() {
        // Issue 22: in "Glass → air beyond θc" the landmarks' names merged and their own
        // lines struck them through.
        let face = Typeface::egui_default();
        let plot_of = || FresnelPlot::of(&state(DVec3::new(0.8, -0.6, 0.0), 1.5, 1.0));
        for locale in refraction_i18n::Locale::ALL {
            refraction_i18n::set_locale(locale);
            let plot = plot_of();
            for size in [
                Vec2::new(225.0, 760.0),
                Vec2::new(385.0, 560.0),
                Vec2::new(430.0, 900.0),
                Vec2::new(1200.0, 330.0),
                Vec2::new(1280.0, 720.0),
            ] {
                let drawn = fresnel_plot(&plot, size, &face, &Palette::STANDARD);
                let canvas = Rect::from_min_size(Vec2::ZERO, size);
                let problems = crate::placer::text_problems(&drawn, &face, &canvas);
                assert!(problems.is_empty(), "{locale:?} {size}: {problems:?}");
                assert!(drawn.iter().all(|p| match p {
                    Primitive::Text(label) => label.size >= SMALLEST_TEXT,
                    _ => true,
                }));
            }
        }
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
    }

    #[test]
    fn the_view_names_its_landmarks_and_its_source_and_maps_x_to_angles() {
        let plot = FresnelPlot::of(&state(DVec3::new(0.3, -0.9, 0.0), 1.5, 1.0));
        let size = Vec2::new(1280.0, 720.0);
        let face = Typeface::egui_default();
        let primitives = fresnel_plot(&plot, size, &face, &Palette::new(Theme::Standard, false));
        let texts = primitive_texts(&primitives);
        for wanted in [
            "Brewster's angle θB = 33.7°",
            "critical angle θc = 41.8°",
            "Hecht",
            "Rp (",
            "θi\u{a0}=\u{a0}18.4°",
        ] {
            assert!(
                texts.iter().any(|t| t.contains(wanted)),
                "{wanted} in {texts:?}"
            );
        }
        let frame = PlotFrame::new(&plot, size, &face);
        assert!((frame.degrees_at(frame.at(41.0, 0.5).x) - 41.0).abs() < 1e-3);
        assert_eq!(frame.degrees_at(-100.0), 0.0);
        assert!(primitives.iter().all(|p| match p {
            Primitive::Polyline { points, .. } | Primitive::Polygon { points, .. } =>
                points.iter().all(|q| q.is_finite()),
            _ => true,
        }));
    }
}

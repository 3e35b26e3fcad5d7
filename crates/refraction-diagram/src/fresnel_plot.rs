//! The Fresnel view: how much light is reflected and transmitted against the angle of
//! incidence, for the current media, with Brewster's and the critical angle marked and the
//! current θi as a cursor. Every value comes from the kernel ([`refraction_kernel::Fresnel`]
//! of the kernel's own cosines), drawn as primitives for the screen and the exports alike.

use glam::{DVec3, Vec2};

use super::geometry::{Colour, Rect};
use super::numbers::number;
use super::palette::Palette;
use super::shapes::{Align, Dash, Figure, Label, Primitive, Stroke, lower_all};
use refraction_i18n::t;
use refraction_kernel::Fresnel;
use refraction_kernel::refract_facing;
use refraction_model::{ExplorerState, SpecialAngles};

/// Where the formula comes from, in words (in the current language), shown under the plot.
#[must_use]
pub fn source() -> String {
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
pub fn fresnel_at(mu: f64, degrees: f64) -> Fresnel<f64> {
    let (sin, cos) = degrees.to_radians().sin_cos();
    let facing = refract_facing(DVec3::new(sin, -cos, 0.0), DVec3::Y, mu);
    facing.transmitted.map_or(Fresnel::TOTAL_REFLECTION, |t| {
        Fresnel::new(mu, facing.cos_i, t.cos_t)
    })
}

/// One curve of the plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
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
    /// `R_s`, `R_p`, unpolarised R and T against θi, in that order.
    pub curves: Vec<Curve>,
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
            .map(|(name, take)| Curve {
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
}

impl PlotFrame {
    /// The frame for a canvas of `size` pixels.
    #[must_use]
    pub fn new(size: Vec2) -> Self {
        let text = (size.y / 45.0).clamp(12.0, 30.0);
        Self {
            area: Rect {
                min: Vec2::new(text * 4.5, text * 5.5),
                max: Vec2::new(size.x - text * 16.0, size.y - text * 7.0),
            },
            text,
        }
    }

    /// The canvas point of (θi in degrees, fraction).
    #[must_use]
    pub fn at(&self, degrees: f64, fraction: f64) -> Vec2 {
        let (min, max) = (self.area.min, self.area.max);
        Vec2::new(
            min.x + (max.x - min.x) * (degrees / 90.0) as f32,
            max.y - (max.y - min.y) * fraction.clamp(0.0, 1.0) as f32,
        )
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
pub fn curve_strokes(palette: &Palette, text: f32) -> [Stroke; 4] {
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
            size: self.frame.text * scale,
            colour,
            background: Some(self.palette.label_background),
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
        let grid = self.palette.guide.with_alpha(90);
        let ink = self.palette.ink;
        for step in 0..=9 {
            let deg = f64::from(step) * 10.0;
            self.line(vec![f.at(deg, 0.0), f.at(deg, 1.0)], 1.0, grid, Dash::Solid);
            let below = f.at(deg, 0.0) + Vec2::new(0.0, f.text * 0.4);
            self.text(
                format!("{deg}°"),
                below,
                (Align::Center, Align::Start),
                0.9,
                ink,
            );
        }
        for step in 0..=5 {
            let value = f64::from(step) * 0.2;
            self.line(
                vec![f.at(0.0, value), f.at(90.0, value)],
                1.0,
                grid,
                Dash::Solid,
            );
            let left = f.at(0.0, value) - Vec2::new(f.text * 0.5, 0.0);
            let text = format!("{} %", number(value * 100.0, 0));
            self.text(text, left, (Align::End, Align::Center), 0.9, ink);
        }
        let frame = vec![f.at(0.0, 1.0), f.at(0.0, 0.0), f.at(90.0, 0.0)];
        self.line(frame, 1.5, ink, Dash::Solid);
        let under = f.at(45.0, 0.0) + Vec2::new(0.0, f.text * 1.9);
        let axis = t!("diagram-fresnel-axis");
        self.text(axis, under, (Align::Center, Align::Start), 1.0, ink);
    }

    /// A vertical marker at `degrees`, named above the plot on text row `row`.
    fn marker(&mut self, degrees: f64, text: String, colour: Colour, dash: Dash, row: f32) {
        let f = self.frame;
        self.line(
            vec![f.at(degrees, 0.0), f.at(degrees, 1.0)],
            2.0,
            colour,
            dash,
        );
        let above = f.at(degrees, 1.0) - Vec2::new(0.0, f.text * (0.4 + 1.3 * row));
        let shade = self.palette.text_shade(colour);
        self.text(text, above, (Align::Center, Align::End), 0.85, shade);
    }

    /// The curves and their legend on the right.
    fn curves(&mut self, plot: &FresnelPlot) {
        let f = self.frame;
        let strokes = curve_strokes(self.palette, f.text);
        for (i, (curve, stroke)) in plot.curves.iter().zip(strokes).enumerate() {
            let points = curve.points.iter().map(|&(d, v)| f.at(d, v)).collect();
            self.shapes.push(Figure::Line { points, stroke });
            let y = f.area.min.y + f.text * (1.0 + 1.6 * i as f32);
            let x = f.area.max.x + f.text * 1.2;
            let sample = vec![Vec2::new(x, y), Vec2::new(x + f.text * 2.5, y)];
            self.shapes.push(Figure::Line {
                points: sample,
                stroke,
            });
            let at = Vec2::new(x + f.text * 3.0, y);
            let ink = self.palette.ink;
            self.text(
                curve.name.clone(),
                at,
                (Align::Start, Align::Center),
                0.8,
                ink,
            );
        }
    }

    /// The cursor at the current θi, with the fractions there.
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
        let text = format!(
            "θi = {}°\nR_s = {}\nR_p = {}\nR = {}\nT = {}",
            number(deg, 1),
            percent(a.rs),
            percent(a.rp),
            percent(a.reflectance()),
            percent(a.transmittance())
        );
        let at = Vec2::new(f.area.max.x + f.text * 1.2, f.area.min.y + f.text * 7.5);
        let shade = self.palette.text_shade(colour);
        self.text(text, at, (Align::Start, Align::Start), 0.9, shade);
    }
}

/// A power fraction as a percentage with one decimal, e.g. `4.0 %`.
#[must_use]
pub fn percent(fraction: f64) -> String {
    format!("{} %", number(fraction * 100.0, 1))
}

/// The Fresnel view of `plot` on a canvas of `size`, in `palette`, back to front.
#[must_use]
pub fn primitives(plot: &FresnelPlot, size: Vec2, palette: &Palette) -> Vec<Primitive> {
    let frame = PlotFrame::new(size);
    let mut p = PlotPainter {
        frame,
        palette,
        shapes: vec![Figure::Fill {
            points: vec![
                Vec2::ZERO,
                Vec2::new(size.x, 0.0),
                size,
                Vec2::new(0.0, size.y),
            ],
            colour: palette.background,
        }],
    };
    let [mu_i, mu_t] = [plot.mu_i, plot.mu_t].map(|mu| refraction_i18n::decimal(&mu.to_string()));
    let title = t!("diagram-fresnel-title", mu_i = mu_i, mu_t = mu_t);
    let top = Vec2::new(size.x / 2.0, frame.text * 0.5);
    p.text(title, top, (Align::Center, Align::Start), 1.2, palette.ink);
    p.axes();
    if let Some(b) = plot.angles.brewster_deg {
        let text = t!("diagram-fresnel-brewster", angle = number(b, 1));
        p.marker(b, text, palette.n, Dash::Dashed, 0.0);
    }
    if let Some(c) = plot.angles.critical_deg {
        let text = t!("diagram-fresnel-critical", angle = number(c, 1));
        p.marker(c, text, palette.critical, Dash::DashDot, 1.0);
    }
    p.curves(plot);
    p.cursor(plot);
    let bottom = Vec2::new(frame.text, size.y - frame.text * 0.5);
    p.text(
        source(),
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
    use crate::shapes::texts;

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
        // R_p dips to zero at Brewster's angle, and nowhere else.
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
    fn the_view_names_its_landmarks_and_its_source_and_maps_x_to_angles() {
        let plot = FresnelPlot::of(&state(DVec3::new(0.3, -0.9, 0.0), 1.5, 1.0));
        let size = Vec2::new(1280.0, 720.0);
        let primitives = primitives(&plot, size, &Palette::new(Theme::Standard, false));
        let texts = texts(&primitives);
        for wanted in [
            "Brewster's angle θB = 33.7°",
            "critical angle θc = 41.8°",
            "Hecht",
            "R_p (",
            "θi = 18.4°",
        ] {
            assert!(
                texts.iter().any(|t| t.contains(wanted)),
                "{wanted} in {texts:?}"
            );
        }
        let frame = PlotFrame::new(size);
        assert!((frame.degrees_at(frame.at(41.0, 0.5).x) - 41.0).abs() < 1e-3);
        assert_eq!(frame.degrees_at(-100.0), 0.0);
        assert!(primitives.iter().all(|p| match p {
            Primitive::Polyline { points, .. } | Primitive::Polygon { points, .. } =>
                points.iter().all(|q| q.is_finite()),
            _ => true,
        }));
    }
}

//! Why it bends: plane wavefronts arriving and leaving the interface, λ/μ apart in each medium
//! and moving at c/μ, and Huygens's construction of the transmitted front.
//!
//! The transmitted fronts are not drawn from the kernel's T: they are built as Huygens did.
//! Two points B and A on the surface, L apart, are reached by one incoming front a time
//! Δt = `L·sinθi/v_i` apart; in that time the wavelet from B grows to r = `v_t·Δt` in the second
//! medium, and the new front is the tangent from A to that wavelet. Its normal (from B to the
//! point of tangency) makes cosα = r/L with the surface, and the test below checks that it is
//! the kernel's T. When r > L there is no tangent: total internal reflection, and the fronts
//! leave by the reflected ray instead.

use glam::{DVec2, Vec2};

use super::geometry::{Colour, arc, clip_segment};
use super::layout::Layout;
use super::numbers::number;
use super::palette::Palette;
use super::shapes::{Align, Dash, Figure, Label, Stroke};
use refraction_i18n::t;
use refraction_model::ExplorerState;

/// How far from the hit point the fronts are drawn, in world units (W, N and T are 1 long).
pub(crate) const EXTENT: f64 = 1.3;

/// The distance between B and A in Huygens's construction, in world units.
const HUYGENS_BASE: f64 = 0.8;

/// The spacing of the fronts in the medium of lower index, in world units: the other medium's
/// are closer by the ratio of the indices.
const WIDEST_SPACING: f64 = 0.22;

/// What the *Wavefronts* switch shows.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WaveOptions {
    /// Where in one period the fronts are, 0 to 1: the fronts move by their own spacing in each
    /// medium over one period, so frames at phases 0 to 1 loop.
    pub phase: f64,
    /// Whether Huygens's construction is highlighted.
    pub huygens: bool,
}

/// Huygens's construction at the hit point: B at the hit point, A on the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Huygens {
    /// Where the front reaches the surface first (the hit point).
    pub b: DVec2,
    /// Where the same front reaches the surface Δt later.
    pub a: DVec2,
    /// Where the front was, on its way to A, when it reached B.
    pub start: DVec2,
    /// How far the wavelet from B has grown in the second medium when the front reaches A.
    pub radius: f64,
    /// Where the tangent from A touches the wavelet: `None` when the wavelet outgrows the base
    /// (total internal reflection).
    pub touch: Option<DVec2>,
}

/// One family of parallel fronts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Fronts {
    /// The unit direction the fronts move in (their normal), in diagram coordinates.
    pub normal: DVec2,
    /// The distance between neighbouring fronts, in world units: λ/μ of the medium.
    pub spacing: f64,
    /// The index of the medium they move in.
    pub index: f64,
    /// Which side of the surface: +1 the ray's medium, −1 the one it enters.
    pub side: f64,
}

/// The waves of one refraction, in diagram coordinates (the hit point at the origin).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Waves {
    /// The unit normal of the surface, facing the incoming ray.
    pub surface_normal: DVec2,
    /// The arriving fronts.
    pub arriving: Fronts,
    /// The leaving fronts: transmitted, or reflected on total internal reflection.
    pub leaving: Fronts,
    /// Whether the leaving fronts are the reflected ones.
    pub reflected: bool,
    /// Huygens's construction; `None` at normal incidence, where every point of a front
    /// reaches the surface at once.
    pub huygens: Option<Huygens>,
}

impl Waves {
    /// The waves of `state`'s refraction.
    #[must_use]
    pub(crate) fn of(state: &ExplorerState) -> Self {
        let r = state.refraction();
        let flat = |v| state.plane().project(v).normalize_or(DVec2::X);
        let n = flat(r.facing_normal);
        let d = flat(r.travel);
        let (mu_i, mu_t) = (state.mu_i(), state.mu_t());
        let vacuum = WIDEST_SPACING * mu_i.min(mu_t);
        let arriving = Fronts {
            normal: d,
            spacing: vacuum / mu_i,
            index: mu_i,
            side: 1.0,
        };
        let huygens = huygens(d, n, mu_i, mu_t);
        let transmitted = huygens.and_then(|h| h.touch.map(|q| (q - h.b) / h.radius));
        let sin_i = d.perp_dot(n).abs();
        let (leaving, reflected) = match transmitted {
            Some(normal) => (normal, false),
            // Normal incidence transmits straight on, the only case without a construction.
            None if sin_i == 0.0 && !r.is_tir() => (d, false),
            None => (flat(r.reflected), true),
        };
        let (index, side) = if reflected { (mu_i, 1.0) } else { (mu_t, -1.0) };
        Self {
            surface_normal: n,
            arriving,
            leaving: Fronts {
                normal: leaving,
                spacing: vacuum / index,
                index,
                side,
            },
            reflected,
            huygens,
        }
    }
}

/// Huygens's construction for travel direction `d` at a surface with facing normal `n`.
fn huygens(d: DVec2, n: DVec2, mu_i: f64, mu_t: f64) -> Option<Huygens> {
    let along = (d - n * d.dot(n)).try_normalize()?;
    let b = DVec2::ZERO;
    let a = along * HUYGENS_BASE;
    // The front through B reaches A after travelling the part of BA along d.
    let travelled = (a - b).dot(d);
    let start = a - d * travelled;
    // Speeds c/μ: the wavelet covers travelled·v_t/v_i = travelled·μ_i/μ_t meanwhile.
    let radius = travelled * mu_i / mu_t;
    let cos_alpha = radius / HUYGENS_BASE;
    let touch = (cos_alpha <= 1.0).then(|| {
        let sin_alpha = (1.0 - cos_alpha * cos_alpha).max(0.0).sqrt();
        b + (along * cos_alpha - n * sin_alpha) * radius
    });
    (travelled > 0.0).then_some(Huygens {
        b,
        a,
        start,
        radius,
        touch,
    })
}

/// The piece of the line {p : p·normal = offset} within [`EXTENT`] of the hit point and on
/// `side` of the surface (`p·surface_normal` has the sign of `side`), if any.
fn chord(normal: DVec2, offset: f64, surface_normal: DVec2, side: f64) -> Option<(DVec2, DVec2)> {
    let half = (EXTENT * EXTENT - offset * offset).sqrt();
    if half.is_nan() || half <= 0.0 {
        return None;
    }
    let centre = normal * offset;
    let (mut a, mut b) = (centre - normal.perp() * half, centre + normal.perp() * half);
    let height = |p: DVec2| p.dot(surface_normal) * side;
    let (ha, hb) = (height(a), height(b));
    if ha < 0.0 && hb < 0.0 {
        return None;
    }
    if ha < 0.0 || hb < 0.0 {
        let crossing = a + (b - a) * (ha / (ha - hb));
        if ha < 0.0 {
            a = crossing;
        } else {
            b = crossing;
        }
    }
    Some((a, b))
}

/// The figures and labels of the *Wavefronts* switch.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct WaveLayer {
    /// The fronts and the construction, to draw under the rays.
    pub shapes: Vec<Figure>,
    /// What they are, to place with the diagram's other labels.
    pub labels: Vec<Label>,
}

/// Draws the waves on a laid-out canvas.
struct Painter<'a> {
    layout: &'a Layout,
    palette: &'a Palette,
    layer: WaveLayer,
}

impl Painter<'_> {
    fn at(&self, world: DVec2) -> Vec2 {
        self.layout.view.to_canvas(world)
    }

    fn stroke(&self, width: f32, colour: Colour, dash: Dash) -> Stroke {
        Stroke {
            width: width * self.layout.unit(),
            colour,
            dash,
        }
    }

    fn line(&mut self, a: DVec2, b: DVec2, stroke: Stroke) {
        if let Some((a, b)) = clip_segment(self.at(a), self.at(b), &self.layout.drawing) {
            self.layer.shapes.push(Figure::Line {
                points: vec![a, b],
                stroke,
            });
        }
    }

    fn label(&mut self, text: String, world: DVec2, colour: Colour, size: f32) {
        let away = self.layout.view.direction(world.normalize_or(DVec2::Y));
        self.layer.labels.push(Label {
            text,
            at: self.at(world),
            h: Align::away(away.x),
            v: Align::away(away.y),
            size: self.layout.text_size(size),
            colour: self.palette.text_shade(colour),
            background: Some(self.palette.label_background),
        });
    }

    /// One family of fronts at `phase`, and its label: spacing and speed.
    fn fronts(&mut self, fronts: &Fronts, surface_normal: DVec2, phase: f64, colour: Colour) {
        let stroke = self.stroke(1.4, colour.with_alpha(200), Dash::Solid);
        let count = (EXTENT / fronts.spacing).ceil() as i64;
        for k in -count..=count {
            let offset = (k as f64 + phase) * fronts.spacing;
            if let Some((a, b)) = chord(fronts.normal, offset, surface_normal, fronts.side) {
                self.line(a, b, stroke);
            }
        }
        let index = number(fronts.index, 2);
        let speed = number(1.0 / fronts.index, 2);
        let text = t!("diagram-fronts", index = index, speed = speed);
        let at = fronts.normal.perp() * (EXTENT * 0.75) + surface_normal * fronts.side * 0.35;
        self.label(text, at, colour, 0.8);
    }

    /// Huygens's construction, highlighted.
    fn huygens(&mut self, h: &Huygens, surface_normal: DVec2) {
        let halo = self.stroke(9.0, self.palette.highlight, Dash::Solid);
        let ink = self.stroke(1.8, self.palette.ink, Dash::Dashed);
        self.line(h.start, h.a, halo);
        self.line(h.start, h.a, ink);
        self.line(h.start, h.b, ink);
        let centre = self.at(h.b);
        let radius = h.radius as f32 * self.layout.view.scale;
        let into = self.layout.view.direction(-surface_normal);
        // The half of the wavelet in the second medium, as two quarters (one half-turn would
        // leave the arc's direction of turning undecided).
        let mut points = arc(centre, radius, into.perp(), into);
        points.extend(arc(centre, radius, into, -into.perp()).into_iter().skip(1));
        let wavelet = self.stroke(2.0, self.palette.t, Dash::Dotted);
        self.layer.shapes.push(Figure::Line {
            points,
            stroke: wavelet,
        });
        let text = match h.touch {
            Some(q) => {
                self.line(h.a, q, halo);
                self.line(h.a, q, self.stroke(2.2, self.palette.t, Dash::Solid));
                self.line(h.b, q, ink);
                t!("diagram-huygens-touch")
            }
            None => t!("diagram-huygens-tir"),
        };
        for (point, name) in [(h.b, "B"), (h.a, "A")] {
            self.label(
                name.to_owned(),
                point + surface_normal * 0.06,
                self.palette.ink,
                0.9,
            );
        }
        // Beyond A (clear of its name), just above the surface: the rays and ghosts leave the
        // hit point steeply there, while the incoming side is crowded with W, θi and the
        // candidates.
        let along = (h.a - h.b).normalize_or(surface_normal.perp());
        let at = h.a + along * 0.22 + surface_normal * 0.1;
        self.label(text, at, self.palette.ink, 0.8);
    }
}

/// The *Wavefronts* layer for `state` on `layout`, in `palette`, with `options`.
#[must_use]
pub(crate) fn layer(
    state: &ExplorerState,
    layout: &Layout,
    palette: &Palette,
    options: &WaveOptions,
) -> WaveLayer {
    let waves = Waves::of(state);
    let mut painter = Painter {
        layout,
        palette,
        layer: WaveLayer::default(),
    };
    let phase = options.phase.rem_euclid(1.0);
    painter.fronts(
        &waves.arriving,
        waves.surface_normal,
        phase,
        palette.incoming,
    );
    let leaving = if waves.reflected {
        palette.reflected
    } else {
        palette.t
    };
    painter.fronts(&waves.leaving, waves.surface_normal, phase, leaving);
    if let Some(h) = waves.huygens.filter(|_| options.huygens) {
        painter.huygens(&h, waves.surface_normal);
    }
    painter.layer
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::palette::Theme;
    use glam::DVec3;

    fn state(w: DVec3, mu_i: f64, mu_t: f64) -> ExplorerState {
        let mut s = ExplorerState::default();
        s.set_vectors(w, DVec3::Y).unwrap();
        s.set_mu_i(mu_i).unwrap();
        s.set_mu_t(mu_t).unwrap();
        s
    }

    #[test]
    fn the_normal_to_the_transmitted_fronts_is_the_kernels_t() {
        for (w, mu_i, mu_t) in [
            (DVec3::new(0.6, -0.8, 0.0), 1.0, 1.5),
            (DVec3::new(0.3, -0.9, 0.2), 1.5, 1.0),
            (DVec3::new(-0.9, -0.1, 0.0), 1.0, 2.4),
            (DVec3::new(0.5, -0.5, 0.0), 1.33, 1.0),
        ] {
            let s = state(w, mu_i, mu_t);
            let waves = Waves::of(&s);
            let t = s.refraction().t().unwrap();
            let expected = s.plane().project(t).normalize();
            assert!(!waves.reflected);
            let error = waves.leaving.normal.angle_to(expected).abs();
            assert!(error < 1e-12, "{w} {mu_i}→{mu_t}: {error:e} rad off T");
            // λ/μ in each medium: the fronts are closer in the denser one, by the index ratio.
            let ratio = waves.arriving.spacing / waves.leaving.spacing;
            assert!((ratio - mu_t / mu_i).abs() < 1e-12);
        }
    }

    #[test]
    fn past_the_critical_angle_the_wavelet_outgrows_the_base_and_fronts_reflect() {
        let s = state(DVec3::new(0.8, -0.6, 0.0), 1.5, 1.0);
        let waves = Waves::of(&s);
        let h = waves.huygens.unwrap();
        assert!(h.touch.is_none() && h.radius > HUYGENS_BASE);
        assert!(waves.reflected);
        let expected = s.plane().project(s.refraction().reflected).normalize();
        assert!(waves.leaving.normal.angle_to(expected).abs() < 1e-12);
    }

    #[test]
    fn fronts_meet_on_the_surface_for_every_front() {
        // Continuity: where a transmitted front meets the surface, an arriving one does too.
        let s = state(DVec3::new(0.6, -0.8, 0.0), 1.0, 1.5);
        let w = Waves::of(&s);
        let along = w.surface_normal.perp();
        // Where front k + phase meets the surface, measured along it, for both families.
        let meet = |f: &Fronts, k: f64| k * f.spacing / f.normal.dot(along);
        for k in [-2.0, 0.5, 3.0] {
            assert!((meet(&w.arriving, k) - meet(&w.leaving, k)).abs() < 1e-12);
        }
    }

    #[test]
    fn the_layer_draws_fronts_in_both_media_and_names_their_speeds() {
        let s = state(DVec3::new(0.6, -0.8, 0.0), 1.0, 1.5);
        let layout = Layout::new(Vec2::new(1280.0, 720.0));
        let options = WaveOptions {
            phase: 0.25,
            huygens: true,
        };
        let layer = layer(&s, &layout, &Palette::new(Theme::Standard, false), &options);
        assert!(layer.shapes.len() > 12, "{} shapes", layer.shapes.len());
        let texts: Vec<_> = layer.labels.iter().map(|l| l.text.as_str()).collect();
        assert!(
            texts.iter().any(|t| t.contains("c/1.50 = 0.67 c")),
            "{texts:?}"
        );
        assert!(
            texts.iter().any(|t| t.contains("c/1.00 = 1.00 c")),
            "{texts:?}"
        );
        assert!(texts.iter().any(|t| t.starts_with("Huygens")), "{texts:?}");
        // A later phase moves the fronts: not one line stays where it was.
        let later = super::layer(
            &s,
            &layout,
            &Palette::new(Theme::Standard, false),
            &WaveOptions::default(),
        );
        assert_ne!(later.shapes, layer.shapes);
    }

    #[test]
    fn normal_incidence_has_no_construction_and_goes_straight_on() {
        let s = state(DVec3::new(0.0, -1.0, 0.0), 1.0, 1.5);
        let waves = Waves::of(&s);
        assert!(waves.huygens.is_none() && !waves.reflected);
        assert!((waves.leaving.normal - waves.arriving.normal).length() < 1e-15);
    }
}

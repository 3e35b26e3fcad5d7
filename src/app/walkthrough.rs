//! The guided walk through the paper's derivation: one step at a time with its equations and
//! live numbers (from [`refraction_diagram::walkthrough_steps`]), the diagram highlighting
//! what the step is about, and the "animate μ → 1" morph that shows why the paper picks its signs.

use egui::{Button, Context, RichText, Ui};
use refraction_i18n::t;

use refraction_diagram::{Focus, walkthrough_steps};
use refraction_model::ExplorerState;

/// How long the μ → 1 morph takes, in seconds.
pub(super) const MORPH_SECONDS: f32 = 3.0;

/// Smoothstep: starts and ends gently, so the class sees both ends of the morph.
#[must_use]
pub(super) fn ease(s: f32) -> f32 {
    let s = if s.is_nan() { 0.0 } else { s.clamp(0.0, 1.0) };
    s * s * (3.0 - 2.0 * s)
}

/// A value moving from `from` to `to` over `duration` seconds along [`ease`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Morph {
    from: f64,
    to: f64,
    elapsed: f32,
    duration: f32,
}

impl Morph {
    /// A morph from `from` to `to` lasting `duration` seconds (at least one frame).
    #[must_use]
    pub(super) fn new(from: f64, to: f64, duration: f32) -> Self {
        Self {
            from,
            to,
            elapsed: 0.0,
            duration: duration.max(1e-3),
        }
    }

    /// Moves `dt` seconds on (negative or NaN time is ignored) and returns the value there:
    /// exactly `to` at the end.
    pub(super) fn advance(&mut self, dt: f32) -> f64 {
        if dt > 0.0 {
            self.elapsed = (self.elapsed + dt).min(self.duration);
        }
        if self.done() {
            return self.to;
        }
        let s = f64::from(ease(self.elapsed / self.duration));
        self.from + (self.to - self.from) * s
    }

    /// Whether the morph has reached its end.
    #[must_use]
    pub(super) fn done(&self) -> bool {
        self.elapsed >= self.duration
    }
}

/// The walk-through's place and its running morph.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct WalkThrough {
    /// The step shown (0-based).
    pub step: usize,
    morph: Option<Morph>,
}

impl WalkThrough {
    /// What the diagram highlights for the step shown.
    #[must_use]
    pub(super) fn focus(&self, state: &ExplorerState) -> Option<Focus> {
        walkthrough_steps(state.refraction())
            .get(self.step)
            .map(|s| s.focus)
    }

    /// Whether the μ → 1 morph is running.
    #[must_use]
    pub(super) fn animating(&self) -> bool {
        self.morph.is_some()
    }

    /// Starts morphing `μ_t` to `μ_i`, so that μ = `μ_i/μ_t` goes to 1.
    pub(super) fn start_morph(&mut self, state: &ExplorerState) {
        self.morph = Some(Morph::new(state.mu_t(), state.mu_i(), MORPH_SECONDS));
    }

    /// Moves a running morph on by this frame's time and asks for the next frame.
    pub(super) fn animate(&mut self, ctx: &Context, state: &mut ExplorerState) {
        let Some(morph) = self.morph.as_mut() else {
            return;
        };
        let dt = ctx.input(|i| i.stable_dt);
        // Indices between μ_t and μ_i are as valid as the two ends: the kernel cannot refuse.
        state.set_mu_t(morph.advance(dt)).ok();
        if morph.done() {
            self.morph = None;
        } else {
            ctx.request_repaint();
        }
    }

    /// The step with its equations and the buttons to move on.
    pub(super) fn show(&mut self, ui: &mut Ui, state: &ExplorerState) {
        let all = walkthrough_steps(state.refraction());
        self.step = self.step.min(all.len() - 1);
        ui.horizontal_wrapped(|ui| {
            if ui
                .add_enabled(
                    self.step > 0,
                    Button::new(format!("◀ {}", t!("walk-previous"))),
                )
                .clicked()
            {
                self.step -= 1;
            }
            if ui
                .add_enabled(
                    self.step + 1 < all.len(),
                    Button::new(format!("{} ▶", t!("walk-next"))),
                )
                .clicked()
            {
                self.step += 1;
            }
            let label = if self.animating() {
                t!("walk-animating")
            } else {
                t!("walk-animate")
            };
            let can_morph = !self.animating() && state.mu_i() != state.mu_t();
            if ui
                .add_enabled(can_morph, Button::new(label))
                .on_hover_text(t!("walk-animate-hover"))
                .on_disabled_hover_text(t!("walk-animate-disabled"))
                .clicked()
            {
                self.start_morph(state);
            }
        });
        // The buttons may have moved on: show the step now selected.
        let step = &all[self.step];
        ui.label(
            RichText::new(t!(
                "walk-step",
                number = self.step + 1,
                count = all.len(),
                title = &step.title
            ))
            .strong(),
        );
        for eq in &step.equations {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(format!("({})  {}", eq.number, eq.formula)).strong());
                ui.label(RichText::new(&eq.substituted).monospace());
            });
        }
        ui.label(&step.explanation);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_morph_eases_and_ends_exactly_on_its_target() {
        assert_eq!(ease(0.0), 0.0);
        assert_eq!(ease(1.0), 1.0);
        assert_eq!(ease(0.5), 0.5);
        assert!(ease(0.1) < 0.1 && ease(0.9) > 0.9);
        assert_eq!(ease(f32::NAN), 0.0);
        let mut morph = Morph::new(1.5, 1.000293, 1.0);
        let early = morph.advance(0.25);
        assert!(early < 1.5 && early > 1.25, "{early}");
        assert_eq!(morph.advance(f32::NAN), early);
        assert!(!morph.done());
        assert_eq!(morph.advance(5.0), 1.000293);
        assert!(morph.done());
    }

    #[test]
    fn morphing_mu_to_one_turns_t_into_the_incoming_ray() {
        let mut state = ExplorerState::default();
        let mut walk = WalkThrough::default();
        walk.start_morph(&state);
        let ctx = Context::default();
        for _ in 0..400 {
            let mut output = ctx.run_ui(egui::RawInput::default(), |ui| {
                walk.animate(ui.ctx(), &mut state);
            });
            output.textures_delta.clear();
        }
        assert!(!walk.animating());
        let r = state.refraction();
        assert_eq!(r.t(), Some(r.travel));
    }
}

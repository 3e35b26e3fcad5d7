//! The top bar's *Effects* menu, the one-interface diagram's switches: *Intensities* (the rays by
//! their share of s, p or unpolarised light) and *Wavefronts* (the fronts λ/μ apart, moving at
//! c/μ when asked, Huygens's construction highlighted when asked). Each effect is drawn only
//! while its switch is on; the diagram model draws them ([`Overlay::intensities`],
//! [`Overlay::waves`]), so the exports show them too.
//!
//! [`Overlay::intensities`]: refraction_diagram::Overlay::intensities
//! [`Overlay::waves`]: refraction_diagram::Overlay::waves

use egui::containers::menu::{MenuButton, MenuConfig};
use egui::{Button, Context, PopupCloseBehavior, Ui};
use refraction_i18n::t;

use refraction_diagram::WaveOptions;
use refraction_model::Polarisation;

/// The *Effects* menu's icon in presentation's bar.
const EFFECTS_ICON: &str = "✨";

/// How long the fronts take to move by one spacing, in seconds: slow enough to follow one.
pub(super) const WAVE_PERIOD_SECONDS: f64 = 2.0;

/// The switches and the fronts' phase.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct EffectsMenu {
    /// The *Intensities* switch.
    pub intensities: bool,
    /// The light the shares are for.
    pub polarisation: Polarisation,
    /// The *Wavefronts* switch.
    pub waves: bool,
    /// Whether the fronts move.
    pub moving: bool,
    /// Whether Huygens's construction is drawn.
    pub huygens: bool,
    /// Where in one period the fronts are, 0 to 1.
    phase: f64,
}

impl EffectsMenu {
    /// Starts the effects of a lesson preset afresh: what the lesson is about and nothing the
    /// last one turned on. At Brewster's angle, the rays by their share of p light (the
    /// reflected one vanishes), so that the preset shows Brewster's angle; every other preset
    /// with no effect (the next preset kept Brewster's p-light shares).
    pub(super) fn start(&mut self, lesson: refraction_model::Lesson) {
        let brewster = lesson == refraction_model::Lesson::Brewster;
        self.intensities = brewster;
        self.polarisation = if brewster {
            Polarisation::P
        } else {
            Polarisation::Unpolarised
        };
        self.waves = false;
    }

    /// The light the rays are drawn for, while *Intensities* is on.
    #[must_use]
    pub(super) fn intensities(&self) -> Option<Polarisation> {
        self.intensities.then_some(self.polarisation)
    }

    /// The fronts to draw, while *Wavefronts* is on.
    #[must_use]
    pub(super) fn waves(&self) -> Option<WaveOptions> {
        self.waves.then_some(WaveOptions {
            phase: self.phase,
            huygens: self.huygens,
        })
    }

    /// Moves the fronts on by this frame's time while they move, and asks for the next frame.
    pub(super) fn animate(&mut self, ctx: &Context) {
        if !(self.waves && self.moving) {
            return;
        }
        let dt = f64::from(ctx.input(|i| i.stable_dt));
        if dt.is_finite() && dt > 0.0 {
            self.phase = (self.phase + dt / WAVE_PERIOD_SECONDS).rem_euclid(1.0);
        }
        ctx.request_repaint();
    }

    /// The *Effects* menu for the top bar (one button, so that the bar keeps its rows on a
    /// projector): the two switches, and each switch's options while it is on. The button
    /// shows selected while an effect is on; the menu stays open until a click outside it.
    ///
    /// In presentation (`compact`), where the bar keeps one row in every language, the button
    /// shows its icon; its name stays its accessible name and leads its hover.
    pub(super) fn menu(&mut self, ui: &mut Ui, compact: bool) {
        let on = self.intensities || self.waves;
        let name = t!("effects-menu");
        let shown = if compact { EFFECTS_ICON } else { name.as_str() };
        let button = Button::new(shown).selected(on);
        let config = MenuConfig::new().close_behavior(PopupCloseBehavior::CloseOnClickOutside);
        let (response, _) = MenuButton::from_button(button)
            .config(config)
            .ui(ui, |ui| self.switches(ui));
        response.widget_info(|| egui::WidgetInfo::selected(egui::Role::Button, true, on, &name));
        let hover = t!("effects-menu-hover");
        if compact {
            response.on_hover_text(format!("{name}: {hover}"));
        } else {
            response.on_hover_text(hover);
        }
    }

    /// The switches and their options, one under the other, each on one line: the menu is as
    /// wide as its longest (a menu as narrow as its first switch broke "Construction de
    /// Huygens" inside its words on a projector).
    fn switches(&mut self, ui: &mut Ui) {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        ui.toggle_value(&mut self.intensities, t!("effects-intensities"))
            .on_hover_text(t!("effects-intensities-hover"));
        if self.intensities {
            ui.horizontal(|ui| {
                for p in Polarisation::ALL {
                    ui.radio_value(&mut self.polarisation, p, p.label());
                }
            });
        }
        ui.separator();
        ui.toggle_value(&mut self.waves, t!("effects-wavefronts"))
            .on_hover_text(t!("effects-wavefronts-hover"));
        if self.waves {
            ui.checkbox(&mut self.moving, t!("effects-moving"));
            ui.checkbox(&mut self.huygens, t!("effects-huygens"))
                .on_hover_text(t!("effects-huygens-hover"));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_effect_is_drawn_only_while_its_switch_is_on_and_the_fronts_move_when_asked() {
        let mut effects = EffectsMenu::default();
        assert_eq!((effects.intensities(), effects.waves()), (None, None));
        effects.polarisation = Polarisation::P;
        effects.intensities = true;
        assert_eq!(effects.intensities(), Some(Polarisation::P));
        effects.waves = true;
        let ctx = Context::default();
        let frame = |effects: &mut EffectsMenu| {
            let input = egui::RawInput {
                predicted_dt: 0.5,
                ..Default::default()
            };
            let mut output = ctx.run_ui(input, |ui| effects.animate(ui.ctx()));
            output.textures_delta.clear();
        };
        frame(&mut effects);
        assert_eq!(effects.waves().map(|w| w.phase), Some(0.0), "still fronts");
        effects.moving = true;
        frame(&mut effects);
        frame(&mut effects);
        let phase = effects.waves().unwrap().phase;
        assert!(phase > 0.0 && phase < 1.0, "{phase}");
    }

    #[test]
    fn a_preset_starts_with_its_own_effects_and_none_of_the_last_ones() {
        use refraction_model::Lesson;
        let mut effects = EffectsMenu::default();
        effects.start(Lesson::Brewster);
        assert_eq!(effects.intensities(), Some(Polarisation::P));
        effects.waves = true;
        effects.start(Lesson::AirToGlass);
        assert_eq!((effects.intensities(), effects.waves()), (None, None));
    }
}

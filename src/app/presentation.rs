//! Presentation mode for a projector: full screen with the whole UI zoomed (large fonts, thick
//! lines), the high-contrast themes, the colour-blind-safe palette, the diagram's pan and
//! zoom, and the language of the window.

use egui::{
    Color32, ComboBox, Context, FontFamily, FontId, Key, KeyboardShortcut, Modifiers, Role,
    TextStyle, Ui, ViewportCommand, WidgetInfo,
};

use super::paint::colour;
use refraction_diagram::PanZoom;
use refraction_diagram::palette::{Palette, Theme};
use refraction_i18n::{Locale, t};

/// The UI zoom in presentation mode: the smallest text, 13 points, is then 20.8 pixels.
pub const ZOOM: f32 = 1.6;

/// The least width of a menu button in the bar that is only as wide as its choice, in points.
const COMPACT_COMBO_WIDTH: f32 = 40.0;

/// The smallest text anywhere in the window, in points (pixels at zoom 1).
pub(super) const SMALLEST_TEXT: f32 = 13.0;

/// The window's text sizes in points: nothing under [`SMALLEST_TEXT`], so that at zoom 1 every
/// word reads at a glance and in presentation ([`ZOOM`]) every word is at least 20 pixels.
#[must_use]
pub(super) fn text_styles() -> std::collections::BTreeMap<TextStyle, FontId> {
    use FontFamily::{Monospace, Proportional};
    [
        (TextStyle::Small, FontId::new(SMALLEST_TEXT, Proportional)),
        (TextStyle::Body, FontId::new(14.0, Proportional)),
        (TextStyle::Button, FontId::new(14.0, Proportional)),
        (TextStyle::Heading, FontId::new(20.0, Proportional)),
        (TextStyle::Monospace, FontId::new(14.0, Monospace)),
    ]
    .into()
}

/// What was last applied to the egui context, so that it is changed only when asked.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Applied {
    on: bool,
    theme: Theme,
}

/// The presentation settings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Presentation {
    /// Full screen and zoomed.
    pub on: bool,
    /// The look of the panels and the diagram.
    pub theme: Theme,
    /// Okabe–Ito colours only, and every ray with its own dash and label.
    pub colour_blind_safe: bool,
    /// How the diagram is panned and zoomed (drag the background, scroll; double-click resets).
    pub pan_zoom: PanZoom,
    /// The language chosen in the bar, kept between runs; `None` follows the system's.
    pub language: Option<Locale>,
    /// The simple view: the three rejected candidates left out, for a class that has not met
    /// them yet (kept between runs).
    pub simple: bool,
    /// In presentation, the diagram alone (key D): the bar, the strips, the panels, the tool
    /// and the index scale folded away.
    pub diagram_only: bool,
    applied: Option<Applied>,
}

/// A quieter shade of `text` on `back` that still has a contrast of 4.5:1 with it: the
/// farthest toward `back`, in steps of a twentieth, that keeps it.
fn weak(text: Color32, back: Color32) -> Color32 {
    let (text_c, back_c) = (colour(text), colour(back));
    let t = (0_u8..=10)
        .map(|i| f32::from(i) / 20.0)
        .take_while(|t| text_c.lerp(back_c, *t).contrast(back_c) >= 4.6)
        .last()
        .unwrap_or(0.0);
    let c = text_c.lerp(back_c, t);
    Color32::from_rgb(c.r, c.g, c.b)
}

/// The egui look of a theme: the standard light one, or black on white / white on black with
/// strong borders.
#[must_use]
pub(super) fn visuals(theme: Theme) -> egui::Visuals {
    let (mut visuals, text, back) = match theme {
        Theme::Standard => {
            let mut visuals = egui::Visuals::light();
            // egui's weak text (the hints) is 60 % of the text over the panel: 2.9:1, under
            // the 4.5:1 text must have. A grey between them that keeps 4.5:1 and reads as
            // quieter than the text.
            visuals.weak_text_color = Some(weak(visuals.text_color(), visuals.panel_fill));
            return visuals;
        }
        Theme::HighContrastLight => (egui::Visuals::light(), Color32::BLACK, Color32::WHITE),
        Theme::HighContrastDark => (egui::Visuals::dark(), Color32::WHITE, Color32::BLACK),
    };
    visuals.weak_text_color = Some(weak(text, back));
    visuals.override_text_color = Some(text);
    visuals.panel_fill = back;
    visuals.window_fill = back;
    visuals.extreme_bg_color = back;
    for widget in [
        &mut visuals.widgets.noninteractive,
        &mut visuals.widgets.inactive,
        &mut visuals.widgets.hovered,
        &mut visuals.widgets.active,
        &mut visuals.widgets.open,
    ] {
        widget.fg_stroke.color = text;
        widget.bg_stroke = egui::Stroke::new(1.5, text);
    }
    visuals
}

impl Presentation {
    /// The diagram's palette for these settings.
    #[must_use]
    pub fn palette(&self) -> Palette {
        Palette::new(self.theme, self.colour_blind_safe)
    }

    /// Applies the zoom, full screen and theme to `ctx` when they changed since last time.
    pub fn apply(&mut self, ctx: &Context) {
        let now = Applied {
            on: self.on,
            theme: self.theme,
        };
        let before = self.applied.replace(now);
        if before.map(|b| b.on) != Some(self.on) {
            ctx.set_zoom_factor(if self.on { ZOOM } else { 1.0 });
            // Only a change of mode touches the window: never leave full screen at start.
            if before.is_some() {
                ctx.send_viewport_cmd(ViewportCommand::Fullscreen(self.on));
            }
        }
        if before.map(|b| b.theme) != Some(self.theme) {
            ctx.set_visuals(visuals(self.theme));
        }
        if before.is_none() {
            ctx.all_styles_mut(|style| style.text_styles = text_styles());
        }
    }

    /// The look worth keeping between runs, the theme, the palette and the language chosen,
    /// as a short JSON text (presentation mode and the diagram's pan and zoom belong to one
    /// session).
    #[must_use]
    pub fn look(&self) -> String {
        serde_json::json!({
            "theme": self.theme.name(),
            "colour_blind_safe": self.colour_blind_safe,
            "language": self.language.map(Locale::code),
            "simple": self.simple,
        })
        .to_string()
    }

    /// Takes back a look saved by [`Presentation::look`]; what cannot be read is left as it is.
    pub fn restore_look(&mut self, text: &str) {
        let Ok(look) = serde_json::from_str::<serde_json::Value>(text) else {
            return;
        };
        if let Some(theme) = Theme::ALL
            .into_iter()
            .find(|t| look["theme"].as_str() == Some(t.name()))
        {
            self.theme = theme;
        }
        if let Some(safe) = look["colour_blind_safe"].as_bool() {
            self.colour_blind_safe = safe;
        }
        if let Some(simple) = look["simple"].as_bool() {
            self.simple = simple;
        }
        if let Some(language) = look["language"].as_str().and_then(Locale::from_tag) {
            self.language = Some(language);
        }
    }

    /// The language the window speaks: the one chosen in the bar, else `system`'s, else
    /// English.
    #[must_use]
    pub fn locale(&self, system: Option<Locale>) -> Locale {
        self.language.or(system).unwrap_or_default()
    }

    /// The presentation toggle (also F11), the theme and language menus and the
    /// colour-blind-safe switch (`speaking` is the language the window speaks now).
    pub fn controls(&mut self, ui: &mut Ui, speaking: Locale) {
        if ui.input_mut(|i| i.consume_shortcut(&KeyboardShortcut::new(Modifiers::NONE, Key::F11))) {
            self.on = !self.on;
        }
        let name = t!("presentation-toggle");
        if self.on {
            // The bar keeps one row on a projector: the switch shows its icon, its name is
            // its accessible name and its hover.
            let toggle = ui.toggle_value(&mut self.on, "🖵");
            toggle.widget_info(|| WidgetInfo::selected(Role::Button, true, true, &name));
            toggle.on_hover_text(format!("{name}: {}", t!("presentation-toggle-hover")));
            self.look_menu(ui);
            self.language_menu(ui, speaking);
            return;
        }
        ui.toggle_value(&mut self.on, name)
            .on_hover_text(t!("presentation-toggle-hover"));
        self.theme_menu(ui);
        self.language_menu(ui, speaking);
        self.look_switches(ui);
    }

    /// The colour-blind-safe and simple-view switches.
    fn look_switches(&mut self, ui: &mut Ui) {
        ui.checkbox(&mut self.colour_blind_safe, t!("presentation-colour-blind"))
            .on_hover_text(t!("presentation-colour-blind-hover"));
        ui.checkbox(&mut self.simple, t!("presentation-simple"))
            .on_hover_text(t!("presentation-simple-hover"));
    }

    /// In presentation, the theme and the look's switches in one menu of the bar, shown as its
    /// icon (the bar keeps one row in every language); its name is its accessible name and
    /// its hover.
    fn look_menu(&mut self, ui: &mut Ui) {
        let name = t!("presentation-look");
        let response = ui.menu_button("🎨 ⏷", |ui| {
            ui.label(t!("presentation-theme"));
            for theme in Theme::ALL {
                ui.radio_value(&mut self.theme, theme, theme.label());
            }
            ui.separator();
            self.look_switches(ui);
            ui.checkbox(&mut self.diagram_only, t!("presentation-diagram-only"));
        });
        let button = response.response;
        button.widget_info(|| WidgetInfo::labeled(Role::Button, true, &name));
        button.on_hover_text(name);
    }

    /// Presentation's diagram-only key (D, unless a text field has the keyboard): toggles the
    /// diagram alone; leaving presentation leaves it too.
    pub fn diagram_only_key(&mut self, ctx: &Context) {
        if !self.on {
            self.diagram_only = false;
            return;
        }
        let pressed = !ctx.text_edit_focused()
            && ctx
                .input_mut(|i| i.consume_shortcut(&KeyboardShortcut::new(Modifiers::NONE, Key::D)));
        if pressed {
            self.diagram_only = !self.diagram_only;
        }
    }

    /// The theme menu, labelled at the desk; in presentation, where the bar is short of room,
    /// as wide as the theme's name, with its label only as its accessible name and on hover.
    fn theme_menu(&mut self, ui: &mut Ui) {
        let label = t!("presentation-theme");
        let menu = if self.on {
            ComboBox::from_id_salt("theme").width(COMPACT_COMBO_WIDTH)
        } else {
            ComboBox::from_label(&label)
        };
        let response = menu
            .selected_text(self.theme.label())
            .show_ui(ui, |ui| {
                for theme in Theme::ALL {
                    ui.selectable_value(&mut self.theme, theme, theme.label());
                }
            })
            .response;
        if self.on {
            response.widget_info(|| WidgetInfo::labeled(Role::ComboBox, true, &label));
        }
        let hover = t!("presentation-theme-hover");
        response.on_hover_text(format!("{label}: {hover}"));
    }

    /// The language menu: each language by its own name (in presentation, where the bar is
    /// short of room, the chosen one by its code); the choice is kept between runs.
    fn language_menu(&mut self, ui: &mut Ui, speaking: Locale) {
        let shown = if self.on {
            speaking.code().to_uppercase()
        } else {
            speaking.name().to_owned()
        };
        // As wide as the chosen name: the bar keeps its rows on a projector; its name is for
        // screen readers and the hover.
        let name = t!("language-menu");
        let response = ComboBox::from_id_salt("language")
            .width(COMPACT_COMBO_WIDTH)
            .selected_text(format!("🌐 {shown}"))
            .show_ui(ui, |ui| {
                for locale in Locale::ALL {
                    if ui
                        .selectable_label(speaking == locale, locale.name())
                        .clicked()
                    {
                        self.language = Some(locale);
                    }
                }
            })
            .response;
        response.widget_info(|| WidgetInfo::labeled(Role::ComboBox, true, &name));
        response.on_hover_text(format!("{name}: {}", t!("language-hover")));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_look_is_kept_between_runs_and_junk_is_ignored() {
        let chosen = Presentation {
            theme: Theme::HighContrastDark,
            colour_blind_safe: true,
            on: true,
            ..Presentation::default()
        };
        let mut next_run = Presentation::default();
        next_run.restore_look(&chosen.look());
        assert_eq!(next_run.theme, Theme::HighContrastDark);
        assert!(next_run.colour_blind_safe);
        assert!(!next_run.on, "presentation mode is not restored");
        assert_eq!(next_run.language, None, "no language chosen: the system's");
        next_run.restore_look("{\"theme\": \"Neon\", \"language\": \"tlh\"}");
        next_run.restore_look("not json");
        assert_eq!(next_run.theme, Theme::HighContrastDark);
        assert_eq!(next_run.language, None);
    }

    #[test]
    fn a_chosen_language_is_kept_and_wins_over_the_systems() {
        let chosen = Presentation {
            language: Some(Locale::De),
            ..Presentation::default()
        };
        let mut next_run = Presentation::default();
        assert_eq!(next_run.locale(Some(Locale::Fr)), Locale::Fr);
        assert_eq!(next_run.locale(None), Locale::En);
        next_run.restore_look(&chosen.look());
        assert_eq!(next_run.locale(Some(Locale::Fr)), Locale::De);
    }

    #[test]
    fn looks_saved_by_earlier_versions_keep_their_theme() {
        let mut next_run = Presentation::default();
        next_run.restore_look("{\"theme\": \"White on black\"}");
        assert_eq!(next_run.theme, Theme::HighContrastDark);
        next_run.restore_look("{\"theme\": \"Black on white\"}");
        assert_eq!(next_run.theme, Theme::HighContrastLight);
    }

    #[test]
    fn high_contrast_themes_use_pure_black_and_white() {
        let light = visuals(Theme::HighContrastLight);
        assert_eq!(light.override_text_color, Some(Color32::BLACK));
        assert_eq!(light.panel_fill, Color32::WHITE);
        let dark = visuals(Theme::HighContrastDark);
        assert!(dark.dark_mode);
        assert_eq!(dark.panel_fill, Color32::BLACK);
        // Every theme's hints read at 4.5:1 (the standard light look's were 2.9:1).
        for theme in Theme::ALL {
            let v = visuals(theme);
            let ratio = colour(v.weak_text_color()).contrast(colour(v.panel_fill));
            assert!(ratio >= 4.5, "{theme:?}: {ratio}");
            assert_ne!(
                v.weak_text_color(),
                v.text_color(),
                "{theme:?}: weak text is quieter"
            );
        }
    }
}

//! The single-interface view's side panels (controls on the left, the kernel's numbers on the
//! right): each collapses to a narrow strip and reopens with its key or the strip's button.
//!
//! Presentation keeps its own panels: their own open/closed switches (both start closed, so
//! the diagram owns the projector) and their own egui ids, so that the narrow widths of a
//! zoomed window are never written over the widths the user chose for the desk, which egui
//! keeps between runs under the desk panels' ids.

use egui::{Button, Key, Panel, RichText, Role, ScrollArea, Ui, WidgetInfo};
use refraction_i18n::t;

/// The width of a collapsed panel's strip, in points.
pub(super) const STRIP_WIDTH: f32 = 36.0;

/// One side panel: where it sits, its name, its key and its sizes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct SidePanel {
    /// Its egui id at the desk (presentation adds a suffix).
    pub id: &'static str,
    /// The key that opens and closes it.
    pub key: Key,
    /// Whether it sits on the left.
    pub left: bool,
    /// Its first width, in points.
    pub default_width: f32,
    /// The most of the window's width it may take, at the desk and in presentation.
    pub max_share: (f32, f32),
}

impl SidePanel {
    /// What its button says: show it (`show`) or hide it, with its `key`. The button's words
    /// are also its accessible name.
    fn words(&self, show: bool, key: &str) -> String {
        match (self.left, show) {
            (true, true) => t!("panel-show-controls", key = key),
            (true, false) => t!("panel-hide-controls", key = key),
            (false, true) => t!("panel-show-numbers", key = key),
            (false, false) => t!("panel-hide-numbers", key = key),
        }
    }
}

/// The controls panel (F2).
pub(super) const CONTROLS: SidePanel = SidePanel {
    id: "controls",
    key: Key::F2,
    left: true,
    default_width: 290.0,
    max_share: (0.25, 0.3),
};

/// The numbers panel (F3): k, the quadratic in b, the candidates, the equations.
pub(super) const NUMBERS: SidePanel = SidePanel {
    id: "readouts",
    key: Key::F3,
    left: false,
    default_width: 440.0,
    max_share: (0.38, 0.30),
};

/// Which side panels are open in one mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Open {
    /// The controls panel.
    pub controls: bool,
    /// The numbers panel.
    pub numbers: bool,
}

impl Open {
    fn of(&mut self, panel: &SidePanel) -> &mut bool {
        if panel.left {
            &mut self.controls
        } else {
            &mut self.numbers
        }
    }
}

/// The side panels' switches, at the desk and in presentation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Panels {
    /// At the desk: both open at first.
    pub desk: Open,
    /// In presentation: both closed at first.
    pub presenting: Open,
}

impl Default for Panels {
    fn default() -> Self {
        Self {
            desk: Open {
                controls: true,
                numbers: true,
            },
            presenting: Open {
                controls: false,
                numbers: false,
            },
        }
    }
}

impl Panels {
    /// The switches of the mode shown.
    pub(super) fn mode(&mut self, presenting: bool) -> &mut Open {
        if presenting {
            &mut self.presenting
        } else {
            &mut self.desk
        }
    }

    /// In presentation a side panel and the open tool do not share the screen: together they
    /// would squeeze the panel's controls (a label wrapped letter by letter at 1280×720) or
    /// the diagram below its share. The one opened last stays, the other gives way
    /// (`tool_opened`: the tool was opened this frame). Returns whether the tool must close.
    pub(super) fn make_room(&mut self, tool_opened: bool) -> bool {
        let mut close_tool = false;
        for panel in [CONTROLS, NUMBERS] {
            let shown = self.presenting.of(&panel);
            if *shown {
                if tool_opened {
                    *shown = false;
                } else {
                    close_tool = true;
                }
            }
        }
        close_tool
    }

    /// In presentation, where a closed panel leaves no strip, a switch for each panel in the
    /// bar: its arrow, named (for screen readers and on hover) with what it does and its key.
    pub(super) fn bar_switches(&mut self, ui: &mut Ui) {
        for panel in [CONTROLS, NUMBERS] {
            let shown = self.presenting.of(&panel);
            let arrow = match (panel.left, *shown) {
                (true, false) | (false, true) => "⏵",
                (true, true) | (false, false) => "⏴",
            };
            let name = panel.words(!*shown, panel.key.name());
            let switch = ui.add(Button::new(RichText::new(arrow).strong()).selected(*shown));
            switch.widget_info(|| WidgetInfo::labeled(Role::Button, true, &name));
            if switch.on_hover_text(&name).clicked() {
                *shown = !*shown;
            }
        }
    }

    /// Toggles the panels whose keys were pressed (unless a text field has the keyboard).
    pub(super) fn keys(&mut self, ui: &Ui, presenting: bool) {
        if ui.ctx().text_edit_focused() {
            return;
        }
        let open = self.mode(presenting);
        for panel in [CONTROLS, NUMBERS] {
            if ui.input(|i| i.key_pressed(panel.key)) {
                let shown = open.of(&panel);
                *shown = !*shown;
            }
        }
    }

    /// Shows `panel` at the side of `ui`: its contents in a vertical scroll area when open,
    /// else a strip with a button that opens it.
    pub(super) fn show(
        &mut self,
        ui: &mut Ui,
        panel: &SidePanel,
        presenting: bool,
        contents: impl FnOnce(&mut Ui),
    ) {
        let shown = self.mode(presenting).of(panel);
        let id = if presenting {
            // untranslated: an egui id (it keys the widths egui keeps between runs).
            format!("{} (presentation)", panel.id)
        } else {
            panel.id.to_owned()
        };
        let side = |id: String| {
            if panel.left {
                Panel::left(id)
            } else {
                Panel::right(id)
            }
        };
        let key = panel.key.name();
        if !*shown && presenting {
            // No strip on a projector: the bar's switches and the keys open the panel.
            return;
        }
        if !*shown {
            // untranslated: an egui id.
            strip(ui, panel, side(format!("{id} strip")), shown);
            return;
        }
        let share = if presenting {
            panel.max_share.1
        } else {
            panel.max_share.0
        };
        // On the frame presentation is switched on or off, egui still lays out at the other
        // zoom: a limit from that frame's width would clamp the width egui keeps for the panel
        // (the numbers came back narrower after presentation, even after a restart). That
        // frame keeps the width as it was and is drawn again at once.
        let ctx = ui.ctx();
        let zoom = if presenting {
            super::presentation::ZOOM
        } else {
            1.0
        };
        let settled = ctx.native_pixels_per_point().unwrap_or(1.0) * zoom;
        let max = if (ctx.pixels_per_point() - settled).abs() > 1e-3 {
            // untranslated: egui's reason for drawing the frame again, for its debug output.
            ctx.request_discard("the zoom changes");
            f32::INFINITY
        } else {
            (ui.available_width() * share).max(STRIP_WIDTH * 4.0)
        };
        side(id)
            .default_size(panel.default_width.min(max))
            .max_size(max)
            .resizable(true)
            .show(ui, |ui| {
                let arrow = if panel.left { "⏴" } else { "⏵" };
                let hide =
                    ui.add(Button::new(format!("{arrow} {}", panel.words(false, key))).small());
                if hide.clicked() {
                    *shown = false;
                }
                // egui's floating scroll bar, thin until hovered: a solid or thin one, whose
                // track is painted, left a black band beside the panel in a real window (glow).
                ui.spacing_mut().scroll = egui::style::ScrollStyle::floating();
                ScrollArea::vertical()
                    .auto_shrink([false, true])
                    .show(ui, contents);
            });
    }
}

/// The thin strip a closed panel leaves at its side (`side`, not yet shown): a button with an
/// arrow that opens it (`shown`).
fn strip(ui: &mut Ui, panel: &SidePanel, side: Panel, shown: &mut bool) {
    // A thin margin: the arrow's button fits the strip whatever the language.
    let frame = egui::Frame::side_top_panel(ui.style()).inner_margin(3.0);
    side.exact_size(STRIP_WIDTH)
        .resizable(false)
        .frame(frame)
        .show(ui, |ui| {
            let arrow = if panel.left { "⏵" } else { "⏴" };
            let name = panel.words(true, panel.key.name());
            let open = ui.add(Button::new(RichText::new(arrow).strong()));
            open.widget_info(|| WidgetInfo::labeled(Role::Button, true, &name));
            if open.on_hover_text(&name).clicked() {
                *shown = true;
            }
        });
}

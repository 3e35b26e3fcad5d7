//! Buttons that change W, N and the two indices a step at a time: 1° for the angle of
//! incidence and the normal, 0.01 for an index, with a slider beside each index for the long
//! way. The one-pointer way to do what a drag does (WCAG 2.2's 2.5.7, dragging movements),
//! each button a finger's size: the student's view shows them under (or beside) the diagram.

use egui::{Button, RichText, Role, Slider, Ui, Vec2, WidgetInfo};
use refraction_diagram::numbers::number;
use refraction_diagram::picture::TOUCH_TARGET;
use refraction_i18n::t;
use refraction_model::{ExplorerState, HandleId, INDEX_RANGE};

use super::canvas::{ANGLE_STEP, INDEX_STEP, nudge_index};

/// The largest angle of incidence a button sets, in degrees: grazing, short of the 90° the
/// model refuses.
const MOST_INCIDENCE: f64 = 89.9;

/// The width of a row's name and value (`μt 1.500`), in points: the rows' buttons line up.
const NAME_WIDTH: f32 = 76.0;

/// A button showing `text`, a finger's size ([`TOUCH_TARGET`]), named `name` for screen readers
/// and on hover. Returns whether it was pressed.
fn step(ui: &mut Ui, text: &str, name: &str) -> bool {
    let button =
        ui.add(Button::new(RichText::new(text).size(18.0)).min_size(Vec2::splat(TOUCH_TARGET)));
    button.widget_info(|| WidgetInfo::labeled(Role::Button, true, name));
    button.on_hover_text(name).clicked()
}

/// A row's name and value, as wide as every row's ([`NAME_WIDTH`]).
fn name(ui: &mut Ui, text: String) {
    let size = Vec2::new(NAME_WIDTH, TOUCH_TARGET);
    ui.add_sized(size, egui::Label::new(RichText::new(text).size(16.0)));
}

/// θi and its two buttons: a degree less or more, within 0° and grazing.
fn incidence(ui: &mut Ui, state: &mut ExplorerState) {
    let now = state.incidence_degrees();
    name(ui, format!("θi {}°", number(now, 1)));
    for (text, words, sign) in [
        ("−1°", t!("student-incidence-less"), -1.0),
        ("+1°", t!("student-incidence-more"), 1.0),
    ] {
        if step(ui, text, &words) {
            let degrees = (now + sign * ANGLE_STEP).clamp(0.0, MOST_INCIDENCE);
            // Within the range the model takes: never refused.
            state.set_incidence_degrees(degrees).ok();
        }
    }
}

/// N and its two buttons: a degree counter-clockwise or clockwise (the surface turns with it).
fn normal(ui: &mut Ui, state: &mut ExplorerState) {
    name(ui, "N".to_owned());
    for (text, words, sign) in [
        ("⟲", t!("student-normal-left"), 1.0),
        ("⟳", t!("student-normal-right"), -1.0),
    ] {
        if step(ui, text, &words) {
            state.rotate(HandleId::N, sign * ANGLE_STEP);
        }
    }
}

/// An index's value, its buttons (0.01 less or more) and a slider between them over the
/// range the index scale shows.
fn index(ui: &mut Ui, state: &mut ExplorerState, handle: HandleId) {
    let symbol = match handle {
        HandleId::MuI => "μi",
        _ => "μt",
    };
    name(ui, format!("{symbol} {}", number(state.index(handle), 3)));
    if step(ui, "−", &t!("student-index-less", symbol = symbol)) {
        nudge_index(state, handle, -INDEX_STEP);
    }
    let mut value = state.index(handle);
    let (low, high) = INDEX_RANGE;
    // The slider takes what the row has left beside the second button.
    let room = ui.available_width() - TOUCH_TARGET - ui.spacing().item_spacing.x;
    ui.spacing_mut().slider_width = room.max(TOUCH_TARGET);
    let slider = Slider::new(&mut value, low..=high)
        .show_value(false)
        .step_by(INDEX_STEP);
    let name = t!("student-index", symbol = symbol);
    let moved = ui.add(slider);
    moved.widget_info(|| WidgetInfo::slider(true, value, &name));
    if moved.changed() {
        // A value the kernel refuses (too far from the other index) leaves the last good one.
        state.set_index(handle, value).ok();
    }
    if step(ui, "+", &t!("student-index-more", symbol = symbol)) {
        nudge_index(state, handle, INDEX_STEP);
    }
}

/// The step buttons of W (as θi), N and both indices: in two rows under a portrait diagram
/// (θi and N side by side, then each index), or one under the other in a `column` beside a
/// landscape one.
pub(super) fn ui(ui: &mut Ui, state: &mut ExplorerState, column: bool) {
    if column {
        ui.horizontal(|ui| incidence(ui, state));
        ui.horizontal(|ui| normal(ui, state));
    } else {
        ui.horizontal(|ui| {
            incidence(ui, state);
            ui.add_space(8.0);
            normal(ui, state);
        });
    }
    for handle in [HandleId::MuI, HandleId::MuT] {
        ui.horizontal(|ui| index(ui, state, handle));
    }
}

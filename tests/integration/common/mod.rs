//! Helpers shared by the headless UI tests: the explorer's window at the tests' size, pointer
//! drags, typing, clicks and undo, and the states several tests start from.

use egui::{Key, Modifiers, Pos2, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use glam::DVec3;
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

/// Shows `app` over the whole window, as eframe's root `Ui` does (the harness's own `Ui` keeps
/// an 8-point margin that the real window does not have).
pub(crate) fn whole_window(ui: &mut egui::Ui, app: &mut Explorer) {
    let window = ui.ctx().content_rect();
    ui.scope_builder(egui::UiBuilder::new().max_rect(window), |ui| {
        ui.set_clip_rect(window);
        app.show(ui);
    });
}

/// The window showing `explorer`, `size` points in the light theme with the window's fonts,
/// after its first frame.
pub(crate) fn harness_sized(explorer: Explorer, size: (f32, f32)) -> Harness<'static, Explorer> {
    let mut harness = Harness::builder()
        .with_context_setup(refraction_explorer::app::install_fonts)
        .with_size(Vec2::new(size.0, size.1))
        .with_theme(egui::Theme::Light)
        .build_ui_state(whole_window, explorer);
    harness.run();
    harness
}

/// The window showing `explorer`, 1280 × 760 points (see [`harness_sized`]).
pub(crate) fn harness_for(explorer: Explorer) -> Harness<'static, Explorer> {
    harness_sized(explorer, (1280.0, 760.0))
}

/// The window of a new explorer showing `state`.
pub(crate) fn harness(state: ExplorerState) -> Harness<'static, Explorer> {
    harness_for(Explorer::new(state))
}

/// From glass into air, W 30° from the normal: below the critical angle (41.8°).
pub(crate) fn leaving_glass() -> ExplorerState {
    let angle = 30_f64.to_radians();
    let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
    ExplorerState::new(w, DVec3::Y, 1.5, 1.0, Default::default()).unwrap()
}

/// The centre of the widget labelled `label`.
pub(crate) fn center_of(harness: &Harness<'_, Explorer>, label: &str) -> Pos2 {
    harness.get_by_label(label).rect().center()
}

/// Presses the pointer at `path`'s first point, moves it through the rest and releases it at
/// the last: a click when the path is one point, a drag otherwise.
pub(crate) fn press_move_release(harness: &mut Harness<'_, Explorer>, path: &[Pos2]) {
    let (Some(&first), Some(&last)) = (path.first(), path.last()) else {
        return;
    };
    harness.hover_at(first);
    harness.run();
    harness.drag_at(first);
    harness.run();
    for &p in &path[1..] {
        harness.hover_at(p);
        harness.run();
    }
    harness.drop_at(last);
    harness.run();
}

/// Drags from `from` to `to` in four pointer moves.
pub(crate) fn drag(harness: &mut Harness<'_, Explorer>, from: Pos2, to: Pos2) {
    let path: Vec<Pos2> = (0..=4)
        .map(|step| from + (to - from) * (step as f32 / 4.0))
        .collect();
    press_move_release(harness, &path);
}

/// Replaces the text of the text field `label` with `text` (Enter is not pressed).
pub(crate) fn replace_text(h: &mut Harness<'_, Explorer>, label: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, label).focus();
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run();
    h.get_by_role_and_label(Role::TextInput, label)
        .type_text(text);
    h.run();
}

/// Replaces the text of the field labelled `label` and presses Enter.
pub(crate) fn type_into(h: &mut Harness<'_, Explorer>, label: &str, text: &str) {
    replace_text(h, label, text);
    h.key_press(Key::Enter);
    h.run();
}

/// Clicks the widget labelled `label`.
pub(crate) fn click(h: &mut Harness<'_, Explorer>, label: &str) {
    h.get_by_label(label).click();
    h.run();
}

/// Undoes one step with the keyboard.
pub(crate) fn undo(h: &mut Harness<'_, Explorer>) {
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
}

/// The smallest size of any non-blank text the last frame drew outside `away_from` (the
/// diagram's canvas, whose labels are sized by the diagram), in pixels.
pub(crate) fn smallest_text_px(h: &Harness<'_, Explorer>, away_from: egui::Rect) -> f32 {
    fn smallest_in(shape: &egui::Shape, away_from: egui::Rect) -> f32 {
        match shape {
            egui::Shape::Vec(shapes) => shapes
                .iter()
                .map(|s| smallest_in(s, away_from))
                .fold(f32::INFINITY, f32::min),
            egui::Shape::Text(text) if !away_from.intersects(text.visual_bounding_rect()) => {
                let job = &text.galley.job;
                job.sections
                    .iter()
                    .filter(|s| {
                        let words = job.text.get(s.byte_range.start.0..s.byte_range.end.0);
                        words.is_some_and(|w| !w.trim().is_empty())
                    })
                    .map(|s| s.format.font_id.size)
                    .fold(f32::INFINITY, f32::min)
            }
            _ => f32::INFINITY,
        }
    }
    let smallest = h
        .output()
        .shapes
        .iter()
        .map(|clipped| smallest_in(&clipped.shape, away_from))
        .fold(f32::INFINITY, f32::min);
    smallest * h.ctx.pixels_per_point()
}

/// Scrolls the panel to the widget labelled `label` and clicks it (the panel is short).
pub(crate) fn reach(h: &mut Harness<'_, Explorer>, label: &str) {
    h.get_by_label(label).scroll_to_me();
    h.run();
    click(h, label);
}

/// Replaces the text of the multi-line box of pasted log lines.
pub(crate) fn paste_log(h: &mut Harness<'_, Explorer>, text: &str) {
    let role = egui::Role::MultilineTextInput;
    h.get_by_role_and_label(role, "Log lines").focus();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run();
    h.get_by_role_and_label(role, "Log lines").type_text(text);
    h.run();
}

/// The words of every text the last frame painted (labels, and the texts of figures painted
/// from the diagram's primitives, which have no accessible node of their own).
pub(crate) fn painted_texts(h: &Harness<'_, Explorer>) -> Vec<String> {
    fn texts_in(shape: &egui::Shape, into: &mut Vec<String>) {
        match shape {
            egui::Shape::Vec(shapes) => shapes.iter().for_each(|s| texts_in(s, into)),
            egui::Shape::Text(text) => into.push(text.galley.job.text.clone()),
            _ => {}
        }
    }
    let mut texts = Vec::new();
    for clipped in &h.output().shapes {
        texts_in(&clipped.shape, &mut texts);
    }
    texts
}

//! The interactive diagram: painted from [`Diagram`], with one focusable, draggable widget per
//! handle and keyboard nudges, and the step buttons under it ([`steps`]).
//!
//! Each handle is a slider for screen readers and tests: W is the angle of incidence θi, N the
//! direction of the normal, μi and μt the indices ([`HandleId::label`]), each with its
//! value in words, its step and bounds, and the increment, decrement and set-value actions a
//! screen reader's slider gestures send. The arrow keys move the selected handle's value the
//! same way (→ and ↑ up, ← and ↓ down), as the step buttons do.

use egui::accesskit::{Action, ActionData};
use egui::emath::RectTransform;
use egui::{
    CursorIcon, EventFilter, Id, Key, Pos2, Rect, Role, Sense, Stroke, Ui, Vec2 as EguiVec2,
    WidgetInfo,
};
use glam::Vec2;
use refraction_i18n::t;

use super::paint::{color, hover_left_out, paint};
use super::steps::{self, Reach};
use refraction_diagram::{Diagram, Overlay};
use refraction_model::describe::{self, Disclosure};
use refraction_model::{ExplorerState, HandleId};

/// Applies the keys pressed while `handle` has focus: the arrows move its value a step (→ and
/// ↑ up, ← and ↓ down: θi, N to the right, the index; Shift: a tenth of a step); + and −
/// change the selected index (μt while W or N is selected).
fn keyboard(ui: &Ui, state: &mut ExplorerState, handle: HandleId) {
    let (arrows, plus, shift) = ui.input(|i| {
        let pressed = |key| i32::from(i.key_pressed(key));
        let arrows = pressed(Key::ArrowUp) + pressed(Key::ArrowRight)
            - pressed(Key::ArrowDown)
            - pressed(Key::ArrowLeft);
        let plus = pressed(Key::Plus) + pressed(Key::Equals) - pressed(Key::Minus);
        (arrows, plus, i.modifiers.shift)
    });
    let scale = if shift { 0.1 } else { 1.0 };
    if arrows != 0 {
        steps::nudge(state, handle, f64::from(arrows) * scale);
    }
    if plus != 0 {
        let target = if handle == HandleId::MuI {
            HandleId::MuI
        } else {
            HandleId::MuT
        };
        steps::nudge(state, target, f64::from(plus) * scale);
    }
}

/// What a screen reader asked of the handle `id` this frame: its slider's increment and
/// decrement (a step each) and set-value actions.
fn screen_reader(ui: &Ui, id: Id, state: &mut ExplorerState, handle: HandleId) {
    let (steps_up, target) = ui.input(|i| {
        let count = |action| i.accesskit_action_requests(id, action).count() as f64;
        let target = i
            .accesskit_action_requests(id, Action::SetValue)
            .filter_map(|request| match request.data {
                Some(ActionData::NumericValue(value)) => Some(value),
                _ => None,
            })
            .last();
        (count(Action::Increment) - count(Action::Decrement), target)
    });
    if let Some(target) = target {
        steps::set(state, handle, target);
    }
    if steps_up != 0.0 {
        steps::nudge(state, handle, steps_up);
    }
}

/// Names the handle `id` for screen readers and tests as the slider of its control: its
/// name, its value (the number, and in words with its unit), its bounds and step, the actions
/// it takes.
fn slider_node(ui: &Ui, grab: &egui::Response, state: &ExplorerState, handle: HandleId) {
    let value = steps::value(state, handle);
    grab.widget_info(|| WidgetInfo::slider(true, value, handle.label()));
    let bounds = steps::bounds(state, handle);
    ui.ctx().accesskit_node_builder(grab.id, |node| {
        node.set_value(describe::control_value(state, handle));
        node.set_min_numeric_value(*bounds.start());
        node.set_max_numeric_value(*bounds.end());
        node.set_numeric_value_step(steps::step(handle));
        node.add_action(Action::SetValue);
        node.add_action(Action::Increment);
        node.add_action(Action::Decrement);
    });
}

/// Pans by dragging the background and zooms by scrolling (or pinching) over it, about the
/// pointer; a double click puts the view back.
fn pan_and_zoom(ui: &Ui, response: &egui::Response, overlay: &mut Overlay) {
    let view = &mut overlay.pan_zoom;
    if response.double_clicked() {
        *view = Default::default();
        return;
    }
    if response.dragged() {
        let delta = response.drag_delta();
        view.pan += Vec2::new(delta.x, delta.y);
    }
    if let Some(pointer) = response.hover_pos() {
        let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        let factor = pinch * (scroll / 400.0).exp();
        if factor != 1.0 {
            let fitted = refraction_diagram::Layout::new(Vec2::new(
                response.rect.width(),
                response.rect.height(),
            ))
            .view
            .origin;
            let at = pointer - response.rect.min;
            view.zoom_about(factor, Vec2::new(at.x, at.y) - fitted);
        }
    }
}

/// The line under the diagram: how to use the handles, or the keys of the one selected.
fn hint(focused: Option<HandleId>) -> String {
    match focused {
        Some(HandleId::W | HandleId::N) => t!("canvas-hint-ray"),
        Some(HandleId::MuI | HandleId::MuT) => t!("canvas-hint-index"),
        None => t!("canvas-hint"),
    }
}

/// Where a drag of a handle that started at `press` (with the handle's centre at `center`)
/// puts the handle when the pointer is at `pointer`: the handle keeps its offset from the
/// pointer, so that starting a drag a few pixels off its centre does not make it jump.
fn dragged_to(center: Pos2, press: Pos2, pointer: Pos2) -> Pos2 {
    pointer + (center - press)
}

/// Lets the user grab, drag and focus each handle of `before` (the diagram as it stood when
/// the frame began), editing `state`; returns the handle that has the keyboard focus.
fn interact(
    ui: &Ui,
    response: &egui::Response,
    to_screen: &RectTransform,
    state: &mut ExplorerState,
    before: &Diagram,
) -> Option<HandleId> {
    let from_screen = to_screen.inverse();
    let mut focused = None;
    for handle in &before.handles {
        let area = Diagram::grab_area(handle);
        let rect = Rect::from_min_max(
            to_screen.transform_pos(Pos2::new(area.min.x, area.min.y)),
            to_screen.transform_pos(Pos2::new(area.max.x, area.max.y)),
        );
        let id = response.id.with(handle.id);
        let grab = ui.interact(rect, id, Sense::click_and_drag());
        screen_reader(ui, id, state, handle.id);
        slider_node(ui, &grab, state, handle.id);
        if grab.clicked() || grab.drag_started() {
            grab.request_focus();
        }
        let press = ui.input(|i| i.pointer.press_origin());
        let center = to_screen.transform_pos(Pos2::new(handle.center.x, handle.center.y));
        if let (Some(pointer), Some(press)) = (grab.interact_pointer_pos(), press)
            && grab.dragged()
        {
            let start = ui.data_mut(|d| *d.get_temp_mut_or(id, center));
            let p = from_screen.transform_pos(dragged_to(start, press, pointer));
            before.drag(state, handle.id, Vec2::new(p.x, p.y));
        } else {
            // Where the handle is when the next drag starts.
            ui.data_mut(|d| d.insert_temp(id, center));
        }
        if grab.hovered() || grab.dragged() {
            ui.ctx().set_cursor_icon(CursorIcon::Grab);
        }
        if grab.has_focus() {
            let filter = EventFilter {
                horizontal_arrows: true,
                vertical_arrows: true,
                ..EventFilter::default()
            };
            ui.memory_mut(|m| m.set_focus_lock_filter(id, filter));
            keyboard(ui, state, handle.id);
            focused = Some(handle.id);
        }
    }
    focused
}

/// Tab with nothing selected selects W: the diagram is the keyboard's first stop, one Tab
/// away rather than after every control of the bar and the panels (Tab goes on from W to N,
/// μi, μt and the step buttons, then round the window). egui gives such a Tab to the window's
/// first control before the canvas is shown, so whether nothing was selected is remembered
/// from the end of the last frame. Not while a dialog is open over the diagram or a field has
/// the keyboard.
fn tab_to_w(ui: &Ui, w_id: Id) {
    let memory = w_id.with("tab-to-w");
    let was_free = ui.data(|d| d.get_temp::<bool>(memory)).unwrap_or(false);
    let tab = ui.input(|i| i.key_pressed(Key::Tab) && i.modifiers.is_none());
    let open = ui.memory(|m| m.allows_interaction(ui.layer_id()));
    if tab && was_free && open && !ui.ctx().text_edit_focused() {
        ui.memory_mut(|m| m.request_focus(w_id));
    }
}

/// Remembers for [`tab_to_w`] whether the frame ends with nothing selected.
fn remember_focus(ui: &Ui, w_id: Id) {
    let free = ui.memory(|m| m.focused().is_none());
    ui.data_mut(|d| d.insert_temp(w_id.with("tab-to-w"), free));
}

/// The rows under the diagram: the step buttons and, at the desk, the line of keys (cut with
/// "…" where the window is narrow, the whole on hover). Returns whether a step button changed
/// `state`.
fn rows_under(
    ui: &mut Ui,
    state: &mut ExplorerState,
    focused: Option<HandleId>,
    under: Under,
) -> bool {
    let changed = under.steps && steps::row(ui, state, Reach::of(ui));
    if under.hint {
        let hint = hint(focused);
        ui.add(egui::Label::new(egui::RichText::new(&hint).weak()).truncate())
            .on_hover_text(hint);
    }
    changed
}

/// What is shown under the diagram.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Under {
    /// The step buttons ([`steps::row`]).
    pub steps: bool,
    /// The line of keys (at the desk; a projector leaves the room to the diagram).
    pub hint: bool,
}

/// The height the rows under the diagram took last frame (the step buttons wrap where the
/// panel is narrow), or one row of buttons and the line of keys before the first.
fn height_under(ui: &Ui, id: Id, under: Under) -> f32 {
    let spacing = ui.spacing();
    let row = Reach::of(ui).side().max(spacing.interact_size.y) + spacing.item_spacing.y;
    let text = ui.text_style_height(&egui::TextStyle::Body);
    let line = text.max(spacing.interact_size.y) + spacing.item_spacing.y;
    let estimate = spacing.item_spacing.y
        + if under.steps { row } else { 0.0 }
        + if under.hint { line } else { 0.0 };
    ui.data(|d| d.get_temp(id)).unwrap_or(estimate)
}

/// Shows the diagram of `state` with `overlay` filling the available space (less the rows
/// `under` it: the step buttons, a line for the keys), editing `state` by drag, keyboard,
/// screen reader and step buttons, and the overlay's view by pan and zoom.
///
/// A press and release within egui's click distance is a click, not a drag: it changes
/// nothing and selects the handle (or, on the background, the W handle) for the arrow keys.
pub(super) fn show(ui: &mut Ui, state: &mut ExplorerState, overlay: &mut Overlay, under: Under) {
    let rows = ui.scope_id().with("rows-under-diagram");
    let size = ui.available_size() - EguiVec2::new(0.0, height_under(ui, rows, under));
    let (response, painter) =
        ui.allocate_painter(size.max(EguiVec2::splat(1.0)), Sense::click_and_drag());
    pan_and_zoom(ui, &response, overlay);
    let size = response.rect.size();
    let to_screen = RectTransform::from_to(Rect::from_min_size(Pos2::ZERO, size), response.rect);
    let canvas_size = Vec2::new(size.x, size.y);
    let before = Diagram::with_overlay(state, canvas_size, overlay);
    let unchanged = state.clone();
    let w_id = response.id.with(HandleId::W);
    tab_to_w(ui, w_id);
    // A click on the background selects W. It is asked for after the handles are interacted
    // with: a handle that sees a click elsewhere gives its focus up, W's too.
    let select_w = response.clicked()
        && !before
            .handles
            .iter()
            .any(|h| ui.memory(|m| m.has_focus(response.id.with(h.id))));
    let interacted = interact(ui, &response, &to_screen, state, &before);
    let focused = if select_w {
        ui.memory_mut(|m| m.request_focus(w_id));
        Some(HandleId::W)
    } else {
        interacted
    };
    // Most frames change nothing: the diagram drawn is then the one the handles were read from.
    let after = if *state == unchanged {
        before
    } else {
        Diagram::with_overlay(state, canvas_size, overlay)
    };
    paint(&painter, &to_screen, &after.primitives());
    hover_left_out(
        &response,
        &to_screen,
        &after.left_out,
        after.layout.font * 2.0,
    );
    response.widget_info(|| WidgetInfo::labeled(Role::Image, true, &after.summary));
    // The diagram in words, as the describer says it, after the banner's name.
    let answer = Disclosure::hidden_if(overlay.hide_answer);
    ui.ctx().accesskit_node_builder(response.id, |node| {
        node.set_description(describe::interface(state, answer).join(" "));
    });
    if let Some(handle) = after.handles.iter().find(|h| Some(h.id) == focused) {
        let center = to_screen.transform_pos(Pos2::new(handle.center.x, handle.center.y));
        let ring = Stroke::new(2.0, color(overlay.palette.ink));
        painter.circle_stroke(center, handle.radius * 1.7, ring);
    }
    let top = ui.cursor().top();
    if rows_under(ui, state, focused, under) {
        // The diagram above was drawn before the step: draw it again.
        ui.ctx().request_repaint();
    }
    let height = ui.cursor().top() - top;
    ui.data_mut(|d| d.insert_temp(rows, height));
    remember_focus(ui, w_id);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drag_keeps_the_handle_where_it_was_grabbed() {
        let center = Pos2::new(100.0, 100.0);
        let press = Pos2::new(103.0, 99.0);
        assert_eq!(dragged_to(center, press, press), center);
        assert_eq!(
            dragged_to(center, press, Pos2::new(113.0, 89.0)),
            Pos2::new(110.0, 90.0)
        );
        assert!(hint(None).contains("click"));
        assert!(hint(Some(HandleId::MuT)).contains("index"));
    }
}

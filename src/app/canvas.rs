//! The interactive diagram: painted from [`Diagram`], with one focusable, draggable widget per
//! handle (named for screen readers and tests) and keyboard nudges.

use egui::emath::RectTransform;
use egui::{
    CursorIcon, EventFilter, Key, Pos2, Rect, Role, Sense, Stroke, Ui, Vec2 as EguiVec2, WidgetInfo,
};
use glam::Vec2;
use refraction_i18n::t;

use super::paint::{color, hover_left_out, paint};
use refraction_diagram::{Diagram, Overlay};
use refraction_model::{ExplorerState, HandleId};

/// Degrees per arrow-key press (Shift: a tenth of it).
pub(super) const ANGLE_STEP: f64 = 1.0;
/// Index change per key press (Shift: a tenth of it).
pub(super) const INDEX_STEP: f64 = 0.01;

/// The value a handle reports to screen readers: the diagram angle of W or N in degrees, or
/// the index.
fn handle_value(state: &ExplorerState, handle: HandleId) -> f64 {
    match handle {
        HandleId::W | HandleId::N => state.direction(handle).to_angle().to_degrees(),
        HandleId::MuI | HandleId::MuT => state.index(handle),
    }
}

/// Changes the index of a μ handle by `delta`, rounding away binary noise.
pub(super) fn nudge_index(state: &mut ExplorerState, handle: HandleId, delta: f64) {
    let index = ((state.index(handle) + delta) * 1e6).round() / 1e6;
    // A nudge to an index the kernel refuses (0 or below, or too far from the other index) leaves the marker where it was,
    // the last good state, as a refused drag does.
    state.set_index(handle, index).ok();
}

/// Applies the keys pressed while `handle` has focus: arrows turn W or N (counter-clockwise
/// for ← and ↑) or move a μ marker (↑ and → raise it); + and − change the selected index
/// (μt while W or N is selected).
fn keyboard(ui: &Ui, state: &mut ExplorerState, handle: HandleId) {
    let (turn, raise, plus, shift) = ui.input(|i| {
        let pressed = |key| i32::from(i.key_pressed(key));
        let turn = pressed(Key::ArrowLeft) + pressed(Key::ArrowUp)
            - pressed(Key::ArrowRight)
            - pressed(Key::ArrowDown);
        let raise = pressed(Key::ArrowUp) + pressed(Key::ArrowRight)
            - pressed(Key::ArrowDown)
            - pressed(Key::ArrowLeft);
        let plus = pressed(Key::Plus) + pressed(Key::Equals) - pressed(Key::Minus);
        (turn, raise, plus, i.modifiers.shift)
    });
    let scale = if shift { 0.1 } else { 1.0 };
    match handle {
        HandleId::W | HandleId::N if turn != 0 => {
            state.rotate(handle, f64::from(turn) * ANGLE_STEP * scale);
        }
        HandleId::MuI | HandleId::MuT if raise != 0 => {
            nudge_index(state, handle, f64::from(raise) * INDEX_STEP * scale);
        }
        _ => {}
    }
    if plus != 0 {
        let target = if handle == HandleId::MuI {
            HandleId::MuI
        } else {
            HandleId::MuT
        };
        nudge_index(state, target, f64::from(plus) * INDEX_STEP * scale);
    }
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
        let value = handle_value(state, handle.id);
        grab.widget_info(|| WidgetInfo::slider(true, value, handle.id.label()));
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

/// Shows the diagram of `state` with `overlay` filling the available space (less a line for
/// the keys), editing `state` by drag and keyboard and the overlay's view by pan and zoom.
///
/// A press and release within egui's click distance is a click, not a drag: it changes
/// nothing and selects the handle (or, on the background, the W handle) for the arrow keys.
pub(super) fn show(ui: &mut Ui, state: &mut ExplorerState, overlay: &mut Overlay, with_hint: bool) {
    // The hint's row (a label's row is as tall as a widget's) and the spacing above it; none
    // on a projector, where the diagram has the room.
    let text = ui.text_style_height(&egui::TextStyle::Body);
    let line = if with_hint {
        text.max(ui.spacing().interact_size.y) + 2.0 * ui.spacing().item_spacing.y
    } else {
        0.0
    };
    let size = ui.available_size() - EguiVec2::new(0.0, line);
    let (response, painter) =
        ui.allocate_painter(size.max(EguiVec2::splat(1.0)), Sense::click_and_drag());
    pan_and_zoom(ui, &response, overlay);
    let size = response.rect.size();
    let to_screen = RectTransform::from_to(Rect::from_min_size(Pos2::ZERO, size), response.rect);
    let canvas_size = Vec2::new(size.x, size.y);
    let before = Diagram::with_overlay(state, canvas_size, overlay);
    let unchanged = state.clone();
    let w_id = response.id.with(HandleId::W);
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
    if let Some(handle) = after.handles.iter().find(|h| Some(h.id) == focused) {
        let center = to_screen.transform_pos(Pos2::new(handle.center.x, handle.center.y));
        let ring = Stroke::new(2.0, color(overlay.palette.ink));
        painter.circle_stroke(center, handle.radius * 1.7, ring);
    }
    if with_hint {
        // One line, cut with "…" where the window is narrow (the whole on hover).
        let hint = hint(focused);
        ui.add(egui::Label::new(egui::RichText::new(&hint).weak()).truncate())
            .on_hover_text(hint);
    }
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

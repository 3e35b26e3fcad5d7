//! The four controls of one interface without a drag: the angle of incidence θi, the direction
//! of N and the two indices, each with its value, its step and a button either way (±1°,
//! ±0.01), for a mouse, a finger, a switch or a screen reader (WCAG 2.5.7, dragging movements).
//!
//! The canvas's handles (their arrow keys and a screen reader's slider actions), these buttons
//! and, in a browser, the page's own HTML controls all go through [`value`], [`set`] and
//! [`nudge`], so every way of turning W says and does the same.

use core::ops::RangeInclusive;

use egui::{Button, Role, Slider, SliderClamping, Ui, Vec2, WidgetInfo};
use refraction_i18n::t;
use refraction_model::describe;
use refraction_model::{ExplorerState, HandleId, INDEX_RANGE};

/// The largest angle of incidence the controls set, in degrees (the model takes θi < 90°).
pub(super) const MAX_INCIDENCE: f64 = 89.9;

/// How large the step buttons are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Reach {
    /// For a mouse: at least 24 × 24 points (WCAG 2.5.8).
    Pointer,
    /// For a finger: at least 44 × 44 points, CSS pixels in a browser (WCAG 2.5.5): the
    /// diagram's [`TOUCH_TARGET`](refraction_diagram::TOUCH_TARGET).
    Finger,
}

impl Reach {
    /// The reach `ui`'s input asks for: a finger once the screen was touched or where the
    /// window is as narrow as a phone.
    pub(super) fn of(ui: &Ui) -> Self {
        let phone = ui.ctx().content_rect().width() < 600.0;
        if phone || ui.input(egui::InputState::has_touch_screen) {
            Self::Finger
        } else {
            Self::Pointer
        }
    }

    /// A button's least side, in points.
    pub(super) fn side(self) -> f32 {
        match self {
            Self::Pointer => 24.0,
            Self::Finger => refraction_diagram::TOUCH_TARGET,
        }
    }
}

/// What `handle`'s control stands for: θi in degrees (W), N's lean from straight up in
/// degrees, clockwise (N), or the index (μi, μt).
pub(super) fn value(state: &ExplorerState, handle: HandleId) -> f64 {
    match handle {
        HandleId::W => state.incidence_degrees(),
        HandleId::N => state.normal_tilt_degrees(),
        HandleId::MuI | HandleId::MuT => state.index(handle),
    }
}

/// One step of `handle`'s control: 1° for θi and N, 0.01 for an index.
pub(super) fn step(handle: HandleId) -> f64 {
    match handle {
        HandleId::W | HandleId::N => 1.0,
        HandleId::MuI | HandleId::MuT => 0.01,
    }
}

/// Where `handle`'s control goes: θi from 0° to [`MAX_INCIDENCE`] (or to where W was dragged
/// beyond it), N all the way round, an index over the index scale's range (or to a typed index
/// beyond it).
pub(super) fn bounds(state: &ExplorerState, handle: HandleId) -> RangeInclusive<f64> {
    match handle {
        HandleId::W => 0.0..=MAX_INCIDENCE.max(state.incidence_degrees()),
        HandleId::N => -180.0..=180.0,
        HandleId::MuI | HandleId::MuT => {
            let (low, high) = INDEX_RANGE;
            let index = state.index(handle);
            low.min(index)..=high.max(index)
        }
    }
}

/// Sets `handle`'s control to `target`, kept within its [`bounds`] (N turns all the way round);
/// a value that is not a number, or an index the kernel refuses beside the other, changes
/// nothing. Returns whether the state changed.
pub(super) fn set(state: &mut ExplorerState, handle: HandleId, target: f64) -> bool {
    if !target.is_finite() {
        return false;
    }
    let before = state.clone();
    let range = bounds(state, handle);
    let kept = target.clamp(*range.start(), *range.end());
    match handle {
        HandleId::W => {
            // Within its bounds, below 90°: always an angle the model takes.
            state.set_incidence_degrees(kept).ok();
        }
        HandleId::N => state.set_normal_tilt_degrees(target),
        HandleId::MuI | HandleId::MuT => {
            // Binary noise from adding steps is rounded away; an index the kernel refuses
            // leaves the last good state, as a refused drag does.
            state.set_index(handle, (kept * 1e6).round() / 1e6).ok();
        }
    }
    *state != before
}

/// Moves `handle`'s control by `steps` of its [`step`] (negative: down; a fraction for a fine
/// step). Returns whether the state changed.
pub(super) fn nudge(state: &mut ExplorerState, handle: HandleId, steps: f64) -> bool {
    let target = value(state, handle) + steps * step(handle);
    set(state, handle, target)
}

/// Whether a step of `handle` in `direction` (+1 or −1) can change anything.
fn can_step(state: &ExplorerState, handle: HandleId, direction: f64) -> bool {
    let range = bounds(state, handle);
    let now = value(state, handle);
    handle == HandleId::N
        || if direction > 0.0 {
            now < *range.end()
        } else {
            now > *range.start()
        }
}

/// The buttons' names (also their hover texts): down, then up.
fn names(handle: HandleId) -> [String; 2] {
    let symbol = symbol(handle);
    match handle {
        HandleId::W => [
            t!("access-incidence-decrease"),
            t!("access-incidence-increase"),
        ],
        HandleId::N => [
            t!("access-normal-turn-left"),
            t!("access-normal-turn-right"),
        ],
        HandleId::MuI | HandleId::MuT => {
            let step = refraction_i18n::decimal("0.01");
            [
                t!(
                    "access-index-decrease",
                    symbol = symbol,
                    step = step.as_str()
                ),
                t!("access-index-increase", symbol = symbol, step = step),
            ]
        }
    }
}

/// The control's symbol, as the diagram labels it.
fn symbol(handle: HandleId) -> &'static str {
    match handle {
        HandleId::W => "θi",
        HandleId::N => "N",
        HandleId::MuI => "μi",
        HandleId::MuT => "μt",
    }
}

/// The value shown beside the buttons: short, as the diagram's labels are (the words a screen
/// reader says are on the hover).
fn shown(state: &ExplorerState, handle: HandleId) -> String {
    match handle {
        HandleId::W | HandleId::N => t!(
            "access-degrees",
            angle = describe::degrees(value(state, handle))
        ),
        HandleId::MuI | HandleId::MuT => describe::index(value(state, handle)),
    }
}

/// One control: its symbol and value (the control's name and value in words on hover), and
/// a button down and a button up. Returns whether a button changed `state`.
fn control(ui: &mut Ui, state: &mut ExplorerState, handle: HandleId, reach: Reach) -> bool {
    let side = Vec2::splat(reach.side());
    let mut changed = false;
    let said = format!(
        "{}, {}",
        handle.label(),
        describe::control_value(state, handle)
    );
    ui.label(format!("{} {}", symbol(handle), shown(state, handle)))
        .on_hover_text(said);
    for (direction, (text, name)) in [-1.0, 1.0]
        .into_iter()
        .zip(["−", "+"].into_iter().zip(names(handle)))
    {
        let enabled = can_step(state, handle, direction);
        let button = ui.add_enabled(enabled, Button::new(text).min_size(side));
        button.widget_info(|| WidgetInfo::labeled(Role::Button, enabled, &name));
        if button.on_hover_text(name).clicked() {
            changed |= nudge(state, handle, direction);
        }
    }
    changed
}

/// The step buttons of θi, N, μi and μt in a row that wraps where the room ends, each control
/// its value and a button either way, `reach` large. Returns whether a button changed `state`
/// (the caller draws what it showed of `state` again).
pub(super) fn row(ui: &mut Ui, state: &mut ExplorerState, reach: Reach) -> bool {
    ui.horizontal_wrapped(|ui| {
        // Off the window's edge, as the panels' contents are.
        ui.add_space(ui.spacing().window_margin.left.into());
        let mut changed = false;
        for (i, handle) in HandleId::ALL.into_iter().enumerate() {
            if i > 0 {
                ui.separator();
            }
            changed |= control(ui, state, handle, reach);
        }
        changed
    })
    .inner
}

/// An index's slider over its [`bounds`], for the long way where no index scale is shown (the
/// student's view), named as its control is. Returns whether it changed `state`.
fn slider(ui: &mut Ui, state: &mut ExplorerState, handle: HandleId) -> bool {
    let mut target = value(state, handle);
    ui.spacing_mut().slider_width = ui.available_width().max(Reach::Finger.side());
    let moved = ui.add(
        Slider::new(&mut target, bounds(state, handle))
            .show_value(false)
            .step_by(step(handle))
            // Only what the finger sets is stepped: egui's default would round a shown index
            // to the step (air's 1.000293 to 1) and write it back, unasked.
            .clamping(SliderClamping::Edits),
    );
    let name = t!("student-index", symbol = symbol(handle));
    moved.widget_info(|| WidgetInfo::slider(true, target, &name));
    moved.changed() && set(state, handle, target)
}

/// The step buttons as the student's view shows them, a finger's size: θi and N (side by side
/// under an upright diagram, one under the other in a `column` beside a sideways one), then
/// each index with a slider for the long way (the student's view shows no index scale).
/// Returns whether a control changed `state`.
pub(super) fn for_student(ui: &mut Ui, state: &mut ExplorerState, column: bool) -> bool {
    let finger = Reach::Finger;
    let mut changed = if column {
        let w = ui
            .horizontal(|ui| control(ui, state, HandleId::W, finger))
            .inner;
        w | ui
            .horizontal(|ui| control(ui, state, HandleId::N, finger))
            .inner
    } else {
        ui.horizontal_wrapped(|ui| {
            let w = control(ui, state, HandleId::W, finger);
            ui.separator();
            w | control(ui, state, HandleId::N, finger)
        })
        .inner
    };
    for handle in [HandleId::MuI, HandleId::MuT] {
        changed |= ui
            .horizontal(|ui| control(ui, state, handle, finger) | slider(ui, state, handle))
            .inner;
    }
    changed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_control_steps_within_its_bounds_and_back() {
        let mut state = ExplorerState::default();
        assert!(nudge(&mut state, HandleId::W, 1.0));
        assert!((value(&state, HandleId::W) - 41.0).abs() < 1e-9);
        assert!(nudge(&mut state, HandleId::N, 1.0));
        assert!(
            (value(&state, HandleId::N) - 1.0).abs() < 1e-9,
            "turned right"
        );
        assert!(
            (value(&state, HandleId::W) - 42.0).abs() < 1e-9,
            "W stays: N leaned 1° away from the ray coming from the upper left"
        );
        assert!(nudge(&mut state, HandleId::MuT, -1.0));
        assert_eq!(state.mu_t(), 1.49);
        assert!(set(&mut state, HandleId::W, 95.0));
        assert_eq!(value(&state, HandleId::W), MAX_INCIDENCE);
        assert!(!can_step(&state, HandleId::W, 1.0) && can_step(&state, HandleId::W, -1.0));
        assert!(!set(&mut state, HandleId::W, f64::NAN));
        state.set_mu_i(1.0).unwrap();
        assert!(!can_step(&state, HandleId::MuI, -1.0));
        assert!(
            !nudge(&mut state, HandleId::MuI, -1.0),
            "not below the scale"
        );
        state.set_mu_i(3.2).unwrap();
        assert_eq!(bounds(&state, HandleId::MuI), 1.0..=3.2);
        assert!(set(&mut state, HandleId::N, 180.0));
        assert!(
            nudge(&mut state, HandleId::N, 1.0),
            "N turns all the way round"
        );
        assert!((value(&state, HandleId::N) + 179.0).abs() < 1e-9);
    }
}

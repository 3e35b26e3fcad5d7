//! The explorer's diagram driven headlessly with `egui_kittest`: dragging the handles, the
//! convention switch turning W around, the keyboard turning the selected handle. No display and
//! no GPU needed.

use crate::common;

use common::{center_of, drag, harness, leaving_glass};
use egui::{Key, Modifiers, Pos2, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use refraction_diagram::Layout;
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

/// The screen position of the hit point, from the canvas (named by its summary) and the
/// diagram's layout for its size.
fn hit_point(harness: &Harness<'_, Explorer>) -> Pos2 {
    let canvas = harness.get_by_role(Role::Image).rect();
    let origin = Layout::new(glam::Vec2::new(canvas.width(), canvas.height()))
        .view
        .origin;
    canvas.min + Vec2::new(origin.x, origin.y)
}

#[test]
fn dragging_the_w_handle_changes_t() {
    let mut h = harness(ExplorerState::default());
    let t_before = h.state().state().refraction().t().unwrap();
    let from = center_of(&h, "Angle of incidence θi (W)");
    let to = from + Vec2::new(-60.0, 40.0);
    drag(&mut h, from, to);
    let t_after = h.state().state().refraction().t().unwrap();
    assert!(
        (t_after - t_before).length() > 0.05,
        "{t_before} → {t_after}"
    );
    assert!(center_of(&h, "Angle of incidence θi (W)").distance(from) > 10.0);
}

#[test]
fn dragging_past_the_critical_angle_shows_the_banner_and_hides_the_candidates() {
    let mut h = harness(leaving_glass());
    assert!(h.query_by_label("wrong side").is_some());
    assert!(
        h.query_by_label_contains("TOTAL INTERNAL REFLECTION")
            .is_none()
    );
    let origin = hit_point(&h);
    let from = center_of(&h, "Angle of incidence θi (W)");
    let radius = from.distance(origin);
    // W along the ray, 60° from the normal: far past the critical angle.
    let angle = 60_f32.to_radians();
    let to = origin + Vec2::new(angle.sin(), angle.cos()) * radius;
    drag(&mut h, from, to);
    assert!(h.state().state().refraction().is_tir());
    assert!(
        h.query_by_label_contains("TOTAL INTERNAL REFLECTION")
            .is_some()
    );
    for role in ["T (chosen)", "wrong side", "wrong bend", "reversed"] {
        assert!(h.query_by_label(role).is_none(), "{role} still shown");
    }
    assert!(h.query_by_label_contains("No candidates").is_some());
}

#[test]
fn switching_convention_flips_w() {
    let mut h = harness(ExplorerState::default());
    let w = h.state().state().w();
    let origin = hit_point(&h);
    let tip = center_of(&h, "Angle of incidence θi (W)");
    h.get_by_label("Section 1: W points back toward the origin")
        .click();
    h.run();
    assert_eq!(h.state().state().w(), -w);
    let flipped = center_of(&h, "Angle of incidence θi (W)");
    assert!(
        (flipped - origin + (tip - origin)).length() < 2.0,
        "{tip:?} → {flipped:?}"
    );
    let banner = h
        .get_by_role(Role::Image)
        .accesskit_node()
        .label()
        .unwrap_or_default();
    assert!(banner.contains("so a = −μ"), "{banner}");
}

#[test]
fn arrow_keys_turn_the_selected_handle_and_tab_moves_on() {
    let mut h = harness(ExplorerState::default());
    let cos_before = h.state().state().refraction().cos_i;
    h.get_by_label("Angle of incidence θi (W)").focus();
    h.run();
    h.key_press(Key::ArrowLeft);
    h.run();
    let cos_after = h.state().state().refraction().cos_i;
    let turned = cos_after.acos().to_degrees() - cos_before.acos().to_degrees();
    assert!((turned.abs() - 1.0).abs() < 1e-9, "turned {turned}°");
    h.key_press_modifiers(Modifiers::SHIFT, Key::ArrowLeft);
    h.run();
    let fine =
        h.state().state().refraction().cos_i.acos().to_degrees() - cos_after.acos().to_degrees();
    assert!((fine.abs() - 0.1).abs() < 1e-9, "turned {fine}°");
    h.key_press(Key::Tab);
    h.run();
    assert!(h.get_by_label("Direction of the normal N").is_focused());
    h.key_press(Key::Tab);
    h.run();
    h.key_press(Key::Plus);
    h.run();
    let s = h.state().state();
    assert!(h.get_by_label("Index μi of the ray's medium").is_focused());
    assert!(
        (s.mu_i() - 1.010293).abs() < 1e-12,
        "{} {}",
        s.mu_i(),
        s.mu_t()
    );
}

#[test]
fn a_click_on_the_background_selects_w_for_the_arrow_keys() {
    // Issue 22: the README promised it, and a click there left nothing selected.
    let mut h = harness(ExplorerState::default());
    let canvas = h.get_by_role(Role::Image).rect();
    let origin = hit_point(&h);
    // Below the surface, left of every ray and label: the glass's empty background.
    let spot = Pos2::new(
        canvas.min.x + 12.0,
        origin.y + (canvas.max.y - origin.y) * 0.5,
    );
    h.hover_at(spot);
    h.run();
    h.event(egui::Event::PointerButton {
        pos: spot,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    h.run();
    h.event(egui::Event::PointerButton {
        pos: spot,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    h.run();
    h.run();
    assert!(h.get_by_label("Angle of incidence θi (W)").is_focused());
    let cos_before = h.state().state().refraction().cos_i;
    h.key_press(Key::ArrowLeft);
    h.run();
    assert!((h.state().state().refraction().cos_i - cos_before).abs() > 1e-6);
}

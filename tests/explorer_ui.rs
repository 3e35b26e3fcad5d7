//! The explorer window driven headlessly with egui_kittest: drags, convention switch, the
//! candidates table, typed input, keyboard. No display and no GPU needed.

use egui::{Key, Modifiers, Pos2, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use refraction_explorer::app::Explorer;
use refraction_explorer::diagram::{ExplorerState, Layout};

fn harness(state: ExplorerState) -> Harness<'static, Explorer> {
    let mut harness = Harness::builder()
        .with_size(Vec2::new(1280.0, 760.0))
        .with_theme(egui::Theme::Light)
        .build_ui_state(|ui, app: &mut Explorer| app.show(ui), Explorer::new(state));
    harness.run();
    harness
}

/// From glass into air, W 30° from the normal: below the critical angle (41.8°).
fn leaving_glass() -> ExplorerState {
    let angle = 30_f64.to_radians();
    let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
    ExplorerState::new(w, DVec3::Y, 1.5, 1.0, Default::default()).unwrap()
}

fn center_of(harness: &Harness<'_, Explorer>, label: &str) -> Pos2 {
    harness.get_by_label(label).rect().center()
}

/// Drags from `from` to `to` in a few pointer moves.
fn drag(harness: &mut Harness<'_, Explorer>, from: Pos2, to: Pos2) {
    harness.hover_at(from);
    harness.run();
    harness.drag_at(from);
    harness.run();
    for step in 1..=4 {
        harness.hover_at(from + (to - from) * (step as f32 / 4.0));
        harness.run();
    }
    harness.drop_at(to);
    harness.run();
}

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
    let from = center_of(&h, "W handle");
    let to = from + Vec2::new(-60.0, 40.0);
    drag(&mut h, from, to);
    let t_after = h.state().state().refraction().t().unwrap();
    assert!(
        (t_after - t_before).length() > 0.05,
        "{t_before} → {t_after}"
    );
    assert!(center_of(&h, "W handle").distance(from) > 10.0);
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
    let from = center_of(&h, "W handle");
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
    let tip = center_of(&h, "W handle");
    h.get_by_label("Section 1: W points back toward the origin")
        .click();
    h.run();
    assert_eq!(h.state().state().w(), -w);
    let flipped = center_of(&h, "W handle");
    assert!(
        (flipped - origin + (tip - origin)).length() < 2.0,
        "{tip:?} → {flipped:?}"
    );
    assert!(h.query_by_label_contains("so a = −μ").is_some());
}

#[test]
fn the_table_has_four_rows_with_the_right_marks() {
    let h = harness(ExplorerState::default());
    let marks = |mark: &str| -> Vec<Pos2> {
        h.query_all_by_label(mark)
            .map(|n| n.rect().center())
            .collect()
    };
    let (passes, fails) = (marks("✔"), marks("✖"));
    let expected = [
        ("T (chosen)", [true, true, true, true]),
        ("wrong side", [true, true, false, true]),
        ("wrong bend", [true, true, true, false]),
        ("reversed", [true, true, false, false]),
    ];
    for (role, columns) in expected {
        let y = center_of(&h, role).y;
        let mut row: Vec<(f32, bool)> = passes
            .iter()
            .map(|p| (p, true))
            .chain(fails.iter().map(|p| (p, false)))
            .filter(|(p, _)| (p.y - y).abs() < 4.0)
            .map(|(p, passed)| (p.x, passed))
            .collect();
        row.sort_by(|a, b| a.0.total_cmp(&b.0));
        let got: Vec<bool> = row.iter().map(|(_, passed)| *passed).collect();
        assert_eq!(got, columns, "{role}");
    }
    assert_eq!(passes.len() + fails.len(), 16);
}

/// Replaces the text of the field labelled `label` and presses Enter.
fn type_into(h: &mut Harness<'_, Explorer>, label: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, label).focus();
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run();
    h.get_by_role_and_label(Role::TextInput, label)
        .type_text(text);
    h.run();
    h.key_press(Key::Enter);
    h.run();
}

#[test]
fn bad_typed_values_show_an_inline_error_and_keep_the_last_good_state() {
    let mut h = harness(ExplorerState::default());
    let good = h.state().state().clone();
    for (bad, message) in [
        ("NaN", "mu_t is NaN"),
        ("0", "mu_t is 0"),
        ("-1.5", "mu_t is -1.5"),
        ("glass", "is not a number"),
    ] {
        type_into(&mut h, "μt value", bad);
        assert!(
            h.query_by_label_contains(message).is_some(),
            "no error for {bad}"
        );
        assert_eq!(h.state().state(), &good);
    }
    type_into(&mut h, "W =", "0, 0, 0");
    assert!(h.query_by_label_contains("w is the zero vector").is_some());
    assert_eq!(h.state().state(), &good);
    type_into(&mut h, "μt value", "1.333");
    assert_eq!(h.state().state().mu_t(), 1.333);
    assert!(h.query_by_label_contains("mu_t is").is_none());
}

#[test]
fn typed_3d_vectors_are_refracted_in_their_plane() {
    let mut h = harness(ExplorerState::default());
    type_into(&mut h, "W =", "0.3, -0.5, 0.8");
    type_into(&mut h, "N =", "0, 0.6, 0.8");
    let state = h.state().state();
    assert_eq!(state.w(), DVec3::new(0.3, -0.5, 0.8));
    let plane = state.plane();
    let t = state.refraction().t().unwrap();
    assert!((plane.lift(plane.project(t)) - t).length() < 1e-12);
}

#[test]
fn arrow_keys_turn_the_selected_handle_and_tab_moves_on() {
    let mut h = harness(ExplorerState::default());
    let cos_before = h.state().state().refraction().cos_i;
    h.get_by_label("W handle").focus();
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
    assert!(h.get_by_label("N handle").is_focused());
    h.key_press(Key::Tab);
    h.run();
    h.key_press(Key::Plus);
    h.run();
    let s = h.state().state();
    assert!(h.get_by_label("μi handle").is_focused());
    assert!(
        (s.mu_i() - 1.010293).abs() < 1e-12,
        "{} {}",
        s.mu_i(),
        s.mu_t()
    );
}

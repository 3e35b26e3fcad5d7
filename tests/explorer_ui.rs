//! The explorer window driven headlessly with egui_kittest: drags, convention switch, the
//! candidates table, typed input, keyboard. No display and no GPU needed.

mod common;

use egui::{Key, Modifiers, Pos2, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use refraction_diagram::{ExplorerState, Layout};
use refraction_explorer::app::Explorer;

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
    common::replace_text(h, label, text);
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

// ---- Classroom tools: undo/redo, presentation, walk-through, check my T, files ----

fn undo(h: &mut Harness<'_, Explorer>) {
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
}

fn redo(h: &mut Harness<'_, Explorer>) {
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    h.run();
}

fn click(h: &mut Harness<'_, Explorer>, label: &str) {
    h.get_by_label(label).click();
    h.run();
}

#[test]
fn undo_and_redo_step_through_every_kind_of_change_and_a_drag_is_one_step() {
    let mut h = harness(ExplorerState::default());
    let mut seen = vec![h.state().state().clone()];
    type_into(&mut h, "μt value", "1.333");
    seen.push(h.state().state().clone());
    click(&mut h, "Section 1: W points back toward the origin");
    seen.push(h.state().state().clone());
    let from = center_of(&h, "W handle");
    drag(&mut h, from, from + Vec2::new(-60.0, 40.0));
    seen.push(h.state().state().clone());
    click(&mut h, "Flip N");
    seen.push(h.state().state().clone());
    assert_eq!(h.state().history().undo_steps(), 4, "a drag is one step");
    for expected in seen.iter().rev().skip(1) {
        undo(&mut h);
        assert_eq!(h.state().state(), expected);
    }
    undo(&mut h);
    assert_eq!(h.state().state(), &seen[0], "nothing before the start");
    for expected in &seen[1..] {
        redo(&mut h);
        assert_eq!(h.state().state(), expected);
    }
    undo(&mut h);
    click(&mut h, "⟳ Redo");
    assert_eq!(h.state().state(), &seen[4]);
    click(&mut h, "⟲ Undo");
    assert_eq!(h.state().state(), &seen[3]);
}

#[test]
fn presentation_mode_zooms_the_ui_and_the_themes_change_panels_and_diagram() {
    use refraction_diagram::palette::Theme;
    let mut h = harness(ExplorerState::default());
    assert_eq!(h.ctx.zoom_factor(), 1.0);
    click(&mut h, "🖵 Presentation");
    assert!(h.state().presentation().on);
    assert_eq!(
        h.ctx.zoom_factor(),
        refraction_explorer::app::presentation::ZOOM
    );
    // 1280 pixels zoomed are 800 points: the controls give way to the diagram.
    assert!(h.query_by_label("Flip N").is_none());
    h.get_by_role_and_label(Role::ComboBox, "Theme").click();
    h.run();
    click(&mut h, Theme::HighContrastDark.label());
    assert!(h.ctx.global_style().visuals.dark_mode);
    let palette = h.state().overlay().palette;
    assert_eq!(palette.background, glam_colour(0x000000));
    click(&mut h, "Colour-blind safe");
    assert!(h.state().overlay().palette.label_incoming);
    h.key_press(Key::F11);
    h.run();
    assert!(!h.state().presentation().on);
    assert_eq!(h.ctx.zoom_factor(), 1.0);
    assert!(h.query_by_label("Flip N").is_some());
}

fn glam_colour(code: u32) -> refraction_diagram::geometry::Colour {
    refraction_diagram::geometry::Colour::hex(code)
}

#[test]
fn the_walk_through_follows_the_source_highlights_the_diagram_and_animates_mu_to_one() {
    use refraction_diagram::Focus;
    let mut h = harness(ExplorerState::default());
    assert_eq!(h.state().overlay().focus, None);
    click(&mut h, "📖 Walk-through");
    assert!(h.query_by_label("Step 1 of 8: Snell's law").is_some());
    assert!(h.query_by_label_contains("μ = μi/μt = 0.6669").is_some());
    assert_eq!(h.state().overlay().focus, Some(Focus::Angles));
    let expected = [
        ("Step 2 of 8", Focus::Angles),
        ("Step 3 of 8", Focus::Decomposition),
        ("Step 4 of 8", Focus::SquaredConstraints),
        ("Step 5 of 8", Focus::RootsOfA),
        ("Step 6 of 8", Focus::ChoiceOfA),
    ];
    for (title, focus) in expected {
        click(&mut h, "Next step ▶");
        assert!(h.query_by_label_contains(title).is_some(), "{title}");
        assert_eq!(h.state().overlay().focus, Some(focus));
    }
    assert!(h.query_by_label_contains("(2.19)  a = μ").is_some());
    assert!(
        h.query_by_label("Step 6 of 8: Choosing a: the limit μ = 1")
            .is_some()
    );
    let steps_before = h.state().history().undo_steps();
    // Stepped, not run: the morph asks for every next frame until it ends.
    h.get_by_label("Animate μ to 1").click();
    h.run_steps(400);
    h.run();
    let state = h.state().state();
    assert_eq!(state.mu_t(), state.mu_i());
    let r = state.refraction();
    assert_eq!(r.t(), Some(r.travel), "T converges to the incoming ray");
    assert!(
        r.candidates
            .iter()
            .filter(|c| c.rejection.is_some())
            .all(|c| (c.t - r.travel).length() > 0.1),
        "the rejected candidates do not"
    );
    assert_eq!(h.state().history().undo_steps(), steps_before + 1);
    undo(&mut h);
    assert_eq!(h.state().state().mu_t(), 1.5);
    click(&mut h, "◀ Previous step");
    assert!(h.query_by_label_contains("Step 5 of 8").is_some());
    click(&mut h, "📖 Walk-through");
    assert_eq!(h.state().overlay().focus, None);
}

/// The case of the default state as the check panel's fields and a T, checked.
fn check_t(h: &mut Harness<'_, Explorer>, t: &str) {
    type_into(h, "Your T", t);
}

fn vector_text(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

#[test]
fn check_my_t_names_every_sign_and_convention_mix_up_and_draws_the_students_t() {
    use refraction_kernel::Rejection;
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    let r = h.state().state().refraction().clone();
    let t = r.t().unwrap();
    let candidate = |rejection| {
        r.candidates
            .iter()
            .find(|c| c.rejection == Some(rejection))
            .unwrap()
            .t
    };
    let swapped_t = refraction_kernel::refract(&refraction_kernel::Incidence {
        w: r.w,
        n: r.n,
        mu_i: 1.5,
        mu_t: 1.000293,
        convention: r.convention,
    })
    .unwrap()
    .t()
    .unwrap();
    let cases = [
        (
            vector_text(t),
            "✔ Your T matches the refracted ray T",
            "Right",
        ),
        (
            vector_text(candidate(Rejection::WrongSide)),
            "✖ Your T matches wrong side (the other root for b)",
            "outward normal",
        ),
        (
            vector_text(candidate(Rejection::WrongBend)),
            "✖ Your T matches wrong bend (the other sign of a)",
            "mixing the conventions",
        ),
        (
            vector_text(candidate(Rejection::Reversed)),
            "✖ Your T matches reversed (−T: both signs wrong)",
            "both signs are wrong",
        ),
        (
            vector_text(swapped_t),
            "✖ Your T matches none of the four candidates",
            "index ratio upside down",
        ),
        (
            vector_text((t + DVec3::new(0.0, 0.0, 0.3)).normalize()),
            "✖ Your T matches none of the four candidates",
            "leaves the plane of incidence",
        ),
        (
            vector_text(t * 2.0),
            "✖ Your T matches T's direction, but not unit length",
            "not 1: normalise",
        ),
        (
            "vec3(nan, 0.0, 1.0)".to_owned(),
            "✖ Your T matches none of the four candidates",
            "NaN or infinite",
        ),
    ];
    check_t(&mut h, &vector_text(t));
    assert_eq!(
        h.state().state(),
        &ExplorerState::default(),
        "the case kept exactly"
    );
    assert_eq!(h.state().history().undo_steps(), 0);
    for (yours, headline, explanation) in cases {
        check_t(&mut h, &yours);
        assert!(
            h.query_by_label(headline).is_some(),
            "{yours}: no {headline}"
        );
        assert!(
            h.query_by_label_contains(explanation).is_some(),
            "{yours}: no {explanation}"
        );
    }
    check_t(&mut h, "1, 2");
    assert!(
        h.query_by_label_contains("your T: expected 3 numbers")
            .is_some()
    );
    check_t(&mut h, &vector_text(candidate(Rejection::WrongSide)));
    let student = h.state().overlay().student.unwrap();
    assert_eq!(student.label, "your T: wrong side (the other root for b)");
    assert_eq!(student.t, candidate(Rejection::WrongSide));
    // Changing the case drops the drawn T.
    click(&mut h, "Flip N");
    assert_eq!(h.state().overlay().student, None);
    assert!(
        h.query_by_label_contains("the verdict is not drawn")
            .is_some()
    );
}

#[test]
fn check_my_t_opens_a_whole_json_line_and_refuses_bad_ones_without_changing_the_state() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    // A Section 1 W fed to the Section 2 formula: the classic convention mix-up.
    let line = r#"{"w":[-0.6,0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"convention":"toward_origin","t_yours":"vec3(-0.4, -0.916515, 0)"}"#;
    check_t(&mut h, line);
    let state = h.state().state().clone();
    assert_eq!(state.w(), DVec3::new(-0.6, 0.8, 0.0));
    assert_eq!(state.mu_t(), 1.5);
    assert!(
        h.query_by_label("✖ Your T matches wrong bend (the other sign of a)")
            .is_some()
    );
    let tir =
        r#"{"w":[0.9,-0.43588989435406733,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"t_yours":[0,0,0]}"#;
    check_t(&mut h, tir);
    assert!(
        h.query_by_label("✔ Your T matches total internal reflection, answered right")
            .is_some()
    );
    let before = h.state().state().clone();
    for (bad, message) in [
        ("{\"w\":[1,0,0]", "malformed JSON"),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#,
            "missing field `t_yours`",
        ),
        (
            r#"{"w":[0,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1,"t_yours":[1,0,0]}"#,
            "w is the zero vector",
        ),
    ] {
        check_t(&mut h, bad);
        assert!(h.query_by_label_contains(message).is_some(), "{bad}");
        assert_eq!(h.state().state(), &before);
    }
    click(&mut h, "Use the current case");
    type_into(&mut h, "μt", "x");
    check_t(&mut h, "0.5, -0.5, 0");
    assert!(
        h.query_by_label_contains("μt: “x” is not a number")
            .is_some()
    );
}

fn temp_file(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("explorer-ui-{}-{name}", std::process::id()))
}

#[test]
fn save_then_open_is_bit_exact_and_corrupt_or_foreign_files_change_nothing() {
    let w = DVec3::new(0.1, -1.0 / 3.0, 1e-300);
    let start = ExplorerState::new(
        w,
        DVec3::new(-0.0, 1.0, 0.0),
        1.000_293,
        std::f64::consts::E,
        Default::default(),
    )
    .unwrap();
    let mut h = harness(start.clone());
    click(&mut h, "💾 Save, open, share");
    let path = temp_file("state.json");
    type_into(&mut h, "State file", path.to_str().unwrap());
    click(&mut h, "💾 Save");
    assert!(h.query_by_label_contains("saved").is_some());
    click(&mut h, "Flip N");
    assert_ne!(h.state().state(), &start);
    click(&mut h, "📂 Open");
    let opened = h.state().state().clone();
    assert_eq!(opened, start);
    let bits = |s: &ExplorerState| {
        let mut all: Vec<u64> = [s.w(), s.n()]
            .iter()
            .flat_map(|v| v.to_array())
            .map(f64::to_bits)
            .collect();
        all.extend([s.mu_i().to_bits(), s.mu_t().to_bits()]);
        all
    };
    assert_eq!(bits(&opened), bits(&start));
    undo(&mut h);
    click(&mut h, "⟳ Redo");
    for (contents, message) in [
        ("{\"w\":[0.6,-0.8", "malformed JSON"),
        ("title = \"Glass slab\"\n", "malformed JSON"),
        (r#"{"scene":"slab"}"#, "missing field `w`"),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":-1,"mu_t":1}"#,
            "mu_i is -1",
        ),
    ] {
        std::fs::write(&path, contents).unwrap();
        click(&mut h, "📂 Open");
        assert!(h.query_by_label_contains(message).is_some(), "{contents}");
        assert_eq!(bits(h.state().state()), bits(&start), "{contents}");
    }
    std::fs::remove_file(&path).unwrap();
    click(&mut h, "📂 Open");
    assert!(
        h.query_by_label_contains("cannot read state file")
            .is_some()
    );
}

#[test]
fn the_share_string_reproduces_the_state_and_the_case_copies_as_code() {
    let mut h = harness(leaving_glass());
    click(&mut h, "💾 Save, open, share");
    click(&mut h, "🔗 Copy share string");
    let share = refraction_explorer::lines::state_file::to_json(h.state().state());
    assert!(h.query_by_label(&share).is_some());
    let shared = h.state().state().clone();
    click(&mut h, "Flip N");
    type_into(&mut h, "Paste a share string", &share);
    click(&mut h, "Apply");
    assert_eq!(h.state().state(), &shared);
    type_into(&mut h, "Paste a share string", "not a state");
    click(&mut h, "Apply");
    assert!(
        h.query_by_label_contains("share string: malformed JSON")
            .is_some()
    );
    assert_eq!(h.state().state(), &shared);
    for (button, text) in [
        ("Rust", "use refraction_kernel"),
        ("GLSL", "vec3 T = refract("),
        ("C++ (glm)", "glm::refract("),
        ("test vector", "\"t_expected\""),
        ("solve line", "\"precision\":\"f64\""),
    ] {
        click(&mut h, button);
        assert!(h.query_by_label_contains(text).is_some(), "{button}");
    }
}

//! The explorer's classroom tools driven headlessly with `egui_kittest`: undo and redo,
//! presentation mode and themes, the walk-through. No display and no GPU needed.

use crate::common;

use common::{center_of, click, drag, harness, type_into, undo};
use egui::{Key, Modifiers, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

fn redo(h: &mut Harness<'_, Explorer>) {
    h.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
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
    let from = center_of(&h, "Angle of incidence θi (W)");
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
        refraction_explorer::app::PRESENTATION_ZOOM
    );
    // 1280 pixels zoomed are 800 points: the controls give way to the diagram.
    assert!(h.query_by_label("Flip N").is_none());
    // On a projector the bar keeps one row: the theme and the look's switches are in one menu.
    click(&mut h, "Look");
    click(&mut h, &Theme::HighContrastDark.label());
    assert!(h.ctx.global_style().visuals.dark_mode);
    let palette = h.state().overlay().palette;
    assert_eq!(palette.background, glam_colour(0x000000));
    if h.query_by_label("Colour-blind safe").is_none() {
        click(&mut h, "Look");
    }
    click(&mut h, "Colour-blind safe");
    // Every palette now labels the incoming ray; the switch gives the colour-blind-safe one.
    assert!(h.state().presentation().colour_blind_safe);
    assert_eq!(
        h.state().overlay().palette,
        refraction_diagram::palette::Palette::new(Theme::HighContrastDark, true)
    );
    h.key_press(Key::F11);
    h.run();
    assert!(!h.state().presentation().on);
    assert_eq!(h.ctx.zoom_factor(), 1.0);
    assert!(h.query_by_label("Flip N").is_some());
}

fn glam_colour(code: u32) -> refraction_diagram::Colour {
    refraction_diagram::Colour::hex(code)
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

#[test]
fn what_an_undo_did_never_grows_the_top_bar() {
    // Issue 22: the Undo message grew the top bar to three rows.
    for present in [false, true] {
        let mut h = harness(ExplorerState::default());
        if present {
            click(&mut h, "🖵 Presentation");
            for _ in 0..3 {
                h.run();
            }
        }
        let top = |h: &Harness<'_, Explorer>| h.get_by_role(Role::Image).rect().min.y;
        let before = top(&h);
        h.get_by_label("Angle of incidence θi (W)").focus();
        h.run();
        h.key_press(Key::ArrowLeft);
        h.run();
        assert_eq!(h.state().history().undo_steps(), 1);
        undo(&mut h);
        for _ in 0..3 {
            h.run();
        }
        assert!(h.state().history().undo_steps() == 0);
        assert!(
            (top(&h) - before).abs() < 0.5,
            "presentation {present}: the diagram moved from {before} to {}",
            top(&h)
        );
    }
}

#[test]
fn the_numbers_keep_their_desk_width_after_presentation() {
    // Issue 22: the numbers panel came back narrower after presentation, even after a restart
    // (egui keeps the narrowed width).
    let mut h = harness(ExplorerState::default());
    let width =
        |h: &Harness<'_, Explorer>| h.get_by_label_contains("Hide the numbers").rect().left();
    for _ in 0..4 {
        h.run();
    }
    let before = width(&h);
    for _ in 0..2 {
        h.key_press(Key::F11);
        for _ in 0..4 {
            h.run();
        }
    }
    assert!(!h.state().presentation().on);
    // Within a point: egui rounds the panel's edge to a pixel at each zoom.
    assert!(
        (width(&h) - before).abs() <= 1.0,
        "the numbers panel's edge moved from {before} to {}",
        width(&h)
    );
}

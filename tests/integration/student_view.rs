//! The student's view (issue 41): what a QR code or a link opens on a phone, driven headlessly
//! at a phone's size (390 × 844 points, CSS pixels in a browser) upright and sideways, at an
//! upright tablet's (820 × 1180), and at a desk's with `view=student` in the link. The step's
//! question in readable type, the diagram across the width, handles and buttons a finger can
//! take, *Reveal*, and nothing of the teacher's.

use crate::common;

use common::{drag, harness_sized};
use egui::{Rect, Role, Shape};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

const PHONE: (f32, f32) = (390.0, 844.0);
const PHONE_SIDEWAYS: (f32, f32) = (844.0, 390.0);
const TABLET: (f32, f32) = (820.0, 1180.0);

/// The window at `size` after opening the link `fragment`.
fn opened(fragment: &str, size: (f32, f32)) -> Harness<'static, Explorer> {
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_link(fragment).unwrap();
    let mut h = harness_sized(explorer, size);
    for _ in 0..3 {
        h.run();
    }
    h
}

fn canvas(h: &Harness<'_, Explorer>) -> Rect {
    h.get_by_role(Role::Image).rect()
}

/// The size of the words `words` are drawn in, in points (the first text that holds them).
fn size_of(h: &Harness<'_, Explorer>, words: &str) -> Option<f32> {
    fn visit(shape: &Shape, words: &str) -> Option<f32> {
        match shape {
            Shape::Vec(shapes) => shapes.iter().find_map(|s| visit(s, words)),
            Shape::Text(text) if text.galley.job.text.contains(words) => text
                .galley
                .job
                .sections
                .iter()
                .map(|s| s.format.font_id.size)
                .reduce(f32::min),
            _ => None,
        }
    }
    h.output()
        .shapes
        .iter()
        .find_map(|clipped| visit(&clipped.shape, words))
}

/// What a phone's student sees of step 2 of Snell's deck, upright or sideways.
fn check_the_phone(size: (f32, f32), least_share: f32) {
    let mut h = opened("#lesson=snell&step=2", size);
    assert!(h.state().shows_student_view(&h.ctx), "{size:?}");
    let deck = h.state().lesson().deck.clone().unwrap();
    let step = &deck.steps[1];
    // The question in readable type; the diagram across the width.
    let question = step.question.clone().unwrap();
    let words: String = question.chars().take(20).collect();
    let size_px = size_of(&h, &words).expect("the question is shown");
    assert!(size_px >= 16.0, "{size:?}: the question at {size_px} px");
    let window = h.ctx.content_rect();
    let diagram = canvas(&h);
    assert!(
        diagram.width() >= window.width() * least_share,
        "{size:?}: the diagram is {} of {} wide",
        diagram.width(),
        window.width()
    );
    assert!(diagram.height() >= 200.0, "{size:?}: {diagram:?}");
    // W and N on screen, each handle a finger's target.
    for handle in ["Angle of incidence θi (W)", "Direction of the normal N"] {
        let r = h.get_by_label(handle).rect();
        assert!(
            diagram.contains_rect(r),
            "{size:?}: {handle} at {r:?} outside {diagram:?}"
        );
        assert!(
            r.width() >= 43.99 && r.height() >= 43.99,
            "{size:?}: {handle} {r:?}"
        );
    }
    // Nothing of the teacher's: no notes, no tools, no export, no panels.
    assert!(
        h.query_by_label_contains(&step.notes[..30]).is_none(),
        "{size:?}: notes"
    );
    for teacher in [
        "📝 Notes window",
        "✔ Check my T",
        "Export picture",
        "Hide the controls (F2)",
    ] {
        assert!(
            h.query_by_label_contains(teacher).is_none(),
            "{size:?}: {teacher}"
        );
    }
    // Every button a finger's size.
    for node in h.query_all_by_role(Role::Button) {
        let r = node.rect();
        let name = node.accesskit_node().label().unwrap_or_default();
        assert!(
            r.height() >= 43.5,
            "{size:?}: “{name}” is {} high",
            r.height()
        );
    }
    // Reveal, then the next step, with a finger.
    assert!(
        h.state().lesson().hides_answer(),
        "{size:?}: hidden at first"
    );
    h.get_by_label("Reveal the answer").click();
    h.run();
    assert!(!h.state().lesson().hides_answer(), "{size:?}: revealed");
    h.get_by_label("Next step").click();
    h.run();
    let shown = h.state().lesson().current().map(|(i, _)| i);
    assert_eq!(shown, Some(2), "{size:?}: the next step");
}

#[test]
fn a_phone_upright_shows_the_question_the_diagram_across_and_buttons_for_a_finger() {
    check_the_phone(PHONE, 0.99);
}

#[test]
fn a_phone_sideways_keeps_the_buttons_beside_the_diagram() {
    check_the_phone(PHONE_SIDEWAYS, 0.6);
}

#[test]
fn an_upright_tablet_gets_the_students_view_too() {
    let h = opened("#lesson=total-internal-reflection&step=2", TABLET);
    assert!(h.state().shows_student_view(&h.ctx), "an upright tablet");
    let diagram = canvas(&h);
    assert!(diagram.width() >= TABLET.0 * 0.99, "{diagram:?}");
}

#[test]
fn the_step_buttons_turn_w_and_n_and_change_the_indices() {
    let mut h = opened("#lesson=snell&step=1", PHONE);
    let before = h.state().state().incidence_degrees();
    h.get_by_label("Increase θi by 1°").click();
    h.run();
    let after = h.state().state().incidence_degrees();
    assert!((after - before - 1.0).abs() < 1e-9, "{before} → {after}");
    h.get_by_label("Decrease μt by 0.01").click();
    h.run();
    let mu_t = h.state().state().mu_t();
    assert!((mu_t - 1.49).abs() < 1e-9, "μt 1.5 → {mu_t}");
    let n = h.state().state().n();
    h.get_by_label("Turn N 1° to the right").click();
    h.run();
    let turned = h.state().state().n();
    let degrees = n.angle_between(turned).to_degrees();
    assert!((degrees - 1.0).abs() < 1e-6, "{degrees}°");
}

#[test]
fn opening_a_step_on_a_phone_keeps_its_indices_as_the_deck_gives_them() {
    // Air's 1.000293 is no multiple of the sliders' 0.01: showing them must not round it.
    let h = opened("#lesson=snell&step=2", PHONE);
    let deck = h.state().lesson().deck.clone().unwrap();
    let given = &deck.steps[1].state;
    let shown = h.state().state();
    assert_eq!((shown.mu_i(), shown.mu_t()), (given.mu_i(), given.mu_t()));
    assert!((shown.mu_i() - 1.000_293).abs() < 1e-9, "{}", shown.mu_i());
}

#[test]
fn a_finger_on_w_s_handle_turns_w() {
    let mut h = opened("#lesson=snell&step=1", PHONE);
    let before = h.state().state().w();
    let w = h.get_by_label("Angle of incidence θi (W)").rect().center();
    drag(&mut h, w, w + egui::vec2(-60.0, 30.0));
    assert_ne!(h.state().state().w(), before, "W turned");
}

#[test]
fn a_desk_opens_the_students_view_only_when_the_link_asks_and_never_on_the_projector() {
    let desk = (1280.0, 720.0);
    let h = opened("#lesson=snell&step=2", desk);
    assert!(!h.state().shows_student_view(&h.ctx), "the teacher's view");
    let mut h = opened("#lesson=snell&step=2&view=student", desk);
    assert!(h.state().shows_student_view(&h.ctx), "asked for");
    // The whole explorer on request, and back.
    h.get_by_label("🖥 Full explorer").click();
    h.run();
    assert!(!h.state().shows_student_view(&h.ctx), "the full explorer");
    h.get_by_label("📱 Student view").click();
    h.run();
    assert!(
        h.state().shows_student_view(&h.ctx),
        "back to the student's"
    );
    h.state_mut().presentation_mut().on = true;
    h.run();
    h.run();
    assert!(
        !h.state().shows_student_view(&h.ctx),
        "the projector keeps the teacher's"
    );
}

#[test]
fn a_scene_step_shows_its_scene_across_the_phone() {
    let h = opened("#lesson=total-internal-reflection&step=5", PHONE);
    let view = h.state().view();
    assert_eq!(
        view,
        refraction_explorer::app::View::Scenes,
        "the step's scene"
    );
    let diagram = canvas(&h);
    assert!(diagram.width() >= PHONE.0 * 0.99, "{diagram:?}");
    // No scene controls nor its files: the scene picker and export are the teacher's.
    assert!(h.query_by_label_contains("Reset").is_none());
}

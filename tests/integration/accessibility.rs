//! The window as a screen reader, a keyboard and a switch reach it, through its AccessKit tree
//! (`egui_kittest`): the four controls are sliders named as the page names them, with their
//! values in words and units; a screen reader's increment, decrement and set-value actions
//! move them; the step buttons do the same without a drag; Tab reaches the handles without a
//! click; the polite live status says what changed once the change rests, total internal
//! reflection once when it begins and once when it ends, and a hidden answer never.

use crate::common;

use common::{harness, harness_sized, leaving_glass};
use egui::Key;
use egui::accesskit::{Live, Role};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use refraction_deck::Deck;
use refraction_explorer::app::Explorer;
use refraction_model::{ExplorerState, HandleId};

const INCIDENCE: &str = "Angle of incidence θi (W)";

/// Steps the window for `seconds` of its time (a quarter of a second a step), so that an edit
/// rests and is said.
fn rest(h: &mut Harness<'_, Explorer>, seconds: f32) {
    for _ in 0..(seconds * 4.0).ceil() as usize {
        h.step();
    }
    h.run();
}

/// What the live status says now.
fn status(h: &Harness<'_, Explorer>) -> String {
    let node = h.get_by_role(Role::Status);
    assert_eq!(
        node.accesskit_node().data().live(),
        Some(Live::Polite),
        "the status is a polite live region"
    );
    node.value().unwrap_or_default()
}

fn incidence(h: &Harness<'_, Explorer>) -> f64 {
    h.state().state().incidence_degrees()
}

/// The slider of `label`'s value in words and as a number.
fn slider(h: &Harness<'_, Explorer>, label: &str) -> (String, f64) {
    let node = h.get_by_role_and_label(Role::Slider, label);
    let number = node.accesskit_node().data().numeric_value().unwrap();
    (node.value().unwrap_or_default(), number)
}

#[test]
fn the_angle_of_incidence_is_a_slider_a_screen_reader_turns_by_a_degree() {
    let mut h = harness(ExplorerState::default());
    let (words, number) = slider(&h, INCIDENCE);
    assert_eq!(words, "40°");
    assert!((number - 40.0).abs() < 1e-9, "{number}");
    let node = h.get_by_role_and_label(Role::Slider, INCIDENCE);
    let data = node.accesskit_node().data().clone();
    assert_eq!(data.numeric_value_step(), Some(1.0));
    assert_eq!(data.min_numeric_value(), Some(0.0));
    let w = h.state().state().w();
    node.increment_accesskit();
    h.run();
    assert!((incidence(&h) - 41.0).abs() < 1e-9, "θi {}", incidence(&h));
    let turned = w.angle_between(h.state().state().w()).to_degrees();
    assert!((turned - 1.0).abs() < 1e-9, "W turned {turned}°");
    assert_eq!(slider(&h, INCIDENCE).0, "41°");
    rest(&mut h, 1.0);
    let said = status(&h);
    assert_eq!(said, "θi 40° → 41°: T at 25.9° from the normal.");
    for _ in 0..2 {
        h.get_by_role_and_label(Role::Slider, INCIDENCE)
            .decrement_accesskit();
        h.run();
    }
    assert!((incidence(&h) - 39.0).abs() < 1e-9);
    h.get_by_role_and_label(Role::Slider, INCIDENCE)
        .set_value_accesskit(60.0);
    h.run();
    assert!((incidence(&h) - 60.0).abs() < 1e-9);
    rest(&mut h, 1.0);
    assert!(status(&h).contains("→ 60°"), "{}", status(&h));
}

#[test]
fn every_control_is_named_with_its_value_and_unit() {
    let mut h = harness(leaving_glass());
    assert_eq!(
        slider(&h, "Direction of the normal N"),
        ("straight up".to_owned(), 0.0)
    );
    assert_eq!(
        slider(&h, "Index μi of the ray's medium"),
        ("1.5 (glass)".to_owned(), 1.5)
    );
    assert_eq!(
        slider(&h, "Index μt of the medium entered"),
        ("1 (vacuum)".to_owned(), 1.0)
    );
    let n = h.get_by_role_and_label(Role::Slider, "Direction of the normal N");
    n.increment_accesskit();
    h.run();
    assert_eq!(
        slider(&h, "Direction of the normal N").0,
        "1° right of straight up"
    );
    // The canvas's words: the banner as its name, the describer's sentences as its description.
    let canvas = h.get_by_role(Role::Image);
    let description = canvas.accesskit_node().description().unwrap_or_default();
    assert!(
        description.contains("T bends away from the normal"),
        "{description}"
    );
    h.get_by_role_and_label(Role::Slider, INCIDENCE)
        .set_value_accesskit(60.0);
    h.run();
    let canvas = h.get_by_role(Role::Image);
    let description = canvas.accesskit_node().description().unwrap_or_default();
    assert!(
        description.contains("Total internal reflection"),
        "{description}"
    );
}

#[test]
fn the_step_buttons_turn_w_and_n_and_change_the_indices_without_a_drag() {
    let mut h = harness(ExplorerState::default());
    for (button, check) in [("Increase θi by 1°", 41.0), ("Decrease θi by 1°", 40.0)] {
        let node = h.get_by_role_and_label(Role::Button, button);
        let size = node.rect().size();
        assert!(size.x >= 24.0 && size.y >= 24.0, "{button}: {size:?}");
        node.click();
        h.run();
        assert!((incidence(&h) - check).abs() < 1e-9, "{button}");
    }
    h.get_by_label("Turn N 1° to the right").click();
    h.run();
    assert!((h.state().state().normal_tilt_degrees() - 1.0).abs() < 1e-9);
    h.get_by_label("Decrease μt by 0.01").click();
    h.run();
    assert_eq!(h.state().state().mu_t(), 1.49);
    h.get_by_label("Increase μi by 0.01").click();
    h.run();
    assert_eq!(h.state().state().mu_i(), 1.010293);
}

#[test]
fn on_a_phone_the_step_buttons_take_a_finger() {
    let mut h = harness_sized(Explorer::new(ExplorerState::default()), (390.0, 844.0));
    h.run();
    let node = h.get_by_role_and_label(Role::Button, "Increase θi by 1°");
    let size = node.rect().size();
    assert!(size.x >= 44.0 && size.y >= 44.0, "{size:?}");
}

#[test]
fn total_internal_reflection_is_said_once_when_it_begins_and_once_when_it_ends() {
    let mut explorer = Explorer::new(leaving_glass());
    let mut state = leaving_glass();
    state.set_incidence_degrees(41.0).unwrap();
    explorer.set_state(state);
    let mut h = common::harness_for(explorer);
    let step = |h: &mut Harness<'_, Explorer>, up: bool| {
        let node = h.get_by_role_and_label(Role::Slider, INCIDENCE);
        if up {
            node.increment_accesskit();
        } else {
            node.decrement_accesskit();
        }
        h.run();
        rest(h, 1.0);
        status(h)
    };
    assert_eq!(
        step(&mut h, true),
        "θi 41° → 42°: now past the critical angle 41.8°; all light is reflected."
    );
    assert_eq!(step(&mut h, true), "θi 42° → 43°.");
    let ends = step(&mut h, false);
    assert_eq!(ends, "θi 43° → 42°.");
    let ends = step(&mut h, false);
    assert!(
        ends.starts_with("θi 42° → 41°: now short of the critical angle 41.8°; T leaves at"),
        "{ends}"
    );
}

#[test]
fn tab_reaches_the_handles_without_a_click_and_the_arrows_turn_w() {
    let mut h = harness(ExplorerState::default());
    let mut presses = 0;
    while !h
        .get_by_role_and_label(Role::Slider, INCIDENCE)
        .is_focused()
    {
        presses += 1;
        assert!(presses < 2, "Tab with nothing selected selects W");
        h.key_press(Key::Tab);
        h.run();
    }
    h.key_press(Key::ArrowUp);
    h.run();
    assert!((incidence(&h) - 41.0).abs() < 1e-9, "↑ raises θi");
    h.key_press(Key::Tab);
    h.run();
    assert!(
        h.get_by_role_and_label(Role::Slider, &HandleId::N.label())
            .is_focused()
    );
    // Esc lets go; Tab comes back to W.
    h.key_press(Key::Escape);
    h.run();
    h.key_press(Key::Tab);
    h.run();
    assert!(
        h.get_by_role_and_label(Role::Slider, INCIDENCE)
            .is_focused()
    );
}

#[test]
fn a_hidden_answer_is_never_said_and_the_reveal_says_it() {
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_deck(Deck::load("snell").unwrap());
    let mut h = harness_sized(explorer, (1280.0, 720.0));
    let canvas = h.get_by_role(Role::Image);
    let description = canvas.accesskit_node().description().unwrap_or_default();
    assert!(
        description.contains("The answer is hidden"),
        "{description}"
    );
    assert!(!description.contains("bends"), "{description}");
    h.get_by_role_and_label(Role::Slider, INCIDENCE)
        .increment_accesskit();
    h.run();
    rest(&mut h, 1.0);
    assert_eq!(status(&h), "θi 40° → 41°.", "no T while it is hidden");
    h.key_press(Key::R);
    h.run();
    let said = status(&h);
    assert!(
        said.starts_with("Step 1 of 5: From air into glass."),
        "{said}"
    );
    assert!(said.contains("T bends toward the normal"), "{said}");
}

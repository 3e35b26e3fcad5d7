//! A lesson deck in the window, driven headlessly with `egui_kittest` as a teacher drives it:
//! the clicker's keys move between steps, R reveals the hidden answer, the arrow keys turn a
//! selected handle before they step, a drag changes the diagram and not the deck, the notes
//! (as data, and in their window, embedded here), and a deck built in the tool, saved and
//! opened again.

use crate::common;

use common::{center_of, drag, harness_sized, replace_text};
use egui::{Key, Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use refraction_deck::{Deck, StepView};
use refraction_explorer::app::{Explorer, Status, View};
use refraction_i18n::t;
use refraction_model::ExplorerState;

/// The window at 1280×720 on the built-in deck `name`, at its first step.
fn on_deck(name: &str) -> Harness<'static, Explorer> {
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_deck(Deck::load(name).unwrap());
    harness_sized(explorer, (1280.0, 720.0))
}

fn press(h: &mut Harness<'_, Explorer>, key: Key) {
    h.key_press(key);
    h.run();
}

/// The position of the step shown.
fn step_shown(h: &Harness<'_, Explorer>) -> usize {
    h.state().lesson().current().unwrap().0
}

/// The accessible name of the canvas: the banner's words.
fn canvas_says(h: &Harness<'_, Explorer>) -> String {
    h.get_by_role(Role::Image)
        .accesskit_node()
        .label()
        .unwrap_or_default()
}

#[test]
fn page_down_moves_a_step_and_the_reveal_key_shows_what_was_hidden() {
    let mut h = on_deck("snell");
    let deck = h.state().lesson().deck.clone().unwrap();
    assert_eq!(step_shown(&h), 0);
    assert!(h.query_by_label("1 / 5").is_some(), "the step's number");
    assert!(h.query_by_label(&deck.steps[0].title).is_some());
    assert!(h.state().overlay().hide_answer, "a question: T is hidden");
    assert!(canvas_says(&h).contains("hidden"), "{}", canvas_says(&h));
    press(&mut h, Key::R);
    assert!(!h.state().overlay().hide_answer, "R reveals it");
    assert!(canvas_says(&h).contains("T exists"), "{}", canvas_says(&h));
    press(&mut h, Key::PageDown);
    assert_eq!(step_shown(&h), 1);
    assert!(h.query_by_label("2 / 5").is_some());
    assert_eq!(
        *h.state().state(),
        deck.steps[1].state,
        "the step's own state"
    );
    assert!(
        h.state().overlay().hide_answer,
        "its question hides its answer"
    );
    press(&mut h, Key::PageUp);
    assert_eq!(step_shown(&h), 0);
    assert!(
        h.state().overlay().hide_answer,
        "hidden again on the way back"
    );
    press(&mut h, Key::Space);
    press(&mut h, Key::ArrowRight);
    assert_eq!(step_shown(&h), 2, "space and → move on too");
    assert!(
        !h.state().overlay().hide_answer,
        "a step without a question shows all"
    );
    for _ in 0..6 {
        press(&mut h, Key::PageDown);
    }
    assert_eq!(step_shown(&h), 4, "the last step stays");
    assert_eq!(h.state().view(), View::Scenes, "the slab, traced");
}

#[test]
fn a_deck_file_gone_by_the_time_the_window_opens_is_said_in_the_deck_tool() {
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_lesson("no-such-deck-file.toml");
    assert!(explorer.lesson().deck.is_none());
    let said = match explorer.lesson().panel.status.clone() {
        Some(Status::Refused(why)) => why,
        _ => String::new(),
    };
    assert!(said.contains("no-such-deck-file.toml"), "{said}");
    let h = harness_sized(explorer, (1280.0, 720.0));
    assert!(
        h.query_by_label_contains("no-such-deck-file.toml")
            .is_some(),
        "the deck tool is open and says why"
    );
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_lesson("snell");
    let opened = explorer.lesson().deck.as_ref().map(|d| d.steps.len());
    assert_eq!(opened, Some(Deck::load("snell").unwrap().steps.len()));
}

#[test]
fn a_scene_steps_rays_stop_at_the_first_surface_until_revealed() {
    let mut h = on_deck("total-internal-reflection");
    for _ in 0..4 {
        press(&mut h, Key::PageDown);
    }
    let step = h.state().lesson().current().unwrap().1.clone();
    assert_eq!(step.view, StepView::Scenes);
    assert_eq!(h.state().scenes().scene().name(), "fibre");
    assert!(h.state().lesson().hides_answer());
    // Before the reveal the picture's words count only the source's rays: "20 total
    // internal reflections" answered "does it escape through the side?".
    let hidden = canvas_says(&h);
    assert_eq!(hidden, "Optical fibre: 9 source rays · 1 wavelength");
    press(&mut h, Key::R);
    assert!(!h.state().lesson().hides_answer());
    let shown = canvas_says(&h);
    assert!(
        shown.starts_with("Optical fibre: ") && shown.contains("20 total internal reflections"),
        "{shown}"
    );
}

#[test]
fn arrow_keys_turn_a_selected_handle_and_step_once_it_is_let_go() {
    let mut h = on_deck("snell");
    let before = h.state().state().clone();
    h.get_by_label("Angle of incidence θi (W)").focus();
    h.run();
    press(&mut h, Key::ArrowRight);
    assert_eq!(step_shown(&h), 0, "the handle takes the arrow");
    assert_ne!(*h.state().state(), before, "W turned");
    press(&mut h, Key::PageDown);
    assert_eq!(step_shown(&h), 1, "Page Down steps whatever has the focus");
    press(&mut h, Key::Escape);
    press(&mut h, Key::ArrowLeft);
    assert_eq!(step_shown(&h), 0, "with nothing selected, ← steps back");
    assert_eq!(
        *h.state().state(),
        before,
        "the step as saved, not as it was turned"
    );
}

#[test]
fn dragging_during_a_step_changes_the_diagram_and_not_the_deck() {
    let mut h = on_deck("snell");
    let saved = h.state().lesson().deck.clone().unwrap();
    let from = center_of(&h, "Angle of incidence θi (W)");
    drag(&mut h, from, from + Vec2::new(-60.0, 40.0));
    assert_ne!(*h.state().state(), saved.steps[0].state, "the drag moved W");
    assert_eq!(h.state().lesson().deck.as_ref(), Some(&saved));
    press(&mut h, Key::PageDown);
    press(&mut h, Key::PageUp);
    assert_eq!(*h.state().state(), saved.steps[0].state);
}

#[test]
fn the_notes_follow_the_step_as_data_and_in_their_window() {
    let mut h = on_deck("fresnel-brewster");
    let notes = h.state().lesson().notes().unwrap();
    let deck = h.state().lesson().deck.clone().unwrap();
    assert_eq!((notes.number, notes.count), (1, deck.steps.len()));
    assert_eq!(notes.notes, deck.steps[0].notes);
    assert_eq!(notes.next.as_deref(), Some(deck.steps[1].title.as_str()));
    press(&mut h, Key::N);
    assert!(h.state().lesson().notes_open);
    let next = t!("deck-notes-next", title = deck.steps[1].title.clone());
    assert!(h.query_by_label(&next).is_some(), "the notes window shows");
    press(&mut h, Key::PageDown);
    let notes = h.state().lesson().notes().unwrap();
    assert_eq!(notes.notes, deck.steps[1].notes);
    assert!(h.query_by_label(&deck.steps[1].notes).is_some());
    press(&mut h, Key::N);
    assert!(!h.state().lesson().notes_open);
}

#[test]
fn a_deck_built_in_the_tool_is_saved_and_opened_again_with_every_field() {
    let folder = std::env::temp_dir().join(format!("deck-tool-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let path = folder.join("mine.toml");
    let mut h = harness_sized(Explorer::new(ExplorerState::default()), (1280.0, 720.0));
    h.get_by_label(&format!("📚 {}", t!("tool-deck"))).click();
    h.run();
    let add = format!("➕ {}", t!("deck-add-step"));
    h.get_by_label(&add).click();
    h.run();
    h.get_by_label(&add).click();
    h.run();
    assert_eq!(h.state().lesson().deck.as_ref().unwrap().steps.len(), 2);
    replace_text(&mut h, &t!("deck-step-title"), "Second, my way");
    replace_text(&mut h, &t!("deck-step-question"), "Which way?");
    replace_text(&mut h, &t!("deck-file"), path.to_str().unwrap());
    h.get_by_label(&t!("deck-save-file")).click();
    h.run();
    let built = h.state().lesson().deck.clone().unwrap();
    assert_eq!(built.steps[1].title, "Second, my way");
    assert_eq!(built.steps[1].question.as_deref(), Some("Which way?"));
    let opened = Deck::load(path.to_str().unwrap()).unwrap();
    assert_eq!(opened.steps, built.steps, "saved with every field");
    // A second save asks before it replaces the file.
    h.get_by_label(&t!("deck-save-file")).click();
    h.run();
    assert!(h.query_by_label(&t!("files-replace")).is_some());
    std::fs::remove_dir_all(&folder).unwrap();
}

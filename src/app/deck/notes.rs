//! The teacher's notes in a window of their own (an egui viewport: a second native window,
//! which can sit on the laptop's screen while the projector shows the diagram; embedded in the
//! main window where the backend has one window only, as under a headless test), and the
//! buttons that step through the deck with a mouse.

use egui::{Context, RichText, ScrollArea, Ui, ViewportBuilder, ViewportId};
use refraction_i18n::t;

use super::{DeckCommand, LessonDeck};
use crate::app::widgets::icon_button;

/// What the notes window shows for one step.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Notes {
    /// The step's number, from 1.
    pub number: usize,
    /// How many steps the deck has.
    pub count: usize,
    /// The deck's title.
    pub deck: String,
    /// The step's title.
    pub title: String,
    /// The question for the class, if any.
    pub question: Option<String>,
    /// The teacher's notes.
    pub notes: String,
    /// The next step's title, or `None` on the last step.
    pub next: Option<String>,
}

/// The buttons that step with a mouse: previous, next, reveal (on a step with a question) and
/// the notes window; only their icons when `compact` (the strip above a projector's diagram),
/// their names then their accessible names and hovers. Returns what was clicked.
pub(super) fn buttons(ui: &mut Ui, notes: &Notes, hidden: bool, compact: bool) -> Vec<DeckCommand> {
    let keys = t!("deck-keys");
    let reveal = if hidden {
        t!("deck-reveal")
    } else {
        t!("deck-hide")
    };
    let buttons = [
        (
            "⏴",
            t!("deck-previous"),
            keys.clone(),
            (notes.number > 1, false),
            DeckCommand::Previous,
        ),
        (
            "⏵",
            t!("deck-next"),
            keys,
            (notes.number < notes.count, false),
            DeckCommand::Next,
        ),
        // Only a step with a question has an answer to reveal; shown, the button stays
        // pressed, so the class sees which state the step is in.
        (
            if hidden { "👁" } else { "🙈" },
            reveal,
            t!("deck-hidden-hint"),
            (notes.question.is_some(), !hidden),
            DeckCommand::Reveal,
        ),
        (
            "📝",
            t!("deck-notes-window"),
            t!("deck-notes-window-hover"),
            (true, false),
            DeckCommand::Notes,
        ),
    ];
    let mut asked = Vec::new();
    for (icon, name, hover, state, command) in buttons {
        if command == DeckCommand::Reveal && notes.question.is_none() {
            continue;
        }
        if icon_button(ui, (icon, name, hover), state, compact) {
            asked.push(command);
        }
    }
    asked
}

/// The notes window's contents: the step, its question and notes, the next step's title and
/// the buttons.
fn contents(ui: &mut Ui, notes: &Notes, hidden: bool) -> Vec<DeckCommand> {
    let number = t!(
        "deck-step-number",
        number = notes.number.to_string(),
        count = notes.count.to_string()
    );
    ui.heading(format!("{number} · {}", notes.title));
    if let Some(question) = &notes.question {
        ui.label(RichText::new(format!("❓ {question}")).strong());
    }
    ui.separator();
    ScrollArea::vertical()
        .max_height(ui.available_height() - 80.0)
        .show(ui, |ui| {
            if notes.notes.trim().is_empty() {
                ui.label(RichText::new(t!("deck-notes-none")).weak());
            } else {
                ui.label(&notes.notes);
            }
        });
    ui.separator();
    let next = notes.next.as_ref().map_or_else(
        || t!("deck-notes-last"),
        |title| t!("deck-notes-next", title = title),
    );
    ui.label(RichText::new(next).weak());
    ui.horizontal_wrapped(|ui| buttons(ui, notes, hidden, false))
        .inner
}

/// Shows the notes window for `notes` and reads the deck's keys pressed in it. Returns what
/// its keys and buttons asked, and whether the window was closed.
pub(super) fn show(ctx: &Context, notes: &Notes, hidden: bool) -> (Vec<DeckCommand>, bool) {
    let title = t!("deck-notes-title", title = &notes.deck);
    let builder = ViewportBuilder::default()
        .with_title(title)
        .with_inner_size([520.0, 420.0]);
    // untranslated: the viewport's id, never shown.
    let id = ViewportId::from_hash_of("lesson-deck-notes");
    ctx.show_viewport_immediate(id, builder, |ui, _class| {
        let closed = ui.input(|i| i.viewport().close_requested());
        let mut asked = LessonDeck::keys(ui);
        egui::CentralPanel::default().show(ui, |ui| {
            asked.extend(contents(ui, notes, hidden));
        });
        // The notes' own button closes the window as its close box does.
        let closed = closed || asked.contains(&DeckCommand::Notes);
        asked.retain(|c| *c != DeckCommand::Notes);
        (asked, closed)
    })
}

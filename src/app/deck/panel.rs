//! The *Lesson deck* tool: builds a deck from what the window shows (a step added from the
//! current state, or the state kept in the step shown), reorders and deletes steps, edits each
//! step's title, question and notes, and opens and saves deck files through the file dialog
//! (after a question before a deck file is replaced, never over a file of another kind).

use core::fmt::Display;
use std::path::{Path, PathBuf};

use egui::{ComboBox, RichText, Role, TextEdit, Ui, WidgetInfo};
use refraction_deck::{Deck, builtin};
use refraction_files::write_atomically;
use refraction_i18n::t;

use super::title_of;
use crate::app::file_dialog::{
    FileDialog, Kind, Purpose, Target, answer_replace, chosen_file, target,
};
use crate::app::status::{self, Look, Status};
use crate::app::widgets::{OPEN_ICON, SAVE_AS_ICON, icon_button};

/// The deck file offered first.
pub(crate) const DEFAULT_DECK_PATH: &str = "lesson.toml";

/// The extensions the dialog lists.
const DECK_FILES: &[&str] = &["toml"];

/// What the tool asks of the window, which holds what a step is made of.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Add the window as it is now as a step after the one shown.
    Add,
    /// Keep the window as it is now in the step shown.
    Update,
    /// Show this step.
    GoTo(usize),
    /// Show this deck from its first step.
    Open(Deck),
    /// Write the deck's handout (PDF).
    Handout,
}

/// The tool's file field, dialog and replace question, and what its last action said.
#[derive(Clone, Debug)]
pub struct DeckPanel {
    path: String,
    /// What the last save, open or step said.
    pub status: Option<Status>,
    dialog: Option<FileDialog>,
    replace: Option<PathBuf>,
    /// Whether the deck changed since it was opened or saved.
    pub edited: bool,
}

impl Default for DeckPanel {
    fn default() -> Self {
        Self {
            path: DEFAULT_DECK_PATH.to_owned(),
            status: None,
            dialog: None,
            replace: None,
            edited: false,
        }
    }
}

impl DeckPanel {
    /// Shows the tool for `deck`, whose step `current` is shown. Returns what it asks of the
    /// window; moves, deletions and edits it makes itself (keeping `current` on its step).
    pub fn show(
        &mut self,
        ui: &mut Ui,
        deck: &mut Option<Deck>,
        current: &mut Option<usize>,
    ) -> Option<Action> {
        let mut action = self.files_row(ui, deck.as_ref());
        ui.horizontal_wrapped(|ui| {
            let add = ui
                .button(format!("➕ {}", t!("deck-add-step")))
                .on_hover_text(t!("deck-add-step-hover"));
            if add.clicked() {
                action = Some(Action::Add);
            }
            let update = ui
                .add_enabled(current.is_some(), egui::Button::new(t!("deck-update-step")))
                .on_hover_text(t!("deck-update-step-hover"));
            if update.clicked() {
                action = Some(Action::Update);
            }
            if ui
                .button(t!("deck-new"))
                .on_hover_text(t!("deck-new-hover"))
                .clicked()
            {
                *deck = Some(Deck {
                    title: String::new(),
                    steps: Vec::new(),
                    folder: None,
                });
                *current = None;
                self.edited = false;
            }
            let has_steps = deck.as_ref().is_some_and(|d| !d.steps.is_empty());
            let handout = ui
                .add_enabled(has_steps, egui::Button::new(t!("handout-export")))
                .on_hover_text(t!("handout-export-hover"));
            if handout.clicked() {
                action = Some(Action::Handout);
            }
        });
        if let Some(deck) = deck {
            let title = ui.label(t!("deck-title-field"));
            let width = ui.available_width();
            self.edited |= ui
                .add(TextEdit::singleline(&mut deck.title).desired_width(width))
                .labelled_by(title.id)
                .changed();
            action = self.steps(ui, deck, current).or(action);
            if let Some(step) = current.and_then(|i| deck.steps.get_mut(i)) {
                self.edited |= fields(ui, step);
            }
        }
        status::show(ui, self.status.as_ref(), Look::Plain);
        if self.edited {
            ui.label(RichText::new(t!("deck-edited")).weak());
        }
        self.dialogs(ui, deck.as_ref()).or(action)
    }

    /// The deck file, *Open file*, *Save file*, the dialog's *Open…* and *Save as…*, and the
    /// built-in decks.
    fn files_row(&mut self, ui: &mut Ui, deck: Option<&Deck>) -> Option<Action> {
        let mut action = None;
        ui.horizontal_wrapped(|ui| {
            let label = ui.label(t!("deck-file"));
            let width = ui.available_width().min(200.0);
            ui.add(TextEdit::singleline(&mut self.path).desired_width(width))
                .labelled_by(label.id);
            if ui.button(t!("deck-open-file")).clicked() {
                action = self.open();
            }
            if ui.button(t!("deck-save-file")).clicked() {
                self.save(deck);
            }
            let open = (
                OPEN_ICON,
                t!("files-open-dialog"),
                t!("deck-open-dialog-hover"),
            );
            if icon_button(ui, open, (true, false), true) {
                self.dialog = Some(FileDialog::new(Purpose::Open, DECK_FILES, &self.path));
            }
            let save_as = (SAVE_AS_ICON, t!("files-save-as"), t!("files-save-as-hover"));
            if icon_button(ui, save_as, (true, false), true) {
                self.dialog = Some(FileDialog::new(Purpose::Save, DECK_FILES, &self.path));
            }
            let mut picked = None;
            let name = t!("deck-built-in");
            ComboBox::from_id_salt("built-in-decks")
                .selected_text(&name)
                .show_ui(ui, |ui| {
                    for info in builtin::catalogue() {
                        if ui.selectable_label(false, &info.title).clicked() {
                            picked = builtin::deck(info.name);
                        }
                    }
                })
                .response
                .widget_info(|| WidgetInfo::labeled(Role::ComboBox, true, &name));
            if let Some(deck) = picked {
                self.edited = false;
                action = Some(Action::Open(deck));
            }
        });
        action
    }

    /// The steps in order, the one shown selected, each with its move and delete buttons.
    fn steps(
        &mut self,
        ui: &mut Ui,
        deck: &mut Deck,
        current: &mut Option<usize>,
    ) -> Option<Action> {
        ui.label(RichText::new(t!("deck-steps")).strong());
        if deck.steps.is_empty() {
            ui.label(RichText::new(t!("deck-no-steps")).weak());
            return None;
        }
        let (mut action, mut moved, mut deleted) = (None, None, None);
        let last = deck.steps.len() - 1;
        for (i, step) in deck.steps.iter().enumerate() {
            ui.horizontal(|ui| {
                let up = ("⏶", t!("deck-move-up"), t!("deck-move-up"));
                if icon_button(ui, up, (i > 0, false), true) {
                    moved = Some((i, i - 1));
                }
                let down = ("⏷", t!("deck-move-down"), t!("deck-move-down"));
                if icon_button(ui, down, (i < last, false), true) {
                    moved = Some((i, i + 1));
                }
                let delete = ("🗑", t!("deck-delete"), t!("deck-delete"));
                if icon_button(ui, delete, (true, false), true) {
                    deleted = Some(i);
                }
                let row = t!(
                    "deck-step-row",
                    number = (i + 1).to_string(),
                    title = title_of(step, i)
                );
                let row = egui::Button::selectable(*current == Some(i), row).truncate();
                if ui.add(row).clicked() {
                    action = Some(Action::GoTo(i));
                }
            });
        }
        if let Some((from, to)) = moved {
            deck.steps.swap(from, to);
            *current = current.map(|c| match c {
                c if c == from => to,
                c if c == to => from,
                c => c,
            });
            self.edited = true;
        }
        if let Some(gone) = deleted {
            deck.steps.remove(gone);
            self.edited = true;
            match *current {
                Some(c) if c == gone => {
                    *current = None;
                    action = (!deck.steps.is_empty())
                        .then(|| Action::GoTo(gone.min(deck.steps.len() - 1)));
                }
                Some(c) if c > gone => *current = Some(c - 1),
                _ => {}
            }
        }
        action
    }

    /// Opens the deck file (or built-in deck) named in the field, or says why it cannot.
    fn open(&mut self) -> Option<Action> {
        let path = self.path.trim().to_owned();
        match Deck::load(&path) {
            Ok(deck) => {
                self.status = Some(Status::Done(t!("deck-opened", path = path)));
                self.edited = false;
                Some(Action::Open(deck))
            }
            Err(e) => {
                self.status = Some(Status::Refused(e.to_string()));
                None
            }
        }
    }

    /// Saves `deck` to the file in the field: at once to a new file, after a question over a
    /// deck file, never over a file of another kind or to a name that is not `.toml`.
    fn save(&mut self, deck: Option<&Deck>) {
        if deck.is_none_or(|d| d.steps.is_empty()) {
            self.status = Some(Status::Refused(t!("deck-nothing-to-save")));
            return;
        }
        let path = PathBuf::from(self.path.trim());
        match target(&path, Kind::Deck) {
            Ok(Target::New) => self.write(deck, &path),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(e) => self.status = Some(Status::Refused(e.to_string())),
        }
    }

    fn write(&mut self, deck: Option<&Deck>, path: &Path) {
        let Some(deck) = deck else {
            return;
        };
        let not_saved = |reason: &dyn Display| {
            Status::Refused(t!("deck-not-saved", reason = reason.to_string()))
        };
        let written = deck
            .to_toml()
            .map(|text| write_atomically(path, text.as_bytes()));
        self.status = Some(match written {
            Ok(Ok(())) => {
                self.edited = false;
                Status::Done(t!("deck-saved", path = path.display().to_string()))
            }
            Ok(Err(e)) => not_saved(&e),
            Err(e) => not_saved(&e),
        });
    }

    /// The dialog and the replace question, while either is up; returns the deck opened from
    /// the dialog, if one was.
    fn dialogs(&mut self, ui: &Ui, deck: Option<&Deck>) -> Option<Action> {
        let mut action = None;
        if let Some((dialog, path)) = chosen_file(ui, &mut self.dialog, |d| d) {
            self.path = path.display().to_string();
            match dialog.purpose() {
                Purpose::Open => action = self.open(),
                Purpose::Save => self.save(deck),
            }
        }
        if let Some(path) = answer_replace(ui, &mut self.replace, &mut self.status) {
            self.write(deck, &path);
        }
        action
    }
}

/// The step's title, question and notes; returns whether any changed.
fn fields(ui: &mut Ui, step: &mut refraction_deck::Step) -> bool {
    let mut changed = false;
    // As wide as the panel: a field asked to be wider would run past the window's edge.
    let width = ui.available_width();
    let title = ui.label(t!("deck-step-title"));
    changed |= ui
        .add(TextEdit::singleline(&mut step.title).desired_width(width))
        .labelled_by(title.id)
        .changed();
    let label = ui.label(t!("deck-step-question"));
    let mut question = step.question.clone().unwrap_or_default();
    let field = TextEdit::singleline(&mut question)
        .hint_text(t!("deck-step-question-hint"))
        .desired_width(width);
    if ui.add(field).labelled_by(label.id).changed() {
        step.question = (!question.trim().is_empty()).then_some(question);
        changed = true;
    }
    let label = ui.label(t!("deck-step-notes"));
    changed |= ui
        .add(
            TextEdit::multiline(&mut step.notes)
                .desired_rows(3)
                .desired_width(width),
        )
        .labelled_by(label.id)
        .changed();
    changed
}

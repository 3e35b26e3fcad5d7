//! Nothing lost, everything shareable: save and open the state as a file (the `solve` JSON
//! fields, written atomically), a share string that reproduces the exact state elsewhere, and
//! the current case copied as a `solve` line, code or a unit-test vector; and the link row
//! (the web build's address, *Copy link*, *QR code*), whose QR code `super::link` shows.

use std::path::{Path, PathBuf};

use egui::{RichText, TextEdit, Ui};
use refraction_i18n::t;

use super::file_dialog::{
    FileDialog, Kind, Purpose, Target, answer_replace, chosen_file, first_bytes, target,
};
use super::status::{self, Look, Status};
use super::widgets::{OPEN_ICON, SAVE_AS_ICON, icon_button};
use refraction_model::ExplorerState;
use refraction_tools::{RequestError, StateFileError, link, snippets};
use refraction_tools::{
    open_state_file, parse_state, save_state_file, state_request, state_to_json,
};

/// The file name offered first.
pub(super) const DEFAULT_PATH: &str = "refraction-state.json";

/// The formats the current case can be copied in: the button's label (in the current
/// language) and how to write it.
type Format = (
    fn() -> String,
    fn(&refraction_tools::Request) -> Result<String, RequestError>,
);

/// The copy buttons, in order. The programming languages' names are the same in every language.
const FORMATS: [Format; 5] = [
    (|| t!("files-copy-solve-line"), |r| Ok(r.to_json_line())),
    (|| "Rust".to_owned(), snippets::rust), // untranslated: a programming language's name
    (|| "GLSL".to_owned(), snippets::glsl), // untranslated: a programming language's name
    (|| "C++ (glm)".to_owned(), snippets::cpp), // untranslated: a language and library's name
    (|| t!("files-copy-test-vector"), snippets::test_vector),
];

/// What went wrong opening a state file, in the current language (the reason as the reader
/// wrote it).
fn open_failed(error: &StateFileError) -> String {
    match error {
        StateFileError::Read { path, source } => {
            let reason = source.to_string();
            t!("files-cannot-read-state", path = path, reason = reason)
        }
        StateFileError::Refused { path, reason } => {
            t!(
                "files-state-refused",
                path = path,
                reason = reason.to_string()
            )
        }
    }
}

/// The panel's fields and what its last action said.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct FilesPanel {
    path: String,
    pasted: String,
    status: Option<Status>,
    copied: Option<String>,
    /// The open or save dialog, while it is up.
    dialog: Option<FileDialog>,
    /// A file the user is asked about replacing.
    replace: Option<PathBuf>,
    /// A scene or a lesson deck opened here by mistake for a state: the window opens it as
    /// what it is.
    opened: Option<Opened>,
    /// The web build's address, *Copy link* and *QR code*.
    pub share: LinkRow,
}

/// A file of another kind than a state, opened from the state's field.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Opened {
    /// A scene, for the Scenes view.
    Scene(Box<refraction_scene::Scene>),
    /// A lesson deck, shown at its first step.
    Deck(Box<refraction_deck::Deck>),
}

impl Default for FilesPanel {
    fn default() -> Self {
        Self {
            path: DEFAULT_PATH.to_owned(),
            pasted: String::new(),
            status: None,
            copied: None,
            dialog: None,
            replace: None,
            opened: None,
            share: LinkRow::default(),
        }
    }
}

impl FilesPanel {
    /// Saves the state to the file in the path field: at once to a new file, after a question
    /// over an existing state file, never over a file of another kind (an image) or to a name
    /// that is not `.json`.
    pub(super) fn save(&mut self, state: &ExplorerState) {
        let path = PathBuf::from(self.path.trim());
        match target(&path, Kind::State) {
            Ok(Target::New) => self.write(state, &path),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(e) => self.status = Some(Status::Refused(e.to_string())),
        }
    }

    fn write(&mut self, state: &ExplorerState, path: &std::path::Path) {
        let shown = path.display().to_string();
        self.status = Some(match save_state_file(state, path) {
            Ok(()) => Status::Done(t!("files-saved", path = &shown)),
            Err(reason) => Status::Refused(t!("files-not-saved", reason = reason.to_string())),
        });
    }

    /// The dialog and the replace question, while either is up.
    fn dialogs(&mut self, ui: &Ui, state: &mut ExplorerState) {
        if let Some((dialog, path)) = chosen_file(ui, &mut self.dialog, |d| d) {
            self.path = path.display().to_string();
            match dialog.purpose() {
                Purpose::Open => self.open(state),
                Purpose::Save => self.save(state),
            }
        }
        if let Some(path) = answer_replace(ui, &mut self.replace, &mut self.status) {
            self.write(state, &path);
        }
    }

    /// Opens the file in the path field; a file that cannot be read or understood leaves the
    /// state as it was and says why.
    pub(super) fn open(&mut self, state: &mut ExplorerState) {
        let path = PathBuf::from(self.path.trim());
        self.status = Some(match open_state_file(&path) {
            Ok(opened) => {
                *state = opened;
                Status::Done(t!("files-opened", path = path.display().to_string()))
            }
            Err(e) => self.open_as_what_it_is(&path, &e),
        });
        // The share string shown was the old state's.
        self.copied = None;
    }

    /// A file that is not a state but a scene or a lesson deck (a TOML file picked by
    /// mistake) is opened as one, and the window shows it; anything else keeps the state's
    /// error.
    fn open_as_what_it_is(&mut self, path: &Path, error: &StateFileError) -> Status {
        let start = first_bytes(path);
        let shown = path.display().to_string();
        let not_a_state = || open_failed(error);
        match start.as_deref().and_then(Kind::of_contents) {
            Some(Kind::Deck) => match refraction_deck::Deck::load(&shown) {
                Ok(deck) => {
                    self.opened = Some(Opened::Deck(Box::new(deck)));
                    Status::Done(t!("files-opened-as-deck", path = shown))
                }
                Err(e) => Status::Refused(e.to_string()),
            },
            Some(Kind::Scene) => match refraction_scene::Scene::load(&shown) {
                Ok(scene) => {
                    self.opened = Some(Opened::Scene(Box::new(scene)));
                    Status::Done(t!("files-opened-as-scene", path = shown))
                }
                Err(e) => {
                    let (state, scene) = (not_a_state(), e.to_string());
                    Status::Refused(t!(
                        "files-neither-state-nor-scene",
                        state = state,
                        scene = scene
                    ))
                }
            },
            _ => Status::Refused(not_a_state()),
        }
    }

    /// A scene or deck the state's field opened, once: the window shows it.
    pub(super) fn take_opened(&mut self) -> Option<Opened> {
        self.opened.take()
    }

    /// Applies the pasted share string, or says why it cannot be.
    pub(super) fn apply_pasted(&mut self, state: &mut ExplorerState) {
        self.status = Some(match parse_state(&self.pasted) {
            Ok(pasted) => {
                *state = pasted;
                // The share string shown was the old state's.
                self.copied = None;
                Status::Done(t!("files-share-applied"))
            }
            Err(reason) => Status::Refused(t!("files-share-refused", reason = reason.to_string())),
        });
    }

    /// Shows the panel: file, share string, copy buttons, and the last outcome.
    pub(super) fn show(&mut self, ui: &mut Ui, state: &mut ExplorerState) {
        ui.horizontal_wrapped(|ui| {
            let name = ui.label(t!("files-state-file"));
            ui.add(TextEdit::singleline(&mut self.path).desired_width(260.0))
                .labelled_by(name.id);
            if ui
                .button(t!("files-save"))
                .on_hover_text(t!("files-save-hover"))
                .clicked()
            {
                self.save(state);
            }
            if ui
                .button(t!("files-open"))
                .on_hover_text(t!("files-open-hover"))
                .clicked()
            {
                self.open(state);
            }
            let open = (
                OPEN_ICON,
                t!("files-open-dialog"),
                t!("files-open-dialog-hover"),
            );
            if icon_button(ui, open, (true, false), false) {
                self.dialog = Some(FileDialog::new(Purpose::Open, &["json"], &self.path));
            }
            let save_as = (SAVE_AS_ICON, t!("files-save-as"), t!("files-save-as-hover"));
            if icon_button(ui, save_as, (true, false), false) {
                self.dialog = Some(FileDialog::new(Purpose::Save, &["json"], &self.path));
            }
        });
        self.dialogs(ui, state);
        ui.horizontal_wrapped(|ui| {
            let share = state_to_json(state);
            if ui
                .button(t!("files-copy-share"))
                .on_hover_text(t!("files-copy-share-hover"))
                .clicked()
            {
                ui.ctx().copy_text(share.clone());
                self.copied = Some(share);
                self.status = Some(Status::Done(t!("files-share-copied")));
            }
            let name = ui.label(t!("files-paste-share"));
            ui.add(TextEdit::singleline(&mut self.pasted).desired_width(260.0))
                .labelled_by(name.id);
            if ui.button(t!("files-apply")).clicked() {
                self.apply_pasted(state);
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label(t!("files-copy-case-as"));
            let request = state_request(state);
            for (label, write) in FORMATS {
                let label = label();
                if ui.button(&label).clicked() {
                    match write(&request) {
                        Ok(text) => {
                            ui.ctx().copy_text(text.clone());
                            self.copied = Some(text);
                            self.status = Some(Status::Done(t!("files-copied", what = label)));
                        }
                        Err(e) => self.status = Some(Status::Refused(e.to_string())),
                    }
                }
            }
        });
        status::show(ui, self.status.as_ref(), Look::Plain);
        if let Some(text) = &self.copied {
            ui.label(RichText::new(text).monospace().small());
        }
        ui.separator();
        self.share.ui(ui);
    }
}

/// The link row of the *Save, open, share* tool: the web build's address, *Copy link*,
/// *QR code* and the link itself, to read or select.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct LinkRow {
    /// The web build's address, as typed (empty: none set).
    pub base: String,
    /// The link of what the class sees, set by the window each frame (`None` without an
    /// address).
    pub url: Option<String>,
    /// Set when *QR code* is pressed, for the window to show it.
    pub qr_asked: bool,
    /// What the last *Copy link* said.
    said: Option<Status>,
}

impl LinkRow {
    /// The row: the address field, *Copy link*, *QR code*, then the link.
    pub(super) fn ui(&mut self, ui: &mut Ui) {
        ui.horizontal_wrapped(|ui| {
            let name = ui.label(t!("link-web-base"));
            ui.add(
                TextEdit::singleline(&mut self.base)
                    .hint_text("https://…")
                    .desired_width(260.0),
            )
            .labelled_by(name.id)
            .on_hover_text(t!("link-web-base-hover"));
            let copy = ui.add_enabled(self.url.is_some(), egui::Button::new(t!("link-copy")));
            if copy.on_hover_text(t!("link-copy-hover")).clicked()
                && let Some(url) = &self.url
            {
                ui.ctx().copy_text(url.clone());
                self.said = Some(Status::Done(t!("link-copied")));
            }
            if ui
                .button(t!("link-qr"))
                .on_hover_text(t!("link-qr-hover"))
                .clicked()
            {
                self.qr_asked = true;
            }
        });
        match &self.url {
            Some(url) => {
                ui.add(egui::Label::new(RichText::new(url).monospace().weak()).selectable(true));
            }
            None => match link::web_base(&self.base) {
                Err(refusal) if !self.base.trim().is_empty() => {
                    ui.label(RichText::new(refusal.message()).color(ui.visuals().warn_fg_color));
                }
                _ => {
                    ui.label(RichText::new(t!("link-no-web-base")).weak());
                }
            },
        }
        status::show(ui, self.said.as_ref(), Look::Plain);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable as _;
    use refraction_i18n::{Locale, set_locale};

    type Panel = (FilesPanel, ExplorerState);

    #[test]
    fn the_save_tool_and_its_dialog_speak_german() {
        set_locale(Locale::De);
        let mut h = Harness::builder()
            .with_size(egui::Vec2::new(900.0, 700.0))
            .build_ui_state(
                |ui, (panel, state): &mut Panel| panel.show(ui, state),
                (FilesPanel::default(), ExplorerState::default()),
            );
        h.run();
        assert!(h.query_by_label("Zustandsdatei").is_some());
        assert!(h.query_by_label("Den Fall kopieren als").is_some());
        h.get_by_label("💾 Speichern unter…").click();
        h.run();
        let found = [
            h.query_by_label("Speichern unter").is_some(),
            h.query_by_label("Dateiname").is_some(),
            h.query_by_label("Abbrechen").is_some(),
        ];
        h.get_by_label("Abbrechen").click();
        h.run();
        let closed = h.query_by_label("Dateiname").is_none();
        set_locale(Locale::En);
        assert_eq!(found, [true; 3]);
        assert!(closed, "Abbrechen closes the dialog");
    }
}

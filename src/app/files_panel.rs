//! Nothing lost, everything shareable: save and open the state as a file (the `solve` JSON
//! fields, written atomically), a share string that reproduces the exact state elsewhere, and
//! the current case copied as a `solve` line, code or a unit-test vector.

use std::path::PathBuf;

use egui::{RichText, TextEdit, Ui};

use super::file_dialog::{Choice, FileDialog, Kind, Purpose, Target, confirm_replace, target};
use super::typed::status;
use crate::app::snippets;
use crate::lines::state_file;
use refraction_diagram::ExplorerState;

/// The file name offered first.
pub const DEFAULT_PATH: &str = "refraction-state.json";

/// The formats the current case can be copied in: the button's label and how to write it.
type Format = (
    &'static str,
    fn(&crate::lines::solve::Request) -> Result<String, String>,
);

/// The copy buttons, in order.
const FORMATS: [Format; 5] = [
    ("solve line", |r| Ok(r.to_json_line())),
    ("Rust", snippets::rust),
    ("GLSL", snippets::glsl),
    ("C++ (glm)", snippets::cpp),
    ("test vector", snippets::test_vector),
];

/// The panel's fields and what its last action said.
#[derive(Clone, Debug, PartialEq)]
pub struct FilesPanel {
    path: String,
    pasted: String,
    status: Option<Result<String, String>>,
    copied: Option<String>,
    /// The open or save dialog, while it is up.
    dialog: Option<FileDialog>,
    /// A file the user is asked about replacing.
    replace: Option<PathBuf>,
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
        }
    }
}

impl FilesPanel {
    /// Saves the state to the file in the path field: at once to a new file, after a question
    /// over an existing state file, never over a file of another kind (an image) or to a name
    /// that is not `.json`.
    pub fn save(&mut self, state: &ExplorerState) {
        let path = PathBuf::from(self.path.trim());
        match target(&path, Kind::State) {
            Ok(Target::New) => self.write(state, &path),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(e) => self.status = Some(Err(e)),
        }
    }

    fn write(&mut self, state: &ExplorerState, path: &std::path::Path) {
        self.status =
            Some(state_file::save(state, path).map(|()| format!("saved {}", path.display())));
    }

    /// The dialog and the replace question, while either is up.
    fn dialogs(&mut self, ui: &Ui, state: &mut ExplorerState) {
        if let Some(dialog) = &mut self.dialog {
            let purpose = dialog.purpose();
            match dialog.show(ui) {
                Choice::Pending => {}
                Choice::Cancelled => self.dialog = None,
                Choice::Chosen(path) => {
                    self.dialog = None;
                    self.path = path.display().to_string();
                    match purpose {
                        Purpose::Open => self.open(state),
                        Purpose::Save => self.save(state),
                    }
                }
            }
        }
        if let Some(path) = self.replace.clone()
            && let Some(replace) = confirm_replace(ui, &path)
        {
            self.replace = None;
            if replace {
                self.write(state, &path);
            } else {
                self.status = Some(Ok(format!("{} left as it was", path.display())));
            }
        }
    }

    /// Opens the file in the path field; a file that cannot be read or understood leaves the
    /// state as it was and says why.
    pub fn open(&mut self, state: &mut ExplorerState) {
        let path = PathBuf::from(self.path.trim());
        self.status = Some(state_file::load(&path).map(|opened| {
            *state = opened;
            format!("opened {}", path.display())
        }));
    }

    /// Applies the pasted share string, or says why it cannot be.
    pub fn apply_pasted(&mut self, state: &mut ExplorerState) {
        self.status = Some(
            state_file::parse(&self.pasted)
                .map(|pasted| {
                    *state = pasted;
                    "applied the share string".to_owned()
                })
                .map_err(|e| format!("share string: {e}")),
        );
    }

    /// Shows the panel: file, share string, copy buttons, and the last outcome.
    pub fn show(&mut self, ui: &mut Ui, state: &mut ExplorerState) {
        ui.horizontal_wrapped(|ui| {
            let name = ui.label("State file");
            ui.add(TextEdit::singleline(&mut self.path).desired_width(260.0))
                .labelled_by(name.id);
            if ui
                .button("💾 Save")
                .on_hover_text("Write W, N, μ and the convention as a solve JSON line")
                .clicked()
            {
                self.save(state);
            }
            if ui
                .button("📂 Open")
                .on_hover_text("Read a solve JSON file; a bad file changes nothing")
                .clicked()
            {
                self.open(state);
            }
            if ui
                .button("📂 Open…")
                .on_hover_text("Choose a state file to open")
                .clicked()
            {
                self.dialog = Some(FileDialog::new(Purpose::Open, &["json"], &self.path));
            }
            if ui
                .button("💾 Save as…")
                .on_hover_text("Choose where to save")
                .clicked()
            {
                self.dialog = Some(FileDialog::new(Purpose::Save, &["json"], &self.path));
            }
        });
        self.dialogs(ui, state);
        ui.horizontal_wrapped(|ui| {
            let share = state_file::to_json(state);
            if ui
                .button("🔗 Copy share string")
                .on_hover_text("Reproduces this exact state on another machine, bit for bit")
                .clicked()
            {
                ui.ctx().copy_text(share.clone());
                self.copied = Some(share);
                self.status = Some(Ok("copied the share string".to_owned()));
            }
            let name = ui.label("Paste a share string");
            ui.add(TextEdit::singleline(&mut self.pasted).desired_width(260.0))
                .labelled_by(name.id);
            if ui.button("Apply").clicked() {
                self.apply_pasted(state);
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Copy the case as");
            let request = state_file::request(state);
            for (label, write) in FORMATS {
                if ui.button(label).clicked() {
                    match write(&request) {
                        Ok(text) => {
                            ui.ctx().copy_text(text.clone());
                            self.copied = Some(text);
                            self.status = Some(Ok(format!("copied the {label}")));
                        }
                        Err(e) => self.status = Some(Err(e)),
                    }
                }
            }
        });
        status(ui, self.status.as_ref());
        if let Some(text) = &self.copied {
            ui.label(RichText::new(text).monospace().small());
        }
    }
}

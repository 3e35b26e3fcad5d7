//! Nothing lost, everything shareable: save and open the state as a file (the `solve` JSON
//! fields, written atomically), a share string that reproduces the exact state elsewhere, and
//! the current case copied as a `solve` line, code or a unit-test vector.

use std::path::PathBuf;

use egui::{RichText, TextEdit, Ui};

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
}

impl Default for FilesPanel {
    fn default() -> Self {
        Self {
            path: DEFAULT_PATH.to_owned(),
            pasted: String::new(),
            status: None,
            copied: None,
        }
    }
}

impl FilesPanel {
    /// Saves the state to the file in the path field.
    pub fn save(&mut self, state: &ExplorerState) {
        let path = PathBuf::from(self.path.trim());
        self.status =
            Some(state_file::save(state, &path).map(|()| format!("saved {}", path.display())));
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
        });
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

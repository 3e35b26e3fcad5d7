//! The open and save dialog in a browser page: *Choose a file…* opens the browser's file
//! picker, and the file chosen is read and handed to `refraction_files` under its name, which
//! keeps it in memory (`refraction_files::browser`); a save asks for the name only, and the file
//! is downloaded (`super::super::browser`, once written).
//!
//! A file the browser cannot read, or one larger than any reader of the window takes
//! ([`MAX_FILE_BYTES`]), is said in the dialog and not read.

use core::cell::RefCell;
use std::path::{Path, PathBuf};

use egui::{Id, Modal, RichText, TextEdit, Ui};
use js_sys::Uint8Array;
use refraction_i18n::t;
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::{Closure, JsValue};
use wasm_bindgen_futures::{JsFuture, spawn_local};

use super::{Choice, Purpose};

/// The largest file the page reads: the largest any reader of the window takes (a log, 16
/// MiB); a bigger one would be refused after it was read whole into the page's memory.
const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;

thread_local! {
    /// The file the picker gave, once read, until the dialog takes it.
    static PICKED: RefCell<Option<PathBuf>> = const { RefCell::new(None) };
    /// Why the file last chosen in the picker was not read, in words, until a new choice.
    static PICK_PROBLEM: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Why the file `name` of `size_bytes` is not read, if it is too large.
pub(in crate::app) fn too_large(name: &str, size_bytes: f64) -> Option<String> {
    let megabytes = |bytes: f64| format!("{:.1}", bytes / 1_048_576.0);
    (size_bytes > MAX_FILE_BYTES as f64).then(|| {
        t!(
            "web-file-too-large",
            name = name,
            size = megabytes(size_bytes),
            limit = (MAX_FILE_BYTES >> 20).to_string()
        )
    })
}

/// The browser's words for a failed read.
pub(in crate::app) fn read_failed(name: &str, reason: &str) -> String {
    t!("web-read-failed", name = name, reason = reason)
}

/// The bytes of a browser `File`, or why they cannot be had, in words.
async fn bytes_of(file: &web_sys::File) -> Result<Vec<u8>, String> {
    if let Some(refusal) = too_large(&file.name(), file.size()) {
        return Err(refusal);
    }
    let buffer = JsFuture::from(file.array_buffer()).await.map_err(|e| {
        let reason = e.as_string().unwrap_or_else(|| format!("{e:?}"));
        read_failed(&file.name(), &reason)
    })?;
    Ok(Uint8Array::new(&buffer).to_vec())
}

/// Opens the browser's file picker for files ending in one of `extensions`; the file chosen
/// is read, given to `refraction_files` under its name and left for [`dialog`] to take.
fn pick(extensions: &[&str], ctx: &egui::Context) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        // untranslated: for the browser's console, where a developer reads it.
        .ok_or_else(|| JsValue::from_str("no document"))?;
    let input: web_sys::HtmlInputElement = document.create_element("input")?.dyn_into()?;
    input.set_type("file");
    let accept: Vec<String> = extensions.iter().map(|e| format!(".{e}")).collect();
    input.set_accept(&accept.join(","));
    let (ctx, chosen) = (ctx.clone(), input.clone());
    let changed = Closure::once_into_js(move || {
        let Some(file) = chosen.files().and_then(|files| files.get(0)) else {
            return;
        };
        spawn_local(async move {
            match bytes_of(&file).await {
                Ok(bytes) => {
                    let path = PathBuf::from(file.name());
                    refraction_files::browser::provide(&path, bytes);
                    PICKED.with_borrow_mut(|picked| *picked = Some(path));
                }
                Err(problem) => PICK_PROBLEM.with_borrow_mut(|said| *said = Some(problem)),
            }
            ctx.request_repaint();
        });
    });
    input.set_onchange(Some(changed.unchecked_ref()));
    PICK_PROBLEM.with_borrow_mut(Option::take);
    input.click();
    Ok(())
}

/// The open or save dialog in a browser: *Choose a file…* opens the browser's picker (the
/// file chosen is the dialog's choice); a save asks for the name only, and the file is
/// downloaded.
pub(super) fn dialog(
    purpose: Purpose,
    extensions: &[&str],
    name: &mut String,
    problem: Option<&String>,
    ui: &Ui,
) -> Choice {
    if let Some(path) = PICKED.with_borrow_mut(Option::take) {
        return Choice::Chosen(path);
    }
    let modal = Modal::new(Id::unique(("browser-file-dialog", purpose))).show(ui.ctx(), |ui| {
        let (mut chosen, mut cancelled) = (false, false);
        match purpose {
            Purpose::Open => {
                ui.heading(t!("files-dialog-open-title"));
                ui.label(t!("web-open-through-picker"));
                ui.horizontal(|ui| {
                    if ui.button(t!("web-choose-file")).clicked()
                        && let Err(e) = pick(extensions, ui.ctx())
                    {
                        web_sys::console::error_1(&e);
                    }
                    cancelled = ui.button(t!("files-cancel")).clicked();
                });
            }
            Purpose::Save => {
                ui.heading(t!("files-dialog-save-title"));
                ui.horizontal(|ui| {
                    let label = ui.label(t!("files-file-name"));
                    ui.add(TextEdit::singleline(name).desired_width(300.0))
                        .labelled_by(label.id);
                });
                ui.label(RichText::new(t!("web-saved-as-download")).weak());
                ui.horizontal(|ui| {
                    chosen = ui.button(t!("web-download")).clicked();
                    cancelled = ui.button(t!("files-cancel")).clicked();
                });
            }
        }
        let picked = PICK_PROBLEM.with_borrow(Clone::clone);
        for problem in problem.into_iter().chain(picked.as_ref()) {
            ui.label(RichText::new(format!("⚠ {problem}")).strong());
        }
        (chosen, cancelled)
    });
    let (chosen, cancelled) = modal.inner;
    let name = Path::new(name.trim());
    if chosen && name.file_name().is_some() {
        return Choice::Chosen(name.to_path_buf());
    }
    if cancelled || modal.should_close() {
        PICK_PROBLEM.with_borrow_mut(Option::take);
        return Choice::Cancelled;
    }
    Choice::Pending
}

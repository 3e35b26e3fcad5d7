//! Files in a browser page: the open and save dialog becomes the browser's file picker and a
//! download, and files dropped on the page are read before the window sees them. What is read
//! and written goes through `refraction_files` as on a desktop, which keeps it in memory
//! (`refraction_files::browser`): this module only moves bytes between it and the browser.
//!
//! A file the browser cannot read, or one larger than any reader of the window takes
//! ([`MAX_FILE_BYTES`]), is said (in the dialog, or in the window's strip for a dropped file)
//! and not read; a download's address is released once the browser has taken it.

use core::cell::RefCell;
use std::path::{Path, PathBuf};

use egui::{Id, Modal, RichText, TextEdit, Ui};
use js_sys::{Array, Uint8Array};
use refraction_i18n::t;
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::{Closure, JsValue};
use wasm_bindgen_futures::{JsFuture, spawn_local};

use crate::app::file_dialog::{Choice, Purpose};

/// The largest file the page reads: the largest any reader of the window takes (a log, 16
/// MiB); a bigger one would be refused after it was read whole into the page's memory.
const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;

/// How long a download's address is kept: the browser has taken the bytes by then (revoked at
/// once, some browsers lose the download).
const DOWNLOAD_ADDRESS_MS: i32 = 60_000;

thread_local! {
    /// The file the picker gave, once read, until the dialog takes it.
    static PICKED: RefCell<Option<PathBuf>> = const { RefCell::new(None) };
    /// Why the file last chosen in the picker was not read, in words, until a new choice.
    static PICK_PROBLEM: RefCell<Option<String>> = const { RefCell::new(None) };
    /// Files dropped on the page and read, to hand back to the window on the next frame.
    static DROPPED: RefCell<Vec<egui::DroppedFileHandle>> = const { RefCell::new(Vec::new()) };
}

/// Why the file `name` of `size_bytes` is not read, if it is too large.
fn too_large(name: &str, size_bytes: f64) -> Option<String> {
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
fn read_failed(name: &str, reason: &str) -> String {
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
pub(in crate::app) fn dialog(
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

/// The type a download of `path` is offered as.
fn mime_of(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()) {
        Some("png") => "image/png",
        Some("gif") => "image/gif",
        Some("svg") => "image/svg+xml",
        Some("pdf") => "application/pdf",
        Some("json") => "application/json",
        _ => "text/plain",
    }
}

/// Hands `bytes` to the browser as a download named after `path`'s file name.
fn download(path: &Path, bytes: &[u8]) -> Result<(), JsValue> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        // untranslated: for the browser's console, where a developer reads it.
        .ok_or_else(|| JsValue::from_str("no document"))?;
    let parts = Array::of1(&Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime_of(path));
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let anchor: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    anchor.set_href(&url);
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    anchor.set_download(&name.unwrap_or_default());
    anchor.click();
    // The browser has taken the bytes once the click is handled; the address (and the bytes
    // the blob holds) can go then.
    let revoke = Closure::once_into_js(move || {
        web_sys::Url::revoke_object_url(&url).ok();
    });
    if let Some(window) = web_sys::window() {
        window.set_timeout_with_callback_and_timeout_and_arguments_0(
            revoke.unchecked_ref(),
            DOWNLOAD_ADDRESS_MS,
        )?;
    }
    Ok(())
}

/// Downloads every file the window wrote since the last frame.
pub(super) fn deliver_written() {
    for (path, bytes) in refraction_files::browser::take_written() {
        if let Err(e) = download(&path, &bytes) {
            web_sys::console::error_1(&e);
        }
    }
}

/// Takes the files dropped on the page out of this frame's input, reads each (the browser
/// reads files only asynchronously) and gives it back to the window in a later frame, once
/// its bytes can be read under its name; the files read since the last frame go in now. A file
/// too large or that cannot be read is said in the window's strip instead.
pub(super) fn take_dropped(ctx: &egui::Context, raw: &mut egui::RawInput) {
    let arriving = core::mem::take(&mut raw.dropped_files);
    raw.dropped_files = DROPPED.with_borrow_mut(core::mem::take);
    for file in arriving {
        let name = file.path().display().to_string();
        let size = file.web_file().map_or(0.0, |f| f.size());
        if let Some(refusal) = too_large(&name, size) {
            super::page::refused(refusal);
            continue;
        }
        let ctx = ctx.clone();
        spawn_local(async move {
            match file.bytes_async().await {
                Ok(bytes) => {
                    refraction_files::browser::provide(file.path(), bytes);
                    DROPPED.with_borrow_mut(|dropped| dropped.push(file));
                }
                Err(reason) => super::page::refused(read_failed(&name, &reason)),
            }
            ctx.request_repaint();
        });
    }
}

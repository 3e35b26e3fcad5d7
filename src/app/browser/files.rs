//! Files in a browser page beside the open and save dialog (the browser's file picker,
//! `crate::app::file_dialog`): what the window writes is downloaded, and files dropped on the
//! page are read before the window sees them. What is read and written goes through
//! `refraction_files` as on a desktop, which keeps it in memory (`refraction_files::browser`):
//! this module only moves bytes between it and the browser.
//!
//! A dropped file the browser cannot read, or one larger than any reader of the window takes,
//! is said in the window's strip and not read; a download's address is released once the
//! browser has taken it.

use core::cell::RefCell;
use std::path::Path;

use js_sys::{Array, Uint8Array};
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::{Closure, JsValue};
use wasm_bindgen_futures::spawn_local;

use crate::app::file_dialog::picker::{read_failed, too_large};

/// How long a download's address is kept: the browser has taken the bytes by then (revoked at
/// once, some browsers lose the download).
const DOWNLOAD_ADDRESS_MS: i32 = 60_000;

thread_local! {
    /// Files dropped on the page and read, to hand back to the window on the next frame.
    static DROPPED: RefCell<Vec<egui::DroppedFileHandle>> = const { RefCell::new(Vec::new()) };
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

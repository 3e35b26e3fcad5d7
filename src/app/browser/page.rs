//! What the window asks of the page around it: its address and fragment, the browser's
//! language, full screen, the clipboard (which a browser may refuse) and the canvas's words
//! for screen readers.

use core::cell::RefCell;

use js_sys::{Function, Promise, Reflect};
use refraction_i18n::{Locale, t};
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::JsValue;
use wasm_bindgen_futures::{JsFuture, spawn_local};

thread_local! {
    /// What the browser refused since the last frame (a copy, full screen), in words.
    static REFUSED: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
    /// Whether the address's fragment changed since it was last read ([`fragment_changed`]).
    static FRAGMENT_CHANGED: core::cell::Cell<bool> = const { core::cell::Cell::new(true) };
}

/// Listens for the address's fragment to change (a link followed in place, or typed), so
/// that a frame reads the fragment only then: a link can be megabytes long, too long to copy
/// out of the browser every frame. Each change asks `ctx` for a frame.
pub(super) fn watch_fragment(ctx: &egui::Context) {
    let Some(window) = window() else {
        return;
    };
    let ctx = ctx.clone();
    let changed = wasm_bindgen::closure::Closure::<dyn FnMut()>::new(move || {
        FRAGMENT_CHANGED.set(true);
        ctx.request_repaint();
    });
    let listen = Reflect::get(&window, &JsValue::from_str("addEventListener"))
        .and_then(|f| f.dyn_into::<Function>());
    if let Ok(listen) = listen {
        listen
            .call2(&window, &JsValue::from_str("hashchange"), changed.as_ref())
            .ok();
    }
    // The listener lives as long as the page.
    changed.forget();
}

/// Whether the address's fragment may have changed since the last call (always, the first
/// time).
pub(super) fn fragment_changed() -> bool {
    FRAGMENT_CHANGED.replace(false)
}

/// The page's window.
fn window() -> Option<web_sys::Window> {
    web_sys::window()
}

/// The page's address without its fragment: where the web build is, for links.
pub(super) fn address() -> Option<String> {
    let href = window()?.location().href().ok()?;
    Some(href.split('#').next().unwrap_or_default().to_owned())
}

/// The address's fragment as the browser keeps it (still percent-encoded), without `#`.
pub(super) fn fragment() -> String {
    let hash = window().and_then(|w| w.location().hash().ok());
    hash.unwrap_or_default().trim_start_matches('#').to_owned()
}

/// The first of the browser's languages the explorer speaks.
pub(super) fn language() -> Option<Locale> {
    let navigator = window()?.navigator();
    let languages = navigator.languages();
    let listed = languages.iter().filter_map(|l| l.as_string());
    listed
        .chain(navigator.language())
        .find_map(|tag| Locale::from_tag(&tag))
}

/// Keeps `message` for the window to show (see [`take_refusals`]).
pub(super) fn refused(message: String) {
    REFUSED.with_borrow_mut(|all| all.push(message));
}

/// What the browser refused since the last call, in words.
pub(super) fn take_refusals() -> Vec<String> {
    REFUSED.with_borrow_mut(core::mem::take)
}

/// Calls the method `name` of `target` without arguments and, where it returns a promise that
/// is rejected, keeps `message` (with the browser's reason) and asks for a repaint.
fn call_and_watch(
    target: &JsValue,
    name: &str,
    ctx: &egui::Context,
    message: fn(String) -> String,
) {
    let called = Reflect::get(target, &JsValue::from_str(name))
        .and_then(|method| method.dyn_into::<Function>())
        .and_then(|method| method.call0(target));
    let reason = |e: &JsValue| {
        e.as_string()
            .or_else(|| {
                Reflect::get(e, &JsValue::from_str("message"))
                    .ok()?
                    .as_string()
            })
            .unwrap_or_default()
    };
    match called.map(|value| value.dyn_into::<Promise>()) {
        Ok(Ok(promise)) => {
            let ctx = ctx.clone();
            spawn_local(async move {
                if let Err(e) = JsFuture::from(promise).await {
                    refused(message(reason(&e)));
                    ctx.request_repaint();
                }
            });
        }
        Ok(Err(_)) => {}
        Err(e) => refused(message(reason(&e))),
    }
}

/// Enters or leaves the browser's full screen (presentation). A browser enters it only
/// shortly after a click or a key; when it refuses, the window says so.
pub(super) fn full_screen(on: bool, ctx: &egui::Context) {
    let Some(document) = window().and_then(|w| w.document()) else {
        return;
    };
    if on == document.fullscreen_element().is_some() {
        return;
    }
    if on {
        if let Some(element) = document.document_element() {
            call_and_watch(&element, "requestFullscreen", ctx, |reason| {
                t!("web-full-screen-refused", reason = reason)
            });
        }
    } else {
        call_and_watch(&document, "exitFullscreen", ctx, |reason| {
            t!("web-full-screen-refused", reason = reason)
        });
    }
}

/// Whether the page is in the browser's full screen now.
pub(super) fn is_full_screen() -> bool {
    let document = window().and_then(|w| w.document());
    document.is_some_and(|d| d.fullscreen_element().is_some())
}

/// Puts `text` on the clipboard; a page that may not (opened from a file, or not in front)
/// says so in the window.
pub(super) fn copy(text: &str, ctx: &egui::Context) {
    let Some(window) = window() else {
        return;
    };
    // No clipboard object (an insecure page has none) or something else under its name.
    let clipboard = Reflect::get(&window.navigator(), &JsValue::from_str("clipboard")).ok();
    let Some(clipboard) = clipboard.and_then(|c| c.dyn_into::<web_sys::Clipboard>().ok()) else {
        refused(t!("web-copy-refused", reason = t!("web-not-secure")));
        return;
    };
    let promise = clipboard.write_text(text);
    let ctx = ctx.clone();
    spawn_local(async move {
        if let Err(e) = JsFuture::from(promise).await {
            let reason = Reflect::get(&e, &JsValue::from_str("message"))
                .ok()
                .and_then(|m| m.as_string())
                .unwrap_or_default();
            refused(t!("web-copy-refused", reason = reason));
            ctx.request_repaint();
        }
    });
}

/// The id of the page's line that says what the window said in its strip (a link not
/// opened, a copy refused), for screen readers: a polite live region, out of sight.
const STATUS_ID: &str = "status";

/// Says `text` in the page's live region (made on first use), as the window's strip does.
pub(super) fn announce(text: &str) {
    let Some(document) = window().and_then(|w| w.document()) else {
        return;
    };
    let line = document.get_element_by_id(STATUS_ID).or_else(|| {
        let line = document.create_element("div").ok()?;
        line.set_id(STATUS_ID);
        line.set_attribute("role", "status").ok()?;
        line.set_attribute("aria-live", "polite").ok()?;
        // untranslated: CSS that hides the line from sight, not from screen readers.
        let hidden = "position: absolute; width: 1px; height: 1px; overflow: hidden; \
                      clip-path: inset(50%); white-space: nowrap;";
        line.set_attribute("style", hidden).ok()?;
        document.body()?.append_child(&line).ok()?;
        Some(line)
    });
    if let Some(line) = line {
        line.set_text_content(Some(text));
    }
}

/// Sets the page's title (the browser's tab) to `title`.
pub(super) fn set_title(title: &str) {
    if let Some(document) = window().and_then(|w| w.document()) {
        document.set_title(title);
    }
}

/// The name of the browser's performance entries that give the window's frame time.
const FRAME_MEASURE: &str = "explorer-frame";

/// Records the last frame's time (`seconds`, eframe's own measure: the UI pass, its
/// tessellation and the WebGL calls that paint it) as a performance entry that ends now, for
/// the browser's profiler and `tests/web/measure.mjs` (a `PerformanceObserver` sees it);
/// the page keeps none of them.
pub(super) fn report_frame(seconds: f32) {
    let Some(performance) = window().and_then(|w| w.performance()) else {
        return;
    };
    let duration = f64::from(seconds) * 1000.0;
    let options = js_sys::Object::new();
    let set = |key: &str, value: f64| {
        Reflect::set(&options, &JsValue::from_str(key), &JsValue::from_f64(value)).ok();
    };
    set("start", performance.now() - duration);
    set("duration", duration);
    let measure = Reflect::get(&performance, &JsValue::from_str("measure"))
        .and_then(|m| m.dyn_into::<Function>());
    if let Ok(measure) = measure {
        measure
            .call2(&performance, &JsValue::from_str(FRAME_MEASURE), &options)
            .ok();
        performance.clear_measures_with_measure_name(FRAME_MEASURE);
    }
}

/// Names the canvas for screen readers with what the diagram says (`summary`), as the desktop
/// window names its canvas: a page's canvas is a picture to the browser.
pub(super) fn describe(canvas: &web_sys::HtmlCanvasElement, summary: &str) {
    canvas.set_attribute("role", "img").ok();
    canvas.set_attribute("aria-label", summary).ok();
}

/// Says on the canvas which view the window shows (`data-view`: `student` or `teacher`), for
/// the page's style and its tests: a canvas's pictures are not the page's elements.
pub(super) fn show_view(canvas: &web_sys::HtmlCanvasElement, student: bool) {
    // untranslated: an attribute's value, read by the page and its tests, never shown.
    let view = if student { "student" } else { "teacher" };
    canvas.set_attribute("data-view", view).ok();
}

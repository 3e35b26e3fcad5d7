//! A panic in the page is never a frozen picture: the page shows what the program said over
//! it, with a link that reloads and the link of the last state, so that the work is not lost
//! (as egui's web demo shows eframe's panic summary in its page). The window keeps that link
//! in the page's root element each time it changes (the program cannot be asked once it has
//! panicked); the page's own script draws the overlay (`web_page`).

use js_sys::{Function, Reflect};
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::JsValue;

use super::Explorer;
use crate::web_page::{DEBUG_PANIC_FRAGMENT, LINK_ATTRIBUTE};

/// The page's function that shows the overlay (`web_page`'s script defines it).
const SHOW: &str = "refractionCrashed";

/// The attribute of the page's root element that a build with debug assertions sets, so that
/// its browser test knows it can panic the page on purpose.
const DEBUG_ASSERTIONS_ATTRIBUTE: &str = "data-debug-assertions";

/// Installs the panic hook that shows the overlay, after the hook the web runner installed
/// (which logs the panic and keeps its summary), which it calls first.
pub(super) fn install() {
    if cfg!(debug_assertions)
        && let Some(root) = root()
    {
        root.set_attribute(DEBUG_ASSERTIONS_ATTRIBUTE, "").ok();
    }
    let runner_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        runner_hook(info);
        show(&eframe::web::PanicSummary::new(info).message());
    }));
}

/// The page's root element (`<html>`).
fn root() -> Option<web_sys::Element> {
    web_sys::window()?.document()?.document_element()
}

/// Asks the page to show `message` over the explorer.
fn show(message: &str) {
    let Some(window) = web_sys::window() else {
        return;
    };
    let shown = Reflect::get(&window, &JsValue::from_str(SHOW))
        .and_then(|f| f.dyn_into::<Function>())
        .and_then(|f| f.call1(&window, &JsValue::from_str(message)));
    if let Err(e) = shown {
        web_sys::console::error_1(&e);
    }
}

/// The last state's link, as the overlay and the new tab's link give it.
#[derive(Default)]
pub(super) struct KeptLink(String);

impl KeptLink {
    /// Keeps the fragment of what `explorer` shows in the page's root element, when it
    /// changed since the last frame.
    pub(super) fn follow(&mut self, explorer: &Explorer) {
        let fragment = refraction_tools::link::fragment(&explorer.link());
        if fragment == self.0 {
            return;
        }
        if let Some(root) = root() {
            root.set_attribute(LINK_ATTRIBUTE, &fragment).ok();
        }
        self.0 = fragment;
    }
}

/// Panics on purpose when the address's fragment is [`DEBUG_PANIC_FRAGMENT`], in a build with
/// debug assertions (the browser test of the overlay); a release build ignores it.
pub(super) fn panic_if_asked(fragment: &str) {
    let asked = cfg!(debug_assertions) && fragment == DEBUG_PANIC_FRAGMENT;
    assert!(
        !asked,
        // untranslated: a panic's message, which the overlay quotes as the program said it.
        "panicked on purpose: the address asked for it ({DEBUG_PANIC_FRAGMENT})"
    );
}

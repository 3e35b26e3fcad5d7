//! The explorer in a browser: the WebAssembly module's entry point. `cargo xtask web` builds
//! this crate for `wasm32-unknown-unknown`, runs `wasm-bindgen --target web` on it and writes
//! the page that loads it (`target/web/`). The window itself, and everything a page does that
//! a desktop window does not (its address, file picker, downloads, full screen), is
//! `refraction_explorer::app::browser`; this crate only starts it.
//!
//! On a desktop this crate is empty, so that `cargo build --workspace` builds nothing for it.

#[cfg(target_arch = "wasm32")]
use wasm_bindgen::prelude::wasm_bindgen;

/// Starts the explorer on the page's canvas (`<canvas id="explorer">`), once the module is
/// loaded; a failure is written on the page.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen(start)]
pub fn start() {
    refraction_explorer::app::browser::start();
}

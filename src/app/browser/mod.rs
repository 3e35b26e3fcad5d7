//! The window in a browser page (`wasm32` only): eframe's web runner on the page's canvas,
//! and what a page does where a desktop window has a system. This is the browser side of the
//! web gate (see `ARCHITECTURE.md`, "The web build"): the rest of the window runs as on a
//! desktop, its work that would use a thread on the window's own ([`super::background`]).
//!
//! - the address's fragment opens a state or a deck's step when the page opens and whenever
//!   it changes ([`Explorer::open_link`]); the page's own address is where links point unless
//!   another is set;
//! - the browser's language is the system's, spoken until one is chosen;
//! - presentation is the browser's full screen;
//! - the file dialog is the browser's file picker (`super::file_dialog`) and a download
//!   ([`files`]), and files dropped on the page are read before the window sees them;
//! - a copy the browser refuses is said in the window;
//! - the canvas is named for screen readers with what the diagram says, and the page carries its
//!   own controls, the window in words and the page's language for them ([`access`]);
//! - the settings and the last state are kept in the browser's storage (eframe's);
//! - each frame's time is a performance entry (`explorer-frame`) for the browser's profiler.

mod access;
mod crash;
mod files;
mod page;

use core::time::Duration;

use refraction_i18n::t;
use refraction_tools::link;
use wasm_bindgen::JsCast as _;

use super::{Explorer, Launch};

/// How often the settings and the last state are written to the browser's storage: a page
/// can be closed at any moment, and the browser does not always say so.
const SAVE_EVERY: Duration = Duration::from_secs(5);

/// The explorer in a page: the window, and what it last did with the page.
struct Page {
    explorer: Explorer,
    canvas: web_sys::HtmlCanvasElement,
    /// The fragment last opened (as the address has it).
    fragment: String,
    /// Whether presentation was on last frame.
    presenting: bool,
    /// Whether the page was in full screen last frame.
    full_screen: bool,
    /// What the canvas is named, last set.
    described: String,
    /// The page's title, last set.
    title: String,
    /// Whether the student's view was shown, last said on the canvas.
    student: Option<bool>,
    /// The strip's message, last said in the page's live region.
    announced: Option<String>,
    /// The page's own controls and words for screen readers and keyboards.
    controls: Option<access::PageControls>,
    /// The last state's link, kept for the panic overlay.
    link: crash::KeptLink,
}

impl Page {
    /// Opens the page's fragment, if it changed since it was last opened; a link that cannot
    /// be opened is said in the window and changes nothing.
    fn follow_address(&mut self) {
        if !page::fragment_changed() {
            return;
        }
        let fragment = page::fragment();
        if fragment == self.fragment {
            return;
        }
        crash::panic_if_asked(&fragment);
        if let Err(why) = self.explorer.open_link(&fragment) {
            let said = t!("web-link-not-opened", reason = why.to_string());
            self.explorer.sharing.notice = Some(said);
        }
        self.fragment = fragment;
    }

    /// Presentation on or off becomes full screen on or off; leaving full screen with the
    /// browser's own key (Esc) ends presentation.
    fn follow_presentation(&mut self, ctx: &egui::Context) {
        let (on, full) = (self.explorer.presentation().on, page::is_full_screen());
        if self.full_screen && !full && on && self.presenting {
            self.explorer.presentation_mut().on = false;
        } else if on != self.presenting {
            page::full_screen(on, ctx);
        }
        self.presenting = self.explorer.presentation().on;
        self.full_screen = full;
    }

    /// Copies with the browser's clipboard what the window copied this frame, so that a
    /// refusal can be said; says what the browser refused.
    fn follow_clipboard(&mut self, ctx: &egui::Context) {
        let copied: Vec<String> = ctx.output_mut(|o| {
            let mut texts = Vec::new();
            o.commands.retain(|command| match command {
                egui::OutputCommand::CopyText(text) => {
                    texts.push(text.clone());
                    false
                }
                _ => true,
            });
            texts
        });
        for text in copied {
            page::copy(&text, ctx);
        }
        if let Some(refusal) = page::take_refusals().pop() {
            self.explorer.sharing.notice = Some(refusal);
        }
    }

    /// Names the canvas with what the diagram says, says on it which view is shown, titles
    /// the page with the deck's step shown, and says the strip's message in the page's live
    /// region, each when it changed.
    fn describe(&mut self, ctx: &egui::Context) {
        let student = self.explorer.shows_student_view(ctx);
        if self.student != Some(student) {
            page::show_view(&self.canvas, student);
            self.student = Some(student);
        }
        let hidden = self.explorer.lesson().hides_answer();
        let summary = refraction_diagram::diagram_summary(self.explorer.state(), hidden);
        if summary != self.described {
            page::describe(&self.canvas, &summary);
            self.described = summary;
        }
        let title = self.explorer.title();
        if title != self.title {
            page::set_title(&title);
            self.title = title;
        }
        if self.explorer.sharing.notice != self.announced {
            page::announce(self.explorer.sharing.notice.as_deref().unwrap_or_default());
            self.announced.clone_from(&self.explorer.sharing.notice);
        }
    }
}

impl eframe::App for Page {
    fn raw_input_hook(&mut self, ctx: &egui::Context, raw_input: &mut egui::RawInput) {
        files::take_dropped(ctx, raw_input);
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        if let Some(seconds) = frame.info().cpu_usage {
            page::report_frame(seconds);
        }
        self.follow_address();
        access::PageControls::take_set(&mut self.explorer);
        self.explorer.show(ui);
        self.link.follow(&self.explorer);
        self.follow_presentation(ui.ctx());
        self.follow_clipboard(ui.ctx());
        files::deliver_written();
        self.describe(ui.ctx());
        if let Some(controls) = &mut self.controls {
            controls.follow(ui.ctx(), &self.explorer);
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::App::save(&mut self.explorer, storage);
    }

    fn auto_save_interval(&self) -> Duration {
        SAVE_EVERY
    }
}

/// The explorer as the page opens it: the last state and settings from the browser's
/// storage, the browser's language, links at the page's own address unless another was set,
/// then what the address's fragment names.
fn launched(cc: &eframe::CreationContext<'_>, canvas: web_sys::HtmlCanvasElement) -> Page {
    super::install_fonts(&cc.egui_ctx);
    page::watch_fragment(&cc.egui_ctx);
    cc.egui_ctx.set_theme(egui::Theme::Light);
    let saved = |key: &str| cc.storage?.get_string(key);
    let launch = Launch {
        system_language: page::language(),
        ..Launch::default()
    };
    let mut explorer = Explorer::launched(launch, saved);
    // The page's own address, where it can start a link (a `file:` page's can, with a word
    // in the QR dialog that a phone cannot open it).
    if explorer.web_base().is_empty()
        && let Some(address) = page::address().and_then(|a| link::web_base(&a).ok())
    {
        explorer.set_web_base(&address);
    }
    let controls = access::PageControls::new(canvas.clone(), &cc.egui_ctx);
    let mut page = Page {
        explorer,
        canvas,
        fragment: String::new(),
        presenting: false,
        full_screen: false,
        described: String::new(),
        title: String::new(),
        student: None,
        announced: None,
        controls,
        link: crash::KeptLink::default(),
    };
    page.follow_address();
    page
}

/// The page's line that says the explorer is loading: removed once it runs, or saying why it
/// could not start.
fn loading_line(failure: Option<&str>) {
    let document = web_sys::window().and_then(|w| w.document());
    let Some(line) = document.and_then(|d| d.get_element_by_id(crate::web_page::LOADING_ID)) else {
        return;
    };
    match failure {
        None => line.remove(),
        Some(reason) => {
            line.set_text_content(Some(&refraction_i18n::t!(
                "web-page-failed",
                reason = reason
            )));
            line.set_class_name("failed");
        }
    }
}

/// Starts the explorer on the page's canvas ([`crate::web_page::CANVAS_ID`]); what goes wrong
/// is said on the page and in the browser's console.
pub fn start() {
    let canvas = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id(crate::web_page::CANVAS_ID))
        .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok());
    let Some(canvas) = canvas else {
        loading_line(Some(crate::web_page::CANVAS_ID));
        return;
    };
    let runner = eframe::WebRunner::new();
    crash::install();
    wasm_bindgen_futures::spawn_local(async move {
        let page_canvas = canvas.clone();
        let started = runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(|cc| Ok(Box::new(launched(cc, page_canvas)))),
            )
            .await;
        match started {
            Ok(()) => loading_line(None),
            Err(e) => {
                let reason = e.as_string().unwrap_or_else(|| format!("{e:?}"));
                loading_line(Some(&reason));
                web_sys::console::error_1(&e);
            }
        }
    });
}

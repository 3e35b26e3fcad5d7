//! The link of what the class sees, for the web build (`cargo xtask web`): *Copy link* and
//! *QR code* in the *Save, open, share* tool (`super::files_panel`), the QR code shown large over the
//! diagram (Q shows or hides it), the web build's address (a setting kept between runs, or
//! `--web-base`; in a browser the page's own address unless one is set), and opening a link
//! ([`Explorer::open_link`]), which a browser page does with its address's fragment.
//!
//! A link names the deck's step while the step is shown as the deck has it, and the state
//! otherwise (see [`refraction_tools::link`]); a link that cannot be opened is said in a strip
//! above the window and changes nothing.

use std::path::Path;

use egui::{Id, Key, Modal, Panel, RichText, TextEdit, Ui};
use refraction_deck::builtin;
use refraction_diagram::QrCode;
use refraction_i18n::t;
use refraction_render::{ImageFormat, RenderError};
use refraction_tools::link::{self, Link, LinkError};

use super::deck::{DeckCommand, handout};
use super::status::{self, Look, Status};
use super::{Explorer, View, export, file_dialog};

/// Where eframe keeps the web build's address between runs.
pub(super) const WEB_BASE_KEY: &str = "explorer_web_base";

/// The size of the QR code's picture when saved, in pixels.
const QR_PICTURE_SIDE: u32 = 800;

/// The window's sharing state: the QR code shown, and what a link that could not be opened
/// (or a copy the browser refused) said.
#[derive(Debug, Default)]
pub(super) struct Sharing {
    /// Whether the QR code is shown over the diagram.
    pub qr_open: bool,
    /// A message for the strip above the window, until it is closed.
    pub notice: Option<String>,
    /// What the QR code's *Save* buttons said.
    saved: Option<Status>,
    /// The web address being typed in the QR code's dialog, kept apart from the one set until
    /// Enter or *Show the QR code*: set at each key, the first letter made a link and the
    /// dialog swapped its field for that letter's QR code, losing the rest of the typing.
    draft: String,
    /// The dialog has just opened: its address field takes the keyboard.
    focus_draft: bool,
}

/// The QR code dialog's address field (focused when the dialog opens, `focus`, so that the
/// teacher types at once) and its button: the address typed into `draft`, returned once
/// Enter or the button gives it.
fn address_field(ui: &mut Ui, draft: &mut String, focus: &mut bool) -> Option<String> {
    ui.horizontal_wrapped(|ui| {
        let name = ui.label(t!("link-web-base"));
        let field = ui
            .add(
                TextEdit::singleline(draft)
                    .hint_text("https://…")
                    .desired_width(300.0),
            )
            .labelled_by(name.id)
            .on_hover_text(t!("link-web-base-hover"));
        if core::mem::take(focus) {
            field.request_focus();
        }
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(Key::Enter));
        let shown = ui
            .add_enabled(
                base_of(draft).is_some(),
                egui::Button::new(t!("link-qr-show")),
            )
            .clicked();
        ((entered || shown) && base_of(draft).is_some()).then(|| core::mem::take(draft))
    })
    .inner
}

/// The least width of the QR code's dialog, in points: the address field and its button.
const QR_DIALOG_WIDTH: f32 = 360.0;

/// The QR code's side in its dialog, in points: half the window's shorter side at the desk,
/// three quarters on a projector, and never so large that the dialog (the code in its quiet
/// zone, the link `url` under it, the buttons and the margins) runs out of the window: it ran
/// off the top of a 1280×720 projector.
fn qr_side(ui: &Ui, url: &str, presenting: bool) -> f32 {
    let screen = ui.ctx().content_rect();
    let share = if presenting { 0.72 } else { 0.5 };
    let wanted = screen.width().min(screen.height()) * share;
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let wrap = wanted.max(QR_DIALOG_WIDTH);
    let link = ui
        .painter()
        .layout(url.to_owned(), font, egui::Color32::PLACEHOLDER, wrap)
        .size()
        .y;
    let spacing = ui.spacing();
    // The rows under the link (a file's warning, the buttons, what they said), the spaces
    // between the rows and the dialog's frame.
    let rows = 3.0 * spacing.interact_size.y + 5.0 * spacing.item_spacing.y;
    let frame = 2.0 * (spacing.window_margin.topf() + spacing.window_margin.bottomf()) + 8.0;
    wanted.min(screen.height() - link - rows - frame).max(120.0)
}

/// The web build's address `base` as a link's start ([`link::web_base`]), or `None` when it
/// is empty or cannot start a link (the row says why).
fn base_of(base: &str) -> Option<String> {
    link::web_base(base).ok()
}

/// The most characters of a strip's message shown: a refusal quotes a link, which can be
/// megabytes long.
const NOTICE_CHARS: usize = 400;

/// Why a link has no QR code, in words.
fn too_long(error: &refraction_diagram::QrTooLong) -> String {
    t!("link-qr-too-long", bytes = error.0.to_string())
}

/// What the strip says when what the last run kept cannot be used: the state that could not
/// be read (the reader's reason), the web address refused; `None` when both were fine.
pub(super) fn storage_notice(
    unreadable_state: Option<&str>,
    refused_base: Option<link::WebBaseError>,
) -> Option<String> {
    let state = unreadable_state.map(|reason| {
        t!(
            "storage-state-unreadable",
            reason = link::echo(reason, link::ECHO_CHARS * 3)
        )
    });
    let base = refused_base.map(|e| t!("storage-web-base-unusable", reason = e.reason()));
    let said: Vec<String> = state.into_iter().chain(base).collect();
    (!said.is_empty()).then(|| said.join(" "))
}

/// Writes the QR code of `url` as a picture of `format` under the next free
/// `refraction-qr-NNN` name; what happened, in words.
fn save_qr(url: &str, format: ImageFormat) -> Status {
    let extension = format.extension();
    let path = file_dialog::numbered(Path::new(""), "refraction-qr", extension);
    let code = match QrCode::new(url) {
        Ok(code) => code,
        Err(e) => return Status::Refused(too_long(&e)),
    };
    let side = QR_PICTURE_SIDE;
    let draw = |size: glam::Vec2, _: &_| code.primitives(glam::Vec2::ZERO, size.x);
    let written = refraction_render::still(
        refraction_render::Picture::Drawn(&draw),
        (format, refraction_render::svg::Labels::default()),
        (side, side),
        &path,
    )
    .and_then(|bytes| {
        refraction_files::write_atomically(&path, &bytes).map_err(RenderError::Write)
    });
    export::outcome(written, &path)
}

/// Why a link was not opened: the link itself, or the lesson or step it names. Worded when
/// shown, in the window's language.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LinkRefusal {
    /// The link is cut short, damaged or from a newer version.
    #[error("{}", .0.message())]
    Link(#[from] LinkError),
    /// No built-in lesson has this name.
    #[error(
        "{}",
        t!(
            "link-no-lesson",
            name = link::echo(name, link::ECHO_CHARS),
            names = builtin::names().join(", ")
        )
    )]
    NoLesson {
        /// The name in the link.
        name: String,
    },
    /// The lesson has fewer steps.
    #[error(
        "{}",
        t!(
            "link-no-step",
            name = link::echo(name, link::ECHO_CHARS),
            step = step.to_string(),
            count = count.to_string()
        )
    )]
    NoStep {
        /// The lesson's name.
        name: String,
        /// The step in the link, from 1.
        step: usize,
        /// How many steps the lesson has.
        count: usize,
    },
}

impl Explorer {
    /// What the class sees now as a link: the deck's step while it is shown as the deck has
    /// it (a built-in deck by name, a deck file's step by its state), else the state.
    #[must_use]
    pub fn link(&self) -> Link {
        let step = self.lesson.current().filter(|(_, step)| {
            self.view == View::Interface && step.state == self.state
                || self.view == View::Scenes && step.view == refraction_deck::StepView::Scenes
        });
        step.and_then(|(index, _)| handout::step_link(self.lesson.deck.as_ref()?, index))
            .unwrap_or_else(|| Link::State(Box::new(self.state.clone())))
    }

    /// The link of what the class sees at the web build's address, if one is set.
    #[must_use]
    pub fn link_url(&self) -> Option<String> {
        base_of(&self.tools.files.share.base).map(|base| link::url(&base, &self.link()))
    }

    /// The link of what the class sees for the students' own devices (the QR code's): the
    /// link that also asks for the student's view, at the web build's address, if one is set.
    #[must_use]
    pub fn student_link_url(&self) -> Option<String> {
        base_of(&self.tools.files.share.base).map(|base| link::student_url(&base, &self.link()))
    }

    /// The web build's address (empty: none).
    #[must_use]
    pub fn web_base(&self) -> &str {
        &self.tools.files.share.base
    }

    /// Sets the web build's address that links are given at.
    pub fn set_web_base(&mut self, base: &str) {
        base.trim().clone_into(&mut self.tools.files.share.base);
    }

    /// Opens what the link's fragment `fragment` (with or without `#`) names: a state, shown
    /// in One interface, or a built-in deck at a step. An empty fragment changes nothing.
    ///
    /// # Errors
    /// A fragment cut short, damaged or from a newer version, an unknown deck or a step past
    /// its end (worded, when shown, in the current language); nothing is changed.
    pub fn open_link(&mut self, fragment: &str) -> Result<(), LinkRefusal> {
        let parsed = link::parse(fragment)?;
        if parsed.is_some() {
            self.student.asked = link::asks_student_view(fragment);
        }
        match parsed {
            None => {}
            Some(Link::State(state)) => {
                self.state = *state;
                self.view = View::Interface;
            }
            Some(Link::Lesson { name, step }) => {
                let Some(deck) = builtin::deck(&name) else {
                    return Err(LinkRefusal::NoLesson { name });
                };
                let count = deck.steps.len();
                if step > count {
                    return Err(LinkRefusal::NoStep { name, step, count });
                }
                self.open_deck(deck);
                self.deck_command(DeckCommand::GoTo(step - 1));
            }
        }
        Ok(())
    }

    /// The sharing parts of the frame: the link handed to the tool, Q, the QR code over the
    /// diagram and the strip that says why a link was not opened.
    pub(super) fn sharing(&mut self, ui: &mut Ui) {
        // Only the tool shows it (a deck's step is matched against the built-in decks).
        let shown = self.tools.open == Some(super::tools::Tool::Files);
        self.tools.files.share.url = shown.then(|| self.link_url()).flatten();
        let was_open = self.sharing.qr_open;
        if core::mem::take(&mut self.tools.files.share.qr_asked) {
            self.sharing.qr_open = true;
        }
        let typing = ui.ctx().text_edit_focused();
        if !typing && ui.input_mut(|i| i.consume_key(egui::Modifiers::NONE, Key::Q)) {
            self.sharing.qr_open = !self.sharing.qr_open;
        }
        self.sharing.focus_draft |= self.sharing.qr_open && !was_open;
        if let Some(notice) = self.sharing.notice.clone() {
            // Esc closes the strip, unless a dialog over the window takes it first.
            let escape = !self.sharing.qr_open
                && !typing
                && ui.input_mut(|i| i.consume_key(egui::Modifiers::NONE, Key::Escape));
            let shown = link::echo(&notice, NOTICE_CHARS);
            Panel::top("link-notice").show(ui, |ui| {
                ui.horizontal_wrapped(|ui| {
                    ui.label(RichText::new(format!("⚠ {shown}")).strong());
                    if ui.button(t!("link-notice-close")).clicked() || escape {
                        self.sharing.notice = None;
                    }
                });
            });
        }
        if self.sharing.qr_open {
            self.qr_modal(ui);
        }
    }

    /// The QR code of what the class sees, large and centred over the window, with the link
    /// under it; without an address, the field to type one. The code opens the student's
    /// view: it is for the students' phones.
    fn qr_modal(&mut self, ui: &Ui) {
        let url = self.student_link_url();
        let side = qr_side(ui, url.as_deref().unwrap_or_default(), self.presentation.on);
        let modal = Modal::new(Id::unique("qr-code")).show(ui.ctx(), |ui| {
            ui.set_max_width(side.max(QR_DIALOG_WIDTH));
            let Some(url) = url else {
                ui.heading(t!("link-qr"));
                ui.label(t!("link-no-web-base"));
                let sharing = &mut self.sharing;
                if let Some(base) = address_field(ui, &mut sharing.draft, &mut sharing.focus_draft)
                {
                    self.set_web_base(&base);
                }
                return;
            };
            match QrCode::new(&url) {
                Ok(code) => {
                    let size = glam::Vec2::splat(side);
                    let (_, painter, to_screen) =
                        super::paint::figure(ui, size, egui::Sense::hover(), &url);
                    super::paint::paint(
                        &painter,
                        &to_screen,
                        &code.primitives(glam::Vec2::ZERO, side),
                    );
                }
                Err(e) => {
                    ui.label(too_long(&e));
                }
            }
            ui.add(egui::Label::new(RichText::new(&url).monospace()).selectable(true));
            if url.starts_with("file:") {
                ui.label(RichText::new(t!("link-file-address")).strong());
            }
            ui.horizontal(|ui| {
                for format in [ImageFormat::Png, ImageFormat::Svg] {
                    let label = t!("link-qr-save", format = format.extension());
                    if ui.button(label).clicked() {
                        self.sharing.saved = Some(save_qr(&url, format));
                    }
                }
                ui.label(RichText::new(t!("link-qr-close")).weak());
            });
            status::show(ui, self.sharing.saved.as_ref(), Look::Plain);
        });
        if modal.should_close() {
            self.sharing.qr_open = false;
        }
    }
}

//! The page's own controls for a screen reader and a keyboard: eframe's web runner gives the
//! page no accessibility tree of the window's widgets (the canvas is one picture to the
//! browser), so the page carries four real HTML controls beside the canvas (θi and N's
//! direction as range inputs, the two indices as number inputs), labelled with the names the
//! desktop's sliders have and valued in the same words ([`describe::control_value`]), bound
//! both ways to the explorer's state through [`steps::set`]; a paragraph with the window in
//! words ([`announce::page_words`]) that describes the canvas; the page's language and the
//! label of eframe's hidden text field; and the way out of the canvas for the keyboard.
//!
//! The controls sit in the page's container ([`crate::web_page::CONTROLS_ID`]) before the
//! canvas: out of sight until one of them has the keyboard, then a bar over the foot of the
//! page with a visible focus (the page's CSS). eframe keeps Tab inside the canvas (it moves
//! between the window's widgets); Tab past the window's last widget comes to these controls,
//! and so does Shift+Tab while no widget of the window is selected (Esc lets go of one), so the
//! keyboard is never trapped.

use core::cell::{Cell, RefCell};

use egui::Key;
use refraction_i18n::{Locale, t};
use refraction_model::HandleId;
use refraction_model::describe;
use wasm_bindgen::JsCast as _;
use wasm_bindgen::prelude::Closure;
use web_sys::{Document, Element, HtmlCanvasElement, HtmlElement, HtmlInputElement};

use super::super::deck::DeckCommand;
use super::super::{Explorer, announce, steps};
use super::page;
use crate::web_page::CONTROLS_ID;

/// The id of the paragraph with the window in words, which describes the canvas.
const WORDS_ID: &str = "diagram-words";

thread_local! {
    /// Values set in the page's controls since the last frame, in order.
    static SET: RefCell<Vec<(HandleId, f64)>> = const { RefCell::new(Vec::new()) };
    /// What the page's deck buttons asked since the last frame, in order.
    static ASKED: RefCell<Vec<DeckCommand>> = const { RefCell::new(Vec::new()) };
    /// Whether a widget of the window had the keyboard at the end of the last frame (the
    /// page's Shift+Tab listener asks).
    static WINDOW_FOCUS: Cell<bool> = const { Cell::new(false) };
}

/// One of the four controls: its input, its label, the value shown beside it, and the words
/// last written into it.
struct Control {
    handle: HandleId,
    input: HtmlInputElement,
    label: Element,
    shown: Element,
    written: String,
}

/// The page's controls and words, and what was last written into them.
pub(super) struct PageControls {
    document: Document,
    canvas: HtmlCanvasElement,
    container: Element,
    controls: Vec<Control>,
    keys: Element,
    words: Element,
    /// The deck's buttons (shown while a deck's step is): previous, next, reveal.
    deck: DeckButtons,
    /// The language the labels are in.
    locale: Option<Locale>,
    /// The window in words, as last written.
    said: String,
    /// How many of the live status's sentences were said in the page's live region.
    announced: u64,
    /// The name of eframe's text field, in the page's language.
    typing: String,
}

/// The input's id for `handle`.
fn input_id(handle: HandleId) -> &'static str {
    match handle {
        HandleId::W => "control-incidence",
        HandleId::N => "control-normal",
        HandleId::MuI => "control-index-i",
        HandleId::MuT => "control-index-t",
    }
}

/// A new element `tag` with `id` (when not empty) inside `parent`.
fn child(document: &Document, parent: &Element, tag: &str, id: &str) -> Option<Element> {
    let element = document.create_element(tag).ok()?;
    if !id.is_empty() {
        element.set_id(id);
    }
    parent.append_child(&element).ok()?;
    Some(element)
}

/// Keeps a value set in `input` for the next frame and asks for it.
fn listen(input: &HtmlInputElement, handle: HandleId, ctx: &egui::Context) {
    let (read, ctx) = (input.clone(), ctx.clone());
    let changed = Closure::<dyn FnMut(web_sys::Event)>::new(move |_: web_sys::Event| {
        let value = read.value_as_number();
        if value.is_finite() {
            SET.with_borrow_mut(|set| set.push((handle, value)));
            ctx.request_repaint();
        }
    });
    for event in ["input", "change"] {
        input
            .add_event_listener_with_callback(event, changed.as_ref().unchecked_ref())
            .ok();
    }
    // The page keeps its controls as long as it lives.
    changed.forget();
}

/// One control in `parent`: a label, its input (a range for the angles, a number for the
/// indices, with each one's step) and its value in words beside it.
fn control(
    document: &Document,
    parent: &Element,
    handle: HandleId,
    ctx: &egui::Context,
) -> Option<Control> {
    let row = child(document, parent, "div", "")?;
    let label = child(document, &row, "label", "")?;
    label.set_attribute("for", input_id(handle)).ok()?;
    let input: HtmlInputElement = child(document, &row, "input", input_id(handle))?
        .dyn_into()
        .ok()?;
    let angle = matches!(handle, HandleId::W | HandleId::N);
    input.set_type(if angle { "range" } else { "number" });
    // untranslated: HTML attribute values (numbers with a point, as HTML writes them).
    input.set_step(&steps::step(handle).to_string());
    // Its value in words describes it too: a browser may leave out the words of a native
    // range input's value and say the number alone.
    let shown_id = format!("{}-value", input_id(handle));
    let shown = child(document, &row, "span", &shown_id)?;
    input.set_attribute("aria-describedby", &shown_id).ok()?;
    listen(&input, handle, ctx);
    Some(Control {
        handle,
        input,
        label,
        shown,
        written: String::new(),
    })
}

impl PageControls {
    /// Builds the controls in the page's container, bound to the window of `ctx`; `None` if
    /// the page has no container (a page of an older build).
    pub(super) fn new(canvas: HtmlCanvasElement, ctx: &egui::Context) -> Option<Self> {
        let document = web_sys::window()?.document()?;
        let container = document.get_element_by_id(CONTROLS_ID)?;
        let keys = child(&document, &container, "p", "")?;
        let controls = HandleId::ALL
            .into_iter()
            .map(|handle| control(&document, &container, handle, ctx))
            .collect::<Option<Vec<_>>>()?;
        let deck = DeckButtons::new(&document, &container, ctx)?;
        let words = child(&document, &container, "p", WORDS_ID)?;
        canvas.set_attribute("aria-describedby", WORDS_ID).ok()?;
        leave_backwards(&canvas);
        Some(Self {
            document,
            canvas,
            container,
            controls,
            keys,
            words,
            deck,
            locale: None,
            said: String::new(),
            announced: 0,
            typing: String::new(),
        })
    }

    /// Applies the values set in the page's controls and what its deck buttons asked since the
    /// last frame to the explorer, as its own controls would.
    pub(super) fn take_set(explorer: &mut Explorer) {
        for command in ASKED.with_borrow_mut(core::mem::take) {
            explorer.deck_command(command);
        }
        let set = SET.with_borrow_mut(core::mem::take);
        if set.is_empty() {
            return;
        }
        let mut state = explorer.state().clone();
        for (handle, value) in set {
            steps::set(&mut state, handle, value);
        }
        explorer.set_state(state);
    }

    /// Brings the page up to date after the window's frame: the language and labels, the
    /// controls' values, the window in words, what the live status said, eframe's text
    /// field, and the keyboard's way out past the window's last widget.
    pub(super) fn follow(&mut self, ctx: &egui::Context, explorer: &Explorer) {
        let locale = refraction_i18n::locale();
        if self.locale != Some(locale) {
            self.relabel(locale);
        }
        let active = self.document.active_element();
        for control in &mut self.controls {
            write_value(control, explorer, active.as_ref());
        }
        let said = announce::page_words(explorer).join(" ");
        if said != self.said {
            self.words.set_text_content(Some(&said));
            self.said = said;
        }
        if let Some((count, sentence)) = announce::last(ctx)
            && count != self.announced
        {
            page::announce(&sentence);
            self.announced = count;
        }
        self.deck.follow(explorer);
        self.text_field(active.as_ref());
        self.keyboard_way_out(ctx, active.as_ref());
    }

    /// Writes every word of the page's own in `locale`: the page's language, the container's
    /// name and keys, the controls' labels, eframe's text field's name.
    fn relabel(&mut self, locale: Locale) {
        if let Some(root) = self.document.document_element() {
            root.set_attribute("lang", locale.code()).ok();
        }
        self.container
            .set_attribute("aria-label", &t!("access-page-controls"))
            .ok();
        self.keys.set_text_content(Some(&t!("access-page-keys")));
        self.typing = t!("access-page-typing");
        for control in &mut self.controls {
            control
                .label
                .set_text_content(Some(&control.handle.label()));
            // The words change with the language.
            control.written.clear();
        }
        self.locale = Some(locale);
    }

    /// eframe's hidden text field, which takes the keys while a field of the window is edited:
    /// named, out of the tab order, and out of the accessibility tree while it is not typed
    /// into.
    fn text_field(&self, active: Option<&Element>) {
        let Some(parent) = self.canvas.parent_element() else {
            return;
        };
        let fields = core::iter::successors(parent.first_element_child(), |field| {
            field.next_element_sibling()
        });
        for field in fields {
            if !field.tag_name().eq_ignore_ascii_case("input") {
                continue;
            }
            let typing = active == Some(&field);
            if field.get_attribute("aria-label").as_deref() != Some(self.typing.as_str()) {
                field.set_attribute("aria-label", &self.typing).ok();
                field.set_attribute("tabindex", "-1").ok();
            }
            if typing == field.has_attribute("aria-hidden") {
                if typing {
                    field.remove_attribute("aria-hidden").ok();
                } else {
                    field.set_attribute("aria-hidden", "true").ok();
                }
            }
        }
    }

    /// While the page's controls show (a control in them has the keyboard), the canvas ends
    /// above them rather than under them: the whole diagram stays in sight while they move it.
    fn make_room(&self, shown: bool) {
        let Some(bar) = self.container.dyn_ref::<HtmlElement>() else {
            return;
        };
        let canvas: &HtmlElement = self.canvas.as_ref();
        let style = canvas.style();
        let height = if shown {
            // untranslated: a CSS length.
            format!("calc(100% - {}px)", bar.offset_height())
        } else {
            String::new()
        };
        if style.get_property_value("height").ok().as_deref() != Some(height.as_str()) {
            if height.is_empty() {
                style.remove_property("height").ok();
            } else {
                style.set_property("height", &height).ok();
            }
        }
    }

    /// Tab past the window's last widget (egui lets go of it and gives the next Tab to its
    /// first): the keyboard comes to the page's first control instead of going round inside
    /// the canvas. While the keyboard is in the page's controls the window lets go of its
    /// widget, so that Tab into the canvas starts at W and Shift+Tab there comes back.
    fn keyboard_way_out(&self, ctx: &egui::Context, active: Option<&Element>) {
        let inside = format!("#{CONTROLS_ID}");
        let in_controls = active.is_some_and(|a| a.closest(&inside).ok().flatten().is_some());
        if in_controls && let Some(id) = ctx.memory(|m| m.focused()) {
            ctx.memory_mut(|m| m.surrender_focus(id));
        }
        self.make_room(in_controls);
        let had = WINDOW_FOCUS.get();
        let has = ctx.memory(|m| m.focused().is_some());
        let forward = ctx.input(|i| i.key_pressed(Key::Tab) && !i.modifiers.shift);
        if had
            && !has
            && forward
            && let Some(first) = self.controls.first()
        {
            first.input.focus().ok();
        }
        WINDOW_FOCUS.set(has);
    }
}

/// Writes the control's value into its input (and in words beside it) when the state's
/// changed, but not into an index's field while it is typed into.
fn write_value(control: &mut Control, explorer: &Explorer, active: Option<&Element>) {
    let state = explorer.state();
    let words = describe::control_value(state, control.handle);
    if words == control.written {
        return;
    }
    let typing = active == Some(control.input.as_ref()) && control.input.type_() == "number";
    if typing {
        return;
    }
    let bounds = steps::bounds(state, control.handle);
    let value = steps::value(state, control.handle);
    // untranslated: HTML attribute values (numbers with a point, as HTML writes them).
    control.input.set_min(&format!("{}", bounds.start()));
    control.input.set_max(&format!("{}", bounds.end()));
    control
        .input
        .set_value(&((value * 1e6).round() / 1e6).to_string());
    control.input.set_attribute("aria-valuetext", &words).ok();
    control.shown.set_text_content(Some(&words));
    control.written = words;
}

/// Shift+Tab on the canvas while no widget of the window has the keyboard leaves the canvas
/// for the page's controls before it: eframe would keep it (it takes every Tab), so the key is
/// stopped on its way to the canvas and the browser moves the focus as on any page.
fn leave_backwards(canvas: &HtmlCanvasElement) {
    let Some(window) = web_sys::window() else {
        return;
    };
    let canvas: HtmlElement = canvas.clone().into();
    let listener =
        Closure::<dyn FnMut(web_sys::KeyboardEvent)>::new(move |event: web_sys::KeyboardEvent| {
            let on_canvas = event
                .target()
                .and_then(|t| t.dyn_into::<HtmlElement>().ok())
                .is_some_and(|target| target == canvas);
            // untranslated: the key's name in the browser's events.
            let tab = event.key() == "Tab";
            if tab && event.shift_key() && on_canvas && !WINDOW_FOCUS.get() {
                event.stop_propagation();
            }
        });
    // In the capture phase, before the canvas's own listener sees the key.
    window
        .add_event_listener_with_callback_and_bool(
            "keydown",
            listener.as_ref().unchecked_ref(),
            true,
        )
        .ok();
    listener.forget();
}

/// The deck's buttons in the page: the previous and next step, and reveal (or hide again) the
/// step's answer, as the window's strip has them; shown only while a deck's step is.
struct DeckButtons {
    group: Element,
    previous: Element,
    next: Element,
    reveal: Element,
    /// What they show: the step's position and whether its answer is hidden (and asked).
    shown: Option<(usize, usize, Option<bool>)>,
}

/// A button in `parent` that asks `command` of the deck.
fn deck_button(
    document: &Document,
    parent: &Element,
    command: DeckCommand,
    ctx: &egui::Context,
) -> Option<Element> {
    let button = child(document, parent, "button", "")?;
    button.set_attribute("type", "button").ok()?;
    let ctx = ctx.clone();
    let pressed = Closure::<dyn FnMut(web_sys::Event)>::new(move |_: web_sys::Event| {
        ASKED.with_borrow_mut(|asked| asked.push(command));
        ctx.request_repaint();
    });
    button
        .add_event_listener_with_callback("click", pressed.as_ref().unchecked_ref())
        .ok()?;
    // The page keeps its buttons as long as it lives.
    pressed.forget();
    Some(button)
}

impl DeckButtons {
    fn new(document: &Document, parent: &Element, ctx: &egui::Context) -> Option<Self> {
        let group = child(document, parent, "div", "")?;
        group.set_attribute("hidden", "").ok()?;
        Some(Self {
            previous: deck_button(document, &group, DeckCommand::Previous, ctx)?,
            next: deck_button(document, &group, DeckCommand::Next, ctx)?,
            reveal: deck_button(document, &group, DeckCommand::Reveal, ctx)?,
            group,
            shown: None,
        })
    }

    /// Shows the buttons for the deck's step shown (none without one), in the page's language.
    fn follow(&mut self, explorer: &Explorer) {
        let lesson = explorer.lesson();
        let shown = lesson
            .current()
            .zip(lesson.deck.as_ref())
            .map(|((index, step), deck)| {
                let asked = step.hides_answer().then(|| lesson.hides_answer());
                (index, deck.steps.len(), asked)
            });
        if shown == self.shown {
            return;
        }
        self.shown = shown;
        let Some((index, count, asked)) = shown else {
            self.group.set_attribute("hidden", "").ok();
            return;
        };
        self.group.remove_attribute("hidden").ok();
        self.previous.set_text_content(Some(&t!("deck-previous")));
        self.next.set_text_content(Some(&t!("deck-next")));
        enable(&self.previous, index > 0);
        enable(&self.next, index + 1 < count);
        match asked {
            Some(hidden) => {
                self.reveal.remove_attribute("hidden").ok();
                let words = if hidden {
                    t!("deck-reveal")
                } else {
                    t!("deck-hide")
                };
                self.reveal.set_text_content(Some(&words));
            }
            None => {
                self.reveal.set_attribute("hidden", "").ok();
            }
        }
    }
}

/// Enables `button`, or disables it.
fn enable(button: &Element, enabled: bool) {
    if enabled {
        button.remove_attribute("disabled").ok();
    } else {
        button.set_attribute("disabled", "").ok();
    }
}

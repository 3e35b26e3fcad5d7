//! A lesson deck in the window: the deck being built or shown ([`LessonDeck`]), the step shown and
//! whether its answer is revealed, the keys a presenter's clicker sends, the strip above the
//! diagram with the step's number, title and question, the notes window, and the *Lesson deck*
//! tool that builds the deck ([`panel`]).
//!
//! The deck holds its own copies of the steps: dragging W or N during a step changes the
//! diagram only, and the deck changes when the teacher keeps the state in the step (or adds a
//! step) and is written when they save it.
//!
//! # Keys
//!
//! A deck's keys are read before anything else in the frame, and in this order:
//!
//! 1. While a text field has the keyboard, no key steps: the keys type.
//! 2. Page Down and Page Up always move a step (what clickers send).
//! 3. → and ↓ (next), ← and ↑ (previous) move a step only while no widget has the keyboard
//!    focus: with a handle on the canvas selected they turn W or N, as without a deck (Esc gives
//!    the focus up).
//! 4. Space moves to the next step while no widget has the focus (a focused button takes it
//!    as a click).
//! 5. R reveals the answer, or hides it again (B and `.`, which a clicker's blank-screen button
//!    sends, do too); N opens or closes the notes window.

pub mod handout;
mod notes;
pub(super) mod panel;

use egui::{Key, Modifiers, Panel, RichText, Ui};
use refraction_deck::{Deck, Effect, Step, StepTool, StepView};
use refraction_diagram::{Overlay, WaveOptions};
use refraction_i18n::t;
use refraction_scene::Scene;

pub(super) use notes::Notes;

use super::status::Status;
use super::tools::Tool;
use super::{Explorer, View};

/// What a key or a button asks of the deck.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeckCommand {
    /// Show the next step.
    Next,
    /// Show the previous step.
    Previous,
    /// Show the step at this position.
    GoTo(usize),
    /// Reveal the answer, or hide it again.
    Reveal,
    /// Open or close the notes window.
    Notes,
}

/// The deck shown in the window and where it is.
#[derive(Clone, Debug, Default)]
pub struct LessonDeck {
    /// The deck, as opened and edited (never by a drag).
    pub deck: Option<Deck>,
    /// The step shown, if any.
    current: Option<usize>,
    /// Whether the shown step's answer is revealed.
    revealed: bool,
    /// Whether the notes window is open.
    pub notes_open: bool,
    /// The tool's fields and files.
    pub panel: panel::DeckPanel,
}

impl LessonDeck {
    /// The step shown, with its position.
    #[must_use]
    pub fn current(&self) -> Option<(usize, &Step)> {
        let index = self.current?;
        Some((index, self.deck.as_ref()?.steps.get(index)?))
    }

    /// Whether the answer of the step shown is hidden: it asks a question not yet revealed.
    #[must_use]
    pub fn hides_answer(&self) -> bool {
        !self.revealed && self.current().is_some_and(|(_, s)| s.hides_answer())
    }

    /// How many steps the deck has.
    fn count(&self) -> usize {
        self.deck.as_ref().map_or(0, |d| d.steps.len())
    }

    /// What the notes window shows for the step shown, as data (the window itself may be a
    /// second native window, which a headless test cannot see).
    #[must_use]
    pub fn notes(&self) -> Option<Notes> {
        let deck = self.deck.as_ref()?;
        let (index, step) = self.current()?;
        Some(Notes {
            number: index + 1,
            count: deck.steps.len(),
            deck: deck.title.clone(),
            title: title_of(step, index),
            question: step.question.clone(),
            notes: step.notes.clone(),
            next: deck.steps.get(index + 1).map(|s| title_of(s, index + 1)),
        })
    }

    /// The keys pressed this frame that ask something of the deck (see the module's
    /// [precedence](self#keys)), taken out of the input so that nothing else acts on them.
    pub(super) fn keys(ui: &Ui) -> Vec<DeckCommand> {
        if ui.ctx().text_edit_focused() {
            return Vec::new();
        }
        let focused = ui.memory(|m| m.focused().is_some());
        let mut commands = Vec::new();
        let mut take = |keys: &[Key], command: DeckCommand, always: bool| {
            for &key in keys {
                if (always || !focused) && ui.input_mut(|i| i.consume_key(Modifiers::NONE, key)) {
                    commands.push(command);
                }
            }
        };
        take(&[Key::PageDown], DeckCommand::Next, true);
        take(&[Key::PageUp], DeckCommand::Previous, true);
        take(
            &[Key::ArrowRight, Key::ArrowDown, Key::Space],
            DeckCommand::Next,
            false,
        );
        take(
            &[Key::ArrowLeft, Key::ArrowUp],
            DeckCommand::Previous,
            false,
        );
        take(&[Key::R, Key::B, Key::Period], DeckCommand::Reveal, true);
        take(&[Key::N], DeckCommand::Notes, true);
        commands
    }
}

/// A step's title, or its number when it has none.
fn title_of(step: &Step, index: usize) -> String {
    if step.title.trim().is_empty() {
        t!("deck-untitled", number = (index + 1).to_string())
    } else {
        step.title.clone()
    }
}

impl From<StepTool> for Tool {
    fn from(tool: StepTool) -> Self {
        match tool {
            StepTool::Check => Self::Check,
            StepTool::WalkThrough => Self::WalkThrough,
            StepTool::Files => Self::Files,
            StepTool::Fresnel => Self::Fresnel,
        }
    }
}

/// The step's tool for a tool of the window (the deck's own tool is none of a step's).
fn step_tool(tool: Tool) -> Option<StepTool> {
    match tool {
        Tool::Check => Some(StepTool::Check),
        Tool::WalkThrough => Some(StepTool::WalkThrough),
        Tool::Files => Some(StepTool::Files),
        Tool::Fresnel => Some(StepTool::Fresnel),
        Tool::Deck => None,
    }
}

/// What is drawn over `step`'s diagram: the effects it turns on, the standard palette, its
/// answer shown. The handout and a step's picture draw with it; the window sets its own
/// switches from the step.
#[must_use]
pub(super) fn overlay_of(step: &Step) -> Overlay {
    Overlay {
        intensities: step.has(Effect::Intensities).then_some(step.light),
        waves: step.has(Effect::Wavefronts).then(|| WaveOptions {
            phase: 0.0,
            huygens: step.has(Effect::Huygens),
        }),
        ..Overlay::default()
    }
}

impl Explorer {
    /// The window's title (in a browser, the page's, which a screen reader says first): the
    /// program's name, then the deck's title, the step's title and where the step is
    /// (`… · Snell's law in ten minutes · From air into glass · 1 / 5`), or the view (and its
    /// scene) other than the one interface. A title of a deck file is cut to a few words, as
    /// a tab shows. Never the step's question, which the strip shows.
    #[must_use]
    pub fn title(&self) -> String {
        let cut = |text: &str| {
            refraction_tools::link::echo(text.trim(), refraction_tools::link::ECHO_CHARS)
        };
        let shown = if let Some(((index, step), deck)) =
            self.lesson.current().zip(self.lesson.deck.as_ref())
        {
            let at = t!(
                "deck-step-number",
                number = (index + 1).to_string(),
                count = deck.steps.len().to_string()
            );
            [cut(&deck.title), cut(&step.title), at]
                .into_iter()
                .filter(|part| !part.is_empty())
                .collect::<Vec<_>>()
                // untranslated: the title's separator, the same in every language.
                .join(" · ")
        } else {
            match self.view {
                View::Interface => return crate::TITLE.to_owned(),
                View::Scenes => t!(
                    "access-title-scene",
                    view = View::Scenes.label(),
                    scene = refraction_diagram::scene_title(self.scenes.scene())
                ),
                View::Accuracy => View::Accuracy.label(),
            }
        };
        format!("{} · {shown}", crate::TITLE)
    }

    /// The lesson deck shown, where it is, and its tool.
    #[must_use]
    pub fn lesson(&self) -> &LessonDeck {
        &self.lesson
    }

    /// Opens the built-in deck or deck file `name` on its first step (a built-in deck in the
    /// window's language); one that cannot be read now (the file changed since the command
    /// line checked it) opens the deck tool with the reason.
    pub fn open_lesson(&mut self, name: &str) {
        match Deck::load(name) {
            Ok(deck) => self.open_deck(deck),
            Err(e) => {
                self.lesson.panel.status = Some(Status::Refused(e.to_string()));
                self.tools.open = Some(Tool::Deck);
            }
        }
    }

    /// Opens `deck` on its first step.
    pub fn open_deck(&mut self, deck: Deck) {
        self.lesson.deck = Some(deck);
        self.lesson.current = None;
        self.show_step(0);
    }

    /// Carries out `command`: moves to a step (shown as it was saved in the deck, its answer
    /// hidden again if it asks a question), reveals the answer or opens the notes.
    pub fn deck_command(&mut self, command: DeckCommand) {
        let current = self.lesson.current.unwrap_or(0);
        match command {
            DeckCommand::Next => self.show_step(current + 1),
            DeckCommand::Previous => self.show_step(current.saturating_sub(1)),
            DeckCommand::GoTo(index) => self.show_step(index),
            DeckCommand::Reveal => self.lesson.revealed = !self.lesson.revealed,
            DeckCommand::Notes => self.lesson.notes_open = !self.lesson.notes_open,
        }
    }

    /// Shows step `index` (clamped to the deck): its state, view, scene, tool and effects.
    fn show_step(&mut self, index: usize) {
        let count = self.lesson.count();
        if count == 0 {
            return;
        }
        let index = index.min(count - 1);
        if self.lesson.current == Some(index) {
            return;
        }
        let Some(deck) = self.lesson.deck.as_ref() else {
            return;
        };
        let step = deck.steps[index].clone();
        let scene =
            (step.view == StepView::Scenes || step.scene.is_some()).then(|| deck.scene(&step));
        self.lesson.current = Some(index);
        self.lesson.revealed = !step.hides_answer();
        self.state = step.state.clone();
        self.presentation.pan_zoom = Default::default();
        match scene {
            Some(Ok(scene)) => self.scenes = super::ScenesView::new(scene),
            Some(Err(why)) => self.lesson.panel.status = Some(Status::Refused(why.to_string())),
            None => {}
        }
        self.view = match step.view {
            StepView::One => View::Interface,
            StepView::Scenes => View::Scenes,
        };
        let tool = step.tool.map(Tool::from);
        if self.tools.open == Some(Tool::Deck) {
            self.tools.before_deck = tool;
        } else {
            self.tools.open = tool;
        }
        self.effects.intensities = step.has(Effect::Intensities);
        self.effects.waves = step.has(Effect::Wavefronts);
        self.effects.moving = step.has(Effect::Moving);
        self.effects.huygens = step.has(Effect::Huygens);
        self.effects.polarisation = step.light;
    }

    /// The window as it is now as a step titled `title`: the state, the view, the scene (by
    /// its name when it is built in), the tool open (the one open before the deck's own) and
    /// the effects.
    pub(super) fn captured_step(&self, title: String) -> Step {
        let view = match self.view {
            View::Scenes => StepView::Scenes,
            View::Interface | View::Accuracy => StepView::One,
        };
        let name = self.scenes.scene().name();
        let built_in = Scene::embedded(name).is_ok();
        let tool = match self.tools.open {
            Some(Tool::Deck) => self.tools.before_deck,
            open => open,
        };
        let menu = &self.effects;
        let effects = [
            (menu.intensities, Effect::Intensities),
            (menu.waves, Effect::Wavefronts),
            (menu.waves && menu.moving, Effect::Moving),
            (menu.waves && menu.huygens, Effect::Huygens),
        ];
        let on: Vec<Effect> = effects.iter().filter(|(on, _)| *on).map(|e| e.1).collect();
        let mut step = Step::new(title, self.state.clone()).effects(&on);
        step.view = view;
        step.scene = (built_in
            && (view == StepView::Scenes || name != refraction_scene::DEFAULT_SCENE))
            .then(|| name.to_owned());
        step.tool = tool.and_then(step_tool);
        step.light = menu.polarisation;
        step
    }

    /// The deck's part of a frame: its keys first, the strip above the view while a step is
    /// shown, the notes window while it is open.
    pub(super) fn deck_frame(&mut self, ui: &mut Ui) {
        if self.lesson.current().is_none() {
            return;
        }
        for command in LessonDeck::keys(ui) {
            self.deck_command(command);
        }
        let mut asked = self.deck_strip(ui);
        if self.lesson.notes_open
            && let Some(notes) = self.lesson.notes()
        {
            let hidden = self.lesson.hides_answer();
            let (commands, closed) = notes::show(ui.ctx(), &notes, hidden);
            asked.extend(commands);
            if closed {
                self.lesson.notes_open = false;
            }
        }
        for command in asked {
            self.deck_command(command);
        }
    }

    /// The strip above the view: the step's number and title, its question and whether the
    /// answer is shown, and the buttons for a mouse; none while the deck's tool (which shows
    /// the step in its fields) is open. Returns what its buttons asked.
    fn deck_strip(&self, ui: &mut Ui) -> Vec<DeckCommand> {
        let Some(notes) = self
            .lesson
            .notes()
            .filter(|_| self.tools.open != Some(Tool::Deck))
        else {
            return Vec::new();
        };
        let hidden = self.lesson.hides_answer();
        // On a projector the strip keeps to as few rows as it can: the buttons show their
        // icons, the question follows the title on its row, the reveal key's hint is the
        // question's hover, and the words are the body's size (20 pixels and more there).
        let compact = self.presentation.on;
        let hint = if hidden {
            t!("deck-hidden-hint")
        } else {
            t!("deck-shown-hint")
        };
        let size = |text: RichText| if compact { text } else { text.heading() };
        let number = t!(
            "deck-step-number",
            number = notes.number.to_string(),
            count = notes.count.to_string()
        );
        let mut asked = Vec::new();
        let height = self
            .lesson
            .deck
            .as_ref()
            .map_or(0.0, |deck| strip_height(ui, deck, compact));
        Panel::top("deck-step").exact_size(height).show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label(size(RichText::new(number).strong()));
                asked.extend(notes::buttons(ui, &notes, hidden, compact));
                ui.label(size(RichText::new(&notes.title)));
                if compact && let Some(question) = &notes.question {
                    let words = RichText::new(format!("❓ {question}")).strong();
                    ui.label(words).on_hover_text(&hint);
                }
            });
            if !compact && let Some(question) = &notes.question {
                ui.horizontal_wrapped(|ui| {
                    ui.label(RichText::new(format!("❓ {question}")).strong());
                    ui.label(RichText::new(&hint).weak());
                });
            }
        });
        asked
    }
}

/// The width of the words on one row of the strip, in points.
fn words_width(ui: &Ui, text: &str, style: &egui::TextStyle) -> f32 {
    let font = style.resolve(ui.style());
    let galley = ui
        .painter()
        .layout_no_wrap(text.to_owned(), font, egui::Color32::PLACEHOLDER);
    galley.size().x
}

/// The strip's height for the longest step of `deck` at this width: the same for every step,
/// so that the diagram below keeps its rectangle while the teacher steps. Each step's words
/// are measured on one line and divided into the rows the width gives (with a margin for the
/// breaks between words), at most four.
fn strip_height(ui: &Ui, deck: &Deck, compact: bool) -> f32 {
    let width = ui.available_width().max(1.0);
    let spacing = ui.spacing();
    let buttons = 4.0 * (spacing.interact_size.y * 1.6 + spacing.item_spacing.x);
    let title_style = if compact {
        egui::TextStyle::Body
    } else {
        egui::TextStyle::Heading
    };
    let rows_for = |used: f32| (used * 1.1 / width).ceil().clamp(1.0, 4.0);
    // At the desk the reveal key's hint follows the question on its row.
    let hint = if compact {
        String::new()
    } else {
        t!("deck-hidden-hint")
    };
    let rows = deck
        .steps
        .iter()
        .map(|step| {
            let title = words_width(ui, &format!("99 / 99  {}", step.title), &title_style);
            let question = step.question.as_ref().map_or(0.0, |q| {
                words_width(ui, &format!("❓ {q}  {hint}"), &egui::TextStyle::Body)
            });
            if compact {
                rows_for(buttons + title + question)
            } else {
                rows_for(buttons + title)
                    + if question > 0.0 {
                        rows_for(question)
                    } else {
                        0.0
                    }
            }
        })
        .fold(1.0, f32::max);
    let row = ui
        .text_style_height(&title_style)
        .max(spacing.interact_size.y);
    rows * (row + spacing.item_spacing.y) + spacing.item_spacing.y
}

impl Explorer {
    /// The *Lesson deck* tool in its panel ([`super::tools::frame`]), while it is open, in
    /// every view; then what it asked done.
    pub(super) fn deck_panel(&mut self, ui: &mut Ui) {
        if self.tools.open != Some(Tool::Deck) {
            return;
        }
        let presenting = self.presentation.on;
        let LessonDeck {
            deck,
            current,
            panel,
            ..
        } = &mut self.lesson;
        let action = super::tools::frame(ui, Tool::Deck, presenting)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .show(ui, |ui| panel.show(ui, deck, current))
                    .inner
            })
            .inner;
        match action {
            Some(panel::Action::GoTo(index)) => self.show_step(index),
            Some(panel::Action::Open(deck)) => self.open_deck(deck),
            Some(panel::Action::Add) => self.add_step(),
            Some(panel::Action::Update) => self.update_step(),
            Some(panel::Action::Handout) => self.write_handout(),
            None => {}
        }
    }

    /// Adds the window as it is now as a step after the one shown (a new deck when none is
    /// open), and shows it.
    fn add_step(&mut self) {
        let deck = self.lesson.deck.get_or_insert_with(|| Deck {
            title: String::new(),
            steps: Vec::new(),
            folder: None,
        });
        let at = self.lesson.current.map_or(deck.steps.len(), |c| c + 1);
        let title = t!("deck-untitled", number = (at + 1).to_string());
        let step = self.captured_step(title);
        if let Some(deck) = self.lesson.deck.as_mut() {
            deck.steps.insert(at.min(deck.steps.len()), step);
        }
        self.lesson.current = Some(at);
        self.lesson.revealed = true;
        self.lesson.panel.edited = true;
    }

    /// Keeps the window as it is now in the step shown: its state, view, scene, tool and
    /// effects (a scene's effects and the step's words stay).
    fn update_step(&mut self) {
        let Some((index, step)) = self.lesson.current() else {
            return;
        };
        let kept = step.clone();
        let mut now = self.captured_step(kept.title.clone());
        now.notes = kept.notes;
        now.question = kept.question;
        let scene_effects: Vec<Effect> = kept
            .effects
            .iter()
            .copied()
            .filter(|e| {
                !matches!(
                    e,
                    Effect::Intensities | Effect::Wavefronts | Effect::Moving | Effect::Huygens
                )
            })
            .chain(now.effects.iter().copied())
            .collect();
        let now = now.effects(&scene_effects);
        if let Some(deck) = self.lesson.deck.as_mut() {
            deck.steps[index] = now;
        }
        self.lesson.panel.edited = true;
    }
}

//! The student's view: what a QR code or a link opens on a phone (a small screen, or any
//! screen when the link says `view=student`). A layout of the same window, not a second
//! program: the same state, deck and diagram, fewer panels. The step's question in readable
//! type, the diagram across the whole width with handles a finger can take (pinch to zoom,
//! one finger to pan where nothing is grabbed), a *Reveal* button instead of the R key, the
//! deck's step buttons and the [step buttons](super::steps::for_student); nothing of the
//! teacher's: no notes, no tools, no export. Portrait puts the buttons under the diagram,
//! landscape beside it. The projector keeps the teacher's view: presentation never shows this
//! one.

use egui::{Button, Context, Panel, RichText, Role, TextStyle, Ui, Vec2, WidgetInfo};
use refraction_diagram::TOUCH_TARGET;
use refraction_i18n::t;

use super::deck::{DeckCommand, LessonDeck};
use super::{Explorer, View, canvas, steps};

/// The widest screen the student's view opens on by itself, in points (CSS pixels in a
/// browser): a phone or a tablet held upright. The desktop window is never narrower (900).
const SMALL_WIDTH: f32 = 900.0;

/// The shortest screen the student's view opens on by itself: a phone held sideways.
const SMALL_HEIGHT: f32 = 480.0;

/// The width of the step buttons' column beside a landscape diagram, in points.
const COLUMN_WIDTH: f32 = 290.0;

/// The size of the question's words, in points (CSS pixels): 18, over the 16 a phone reads.
const QUESTION_SIZE: f32 = 18.0;

/// The size of the step's title and the panels' words, in points.
const WORDS_SIZE: f32 = 16.0;

/// Whether the window shows the student's view.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct StudentView {
    /// The link opened asked for it (`view=student`).
    pub asked: bool,
    /// The whole explorer was chosen instead (*Full explorer*), for this session.
    pub full: bool,
}

impl StudentView {
    /// Whether the screen of `ctx` is a phone's or an upright tablet's.
    fn small(ctx: &Context) -> bool {
        let screen = ctx.content_rect();
        screen.width() < SMALL_WIDTH || screen.height() < SMALL_HEIGHT
    }

    /// Whether the student's view may be shown: a link asked for it, or the screen is small.
    pub(super) fn offered(self, ctx: &Context) -> bool {
        self.asked || Self::small(ctx)
    }

    /// Whether the window shows it now: offered, not turned down, and not on a projector.
    pub(super) fn shown(self, ctx: &Context, presenting: bool) -> bool {
        !presenting && !self.full && self.offered(ctx)
    }

    /// In the teacher's bar, where the student's view is offered: the switch back to it.
    pub(super) fn switch(&mut self, ui: &mut Ui) {
        if !self.offered(ui.ctx()) {
            return;
        }
        let name = t!("student-view");
        let switch = ui.button(format!("📱 {name}"));
        if switch.on_hover_text(t!("student-view-hover")).clicked() {
            self.full = false;
        }
    }
}

/// Sets `ui`'s spacing and words for a finger and a phone: controls at least [`TOUCH_TARGET`]
/// high, words at [`WORDS_SIZE`].
fn finger_sized(ui: &mut Ui) {
    let style = ui.style_mut();
    style.spacing.interact_size = Vec2::splat(TOUCH_TARGET);
    style.spacing.item_spacing = Vec2::splat(8.0);
    for text in [TextStyle::Body, TextStyle::Button] {
        if let Some(font) = style.text_styles.get_mut(&text) {
            font.size = WORDS_SIZE;
        }
    }
}

/// A button of a finger's size showing `text`, named `name`; `enabled` greys it out.
fn big_button(ui: &mut Ui, text: &str, name: &str, (enabled, selected): (bool, bool)) -> bool {
    let button = Button::new(RichText::new(text).size(QUESTION_SIZE))
        .min_size(Vec2::splat(TOUCH_TARGET))
        .selected(selected);
    let pressed = ui.add_enabled(enabled, button);
    pressed.widget_info(|| WidgetInfo::labeled(Role::Button, enabled, name));
    pressed.on_hover_text(name).clicked()
}

impl Explorer {
    /// Shows the student's view in `ui` (the whole window): the step and its question above,
    /// the step buttons under the diagram (beside it in landscape), the diagram in between.
    pub(super) fn show_student(&mut self, ui: &mut Ui) {
        let screen = ui.ctx().content_rect();
        let landscape = screen.width() > screen.height();
        // Sideways the step buttons take the window's height beside the diagram, and the
        // step's strip stands over the diagram alone; a scene has none (its handles are its
        // own), and keeps the width.
        let column = landscape && self.view != View::Scenes;
        if column {
            self.student_buttons(ui, true);
        }
        if self.lesson.current().is_some() {
            // The deck's keys still step and reveal (a laptop's keyboard); no notes here.
            let mut asked = LessonDeck::keys(ui);
            asked.retain(|c| *c != DeckCommand::Notes);
            asked.extend(self.student_step(ui, landscape));
            for command in asked {
                self.deck_command(command);
            }
        }
        if !column {
            self.student_buttons(ui, false);
        }
        self.student_diagram(ui);
    }

    /// The panel of the step buttons (none for a scene, whose handles are its own) and
    /// *Full explorer*: under the diagram, or in a `column` beside it.
    fn student_buttons(&mut self, ui: &mut Ui, column: bool) {
        let panel = if column {
            let width = COLUMN_WIDTH.min(ui.ctx().content_rect().width() * 0.4);
            Panel::right("student-buttons")
                .resizable(false)
                .exact_size(width)
        } else {
            Panel::bottom("student-buttons").resizable(false)
        };
        let scene = self.view == View::Scenes;
        let (state, student) = (&mut self.state, &mut self.student);
        panel.show(ui, |ui| {
            finger_sized(ui);
            ui.add_space(4.0);
            if !scene {
                steps::for_student(ui, state, column);
            }
            let full = t!("student-full");
            if ui
                .button(format!("🖥 {full}"))
                .on_hover_text(t!("student-full-hover"))
                .clicked()
            {
                student.full = true;
            }
        });
    }

    /// The strip above the diagram: the deck's step buttons, *Reveal* on a step that asks,
    /// the step's title (upright; sideways, where the height is short, the question alone)
    /// and its question. Returns what its buttons asked.
    fn student_step(&self, ui: &mut Ui, landscape: bool) -> Vec<DeckCommand> {
        let Some(notes) = self.lesson.notes() else {
            return Vec::new();
        };
        let hidden = self.lesson.hides_answer();
        let mut asked = Vec::new();
        Panel::top("student-step").show(ui, |ui| {
            finger_sized(ui);
            ui.horizontal_wrapped(|ui| {
                let first = notes.number > 1;
                if big_button(ui, "⏴", &t!("deck-previous"), (first, false)) {
                    asked.push(DeckCommand::Previous);
                }
                let at = t!(
                    "deck-step-number",
                    number = notes.number.to_string(),
                    count = notes.count.to_string()
                );
                ui.label(RichText::new(at).size(QUESTION_SIZE).strong());
                let last = notes.number < notes.count;
                if big_button(ui, "⏵", &t!("deck-next"), (last, false)) {
                    asked.push(DeckCommand::Next);
                }
                if notes.question.is_some() {
                    let (icon, name) = if hidden {
                        ("👁", t!("deck-reveal"))
                    } else {
                        ("🙈", t!("deck-hide"))
                    };
                    let words = format!("{icon} {name}");
                    if big_button(ui, &words, &name, (true, !hidden)) {
                        asked.push(DeckCommand::Reveal);
                    }
                }
            });
            if !landscape || notes.question.is_none() {
                ui.label(RichText::new(&notes.title).size(WORDS_SIZE).strong());
            }
            if let Some(question) = &notes.question {
                ui.label(RichText::new(format!("❓ {question}")).size(QUESTION_SIZE));
            }
            ui.add_space(4.0);
        });
        asked
    }

    /// The diagram across what the strips leave: the interface with handles for a finger and
    /// no index scale (the step buttons set the indices), or the step's scene.
    fn student_diagram(&mut self, ui: &mut Ui) {
        let step_shown = self.lesson.current().is_some();
        self.scenes
            .for_lesson(step_shown, self.lesson.hides_answer());
        if self.view == View::Scenes {
            let palette = self.presentation.palette();
            if let Some(state) = self.scenes.show_for_touch(ui, &palette) {
                self.state = state;
                self.view = View::Interface;
            }
            return;
        }
        let mut overlay = self.overlay();
        let state = &mut self.state;
        egui::CentralPanel::no_frame().show(ui, |ui| {
            let under = canvas::Under {
                steps: false,
                hint: false,
            };
            canvas::show(ui, state, &mut overlay, under);
        });
        self.presentation.pan_zoom = overlay.pan_zoom;
    }
}

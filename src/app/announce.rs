//! What a screen reader hears without looking at the window: the window in words (the lesson
//! step, the view and the diagram: [`refraction_deck::describe::page`]) and, after an edit, what
//! changed ([`refraction_model::describe::change`]), said once the edit rests, in one polite
//! live region: a status node of the window's AccessKit tree on the desktop; in a browser the
//! page's live region says [`last`].
//!
//! A new step, a revealed answer or another view is said whole, at once; an edit within them
//! is said as a change once the pointer is up and the state has rested for [`SETTLE_S`], so
//! that a key held down or a run of step buttons is said once, where it ended. Opening the
//! window is not news: nothing is said until something changes.

use egui::accesskit::{Live, Role};
use egui::{Context, Id, Ui};
use refraction_deck::describe::{Shown, StepShown};
use refraction_diagram::{scene_description, scene_title};
use refraction_model::ExplorerState;
use refraction_model::describe::{self, Disclosure};

use super::{Explorer, View};

/// How long an edit rests before it is said, in seconds.
const SETTLE_S: f64 = 0.4;

/// What the window shows besides the interface's state: when it changes, the whole window is
/// said again.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Scope {
    view: View,
    /// The deck's step shown, by position.
    step: Option<usize>,
    /// Whether the step's answer is hidden.
    hidden: bool,
}

/// What was said, kept in the window's memory between frames.
#[derive(Clone, Debug, Default)]
struct Spoken {
    /// The scope and state last said: what the next change is told against.
    said: Option<(Scope, ExplorerState)>,
    /// The state last seen, and when it last changed (egui's time, in seconds).
    seen: Option<(ExplorerState, f64)>,
    /// The last sentence said, and how many have been said.
    sentence: String,
    count: u64,
}

impl Spoken {
    /// Says `sentence` (counted even when it repeats the last one, so that it is said again).
    fn say(&mut self, sentence: String) {
        self.sentence = sentence;
        self.count += 1;
    }
}

/// Where the window keeps what was said.
fn memory() -> Id {
    Id::unique("explorer-spoken")
}

/// The status node's id in the AccessKit tree.
fn status() -> Id {
    Id::unique("explorer-live-status")
}

/// The window in words, as a sighted student sees it: the step shown and its question, the
/// view, and the diagram (or the scene) with the step's answer kept out while it is hidden.
pub(super) fn page_words(explorer: &Explorer) -> Vec<String> {
    let lesson = explorer.lesson();
    let answer = Disclosure::hidden_if(lesson.hides_answer());
    let step = lesson
        .current()
        .zip(lesson.deck.as_ref())
        .map(|((index, step), deck)| StepShown {
            step,
            number: index + 1,
            count: deck.steps.len(),
        });
    let scene = explorer.scenes().scene();
    let (title, about) = (scene_title(scene), scene_description(scene));
    let accuracy = View::Accuracy.label();
    let shown = match explorer.view() {
        View::Interface => Shown::Interface,
        View::Scenes => Shown::Scene {
            title: &title,
            about: &about,
        },
        View::Accuracy => Shown::Other { name: &accuracy },
    };
    refraction_deck::describe::page(explorer.state(), shown, step, answer)
}

/// Follows the window after its frame: says a new scope whole and a rested edit as a change,
/// and puts the last sentence in the window's live status node.
pub(super) fn follow(ui: &Ui, explorer: &Explorer) {
    let ctx = ui.ctx();
    let (now, pressed) = ui.input(|i| (i.time, i.pointer.any_down()));
    let lesson = explorer.lesson();
    let scope = Scope {
        view: explorer.view(),
        step: lesson.current().map(|(index, _)| index),
        hidden: lesson.hides_answer(),
    };
    let state = explorer.state();
    let mut spoken: Spoken = ctx.data_mut(|d| d.get_temp(memory())).unwrap_or_default();
    if spoken.seen.as_ref().is_none_or(|(seen, _)| seen != state) {
        spoken.seen = Some((state.clone(), now));
    }
    let rested = spoken.seen.as_ref().map_or(0.0, |(_, since)| now - since);
    match &spoken.said {
        None => spoken.said = Some((scope, state.clone())),
        Some((before, _)) if *before != scope => {
            spoken.say(page_words(explorer).join(" "));
            spoken.said = Some((scope, state.clone()));
        }
        Some((_, before)) if before != state => {
            if pressed || explorer.animating() || rested < SETTLE_S {
                ctx.request_repaint_after_secs((SETTLE_S - rested).max(0.05) as f32);
            } else {
                let answer = Disclosure::hidden_if(scope.hidden);
                if let Some(sentence) = describe::change(before, state, answer) {
                    spoken.say(sentence);
                }
                spoken.said = Some((scope, state.clone()));
            }
        }
        Some(_) => {}
    }
    live_status(ctx, &spoken.sentence);
    ctx.data_mut(|d| d.insert_temp(memory(), spoken));
}

/// The window's polite live status: an AccessKit node whose words a screen reader says when
/// they change (its label on Windows and Linux, its value on macOS).
fn live_status(ctx: &Context, sentence: &str) {
    let window = ctx.content_rect();
    ctx.accesskit_node_builder(status(), |node| {
        node.set_role(Role::Status);
        node.set_live(Live::Polite);
        node.set_bounds(egui::accesskit::Rect {
            x0: window.min.x.into(),
            y0: window.min.y.into(),
            x1: window.max.x.into(),
            y1: window.max.y.into(),
        });
        if !sentence.is_empty() {
            node.set_label(sentence);
            node.set_value(sentence);
        }
    });
}

/// The last sentence said and how many have been said (a new count is a new sentence, even
/// when the words repeat), once something was said.
#[cfg_attr(
    not(target_arch = "wasm32"),
    expect(
        dead_code,
        reason = "the page's live region reads it; the desktop's is AccessKit's"
    )
)]
pub(super) fn last(ctx: &Context) -> Option<(u64, String)> {
    let spoken: Spoken = ctx.data_mut(|d| d.get_temp(memory()))?;
    (spoken.count > 0).then_some((spoken.count, spoken.sentence))
}

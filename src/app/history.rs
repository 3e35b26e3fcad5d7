//! Undo and redo (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y) over whole snapshots of what the user edits.
//!
//! The history keeps copies of the whole [`Snapshot`], not a list of edits, so any new part of
//! the explorer's state becomes undoable by adding a field to [`Snapshot`]: nothing else here
//! changes. A change is recorded once the user lets go (no pointer button held, no animation
//! running), so a drag or the μ → 1 animation is one step, not one per frame.

use std::collections::VecDeque;
use std::sync::Arc;

use egui::{Key, KeyboardShortcut, Modifiers, Ui};

use super::widgets::icon_button;

use refraction_diagram::numbers::significant;
use refraction_i18n::t;
use refraction_model::ExplorerState;
use refraction_scene::Scene;

/// How many steps back the history reaches; older ones are forgotten.
pub(super) const LIMIT: usize = 1000;

/// Everything undo restores. The scene is shared between the steps that did not change it
/// (most steps edit the single interface), so a thousand steps hold a few scenes, not a
/// thousand copies.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// The single interface: W, N, `μ_i`, `μ_t` and the convention.
    pub interface: ExplorerState,
    /// The Scenes view's scene as edited: which scene, its source and its shapes.
    pub scene: Arc<Scene>,
}

impl Snapshot {
    /// Whether this snapshot already holds `interface` and `scene` (compared in place, so that
    /// nothing is copied on the frames where nothing changed).
    #[must_use]
    pub fn same_as(&self, interface: &ExplorerState, scene: &Scene) -> bool {
        self.interface == *interface && *self.scene == *scene
    }

    /// A snapshot of `interface` and `scene`, sharing `before`'s scene when it is the same.
    #[must_use]
    pub fn after(before: &Self, interface: &ExplorerState, scene: &Scene) -> Self {
        let scene = if *before.scene == *scene {
            Arc::clone(&before.scene)
        } else {
            Arc::new(scene.clone())
        };
        Self {
            interface: interface.clone(),
            scene,
        }
    }

    /// A first snapshot of `interface` and `scene`.
    #[must_use]
    pub fn of(interface: &ExplorerState, scene: &Scene) -> Self {
        Self {
            interface: interface.clone(),
            scene: Arc::new(scene.clone()),
        }
    }
}

/// What one undo or redo changed, in words and by view.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Change {
    /// E.g. `Undid μt 1.5 → 1.333`.
    pub words: String,
    /// Whether the single interface changed.
    pub in_interface: bool,
    /// Whether the Scenes view's scene changed.
    pub in_scene: bool,
}

/// The angle of W from the normal, in degrees, for a message.
fn incidence_degrees(state: &ExplorerState) -> String {
    significant(
        state
            .refraction()
            .cos_i
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees(),
        3,
    )
}

/// What changed from `from` to `to` in the single interface, one phrase per part.
fn interface_changes(from: &ExplorerState, to: &ExplorerState) -> Vec<String> {
    let mut parts = Vec::new();
    if from.convention() != to.convention() {
        parts.push(t!(
            "files-undo-convention",
            from = from.convention().section().to_string(),
            to = to.convention().section().to_string()
        ));
    }
    for (symbol, a, b) in [
        ("μi", from.mu_i(), to.mu_i()),
        ("μt", from.mu_t(), to.mu_t()),
    ] {
        if a != b {
            parts.push(format!(
                "{symbol} {} → {}",
                significant(a, 4),
                significant(b, 4)
            ));
        }
    }
    if from.n() != to.n() && from.n() != -to.n() {
        parts.push(t!("files-undo-n-turned"));
    } else if from.n() == -to.n() {
        parts.push(t!("files-undo-n-flipped"));
    }
    if from.w() != to.w() && from.convention() == to.convention() {
        parts.push(format!(
            "θi {}° → {}°",
            incidence_degrees(from),
            incidence_degrees(to)
        ));
    }
    parts
}

/// What moving from `from` to `to` by `travel` changed, in words.
#[must_use]
pub(super) fn describe(travel: Travel, from: &Snapshot, to: &Snapshot) -> Change {
    let mut parts = interface_changes(&from.interface, &to.interface);
    let in_interface = from.interface != to.interface;
    let in_scene = from.scene != to.scene;
    if in_scene {
        parts.push(if from.scene.name() == to.scene.name() {
            t!("files-undo-scene-edit", scene = to.scene.title())
        } else {
            t!(
                "files-undo-scene",
                from = from.scene.title(),
                to = to.scene.title()
            )
        });
    }
    if parts.is_empty() && in_interface {
        parts.push(t!("files-undo-w-or-n-typed"));
    }
    // The language's list separator: "; " where numbers have a decimal comma.
    let changes = parts.join(refraction_i18n::locale().list_separator());
    let words = match travel {
        Travel::Undo => t!("files-undid", changes = changes),
        Travel::Redo => t!("files-redid", changes = changes),
    };
    Change {
        words,
        in_interface,
        in_scene,
    }
}

/// A linear history of values: the present, what came before it (the oldest forgotten first,
/// past [`LIMIT`]) and what was undone.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct History<T> {
    past: VecDeque<T>,
    present: T,
    future: Vec<T>,
}

/// Which way to move in the history.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Travel {
    /// Back one step.
    Undo,
    /// Forward one undone step.
    Redo,
}

impl<T: Clone + PartialEq> History<T> {
    /// A history that starts at `present`, with nothing to undo.
    #[must_use]
    pub fn new(present: T) -> Self {
        Self {
            past: VecDeque::new(),
            present,
            future: Vec::new(),
        }
    }

    /// The present value.
    #[must_use]
    pub fn present(&self) -> &T {
        &self.present
    }

    /// Records `now` as a new step if it differs from the present; a new step forgets what was
    /// undone.
    pub fn record(&mut self, now: &T) {
        if *now != self.present {
            self.push(now.clone());
        }
    }

    /// Records `make(present)` as the present unless `unchanged` says the present already
    /// holds it: for values that are costly to build every frame.
    pub fn record_unless(
        &mut self,
        unchanged: impl FnOnce(&T) -> bool,
        make: impl FnOnce(&T) -> T,
    ) {
        if !unchanged(&self.present) {
            let now = make(&self.present);
            self.push(now);
        }
    }

    fn push(&mut self, now: T) {
        self.past
            .push_back(core::mem::replace(&mut self.present, now));
        if self.past.len() > LIMIT {
            self.past.pop_front();
        }
        self.future.clear();
    }

    /// Moves one step back or forward and returns the value to restore, or `None` when there
    /// is nothing that way.
    pub fn travel(&mut self, travel: Travel) -> Option<T> {
        let value = match travel {
            Travel::Undo => self.past.pop_back()?,
            Travel::Redo => self.future.pop()?,
        };
        let before = core::mem::replace(&mut self.present, value);
        match travel {
            Travel::Undo => self.future.push(before),
            Travel::Redo => self.past.push_back(before),
        }
        Some(self.present.clone())
    }

    /// How many steps can be undone.
    #[must_use]
    pub fn undo_steps(&self) -> usize {
        self.past.len()
    }

    /// How many undone steps can be redone.
    #[must_use]
    pub fn redo_steps(&self) -> usize {
        self.future.len()
    }
}

/// The history's keyboard shortcuts, unless a text field has the keyboard (there Ctrl+Z
/// undoes typing).
fn shortcut(ui: &Ui) -> Option<Travel> {
    if ui.ctx().text_edit_focused() {
        return None;
    }
    let redo_shift = KeyboardShortcut::new(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    let redo_y = KeyboardShortcut::new(Modifiers::COMMAND, Key::Y);
    let undo = KeyboardShortcut::new(Modifiers::COMMAND, Key::Z);
    ui.input_mut(|i| {
        // Redo first: Ctrl+Z would also match Ctrl+Shift+Z, which egui compares logically.
        if i.consume_shortcut(&redo_shift) || i.consume_shortcut(&redo_y) {
            Some(Travel::Redo)
        } else if i.consume_shortcut(&undo) {
            Some(Travel::Undo)
        } else {
            None
        }
    })
}

/// The Undo and Redo buttons, and their shortcuts: which way the user asked to move. A
/// `compact` bar (presentation) shows only their arrows; their names stay their accessible
/// names and hover texts.
pub(super) fn controls<T: Clone + PartialEq>(
    ui: &mut Ui,
    history: &History<T>,
    compact: bool,
) -> Option<Travel> {
    let mut asked = shortcut(ui);
    let undo = ("⟲", t!("files-undo"), t!("files-undo-hover"));
    if icon_button(ui, undo, (history.undo_steps() > 0, false), compact) {
        asked = Some(Travel::Undo);
    }
    let redo = ("⟳", t!("files-redo"), t!("files-redo-hover"));
    if icon_button(ui, redo, (history.redo_steps() > 0, false), compact) {
        asked = Some(Travel::Redo);
    }
    asked
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oldest_steps_are_forgotten_and_an_unchanged_scene_is_shared() {
        // Issue 35: a thousand full scene clones, the oldest removed from the front of a Vec.
        let scene = Scene::embedded("droplet").unwrap();
        let mut state = ExplorerState::default();
        let mut history = History::new(Snapshot::of(&state, &scene));
        for i in 0..LIMIT + 5 {
            state.set_mu_t(1.2 + i as f64 * 1e-4).unwrap();
            history.record_unless(
                |present| present.same_as(&state, &scene),
                |present| Snapshot::after(present, &state, &scene),
            );
        }
        assert_eq!(history.undo_steps(), LIMIT);
        let present = Arc::clone(&history.present().scene);
        let before = history.travel(Travel::Undo).unwrap();
        assert!(
            Arc::ptr_eq(&before.scene, &present),
            "one scene for every step"
        );
    }

    #[test]
    fn undo_and_redo_walk_the_recorded_steps_and_a_new_step_forgets_the_future() {
        let mut history = History::new(0);
        assert_eq!(history.travel(Travel::Undo), None);
        for value in [1, 1, 2, 3] {
            history.record(&value);
        }
        assert_eq!(history.undo_steps(), 3);
        assert_eq!(history.travel(Travel::Undo), Some(2));
        assert_eq!(history.travel(Travel::Undo), Some(1));
        assert_eq!(history.travel(Travel::Redo), Some(2));
        // Restoring the present records nothing.
        history.record(&2);
        assert_eq!(history.redo_steps(), 1);
        history.record(&7);
        assert_eq!(history.redo_steps(), 0);
        assert_eq!(history.travel(Travel::Redo), None);
        assert_eq!(history.travel(Travel::Undo), Some(2));
    }

    /// The droplet with the default interface, and the same with μt 1.333 and N flipped.
    fn start_and_edited() -> (Snapshot, Snapshot) {
        let start = Snapshot::of(
            &ExplorerState::default(),
            &Scene::embedded("droplet").unwrap(),
        );
        let mut edited = start.clone();
        edited.interface.set_mu_t(1.333).unwrap();
        edited.interface.flip_normal();
        (start, edited)
    }

    #[test]
    fn an_undo_says_what_it_changed_and_where() {
        let (start, edited) = start_and_edited();
        let change = describe(Travel::Undo, &edited, &start);
        assert_eq!(change.words, "Undid μt 1.333 → 1.5, N flipped");
        assert!(change.in_interface && !change.in_scene);
        let mut scene = start.clone();
        scene.scene = Arc::new(Scene::embedded("slab").unwrap());
        let change = describe(Travel::Redo, &start, &scene);
        assert!(
            change.words.starts_with("Redid the scene ("),
            "{}",
            change.words
        );
        assert!(change.in_scene && !change.in_interface);
        let mut turned = start.clone();
        turned.interface.rotate(refraction_model::HandleId::W, 10.0);
        let words = describe(Travel::Undo, &turned, &start).words;
        assert_eq!(words, "Undid θi 50° → 40°");
    }

    #[test]
    fn an_undo_speaks_the_language_of_the_window_with_its_decimal_comma() {
        use refraction_i18n::{Locale, set_locale};
        let (start, edited) = start_and_edited();
        set_locale(Locale::De);
        let undone = describe(Travel::Undo, &edited, &start).words;
        let redone = describe(Travel::Redo, &start, &edited).words;
        set_locale(Locale::En);
        // A semicolon between the changes: the comma is the numbers' own.
        assert_eq!(undone, "Rückgängig: μt 1,333 → 1,5; N umgekehrt");
        assert_eq!(redone, "Wiederholt: μt 1,5 → 1,333; N umgekehrt");
    }

    #[test]
    fn the_oldest_steps_are_forgotten_beyond_the_limit() {
        let mut history = History::new(0);
        for value in 1..=LIMIT + 10 {
            history.record(&value);
        }
        assert_eq!(history.undo_steps(), LIMIT);
        while history.travel(Travel::Undo).is_some() {}
        assert_eq!(history.present, 10);
    }
}

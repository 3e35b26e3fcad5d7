//! Undo and redo (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y) over whole snapshots of what the user edits.
//!
//! The history keeps copies of the whole [`Snapshot`], not a list of edits, so any new part of
//! the explorer's state becomes undoable by adding a field to [`Snapshot`]: nothing else here
//! changes. A change is recorded once the user lets go (no pointer button held, no animation
//! running), so a drag or the μ → 1 animation is one step, not one per frame.

use egui::{Button, Key, KeyboardShortcut, Modifiers, Ui};

use refraction_diagram::ExplorerState;
use refraction_scene::Scene;

/// How many steps back the history reaches; older ones are forgotten.
pub const LIMIT: usize = 1000;

/// Everything undo restores.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// The single interface: W, N, μ_i, μ_t and the convention.
    pub interface: ExplorerState,
    /// The Scenes view's scene as edited: which scene, its source and its shapes.
    pub scene: Scene,
}

impl Snapshot {
    /// Whether this snapshot already holds `interface` and `scene` (compared in place, so that
    /// nothing is copied on the frames where nothing changed).
    #[must_use]
    pub fn holds(&self, interface: &ExplorerState, scene: &Scene) -> bool {
        self.interface == *interface && self.scene == *scene
    }
}

/// A linear history of values: the present, what came before it and what was undone.
#[derive(Clone, Debug, PartialEq)]
pub struct History<T> {
    past: Vec<T>,
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
            past: Vec::new(),
            present,
            future: Vec::new(),
        }
    }

    /// Records `now` as a new step if it differs from the present; a new step forgets what was
    /// undone.
    pub fn record(&mut self, now: &T) {
        if *now != self.present {
            self.push(now.clone());
        }
    }

    /// Records `make()` as the present unless `unchanged` says the present already holds it:
    /// for values that are costly to build every frame.
    pub fn record_unless(&mut self, unchanged: impl FnOnce(&T) -> bool, make: impl FnOnce() -> T) {
        if !unchanged(&self.present) {
            self.push(make());
        }
    }

    fn push(&mut self, now: T) {
        self.past.push(std::mem::replace(&mut self.present, now));
        if self.past.len() > LIMIT {
            self.past.remove(0);
        }
        self.future.clear();
    }

    /// Moves one step back or forward and returns the value to restore, or `None` when there
    /// is nothing that way.
    pub fn travel(&mut self, travel: Travel) -> Option<T> {
        let (from, to) = match travel {
            Travel::Undo => (&mut self.past, &mut self.future),
            Travel::Redo => (&mut self.future, &mut self.past),
        };
        let value = from.pop()?;
        to.push(std::mem::replace(&mut self.present, value));
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
fn shortcut(ui: &mut Ui) -> Option<Travel> {
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

/// The Undo and Redo buttons, and their shortcuts: which way the user asked to move.
pub fn controls<T: Clone + PartialEq>(ui: &mut Ui, history: &History<T>) -> Option<Travel> {
    let mut asked = shortcut(ui);
    let undo = Button::new("⟲ Undo");
    let undo = ui
        .add_enabled(history.undo_steps() > 0, undo)
        .on_hover_text("Undo the last change of W, N, μ or convention (Ctrl+Z)");
    if undo.clicked() {
        asked = Some(Travel::Undo);
    }
    let redo = Button::new("⟳ Redo");
    let redo = ui
        .add_enabled(history.redo_steps() > 0, redo)
        .on_hover_text("Redo what was undone (Ctrl+Shift+Z)");
    if redo.clicked() {
        asked = Some(Travel::Redo);
    }
    asked
}

#[cfg(test)]
mod tests {
    use super::*;

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

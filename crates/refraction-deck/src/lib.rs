//! Lesson decks: a teacher's own sequence of explorer states, stepped through in front of a
//! class. A [`Deck`] is a title and ordered [`Step`]s; each step holds a title, the state shown
//! (W, N, the indices and the convention, the view, a built-in or file scene, the tool and the
//! effects open), the teacher's notes and optionally a question for the class, whose answer
//! stays hidden until the teacher reveals it ([`answer`]).
//!
//! - [`Deck::load`]: a built-in deck by name ([`builtin`]) or a deck file, read with the scene
//!   format's `FILE:LINE:COLUMN` errors; [`Deck::to_toml`] writes it back exactly.
//! - [`builtin::catalogue`]: the decks built in, in the current language.
//! - [`describe::page`]: the step shown and its view in words, for a screen reader, its answer
//!   kept out until it is revealed.
//!
//! It sits above the model and the scenes and below the window and the commands, so that the
//! window steps through a deck and `render --lesson` draws its handout from the same steps.
//!
//! ```
//! use refraction_deck::Deck;
//! let deck = Deck::load("snell")?;
//! assert!(deck.steps.len() >= 4);
//! let text = deck.to_toml().unwrap();
//! assert_eq!(Deck::from_toml(&text, "snell.toml", None)?, deck);
//! # Ok::<(), refraction_scene::LoadError>(())
//! ```

pub mod answer;
pub mod builtin;
pub mod describe;
mod file;
mod step;

use std::path::PathBuf;

pub use file::{
    MAX_DECK_FILE_BYTES, MAX_STEPS, VERSION, looks_like_deck, resolve_scene, scene_file,
};
pub use step::{Effect, Step, StepTool, StepView};

use refraction_scene::{LoadError, Scene};

/// A lesson deck: a title and its steps, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Deck {
    /// The deck's title (may be empty).
    pub title: String,
    /// The steps, in the order they are shown.
    pub steps: Vec<Step>,
    /// The folder a step's scene file is found from (the deck file's); `None`: the working
    /// folder, as for a built-in deck.
    pub folder: Option<PathBuf>,
}

impl Deck {
    /// The scene files the deck's steps read, each once, in the order of the steps (built-in
    /// scenes are no files): with the deck's own file, what a command that writes must never
    /// write over.
    #[must_use]
    pub fn scene_files(&self) -> Vec<PathBuf> {
        let mut files: Vec<PathBuf> = Vec::new();
        for name in self.steps.iter().filter_map(|s| s.scene.as_deref()) {
            if let Some(path) = scene_file(name, self.folder.as_deref())
                && !files.contains(&path)
            {
                files.push(path);
            }
        }
        files
    }

    /// The scene `step` shows on the Scenes view, its effects with the step's added.
    ///
    /// # Errors
    /// The scene cannot be opened ([`resolve_scene`]).
    pub fn scene(&self, step: &Step) -> Result<Scene, LoadError> {
        let mut scene = resolve_scene(step.scene_name(), self.folder.as_deref())?;
        let effects = step.scene_effects(*scene.effects());
        // Turning effects on keeps the scene's limits, which it was loaded with.
        scene.set_effects(effects).map_err(|e| LoadError {
            file: scene.name().to_owned(),
            position: None,
            message: e.to_string(),
        })?;
        Ok(scene)
    }
}

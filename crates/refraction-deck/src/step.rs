//! One step of a lesson deck: what the window shows (the state, the view, a scene, the open
//! tool and effects) and what the teacher says and asks.

use serde::{Deserialize, Serialize};

use refraction_model::{ExplorerState, Polarisation};
use refraction_scene::{DEFAULT_SCENE, Effects};

/// The view a step shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StepView {
    /// One interface: W, N and the indices of the step's state.
    #[default]
    One,
    /// The step's scene, traced.
    Scenes,
}

/// The tool open beside the diagram during a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StepTool {
    /// Check my T.
    Check,
    /// The walk-through of the derivation.
    WalkThrough,
    /// Save, open, share.
    Files,
    /// The Fresnel plot.
    Fresnel,
}

/// An effect a step turns on: the one-interface diagram's switches, or a scene's effects on
/// top of those its file asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    /// The one-interface diagram's rays drawn by their share of the light.
    Intensities,
    /// The one-interface diagram's wavefronts.
    Wavefronts,
    /// The wavefronts move.
    Moving,
    /// Huygens's construction over the wavefronts.
    Huygens,
    /// A scene's partial reflection at every hit.
    PartialReflection,
    /// A scene's Fresnel intensities.
    Fresnel,
    /// A scene's white light split by wavelength.
    Dispersion,
    /// A scene's absorbing media.
    Absorption,
}

impl Effect {
    /// Every effect, in the order a deck file lists them.
    pub const ALL: [Self; 8] = [
        Self::Intensities,
        Self::Wavefronts,
        Self::Moving,
        Self::Huygens,
        Self::PartialReflection,
        Self::Fresnel,
        Self::Dispersion,
        Self::Absorption,
    ];
}

/// One step: a title, the state shown, the teacher's notes and, optionally, a question for the
/// class. A step with a question opens with its answer hidden ([`Step::hides_answer`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// What the class reads above the diagram.
    pub title: String,
    /// The teacher's notes (any number of lines; may be empty).
    pub notes: String,
    /// The question asked before the answer is shown; `None` for a step that shows all.
    pub question: Option<String>,
    /// The single-interface problem.
    pub state: ExplorerState,
    /// The view shown.
    pub view: StepView,
    /// The scene of the Scenes view: a built-in scene's name or a scene file's path (relative
    /// to the deck file's folder); `None` for the default scene.
    pub scene: Option<String>,
    /// The tool open beside the diagram.
    pub tool: Option<StepTool>,
    /// The effects turned on, each once, in [`Effect::ALL`]'s order.
    pub effects: Vec<Effect>,
    /// The light *Intensities* draws for.
    pub light: Polarisation,
}

impl Step {
    /// A step titled `title` showing `state` on the one-interface view, with nothing else.
    #[must_use]
    pub fn new(title: impl Into<String>, state: ExplorerState) -> Self {
        Self {
            title: title.into(),
            notes: String::new(),
            question: None,
            state,
            view: StepView::One,
            scene: None,
            tool: None,
            effects: Vec::new(),
            light: Polarisation::default(),
        }
    }

    /// The step with these notes.
    #[must_use]
    pub fn notes(self, notes: impl Into<String>) -> Self {
        Self {
            notes: notes.into(),
            ..self
        }
    }

    /// The step asking `question` before its answer is shown.
    #[must_use]
    pub fn question(self, question: impl Into<String>) -> Self {
        Self {
            question: Some(question.into()),
            ..self
        }
    }

    /// The step on the Scenes view, showing the scene `scene` (a built-in name or a path).
    #[must_use]
    pub fn scene(self, scene: &str) -> Self {
        Self {
            view: StepView::Scenes,
            scene: Some(scene.to_owned()),
            ..self
        }
    }

    /// The step with `tool` open.
    #[must_use]
    pub fn tool(self, tool: StepTool) -> Self {
        Self {
            tool: Some(tool),
            ..self
        }
    }

    /// The step with `effects` turned on (kept in [`Effect::ALL`]'s order, each once).
    #[must_use]
    pub fn effects(self, effects: &[Effect]) -> Self {
        let effects = Effect::ALL
            .into_iter()
            .filter(|e| effects.contains(e))
            .collect();
        Self { effects, ..self }
    }

    /// The step drawing the intensities for `light`.
    #[must_use]
    pub fn light(self, light: Polarisation) -> Self {
        Self { light, ..self }
    }

    /// Whether the step opens with its answer hidden: it asks a question.
    #[must_use]
    pub fn hides_answer(&self) -> bool {
        self.question.is_some()
    }

    /// Whether `effect` is on.
    #[must_use]
    pub fn has(&self, effect: Effect) -> bool {
        self.effects.contains(&effect)
    }

    /// The scene the Scenes view shows: the step's, or the default one.
    #[must_use]
    pub fn scene_name(&self) -> &str {
        self.scene.as_deref().unwrap_or(DEFAULT_SCENE)
    }

    /// `effects` (a scene's own) with the scene effects the step turns on added.
    #[must_use]
    pub fn scene_effects(&self, effects: Effects) -> Effects {
        Effects {
            partial_reflection: effects.partial_reflection || self.has(Effect::PartialReflection),
            fresnel: effects.fresnel || self.has(Effect::Fresnel),
            dispersion: effects.dispersion || self.has(Effect::Dispersion),
            absorption: effects.absorption || self.has(Effect::Absorption),
            ..effects
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn effects_are_kept_once_in_order_and_a_scenes_own_stay_on() {
        let step = Step::new("t", ExplorerState::default()).effects(&[
            Effect::Fresnel,
            Effect::Intensities,
            Effect::Fresnel,
        ]);
        assert_eq!(step.effects, [Effect::Intensities, Effect::Fresnel]);
        let own = Effects {
            dispersion: true,
            ..Effects::default()
        };
        let traced = step.scene_effects(own);
        assert!(traced.fresnel && traced.dispersion && !traced.partial_reflection);
        assert_eq!(step.scene_name(), DEFAULT_SCENE);
        assert!(!step.hides_answer());
        assert!(step.question("why?").hides_answer());
    }
}

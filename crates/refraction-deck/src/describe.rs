//! The whole window in words, for a student who cannot see it: the lesson step shown (its
//! number, title and question), the view, and the diagram or scene as a sighted student sees
//! it ([`refraction_model::describe`]), with the step's answer kept out until it is revealed.
//!
//! A pure function of the state, the view, the step and what the step hides, in the current
//! language; the desktop's accessibility tree and the page's canvas and live region both say
//! it. The teacher's notes are never said: they hold the answer.
//!
//! ```
//! use refraction_deck::Deck;
//! use refraction_deck::describe::{Shown, StepShown, page};
//! use refraction_model::describe::Disclosure;
//! let deck = Deck::load("snell")?;
//! let step = &deck.steps[0];
//! let at = StepShown { step, number: 1, count: deck.steps.len() };
//! let said = page(&step.state, Shown::Interface, Some(at), Disclosure::Hidden).join(" ");
//! assert!(said.starts_with("Step 1 of 5: From air into glass."));
//! assert!(said.contains("Does it bend toward the normal or away from it?"));
//! assert!(!said.contains("bends toward"), "the answer stays hidden: {said}");
//! # Ok::<(), refraction_scene::LoadError>(())
//! ```

use refraction_i18n::t;
use refraction_model::ExplorerState;
use refraction_model::describe::{self, Disclosure};

use crate::Step;

/// What the window's view shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shown<'a> {
    /// One interface: W, N and the indices of the state.
    Interface,
    /// A traced scene.
    Scene {
        /// Its title, in the current language.
        title: &'a str,
        /// What it shows, in the current language (its description, which may state the
        /// answer: said only once the answer is shown).
        about: &'a str,
    },
    /// A view with neither (the accuracy plot), named as the bar names it.
    Other {
        /// The view's name.
        name: &'a str,
    },
}

/// A deck's step as it is shown: the step, its position counted from 1 and the deck's number
/// of steps.
#[derive(Clone, Copy, Debug)]
pub struct StepShown<'a> {
    /// The step.
    pub step: &'a Step,
    /// Its position in the deck, from 1.
    pub number: usize,
    /// How many steps the deck has.
    pub count: usize,
}

/// The step's title, or its number when it has none.
fn title(step: &StepShown<'_>) -> String {
    if step.step.title.trim().is_empty() {
        t!("deck-untitled", number = step.number.to_string())
    } else {
        step.step.title.trim().to_owned()
    }
}

/// What a sighted student sees, as sentences in the current language: the step shown (its
/// number of the deck's, its title and its question), then the view: the interface `state`
/// ([`describe::interface`]), or the scene's title and, with the answer shown, what it
/// shows (hidden, only that its rays stop at the first surface), or the other view's name.
/// With `answer` hidden nothing the step's question asks is said.
#[must_use]
pub fn page(
    state: &ExplorerState,
    shown: Shown<'_>,
    step: Option<StepShown<'_>>,
    answer: Disclosure,
) -> Vec<String> {
    let mut said = Vec::new();
    if let Some(step) = step {
        said.push(t!(
            "access-step",
            number = step.number.to_string(),
            count = step.count.to_string(),
            title = title(&step)
        ));
        if let Some(question) = step.step.question.as_deref().map(str::trim) {
            said.push(t!("access-question", question = question));
        }
    }
    match shown {
        Shown::Interface => said.extend(describe::interface(state, answer)),
        Shown::Scene { title, about } => {
            said.push(t!("access-view", view = t!("view-scenes")));
            said.push(t!("access-scene", title = title));
            said.push(match answer {
                Disclosure::Shown => about.to_owned(),
                Disclosure::Hidden => t!("access-scene-hidden"),
            });
        }
        Shown::Other { name } => said.push(t!("access-view", view = name)),
    }
    said
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{StepView, builtin};
    use refraction_i18n::{Locale, set_locale};
    use refraction_scene::Scene;

    /// The step's view as the window shows it, with the scene's words from its file.
    fn seen(step: &Step) -> (String, String) {
        let scene = Scene::embedded(step.scene_name()).expect("a built-in scene");
        (scene.title().to_owned(), scene.description().to_owned())
    }

    /// `step` said with its answer hidden and shown, each sentence on its own.
    fn said(step: &Step, number: usize, count: usize) -> [Vec<String>; 2] {
        let (title, about) = seen(step);
        let shown = match step.view {
            StepView::One => Shown::Interface,
            StepView::Scenes => Shown::Scene {
                title: &title,
                about: &about,
            },
        };
        let at = StepShown {
            step,
            number,
            count,
        };
        [Disclosure::Hidden, Disclosure::Shown]
            .map(|answer| page(&step.state, shown, Some(at), answer))
    }

    #[test]
    fn every_step_of_every_deck_is_said_and_a_hidden_answer_never_leaks() {
        for locale in Locale::ALL {
            set_locale(locale);
            for name in builtin::names() {
                let deck = builtin::deck(name).expect("a built-in deck");
                let count = deck.steps.len();
                for (index, step) in deck.steps.iter().enumerate() {
                    let [hidden, shown] = said(step, index + 1, count);
                    let whole = format!("{locale} {name} {}: {hidden:?}", index + 1);
                    assert!(hidden[0].contains(step.title.trim()), "{whole}");
                    if let Some(question) = &step.question {
                        assert!(hidden[1].contains(question.trim()), "{whole}");
                    }
                    let notes = step.notes.trim();
                    for sentence in hidden.iter().chain(&shown) {
                        assert!(!sentence.contains(notes), "the notes in {whole}");
                    }
                    if !step.hides_answer() {
                        continue;
                    }
                    // What the answer adds is never said while it is hidden, nor any of
                    // its numbers (the question may name the critical angle itself).
                    let answers: Vec<&String> =
                        shown.iter().filter(|s| !hidden.contains(s)).collect();
                    assert!(!answers.is_empty(), "{whole}");
                    let asked: Vec<&String> = hidden.iter().skip(2).collect();
                    for answer in &answers {
                        assert!(!asked.contains(answer), "{answer} in {whole}");
                    }
                    let mut numbers = Vec::new();
                    if let Some(t) = step.state.refraction().transmission {
                        numbers.push(describe::degrees(t.cos_t.acos().to_degrees()));
                    }
                    if let Some(critical) = step.state.critical_angle() {
                        numbers.push(describe::degrees(critical.to_degrees()));
                    }
                    let theta_i = describe::degrees(step.state.incidence_degrees());
                    for number in numbers.iter().filter(|n| **n != theta_i) {
                        let number = t!("access-degrees", angle = number.as_str());
                        for sentence in &asked {
                            assert!(!sentence.contains(&number), "{number} in {whole}");
                        }
                    }
                }
            }
        }
        set_locale(Locale::En);
    }

    #[test]
    fn a_scene_step_names_its_scene_and_says_what_it_shows_once_revealed() {
        let deck = builtin::deck("total-internal-reflection").expect("the deck");
        let fibre = &deck.steps[4];
        let [hidden, shown] = said(fibre, 5, deck.steps.len());
        assert_eq!(
            hidden,
            [
                "Step 5 of 6: The fibre.",
                "Question: The light enters the end of the fibre. Does it escape through the side?",
                "View: Scenes.",
                "Scene: Optical fibre.",
                "Its rays are drawn up to the first surface they meet.",
            ]
        );
        assert!(shown[4].contains("total internal reflection"), "{shown:?}");
        let accuracy = page(
            &fibre.state,
            Shown::Other {
                name: "Accuracy vs time",
            },
            None,
            Disclosure::Shown,
        );
        assert_eq!(accuracy, ["View: Accuracy vs time."]);
    }
}

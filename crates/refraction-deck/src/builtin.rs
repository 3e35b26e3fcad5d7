//! The decks built into the explorer, in the current language: Snell's law in ten minutes,
//! total internal reflection and the fibre, Fresnel and Brewster, and the sign conventions a
//! ray tracer must get right. Their states are the model's lessons and the built-in scenes.

use glam::DVec3;

use refraction_i18n::t;
use refraction_kernel::Convention;
use refraction_model::{ExplorerState, Lesson, MATERIALS};

use super::Deck;
use super::step::{Effect, Step, StepTool};
use refraction_model::Polarisation;

/// The indices of air, water and glass, as the lessons use them.
const AIR: f64 = MATERIALS[1].index;
const WATER: f64 = MATERIALS[2].index;
const GLASS: f64 = MATERIALS[3].index;

/// A built-in deck as `lessons` lists it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeckInfo {
    /// What `--lesson` takes.
    pub name: &'static str,
    /// Its title, in the current language.
    pub title: String,
    /// How many steps it has.
    pub steps: usize,
}

/// How a built-in deck is built, in the current language.
type Build = fn() -> Deck;

/// The built-in decks: name and how to build each.
const DECKS: [(&str, Build); 4] = [
    ("snell", snell),
    ("total-internal-reflection", total_internal_reflection),
    ("fresnel-brewster", fresnel_brewster),
    ("sign-conventions", sign_conventions),
];

/// The built-in decks' names, in the order `lessons` lists them.
#[must_use]
pub fn names() -> Vec<&'static str> {
    DECKS.iter().map(|(name, _)| *name).collect()
}

/// The built-in deck `name`, in the current language.
#[must_use]
pub fn deck(name: &str) -> Option<Deck> {
    DECKS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, make)| make())
}

/// Every built-in deck's name, title and number of steps.
#[must_use]
pub fn catalogue() -> Vec<DeckInfo> {
    DECKS
        .iter()
        .map(|(name, make)| {
            let deck = make();
            DeckInfo {
                name,
                title: deck.title,
                steps: deck.steps.len(),
            }
        })
        .collect()
}

/// A ray travelling `degrees` from the normal (down and to the right) from `mu_i` into
/// `mu_t` with the normal `n`, W written in `convention`.
fn ray(degrees: f64, mu_i: f64, mu_t: f64, n: DVec3, convention: Convention) -> ExplorerState {
    let angle = degrees.to_radians();
    let travel = DVec3::new(angle.sin(), -angle.cos(), 0.0);
    let w = match convention {
        Convention::AlongRay => travel,
        Convention::TowardOrigin => -travel,
    };
    ExplorerState::new(w, n, mu_i, mu_t, convention)
        // untranslated: a panic message for developers, never shown to a user.
        .unwrap_or_else(|_| unreachable!("every built-in step's incidence is valid (tested)"))
}

/// [`ray`] with the normal up, in Section 2's convention.
fn at(degrees: f64, mu_i: f64, mu_t: f64) -> ExplorerState {
    ray(degrees, mu_i, mu_t, DVec3::Y, Convention::AlongRay)
}

fn titled(title: String, steps: Vec<Step>) -> Deck {
    Deck {
        title,
        steps,
        folder: None,
    }
}

fn snell() -> Deck {
    titled(
        t!("deck-snell-title"),
        vec![
            Step::new(t!("deck-snell-1-title"), Lesson::AirToGlass.state())
                .question(t!("deck-snell-1-question"))
                .notes(t!("deck-snell-1-notes")),
            Step::new(t!("deck-snell-2-title"), Lesson::NormalIncidence.state())
                .question(t!("deck-snell-2-question"))
                .notes(t!("deck-snell-2-notes")),
            Step::new(t!("deck-snell-3-title"), Lesson::AirToGlass.state())
                .tool(StepTool::WalkThrough)
                .notes(t!("deck-snell-3-notes")),
            Step::new(t!("deck-snell-4-title"), at(30.0, GLASS, AIR))
                .question(t!("deck-snell-4-question"))
                .notes(t!("deck-snell-4-notes")),
            Step::new(t!("deck-snell-5-title"), Lesson::AirToGlass.state())
                .scene("slab")
                .question(t!("deck-snell-5-question"))
                .notes(t!("deck-snell-5-notes")),
        ],
    )
}

fn total_internal_reflection() -> Deck {
    titled(
        t!("deck-tir-title"),
        vec![
            Step::new(t!("deck-tir-1-title"), at(30.0, GLASS, AIR))
                .effects(&[Effect::Intensities])
                .question(t!("deck-tir-1-question"))
                .notes(t!("deck-tir-1-notes")),
            Step::new(t!("deck-tir-2-title"), at(41.0, GLASS, AIR))
                .question(t!("deck-tir-2-question"))
                .notes(t!("deck-tir-2-notes")),
            Step::new(t!("deck-tir-3-title"), Lesson::BeyondCritical.state())
                .question(t!("deck-tir-3-question"))
                .notes(t!("deck-tir-3-notes")),
            Step::new(t!("deck-tir-4-title"), at(50.0, WATER, AIR))
                .question(t!("deck-tir-4-question"))
                .notes(t!("deck-tir-4-notes")),
            Step::new(t!("deck-tir-5-title"), Lesson::BeyondCritical.state())
                .scene("fibre")
                .question(t!("deck-tir-5-question"))
                .notes(t!("deck-tir-5-notes")),
            Step::new(t!("deck-tir-6-title"), Lesson::BeyondCritical.state())
                .scene("right-angle-prism")
                .question(t!("deck-tir-6-question"))
                .notes(t!("deck-tir-6-notes")),
        ],
    )
}

fn fresnel_brewster() -> Deck {
    let intensities = [Effect::Intensities];
    titled(
        t!("deck-fresnel-title"),
        vec![
            Step::new(t!("deck-fresnel-1-title"), Lesson::AirToGlass.state())
                .tool(StepTool::Fresnel)
                .effects(&intensities)
                .question(t!("deck-fresnel-1-question"))
                .notes(t!("deck-fresnel-1-notes")),
            Step::new(t!("deck-fresnel-2-title"), at(80.0, AIR, GLASS))
                .tool(StepTool::Fresnel)
                .effects(&intensities)
                .question(t!("deck-fresnel-2-question"))
                .notes(t!("deck-fresnel-2-notes")),
            Step::new(t!("deck-fresnel-3-title"), Lesson::Brewster.state())
                .tool(StepTool::Fresnel)
                .effects(&intensities)
                .light(Polarisation::P)
                .question(t!("deck-fresnel-3-question"))
                .notes(t!("deck-fresnel-3-notes")),
            Step::new(t!("deck-fresnel-4-title"), Lesson::Brewster.state())
                .tool(StepTool::Fresnel)
                .effects(&intensities)
                .light(Polarisation::S)
                .notes(t!("deck-fresnel-4-notes")),
            Step::new(t!("deck-fresnel-5-title"), Lesson::AirToGlass.state())
                .scene("slab")
                .effects(&[Effect::PartialReflection, Effect::Fresnel])
                .question(t!("deck-fresnel-5-question"))
                .notes(t!("deck-fresnel-5-notes")),
        ],
    )
}

fn sign_conventions() -> Deck {
    let toward_origin = ray(40.0, AIR, GLASS, DVec3::Y, Convention::TowardOrigin);
    titled(
        t!("deck-signs-title"),
        vec![
            Step::new(t!("deck-signs-1-title"), Lesson::AirToGlass.state())
                .tool(StepTool::WalkThrough)
                .question(t!("deck-signs-1-question"))
                .notes(t!("deck-signs-1-notes")),
            Step::new(t!("deck-signs-2-title"), Lesson::DropletExit.state())
                .question(t!("deck-signs-2-question"))
                .notes(t!("deck-signs-2-notes")),
            Step::new(t!("deck-signs-3-title"), toward_origin)
                .question(t!("deck-signs-3-question"))
                .notes(t!("deck-signs-3-notes")),
            Step::new(t!("deck-signs-4-title"), Lesson::AirToGlass.state())
                .notes(t!("deck-signs-4-notes")),
            Step::new(t!("deck-signs-5-title"), Lesson::DropletExit.state())
                .tool(StepTool::Check)
                .question(t!("deck-signs-5-question"))
                .notes(t!("deck-signs-5-notes")),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_deck_has_four_steps_or_more_and_asks_questions() {
        for info in catalogue() {
            assert!(info.steps >= 4, "{}: {} steps", info.name, info.steps);
            let deck = super::deck(info.name).unwrap();
            assert!(deck.steps.iter().any(Step::hides_answer), "{}", info.name);
            assert!(
                deck.steps.iter().all(|s| !s.notes.is_empty()),
                "{}",
                info.name
            );
        }
        assert!(super::deck("no-such-deck").is_none());
    }

    #[test]
    fn the_critical_angle_steps_sit_either_side_of_it() {
        let deck = total_internal_reflection();
        assert!(
            !deck.steps[1].state.refraction().is_tir(),
            "41° is short of 41.8°"
        );
        assert!(deck.steps[2].state.refraction().is_tir());
        assert!(
            deck.steps[3].state.refraction().is_tir(),
            "50° is past water's 48.6°"
        );
        let signs = sign_conventions();
        assert_eq!(signs.steps[2].state.convention(), Convention::TowardOrigin);
        let t = |s: &Step| s.state.refraction().transmission.map(|t| t.t).unwrap();
        let apart = t(&signs.steps[2]).distance(t(&signs.steps[3]));
        assert!(apart < 1e-12, "the same ray in either section: {apart}");
    }
}

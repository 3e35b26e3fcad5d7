//! The explorer in words, for a student who cannot see the diagram: what a sighted student sees
//! of one interface, said as sentences (the desktop's accessibility tree and the page's live
//! region both say them), the values of the four controls that set it (θi, N's direction, μi
//! and μt) and what an edit changed.
//!
//! Every function here is a pure function of the state, in the current language
//! ([`refraction_i18n::locale`]), and says nothing a hidden answer would give away: while a
//! lesson step hides its answer ([`Disclosure::Hidden`]) the sentences keep to what the diagram
//! shows then (the media, W, N and θi), never T, its angle, the bend, the reflected ray, total
//! internal reflection, the critical angle or the convention's sign of a.
//!
//! ```
//! use refraction_model::ExplorerState;
//! use refraction_model::describe::{self, Disclosure};
//! let state = ExplorerState::default(); // 40° from air into glass
//! let said = describe::interface(&state, Disclosure::Shown).join(" ");
//! assert!(said.contains("bends toward the normal, 25.4° from it"));
//! let hidden = describe::interface(&state, Disclosure::Hidden).join(" ");
//! assert!(!hidden.contains("25.4"));
//! ```

use refraction_i18n::t;
use refraction_kernel::Convention;

use crate::state::{ExplorerState, HandleId, material_of};

/// Whether the answer of the lesson step shown may be said.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Disclosure {
    /// No question is open, or its answer was revealed: everything the diagram shows is said.
    Shown,
    /// A question waits for the class's prediction: T and what gives it away are not said.
    Hidden,
}

impl Disclosure {
    /// [`Disclosure::Hidden`] when `hidden`, else [`Disclosure::Shown`].
    #[must_use]
    pub fn hidden_if(hidden: bool) -> Self {
        if hidden { Self::Hidden } else { Self::Shown }
    }
}

/// Angles closer than this (in degrees) are said as equal: what a tenth of a degree, the
/// precision said, cannot tell apart.
const SAME_DEGREES: f64 = 0.05;

/// `degrees` to a tenth of a degree, in the language's way, without a trailing `.0`: `41`,
/// `41.8`, `41,8`.
#[must_use]
pub fn degrees(degrees: f64) -> String {
    let tenths = (degrees * 10.0).round() / 10.0;
    // −0.0 is said as 0.
    let tenths = if tenths == 0.0 { 0.0 } else { tenths };
    let text = if tenths.fract() == 0.0 {
        format!("{tenths:.0}")
    } else {
        format!("{tenths:.1}")
    };
    refraction_i18n::decimal(&text)
}

/// An index as the controls show it: to six decimals at most, without trailing zeros, in the
/// language's way (`1.000293`, `1,5`).
#[must_use]
pub fn index(index: f64) -> String {
    let rounded = (index * 1e6).round() / 1e6;
    refraction_i18n::decimal(&rounded.to_string())
}

/// The value of the θi control: `40°`, `41.8°`.
#[must_use]
pub fn incidence_value(state: &ExplorerState) -> String {
    t!("access-degrees", angle = degrees(state.incidence_degrees()))
}

/// The value of the N control in words: `straight up`, `20° right of straight up`.
#[must_use]
pub fn normal_value(state: &ExplorerState) -> String {
    let tilt = state.normal_tilt_degrees();
    if tilt.abs() < SAME_DEGREES {
        t!("access-normal-up")
    } else if tilt.abs() > 180.0 - SAME_DEGREES {
        t!("access-normal-down")
    } else if tilt > 0.0 {
        t!("access-normal-right", angle = degrees(tilt))
    } else {
        t!("access-normal-left", angle = degrees(-tilt))
    }
}

/// The value of a μ control: the index, with the preset's name when it is one's (`1,5 (Glas)`).
#[must_use]
pub fn index_value(value: f64) -> String {
    match material_of(value) {
        Some(material) => t!(
            "access-index-named",
            index = index(value),
            name = material.label()
        ),
        None => index(value),
    }
}

/// The value of one of the four controls in words (whose names are [`HandleId::label`]'s: θi
/// for W, the direction of N, the two indices).
#[must_use]
pub fn control_value(state: &ExplorerState, handle: HandleId) -> String {
    match handle {
        HandleId::W => incidence_value(state),
        HandleId::N => normal_value(state),
        HandleId::MuI | HandleId::MuT => index_value(state.index(handle)),
    }
}

/// A medium with its index: `air, μi = 1.000293` or `a medium with μt = 1.42`.
fn medium(symbol: &str, value: f64) -> String {
    match material_of(value) {
        Some(material) => t!(
            "access-medium-named",
            name = material.label(),
            symbol = symbol,
            index = index(value)
        ),
        None => t!(
            "access-medium-custom",
            symbol = symbol,
            index = index(value)
        ),
    }
}

/// θt in degrees, if there is a refracted ray.
fn refraction_degrees(state: &ExplorerState) -> Option<f64> {
    let transmission = state.refraction().transmission?;
    Some(transmission.cos_t.clamp(-1.0, 1.0).acos().to_degrees())
}

/// The critical angle in degrees, if the ray travels into the less dense medium.
fn critical_degrees(state: &ExplorerState) -> Option<f64> {
    state.critical_angle().map(f64::to_degrees)
}

/// Where T goes: bent toward or away from the normal (and how far from it), straight on, or
/// nowhere (total internal reflection, with the critical angle).
fn outcome(state: &ExplorerState) -> String {
    let theta_i = state.incidence_degrees();
    let Some(theta_t) = refraction_degrees(state) else {
        let critical = critical_degrees(state).unwrap_or(90.0);
        return t!("access-tir", critical = degrees(critical));
    };
    let angle = degrees(theta_t);
    if theta_i < SAME_DEGREES {
        t!("access-t-along-normal")
    } else if (theta_t - theta_i).abs() < SAME_DEGREES {
        t!("access-t-straight", angle = angle)
    } else if theta_t < theta_i {
        t!("access-t-toward", angle = angle)
    } else {
        t!("access-t-away", angle = angle)
    }
}

/// The banner's first line as a sentence: the section and its sign of a.
fn section(state: &ExplorerState) -> String {
    let convention = state.convention();
    let words = match convention {
        Convention::TowardOrigin => t!("diagram-banner-toward-origin"),
        Convention::AlongRay => t!("diagram-banner-along-ray"),
    };
    let title = t!(
        "diagram-banner-section",
        section = convention.section().to_string(),
        words = words
    );
    t!("access-sentence", text = title)
}

/// What a sighted student sees of the interface `state`, as sentences in the current
/// language: the media and their indices, θi from the normal and where N points; with the
/// answer shown, also where T goes and at what angle (or total internal reflection and the
/// critical angle), the reflected ray, the critical angle where there is one, a flipped
/// normal, and the section's convention.
#[must_use]
pub fn interface(state: &ExplorerState, answer: Disclosure) -> Vec<String> {
    let theta_i = state.incidence_degrees();
    let mut said = vec![
        t!(
            "access-media",
            from = medium("μi", state.mu_i()),
            to = medium("μt", state.mu_t())
        ),
        if theta_i < SAME_DEGREES {
            t!("access-incidence-along-normal")
        } else {
            t!("access-incidence-sentence", angle = degrees(theta_i))
        },
        t!("access-normal-sentence", direction = normal_value(state)),
    ];
    if answer == Disclosure::Hidden {
        said.push(t!("deck-answer-hidden"));
        return said;
    }
    said.push(outcome(state));
    let r = state.refraction();
    if !r.is_tir() && theta_i >= SAME_DEGREES {
        said.push(t!("access-reflected", angle = degrees(theta_i)));
    }
    if let Some(critical) = critical_degrees(state).filter(|_| !r.is_tir()) {
        said.push(t!("access-critical", critical = degrees(critical)));
    }
    if r.normal_flipped {
        said.push(t!("access-flipped"));
    }
    said.push(section(state));
    said
}

/// One control's change, `θi 41° → 43°`, if its words changed.
fn changed(symbol: &str, before: String, after: String) -> Option<String> {
    (before != after).then(|| {
        t!(
            "access-change-value",
            name = symbol,
            before = before,
            after = after
        )
    })
}

/// What the answer became with the change from `before` to `after`: total internal
/// reflection begun or ended (said once each), or T's new angle; nothing while it goes on.
fn consequence(before: &ExplorerState, after: &ExplorerState) -> Option<String> {
    let critical = || degrees(critical_degrees(after).unwrap_or(90.0));
    match (refraction_degrees(before), refraction_degrees(after)) {
        (Some(_), None) => Some(t!("access-change-tir-begins", critical = critical())),
        (None, Some(theta_t)) => Some(t!(
            "access-change-tir-ends",
            critical = critical(),
            angle = degrees(theta_t)
        )),
        (Some(was), Some(theta_t)) if degrees(was) != degrees(theta_t) => {
            Some(t!("access-change-t", angle = degrees(theta_t)))
        }
        _ => None,
    }
}

/// What changed from `before` to `after`, as one sentence (`θi 41° → 43°: now past the
/// critical angle 41.8°; all light is reflected.`), or `None` when nothing a student sees in
/// words changed. Each control whose value changed is named with its old and new value; with
/// the answer shown, the sentence goes on with what became of T: total internal reflection
/// is said when it begins and when it ends, not at every step in between.
#[must_use]
pub fn change(before: &ExplorerState, after: &ExplorerState, answer: Disclosure) -> Option<String> {
    let mut parts: Vec<String> = [
        changed("θi", incidence_value(before), incidence_value(after)),
        changed("N", normal_value(before), normal_value(after)),
        changed("μi", index(before.mu_i()), index(after.mu_i())),
        changed("μt", index(before.mu_t()), index(after.mu_t())),
    ]
    .into_iter()
    .flatten()
    .collect();
    if answer == Disclosure::Shown && before.convention() != after.convention() {
        parts.push(section(after).trim_end_matches('.').to_owned());
    }
    if parts.is_empty() {
        return None;
    }
    // untranslated: a list separator between the changed values, the same in every language.
    let changes = parts.join(", ");
    let outcome = (answer == Disclosure::Shown)
        .then(|| consequence(before, after))
        .flatten();
    Some(match outcome {
        Some(outcome) => t!("access-change", changes = changes, outcome = outcome),
        None => t!("access-sentence", text = changes),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Lesson;
    use refraction_i18n::{Locale, set_locale};

    /// Every sentence of `state` with the answer shown and hidden, in `locale`.
    fn both(state: &ExplorerState, locale: Locale) -> (String, String) {
        set_locale(locale);
        let shown = interface(state, Disclosure::Shown).join(" ");
        let hidden = interface(state, Disclosure::Hidden).join(" ");
        set_locale(Locale::En);
        (shown, hidden)
    }

    #[test]
    fn numbers_are_said_to_a_tenth_of_a_degree_and_as_the_controls_show_indices() {
        assert_eq!(degrees(41.0), "41");
        assert_eq!(degrees(41.81), "41.8");
        assert_eq!(degrees(-0.01), "0");
        assert_eq!(degrees(89.96), "90");
        assert_eq!(index(1.000293), "1.000293");
        assert_eq!(index(1.49 + 1e-12), "1.49");
        set_locale(Locale::De);
        assert_eq!(degrees(41.81), "41,8");
        assert_eq!(index_value(1.5), "1,5 (Glas)");
        set_locale(Locale::En);
        assert_eq!(index_value(1.42), "1.42");
    }

    #[test]
    fn every_lesson_is_said_as_a_sighted_student_sees_it() {
        let said: Vec<String> = Lesson::ALL
            .iter()
            .map(|l| interface(&l.state(), Disclosure::Shown).join(" "))
            .collect();
        let [glass, beyond, normal, brewster, droplet] = &said[..] else {
            unreachable!("five lessons")
        };
        assert!(
            glass.starts_with("The ray travels in air (μi = 1.000293) and meets glass (μt = 1.5)."),
            "{glass}"
        );
        assert!(glass.contains("θi = 40° from the normal"), "{glass}");
        assert!(
            glass.contains("T bends toward the normal, 25.4° from it."),
            "{glass}"
        );
        assert!(
            glass.contains("The normal N points straight up."),
            "{glass}"
        );
        assert!(glass.contains("Section 2"), "{glass}");
        assert!(beyond.contains("Total internal reflection"), "{beyond}");
        assert!(beyond.contains("critical angle θc = 41.8°"), "{beyond}");
        assert!(!beyond.contains("T bends"), "{beyond}");
        assert!(normal.contains("along the normal"), "{normal}");
        assert!(normal.contains("does not bend"), "{normal}");
        assert!(brewster.contains("56.3°"), "{brewster}");
        assert!(
            droplet.contains("bends away from the normal, 58.9° from it"),
            "{droplet}"
        );
        assert!(
            droplet.contains("critical angle is θc = 48.6°"),
            "{droplet}"
        );
        assert!(droplet.contains("−N"), "{droplet}");
        assert!(droplet.contains("straight down"), "{droplet}");
    }

    #[test]
    fn a_hidden_answer_is_never_said_in_any_language() {
        for locale in Locale::ALL {
            for lesson in Lesson::ALL {
                let state = lesson.state();
                let (shown, hidden) = both(&state, locale);
                set_locale(locale);
                // What only the answer says: T's angle and bend, total internal reflection,
                // the critical angle, the flipped normal, the section's sign of a.
                let mut answers = vec![section(&state), outcome(&state)];
                if let Some(critical) = critical_degrees(&state) {
                    answers.push(degrees(critical));
                }
                if let Some(theta_t) = refraction_degrees(&state).filter(|t| *t > 0.05) {
                    answers.push(degrees(theta_t));
                }
                if state.refraction().normal_flipped {
                    answers.push(t!("access-flipped"));
                }
                set_locale(Locale::En);
                for answer in answers {
                    assert!(
                        shown.contains(&answer),
                        "{locale} {lesson:?}: {answer} in {shown}"
                    );
                    assert!(
                        !hidden.contains(&answer),
                        "{locale} {lesson:?}: {answer} in {hidden}"
                    );
                }
                assert!(hidden.len() < shown.len());
            }
        }
    }

    #[test]
    fn the_controls_say_the_angle_of_incidence_and_where_n_leans() {
        let mut state = ExplorerState::default();
        assert_eq!(incidence_value(&state), "40°");
        assert_eq!(normal_value(&state), "straight up");
        state.rotate(HandleId::N, -20.0);
        assert!((state.normal_tilt_degrees() - 20.0).abs() < 1e-9);
        assert_eq!(normal_value(&state), "20° right of straight up");
        state.rotate(HandleId::N, 45.0);
        assert_eq!(normal_value(&state), "25° left of straight up");
        assert_eq!(control_value(&state, HandleId::MuT), "1.5 (glass)");
        assert_eq!(HandleId::W.label(), "Angle of incidence θi (W)");
        state.set_normal_tilt_degrees(180.0);
        assert_eq!(normal_value(&state), "straight down");
    }

    #[test]
    fn a_change_names_what_moved_and_says_total_internal_reflection_once() {
        let mut before = Lesson::BeyondCritical.state();
        before.set_incidence_degrees(41.0).unwrap();
        let mut after = before.clone();
        after.set_incidence_degrees(43.0).unwrap();
        assert_eq!(
            change(&before, &after, Disclosure::Shown).unwrap(),
            "θi 41° → 43°: now past the critical angle 41.8°; all light is reflected."
        );
        let mut further = after.clone();
        further.set_incidence_degrees(44.0).unwrap();
        assert_eq!(
            change(&after, &further, Disclosure::Shown).unwrap(),
            "θi 43° → 44°."
        );
        let back = change(&further, &before, Disclosure::Shown).unwrap();
        assert!(
            back.starts_with(
                "θi 44° → 41°: now short of the critical angle 41.8°; T leaves at 79."
            ),
            "{back}"
        );
        let mut denser = before.clone();
        denser.set_mu_t(1.1).unwrap();
        let bent = change(&before, &denser, Disclosure::Shown).unwrap();
        assert!(bent.starts_with("μt 1.000293 → 1.1: T at "), "{bent}");
        assert_eq!(
            change(&before, &after, Disclosure::Hidden).unwrap(),
            "θi 41° → 43°."
        );
        assert_eq!(change(&before, &before, Disclosure::Shown), None);
        let mut turned = before.clone();
        turned.set_convention(Convention::TowardOrigin);
        let section = change(&before, &turned, Disclosure::Shown).unwrap();
        assert!(section.starts_with("Section 1"), "{section}");
        assert_eq!(change(&before, &turned, Disclosure::Hidden), None);
    }
}

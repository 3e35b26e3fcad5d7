//! The paper's derivation as a sequence of steps, each with its equations in the paper's
//! numbering, the current numbers substituted, what the step argues in plain words, and the
//! parts of the diagram it is about ([`Focus`]). Every number is the kernel's.

use super::equations::{Equation, chosen_a, equations, n, term};
use super::overlay::Focus;
use refraction_i18n::t;
use refraction_kernel::{Convention, Refraction};

/// One step of the walk-through.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WalkthroughStep {
    /// A short title in the current language, e.g. `The two roots for a`.
    pub title: String,
    /// The paper's equations for this step, with numbers.
    pub equations: Vec<Equation>,
    /// What the step argues, in words a student follows.
    pub explanation: String,
    /// What the diagram highlights.
    pub focus: Focus,
}

/// One step as the paper takes it, before any numbers.
struct Description {
    title: fn() -> String,
    /// The equations the step cites, by their number within the section.
    cites: &'static [u8],
    /// What the step argues: the same words for every case, or words with the case's numbers.
    explanation: fn(&Refraction<f64>) -> String,
    focus: Focus,
}

/// The paper's eight steps, in its order.
const STEPS: [Description; 8] = [
    Description {
        title: || t!("diagram-step-snell"),
        cites: &[4],
        explanation: |_| t!("diagram-step-snell-text"),
        focus: Focus::Angles,
    },
    Description {
        title: || t!("diagram-step-square"),
        cites: &[6],
        explanation: |_| t!("diagram-step-square-text"),
        focus: Focus::Angles,
    },
    Description {
        title: || t!("diagram-step-decomposition"),
        cites: &[7, 8],
        explanation: decomposition,
        focus: Focus::Decomposition,
    },
    Description {
        title: || t!("diagram-step-constraints"),
        cites: &[10, 12],
        explanation: |_| t!("diagram-step-constraints-text"),
        focus: Focus::SquaredConstraints,
    },
    Description {
        title: || t!("diagram-step-roots-a"),
        cites: &[17, 18],
        explanation: |_| t!("diagram-step-roots-a-text"),
        focus: Focus::RootsOfA,
    },
    Description {
        title: || t!("diagram-step-choice-a"),
        cites: &[19],
        explanation: choice_of_a,
        focus: Focus::ChoiceOfA,
    },
    Description {
        title: || t!("diagram-step-roots-b"),
        cites: &[20, 21],
        explanation: |_| t!("diagram-step-roots-b-text"),
        focus: Focus::RootsOfB,
    },
    Description {
        title: || t!("diagram-step-choice-b"),
        cites: &[22],
        explanation: choice_of_b,
        focus: Focus::ChoiceOfB,
    },
];

/// What the paper's two sections write differently in the steps beyond the key equations.
struct Wording {
    /// Eq. 8: cosθi from wn.
    cos_i: &'static str,
    /// The direction of travel in terms of W.
    travel: &'static str,
    /// Eq. 19: the a the section takes.
    a: &'static str,
    /// Eq. 20: eq. 12 with that a.
    quadratic_in_b: &'static str,
    /// What the section's text gets wrong, if anything.
    typo: Option<fn() -> String>,
}

const TOWARD_ORIGIN: Wording = Wording {
    // untranslated: a formula.
    cos_i: "cosθi = wn",
    travel: "−W",
    a: "a = −μ",
    // untranslated: a formula.
    quadratic_in_b: "μ² − 2μ·b·wn + b² = 1",
    typo: None,
};

const ALONG_RAY: Wording = Wording {
    // untranslated: a formula.
    cos_i: "cosθi = −wn",
    travel: "W",
    a: "a = μ",
    // untranslated: a formula.
    quadratic_in_b: "μ² + 2μ·b·wn + b² = 1",
    typo: Some(|| t!("diagram-step-choice-a-typo")),
};

fn wording(convention: Convention) -> &'static Wording {
    match convention {
        Convention::TowardOrigin => &TOWARD_ORIGIN,
        Convention::AlongRay => &ALONG_RAY,
    }
}

/// Every step for the refraction `r`, in the paper's order.
#[must_use]
pub fn walkthrough_steps(r: &Refraction<f64>) -> Vec<WalkthroughStep> {
    let mut all = equations(r);
    all.extend(other_equations(r));
    STEPS
        .iter()
        .map(|step| WalkthroughStep {
            title: (step.title)(),
            equations: step
                .cites
                .iter()
                .filter_map(|&cited| {
                    let number = format!("{}.{cited}", r.convention.section());
                    all.iter().find(|e| e.number == number).cloned()
                })
                .collect(),
            explanation: (step.explanation)(r),
            focus: step.focus,
        })
        .collect()
}

/// An equation of the paper that the key-equation list does not carry.
fn equation(r: &Refraction<f64>, number: u8, formula: &str, values: String) -> Equation {
    Equation {
        number: format!("{}.{number}", r.convention.section()),
        formula: formula.to_owned(),
        substituted: values,
    }
}

/// The equations the steps cite beyond the six key ones: 4, 6, 8, 10, 19 and 20.
fn other_equations(r: &Refraction<f64>) -> [Equation; 6] {
    let wording = wording(r.convention);
    let a = chosen_a(r);
    let wn = r.wn();
    let sin = t!("diagram-math-sin");
    [
        // untranslated: a formula.
        equation(r, 4, &format!("{sin}(θi)·μ = {sin}(θt)"), snell(r)),
        // untranslated: a formula.
        equation(r, 6, "(1 − cos²θi)·μ² = 1 − cos²θt", squared(r)),
        equation(r, 8, wording.cos_i, incidence(r)),
        // untranslated: a formula.
        equation(r, 10, "(1 − wn²)·μ² = 1 − (−a·wn − b)²", squared_snell(r)),
        equation(r, 19, wording.a, format!("a = {}", n(a))),
        equation(
            r,
            20,
            wording.quadratic_in_b,
            format!("b² + {}·b + {} = 0", term(2.0 * a * wn), term(a * a - 1.0)),
        ),
    ]
}

/// Eq. 8 with numbers: wn and cosθi, and where N faced away from the ray, the −N the kernel
/// used instead (so that cosθi = −wn reads true of the numbers shown).
fn incidence(r: &Refraction<f64>) -> String {
    let wn = r.wn();
    if r.n == r.facing_normal {
        // untranslated: a formula with numbers.
        format!("wn = W·N = {}, cosθi = {}", n(wn), n(r.cos_i))
    } else {
        t!(
            "diagram-step-wn-flipped",
            given = n(wn),
            wn = n(-wn),
            cos = n(r.cos_i)
        )
    }
}

/// sinθi, from the kernel's cosθi.
fn sin_i(r: &Refraction<f64>) -> f64 {
    (1.0 - r.cos_i * r.cos_i).max(0.0).sqrt()
}

/// Eq. 4: sinθt from Snell's law, or why there is no θt.
fn snell(r: &Refraction<f64>) -> String {
    let (sin_i, sin) = (sin_i(r), t!("diagram-math-sin"));
    let sin_t = r.mu * sin_i;
    // untranslated: a formula with numbers.
    let given = format!("μ = μi/μt = {}; {sin}θi = {}", n(r.mu), n(sin_i));
    if sin_t > 1.0 {
        t!("diagram-eq-no-theta-t", given = given, sin_t = n(sin_t))
    } else {
        // untranslated: a formula with numbers.
        let then = format!("{sin}θt = {}", n(sin_t));
        t!("diagram-eq-so", given = given, then = then)
    }
}

/// Eq. 6: squared Snell in cosines.
fn squared(r: &Refraction<f64>) -> String {
    let (cos_i, mu) = (r.cos_i, r.mu);
    format!(
        // untranslated: a formula with numbers.
        "(1 − {}²)·{}² = {} = 1 − cos²θt",
        term(cos_i),
        term(mu),
        n((1.0 - cos_i * cos_i) * mu * mu)
    )
}

/// Eq. 10 checked with the kernel's a and b.
fn squared_snell(r: &Refraction<f64>) -> String {
    match r.transmission {
        Some(tr) => {
            let wn = r.wn();
            let lhs = (1.0 - wn * wn) * r.mu * r.mu;
            let rhs = 1.0 - (-tr.a * wn - tr.b).powi(2);
            t!("diagram-eq-with-chosen", lhs = n(lhs), rhs = n(rhs))
        }
        None => t!("diagram-eq-no-ab-with-12"),
    }
}

/// Step 3's words: the direction of travel depends on the convention.
fn decomposition(r: &Refraction<f64>) -> String {
    let travel = wording(r.convention).travel;
    t!("diagram-step-decomposition-text", travel = travel)
}

/// Step 6's words: the limit μ = 1 picks the a that keeps the direction of travel.
fn choice_of_a(r: &Refraction<f64>) -> String {
    let Wording { travel, typo, .. } = wording(r.convention);
    let a = if chosen_a(r) < 0.0 { "−μ" } else { "+μ" };
    let words = t!("diagram-step-choice-a-text", travel = *travel, a = a);
    match typo {
        Some(typo) => format!("{words} {}", typo()),
        None => words,
    }
}

/// Step 8's words: with an outward normal the paper's root is the wrong side.
fn choice_of_b(r: &Refraction<f64>) -> String {
    if r.normal_flipped {
        t!("diagram-step-choice-b-flipped")
    } else {
        t!("diagram-step-choice-b-text")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_i18n::{Locale, set_locale};
    use refraction_model::ExplorerState;

    #[test]
    fn the_steps_follow_the_source_with_live_numbers() {
        let mut state = ExplorerState::default();
        let along = walkthrough_steps(state.refraction());
        assert_eq!(along.len(), 8);
        let numbers: Vec<&str> = along
            .iter()
            .flat_map(|s| s.equations.iter().map(|e| e.number.as_str()))
            .collect();
        assert_eq!(
            numbers,
            [
                "2.4", "2.6", "2.7", "2.8", "2.10", "2.12", "2.17", "2.18", "2.19", "2.20", "2.21",
                "2.22"
            ]
        );
        assert!(
            along[0].equations[0]
                .substituted
                .contains("μ = μi/μt = 0.6669")
        );
        assert!(along[5].explanation.contains("a = +μ"));
        assert!(along[5].explanation.contains("a = −μ solution"));
        state.set_convention(Convention::TowardOrigin);
        let toward = walkthrough_steps(state.refraction());
        assert_eq!(toward[5].equations[0].formula, "a = −μ");
        assert!(toward[5].explanation.contains("direction of travel, −W"));
        state.flip_normal();
        assert!(
            walkthrough_steps(state.refraction())[7]
                .explanation
                .contains("outward normal")
        );
    }

    #[test]
    fn total_internal_reflection_says_there_is_no_theta_t() {
        let mut state = ExplorerState::default();
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.rotate(refraction_model::HandleId::W, 40.0);
        let all = walkthrough_steps(state.refraction());
        assert!(all[0].equations[0].substituted.contains("> 1: no angle θt"));
        assert!(all[3].equations[0].substituted.contains("no real (a, b)"));
    }

    /// The steps of `state` in `locale`; the thread speaks English again after.
    fn steps_in(locale: Locale, state: &ExplorerState) -> Vec<WalkthroughStep> {
        set_locale(locale);
        let all = walkthrough_steps(state.refraction());
        set_locale(Locale::En);
        all
    }

    #[test]
    fn the_sine_and_the_equation_labels_are_written_as_each_languages_schools_write_them() {
        let mut state = ExplorerState::default();
        let english = steps_in(Locale::En, &state);
        assert_eq!(english[0].equations[0].formula, "sin(θi)·μ = sin(θt)");
        assert!(english[0].equations[0].substituted.contains("; sinθi = 0."));
        assert!(english[3].explanation.contains("Squared Snell (eq. 10)"));
        let spanish = steps_in(Locale::Es, &state);
        assert_eq!(spanish[0].equations[0].formula, "sen(θi)·μ = sen(θt)");
        let substituted = &spanish[0].equations[0].substituted;
        assert!(substituted.contains("; senθi = 0,"), "{substituted}");
        assert!(substituted.contains(", así que senθt = "), "{substituted}");
        assert!(spanish[0].explanation.contains("μi·senθi = μt·senθt"));
        assert!(spanish[3].explanation.contains("(ec. 10)"));
        let russian = steps_in(Locale::Ru, &state);
        assert_eq!(russian[0].equations[0].formula, "sin(θi)·μ = sin(θt)");
        assert!(russian[3].explanation.contains("(ур. 10)"));
        assert!(
            russian[4]
                .explanation
                .contains("Подстановка ур. 12 в ур. 10")
        );
        let german = steps_in(Locale::De, &state);
        assert!(german[3].explanation.contains("(Gl. 10)"));
        let french = steps_in(Locale::Fr, &state);
        assert!(french[3].explanation.contains("(éq. 10)"));
        // Past the critical angle the equations' own words cite eq. 12 too.
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.rotate(refraction_model::HandleId::W, 40.0);
        let russian = steps_in(Locale::Ru, &state);
        let substituted = &russian[3].equations[0].substituted;
        assert!(substituted.ends_with("вместе с ур. 12"), "{substituted}");
        let portuguese = steps_in(Locale::PtBr, &state);
        let substituted = &portuguese[0].equations[0].substituted;
        assert!(
            substituted.contains(", então senθt seria "),
            "{substituted}"
        );
        for all in [&english, &spanish, &russian, &portuguese] {
            let words: String = all.iter().map(|s| s.explanation.as_str()).collect();
            assert!(!words.contains("eq.10"), "{words}");
        }
    }
}

//! The source's derivation as a sequence of steps, each with its equations in the source's
//! numbering, the current numbers substituted, what the step argues in plain words, and the
//! parts of the diagram it is about ([`Focus`]). Every number is the kernel's.

use super::equations::{Equation, chosen_a, equations, n};
use super::overlay::Focus;
use refraction_kernel::{Convention, Refraction};

/// One step of the walk-through.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// A short title, e.g. `The two roots for a`.
    pub title: &'static str,
    /// The source's equations for this step, with numbers.
    pub equations: Vec<Equation>,
    /// What the step argues, in words a student follows.
    pub explanation: String,
    /// What the diagram highlights.
    pub focus: Focus,
}

/// What a step argues: the same words for every case, or words with the case's numbers in.
enum Explanation {
    Fixed(&'static str),
    Live(fn(&Refraction<f64>) -> String),
}

/// One step as the source takes it, before any numbers.
struct Description {
    title: &'static str,
    /// The equations the step cites, by their number within the section.
    cites: &'static [u8],
    explanation: Explanation,
    focus: Focus,
}

/// The source's eight steps, in its order.
const STEPS: [Description; 8] = [
    Description {
        title: "Snell's law",
        cites: &[4],
        explanation: Explanation::Fixed(
            "The ray bends so that μi·sinθi = μt·sinθt; with μ = μi/μt, the sine of the angle \
             in the new medium is μ times the old one.",
        ),
        focus: Focus::Angles,
    },
    Description {
        title: "Square it, and use cosines",
        cites: &[6],
        explanation: Explanation::Fixed(
            "Squaring lets the cosines (dot products) replace the sines, but it also lets in \
             false solutions: a solution and its signed opposite both satisfy it.",
        ),
        focus: Focus::Angles,
    },
    Description {
        title: "T as a·W + b·N",
        cites: &[7, 8],
        explanation: Explanation::Live(decomposition),
        focus: Focus::Decomposition,
    },
    Description {
        title: "The two squared constraints",
        cites: &[10, 12],
        explanation: Explanation::Fixed(
            "Squared Snell (eq. 10) and unit length (eq. 12) are two quadratics in a and b. \
             Four pairs (a, b) satisfy both: T and the three ghosts. Nothing in them tells the \
             four apart.",
        ),
        focus: Focus::SquaredConstraints,
    },
    Description {
        title: "The two roots for a",
        cites: &[17, 18],
        explanation: Explanation::Fixed(
            "Substituting eq. 12 into eq. 10 leaves a² = μ²: a = +μ or a = −μ. The other sign \
             mirrors T across the normal: it bends the wrong way.",
        ),
        focus: Focus::RootsOfA,
    },
    Description {
        title: "Choosing a: the limit μ = 1",
        cites: &[19],
        explanation: Explanation::Live(choice_of_a),
        focus: Focus::ChoiceOfA,
    },
    Description {
        title: "The two roots for b",
        cites: &[20, 21],
        explanation: Explanation::Fixed(
            "With a fixed, eq. 12 is a quadratic in b with the roots −a·wn ± √k (k = μ²wn² − μ² \
             + 1). The other root mirrors T across the surface, back into the medium the ray \
             came from. k < 0 means no real root: total internal reflection.",
        ),
        focus: Focus::RootsOfB,
    },
    Description {
        title: "Choosing b",
        cites: &[22],
        explanation: Explanation::Live(choice_of_b),
        focus: Focus::ChoiceOfB,
    },
];

/// What the source's two sections write differently in the steps beyond the key equations.
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
    typo: &'static str,
}

const TOWARD_ORIGIN: Wording = Wording {
    cos_i: "cosθi = wn",
    travel: "−W",
    a: "a = −μ",
    quadratic_in_b: "μ² − 2μ·b·wn + b² = 1",
    typo: "",
};

const ALONG_RAY: Wording = Wording {
    cos_i: "cosθi = −wn",
    travel: "W",
    a: "a = μ",
    quadratic_in_b: "μ² + 2μ·b·wn + b² = 1",
    typo: " (Section 2's text then says \"once we decide upon using the a = −μ solution\": it \
           means a = +μ, the one it chose.)",
};

fn wording(convention: Convention) -> &'static Wording {
    match convention {
        Convention::TowardOrigin => &TOWARD_ORIGIN,
        Convention::AlongRay => &ALONG_RAY,
    }
}

/// Every step for the refraction `r`, in the source's order.
#[must_use]
pub fn steps(r: &Refraction<f64>) -> Vec<Step> {
    let mut all = equations(r);
    all.extend(other_equations(r));
    STEPS
        .iter()
        .map(|step| Step {
            title: step.title,
            equations: step
                .cites
                .iter()
                .filter_map(|&cited| {
                    let number = format!("{}.{cited}", r.convention.section());
                    all.iter().find(|e| e.number == number).cloned()
                })
                .collect(),
            explanation: match step.explanation {
                Explanation::Fixed(text) => text.to_owned(),
                Explanation::Live(text) => text(r),
            },
            focus: step.focus,
        })
        .collect()
}

/// An equation of the source that the key-equation list does not carry.
fn equation(r: &Refraction<f64>, number: u8, formula: &'static str, values: String) -> Equation {
    Equation {
        number: format!("{}.{number}", r.convention.section()),
        formula,
        substituted: values,
    }
}

/// The equations the steps cite beyond the six key ones: 4, 6, 8, 10, 19 and 20.
fn other_equations(r: &Refraction<f64>) -> [Equation; 6] {
    let wording = wording(r.convention);
    let a = chosen_a(r);
    let wn = r.wn();
    [
        equation(r, 4, "sin(θi)·μ = sin(θt)", snell(r)),
        equation(r, 6, "(1 − cos²θi)·μ² = 1 − cos²θt", squared(r)),
        equation(
            r,
            8,
            wording.cos_i,
            format!("wn = W·N = {}, cosθi = {}", n(wn), n(r.cos_i)),
        ),
        equation(r, 10, "(1 − wn²)·μ² = 1 − (−a·wn − b)²", squared_snell(r)),
        equation(r, 19, wording.a, format!("a = {}", n(a))),
        equation(
            r,
            20,
            wording.quadratic_in_b,
            format!("b² + {}·b + {} = 0", n(2.0 * a * wn), n(a * a - 1.0)),
        ),
    ]
}

/// sinθi, from the kernel's cosθi.
fn sin_i(r: &Refraction<f64>) -> f64 {
    (1.0 - r.cos_i * r.cos_i).max(0.0).sqrt()
}

/// Eq. 4: sinθt from Snell's law, or why there is no θt.
fn snell(r: &Refraction<f64>) -> String {
    let sin_i = sin_i(r);
    let sin_t = r.mu * sin_i;
    let given = format!("μ = μi/μt = {}; sinθi = {}", n(r.mu), n(sin_i));
    if sin_t > 1.0 {
        format!(
            "{given}, so sinθt would be {} > 1: no angle θt exists",
            n(sin_t)
        )
    } else {
        format!("{given}, so sinθt = {}", n(sin_t))
    }
}

/// Eq. 6: squared Snell in cosines.
fn squared(r: &Refraction<f64>) -> String {
    let (cos_i, mu) = (r.cos_i, r.mu);
    format!(
        "(1 − {}²)·{}² = {} = 1 − cos²θt",
        n(cos_i),
        n(mu),
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
            format!("{} = {} with the chosen (a, b)", n(lhs), n(rhs))
        }
        None => "no real (a, b) satisfies it with eq. 12".to_owned(),
    }
}

/// Step 3's words: the direction of travel depends on the convention.
fn decomposition(r: &Refraction<f64>) -> String {
    let travel = wording(r.convention).travel;
    format!(
        "T lies in the plane of W and N, so it is a·W + b·N; the cosines become dot products \
         with wn = W·N, and cosθt = −a·wn − b. The ray travels along {travel}."
    )
}

/// Step 6's words: the limit μ = 1 picks the a that keeps the direction of travel.
fn choice_of_a(r: &Refraction<f64>) -> String {
    let Wording { travel, typo, .. } = wording(r.convention);
    format!(
        "When μ = 1 nothing bends, so T must be the direction of travel, {travel}. Only a = {} \
         gives that; the other sign would give the mirror image. Press \"Animate μ to 1\" to \
         watch T converge to {travel} and the ghosts not.{typo}",
        if chosen_a(r) < 0.0 { "−μ" } else { "+μ" }
    )
}

/// Step 8's words: with an outward normal the source's root is the wrong side.
fn choice_of_b(r: &Refraction<f64>) -> String {
    if r.normal_flipped {
        "The root with −√k goes to b = 0 at μ = 1, so T becomes the incoming ray. But here N \
         points along the ray (an outward normal where the ray leaves the medium): with N as \
         given that root is the wrong side. The kernel turns N around first."
    } else {
        "Of the two roots only the one with −√k becomes b = 0 at μ = 1, when T must be the \
         incoming ray unchanged; the other sends T back across the surface."
    }
    .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ExplorerState;

    #[test]
    fn the_steps_follow_the_source_with_live_numbers() {
        let mut state = ExplorerState::default();
        let along = steps(state.refraction());
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
        let toward = steps(state.refraction());
        assert_eq!(toward[5].equations[0].formula, "a = −μ");
        assert!(toward[5].explanation.contains("direction of travel, −W"));
        state.flip_normal();
        assert!(
            steps(state.refraction())[7]
                .explanation
                .contains("outward normal")
        );
    }

    #[test]
    fn total_internal_reflection_says_there_is_no_theta_t() {
        let mut state = ExplorerState::default();
        state.set_mu_i(1.5).unwrap();
        state.set_mu_t(1.0).unwrap();
        state.rotate(crate::HandleId::W, 40.0);
        let all = steps(state.refraction());
        assert!(all[0].equations[0].substituted.contains("> 1: no angle θt"));
        assert!(all[3].equations[0].substituted.contains("no real (a, b)"));
    }
}

//! The source's derivation as a sequence of steps, each with its equations in the source's
//! numbering, the current numbers substituted, what the step argues in plain words, and the
//! parts of the diagram it is about ([`Focus`]). Every number is the kernel's.

use super::equations::{Equation, equations};
use super::numbers::number;
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

/// An equation of the source that the key-equation list does not carry.
fn equation(r: &Refraction<f64>, number: u8, formula: &'static str, values: String) -> Equation {
    Equation {
        number: format!("{}.{number}", r.convention.section()),
        formula,
        substituted: values,
    }
}

/// Every step for the refraction `r`, in the source's order.
#[must_use]
pub fn steps(r: &Refraction<f64>) -> Vec<Step> {
    let n = |x: f64| number(x, 4);
    let [eq7, eq12, eq17, eq18, eq21, eq22] = <[Equation; 6]>::try_from(equations(r))
        .unwrap_or_else(|_| unreachable!("equations() lists six equations"));
    let (mu, wn, cos_i) = (r.mu, r.wn(), r.cos_i);
    let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
    let sin_t = mu * sin_i;
    let snell = if sin_t > 1.0 {
        format!(
            "μ = μi/μt = {}; sinθi = {}, so sinθt would be {} > 1: no angle θt exists",
            n(mu),
            n(sin_i),
            n(sin_t)
        )
    } else {
        format!(
            "μ = μi/μt = {}; sinθi = {}, so sinθt = {}",
            n(mu),
            n(sin_i),
            n(sin_t)
        )
    };
    let squared = format!(
        "(1 − {}²)·{}² = {} = 1 − cos²θt",
        n(cos_i),
        n(mu),
        n((1.0 - cos_i * cos_i) * mu * mu)
    );
    let (cos_i_formula, travel) = match r.convention {
        Convention::TowardOrigin => ("cosθi = wn", "−W"),
        Convention::AlongRay => ("cosθi = −wn", "W"),
    };
    let eq8 = equation(
        r,
        8,
        cos_i_formula,
        format!("wn = W·N = {}, cosθi = {}", n(wn), n(cos_i)),
    );
    let eq10 = match r.transmission {
        Some(tr) => {
            let lhs = (1.0 - wn * wn) * mu * mu;
            let rhs = 1.0 - (-tr.a * wn - tr.b).powi(2);
            equation(
                r,
                10,
                "(1 − wn²)·μ² = 1 − (−a·wn − b)²",
                format!("{} = {} with the chosen (a, b)", n(lhs), n(rhs)),
            )
        }
        None => equation(
            r,
            10,
            "(1 − wn²)·μ² = 1 − (−a·wn − b)²",
            "no real (a, b) satisfies it with eq. 12".to_owned(),
        ),
    };
    let a = r.convention.travel_sign::<f64>() * mu;
    let eq19 = match r.convention {
        Convention::TowardOrigin => equation(r, 19, "a = −μ", format!("a = {}", n(a))),
        Convention::AlongRay => equation(r, 19, "a = μ", format!("a = {}", n(a))),
    };
    let eq20 = equation(
        r,
        20,
        match r.convention {
            Convention::TowardOrigin => "μ² − 2μ·b·wn + b² = 1",
            Convention::AlongRay => "μ² + 2μ·b·wn + b² = 1",
        },
        format!("b² + {}·b + {} = 0", n(2.0 * a * wn), n(a * a - 1.0)),
    );
    let typo = match r.convention {
        Convention::AlongRay => {
            " (Section 2's text then says \"once we decide upon using the a = −μ solution\": \
             it means a = +μ, the one it chose.)"
        }
        Convention::TowardOrigin => "",
    };
    let choice_of_b = if r.normal_flipped {
        "The root with −√k goes to b = 0 at μ = 1, so T becomes the incoming ray. But here N \
         points along the ray (an outward normal where the ray leaves the medium): with N as \
         given that root is the wrong side. The kernel turns N around first."
    } else {
        "Of the two roots only the one with −√k becomes b = 0 at μ = 1, when T must be the \
         incoming ray unchanged; the other sends T back across the surface."
    };
    vec![
        Step {
            title: "Snell's law",
            equations: vec![equation(r, 4, "sin(θi)·μ = sin(θt)", snell)],
            explanation: "The ray bends so that μi·sinθi = μt·sinθt; with μ = μi/μt, the sine of \
                          the angle in the new medium is μ times the old one."
                .to_owned(),
            focus: Focus::Angles,
        },
        Step {
            title: "Square it, and use cosines",
            equations: vec![equation(r, 6, "(1 − cos²θi)·μ² = 1 − cos²θt", squared)],
            explanation: "Squaring lets the cosines (dot products) replace the sines, but it \
                          also lets in false solutions: a solution and its signed opposite \
                          both satisfy it."
                .to_owned(),
            focus: Focus::Angles,
        },
        Step {
            title: "T as a·W + b·N",
            equations: vec![eq7, eq8],
            explanation: format!(
                "T lies in the plane of W and N, so it is a·W + b·N; the cosines become dot \
                 products with wn = W·N, and cosθt = −a·wn − b. The ray travels along {travel}."
            ),
            focus: Focus::Decomposition,
        },
        Step {
            title: "The two squared constraints",
            equations: vec![eq10, eq12],
            explanation: "Squared Snell (eq. 10) and unit length (eq. 12) are two quadratics in \
                          a and b. Four pairs (a, b) satisfy both: T and the three ghosts. \
                          Nothing in them tells the four apart."
                .to_owned(),
            focus: Focus::SquaredConstraints,
        },
        Step {
            title: "The two roots for a",
            equations: vec![eq17, eq18],
            explanation: "Substituting eq. 12 into eq. 10 leaves a² = μ²: a = +μ or a = −μ. \
                          The other sign mirrors T across the normal: it bends the wrong way."
                .to_owned(),
            focus: Focus::RootsOfA,
        },
        Step {
            title: "Choosing a: the limit μ = 1",
            equations: vec![eq19],
            explanation: format!(
                "When μ = 1 nothing bends, so T must be the direction of travel, {travel}. Only \
                 a = {} gives that; the other sign would give the mirror image. Press \
                 \"Animate μ to 1\" to watch T converge to {travel} and the ghosts not.{typo}",
                if a < 0.0 { "−μ" } else { "+μ" }
            ),
            focus: Focus::ChoiceOfA,
        },
        Step {
            title: "The two roots for b",
            equations: vec![eq20, eq21],
            explanation: "With a fixed, eq. 12 is a quadratic in b with the roots −a·wn ± √k \
                          (k = μ²wn² − μ² + 1). The other root mirrors T across the surface, \
                          back into the medium the ray came from. k < 0 means no real root: \
                          total internal reflection."
                .to_owned(),
            focus: Focus::RootsOfB,
        },
        Step {
            title: "Choosing b",
            equations: vec![eq22],
            explanation: choice_of_b.to_owned(),
            focus: Focus::ChoiceOfB,
        },
    ]
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

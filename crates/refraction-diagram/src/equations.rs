//! The paper's key equations (7, 12, 17, 18, 21, 22) in the chosen convention, with the
//! current numbers substituted. Every number comes from the kernel (or, for eq. 22 with a
//! flipped normal, from the paper's formula taken literally, [`refraction_kernel::seed`]).

use refraction_i18n::t;
use refraction_kernel::{Convention, Refraction, seed};

use super::numbers::{number, vector};

/// One equation of the paper, as written there and with numbers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Equation {
    /// The paper's number, e.g. `2.21` (section.equation).
    pub number: String,
    /// The equation as the paper writes it, with the sine named as the language's schools
    /// write it (`sin`, `sen`).
    pub formula: String,
    /// The same with the current numbers, and what follows from them.
    pub substituted: String,
}

/// What the paper's two sections write differently among the key equations: Section 1 has W
/// point back toward the origin, Section 2 along the ray, and the signs of a and b follow.
struct Wording {
    /// Eq. 18's conclusion: which root for a the section takes, and why.
    chosen_a: fn() -> String,
    /// Eq. 21: the two roots for b.
    roots_of_b: &'static str,
    /// Eq. 22: the root for b the section chooses.
    chosen_b: &'static str,
}

const TOWARD_ORIGIN: Wording = Wording {
    chosen_a: || t!("diagram-eq-toward-origin-a"),
    // untranslated: a formula.
    roots_of_b: "b = μ·wn ± √(μ²wn² − μ² + 1)",
    // untranslated: a formula.
    chosen_b: "b = μ·wn − √(μ²wn² − μ² + 1)",
};

const ALONG_RAY: Wording = Wording {
    chosen_a: || t!("diagram-eq-along-ray-a"),
    // untranslated: a formula.
    roots_of_b: "b = −μ·wn ± √(μ²wn² − μ² + 1)",
    // untranslated: a formula.
    chosen_b: "b = −μ·wn − √(μ²wn² − μ² + 1)",
};

/// `x` as every equation prints it: four decimals.
pub(crate) fn n(x: f64) -> String {
    number(x, 4)
}

/// [`n`] in parentheses when negative: a number squared, multiplied or added in a formula
/// ("(−0.7071)²", "+ (−0.3832)·b"), where a bare minus would read as an operator.
pub(crate) fn term(x: f64) -> String {
    let text = n(x);
    if text.starts_with('−') {
        format!("({text})")
    } else {
        text
    }
}

/// The a the paper chooses in `r`'s convention: −μ or +μ.
pub(crate) fn chosen_a(r: &Refraction<f64>) -> f64 {
    r.convention.travel_sign::<f64>() * r.mu
}

/// The six key equations for `r`.
#[must_use]
pub fn equations(r: &Refraction<f64>) -> Vec<Equation> {
    let wording = match r.convention {
        Convention::TowardOrigin => &TOWARD_ORIGIN,
        Convention::AlongRay => &ALONG_RAY,
    };
    [
        (7, "T = a·W + b·N", decomposition(r)),
        // untranslated: a formula.
        (12, "a² + 2ab·wn + b² = 1", unit_length(r)),
        // untranslated: a formula.
        (17, "(wn² − 1)·μ² = a²·(wn² − 1)", squared_a(r)),
        (18, "a = (μ, −μ)", roots_of_a(r, &(wording.chosen_a)())),
        (21, wording.roots_of_b, roots_of_b(r)),
        (22, wording.chosen_b, choice_of_b(r)),
    ]
    .into_iter()
    .map(|(number, formula, substituted)| Equation {
        number: format!("{}.{number}", r.convention.section()),
        formula: formula.to_owned(),
        substituted,
    })
    .collect()
}

/// Eq. 7 with the kernel's a and b.
fn decomposition(r: &Refraction<f64>) -> String {
    match r.transmission {
        Some(tr) => format!(
            "T = {}·{} + {}·{} = {}",
            n(tr.a),
            vector(r.w, 3),
            term(tr.b),
            vector(r.n, 3),
            vector(tr.t, 4)
        ),
        None => t!("diagram-eq-no-refracted-ray"),
    }
}

/// Eq. 12: T's length from the kernel's a and b.
fn unit_length(r: &Refraction<f64>) -> String {
    let wn = r.wn();
    match r.transmission {
        Some(tr) => format!(
            "{}² + 2·{}·{}·{} + {}² = {}",
            term(tr.a),
            term(tr.a),
            term(tr.b),
            term(wn),
            term(tr.b),
            n(tr.a * tr.a + 2.0 * tr.a * tr.b * wn + tr.b * tr.b)
        ),
        None => t!("diagram-eq-no-b-with-10"),
    }
}

/// Eq. 17: eq. 12 substituted into eq. 10 leaves a² = μ².
fn squared_a(r: &Refraction<f64>) -> String {
    let (mu, wn) = (r.mu, r.wn());
    let wn2_minus_1 = wn * wn - 1.0;
    let given = format!(
        // untranslated: a formula with numbers.
        "({}² − 1)·{}² = {} = a²·({})",
        term(wn),
        term(mu),
        n(wn2_minus_1 * mu * mu),
        n(wn2_minus_1)
    );
    let then = format!("a² = {}", n(mu * mu));
    t!("diagram-eq-so", given = given, then = then)
}

/// Eq. 18: the two roots for a and the one the paper takes.
fn roots_of_a(r: &Refraction<f64>, chosen: &str) -> String {
    format!("a = ±{}; {chosen} = {}", n(r.mu), n(chosen_a(r)))
}

/// Eq. 21: the two roots for b, or why there are none.
fn roots_of_b(r: &Refraction<f64>) -> String {
    if r.is_tir() {
        return t!("diagram-eq-negative-root", k = n(r.k));
    }
    let a = chosen_a(r);
    let roots: Vec<String> = r
        .candidates
        .iter()
        .filter(|c| c.a == a)
        .map(|c| n(c.b))
        .collect();
    format!(
        "b = {} ± √{} = {}",
        n(-a * r.wn()),
        n(r.k),
        roots.join(&format!(" {} ", t!("diagram-eq-or")))
    )
}

/// Eq. 22: the paper's root for b, taken literally; with a flipped normal, how it goes wrong.
fn choice_of_b(r: &Refraction<f64>) -> String {
    match (seed::weights(r.w, r.n, r.mu, r.convention), r.transmission) {
        (Some((_, b)), Some(tr)) if r.normal_flipped => {
            let (b, kernel) = (n(b), n(tr.b));
            t!("diagram-eq-outward-normal-bug", b = b, kernel_b = kernel)
        }
        (Some((_, b)), Some(_)) => {
            format!("b = {} − √{} = {}", n(-chosen_a(r) * r.wn()), n(r.k), n(b))
        }
        _ => t!("diagram-eq-no-root"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_model::ExplorerState;

    #[test]
    fn equations_follow_the_convention_and_the_flip() {
        let mut state = ExplorerState::default();
        let along = equations(state.refraction());
        assert_eq!(along.len(), 6);
        assert_eq!(along[0].number, "2.7");
        assert!(along[4].formula.starts_with("b = −μ·wn"));
        assert!(along[1].substituted.ends_with("= 1.0000"), "{:?}", along[1]);
        state.set_convention(Convention::TowardOrigin);
        let toward = equations(state.refraction());
        assert_eq!(toward[5].number, "1.22");
        assert!(toward[3].substituted.contains("a = −μ = −0.6669"));
        state.flip_normal();
        assert!(
            equations(state.refraction())[5]
                .substituted
                .contains("outward-normal bug")
        );
    }
}

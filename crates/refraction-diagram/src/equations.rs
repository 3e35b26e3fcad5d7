//! The source's key equations (7, 12, 17, 18, 21, 22) in the chosen convention, with the
//! current numbers substituted. Every number comes from the kernel (or, for eq. 22 with a
//! flipped normal, from the source's formula taken literally, [`refraction_kernel::seed`]).

use refraction_kernel::{Convention, Refraction, seed};

use super::numbers::{number, vector};

/// One equation of the source, as written there and with numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Equation {
    /// The source's number, e.g. `2.21` (section.equation).
    pub number: String,
    /// The equation as the source writes it.
    pub formula: &'static str,
    /// The same with the current numbers, and what follows from them.
    pub substituted: String,
}

/// The six key equations for `r`.
#[must_use]
pub fn equations(r: &Refraction<f64>) -> Vec<Equation> {
    let section = r.convention.section();
    let (mu, wn, k) = (r.mu, r.wn(), r.k);
    let a = r.convention.travel_sign::<f64>() * mu;
    let n = |x: f64| number(x, 4);
    let (chosen_a, formula_21, formula_22) = match r.convention {
        Convention::TowardOrigin => (
            "W points away from T, so the source takes a = −μ",
            "b = μ·wn ± √(μ²wn² − μ² + 1)",
            "b = μ·wn − √(μ²wn² − μ² + 1)",
        ),
        Convention::AlongRay => (
            "W points along T, so the source takes a = +μ",
            "b = −μ·wn ± √(μ²wn² − μ² + 1)",
            "b = −μ·wn − √(μ²wn² − μ² + 1)",
        ),
    };
    let eq7 = match r.transmission {
        Some(tr) => format!(
            "T = {}·{} + {}·{} = {}",
            n(tr.a),
            vector(r.w, 3),
            n(tr.b),
            vector(r.n, 3),
            vector(tr.t, 4)
        ),
        None => "no real (a, b): there is no refracted ray".to_owned(),
    };
    let eq12 = match r.transmission {
        Some(tr) => format!(
            "{}² + 2·{}·{}·{} + {}² = {}",
            n(tr.a),
            n(tr.a),
            n(tr.b),
            n(wn),
            n(tr.b),
            n(tr.a * tr.a + 2.0 * tr.a * tr.b * wn + tr.b * tr.b)
        ),
        None => "no real b satisfies it together with eq. 10".to_owned(),
    };
    let wn2_minus_1 = wn * wn - 1.0;
    let eq17 = format!(
        "({}² − 1)·{}² = {} = a²·({}), so a² = {}",
        n(wn),
        n(mu),
        n(wn2_minus_1 * mu * mu),
        n(wn2_minus_1),
        n(mu * mu)
    );
    let eq18 = format!("a = ±{}; {chosen_a} = {}", n(mu), n(a));
    let eq21 = if r.is_tir() {
        format!(
            "√({}) of a negative number: no real b (total internal reflection)",
            n(k)
        )
    } else {
        let roots: Vec<String> = r
            .candidates
            .iter()
            .filter(|c| c.a == a)
            .map(|c| n(c.b))
            .collect();
        format!("b = {} ± √{} = {}", n(-a * wn), n(k), roots.join(" or "))
    };
    let eq22 = match (seed::weights(r.w, r.n, mu, r.convention), r.transmission) {
        (Some((_, b)), Some(tr)) if r.normal_flipped => format!(
            "with N as given b = {}: the wrong root, T goes back (the outward-normal bug); \
             the kernel uses −N and gets b = {} for N",
            n(b),
            n(tr.b)
        ),
        (Some((_, b)), Some(_)) => format!("b = {} − √{} = {}", n(-a * wn), n(k), n(b)),
        _ => "no real root to choose".to_owned(),
    };
    [
        (7, "T = a·W + b·N", eq7),
        (12, "a² + 2ab·wn + b² = 1", eq12),
        (17, "(wn² − 1)·μ² = a²·(wn² − 1)", eq17),
        (18, "a = (μ, −μ)", eq18),
        (21, formula_21, eq21),
        (22, formula_22, eq22),
    ]
    .into_iter()
    .map(|(number, formula, substituted)| Equation {
        number: format!("{section}.{number}"),
        formula,
        substituted,
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ExplorerState;

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

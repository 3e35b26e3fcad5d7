//! The candidates table: each (a, b), its T, and which laws it keeps.

use glam::DVec3;

use refraction_i18n::t;
use refraction_kernel::{Refraction, Rejection};

/// One row of the candidates table.
#[derive(Clone, Debug, PartialEq)]
pub struct CandidateRow {
    /// What the candidate is, in the current language: `T (chosen)`, `wrong side`, `wrong
    /// bend` or `reversed`.
    pub role: String,
    /// Weight of W.
    pub a: f64,
    /// Weight of N.
    pub b: f64,
    /// The direction a·W + b·N.
    pub t: DVec3,
    /// |T| = 1.
    pub unit: bool,
    /// Squared Snell (source eq. 10).
    pub squared_snell: bool,
    /// T crosses into the new medium.
    pub correct_side: bool,
    /// T's part along the surface points the way the ray's does (the μ → 1 argument).
    pub tangential: bool,
    /// The rule a rejected candidate breaks, in a sentence in the current language.
    pub rule: Option<String>,
}

/// The role of a candidate, as the table names it in the current language.
#[must_use]
pub(crate) fn role(rejection: Option<Rejection>) -> String {
    match rejection {
        None => t!("diagram-role-chosen"),
        Some(Rejection::WrongSide) => t!("diagram-role-wrong-side"),
        Some(Rejection::WrongBend) => t!("diagram-role-wrong-bend"),
        Some(Rejection::Reversed) => t!("diagram-role-reversed"),
    }
}

/// The rule a rejected candidate breaks, in a sentence in the current language (the kernel's
/// [`Rejection::rule`] in English).
#[must_use]
pub(crate) fn rule(rejection: Rejection) -> String {
    match rejection {
        Rejection::WrongSide => t!("diagram-rule-wrong-side"),
        Rejection::WrongBend => t!("diagram-rule-wrong-bend"),
        Rejection::Reversed => t!("diagram-rule-reversed"),
    }
}

/// The rows for the kernel's four candidates, in the paper's order (empty on total internal
/// reflection, where there are none).
#[must_use]
pub fn candidate_rows(r: &Refraction<f64>) -> Vec<CandidateRow> {
    let tolerance = r.tolerance();
    r.candidates
        .iter()
        .map(|c| {
            let checks = r.checks(c.t);
            CandidateRow {
                role: role(c.rejection),
                a: c.a,
                b: c.b,
                t: c.t,
                unit: checks.is_unit(tolerance),
                squared_snell: checks.obeys_squared_snell(tolerance),
                correct_side: checks.is_on_correct_side(tolerance),
                tangential: checks.bends_correctly(tolerance),
                rule: c.rejection.map(rule),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_model::ExplorerState;

    #[test]
    fn all_four_keep_the_squared_laws_and_only_t_keeps_the_rest() {
        let rows = candidate_rows(ExplorerState::default().refraction());
        assert_eq!(rows.len(), 4);
        for row in &rows {
            assert!(row.unit && row.squared_snell, "{row:?}");
            let expected = match row.role.as_str() {
                "T (chosen)" => (true, true),
                "wrong side" => (false, true),
                "wrong bend" => (true, false),
                _ => (false, false),
            };
            assert_eq!((row.correct_side, row.tangential), expected, "{row:?}");
        }
    }
}

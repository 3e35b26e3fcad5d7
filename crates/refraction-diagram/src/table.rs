//! The candidates table: each (a, b), its T, and which laws it keeps.

use glam::DVec3;

use refraction_kernel::{Refraction, Rejection};

/// One row of the candidates table.
#[derive(Clone, Debug, PartialEq)]
pub struct CandidateRow {
    /// What the candidate is: `T (chosen)`, `wrong side`, `wrong bend` or `reversed`.
    pub role: &'static str,
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
    /// The rule a rejected candidate breaks, in a sentence.
    pub rule: Option<&'static str>,
}

/// The role of a candidate, as the table names it.
#[must_use]
pub fn role(rejection: Option<Rejection>) -> &'static str {
    match rejection {
        None => "T (chosen)",
        Some(Rejection::WrongSide) => "wrong side",
        Some(Rejection::WrongBend) => "wrong bend",
        Some(Rejection::Reversed) => "reversed",
    }
}

/// The rows for the kernel's four candidates, in the source's order (empty on total internal
/// reflection, where there are none).
#[must_use]
pub fn rows(r: &Refraction<f64>) -> Vec<CandidateRow> {
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
                rule: c.rejection.map(Rejection::rule),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ExplorerState;

    #[test]
    fn all_four_keep_the_squared_laws_and_only_t_keeps_the_rest() {
        let rows = rows(ExplorerState::default().refraction());
        assert_eq!(rows.len(), 4);
        for row in &rows {
            assert!(row.unit && row.squared_snell, "{row:?}");
            let expected = match row.role {
                "T (chosen)" => (true, true),
                "wrong side" => (false, true),
                "wrong bend" => (true, false),
                _ => (false, false),
            };
            assert_eq!((row.correct_side, row.tangential), expected, "{row:?}");
        }
    }
}

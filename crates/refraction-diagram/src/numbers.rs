//! Numbers as the diagram and the panels print them: fixed decimals, a true minus sign, no
//! "−0".

/// `x` with `decimals` digits, a true minus sign, and no "−0".
#[must_use]
pub fn number(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    if text
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        text.trim_start_matches('-').to_owned()
    } else {
        text.replace('-', "−")
    }
}

/// A 3D vector as `(x, y, z)` with [`number`]s.
#[must_use]
pub fn vector(v: glam::DVec3, decimals: usize) -> String {
    format!(
        "({}, {}, {})",
        number(v.x, decimals),
        number(v.y, decimals),
        number(v.z, decimals)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_use_a_true_minus_and_no_negative_zero() {
        assert_eq!(number(-0.25, 3), "−0.250");
        assert_eq!(number(-0.00001, 3), "0.000");
        assert_eq!(number(1.5, 1), "1.5");
        assert_eq!(
            vector(glam::DVec3::new(0.0, -1.0, 0.5), 1),
            "(0.0, −1.0, 0.5)"
        );
        assert_eq!(number(f64::NAN, 2), "NaN");
    }
}

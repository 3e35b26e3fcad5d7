//! Numbers as the diagram and the panels print them: fixed decimals, a true minus sign, no
//! "−0", and the decimal separator of the user's language (a comma in German, say). Copied
//! code, JSON and files never use these: they keep Rust's own point.

/// `x` with `decimals` digits, a true minus sign, no "−0", and the language's decimal
/// separator.
#[must_use]
pub fn number(x: f64, decimals: usize) -> String {
    refraction_i18n::decimal(&point_number(x, decimals))
}

/// [`number`] with a decimal point whatever the language.
fn point_number(x: f64, decimals: usize) -> String {
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

/// `x` with at most `digits` significant digits (at least 1), for labels: a true minus sign,
/// no "−0", and no trailing zeros when they would only repeat an exact value (`1.5`, not
/// `1.500`); a value that was rounded keeps them (`1.000` for 1.000293), so the label does not
/// claim an exact 1. Very large or small magnitudes are written as `1.234e-5`. The decimal
/// separator is the language's.
#[must_use]
pub fn significant(x: f64, digits: usize) -> String {
    refraction_i18n::decimal(&point_significant(x, digits))
}

/// [`significant`] with a decimal point whatever the language.
fn point_significant(x: f64, digits: usize) -> String {
    let digits = digits.max(1);
    if !x.is_finite() || x == 0.0 {
        return point_number(x, 0);
    }
    let magnitude = x.abs().log10().floor();
    if !(-3.0..4.0).contains(&magnitude) {
        let text = format!("{x:.*e}", digits - 1);
        return text.replace('-', "−");
    }
    let mut decimals = (digits as f64 - 1.0 - magnitude).max(0.0) as usize;
    // 0.99999 rounds up to the next decade (1.0000): one decimal fewer.
    let rounded: f64 = format!("{:.decimals$}", x.abs()).parse().unwrap_or(0.0);
    if rounded >= 10f64.powf(magnitude + 1.0) && decimals > 0 {
        decimals -= 1;
    }
    let text = point_number(x, decimals);
    // A value within a few ulps of its rounded text (40 reached by turning 50° by 10°) is that
    // value: its trailing zeros would only claim digits it does not have.
    let exact = format!("{x:.decimals$}")
        .parse::<f64>()
        .is_ok_and(|r| (r - x).abs() <= 4.0 * f64::EPSILON * x.abs());
    if exact && text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// [`significant`] with at least `digits` digits and as many more (up to 15) as it takes for
/// the text not to read as `other`: a length of 1.0004 is "1.0004", not 1, since "has length
/// 1.000, not 1" would contradict itself.
#[must_use]
pub fn significant_apart(x: f64, other: f64, digits: usize) -> String {
    (digits.max(1)..=15)
        .map(|d| (d, point_significant(x, d)))
        .find(|(_, text)| text.replace('−', "-").parse::<f64>().ok() != Some(other))
        .map_or_else(|| significant(x, digits), |(d, _)| significant(x, d))
}

/// A 3D vector as `(x, y, z)` with [`number`]s, separated as the language separates a list
/// of numbers (`(0,5; −1,0; 0,0)` where the decimal separator is a comma).
#[must_use]
pub fn vector(v: glam::DVec3, decimals: usize) -> String {
    let separator = refraction_i18n::locale().list_separator();
    let [x, y, z] = [v.x, v.y, v.z].map(|c| number(c, decimals));
    format!("({x}{separator}{y}{separator}{z})")
}

/// A power fraction as a percentage with one decimal, e.g. `4.0 %`.
#[must_use]
pub fn percent(fraction: f64) -> String {
    format!("{} %", number(fraction * 100.0, 1))
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

    #[test]
    fn labels_get_at_most_four_significant_digits() {
        assert_eq!(significant(1.3573907540770769, 4), "1.357");
        assert_eq!(significant(9.999904099540156e-1, 4), "1.000");
        assert_eq!(significant(1.000293, 4), "1.000");
        assert_eq!(significant(1.5, 4), "1.5");
        assert_eq!(significant(2.417, 4), "2.417");
        assert_eq!(significant(-0.39258, 4), "−0.3926");
        assert_eq!(significant(587.56, 4), "587.6");
        assert_eq!(significant(0.0, 4), "0");
        assert_eq!(significant(-1.0e-9, 4), "−1.000e−9");
        assert_eq!(significant(123456.0, 4), "1.235e5");
        for x in [1.0 / 3.0, 12.345678, -0.000123456, 98765.4321] {
            let text = significant(x, 4);
            let digits = text
                .split('e')
                .next()
                .unwrap()
                .chars()
                .filter(char::is_ascii_digit)
                .skip_while(|c| *c == '0')
                .count();
            assert!(digits <= 4, "{x}: {text}");
        }
    }

    #[test]
    fn a_length_near_one_gets_the_digits_that_tell_it_from_one() {
        assert_eq!(significant_apart(1.0004, 1.0, 4), "1.0004");
        assert_eq!(significant_apart(1.000293, 1.0, 4), "1.0003");
        assert_eq!(significant_apart(0.99999999, 1.0, 4), "0.99999999");
        assert_eq!(significant_apart(2.5, 1.0, 4), "2.5");
        assert_eq!(significant_apart(1.25, 1.0, 4), "1.25");
    }

    #[test]
    fn a_german_label_has_a_decimal_comma_and_semicolons_between_components() {
        refraction_i18n::set_locale(refraction_i18n::Locale::De);
        let written = (
            number(-0.25, 3),
            significant(1.3573907540770769, 4),
            vector(glam::DVec3::new(0.5, -1.0, 0.0), 1),
        );
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
        assert_eq!(written.0, "−0,250");
        assert_eq!(written.1, "1,357");
        assert_eq!(written.2, "(0,5; −1,0; 0,0)");
    }
}

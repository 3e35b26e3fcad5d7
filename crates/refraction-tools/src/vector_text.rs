//! Numbers and 3-vectors written the way programs print them, with how many significant digits
//! each carries, and the length and angle arithmetic that holds for any finite vector.
//!
//! A number is a decimal (`-0.9`, `1e-05`, `.5`), a C hexadecimal float (`0x1.8p+0`, as `%a`
//! prints it), `inf`/`infinity`/`nan` in any case with a sign (`-nan`, `nan(ind)`, `1.#INF`),
//! and may end in a literal suffix (`0.5f`, `1.0f32`, `2_f64`); the `f` of `inf` is the word's
//! own. A vector is three numbers separated by commas or spaces, bare or inside brackets with
//! an optional type name: `x y z`, `x, y, z`, `[ x, y, z ]`, `(x, y, z)`, `vec3(x, y, z)`,
//! `glm::vec3(...)`, `Vec3 { x: .., y: .., z: .. }`, nested (`[[x, y, z]]`, as a one-lane Dr.Jit
//! array prints) or as Node prints a typed array (`Float32Array(3) [ x, y, z ]`).

use crate::error::VectorError;
use glam::DVec3;
use refraction_i18n::t;

/// A parsed number and the digits it was written with (0 for `inf` and `nan`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Number {
    /// The value.
    pub value: f64,
    /// Significant digits as written (17 for a hexadecimal float, which is exact).
    pub digits: u32,
}

/// A parsed 3-vector and how precisely it was written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector {
    /// The components.
    pub value: [f64; 3],
    /// The significant digits of a number of magnitude 1 written as precisely as the vector
    /// (at most 17): its format's precision (its components' most significant digits) carried
    /// to the magnitude of its largest component, which sets its rounding. `0.428525,
    /// -0.90353, 0` gives 7 (half a unit in the sixth decimal place), as does a `%g` vector
    /// with a tiny component (`1.23457e-05`), which is no coarser for it.
    pub digits: u32,
}

/// The digits a vector with these components, written with these significant digits, is
/// trusted to (see [`Vector::digits`]): 0 when every component is zero.
fn vector_digits(components: [f64; 3], digits: [u32; 3]) -> u32 {
    let largest = components.iter().map(|c| c.abs()).fold(0.0, f64::max);
    if largest == 0.0 || !largest.is_finite() {
        return 0;
    }
    // floor(log10) of a finite non-zero f64 lies within ±324.
    #[expect(clippy::cast_possible_truncation)]
    let magnitude = largest.log10().floor() as i32;
    let format = digits.into_iter().max().unwrap_or(0);
    let carried = i32::try_from(format)
        .unwrap_or(17)
        .saturating_sub(magnitude);
    u32::try_from(carried.clamp(0, 17)).unwrap_or(17)
}

fn special(word: &str) -> Option<f64> {
    let lower = word.to_ascii_lowercase();
    let (negative, body) = match lower.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, lower.strip_prefix('+').unwrap_or(&lower)),
    };
    let value = match body {
        "inf" | "infinity" | "1.#inf" => f64::INFINITY,
        "nan" | "1.#ind" | "1.#qnan" => f64::NAN,
        _ if body.starts_with("nan(") && body.ends_with(')') => f64::NAN,
        _ => return None,
    };
    Some(if negative { -value } else { value })
}

/// Significant digits of a decimal literal's mantissa: digits after any leading zeros.
fn decimal_digits(mantissa: &str) -> u32 {
    let digits: Vec<char> = mantissa.chars().filter(char::is_ascii_digit).collect();
    let significant = digits.iter().skip_while(|&&c| c == '0').count();
    u32::try_from(significant.max(1)).unwrap_or(u32::MAX)
}

fn hexadecimal(word: &str) -> Option<f64> {
    let (negative, body) = match word.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, word.strip_prefix('+').unwrap_or(word)),
    };
    let body = body
        .strip_prefix("0x")
        .or_else(|| body.strip_prefix("0X"))?;
    let (mantissa, exponent) = body.split_once(['p', 'P'])?;
    let exponent: i32 = exponent.parse().ok()?;
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    if whole.len() + fraction.len() > 15 || (whole.is_empty() && fraction.is_empty()) {
        return None;
    }
    let digits = u64::from_str_radix(&format!("{whole}{fraction}0"), 16).ok()? >> 4;
    let shift = exponent - 4 * i32::try_from(fraction.len()).ok()?;
    // The mantissa has at most 60 bits, so it is exact in f64 up to its last 7: fine for the
    // 53-bit mantissas %a prints; powi of 2 is exact.
    #[expect(clippy::cast_precision_loss)]
    let value = digits as f64 * 2f64.powi(shift);
    Some(if negative { -value } else { value })
}

/// Reads one number as programs print it (see the module documentation).
///
/// # Errors
/// The word is not a number; the message quotes it.
pub fn parse_number(word: &str) -> Result<Number, VectorError> {
    let word = word.trim();
    if let Some(value) = special(word) {
        return Ok(Number { value, digits: 0 });
    }
    if let Some(value) = hexadecimal(word) {
        return Ok(Number { value, digits: 17 });
    }
    let stripped = ["_f32", "_f64", "f32", "f64", "f", "F"]
        .iter()
        .find_map(|suffix| word.strip_suffix(suffix))
        .filter(|rest| rest.ends_with(|c: char| c.is_ascii_digit() || c == '.'))
        .unwrap_or(word);
    let is_decimal = stripped
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'))
        && stripped.chars().any(|c| c.is_ascii_digit());
    match stripped.parse::<f64>() {
        Ok(value) if is_decimal => {
            let mantissa = stripped.split(['e', 'E']).next().unwrap_or(stripped);
            Ok(Number {
                value,
                digits: decimal_digits(mantissa),
            })
        }
        _ => Err(VectorError::NotANumber {
            word: word.to_owned(),
        }),
    }
}

/// The significant digits of `x` written in its shortest form that reads back exactly (how a
/// JSON number's precision is judged once parsed).
#[must_use]
pub fn digits_of(x: f64) -> u32 {
    if !x.is_finite() {
        return 0;
    }
    let text = format!("{x:e}");
    decimal_digits(text.split('e').next().unwrap_or(&text))
}

/// The digits a JSON vector with these components is trusted to (see [`Vector::digits`]).
#[must_use]
pub fn json_vector_digits(components: [f64; 3]) -> u32 {
    vector_digits(components, components.map(digits_of))
}

/// The text between a type name's opening bracket and its closing one, or the text itself;
/// nested brackets (`[[x, y, z]]`, a one-lane Dr.Jit array) are taken off one by one.
fn vector_body(text: &str) -> &str {
    let mut body = text.trim();
    loop {
        let inner = one_body(body).trim();
        if inner == body {
            return body;
        }
        body = inner;
    }
}

/// Node's name for a typed array before its elements, `Float32Array(3) `, taken off.
fn without_typed_array(text: &str) -> &str {
    let Some((name, rest)) = text.split_once('(') else {
        return text;
    };
    let Some((count, rest)) = rest.split_once(')') else {
        return text;
    };
    // untranslated: the end of JavaScript's typed arrays' names (Float32Array, Float64Array)
    let typed = name.ends_with("Array")
        && name.chars().all(char::is_alphanumeric)
        && count.chars().all(|c| c.is_ascii_digit())
        && rest.trim_start().starts_with('[');
    if typed { rest.trim_start() } else { text }
}

/// [`vector_body`]'s one step: the text inside one type name's brackets.
fn one_body(text: &str) -> &str {
    let text = without_typed_array(text);
    let Some(open) = text.find(['(', '[', '{']) else {
        return text;
    };
    let name = text[..open].trim_end();
    let is_name = name
        .chars()
        .all(|c| c.is_alphanumeric() || matches!(c, '_' | ':' | '<' | '>'));
    let close = match &text[open..=open] {
        "(" => ')',
        "[" => ']',
        _ => '}',
    };
    if is_name && special(name).is_none() && text.ends_with(close) {
        &text[open + 1..text.len() - 1]
    } else {
        text
    }
}

/// The components of `Vec3 { x: 1, y: 2, z: 3 }`'s body, or `None` when it has no names.
fn named_components(body: &str) -> Option<Result<Vec<&str>, VectorError>> {
    if !body.contains(':') {
        return None;
    }
    let parts: Vec<&str> = body
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect();
    let values = parts
        .iter()
        .zip(["x", "y", "z"])
        .map(|(part, expected)| match part.split_once(':') {
            Some((name, value)) if name.trim().eq_ignore_ascii_case(expected) => Ok(value.trim()),
            _ => Err(VectorError::ExpectedNamed {
                expected,
                found: (*part).to_owned(),
            }),
        })
        .collect::<Result<Vec<&str>, VectorError>>();
    Some(values.map(|v| if parts.len() == 3 { v } else { parts.clone() }))
}

/// Reads a 3-vector as programs print it (see the module documentation).
///
/// # Errors
/// A message saying what was found instead of three numbers.
pub fn parse_vector(text: &str) -> Result<Vector, VectorError> {
    let trimmed = text.trim();
    let body = vector_body(trimmed.trim_end_matches([';', ',']).trim_end());
    let within = |error: VectorError| VectorError::Within {
        error: Box::new(error),
        text: trimmed.to_owned(),
    };
    let words: Vec<&str> = match named_components(body) {
        Some(named) => named.map_err(within)?,
        None => body
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .collect(),
    };
    if words.len() != 3 {
        return Err(VectorError::NotThree {
            count: words.len(),
            text: trimmed.to_owned(),
        });
    }
    let mut value = [0.0; 3];
    let mut digits = [0; 3];
    for ((slot, written), word) in value.iter_mut().zip(&mut digits).zip(&words) {
        let number = parse_number(word).map_err(within)?;
        *slot = number.value;
        *written = number.digits;
    }
    Ok(Vector {
        value,
        digits: vector_digits(value, digits),
    })
}

/// What an explanation says for a number that is not finite: words, never `NaN` or `inf`
/// written as if they were numbers.
// untranslated: the words of `short`, for the command line's text; `spoken` translates them
const NOT_FINITE: &str = "not finite (NaN or infinite)";

/// `x` with 6 significant digits and no trailing zeros, as C's `%g` prints it (`0.666667`,
/// `1.5`, `1e+201` becomes `1e201`), for explanations; words for NaN and ±∞.
#[must_use]
pub fn short(x: f64) -> String {
    if x == 0.0 {
        return "0".to_owned();
    }
    if !x.is_finite() {
        return NOT_FINITE.to_owned();
    }
    let exponent = x.abs().log10().floor();
    if (-5.0..6.0).contains(&exponent) {
        // 0 ≤ 5 − exponent ≤ 10 here.
        #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let decimals = (5.0 - exponent) as usize;
        let text = format!("{x:.decimals$}");
        let text = if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.')
        } else {
            &text
        };
        text.to_owned()
    } else {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

/// A vector as `(x, y, z)` with [`short`] numbers, or words for one with a component that is
/// not finite.
#[must_use]
pub fn short_vector(v: [f64; 3]) -> String {
    if v.iter().all(|x| x.is_finite()) {
        format!("({}, {}, {})", short(v[0]), short(v[1]), short(v[2]))
    } else {
        // untranslated: the words of `short_vector`, for the command line's text
        "a vector that is not finite (NaN or infinite components)".to_owned()
    }
}

/// [`short`] for a sentence a user reads: the language's decimal separator, and the language's
/// words for a number that is not finite. Never for text that is parsed back or copied.
#[must_use]
pub fn spoken(x: f64) -> String {
    if x.is_finite() {
        refraction_i18n::decimal(&short(x))
    } else {
        t!("check-number-not-finite")
    }
}

/// [`short_vector`] for a sentence a user reads: [`spoken`] components separated as the
/// language separates a list of numbers (`(0,6; −0,8; 0)` where the decimal separator is a
/// comma), or the language's words for a vector that is not finite.
#[must_use]
pub fn spoken_vector(v: [f64; 3]) -> String {
    if v.iter().all(|x| x.is_finite()) {
        let separator = refraction_i18n::locale().list_separator();
        let [x, y, z] = v.map(spoken);
        format!("({x}{separator}{y}{separator}{z})")
    } else {
        t!("check-vector-not-finite")
    }
}

/// The largest absolute component (0 for the zero vector; NaN components are skipped).
fn scale_of(v: DVec3) -> f64 {
    v.abs().max_element()
}

/// |v| without overflow or underflow for any finite v (1e201 and 4e-320 alike).
#[must_use]
pub fn length(v: DVec3) -> f64 {
    let scale = scale_of(v);
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    scale * (v / scale).length()
}

/// v / |v| for any finite non-zero v; the zero vector stays zero.
#[must_use]
pub fn unit(v: DVec3) -> DVec3 {
    let scale = scale_of(v);
    if scale == 0.0 || !scale.is_finite() {
        return v;
    }
    (v / scale).normalize()
}

/// The angle in radians between two finite non-zero vectors, in [0, π], whatever their
/// lengths.
#[must_use]
pub fn angle(a: DVec3, b: DVec3) -> f64 {
    let (a, b) = (unit(a), unit(b));
    a.cross(b).length().atan2(a.dot(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vector(text: &str) -> [f64; 3] {
        parse_vector(text).unwrap().value
    }

    #[test]
    fn every_printed_form() {
        for text in [
            "0.1 -0.9 0",
            "0.1, -0.9, 0",
            "[ 0.1, -0.9, 0 ]",
            "(0.1, -0.9, 0)",
            "vec3(0.1, -0.9, 0.0)",
            "glm::vec3(0.1, -0.9, 0)",
            "Vec3(0.1, -0.9, 0.0)",
            "Vec3 { x: 0.1, y: -0.9, z: 0.0 }",
            "DVec3 { x: 0.1, y: -0.9, z: 0 };",
            "(0.1f, -0.9f, 0.0f);",
            "Vector3f[0.1_f32, -0.9f32, 0]",
            "[[0.1, -0.9, 0]]",
            "Float32Array(3) [ 0.1, -0.9, 0 ]",
            "Float32Array(3) [\n  0.1,\n  -0.9,\n  0\n]",
        ] {
            assert_eq!(vector(text), [0.1, -0.9, 0.0], "{text}");
        }
    }

    #[test]
    fn inf_keeps_its_f_and_nan_comes_in_every_spelling() {
        assert_eq!(vector("inf, 0, 0"), [f64::INFINITY, 0.0, 0.0]);
        assert_eq!(vector("-INF 1.5f +Infinity")[0], f64::NEG_INFINITY);
        for text in [
            "nan 0 1",
            "-nan, 0, 1",
            "(nan(ind), 0, 1)",
            "1.#IND 0 1",
            "NaN 0 1",
        ] {
            assert!(vector(text)[0].is_nan(), "{text}");
        }
        assert_eq!(parse_number("0x1.8p+0").unwrap().value, 1.5);
        assert_eq!(parse_number("-0x1p-2").unwrap().value, -0.25);
    }

    #[test]
    fn digits_are_counted_as_written() {
        assert_eq!(parse_number("0.642788").unwrap().digits, 6);
        assert_eq!(parse_number("-0.000500000").unwrap().digits, 6);
        assert_eq!(parse_number("1.5e-05").unwrap().digits, 2);
        // A vector: its format's digits carried to its largest component (unit scale).
        assert_eq!(parse_vector("0.5 0.25 0.123456").unwrap().digits, 7);
        assert_eq!(parse_vector("0.90353 0.0412 0").unwrap().digits, 6);
        assert_eq!(
            parse_vector("0.0412345 -0.998123 1.23457e-05")
                .unwrap()
                .digits,
            7
        );
        assert_eq!(
            parse_vector("0.000000 1.000000 0.000000").unwrap().digits,
            7
        );
        assert_eq!(parse_vector("0 1 0").unwrap().digits, 1);
        assert_eq!(digits_of(0.1), 1);
        assert_eq!(digits_of(0.6427876096865393), 16);
    }

    #[test]
    fn what_is_not_a_vector_says_why() {
        assert!(
            parse_vector("1, 2")
                .unwrap_err()
                .to_string()
                .contains("found 2")
        );
        assert!(
            parse_vector("1, x, 2")
                .unwrap_err()
                .to_string()
                .contains("\"x\" is not a number")
        );
        assert!(
            parse_vector("Vec3 { x: 1, w: 2, z: 3 }")
                .unwrap_err()
                .to_string()
                .contains("`y: <number>`")
        );
        assert!(parse_number("in").is_err() && parse_number("f").is_err());
        assert!(parse_number("1.5.5").is_err() && parse_number("0x").is_err());
    }

    #[test]
    fn short_numbers_read_like_printf_g() {
        assert_eq!(short(1.0 / 1.5), "0.666667");
        assert_eq!(short(1.5), "1.5");
        assert_eq!(short(-0.903_529_889), "-0.90353");
        assert_eq!(short(1e201), "1e201");
        assert_eq!(short(-2.5e-300), "-2.5e-300");
        assert_eq!(short(123_456.7), "123457");
        assert_eq!(short_vector([-0.0, -1.0, 0.25]), "(0, -1, 0.25)");
    }

    #[test]
    fn length_and_angle_hold_at_any_scale() {
        let t = DVec3::new(0.6, -0.8, 0.0);
        let off = DVec3::new(0.6 + 6e-6, -0.8, 0.0);
        assert!((angle(off * 1e201, t) - 4.8e-6).abs() < 1e-7);
        assert!((length(t * 4e-320) / 4e-320 - 1.0).abs() < 1e-3);
        assert!(length(t * 4e-320) > 0.0 && (length(t * 1e300) / 1e300 - 1.0).abs() < 1e-15);
        assert!((angle(DVec3::Z * 1e-310, DVec3::Z) - 0.0).abs() < 1e-15);
    }
}

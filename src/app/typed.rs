//! Typed input: a text field that follows the state while the user is not editing it, applies
//! what was typed, if it differs, on Enter (or when focus leaves), and shows an inline error instead when the
//! text is refused, keeping the last good state.

use core::fmt;

use egui::{RichText, TextEdit, Ui};
use glam::DVec3;

use super::paint::verdict_colour;
use refraction_i18n::t;

/// One typed field: its text and the error of the last attempt to apply it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct TypedField {
    /// What is in the field.
    pub text: String,
    /// Why the last text typed was refused.
    pub error: Option<String>,
    /// The value the field followed when its error was shown: once the value changes by other
    /// means (a slider, a drag), the error is stale and goes.
    errored_at: Option<String>,
}

impl TypedField {
    /// Shows the field labelled `label`, showing `current` when not being edited. Returns the
    /// text to apply when the user confirmed an edit.
    pub(super) fn show(
        &mut self,
        ui: &mut Ui,
        label: &str,
        current: String,
        width: f32,
    ) -> Option<String> {
        let mut submitted = None;
        if self.error.is_some() {
            let at = self.errored_at.get_or_insert_with(|| current.clone());
            if *at != current {
                self.error = None;
            }
        }
        if self.error.is_none() {
            self.errored_at = None;
        }
        ui.horizontal(|ui| {
            let name = ui.label(label);
            let response = ui
                .add(TextEdit::singleline(&mut self.text).desired_width(width))
                .labelled_by(name.id);
            if response.lost_focus() {
                if self.text.trim() == current {
                    self.error = None;
                } else {
                    submitted = Some(self.text.trim().to_owned());
                }
            } else if !response.has_focus() && self.error.is_none() {
                self.text = current;
            }
        });
        if let Some(error) = &self.error {
            error_label(ui, error);
        }
        submitted
    }

    /// Records the outcome of applying the text: an error is shown, in words, until the next
    /// success.
    pub(super) fn show_outcome(&mut self, outcome: Result<(), impl fmt::Display>) {
        self.error = outcome.err().map(|error| error.to_string());
    }
}

/// Why something typed or asked for was refused, as it is shown: after ⚠, in the alarm colour.
pub(super) fn warning(ui: &Ui, message: &str) -> RichText {
    RichText::new(format!("⚠ {message}")).color(verdict_colour(ui, false))
}

/// Shows why something typed or asked for was refused ([`warning`]).
pub(super) fn error_label(ui: &mut Ui, message: &str) {
    ui.label(warning(ui, message));
}

/// Why a typed number or vector was refused: the field's name and what was typed, worded when
/// shown, in the window's language.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub(super) enum TypedError {
    /// A word that is not a number.
    #[error("{}", t!("typed-not-a-number", name = name, text = text))]
    NotANumber {
        /// The field's name (`θi`, `W`).
        name: String,
        /// The word typed.
        text: String,
    },
    /// A vector of other than three numbers.
    #[error("{}", t!("typed-not-three-numbers", name = name, count = *count))]
    NotThree {
        /// The vector's name.
        name: String,
        /// How many numbers were typed.
        count: usize,
    },
}

/// Parses a number as typed, with a decimal point or a decimal comma whatever the language
/// (`NaN` and `inf` parse, for the kernel to refuse by name).
///
/// # Errors
/// The text is not a number.
pub(super) fn parse_number(text: &str, name: &str) -> Result<f64, TypedError> {
    refraction_i18n::read_number(text).ok_or_else(|| TypedError::NotANumber {
        name: name.to_owned(),
        text: text.to_owned(),
    })
}

/// Parses a 3D vector typed as `x, y, z` (commas and/or spaces, optional brackets), or with
/// decimal commas as `x; y; z` or `x, y, z` with spaces after the commas (`0,6; −0,8; 0` and
/// `0,6, −0,8, 0` are both (0.6, −0.8, 0)).
///
/// # Errors
/// Not exactly three numbers; the message names the vector.
pub(super) fn parse_vector(text: &str, name: &str) -> Result<DVec3, TypedError> {
    let inner = text.trim_matches(|c: char| "[]() ".contains(c));
    let words = |separators: &[char]| -> Vec<&str> {
        inner
            .split(|c: char| separators.contains(&c) || c.is_whitespace())
            .map(|s| s.trim_matches(','))
            .filter(|s| !s.is_empty())
            .collect()
    };
    // Decimal commas first: a comma inside a number, spaces or semicolons between numbers.
    let local = words(&[';']);
    let parts = if local.len() == 3
        && local
            .iter()
            .all(|p| refraction_i18n::read_number(p).is_some())
    {
        local
    } else {
        words(&[',', ';'])
    };
    if parts.len() != 3 {
        return Err(TypedError::NotThree {
            name: name.to_owned(),
            count: parts.len(),
        });
    }
    let mut v = [0.0; 3];
    for (slot, part) in v.iter_mut().zip(&parts) {
        *slot = parse_number(part, name)?;
    }
    Ok(DVec3::from_array(v))
}

/// A vector as `x, y, z` with enough digits to read back what a student logged, written the
/// language's way (`x; y; z` where the decimal separator is a comma).
#[must_use]
pub(super) fn format_vector(v: DVec3) -> String {
    let separator = refraction_i18n::locale().list_separator();
    let [x, y, z] = [v.x, v.y, v.z].map(short);
    format!("{x}{separator}{y}{separator}{z}")
}

/// A number with at most 6 decimals and no trailing zeros, with the language's decimal
/// separator.
#[must_use]
pub(super) fn short(x: f64) -> String {
    let text = format!("{x:.6}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".to_owned()
    } else {
        refraction_i18n::decimal(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_error_goes_once_the_value_changes_by_other_means() {
        // Issue 32: "0.1, 0.9, 0.2" typed into μt was refused, and the error stayed after the
        // slider had set μt.
        let ctx = egui::Context::default();
        let mut field = TypedField::default();
        let frame = |field: &mut TypedField, current: &str| {
            let _ = ctx.run_ui(egui::RawInput::default(), |ui| {
                field.show(ui, "μt value", current.to_owned(), 90.0);
            });
        };
        frame(&mut field, "1.5");
        field.text = "0.1, 0.9, 0.2".to_owned();
        field.show_outcome(parse_number(&field.text, "μt").map(drop));
        assert!(
            field
                .error
                .as_deref()
                .is_some_and(|e| e.contains("not a number"))
        );
        frame(&mut field, "1.5");
        assert!(
            field.error.is_some(),
            "the value is as it was: the error stays"
        );
        frame(&mut field, "1.333");
        assert_eq!(field.error, None, "the slider set μt: the error is stale");
        assert_eq!(field.text, "1.333");
    }

    #[test]
    fn vectors_and_numbers_parse_with_clear_errors() {
        assert_eq!(
            parse_vector("[0.6, -0.8 0]", "W").unwrap(),
            DVec3::new(0.6, -0.8, 0.0)
        );
        assert_eq!(
            parse_vector("1, 2", "N").unwrap_err().to_string(),
            "N: expected three numbers x, y, z, got 2"
        );
        assert_eq!(
            parse_vector("1, x, 2", "N").unwrap_err().to_string(),
            "N: “x” is not a number"
        );
        assert!(parse_number("NaN", "μt").unwrap().is_nan());
        assert_eq!(
            format_vector(DVec3::new(0.5, -0.0, 1.0 / 3.0)),
            "0.5, 0, 0.333333"
        );
    }

    #[test]
    fn german_numbers_and_vectors_are_written_and_read_with_a_decimal_comma() {
        refraction_i18n::set_locale(refraction_i18n::Locale::De);
        let written = (short(-0.8), format_vector(DVec3::new(0.6, -0.8, 0.0)));
        let read = (
            parse_number("1,5", "μt"),
            parse_vector("0,6; -0,8; 0", "W"),
            parse_vector("0,6, -0,8, 0", "W"),
            parse_vector(&written.1, "W"),
        );
        let refused = parse_number("1,5x", "μt").unwrap_err().to_string();
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
        assert_eq!(written.0, "-0,8");
        assert_eq!(written.1, "0,6; -0,8; 0");
        let w = DVec3::new(0.6, -0.8, 0.0);
        assert_eq!(read.0, Ok(1.5));
        assert_eq!((read.1, read.2, read.3), (Ok(w), Ok(w), Ok(w)));
        assert!(refused.contains("keine Zahl"), "{refused}");
        assert_eq!(parse_vector("0.6,-0.8,0", "W"), Ok(w), "points still read");
    }
}

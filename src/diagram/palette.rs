//! The explorer's colours (Okabe–Ito hues, which stay distinct for the common colour-vision
//! deficiencies) and how numbers are written in labels.

use super::geometry::Colour;

/// The canvas background.
pub const BACKGROUND: Colour = Colour::hex(0xFFFFFF);
/// Dark text and the surface line.
pub const INK: Colour = Colour::hex(0x202020);
/// Reference lines (the normal's axis, the index scale).
pub const GUIDE: Colour = Colour::hex(0x8A8A8A);
/// The incoming ray.
pub const INCOMING: Colour = Colour::hex(0x555555);
/// W.
pub const W: Colour = Colour::hex(0xE69F00);
/// N.
pub const N: Colour = Colour::hex(0x009E73);
/// T, the refracted ray.
pub const T: Colour = Colour::hex(0x0072B2);
/// The reflected ray.
pub const REFLECTED: Colour = Colour::hex(0xCC79A7);
/// The rejected candidates.
pub const REJECTED: Colour = Colour::hex(0x6E6E6E);
/// The source's formula with the un-flipped normal (the bug's wrong T) and other warnings.
pub const WARNING: Colour = Colour::hex(0xD55E00);
/// The critical-angle line.
pub const CRITICAL: Colour = Colour::hex(0x7B3294);
/// The total-internal-reflection banner.
pub const ALARM: Colour = Colour::hex(0xB00020);
/// The ordinary banner.
pub const CALM: Colour = Colour::hex(0xEEF2F6);
/// A medium with index 1.
pub const THIN_MEDIUM: Colour = Colour::hex(0xF6F9FC);
/// A medium with the index at the top of the scale.
pub const DENSE_MEDIUM: Colour = Colour::hex(0x8DB6DC);
/// White light traced at one wavelength (no dispersion asked for): neutral on the light canvas.
pub const WHITE_LIGHT: Colour = Colour::hex(0x767676);
/// Beyond the world rectangle of a scene, where no ray goes.
pub const OUTSIDE_WORLD: Colour = Colour::hex(0xE2E5E9);
/// Behind labels.
pub const LABEL_BACKGROUND: Colour = Colour::hex(0xFFFFFF).with_alpha(210);

/// A darker shade of an arrow colour, for text in that colour on a light background.
#[must_use]
pub fn text_shade(colour: Colour) -> Colour {
    colour.lerp(Colour::hex(0x000000), 0.35)
}

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

//! The colour of a traced ray: its wavelength's hue, darkened where a bright hue (yellow, green)
//! would vanish on the light canvas and toward either end of the spectrum; white light traced
//! once is a neutral grey.

use super::geometry::Colour;
use super::palette;

/// The darkest the visible spectrum is drawn at either end (where the eye is least sensitive).
const END_FADE: f64 = 0.35;

/// The highest luminance (0–1, Rec. 709 weights on the encoded channels) a ray colour keeps, so
/// that yellow and green rays stay readable on a white background.
const MAX_LUMINANCE: f64 = 0.55;

/// The sRGB colour of monochromatic light of `nm` nanometres (clamped to 380–780 nm: ultraviolet
/// is drawn violet and infrared deep red), kept readable on the light canvas. A non-finite
/// wavelength is drawn as white light.
#[must_use]
pub fn wavelength_colour(nm: f64) -> Colour {
    if !nm.is_finite() {
        return palette::WHITE_LIGHT;
    }
    let x = nm.clamp(380.0, 780.0);
    // A piecewise-linear walk round the hue circle (after Dan Bruton's approximation).
    let (r, g, b) = if x < 440.0 {
        ((440.0 - x) / 60.0, 0.0, 1.0)
    } else if x < 490.0 {
        (0.0, (x - 440.0) / 50.0, 1.0)
    } else if x < 510.0 {
        (0.0, 1.0, (510.0 - x) / 20.0)
    } else if x < 580.0 {
        ((x - 510.0) / 70.0, 1.0, 0.0)
    } else if x < 645.0 {
        (1.0, (645.0 - x) / 65.0, 0.0)
    } else {
        (1.0, 0.0, 0.0)
    };
    let fade = if x < 420.0 {
        END_FADE + (1.0 - END_FADE) * (x - 380.0) / 40.0
    } else if x > 645.0 {
        // Through the reds, so that deep red (700 nm) is told from red (650 nm).
        END_FADE + (1.0 - END_FADE) * (780.0 - x) / 135.0
    } else {
        1.0
    };
    let luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    let scale = fade * (MAX_LUMINANCE / luminance).min(1.0);
    let channel = |c: f64| ((c * scale).powf(0.8) * 255.0).round() as u8;
    Colour {
        r: channel(r),
        g: channel(g),
        b: channel(b),
        a: 255,
    }
}

/// The colour a ray of this traced light is drawn in.
#[must_use]
pub fn ray_colour(light: refraction_scene::Light) -> Colour {
    light
        .wavelength_nm()
        .map_or(palette::WHITE_LIGHT, wavelength_colour)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spectrum_runs_from_violet_through_green_to_red() {
        let violet = wavelength_colour(400.0);
        assert!(violet.b > violet.g && violet.r > violet.g);
        let green = wavelength_colour(530.0);
        assert!(green.g > green.r && green.g > green.b);
        let red = wavelength_colour(650.0);
        assert!(red.r > 200 && red.g == 0 && red.b == 0);
        let deep_red = wavelength_colour(700.0);
        assert!(deep_red.g == 0 && deep_red.b == 0 && red.r - deep_red.r >= 40);
        assert_eq!(wavelength_colour(200.0), wavelength_colour(380.0));
        assert_eq!(wavelength_colour(f64::NAN), palette::WHITE_LIGHT);
        assert_eq!(
            ray_colour(refraction_scene::Light::White),
            palette::WHITE_LIGHT
        );
    }

    #[test]
    fn bright_hues_are_darkened_to_stay_readable_on_white() {
        for nm in (380..=780).step_by(5) {
            let c = wavelength_colour(f64::from(nm));
            let luminance =
                (0.2126 * f64::from(c.r) + 0.7152 * f64::from(c.g) + 0.0722 * f64::from(c.b))
                    / 255.0;
            assert!(luminance < 0.7, "{nm} nm: {c:?}");
        }
    }
}

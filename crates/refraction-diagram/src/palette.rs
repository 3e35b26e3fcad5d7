//! The explorer's colours (Okabe–Ito hues, which stay distinct for the common colour-vision
//! deficiencies) and how numbers are written in labels.
//!
//! The constants are the standard light palette, which the egui panels use too. [`Palette`]
//! gathers them so that the diagram can also be drawn in the high-contrast light and dark
//! themes of presentation mode, or with the strictly colour-blind-safe choice, in which every
//! ray also has its own dash pattern and label.

use refraction_i18n::t;

use super::geometry::Colour;
use super::shapes::Dash;

/// The canvas background.
pub const BACKGROUND: Colour = Colour::hex(0xFFFFFF);
/// Dark text and the surface line.
pub const INK: Colour = Colour::hex(0x202020);
/// Reference lines (the normal's axis, the index scale).
pub(crate) const GUIDE: Colour = Colour::hex(0x8A8A8A);
/// The incoming ray.
pub(crate) const INCOMING: Colour = Colour::hex(0x555555);
/// W.
pub const W: Colour = Colour::hex(0xE69F00);
/// N.
pub const N: Colour = Colour::hex(0x009E73);
/// T, the refracted ray.
pub const T: Colour = Colour::hex(0x0072B2);
/// The reflected ray.
pub(crate) const REFLECTED: Colour = Colour::hex(0xCC79A7);
/// The rejected candidates.
pub(crate) const REJECTED: Colour = Colour::hex(0x6E6E6E);
/// The paper's formula with the un-flipped normal (the bug's wrong T) and other warnings.
pub(crate) const WARNING: Colour = Colour::hex(0xD55E00);
/// The critical-angle line.
pub(crate) const CRITICAL: Colour = Colour::hex(0x7B3294);
/// The total-internal-reflection banner.
pub(crate) const ALARM: Colour = Colour::hex(0xB00020);
/// The ordinary banner.
pub(crate) const CALM: Colour = Colour::hex(0xEEF2F6);
/// A medium with index 1.
pub(crate) const THIN_MEDIUM: Colour = Colour::hex(0xF6F9FC);
/// A medium with the index at the top of the scale.
pub(crate) const DENSE_MEDIUM: Colour = Colour::hex(0x8DB6DC);
/// White light traced at one wavelength (no dispersion asked for): neutral on the light canvas.
pub(crate) const WHITE_LIGHT: Colour = Colour::hex(0x767676);
/// Beyond the world rectangle of a scene, where no ray goes.
pub(crate) const OUTSIDE_WORLD: Colour = Colour::hex(0xE2E5E9);
/// Behind labels.
pub(crate) const LABEL_BACKGROUND: Colour = Colour::hex(0xFFFFFF).with_alpha(210);

/// The student's T drawn beside the right one.
pub(crate) const STUDENT: Colour = Colour::hex(0x000000);
/// The halo behind what a walk-through step is about.
pub(crate) const HIGHLIGHT: Colour = Colour::hex(0xF0E442).with_alpha(170);

/// The diagram's themes: the standard look and the two high-contrast ones for a projector.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Theme {
    /// Soft media shading on white.
    #[default]
    Standard,
    /// Black on white, darker hues, stronger shading.
    HighContrastLight,
    /// White on black, lighter hues.
    HighContrastDark,
}

impl Theme {
    /// Every theme, in the order of the menu.
    pub const ALL: [Self; 3] = [
        Self::Standard,
        Self::HighContrastLight,
        Self::HighContrastDark,
    ];

    /// The theme's name in the menu, in the current language.
    #[must_use]
    pub fn label(self) -> String {
        match self {
            Self::Standard => t!("diagram-theme-standard"),
            // Short, so that the presentation bar keeps to two rows at 1280×720.
            Self::HighContrastLight => t!("diagram-theme-black-on-white"),
            Self::HighContrastDark => t!("diagram-theme-white-on-black"),
        }
    }

    /// The theme's name in saved settings: the same in every language, so that a look saved
    /// in one language is read back in another (the English names of earlier versions).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            // untranslated: the name saved in settings, the same in every language.
            Self::Standard => "Standard",
            // untranslated: the name saved in settings, the same in every language.
            Self::HighContrastLight => "Black on white",
            // untranslated: the name saved in settings, the same in every language.
            Self::HighContrastDark => "White on black",
        }
    }

    /// Whether the background is dark.
    #[must_use]
    pub(crate) fn is_dark(self) -> bool {
        self == Self::HighContrastDark
    }
}

/// Every colour the diagram uses, and the dash patterns of the rays that have no other.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Palette {
    /// The canvas background.
    pub background: Colour,
    /// Text and the surface line.
    pub ink: Colour,
    /// Reference lines.
    pub guide: Colour,
    /// The incoming ray.
    pub incoming: Colour,
    /// W.
    pub w: Colour,
    /// N.
    pub n: Colour,
    /// T.
    pub t: Colour,
    /// The reflected ray.
    pub reflected: Colour,
    /// The rejected candidates.
    pub rejected: Colour,
    /// The outward-normal bug's T.
    pub warning: Colour,
    /// The critical-angle line.
    pub critical: Colour,
    /// The total-internal-reflection banner.
    pub alarm: Colour,
    /// Text on the alarm banner.
    pub on_alarm: Colour,
    /// The ordinary banner.
    pub calm: Colour,
    /// A medium with index 1.
    pub thin_medium: Colour,
    /// A medium at the top of the index scale.
    pub dense_medium: Colour,
    /// Behind labels.
    pub label_background: Colour,
    /// The student's T.
    pub student: Colour,
    /// The halo of a walk-through step.
    pub highlight: Colour,
    /// What text in a ray's colour is shaded toward, for legibility on the background.
    pub text_toward: Colour,
    /// Beyond a scene's world rectangle.
    pub outside_world: Colour,
    /// White light traced at one wavelength, in a scene.
    pub white_light: Colour,
    /// The incoming ray's dash.
    pub incoming_dash: Dash,
    /// The reflected ray's dash.
    pub reflected_dash: Dash,
    /// Seven hues for the series of a plot (the accuracy plot's variants), apart from each
    /// other and readable on the background: the rays' hues and ink.
    pub series: [Colour; 7],
}

impl Palette {
    /// The standard light palette: the module's constants.
    pub const STANDARD: Self = Self {
        background: BACKGROUND,
        ink: INK,
        guide: GUIDE,
        incoming: INCOMING,
        w: W,
        n: N,
        t: T,
        reflected: REFLECTED,
        rejected: REJECTED,
        warning: WARNING,
        critical: CRITICAL,
        alarm: ALARM,
        on_alarm: BACKGROUND,
        calm: CALM,
        thin_medium: THIN_MEDIUM,
        dense_medium: DENSE_MEDIUM,
        label_background: LABEL_BACKGROUND,
        student: STUDENT,
        highlight: HIGHLIGHT,
        text_toward: Colour::hex(0x000000),
        outside_world: OUTSIDE_WORLD,
        white_light: WHITE_LIGHT,
        // Every palette, not only the colour-blind one, tells the rays apart by stroke too: the
        // incoming ray is thin and solid (T is bold and solid, the ghosts are dashed, dotted
        // and dash-dotted), the reflected ray dash-dot-dotted.
        incoming_dash: Dash::Solid,
        reflected_dash: Dash::DashDotDot,
        series: [W, T, N, REFLECTED, WARNING, CRITICAL, INK],
    };

    /// The palette of `theme`; `colour_blind_safe` keeps to the eight Okabe–Ito colours.
    #[must_use]
    pub fn new(theme: Theme, colour_blind_safe: bool) -> Self {
        let base = Self::of_theme(theme);
        if !colour_blind_safe {
            return base;
        }
        // Okabe–Ito: orange, bluish green, blue (sky blue on black), reddish purple,
        // vermillion, yellow; black or white for everything without a hue. A plot's sixth
        // series takes the hue T leaves: sky blue on white, yellow on black.
        let (t, sixth) = if theme.is_dark() {
            (0x56B4E9, 0xF0E442)
        } else {
            (0x0072B2, 0x56B4E9)
        };
        let [orange, blue, green, purple, vermillion, sixth] =
            [0xE69F00, t, 0x009E73, 0xCC79A7, 0xD55E00, sixth].map(Colour::hex);
        Self {
            w: orange,
            n: green,
            t: blue,
            reflected: purple,
            warning: vermillion,
            critical: base.ink,
            alarm: vermillion,
            highlight: Colour::hex(0xF0E442).with_alpha(150),
            series: [orange, blue, green, purple, vermillion, sixth, base.ink],
            ..base
        }
    }

    /// The palette of `theme` in its own hues.
    fn of_theme(theme: Theme) -> Self {
        let mut base = match theme {
            Theme::Standard => Self::STANDARD,
            Theme::HighContrastLight => Self {
                ink: Colour::hex(0x000000),
                guide: Colour::hex(0x4A4A4A),
                incoming: Colour::hex(0x303030),
                w: Colour::hex(0xB36B00),
                n: Colour::hex(0x00704F),
                t: Colour::hex(0x004F8C),
                reflected: Colour::hex(0x9C3F75),
                rejected: Colour::hex(0x4A4A4A),
                warning: Colour::hex(0xB34700),
                critical: Colour::hex(0x5A1F74),
                alarm: Colour::hex(0x9E0016),
                calm: Colour::hex(0xE4E4E4),
                thin_medium: Colour::hex(0xFFFFFF),
                dense_medium: Colour::hex(0x8CB8E2),
                label_background: Colour::hex(0xFFFFFF).with_alpha(235),
                ..Self::STANDARD
            },
            Theme::HighContrastDark => Self {
                background: Colour::hex(0x000000),
                ink: Colour::hex(0xFFFFFF),
                guide: Colour::hex(0xA8A8A8),
                incoming: Colour::hex(0xD0D0D0),
                w: Colour::hex(0xFFB000),
                n: Colour::hex(0x2BD9A4),
                t: Colour::hex(0x56B4E9),
                reflected: Colour::hex(0xE495C4),
                rejected: Colour::hex(0xA0A0A0),
                warning: Colour::hex(0xFF7A2F),
                critical: Colour::hex(0xC9A0DC),
                alarm: Colour::hex(0xC0002A),
                on_alarm: Colour::hex(0xFFFFFF),
                calm: Colour::hex(0x1C1C1C),
                thin_medium: Colour::hex(0x0A0A0A),
                dense_medium: Colour::hex(0x1E4E7E),
                label_background: Colour::hex(0x000000).with_alpha(215),
                student: Colour::hex(0xFFFFFF),
                highlight: Colour::hex(0xF0E442).with_alpha(120),
                text_toward: Colour::hex(0xFFFFFF),
                outside_world: Colour::hex(0x262626),
                white_light: Colour::hex(0xC8C8C8),
                ..Self::STANDARD
            },
        };
        base.series = [
            base.w,
            base.t,
            base.n,
            base.reflected,
            base.warning,
            base.critical,
            base.ink,
        ];
        base
    }

    /// A shade of an arrow colour for text in that colour: darker on a light background,
    /// lighter on a dark one, by a third at least and as far as it takes to read at 4.5:1 on
    /// the background (WCAG's least for text).
    #[must_use]
    pub fn text_shade(&self, colour: Colour) -> Colour {
        self.text_shade_on(colour, self.background)
    }

    /// [`Palette::text_shade`] on the fill `back` (a banner's) instead of the background.
    #[must_use]
    pub(crate) fn text_shade_on(&self, colour: Colour, back: Colour) -> Colour {
        (7_u8..=20)
            .map(|i| colour.lerp(self.text_toward, f32::from(i) / 20.0))
            .find(|shade| shade.over(back).contrast(back) >= 4.6)
            .unwrap_or(self.text_toward)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_in_a_rays_colour_reads_at_four_and_a_half_to_one_in_every_palette() {
        for theme in Theme::ALL {
            for safe in [false, true] {
                let p = Palette::new(theme, safe);
                for colour in [
                    p.w,
                    p.n,
                    p.t,
                    p.reflected,
                    p.warning,
                    p.critical,
                    p.alarm,
                    p.guide,
                ] {
                    let ratio = p.text_shade(colour).contrast(p.background);
                    assert!(ratio >= 4.5, "{theme:?} {safe}: {colour:?} gives {ratio}");
                }
            }
        }
    }

    #[test]
    fn every_palette_keeps_rays_apart_and_text_readable() {
        for theme in Theme::ALL {
            for safe in [false, true] {
                let p = Palette::new(theme, safe);
                let rays = [
                    p.incoming,
                    p.w,
                    p.n,
                    p.t,
                    p.reflected,
                    p.rejected,
                    p.student,
                ];
                for (i, a) in rays.iter().enumerate() {
                    assert!(rays[i + 1..].iter().all(|b| b != a), "{theme:?} {safe}");
                }
                assert_ne!(p.ink, p.background);
                assert_ne!(p.incoming_dash, p.reflected_dash);
                assert_ne!(p.outside_world, p.background);
                for (i, a) in p.series.iter().enumerate() {
                    assert!(p.series[i + 1..].iter().all(|b| b != a), "{theme:?} {safe}");
                    assert_ne!(*a, p.background, "{theme:?} {safe}");
                }
            }
        }
        assert_eq!(Palette::new(Theme::Standard, false), Palette::STANDARD);
    }
}

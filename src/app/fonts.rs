//! The window's fonts: egui's own, with Hack (egui's monospace font) behind Ubuntu Light in the
//! proportional family, so arrows such as "→" in a preset's name or a key hint are drawn
//! instead of as boxes (Ubuntu Light has no arrows).

use egui::{Context, FontDefinitions, FontFamily};

/// The font that covers arrows in egui's built-in set.
const ARROWS: &str = "Hack"; // untranslated: a font's name.

/// egui's fonts with [`ARROWS`] as the proportional family's first fallback.
fn definitions() -> FontDefinitions {
    let mut fonts = FontDefinitions::default();
    if let Some(family) = fonts.families.get_mut(&FontFamily::Proportional) {
        // After the primary font, before the icon and emoji fonts.
        family.insert(1.min(family.len()), ARROWS.to_owned());
    }
    fonts
}

/// Installs the window's fonts in `ctx`: call it before the first frame (fonts set later take
/// effect only on the next one).
pub fn install(ctx: &Context) {
    ctx.set_fonts(definitions());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrows_follow_the_primary_font_before_the_icons() {
        let fonts = definitions();
        let proportional = &fonts.families[&FontFamily::Proportional];
        assert_eq!(proportional[0], "Ubuntu-Light");
        assert_eq!(proportional[1], ARROWS);
        assert!(fonts.font_data.contains_key(ARROWS));
    }
}

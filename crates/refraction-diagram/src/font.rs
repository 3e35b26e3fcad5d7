//! The labels' font: egui's own default proportional font (Ubuntu Light, from
//! `epaint_default_fonts`), read with skrifa (the crate egui itself reads glyphs with). The
//! diagram measures labels with it to keep them inside the canvas; the PNG renderer outlines
//! them with it, so labels in the export look like labels on screen.

use std::collections::HashMap;
use std::sync::OnceLock;

use glam::Vec2;
use skrifa::instance::{LocationRef, Size};
use skrifa::outline::{DrawSettings, OutlinePen};
use skrifa::{FontRef, GlyphId, MetadataProvider as _};

/// A font at hand for measuring and outlining labels.
pub struct Typeface {
    font: FontRef<'static>,
    metrics: &'static Metrics,
}

/// The font's measures at size 1, read once per run: every view measures its labels many
/// times a frame (the placer tries spots), and reading them from the font each time is slow.
/// Unhinted measures scale linearly with the size.
struct Metrics {
    advances: HashMap<char, f32>,
    /// The advance of the glyph drawn for a character the font lacks.
    missing: f32,
    ascent: f32,
    line_height: f32,
}

static METRICS: OnceLock<Metrics> = OnceLock::new();

fn read_metrics(font: &FontRef<'_>) -> Metrics {
    let unit = Size::new(1.0);
    let glyphs = font.glyph_metrics(unit, LocationRef::default());
    let advances = font
        .charmap()
        .mappings()
        .filter_map(|(code, id)| {
            let ch = char::from_u32(code)?;
            Some((ch, glyphs.advance_width(id).unwrap_or(0.0)))
        })
        .collect();
    let m = font.metrics(unit, LocationRef::default());
    Metrics {
        advances,
        missing: glyphs.advance_width(GlyphId::NOTDEF).unwrap_or(0.0),
        ascent: m.ascent,
        line_height: m.ascent - m.descent + m.leading,
    }
}

/// Moves glyph outlines (y up, origin on the baseline) to their place on the canvas (y down)
/// before handing them on.
struct Placed<'a, P> {
    pen: &'a mut P,
    x: f32,
    baseline: f32,
}

impl<P> Placed<'_, P> {
    fn at(&self, x: f32, y: f32) -> (f32, f32) {
        (self.x + x, self.baseline - y)
    }
}

impl<P: OutlinePen> OutlinePen for Placed<'_, P> {
    fn move_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.pen.move_to(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.pen.line_to(x, y);
    }

    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        let (cx0, cy0) = self.at(cx0, cy0);
        let (x, y) = self.at(x, y);
        self.pen.quad_to(cx0, cy0, x, y);
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        let (cx0, cy0) = self.at(cx0, cy0);
        let (cx1, cy1) = self.at(cx1, cy1);
        let (x, y) = self.at(x, y);
        self.pen.curve_to(cx0, cy0, cx1, cy1, x, y);
    }

    fn close(&mut self) {
        self.pen.close();
    }
}

impl Typeface {
    /// egui's default proportional font. It is compiled in, so a build that runs has it: no
    /// caller needs a fallback.
    ///
    /// # Panics
    /// Only in a broken build, whose compiled-in font is not a font (this module's tests read
    /// it).
    #[must_use]
    pub fn egui_default() -> Self {
        let font = FontRef::new(epaint_default_fonts::UBUNTU_LIGHT)
            // untranslated: a broken build's message for developers, never caused by a user.
            .expect("egui's default font is compiled in and is a font");
        let metrics = METRICS.get_or_init(|| read_metrics(&font));
        Self { font, metrics }
    }

    fn glyph(&self, ch: char) -> GlyphId {
        self.font.charmap().map(ch).unwrap_or(GlyphId::NOTDEF)
    }

    /// Whether the font has a glyph for `ch`.
    #[must_use]
    pub fn covers(&self, ch: char) -> bool {
        self.glyph(ch) != GlyphId::NOTDEF
    }

    /// The distance from the top of a line to its baseline, in pixels at font size `size`.
    #[must_use]
    pub fn ascent(&self, size: f32) -> f32 {
        self.metrics.ascent * size
    }

    /// The height of one line, in pixels at font size `size`.
    #[must_use]
    pub fn line_height(&self, size: f32) -> f32 {
        self.metrics.line_height * size
    }

    /// The advance width of one line of text.
    #[must_use]
    pub fn width(&self, line: &str, size: f32) -> f32 {
        let m = self.metrics;
        let units: f32 = line
            .chars()
            .map(|ch| m.advances.get(&ch).copied().unwrap_or(m.missing))
            .sum();
        units * size
    }

    /// The size of the box of (possibly multi-line) text.
    #[must_use]
    pub fn measure(&self, text: &str, size: f32) -> Vec2 {
        let lines = text.lines().count().max(1);
        let width = text
            .lines()
            .map(|l| self.width(l, size))
            .fold(0.0, f32::max);
        Vec2::new(width, lines as f32 * self.line_height(size))
    }

    /// Draws the outlines of `text` with `pen`, in canvas pixels, with the text box's top-left
    /// corner at `top_left`. A glyph that fails to draw is left out.
    pub fn outline(&self, text: &str, top_left: Vec2, size: f32, pen: &mut impl OutlinePen) {
        let outlines = self.font.outline_glyphs();
        let metrics = self
            .font
            .glyph_metrics(Size::new(size), LocationRef::default());
        let line_height = self.line_height(size);
        for (row, line) in text.lines().enumerate() {
            let mut placed = Placed {
                pen: &mut *pen,
                x: top_left.x,
                baseline: top_left.y + self.ascent(size) + row as f32 * line_height,
            };
            for ch in line.chars() {
                let id = self.glyph(ch);
                if let Some(glyph) = outlines.get(id) {
                    let settings = DrawSettings::unhinted(Size::new(size), LocationRef::default());
                    // A glyph whose outline cannot be drawn (a broken glyph in the font) is
                    // left out, as documented: the rest of the label still reads.
                    glyph.draw(settings, &mut placed).ok();
                }
                placed.x += metrics.advance_width(id).unwrap_or(0.0);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Counts the pen's moves (one per contour) and where they land.
    #[derive(Default)]
    struct Count {
        contours: usize,
        lowest: f32,
    }

    impl OutlinePen for Count {
        fn move_to(&mut self, _: f32, y: f32) {
            self.contours += 1;
            self.lowest = self.lowest.max(y);
        }
        fn line_to(&mut self, _: f32, y: f32) {
            self.lowest = self.lowest.max(y);
        }
        fn quad_to(&mut self, _: f32, _: f32, _: f32, y: f32) {
            self.lowest = self.lowest.max(y);
        }
        fn curve_to(&mut self, _: f32, _: f32, _: f32, _: f32, _: f32, y: f32) {
            self.lowest = self.lowest.max(y);
        }
        fn close(&mut self) {}
    }

    #[test]
    fn the_labels_characters_are_in_the_font_and_measure_sensibly() {
        let face = Typeface::egui_default();
        for ch in "θμ°−√·²±≥ΔabWNT()".chars() {
            assert!(face.covers(ch), "{ch}");
        }
        let one = face.measure("W", 20.0);
        let two = face.measure("WW\nW", 20.0);
        assert!((two.x - 2.0 * one.x).abs() < 1e-3 && (two.y - 2.0 * one.y).abs() < 1e-3);
        let mut count = Count::default();
        face.outline("T\nT", Vec2::new(0.0, 100.0), 20.0, &mut count);
        assert_eq!(count.contours, 2);
        assert!(count.lowest > 100.0 + one.y && count.lowest < 100.0 + two.y);
    }
}

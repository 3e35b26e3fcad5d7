//! Text for the PNG: egui's own default proportional font (Ubuntu Light, from
//! `epaint_default_fonts`), outlined with skrifa (the crate egui itself rasterises glyphs with)
//! and filled by tiny-skia, so labels in the export look like labels on screen.

use glam::Vec2;
use skrifa::instance::{LocationRef, Size};
use skrifa::outline::{DrawSettings, OutlinePen};
use skrifa::{FontRef, GlyphId, MetadataProvider};
use tiny_skia::{Path, PathBuilder};

/// A font at hand for measuring and outlining labels.
pub struct Typeface {
    font: FontRef<'static>,
}

/// Turns font-unit outlines (y up, origin on the baseline) into canvas paths (y down).
struct Pen<'a> {
    path: &'a mut PathBuilder,
    x: f32,
    baseline: f32,
}

impl Pen<'_> {
    fn at(&self, x: f32, y: f32) -> (f32, f32) {
        (self.x + x, self.baseline - y)
    }
}

impl OutlinePen for Pen<'_> {
    fn move_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.path.move_to(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let (x, y) = self.at(x, y);
        self.path.line_to(x, y);
    }

    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        let (cx0, cy0) = self.at(cx0, cy0);
        let (x, y) = self.at(x, y);
        self.path.quad_to(cx0, cy0, x, y);
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        let (cx0, cy0) = self.at(cx0, cy0);
        let (cx1, cy1) = self.at(cx1, cy1);
        let (x, y) = self.at(x, y);
        self.path.cubic_to(cx0, cy0, cx1, cy1, x, y);
    }

    fn close(&mut self) {
        self.path.close();
    }
}

impl Typeface {
    /// egui's default proportional font.
    ///
    /// # Errors
    /// The embedded font cannot be read (a broken build).
    pub fn egui_default() -> Result<Self, String> {
        FontRef::new(epaint_default_fonts::UBUNTU_LIGHT)
            .map(|font| Self { font })
            .map_err(|e| format!("cannot read the embedded font: {e}"))
    }

    fn glyph(&self, ch: char) -> GlyphId {
        self.font.charmap().map(ch).unwrap_or(GlyphId::NOTDEF)
    }

    /// The distance from the top of a line to its baseline, in pixels at font size `size`.
    #[must_use]
    pub fn ascent(&self, size: f32) -> f32 {
        self.font
            .metrics(Size::new(size), LocationRef::default())
            .ascent
    }

    /// The height of one line, in pixels at font size `size`.
    #[must_use]
    pub fn line_height(&self, size: f32) -> f32 {
        let m = self.font.metrics(Size::new(size), LocationRef::default());
        m.ascent - m.descent + m.leading
    }

    /// The advance width of one line of text.
    #[must_use]
    pub fn width(&self, line: &str, size: f32) -> f32 {
        let metrics = self
            .font
            .glyph_metrics(Size::new(size), LocationRef::default());
        line.chars()
            .map(|ch| metrics.advance_width(self.glyph(ch)).unwrap_or(0.0))
            .sum()
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

    /// The outlines of `text` with its box's top-left corner at `top_left`, or `None` for text
    /// without ink (spaces only).
    #[must_use]
    pub fn outline(&self, text: &str, top_left: Vec2, size: f32) -> Option<Path> {
        let outlines = self.font.outline_glyphs();
        let metrics = self
            .font
            .glyph_metrics(Size::new(size), LocationRef::default());
        let mut path = PathBuilder::new();
        let line_height = self.line_height(size);
        for (row, line) in text.lines().enumerate() {
            let mut pen = Pen {
                path: &mut path,
                x: top_left.x,
                baseline: top_left.y + self.ascent(size) + row as f32 * line_height,
            };
            for ch in line.chars() {
                let id = self.glyph(ch);
                if let Some(glyph) = outlines.get(id) {
                    let settings = DrawSettings::unhinted(Size::new(size), LocationRef::default());
                    // A glyph that fails to draw is left out rather than failing the export.
                    let _ = glyph.draw(settings, &mut pen);
                }
                pen.x += metrics.advance_width(id).unwrap_or(0.0);
            }
        }
        path.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_labels_characters_are_in_the_font_and_measure_sensibly() {
        let face = Typeface::egui_default().unwrap();
        for ch in "θμ°−√·²±≥ΔabWNT()".chars() {
            assert_ne!(face.glyph(ch), GlyphId::NOTDEF, "{ch}");
        }
        let one = face.measure("W", 20.0);
        let two = face.measure("WW\nW", 20.0);
        assert!((two.x - 2.0 * one.x).abs() < 1e-3 && (two.y - 2.0 * one.y).abs() < 1e-3);
        assert!(face.outline("T", Vec2::ZERO, 20.0).is_some());
        assert!(face.outline("  ", Vec2::ZERO, 20.0).is_none());
    }
}

//! Labels as tiny-skia paths: the diagram's [`Typeface`] outlines them, this pen collects the
//! outlines into one path to fill.

use glam::Vec2;
use skrifa::outline::OutlinePen;
use tiny_skia::{Path, PathBuilder};

use refraction_diagram::Typeface;

/// Collects outlines into a tiny-skia path.
struct Collect(PathBuilder);

impl OutlinePen for Collect {
    fn move_to(&mut self, x: f32, y: f32) {
        self.0.move_to(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.0.line_to(x, y);
    }

    fn quad_to(&mut self, cx0: f32, cy0: f32, x: f32, y: f32) {
        self.0.quad_to(cx0, cy0, x, y);
    }

    fn curve_to(&mut self, cx0: f32, cy0: f32, cx1: f32, cy1: f32, x: f32, y: f32) {
        self.0.cubic_to(cx0, cy0, cx1, cy1, x, y);
    }

    fn close(&mut self) {
        self.0.close();
    }
}

/// The outlines of `text` with its box's top-left corner at `top_left`, or `None` for text
/// without ink (spaces only).
#[must_use]
pub(crate) fn outline(face: &Typeface, text: &str, top_left: Vec2, size: f32) -> Option<Path> {
    let mut pen = Collect(PathBuilder::new());
    face.outline(text, top_left, size, &mut pen);
    pen.0.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ink_makes_a_path_and_spaces_do_not() {
        let face = Typeface::egui_default();
        let path = outline(&face, "T", Vec2::new(10.0, 10.0), 20.0).unwrap();
        assert!(path.bounds().left() >= 10.0 && path.bounds().top() >= 10.0);
        assert!(outline(&face, "  ", Vec2::ZERO, 20.0).is_none());
    }
}

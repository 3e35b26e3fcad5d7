//! Where things go on a canvas of a given size: the banner strip, the index scale, the drawing
//! area, and the map between the world (the hit point at the origin, arrows of length 1, y up)
//! and canvas pixels.

use glam::{DVec2, Vec2};

use super::geometry::Rect;
use refraction_model::INDEX_RANGE;

/// The least and the most the diagram can be zoomed.
pub const ZOOM_RANGE: (f32, f32) = (0.4, 4.0);

/// How the view is moved from its fitted place: a shift of the hit point in canvas pixels and a
/// zoom factor about it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PanZoom {
    /// Canvas pixels the hit point moves by.
    pub pan: Vec2,
    /// Scale factor on the fitted size (within [`ZOOM_RANGE`]).
    pub zoom: f32,
}

impl Default for PanZoom {
    fn default() -> Self {
        Self {
            pan: Vec2::ZERO,
            zoom: 1.0,
        }
    }
}

impl PanZoom {
    /// Zooms by `factor` keeping the canvas point `fixed` (relative to the fitted hit point)
    /// where it is; the zoom stays within [`ZOOM_RANGE`] and non-finite factors are ignored.
    pub fn zoom_about(&mut self, factor: f32, fixed: Vec2) {
        if !factor.is_finite() || factor <= 0.0 {
            return;
        }
        let (low, high) = ZOOM_RANGE;
        let zoom = (self.zoom * factor).clamp(low, high);
        let applied = zoom / self.zoom;
        // The point under the pointer stays put: pan' = fixed − (fixed − pan)·applied.
        self.pan = fixed - (fixed - self.pan) * applied;
        self.zoom = zoom;
    }
}

/// The world↔canvas map of the drawing area.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewport {
    /// The canvas position of the hit point.
    pub origin: Vec2,
    /// Pixels per world unit (the length of W, N and T on screen).
    pub scale: f32,
}

impl Viewport {
    /// The canvas point of a world point.
    #[must_use]
    pub fn to_canvas(&self, world: DVec2) -> Vec2 {
        self.origin + Vec2::new(world.x as f32, -(world.y as f32)) * self.scale
    }

    /// The canvas direction of a world direction (same length in world units).
    #[must_use]
    pub fn direction(&self, world: DVec2) -> Vec2 {
        Vec2::new(world.x as f32, -(world.y as f32))
    }

    /// The map that shows the world rectangle `min`–`max` as large as fits in `rect`, centred,
    /// y up. A rectangle with no area (or not finite) is shown at 1 pixel per world unit.
    #[must_use]
    pub fn fitted(min: DVec2, max: DVec2, rect: &Rect) -> Self {
        let world = (max - min).as_vec2();
        let fit = (rect.size() / world).min_element();
        let scale = if fit.is_finite() && fit > 0.0 {
            fit
        } else {
            1.0
        };
        let center = (min + max) * 0.5;
        let center = if center.is_finite() {
            center
        } else {
            DVec2::ZERO
        };
        Self {
            origin: rect.center() - Vec2::new(center.x as f32, -(center.y as f32)) * scale,
            scale,
        }
    }

    /// The world point of a canvas point.
    #[must_use]
    pub fn to_world(&self, canvas: Vec2) -> DVec2 {
        let d = (canvas - self.origin) / self.scale;
        DVec2::new(f64::from(d.x), -f64::from(d.y))
    }
}

/// The vertical index scale at the right edge of the canvas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IndexScale {
    /// The x of the scale's line.
    pub x: f32,
    /// The y of [`INDEX_RANGE`]'s top (largest index).
    pub top: f32,
    /// The y of [`INDEX_RANGE`]'s bottom (smallest index).
    pub bottom: f32,
}

impl IndexScale {
    /// The y of an index (clamped to the scale).
    #[must_use]
    pub(crate) fn y_of(&self, index: f64) -> f32 {
        let (low, high) = INDEX_RANGE;
        let t = ((index - low) / (high - low)).clamp(0.0, 1.0) as f32;
        self.bottom + (self.top - self.bottom) * t
    }

    /// The index at height `y` (clamped to [`INDEX_RANGE`]), rounded to 0.001.
    #[must_use]
    pub(crate) fn index_at(&self, y: f32) -> f64 {
        let (low, high) = INDEX_RANGE;
        let t = f64::from((y - self.bottom) / (self.top - self.bottom));
        let t = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        };
        ((low + (high - low) * t) * 1000.0).round() / 1000.0
    }
}

/// The smallest text any view draws, in canvas pixels (points on screen): 13, so that text
/// reads at a glance at zoom 1 and is over 20 pixels in presentation (zoom 1.6).
pub const SMALLEST_TEXT: f32 = 13.0;

/// The label font size in pixels for a canvas `size` pixels wide and high: larger canvases
/// (a projector, a 1080p export) get larger text, within limits.
#[must_use]
pub(crate) fn font_size(size: Vec2) -> f32 {
    (size.min_element() / 48.0).clamp(13.0, 30.0)
}

/// The index scale's width in label font sizes: the material names (`diamond`) left of its
/// line and the μi marker, the μt marker and the values right of it.
pub(crate) const SCALE_WIDTH: f32 = 8.8;

/// Where everything goes on a canvas of one size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The whole canvas, from (0, 0).
    pub canvas: Rect,
    /// The strip at the top for the banner.
    pub banner: Rect,
    /// The area of the interface diagram (canvas minus banner and scale).
    pub drawing: Rect,
    /// The index scale, unless it is folded away (presentation's diagram-only key).
    pub scale: Option<IndexScale>,
    /// The world↔canvas map.
    pub view: Viewport,
    /// The label font size in pixels; strokes and handles scale with it.
    pub font: f32,
}

impl Layout {
    /// The layout of a canvas `size` pixels wide and high (sizes below 1 are treated as 1),
    /// with a banner two lines high.
    #[must_use]
    pub fn new(size: Vec2) -> Self {
        let size = size.max(Vec2::ONE);
        Self::with_banner(size, font_size(size) * 3.2, true)
    }

    /// The same canvas with a banner `height` pixels high (at most half the canvas), the
    /// drawing area and the index scale (if it has one) below it.
    #[must_use]
    pub(crate) fn with_banner_height(self, height: f32) -> Self {
        Self::with_banner(self.canvas.size(), height, self.scale.is_some())
    }

    /// The same canvas with the index scale folded away: the drawing takes its width too
    /// (presentation's diagram-only key).
    #[must_use]
    pub(crate) fn without_scale(self) -> Self {
        Self::with_banner(self.canvas.size(), self.banner.size().y, false)
    }

    fn with_banner(size: Vec2, height: f32, with_scale: bool) -> Self {
        let font = font_size(size);
        let canvas = Rect::from_min_size(Vec2::ZERO, size);
        let banner = Rect::from_min_size(Vec2::ZERO, Vec2::new(size.x, height.min(size.y * 0.5)));
        let scale_width = if with_scale { font * SCALE_WIDTH } else { 0.0 };
        let drawing = Rect {
            min: Vec2::new(0.0, banner.max.y),
            max: Vec2::new(
                (size.x - scale_width).max(1.0),
                size.y.max(banner.max.y + 1.0),
            ),
        };
        let scale = with_scale.then_some(IndexScale {
            x: size.x - font * 4.0,
            top: banner.max.y + font * 2.5,
            bottom: size.y - font * 2.5,
        });
        let view = Viewport {
            origin: drawing.center(),
            scale: drawing.size().min_element() * 0.36,
        };
        Self {
            canvas,
            banner,
            drawing,
            scale,
            view,
            font,
        }
    }

    /// The same layout with the view moved by `pan_zoom` (the hit point shifted, the world
    /// scaled about it).
    #[must_use]
    pub fn panned(mut self, pan_zoom: PanZoom) -> Self {
        self.view.origin += pan_zoom.pan;
        self.view.scale *= pan_zoom.zoom;
        self
    }

    /// One stroke-width unit in pixels.
    #[must_use]
    pub fn unit(&self) -> f32 {
        self.font / 14.0
    }

    /// The size in pixels of text `scale` times the label font, never below [`SMALLEST_TEXT`].
    #[must_use]
    pub(crate) fn text_size(&self, scale: f32) -> f32 {
        (self.font * scale).max(SMALLEST_TEXT)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zooming_keeps_the_fixed_point_and_stays_in_range() {
        let mut view = PanZoom::default();
        let fixed = Vec2::new(100.0, -40.0);
        view.zoom_about(2.0, fixed);
        // The point that was under `fixed` at zoom 1 is still there.
        let world = (fixed - view.pan) / view.zoom;
        assert!((world - fixed).length() < 1e-3, "{view:?}");
        view.zoom_about(1e9, Vec2::ZERO);
        assert_eq!(view.zoom, ZOOM_RANGE.1);
        view.zoom_about(f32::NAN, Vec2::ZERO);
        assert_eq!(view.zoom, ZOOM_RANGE.1);
    }

    #[test]
    fn world_and_canvas_round_trip_with_y_up() {
        let layout = Layout::new(Vec2::new(1920.0, 1080.0));
        let view = layout.view;
        let up = view.to_canvas(DVec2::Y);
        assert!(up.y < view.origin.y);
        assert!((view.to_world(up) - DVec2::Y).length() < 1e-6);
        assert!(
            layout
                .drawing
                .contains(view.to_canvas(DVec2::new(1.0, 1.0)))
        );
    }

    #[test]
    fn a_fitted_view_shows_the_whole_world_rectangle_centred() {
        let rect = Rect::from_min_size(Vec2::new(0.0, 100.0), Vec2::new(800.0, 400.0));
        let view = Viewport::fitted(DVec2::new(-4.0, -1.0), DVec2::new(4.0, 3.0), &rect);
        assert_eq!(view.scale, 100.0);
        assert_eq!(view.to_canvas(DVec2::new(0.0, 1.0)), rect.center());
        assert_eq!(view.to_canvas(DVec2::new(-4.0, 3.0)), Vec2::new(0.0, 100.0));
        let flat = Viewport::fitted(DVec2::ONE, DVec2::ONE, &rect);
        assert_eq!(flat.scale, 1.0);
        assert_eq!(flat.to_canvas(DVec2::ONE), rect.center());
    }

    #[test]
    fn the_index_scale_maps_both_ways_and_clamps() {
        let layout = Layout::new(Vec2::new(800.0, 600.0));
        let scale = layout.scale.unwrap();
        assert_eq!(scale.index_at(scale.y_of(1.5)), 1.5);
        assert_eq!(scale.index_at(-1e6), INDEX_RANGE.1);
        assert_eq!(scale.y_of(10.0), scale.top);
        assert!(Layout::new(Vec2::ZERO).view.scale > 0.0);
        let folded = layout.without_scale();
        assert_eq!(folded.scale, None);
        assert_eq!(
            folded.drawing.max.x, 800.0,
            "the drawing takes the scale's width"
        );
        assert_eq!(folded.banner, layout.banner);
    }
}

//! What a label must not cover ([`Obstacle`]: a box, a disc, an arrowhead, a ray's shaft), and
//! whether a label's box touches one: the one test the placer, its grid and the layout audit
//! ask.

use glam::Vec2;

use super::geometry::Rect;

/// Something a label must not cover.
#[derive(Clone, Debug, PartialEq)]
pub enum Obstacle {
    /// A box: a handle's grab area, a banner.
    Box(Rect),
    /// A disc: a hit marker, a plot marker.
    Disc {
        /// Centre.
        center: Vec2,
        /// Radius in pixels.
        radius: f32,
    },
    /// A convex polygon: an arrowhead.
    Polygon(Vec<Vec2>),
    /// A thick line: a ray's shaft, `half_width` pixels either side of `a`–`b`.
    Shaft {
        /// One end.
        a: Vec2,
        /// The other end.
        b: Vec2,
        /// Half the stroke's width, with a margin.
        half_width: f32,
        /// Whether a label that must be shown crosses it only as a last resort, where no
        /// other spot is left (a lesson's own rays: W, N and T).
        firm: bool,
    },
}

impl Obstacle {
    /// Whether the box `r` covers any part of this obstacle.
    #[must_use]
    pub fn touches(&self, r: &Rect) -> bool {
        match self {
            Self::Box(b) => b.overlaps(r),
            Self::Disc { center, radius } => center.clamp(r.min, r.max).distance(*center) < *radius,
            Self::Polygon(points) => convex_overlaps(points, r),
            Self::Shaft {
                a, b, half_width, ..
            } => shaft_touches(*a, *b, *half_width, r),
        }
    }
}

/// Whether the line `a`–`b` passes within `half_width` of the box `r` (touching counts): it
/// meets `r` grown by `half_width` where their boxes overlap and the grown box's corners are
/// not all on one side of the line. No division, as the placer asks it of many thousands of
/// ray segments a frame.
fn shaft_touches(a: Vec2, b: Vec2, half_width: f32, r: &Rect) -> bool {
    if !(a.is_finite() && b.is_finite()) {
        return false;
    }
    let (min, max) = (
        r.min - Vec2::splat(half_width),
        r.max + Vec2::splat(half_width),
    );
    if a.max(b).cmplt(min).any() || max.cmplt(a.min(b)).any() {
        return false;
    }
    let d = b - a;
    let sides = [min, Vec2::new(max.x, min.y), max, Vec2::new(min.x, max.y)]
        .map(|corner| d.perp_dot(corner - a));
    !(sides.iter().all(|&s| s > 0.0) || sides.iter().all(|&s| s < 0.0))
}

/// Whether the convex polygon `points` and the box `r` overlap (separating axis test: the box's
/// two axes and each edge's normal).
fn convex_overlaps(points: &[Vec2], r: &Rect) -> bool {
    if points.is_empty() {
        return false;
    }
    let corners = r.corners();
    let apart = |axis: Vec2| {
        let span = |ps: &mut dyn Iterator<Item = Vec2>| {
            ps.map(|p| p.dot(axis))
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), d| {
                    (lo.min(d), hi.max(d))
                })
        };
        let (a0, a1) = span(&mut points.iter().copied());
        let (b0, b1) = span(&mut corners.iter().copied());
        a1 <= b0 || b1 <= a0
    };
    let edges = points
        .iter()
        .zip(points.iter().cycle().skip(1))
        .map(|(a, b)| (*b - *a).perp());
    !core::iter::once(Vec2::X)
        .chain(core::iter::once(Vec2::Y))
        .chain(edges)
        .filter(|axis| axis.length_squared() > 0.0)
        .any(apart)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn discs_and_polygons_are_touched_only_where_they_are() {
        let r = Rect::from_min_size(Vec2::ZERO, Vec2::splat(10.0));
        let disc = |x: f32| Obstacle::Disc {
            center: Vec2::new(x, 5.0),
            radius: 3.0,
        };
        assert!(disc(12.0).touches(&r));
        assert!(!disc(13.5).touches(&r));
        let triangle = |dx: f32| {
            Obstacle::Polygon(
                [(11.0, 0.0), (20.0, 0.0), (20.0, 9.0)]
                    .map(|(x, y)| Vec2::new(x + dx, y))
                    .into(),
            )
        };
        assert!(!triangle(0.0).touches(&r));
        assert!(triangle(-5.0).touches(&r));
        // Near the corner but outside the slanted edge: the box's axes alone would say yes.
        let slanted = Obstacle::Polygon(vec![
            Vec2::new(12.0, 20.0),
            Vec2::new(20.0, 12.0),
            Vec2::new(20.0, 20.0),
        ]);
        assert!(!slanted.touches(&r));
        assert!(!Obstacle::Polygon(Vec::new()).touches(&r));
    }

    proptest! {
        #[test]
        fn a_shaft_touches_a_box_where_its_line_meets_the_grown_box(
            a in (-50.0_f32..150.0, -50.0_f32..150.0),
            b in (-50.0_f32..150.0, -50.0_f32..150.0),
            half_width in 0.0_f32..5.0,
            corner in (0.0_f32..100.0, 0.0_f32..100.0),
            size in (0.0_f32..60.0, 0.0_f32..60.0),
        ) {
            let (a, b) = (Vec2::new(a.0, a.1), Vec2::new(b.0, b.1));
            let r = Rect::from_min_size(Vec2::new(corner.0, corner.1), Vec2::new(size.0, size.1));
            let clipped = |grow: f32| {
                let grown = Rect {
                    min: r.min - Vec2::splat(half_width + grow),
                    max: r.max + Vec2::splat(half_width + grow),
                };
                crate::geometry::clip_segment(a, b, &grown).is_some()
            };
            let touches = shaft_touches(a, b, half_width, &r);
            // The same answer as clipping the line to the grown box, but where rounding
            // decides: within a hundredth of a pixel of its border.
            prop_assert!(!touches || clipped(0.01), "touches, yet the line misses");
            prop_assert!(touches || !clipped(-0.01), "the line meets it, yet no touch");
        }
    }
}

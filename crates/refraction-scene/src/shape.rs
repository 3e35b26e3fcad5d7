//! The 2D shapes of a scene: where a ray first crosses each one, the outward normal there, and
//! which points lie inside.
//!
//! Every shape but a screen is the boundary of a region filled with one medium. Normals point
//! out of the region whichever way the ray crosses, so that a ray leaving a sphere meets a
//! normal that points along it: the case the kernel must turn around.

use glam::DVec2;
use serde::Serialize;

use super::bounds::Bounds;
use super::outline::Piece;

/// The smallest ray parameter (in world units along a unit direction) counted as a crossing:
/// keeps a ray that has just crossed a boundary from crossing it again at t ≈ 0. Scenes are
/// meant to be laid out in units of order 1 to 1000.
pub const T_MIN: f64 = 1e-9;

/// A biconvex lens: the intersection of two discs, its optical axis along x.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Lens {
    /// The middle of the lens on its axis.
    pub center: DVec2,
    /// The thickness on the axis (> 0 and < 2·min(radii)).
    pub thickness: f64,
    /// The radii of curvature of the left (−x) and right (+x) surfaces (> 0).
    pub radii: [f64; 2],
}

impl Lens {
    /// The two circles (centre, radius): the left surface's first, the right surface's second.
    #[must_use]
    pub fn circles(&self) -> [(DVec2, f64); 2] {
        let [left, right] = self.radii;
        let half = self.thickness / 2.0;
        [
            (self.center + DVec2::new(left - half, 0.0), left),
            (self.center - DVec2::new(right - half, 0.0), right),
        ]
    }

    /// The smallest rectangle holding the lens: its rim, its two vertices on the axis, and the
    /// top and bottom of a surface that bulges past the rim (a surface more than half a circle,
    /// when the thickness is near twice a radius).
    #[must_use]
    pub fn extent(&self) -> Bounds {
        let half = DVec2::new(self.thickness / 2.0, 0.0);
        let circles = self.circles();
        let bulges = circles
            .iter()
            .enumerate()
            .flat_map(|(i, &(center, radius))| {
                let (other, other_radius) = circles[1 - i];
                [DVec2::Y, -DVec2::Y]
                    .map(|up| center + up * radius)
                    .into_iter()
                    .filter(move |p| p.distance(other) < other_radius)
            });
        self.rim()
            .into_iter()
            .chain([self.center - half, self.center + half])
            .chain(bulges)
            .map(Bounds::point)
            .fold(Bounds::point(self.center), Bounds::union)
    }

    /// The top and bottom rim, where the two surfaces meet.
    #[must_use]
    pub fn rim(&self) -> [DVec2; 2] {
        let [(c1, r1), (c2, r2)] = self.circles();
        // c1 lies right of c2 at distance r1 + r2 − thickness; measure from c1 toward c2.
        let gap = c1.x - c2.x;
        let along = (r1 * r1 - r2 * r2 + gap * gap) / (2.0 * gap);
        let half_chord = (r1 * r1 - along * along).max(0.0).sqrt();
        let x = c1.x - along;
        [
            DVec2::new(x, self.center.y + half_chord),
            DVec2::new(x, self.center.y - half_chord),
        ]
    }
}

/// One shape of a scene. Region shapes carry the index of their medium in the scene's list.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Shape {
    /// An infinite line; the region is the half-plane behind `normal`.
    Line {
        /// A point on the line.
        point: DVec2,
        /// The unit outward normal.
        normal: DVec2,
        /// The medium behind the line.
        medium: usize,
    },
    /// A screen: a segment that stops the rays that reach it (no medium, no refraction).
    Segment {
        /// One end.
        from: DVec2,
        /// The other end.
        to: DVec2,
    },
    /// A disc.
    Circle {
        /// Its centre.
        center: DVec2,
        /// Its radius (> 0).
        radius: f64,
        /// The medium inside.
        medium: usize,
    },
    /// A simple polygon.
    Polygon {
        /// Its vertices, counter-clockwise (at least 3, non-zero area).
        points: Vec<DVec2>,
        /// The medium inside.
        medium: usize,
    },
    /// A biconvex lens.
    Lens {
        /// Its geometry.
        lens: Lens,
        /// The medium inside.
        medium: usize,
    },
}

/// Where a ray crosses a shape's boundary.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The ray parameter: the crossing is at origin + t·direction (t > [`T_MIN`]).
    pub t: f64,
    /// The unit outward normal there (for a screen: the side facing the ray).
    pub normal: DVec2,
}

/// The ray parameters where the ray meets a circle, nearest first; `direction` is unit length.
fn circle_roots(center: DVec2, radius: f64, origin: DVec2, direction: DVec2) -> Option<[f64; 2]> {
    let f = origin - center;
    let b = f.dot(direction);
    // r² − |f − b·d|² keeps its digits when the ray passes far from the centre; b² − |f|² + r²
    // would cancel.
    let h2 = radius * radius - (f - b * direction).length_squared();
    (h2 >= 0.0).then(|| {
        let h = h2.sqrt();
        [-b - h, -b + h]
    })
}

/// The ray parameter where the ray meets the segment from `a` to `b`, if it does ahead.
fn segment_t(a: DVec2, b: DVec2, origin: DVec2, direction: DVec2) -> Option<f64> {
    let edge = b - a;
    let denominator = direction.perp_dot(edge);
    if denominator == 0.0 {
        return None;
    }
    let w = a - origin;
    let t = w.perp_dot(edge) / denominator;
    let s = w.perp_dot(direction) / denominator;
    ((0.0..=1.0).contains(&s) && t > T_MIN).then_some(t)
}

/// The outward unit normal of the edge `a → b` of a counter-clockwise polygon.
fn edge_normal(a: DVec2, b: DVec2) -> DVec2 {
    let e = b - a;
    DVec2::new(e.y, -e.x).normalize_or_zero()
}

fn edges(points: &[DVec2]) -> impl Iterator<Item = (DVec2, DVec2)> + '_ {
    points
        .iter()
        .copied()
        .zip(points.iter().copied().cycle().skip(1))
}

fn nearer(best: Option<Crossing>, t: f64, normal: impl FnOnce() -> DVec2) -> Crossing {
    match best {
        Some(b) if b.t <= t => b,
        _ => Crossing {
            t,
            normal: normal(),
        },
    }
}

/// The square that holds a disc.
fn disc_box(center: DVec2, radius: f64) -> Bounds {
    Bounds {
        min: center - DVec2::splat(radius),
        max: center + DVec2::splat(radius),
    }
}

/// The nearest crossing of a lens's two surfaces that `ahead` accepts: a point on one circle
/// that lies in the other disc.
fn lens_crossing(
    lens: &Lens,
    origin: DVec2,
    direction: DVec2,
    ahead: impl Fn(f64) -> bool,
) -> Option<Crossing> {
    let circles = lens.circles();
    let mut best = None;
    for (i, &(center, radius)) in circles.iter().enumerate() {
        let (other, other_radius) = circles[1 - i];
        let Some(roots) = circle_roots(center, radius, origin, direction) else {
            continue;
        };
        for t in roots.into_iter().filter(|&t| ahead(t)) {
            let p = origin + t * direction;
            if p.distance_squared(other) <= other_radius * other_radius * (1.0 + 1e-12) {
                // Normalised: a hit point's rounding, over a small radius, would leave it off unit.
                best = Some(nearer(best, t, || {
                    ((p - center) / radius).normalize_or_zero()
                }));
            }
        }
    }
    best
}

/// Whether the edge `a → b` crosses the half-line from `p` towards +x: one step of the
/// even-odd point-in-polygon test.
pub(crate) fn crosses_rightward(a: DVec2, b: DVec2, p: DVec2) -> bool {
    (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)
}

impl Shape {
    /// The medium inside, or `None` for a screen.
    #[must_use]
    pub fn medium(&self) -> Option<usize> {
        match self {
            Self::Segment { .. } => None,
            Self::Line { medium, .. }
            | Self::Circle { medium, .. }
            | Self::Polygon { medium, .. }
            | Self::Lens { medium, .. } => Some(*medium),
        }
    }

    /// The first crossing of the ray `origin + t·direction` (unit `direction`) with the
    /// boundary at t > [`T_MIN`]: the nearest crossing of any of its pieces (the first piece
    /// wins a tie).
    #[must_use]
    pub fn first_crossing(&self, origin: DVec2, direction: DVec2) -> Option<Crossing> {
        (0..self.piece_count()).fold(None, |best, piece| {
            self.piece_crossing(piece, origin, direction)
                .map_or(best, |c| Some(nearer(best, c.t, || c.normal)))
        })
    }

    /// How many pieces the tracer tests one by one: a polygon's edges, or the whole shape.
    pub(crate) fn piece_count(&self) -> usize {
        match self {
            Self::Polygon { points, .. } => points.len(),
            _ => 1,
        }
    }

    /// A polygon's edge `i`: from vertex `i` to the next.
    fn edge(points: &[DVec2], i: usize) -> (DVec2, DVec2) {
        (points[i], points[(i + 1) % points.len()])
    }

    /// The box that holds piece `piece` (for a lens, a box that holds it: the overlap of its
    /// discs' boxes), or `None` for a line, which has no end.
    pub(crate) fn piece_bounds(&self, piece: usize) -> Option<Bounds> {
        let segment = |a: DVec2, b: DVec2| Bounds {
            min: a.min(b),
            max: a.max(b),
        };
        match self {
            Self::Line { .. } => None,
            Self::Segment { from, to } => Some(segment(*from, *to)),
            Self::Circle { center, radius, .. } => Some(disc_box(*center, *radius)),
            Self::Polygon { points, .. } => {
                let (a, b) = Self::edge(points, piece);
                Some(segment(a, b))
            }
            Self::Lens { lens, .. } => {
                let [(c1, r1), (c2, r2)] = lens.circles();
                let (one, two) = (disc_box(c1, r1), disc_box(c2, r2));
                Some(Bounds {
                    min: one.min.max(two.min),
                    max: one.max.min(two.max),
                })
            }
        }
    }

    /// The first crossing of piece `piece` (see [`Self::piece_count`]) at t > [`T_MIN`] that
    /// lies in the piece's box (grown by a margin far wider than rounding; see `bounds`).
    pub(crate) fn piece_crossing(
        &self,
        piece: usize,
        origin: DVec2,
        direction: DVec2,
    ) -> Option<Crossing> {
        let ahead = |t: f64| {
            t > T_MIN
                && self
                    .piece_bounds(piece)
                    .is_none_or(|b| b.admits(origin, direction, t))
        };
        match self {
            Self::Line { point, normal, .. } => {
                let denominator = direction.dot(*normal);
                let t = (*point - origin).dot(*normal) / denominator;
                (t > T_MIN && t.is_finite()).then_some(Crossing { t, normal: *normal })
            }
            Self::Segment { from, to } => segment_t(*from, *to, origin, direction)
                .filter(|&t| ahead(t))
                .map(|t| {
                    let n = edge_normal(*from, *to);
                    Crossing {
                        t,
                        normal: if n.dot(direction) > 0.0 { -n } else { n },
                    }
                }),
            Self::Circle { center, radius, .. } => {
                let roots = circle_roots(*center, *radius, origin, direction)?;
                let t = roots.into_iter().find(|&t| ahead(t))?;
                Some(Crossing {
                    t,
                    // Normalised: a hit point's rounding, over a small radius, would leave it off unit.
                    normal: ((origin + t * direction - *center) / *radius).normalize_or_zero(),
                })
            }
            Self::Polygon { points, .. } => {
                let (a, b) = Self::edge(points, piece);
                segment_t(a, b, origin, direction)
                    .filter(|&t| ahead(t))
                    .map(|t| Crossing {
                        t,
                        normal: edge_normal(a, b),
                    })
            }
            Self::Lens { lens, .. } => lens_crossing(lens, origin, direction, ahead),
        }
    }

    /// Whether `p` lies strictly inside the region (never, for a screen).
    #[must_use]
    pub fn contains(&self, p: DVec2) -> bool {
        match self {
            Self::Line { point, normal, .. } => (p - *point).dot(*normal) < 0.0,
            Self::Segment { .. } => false,
            Self::Circle { center, radius, .. } => p.distance_squared(*center) < radius * radius,
            Self::Polygon { points, .. } => {
                edges(points).fold(false, |inside, (a, b)| inside != crosses_rightward(a, b, p))
            }
            Self::Lens { lens, .. } => lens
                .circles()
                .iter()
                .all(|&(c, r)| p.distance_squared(c) < r * r),
        }
    }

    /// A point that stands for the shape's position (centre, centroid of the vertices, midpoint
    /// of a screen, the given point of a line): where an editor puts its drag handle.
    #[must_use]
    pub fn anchor(&self) -> DVec2 {
        match self {
            Self::Line { point, .. } => *point,
            Self::Segment { from, to } => from.midpoint(*to),
            Self::Circle { center, .. }
            | Self::Lens {
                lens: Lens { center, .. },
                ..
            } => *center,
            Self::Polygon { points, .. } => {
                points.iter().copied().sum::<DVec2>() / points.len().max(1) as f64
            }
        }
    }

    /// The largest absolute coordinate of the points that place the shape (as a scene file
    /// gives them: a line's point, a segment's ends, a centre, a polygon's points).
    pub(crate) fn reach(&self) -> f64 {
        let reach = |p: &DVec2| p.abs().max_element();
        match self {
            Self::Line { point, .. } => reach(point),
            Self::Segment { from, to } => reach(from).max(reach(to)),
            Self::Circle { center, .. }
            | Self::Lens {
                lens: Lens { center, .. },
                ..
            } => reach(center),
            Self::Polygon { points, .. } => points.iter().map(reach).fold(0.0, f64::max),
        }
    }

    /// Moves the shape by `delta` world units.
    pub fn translate(&mut self, delta: DVec2) {
        match self {
            Self::Line { point, .. } => *point += delta,
            Self::Segment { from, to } => {
                *from += delta;
                *to += delta;
            }
            Self::Circle { center, .. }
            | Self::Lens {
                lens: Lens { center, .. },
                ..
            } => {
                *center += delta;
            }
            Self::Polygon { points, .. } => points.iter_mut().for_each(|p| *p += delta),
        }
    }

    /// The smallest rectangle holding the shape, or `None` for an infinite line.
    #[must_use]
    pub fn extent(&self) -> Option<Bounds> {
        let around = |center: DVec2, radius: f64| Bounds {
            min: center - DVec2::splat(radius),
            max: center + DVec2::splat(radius),
        };
        match self {
            Self::Line { .. } => None,
            Self::Segment { from, to } => Some(Bounds::point(*from).union(Bounds::point(*to))),
            Self::Circle { center, radius, .. } => Some(around(*center, *radius)),
            Self::Polygon { points, .. } => points
                .iter()
                .map(|&p| Bounds::point(p))
                .reduce(Bounds::union),
            Self::Lens { lens, .. } => Some(lens.extent()),
        }
    }

    /// The boundary as pieces in world coordinates; a line's half-plane is cut to `bounds`.
    #[must_use]
    pub fn pieces(&self, bounds: Bounds) -> Vec<Piece> {
        let polygon = |points: &[DVec2]| {
            edges(points)
                .map(|(from, to)| Piece::Segment { from, to })
                .collect()
        };
        match self {
            Self::Line { point, normal, .. } => polygon(&behind(bounds, *point, *normal)),
            Self::Segment { from, to } => vec![Piece::Segment {
                from: *from,
                to: *to,
            }],
            Self::Circle { center, radius, .. } => vec![Piece::Circle {
                center: *center,
                radius: *radius,
            }],
            Self::Polygon { points, .. } => polygon(points),
            Self::Lens { lens, .. } => {
                let [(c1, r1), (c2, r2)] = lens.circles();
                let [top, bottom] = lens.rim();
                vec![
                    Piece::Arc {
                        center: c1,
                        radius: r1,
                        from: top,
                        to: bottom,
                    },
                    Piece::Arc {
                        center: c2,
                        radius: r2,
                        from: bottom,
                        to: top,
                    },
                ]
            }
        }
    }
}

/// The part of the rectangle behind the line through `point` with normal `normal`, as a
/// counter-clockwise polygon (one step of Sutherland–Hodgman clipping).
fn behind(bounds: Bounds, point: DVec2, normal: DVec2) -> Vec<DVec2> {
    let corners = bounds.corners();
    let side = |p: DVec2| (p - point).dot(normal);
    let mut out = Vec::with_capacity(5);
    for (a, b) in edges(&corners) {
        let (sa, sb) = (side(a), side(b));
        if sa <= 0.0 {
            out.push(a);
        }
        if sa * sb < 0.0 {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Shape {
        Shape::Polygon {
            points: vec![
                DVec2::new(-1.0, -1.0),
                DVec2::new(1.0, -1.0),
                DVec2::new(1.0, 1.0),
                DVec2::new(-1.0, 1.0),
            ],
            medium: 1,
        }
    }

    #[test]
    fn a_ray_leaving_a_circle_meets_an_outward_normal_along_it() {
        let circle = Shape::Circle {
            center: DVec2::ZERO,
            radius: 2.0,
            medium: 1,
        };
        let enter = circle
            .first_crossing(DVec2::new(-5.0, 0.0), DVec2::X)
            .unwrap();
        assert!((enter.t - 3.0).abs() < 1e-15 && enter.normal == -DVec2::X);
        let leave = circle
            .first_crossing(DVec2::new(-2.0, 0.0), DVec2::X)
            .unwrap();
        assert!((leave.t - 4.0).abs() < 1e-15);
        assert!(leave.normal.dot(DVec2::X) > 0.0);
        assert!(circle.contains(DVec2::ONE) && !circle.contains(DVec2::splat(2.0)));
    }

    #[test]
    fn polygon_edges_give_outward_normals_and_the_nearest_hit() {
        let s = square();
        let c = s.first_crossing(DVec2::new(-3.0, 0.5), DVec2::X).unwrap();
        assert!((c.t - 2.0).abs() < 1e-15 && c.normal == -DVec2::X);
        let c = s.first_crossing(DVec2::new(0.0, 0.0), DVec2::Y).unwrap();
        assert!((c.t - 1.0).abs() < 1e-15 && c.normal == DVec2::Y);
        assert!(s.contains(DVec2::new(0.9, -0.9)) && !s.contains(DVec2::new(1.1, 0.0)));
    }

    #[test]
    fn a_lens_is_where_both_discs_overlap() {
        let lens = Lens {
            center: DVec2::new(1.0, 0.0),
            thickness: 0.5,
            radii: [3.0, 2.0],
        };
        let shape = Shape::Lens { lens, medium: 1 };
        let hit = shape
            .first_crossing(DVec2::new(-5.0, 0.0), DVec2::X)
            .unwrap();
        assert!((hit.t - 5.75).abs() < 1e-12 && (hit.normal + DVec2::X).length() < 1e-12);
        let out = shape
            .first_crossing(DVec2::new(1.0, 0.0), DVec2::X)
            .unwrap();
        assert!((out.t - 0.25).abs() < 1e-12 && (out.normal - DVec2::X).length() < 1e-12);
        let [top, bottom] = lens.rim();
        for (c, r) in lens.circles() {
            assert!((top.distance(c) - r).abs() < 1e-12);
            assert!((bottom.distance(c) - r).abs() < 1e-12);
        }
        assert!(
            shape
                .first_crossing(top + DVec2::new(-5.0, 0.1), DVec2::X)
                .is_none()
        );
        assert!(shape.contains(DVec2::new(1.0, 0.0)));
    }

    #[test]
    fn a_half_plane_is_cut_to_the_bounds() {
        let bounds = Bounds {
            min: DVec2::splat(-1.0),
            max: DVec2::splat(1.0),
        };
        let line = Shape::Line {
            point: DVec2::ZERO,
            normal: DVec2::Y,
            medium: 1,
        };
        let pieces = line.pieces(bounds);
        assert_eq!(pieces.len(), 4);
        assert!(pieces.iter().all(|p| match p {
            Piece::Segment { from, to } => from.y <= 0.0 && to.y <= 0.0,
            _ => false,
        }));
    }

    #[test]
    fn moving_a_shape_moves_its_anchor() {
        let mut s = square();
        s.translate(DVec2::new(2.0, 1.0));
        assert_eq!(s.anchor(), DVec2::new(2.0, 1.0));
    }
}

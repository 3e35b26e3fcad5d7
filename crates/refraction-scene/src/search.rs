//! How the tracer finds crossings and media: every shape's pieces in turn, as
//! [`Scene::first_crossing`] and [`Scene::medium_where`] do, counting the tests made so that a
//! trace keeps within its work budget ([`MAX_INTERSECTION_TESTS`]).
//!
//! A classroom scene has a few shapes (every built-in scene one to four, a teacher's a few
//! dozen at most, [`crate::MAX_SHAPES`]): a ray's crossing costs one test per piece, a few
//! dozen, which an acceleration structure would not make faster. The budget keeps a scene
//! that pushes the limits from holding the tracer for long.

use glam::DVec2;

use super::Scene;

/// The most intersection tests one trace makes (a ray or a point against a shape's piece, in
/// finding crossings and the media at hits); past it the trace stops and says so
/// ([`crate::Counts::truncated`]), so that no scene can keep the tracer busy for long (about
/// a second at this many on one core).
pub const MAX_INTERSECTION_TESTS: u64 = 100_000_000;

/// The crossings and media of one scene, with the tests made so far.
pub(crate) struct Search<'a> {
    scene: &'a Scene,
    /// The pieces every query tests: a polygon's edges, every other shape one.
    pieces: u64,
    tests: u64,
}

impl<'a> Search<'a> {
    /// A search over `scene`'s shapes.
    pub(crate) fn new(scene: &'a Scene) -> Self {
        let pieces = scene.shapes().iter().map(|s| s.piece_count() as u64).sum();
        Self {
            scene,
            pieces,
            tests: 0,
        }
    }

    /// The piece tests made so far.
    pub(crate) fn tests(&self) -> u64 {
        self.tests
    }

    /// The first boundary the ray `origin + t·direction` (unit `direction`) crosses:
    /// [`Scene::first_crossing`].
    pub(crate) fn first_crossing(
        &mut self,
        origin: DVec2,
        direction: DVec2,
    ) -> Option<(usize, super::Crossing)> {
        self.tests += self.pieces;
        self.scene.first_crossing(origin, direction)
    }

    /// The medium at `p`, with `on_boundary` = (shape, inside) deciding that shape's side:
    /// [`Scene::medium_where`].
    pub(crate) fn medium_where(&mut self, p: DVec2, on_boundary: Option<(usize, bool)>) -> usize {
        self.tests += self.pieces;
        self.scene.medium_where(p, on_boundary)
    }
}

/// The sign of the turn a → b → c: 1 counter-clockwise, −1 clockwise, 0 in a line.
fn turn(a: DVec2, b: DVec2, c: DVec2) -> i8 {
    let cross = (b - a).perp_dot(c - a);
    if cross > 0.0 {
        1
    } else if cross < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether `p`, in line with `a` and `b`, lies within their box (so on the segment).
fn on_segment(a: DVec2, b: DVec2, p: DVec2) -> bool {
    a.min(b).cmple(p).all() && p.cmple(a.max(b)).all()
}

/// Whether the segments a–b and c–d have a point in common.
fn segments_meet(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let (t1, t2) = (turn(a, b, c), turn(a, b, d));
    let (t3, t4) = (turn(c, d, a), turn(c, d, b));
    (t1 != t2 && t3 != t4)
        || (t1 == 0 && on_segment(a, b, c))
        || (t2 == 0 && on_segment(a, b, d))
        || (t3 == 0 && on_segment(c, d, a))
        || (t4 == 0 && on_segment(c, d, b))
}

/// Whether edges `i` < `j` of the closed polygon `points` meet anywhere but at the vertex that
/// neighbouring edges share (where they meet only if they fold back along each other).
fn edges_meet(points: &[DVec2], i: usize, j: usize) -> bool {
    let n = points.len();
    let edge = |k: usize| (points[k], points[(k + 1) % n]);
    let ((a, b), (c, d)) = (edge(i), edge(j));
    let fold = |shared: DVec2, one: DVec2, other: DVec2| {
        turn(shared, one, other) == 0 && (one - shared).dot(other - shared) > 0.0
    };
    if j == i + 1 {
        fold(b, a, d)
    } else if i == 0 && j == n - 1 {
        fold(a, b, c)
    } else {
        segments_meet(a, b, c, d)
    }
}

/// The first pair of edges (i, j), i < j, j as small as can be, at which the closed polygon
/// `points` crosses or touches itself, if it does: edge k runs from point k to the next, and
/// each is tested against the edges before it.
///
/// # Errors
/// The number of tests made, when it passes [`MAX_INTERSECTION_TESTS`] before an answer (a
/// polygon of tens of thousands of points; a scene file holds at most [`crate::MAX_POINTS`]).
pub(crate) fn first_self_crossing(points: &[DVec2]) -> Result<Option<(usize, usize)>, u64> {
    let mut tests = 0_u64;
    for j in 0..points.len() {
        for i in 0..j {
            tests += 1;
            if edges_meet(points, i, j) {
                return Ok(Some((i, j)));
            }
        }
        if tests > MAX_INTERSECTION_TESTS {
            return Err(MAX_INTERSECTION_TESTS);
        }
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polygon_that_crosses_or_folds_onto_itself_is_found() {
        let at = |xy: &[(f64, f64)]| {
            xy.iter()
                .map(|&(x, y)| DVec2::new(x, y))
                .collect::<Vec<_>>()
        };
        let square = at(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        assert_eq!(first_self_crossing(&square), Ok(None));
        let bow_tie = at(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        assert_eq!(first_self_crossing(&bow_tie), Ok(Some((0, 2))));
        // Two squares touching at a corner: a figure of eight through (1, 1).
        let touching = at(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (1.0, 1.0),
            (2.0, 1.0),
            (2.0, 2.0),
            (1.0, 2.0),
            (1.0, 1.0),
            (0.0, 1.0),
        ]);
        assert!(first_self_crossing(&touching).unwrap().is_some());
        // A spike folding back along its own edge.
        let spike = at(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (1.0, 1.0)]);
        assert_eq!(first_self_crossing(&spike), Ok(Some((0, 1))));
        let n = 2_000;
        let round: Vec<DVec2> = (0..n)
            .map(|k| DVec2::from_angle(core::f64::consts::TAU * f64::from(k) / f64::from(n)))
            .collect();
        assert_eq!(first_self_crossing(&round), Ok(None));
    }
}

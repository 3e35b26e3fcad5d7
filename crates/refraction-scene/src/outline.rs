//! What a renderer draws for a shape: its boundary as segments and circular arcs in world
//! coordinates, and the same flattened to a polyline.

use core::f64::consts::TAU;

use glam::DVec2;
use serde::Serialize;

/// One piece of a shape's boundary.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Piece {
    /// A straight segment.
    Segment {
        /// Where it starts.
        from: DVec2,
        /// Where it ends.
        to: DVec2,
    },
    /// A circular arc, counter-clockwise from `from` to `to` (both on the circle).
    Arc {
        /// The circle's centre.
        center: DVec2,
        /// The circle's radius (> 0).
        radius: f64,
        /// Where it starts.
        from: DVec2,
        /// Where it ends.
        to: DVec2,
    },
    /// A whole circle.
    Circle {
        /// Its centre.
        center: DVec2,
        /// Its radius (> 0).
        radius: f64,
    },
}

impl Piece {
    /// Appends the piece's points to `points`, except its first point when `points` already
    /// ends there; arcs and circles become chords no longer than `max_step` world units (and
    /// at most 1024 of them).
    fn flatten_into(&self, max_step: f64, points: &mut Vec<DVec2>) {
        let (center, radius, start, sweep) = match *self {
            Self::Segment { from, to } => {
                push_distinct(points, from);
                points.push(to);
                return;
            }
            Self::Arc {
                center,
                radius,
                from,
                to,
            } => {
                let start = angle(from - center);
                (
                    center,
                    radius,
                    start,
                    (angle(to - center) - start).rem_euclid(TAU),
                )
            }
            Self::Circle { center, radius } => (center, radius, 0.0, TAU),
        };
        let chords = (sweep * radius / max_step.max(f64::MIN_POSITIVE))
            .ceil()
            .clamp(1.0, 1024.0);
        // The chord count is clamped to 1..=1024 just above, so the cast is exact.
        let steps = chords as usize;
        for i in 0..=steps {
            let a = start + sweep * i as f64 / chords;
            let p = center + radius * DVec2::from_angle(a);
            if i == 0 {
                push_distinct(points, p);
            } else {
                points.push(p);
            }
        }
    }
}

fn angle(v: DVec2) -> f64 {
    v.y.atan2(v.x)
}

fn push_distinct(points: &mut Vec<DVec2>, p: DVec2) {
    if points
        .last()
        .is_none_or(|last| last.distance_squared(p) > 1e-24)
    {
        points.push(p);
    }
}

/// The boundary of one shape of a scene.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Outline {
    /// The shape's position in the scene's list of shapes.
    pub shape: usize,
    /// The name of the medium inside it, or `None` for a screen.
    pub medium: Option<String>,
    /// Whether the pieces enclose a region (to be filled with its medium's colour).
    pub closed: bool,
    /// The boundary, piece after piece, each starting where the previous one ends.
    pub pieces: Vec<Piece>,
}

impl Outline {
    /// The boundary as one polyline with chords no longer than `max_step` world units; a closed
    /// outline's last point equals its first. Corners closer than half of `max_step` to the last
    /// point kept are left out (the last one stays): a step is what a picture can show, so a
    /// polygon of 200,000 vertices comes out with as many points as its picture has room for.
    #[must_use]
    pub fn polyline(&self, max_step: f64) -> Vec<DVec2> {
        let mut points = Vec::new();
        for piece in &self.pieces {
            piece.flatten_into(max_step, &mut points);
        }
        let min_step = max_step / 2.0;
        let Some(&last) = points.last() else {
            return points;
        };
        let mut kept: Vec<DVec2> = Vec::with_capacity(points.len());
        for p in points {
            if kept.last().is_none_or(|k| k.distance(p) >= min_step) {
                kept.push(p);
            }
        }
        if kept.last() != Some(&last) {
            // The end is kept exactly, so that a closed outline still closes: it replaces the
            // point before it when that one is too close.
            if kept.len() > 1 && kept.last().is_some_and(|k| k.distance(last) < min_step) {
                kept.pop();
            }
            kept.push(last);
        }
        kept
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_arc_flattens_counter_clockwise_between_its_ends() {
        let arc = Outline {
            shape: 0,
            medium: None,
            closed: false,
            pieces: vec![Piece::Arc {
                center: DVec2::ZERO,
                radius: 1.0,
                from: DVec2::Y,
                to: -DVec2::Y,
            }],
        };
        let points = arc.polyline(0.1);
        assert!(points.first().unwrap().distance(DVec2::Y) < 1e-12);
        assert!(points.last().unwrap().distance(-DVec2::Y) < 1e-12);
        assert!(points.iter().all(|p| p.x <= 1e-12));
        assert!(points.len() >= 32);
    }

    #[test]
    fn a_polygon_of_many_vertices_keeps_as_many_as_its_step_can_show() {
        let n = 200_000;
        let corners: Vec<DVec2> = (0..=n)
            .map(|k| DVec2::from_angle(TAU * f64::from(k % n) / f64::from(n)) * 10.0)
            .collect();
        let outline = Outline {
            shape: 0,
            medium: None,
            closed: true,
            pieces: corners
                .windows(2)
                .map(|w| Piece::Segment {
                    from: w[0],
                    to: w[1],
                })
                .collect(),
        };
        let points = outline.polyline(0.04);
        // A perimeter of 62.8 at one point per 0.02 or more.
        assert!(points.len() <= 3200, "{}", points.len());
        assert!(points.len() > 1000, "{}", points.len());
        assert_eq!(points.first(), points.last(), "still closed");
        assert!(
            points
                .windows(2)
                .all(|w| w[0].distance(w[1]) >= 0.02 - 1e-12)
        );
    }

    #[test]
    fn joined_segments_share_their_points() {
        let outline = Outline {
            shape: 0,
            medium: None,
            closed: true,
            pieces: vec![
                Piece::Segment {
                    from: DVec2::ZERO,
                    to: DVec2::X,
                },
                Piece::Segment {
                    from: DVec2::X,
                    to: DVec2::Y,
                },
                Piece::Segment {
                    from: DVec2::Y,
                    to: DVec2::ZERO,
                },
            ],
        };
        assert_eq!(
            outline.polyline(1.0),
            vec![DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ZERO]
        );
    }
}

//! The axis-aligned world rectangle a scene is seen and traced in.

use glam::DVec2;
use serde::Serialize;

/// How far past a piece's box a computed crossing may lie and still count, as a fraction of the
/// largest coordinate involved (the box's or the ray origin's). A crossing computed within a few
/// rounding errors (~1e-15 relative) of its piece is well inside this margin; one farther out
/// comes from a ray so close to parallel to a segment (sin θ below ~1e-7) that its position
/// along the ray means nothing, and is refused.
const PAD: f64 = 1e-9;

/// The margin around a box whose largest coordinate is `reach`, seen from `point`. It grows with
/// both, so a box holding another has a margin at least as wide (rounding is monotonic).
pub(crate) fn padding(reach: f64, point: DVec2) -> f64 {
    PAD * reach.max(point.abs().max_element())
}

/// An axis-aligned rectangle in world coordinates (`min` ≤ `max` componentwise). Rays that
/// leave every shape end where they leave it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    /// The lower-left corner.
    pub min: DVec2,
    /// The upper-right corner.
    pub max: DVec2,
}

impl Bounds {
    /// The smallest rectangle holding one point.
    #[must_use]
    pub fn point(p: DVec2) -> Self {
        Self { min: p, max: p }
    }

    /// The smallest rectangle holding both.
    #[must_use]
    pub fn union(self, other: Self) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The rectangle grown by `fraction` of its larger side on every side, and by at least
    /// `at_least` world units, so that a single point or a thin shape still has room around it.
    #[must_use]
    pub fn padded(self, fraction: f64, at_least: f64) -> Self {
        let size = self.max - self.min;
        let pad = DVec2::splat((size.max_element() * fraction).max(at_least));
        Self {
            min: self.min - pad,
            max: self.max + pad,
        }
    }

    /// The smallest rectangle `aspect` times as wide as it is high that holds this one, about
    /// the same centre: a scene's world widened (or heightened) to fill a canvas of that shape.
    /// A rectangle with no area, or an aspect that is not a finite number > 0, is kept.
    #[must_use]
    pub fn widened_to(self, aspect: f64) -> Self {
        let size = self.max - self.min;
        if !(aspect.is_finite() && aspect > 0.0 && size.x > 0.0 && size.y > 0.0) {
            return self;
        }
        let wanted = if size.x / size.y < aspect {
            DVec2::new(size.y * aspect, size.y)
        } else {
            DVec2::new(size.x, size.x / aspect)
        };
        let center = (self.min + self.max) * 0.5;
        Self {
            min: center - wanted * 0.5,
            max: center + wanted * 0.5,
        }
    }

    /// The four corners, counter-clockwise from `min`.
    #[must_use]
    pub fn corners(self) -> [DVec2; 4] {
        [
            self.min,
            DVec2::new(self.max.x, self.min.y),
            self.max,
            DVec2::new(self.min.x, self.max.y),
        ]
    }

    /// The largest absolute coordinate of the rectangle.
    pub(crate) fn reach(self) -> f64 {
        self.min.abs().max(self.max.abs()).max_element()
    }

    /// The range of ray parameters (entry, exit) over which `origin + t·direction` lies in the
    /// rectangle grown by `pad`; entry > exit when the ray misses it.
    pub(crate) fn slab(self, pad: f64, origin: DVec2, direction: DVec2) -> (f64, f64) {
        let (min, max) = (self.min - DVec2::splat(pad), self.max + DVec2::splat(pad));
        let (mut entry, mut exit) = (f64::NEG_INFINITY, f64::INFINITY);
        for axis in 0..2 {
            let (o, d) = (origin[axis], direction[axis]);
            if d == 0.0 {
                if o < min[axis] || o > max[axis] {
                    return (f64::INFINITY, f64::NEG_INFINITY);
                }
                continue;
            }
            let (t0, t1) = ((min[axis] - o) / d, (max[axis] - o) / d);
            let (near, far) = if d > 0.0 { (t0, t1) } else { (t1, t0) };
            entry = entry.max(near);
            exit = exit.min(far);
        }
        (entry, exit)
    }

    /// Whether the ray is within the rectangle, grown by [`padding`], at parameter `t`.
    pub(crate) fn admits(self, origin: DVec2, direction: DVec2, t: f64) -> bool {
        let (entry, exit) = self.slab(padding(self.reach(), origin), origin, direction);
        entry <= t && t <= exit
    }

    /// The parameter t ≥ 0 at which the ray `origin + t·direction` leaves the rectangle, or 0
    /// when it never is inside it ahead of `origin`.
    #[must_use]
    pub fn exit(self, origin: DVec2, direction: DVec2) -> f64 {
        let mut exit = f64::INFINITY;
        let mut entry = 0.0_f64;
        for axis in 0..2 {
            let (o, d) = (origin[axis], direction[axis]);
            if d == 0.0 {
                if o < self.min[axis] || o > self.max[axis] {
                    return 0.0;
                }
                continue;
            }
            let (t0, t1) = ((self.min[axis] - o) / d, (self.max[axis] - o) / d);
            entry = entry.max(t0.min(t1));
            exit = exit.min(t0.max(t1));
        }
        if exit >= entry && exit.is_finite() {
            exit
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_leaves_the_box_where_it_crosses_its_side() {
        let b = Bounds {
            min: DVec2::new(-1.0, -2.0),
            max: DVec2::new(3.0, 2.0),
        };
        assert_eq!(b.exit(DVec2::ZERO, DVec2::X), 3.0);
        assert_eq!(b.exit(DVec2::ZERO, -DVec2::Y), 2.0);
        assert_eq!(b.exit(DVec2::new(5.0, 0.0), DVec2::X), 0.0);
        assert_eq!(b.exit(DVec2::new(0.0, 5.0), DVec2::X), 0.0);
    }

    #[test]
    fn padding_gives_a_point_room() {
        let b = Bounds::point(DVec2::ONE).padded(0.2, 0.5);
        assert_eq!(b.min, DVec2::splat(0.5));
        assert_eq!(b.max, DVec2::splat(1.5));
    }

    #[test]
    fn widening_keeps_the_centre_and_holds_the_original() {
        let b = Bounds {
            min: DVec2::new(-1.0, -2.0),
            max: DVec2::new(1.0, 2.0),
        };
        let wide = b.widened_to(2.0);
        assert_eq!(wide.min, DVec2::new(-4.0, -2.0));
        assert_eq!(wide.max, DVec2::new(4.0, 2.0));
        let tall = b.widened_to(0.25);
        assert_eq!(tall.min, DVec2::new(-1.0, -4.0));
        assert_eq!(b.widened_to(f64::NAN), b);
        assert_eq!(b.widened_to(0.0), b);
    }
}

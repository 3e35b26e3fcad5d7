//! Plane geometry on the canvas: colours, rectangles, clipping, dashes, arcs and arrowheads.
//!
//! Canvas coordinates are pixels with the origin at the top-left corner and y pointing down, as
//! both egui and tiny-skia use them. Everything here is total: degenerate input (zero-length
//! segments, empty rectangles) gives empty output, never NaN or a panic.

use glam::Vec2;

/// An sRGB colour with straight (not premultiplied) alpha.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Colour {
    /// Red, 0–255.
    pub r: u8,
    /// Green, 0–255.
    pub g: u8,
    /// Blue, 0–255.
    pub b: u8,
    /// Opacity, 0 (transparent) to 255 (opaque).
    pub a: u8,
}

impl Colour {
    /// An opaque colour from its hex code, e.g. `0x0072B2`.
    #[must_use]
    pub const fn hex(code: u32) -> Self {
        Self {
            r: (code >> 16) as u8,
            g: (code >> 8) as u8,
            b: code as u8,
            a: 255,
        }
    }

    /// The same colour with opacity `a`.
    #[must_use]
    pub const fn with_alpha(self, a: u8) -> Self {
        Self { a, ..self }
    }

    /// The colour `t` of the way from `self` to `other` (t clamped to 0..=1), channel by channel.
    #[must_use]
    pub fn lerp(self, other: Self, t: f32) -> Self {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let mix = |x: u8, y: u8| (f32::from(x) + (f32::from(y) - f32::from(x)) * t).round() as u8;
        Self {
            r: mix(self.r, other.r),
            g: mix(self.g, other.g),
            b: mix(self.b, other.b),
            a: mix(self.a, other.a),
        }
    }

    /// The colour's relative luminance (WCAG 2): 0 for black, 1 for white; opacity ignored.
    #[must_use]
    pub(crate) fn luminance(self) -> f32 {
        let linear = |c: u8| {
            let c = f32::from(c) / 255.0;
            if c <= 0.040_45 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * linear(self.r) + 0.7152 * linear(self.g) + 0.0722 * linear(self.b)
    }

    /// The contrast ratio of two opaque colours (WCAG 2), from 1 (the same) to 21 (black and
    /// white); text reads at 4.5 and above.
    #[must_use]
    pub fn contrast(self, other: Self) -> f32 {
        let (a, b) = (self.luminance(), other.luminance());
        (a.max(b) + 0.05) / (a.min(b) + 0.05)
    }

    /// This colour over `background`, its opacity blended in: what the eye sees.
    #[must_use]
    pub fn over(self, background: Self) -> Self {
        background.lerp(Self { a: 255, ..self }, f32::from(self.a) / 255.0)
    }
}

/// An axis-aligned rectangle on the canvas (`min` top-left, `max` bottom-right).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    /// Top-left corner.
    pub min: Vec2,
    /// Bottom-right corner.
    pub max: Vec2,
}

impl Rect {
    /// The rectangle from its top-left corner and size.
    #[must_use]
    pub fn from_min_size(min: Vec2, size: Vec2) -> Self {
        Self {
            min,
            max: min + size,
        }
    }

    /// The square of half-side `half` centred on `center`.
    #[must_use]
    pub fn around(center: Vec2, half: f32) -> Self {
        Self {
            min: center - Vec2::splat(half),
            max: center + Vec2::splat(half),
        }
    }

    /// Width and height.
    #[must_use]
    pub fn size(&self) -> Vec2 {
        self.max - self.min
    }

    /// The centre point.
    #[must_use]
    pub fn center(&self) -> Vec2 {
        (self.min + self.max) * 0.5
    }

    /// The four corners, clockwise on screen from the top-left.
    #[must_use]
    pub fn corners(&self) -> [Vec2; 4] {
        [
            self.min,
            Vec2::new(self.max.x, self.min.y),
            self.max,
            Vec2::new(self.min.x, self.max.y),
        ]
    }

    /// Whether the two rectangles share interior points.
    #[must_use]
    pub fn overlaps(&self, other: &Self) -> bool {
        self.min.cmplt(other.max).all() && other.min.cmplt(self.max).all()
    }

    /// Whether `p` lies inside or on the border.
    #[must_use]
    pub fn contains(&self, p: Vec2) -> bool {
        p.cmpge(self.min).all() && p.cmple(self.max).all()
    }
}

/// The convex polygon `rect ∩ {p : (p − through)·normal ≥ 0}` (empty when they do not meet).
#[must_use]
pub(crate) fn clip_rect_to_half_plane(rect: &Rect, through: Vec2, normal: Vec2) -> Vec<Vec2> {
    let side = |p: Vec2| (p - through).dot(normal);
    let corners = rect.corners();
    let mut out = Vec::with_capacity(5);
    for (i, &p) in corners.iter().enumerate() {
        let q = corners[(i + 1) % 4];
        let (sp, sq) = (side(p), side(q));
        if sp >= 0.0 {
            out.push(p);
        }
        if (sp >= 0.0) != (sq >= 0.0) {
            out.push(p + (q - p) * (sp / (sp - sq)));
        }
    }
    out
}

/// Twice the signed area of the triangle `a`, `b`, `c`: positive when it turns one way, negative
/// the other, zero when the points are in a line.
fn turn(a: Vec2, b: Vec2, c: Vec2) -> f32 {
    (b - a).perp_dot(c - b)
}

/// A simple polygon as convex pieces that fill it together: itself when it is convex, else the
/// triangles of ear clipping. A repeated closing point is ignored; fewer than three corners give
/// nothing. A self-intersecting outline gives triangles that cover it only roughly, never a panic.
#[must_use]
pub(crate) fn convex_pieces(points: &[Vec2]) -> Vec<Vec<Vec2>> {
    let mut corners = points.to_vec();
    if corners.len() > 1 && corners.first() == corners.last() {
        corners.pop();
    }
    if corners.len() < 3 {
        return Vec::new();
    }
    let n = corners.len();
    let turns: Vec<f32> = (0..n)
        .map(|i| turn(corners[i], corners[(i + 1) % n], corners[(i + 2) % n]))
        .collect();
    if turns.iter().all(|t| *t >= 0.0) || turns.iter().all(|t| *t <= 0.0) {
        return vec![corners];
    }
    let orientation = (0..n)
        .map(|i| corners[i].perp_dot(corners[(i + 1) % n]))
        .sum::<f32>()
        .signum();
    let mut triangles = Vec::with_capacity(n - 2);
    while corners.len() > 3 {
        let m = corners.len();
        let is_ear = |i: usize| {
            let (a, b, c) = (corners[(i + m - 1) % m], corners[i], corners[(i + 1) % m]);
            turn(a, b, c) * orientation > 0.0
                && corners.iter().all(|&p| {
                    p == a
                        || p == b
                        || p == c
                        || turn(a, b, p) * orientation < 0.0
                        || turn(b, c, p) * orientation < 0.0
                        || turn(c, a, p) * orientation < 0.0
                })
        };
        // A degenerate outline may have no ear: cut its first corner anyway, so that the loop
        // always ends.
        let ear = (0..m).find(|&i| is_ear(i)).unwrap_or(0);
        triangles.push(vec![
            corners[(ear + m - 1) % m],
            corners[ear],
            corners[(ear + 1) % m],
        ]);
        corners.remove(ear);
    }
    triangles.push(corners);
    triangles
}

/// The part of the segment `a`–`b` inside `rect` (Liang–Barsky), or `None`.
#[must_use]
pub(crate) fn clip_segment(a: Vec2, b: Vec2, rect: &Rect) -> Option<(Vec2, Vec2)> {
    let d = b - a;
    let (mut t0, mut t1) = (0.0_f32, 1.0_f32);
    for (p, q) in [
        (-d.x, a.x - rect.min.x),
        (d.x, rect.max.x - a.x),
        (-d.y, a.y - rect.min.y),
        (d.y, rect.max.y - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1 && t0.is_finite() && t1.is_finite()).then(|| (a + d * t0, a + d * t1))
}

/// Splits a polyline into the drawn pieces of a dash `pattern` (on, off, on, off… lengths in
/// pixels). An empty or non-positive pattern returns the polyline whole.
#[must_use]
pub(crate) fn dash(points: &[Vec2], pattern: &[f32]) -> Vec<Vec<Vec2>> {
    let period: f32 = pattern.iter().sum();
    if !pattern.iter().all(|l| l.is_finite() && *l >= 0.0) || period <= 0.0 {
        return vec![points.to_vec()];
    }
    let mut pieces = Vec::new();
    let mut current: Vec<Vec2> = Vec::new();
    let (mut index, mut left) = (0, pattern[0]);
    for pair in points.windows(2) {
        let (mut from, to) = (pair[0], pair[1]);
        let mut remaining = from.distance(to);
        while remaining > 0.0 {
            let on = index % 2 == 0;
            if on && current.is_empty() {
                current.push(from);
            }
            let step = left.min(remaining);
            let next = from + (to - from) * (step / remaining);
            if on {
                current.push(next);
            }
            (from, remaining, left) = (next, remaining - step, left - step);
            if left <= 0.0 {
                if on {
                    pieces.push(core::mem::take(&mut current));
                }
                index = (index + 1) % pattern.len();
                left = pattern[index];
            }
        }
    }
    if current.len() > 1 {
        pieces.push(current);
    }
    pieces
}

/// Points along the circular arc around `center` of `radius`, from the direction `from` turning
/// the short way to the direction `to` (both canvas directions, any non-zero length).
#[must_use]
pub(crate) fn arc(center: Vec2, radius: f32, from: Vec2, to: Vec2) -> Vec<Vec2> {
    let start = from.y.atan2(from.x);
    let mut sweep = to.y.atan2(to.x) - start;
    if sweep > core::f32::consts::PI {
        sweep -= core::f32::consts::TAU;
    } else if sweep < -core::f32::consts::PI {
        sweep += core::f32::consts::TAU;
    }
    let steps = 32;
    (0..=steps)
        .map(|i| {
            let angle = start + sweep * i as f32 / steps as f32;
            center + Vec2::new(angle.cos(), angle.sin()) * radius
        })
        .collect()
}

/// The triangle of an arrowhead whose tip is at `tip`, pointing along `direction`, `length`
/// long and `length`·0.7 wide. Empty when `direction` is zero.
#[must_use]
pub(crate) fn arrowhead(tip: Vec2, direction: Vec2, length: f32) -> Vec<Vec2> {
    let Some(d) = direction.try_normalize() else {
        return Vec::new();
    };
    let base = tip - d * length;
    let side = d.perp() * (length * 0.35);
    vec![tip, base + side, base - side]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect() -> Rect {
        Rect::from_min_size(Vec2::ZERO, Vec2::new(100.0, 50.0))
    }

    #[test]
    fn half_plane_clip_keeps_the_right_half() {
        let half = clip_rect_to_half_plane(&rect(), Vec2::new(50.0, 25.0), Vec2::X);
        assert_eq!(half.len(), 4);
        assert!(half.iter().all(|p| p.x >= 50.0 - 1e-4));
        assert!(clip_rect_to_half_plane(&rect(), Vec2::new(200.0, 0.0), Vec2::X).is_empty());
        assert_eq!(
            clip_rect_to_half_plane(&rect(), Vec2::ZERO, Vec2::X).len(),
            4
        );
    }

    #[test]
    fn segments_are_clipped_to_the_rectangle() {
        let (a, b) = clip_segment(Vec2::new(-50.0, 25.0), Vec2::new(150.0, 25.0), &rect()).unwrap();
        assert_eq!((a, b), (Vec2::new(0.0, 25.0), Vec2::new(100.0, 25.0)));
        assert!(clip_segment(Vec2::new(-5.0, -5.0), Vec2::new(-1.0, 80.0), &rect()).is_none());
        assert!(clip_segment(Vec2::splat(10.0), Vec2::splat(10.0), &rect()).is_some());
        let right = Rect::from_min_size(Vec2::new(100.0, 0.0), Vec2::splat(10.0));
        assert!(!rect().overlaps(&right));
        assert!(rect().overlaps(&Rect::from_min_size(
            Vec2::new(90.0, 40.0),
            Vec2::splat(20.0)
        )));
    }

    #[test]
    fn dashes_cover_the_on_parts_only() {
        let line = [Vec2::ZERO, Vec2::new(25.0, 0.0)];
        let pieces = dash(&line, &[5.0, 5.0]);
        assert_eq!(pieces.len(), 3);
        assert_eq!(pieces[1], vec![Vec2::new(10.0, 0.0), Vec2::new(15.0, 0.0)]);
        assert_eq!(dash(&line, &[]), vec![line.to_vec()]);
        assert_eq!(dash(&line, &[0.0, 0.0]), vec![line.to_vec()]);
    }

    #[test]
    fn arcs_turn_the_short_way_and_arrowheads_point_along() {
        let points = arc(Vec2::ZERO, 10.0, Vec2::X, -Vec2::Y);
        assert!((points[0] - Vec2::new(10.0, 0.0)).length() < 1e-4);
        assert!((points[32] - Vec2::new(0.0, -10.0)).length() < 1e-4);
        assert!(points.iter().all(|p| p.x >= -1e-4 && p.y <= 1e-4));
        let head = arrowhead(Vec2::ZERO, Vec2::X, 10.0);
        assert_eq!(head[0], Vec2::ZERO);
        assert!(head[1].x < 0.0 && head[2].x < 0.0);
        assert!(arrowhead(Vec2::ZERO, Vec2::ZERO, 10.0).is_empty());
    }

    fn area(polygon: &[Vec2]) -> f32 {
        let n = polygon.len();
        (0..n)
            .map(|i| polygon[i].perp_dot(polygon[(i + 1) % n]))
            .sum::<f32>()
            .abs()
            / 2.0
    }

    #[test]
    fn a_convex_polygon_stays_whole_and_a_concave_one_becomes_triangles_of_the_same_area() {
        let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y, Vec2::ZERO];
        assert_eq!(convex_pieces(&square), vec![square[..4].to_vec()]);
        let l_shape = [
            Vec2::ZERO,
            Vec2::new(2.0, 0.0),
            Vec2::new(2.0, 1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(1.0, 2.0),
            Vec2::new(0.0, 2.0),
        ];
        for outline in [l_shape.to_vec(), l_shape.iter().rev().copied().collect()] {
            let pieces = convex_pieces(&outline);
            assert_eq!(pieces.len(), 4);
            let total: f32 = pieces.iter().map(|t| area(t)).sum();
            assert!((total - 3.0).abs() < 1e-5, "{pieces:?}");
        }
        assert!(convex_pieces(&[Vec2::ZERO, Vec2::X]).is_empty());
        let bow_tie = [Vec2::ZERO, Vec2::ONE, Vec2::X, Vec2::Y];
        assert_eq!(convex_pieces(&bow_tie).len(), 2);
    }

    #[test]
    fn colours_mix_and_parse() {
        let c = Colour::hex(0x0072B2);
        assert_eq!((c.r, c.g, c.b, c.a), (0x00, 0x72, 0xB2, 255));
        assert_eq!(Colour::hex(0).lerp(Colour::hex(0xFFFFFF), 0.5).r, 128);
        assert_eq!(c.lerp(Colour::hex(0), f32::NAN), c);
    }
}

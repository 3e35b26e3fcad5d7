//! The figures of a judged log that its failure map draws: for each judged line, the angle of
//! incidence, how far the direction the student's code sent is from the right one, the side
//! the ray arrives from and whether the right answer is total internal reflection. The tools
//! compute them when they judge a line; the diagram draws them, so that the pattern of a bug
//! ("everything from inside is wrong") can be seen.

use glam::DVec3;

pub use refraction_kernel::Side;

/// One judged line of a log, as its failure map shows it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinePoint {
    /// The angle of incidence of the right problem, in degrees within [0, 90].
    pub incidence_deg: f64,
    /// The angle between the direction the student's code sent the ray in and the right one
    /// (T, or the reflected ray past the critical angle), in degrees within [0, 180]. A code
    /// that reported total internal reflection sends the reflected ray.
    pub error_deg: f64,
    /// The side the ray arrives from, when the line or its API's convention says.
    pub side: Option<Side>,
    /// Whether the right answer is total internal reflection.
    pub past_critical: bool,
    /// Whether the line is right.
    pub ok: bool,
}

/// The angle between `a` and `b` in degrees, 0 when either has no direction (zero or not
/// finite): such a line has no direction to be off by, and its verdict says why.
#[must_use]
pub fn angle_deg(a: DVec3, b: DVec3) -> f64 {
    let (a, b) = (a.normalize_or_zero(), b.normalize_or_zero());
    if a == DVec3::ZERO || b == DVec3::ZERO {
        return 0.0;
    }
    // atan2 of the cross and dot products: accurate at 0° and 180° alike, unlike acos.
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// The angle of incidence in degrees of a ray travelling along `travel` onto a surface with
/// normal `normal` (either side), within [0, 90]; 0 for a zero vector.
#[must_use]
pub fn incidence_deg(travel: DVec3, normal: DVec3) -> f64 {
    let angle = angle_deg(-travel, normal);
    if angle > 90.0 { 180.0 - angle } else { angle }
}

/// `travel` reflected by the surface with normal `normal` (either side, any length).
#[must_use]
pub fn reflected(travel: DVec3, normal: DVec3) -> DVec3 {
    let n = normal.normalize_or_zero();
    travel - 2.0 * travel.dot(n) * n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_are_measured_from_either_side_and_exactly_at_the_ends() {
        let down = DVec3::new(0.6, -0.8, 0.0);
        let up = DVec3::Y;
        let i = incidence_deg(down, up);
        assert!((i - 36.869_897_645_844_02).abs() < 1e-9, "{i}");
        assert!((incidence_deg(down, -up) - i).abs() < 1e-9);
        assert_eq!(angle_deg(up, up), 0.0);
        assert!((angle_deg(up, -up) - 180.0).abs() < 1e-12);
        assert_eq!(angle_deg(DVec3::ZERO, up), 0.0);
        assert_eq!(angle_deg(DVec3::splat(f64::NAN), up), 0.0);
        assert_eq!(reflected(down, up * 3.0), DVec3::new(0.6, 0.8, 0.0));
    }
}

//! The refraction formula with its parts varied: what a line of code that gets one part wrong
//! returns, for the diagnosis's search over single-line mistakes.
//!
//! In this project's terms (d the direction of travel, N the unit normal facing it, cosθi =
//! −d·N, μ = `n_from/n_to`) every renderer computes T = μ·d⊥ − √k·N, where d⊥ = d + cosθi·N is
//! the part of d across the normal and k = 1 − μ²·sin²θi (total internal reflection when
//! k < 0). A [`Variant`] changes one or more parts: the ratio in the part across N, the ratio
//! in k (and so in the test for total internal reflection), the incident vector's sign (the
//! part across N negated), the root's sign (the part along N negated), the whole term along N
//! added with the wrong sign (T = μ·d − b·N for μ·d + b·N), and the result's sign (−T: the
//! outgoing vector in the other convention).
//!
//! Each variant is compared with what the code sent the ray along by direction only (many
//! renderers normalise, many do not), in the plane of incidence.

use glam::DVec3;

/// A set of changes to the formula, one bit each (see the module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct Variant(u8);

impl Variant {
    /// The formula as it is.
    pub(crate) const RIGHT: Self = Self(0);
    /// The ratio inverted in the part across N.
    pub(crate) const ACROSS: Self = Self(1);
    /// The ratio inverted in k: in cosθt and the test for total internal reflection.
    pub(crate) const ALONG: Self = Self(2);
    /// The part across N negated (the incident vector the wrong way round).
    pub(crate) const INCIDENT: Self = Self(4);
    /// The part along N negated (the other root).
    pub(crate) const ROOT: Self = Self(8);
    /// The term along N subtracted instead of added.
    pub(crate) const TERM: Self = Self(16);
    /// The whole result negated.
    pub(crate) const REVERSED: Self = Self(32);

    /// Both changes (the same change twice cancels: it is an exclusive or).
    #[must_use]
    pub(crate) fn with(self, other: Self) -> Self {
        Self(self.0 ^ other.0)
    }

    /// Whether this variant has the change `part`.
    #[must_use]
    pub(crate) fn has(self, part: Self) -> bool {
        self.0 & part.0 == part.0
    }

    /// The variant's bit in a set of variants.
    #[must_use]
    pub(crate) fn bit(self) -> u64 {
        1 << self.0
    }

    /// Every variant.
    pub(crate) fn all() -> impl Iterator<Item = Self> {
        (0..64).map(Self)
    }
}

/// What the code sent the ray along.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Outcome {
    /// A direction (any length).
    Direction(DVec3),
    /// Nothing transmitted: total internal reflection said (null, false, the zero vector, the
    /// reflection, or a vector that is not finite).
    #[default]
    Nothing,
}

/// A line's situation: the direction of travel, the normal facing it and μ.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Situation {
    /// The direction of travel (any length).
    pub travel: DVec3,
    /// The normal (any length, either side: it is turned to face the ray).
    pub normal: DVec3,
    /// μ = `n_from/n_to`.
    pub mu: f64,
}

/// The situation in the plane of incidence: sinθi, cosθi and the unit vectors across and
/// along the facing normal.
struct Plane {
    sin: f64,
    cos: f64,
    across: DVec3,
    normal: DVec3,
    mu: f64,
}

impl Plane {
    fn new(s: &Situation) -> Option<Self> {
        let d = s.travel.try_normalize()?;
        let n = s.normal.try_normalize()?;
        let n = if d.dot(n) > 0.0 { -n } else { n };
        let cos = (-d.dot(n)).clamp(0.0, 1.0);
        let tangent = d + cos * n;
        let sin = tangent.length();
        let across = if sin > 1e-12 {
            tangent / sin
        } else {
            n.any_orthonormal_vector()
        };
        (s.mu.is_finite() && s.mu > 0.0).then_some(Self {
            sin,
            cos,
            across,
            normal: n,
            mu: s.mu,
        })
    }

    /// What `variant` sends the ray along, as (part across N, part along N); `None` for total
    /// internal reflection.
    fn predict(&self, variant: Variant) -> Option<(f64, f64)> {
        let flip = |part: Variant, mu: f64| if variant.has(part) { 1.0 / mu } else { mu };
        let (across_mu, along_mu) = (
            flip(Variant::ACROSS, self.mu),
            flip(Variant::ALONG, self.mu),
        );
        let k = 1.0 - along_mu * along_mu * self.sin * self.sin;
        if k < 0.0 {
            return None;
        }
        let sign = |part: Variant| if variant.has(part) { -1.0 } else { 1.0 };
        let a = sign(Variant::INCIDENT) * across_mu;
        let across = a * self.sin;
        let mut along = -sign(Variant::ROOT) * k.sqrt();
        if variant.has(Variant::TERM) {
            // T = a·d + b·N with b = along + a·cosθi (d's own part along N is −cosθi·N).
            along = -along - 2.0 * a * self.cos;
        }
        let reversed = sign(Variant::REVERSED);
        Some((reversed * across, reversed * along))
    }
}

/// The variants that reproduce `outcome` for `situation`, within `tolerance` radians, as a
/// set of [`Variant::bit`]s; 0 when the situation is degenerate.
#[must_use]
pub(crate) fn reproducing(situation: &Situation, outcome: Outcome, tolerance: f64) -> u64 {
    let Some(plane) = Plane::new(situation) else {
        return 0;
    };
    let logged = match outcome {
        Outcome::Direction(v) if v.is_finite() && v != DVec3::ZERO => {
            let along = v.dot(plane.normal);
            let across = v.dot(plane.across);
            let off = (v - along * plane.normal - across * plane.across).length();
            Some((across, along, off))
        }
        Outcome::Direction(_) | Outcome::Nothing => None,
    };
    let mut set = 0;
    for variant in Variant::all() {
        let same = match (plane.predict(variant), logged) {
            (None, None) => true,
            (Some(p), Some(v)) => same_direction(p, v, tolerance),
            _ => false,
        };
        if same {
            set |= variant.bit();
        }
    }
    set
}

/// What `variant` of the formula sends the ray along in `situation` (nothing for a
/// degenerate situation).
#[must_use]
pub(crate) fn outcome(situation: &Situation, variant: Variant) -> Outcome {
    Plane::new(situation)
        .and_then(|plane| {
            let (across, along) = plane.predict(variant)?;
            Some(Outcome::Direction(
                across * plane.across + along * plane.normal,
            ))
        })
        .unwrap_or(Outcome::Nothing)
}

/// The variants whose outcome is the right one's (for a line that is right).
#[must_use]
pub(crate) fn agreeing(situation: &Situation, tolerance: f64) -> u64 {
    if Plane::new(situation).is_none() {
        return Variant::RIGHT.bit();
    }
    reproducing(situation, outcome(situation, Variant::RIGHT), tolerance)
}

/// Whether (across, along) points within `tolerance` of (across, along, off the plane).
fn same_direction(p: (f64, f64), v: (f64, f64, f64), tolerance: f64) -> bool {
    let dot = p.0 * v.0 + p.1 * v.1;
    let (pp, vv) = (p.0 * p.0 + p.1 * p.1, v.0 * v.0 + v.1 * v.1 + v.2 * v.2);
    if dot <= 0.0 || pp == 0.0 || vv == 0.0 {
        return pp == 0.0 && vv == 0.0;
    }
    let sin2 = (1.0 - dot * dot / (pp * vv)).max(0.0);
    sin2 <= tolerance * tolerance
}

/// The Fresnel reflectance of unpolarised light at this situation (1 past the critical
/// angle): the probability with which a renderer that samples reflection reflects.
#[must_use]
pub(crate) fn reflectance(situation: &Situation) -> f64 {
    let Some(p) = Plane::new(situation) else {
        return 1.0;
    };
    let k = 1.0 - p.mu * p.mu * p.sin * p.sin;
    if k <= 0.0 {
        return 1.0;
    }
    let (ci, ct, mu) = (p.cos, k.sqrt(), p.mu);
    let s = (mu * ci - ct) / (mu * ci + ct);
    let pp = (mu * ct - ci) / (mu * ct + ci);
    (0.5 * (s * s + pp * pp)).clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Entering glass (μ = 1/1.5) at 40° from the normal +y, in the xy plane.
    fn entering(degrees: f64) -> Situation {
        let a = degrees.to_radians();
        Situation {
            travel: DVec3::new(a.sin(), -a.cos(), 0.0),
            normal: DVec3::Y,
            mu: 1.0 / 1.5,
        }
    }

    fn right(s: &Situation) -> DVec3 {
        let d = s.travel.normalize();
        let c = -d.dot(s.normal);
        let k = 1.0 - s.mu * s.mu * (1.0 - c * c);
        s.mu * d + (s.mu * c - k.sqrt()) * s.normal
    }

    #[test]
    fn the_right_t_is_the_formula_as_it_is_and_each_change_differs() {
        let s = entering(40.0);
        let set = reproducing(&s, Outcome::Direction(right(&s)), 1e-6);
        assert!(set & Variant::RIGHT.bit() != 0);
        assert_eq!(agreeing(&s, 1e-6), set);
        // The part across N negated twice over (the incident vector and the result) with the
        // root's sign is the formula again; no single change is.
        let twice = Variant::INCIDENT
            .with(Variant::ROOT)
            .with(Variant::REVERSED);
        assert_eq!(set, Variant::RIGHT.bit() | twice.bit());
    }

    #[test]
    fn each_part_changed_is_what_the_mistake_gives() {
        let s = entering(40.0);
        let (d, t, n) = (s.travel, right(&s), DVec3::Y);
        let cases = [
            (t - 2.0 * t.dot(n) * n, Variant::ROOT),
            (2.0 * t.dot(n) * n - t, Variant::INCIDENT),
            (-t, Variant::REVERSED),
            (2.0 * s.mu * d - t, Variant::TERM),
            (
                right(&Situation { mu: 1.5, ..s }),
                Variant::ACROSS.with(Variant::ALONG),
            ),
        ];
        for (logged, variant) in cases {
            let set = reproducing(&s, Outcome::Direction(logged), 1e-6);
            assert!(set & variant.bit() != 0, "{variant:?}: {set:b}");
            assert!(set & Variant::RIGHT.bit() == 0, "{variant:?}: {set:b}");
        }
        // Past sinθ = 1/1.5 the ratio inverted in k says total internal reflection.
        let set = reproducing(&entering(60.0), Outcome::Nothing, 1e-6);
        assert!(set & Variant::ACROSS.with(Variant::ALONG).bit() != 0);
        assert!(set & Variant::ALONG.bit() != 0);
        assert!(set & Variant::ACROSS.bit() == 0);
    }

    #[test]
    fn the_ratio_in_one_part_only() {
        // Cycles' refract_angle given eta where it takes 1/eta: the part across N scaled by
        // 1/μ, cosθt right.
        let s = entering(30.0);
        let d = s.travel;
        let n = DVec3::Y;
        let c = -d.dot(n);
        let k = 1.0 - s.mu * s.mu * (1.0 - c * c);
        let across_only = (d + c * n) / s.mu - k.sqrt() * n;
        let set = reproducing(&s, Outcome::Direction(across_only), 1e-9);
        assert_eq!(set & 0b11, Variant::ACROSS.bit() & 0b11);
        assert!(set & Variant::ACROSS.bit() != 0);
    }

    #[test]
    fn reflectance_is_four_percent_at_normal_incidence_and_one_past_the_critical_angle() {
        assert!((reflectance(&entering(0.0)) - 0.04).abs() < 1e-12);
        let inside = Situation {
            mu: 1.5,
            ..entering(60.0)
        };
        assert_eq!(reflectance(&inside), 1.0);
    }
}

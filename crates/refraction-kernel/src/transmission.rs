//! The refracted ray of one refraction, as the full answer ([`crate::refract`]) and the
//! stable kernel ([`crate::refract_facing`]) both give it.

use super::real::Real;

/// The transmitted ray and the paper's weights for it: T = a·W + b·N.
///
/// In [`crate::Refraction`] W and N are Ŵ and N̂, the vectors as given, normalised, before any flip
/// (so a = ±μ by the convention); in [`crate::Facing`] they are the travel direction d and
/// the facing normal (so a = μ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transmission<S: Real> {
    /// The refracted direction of travel T (unit length up to rounding).
    pub t: S::Vec3,
    /// cosθt = √k ≥ 0.
    pub cos_t: S,
    /// Weight of W in T = a·W + b·N: ±μ.
    pub a: S,
    /// Weight of N in T = a·W + b·N.
    pub b: S,
}

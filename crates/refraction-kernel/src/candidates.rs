//! The four (a, b) pairs that satisfy the source's squared constraints, and why three of them
//! are not the refracted ray.
//!
//! Squaring Snell's law (eq. 5) and requiring |T| = 1 (eq. 12) give a = ±μ (eq. 18) and, for
//! each a, b = −a·wn ± √k (eq. 21). The four vectors are T, its mirror across the surface, its
//! mirror across the normal, and −T: all unit length, all satisfying squared Snell.

use super::real::{Real, Vector3};

/// The rule a rejected candidate breaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rejection {
    /// The other root for b: T mirrored across the surface, back into the incident medium.
    WrongSide,
    /// The other sign of a: T mirrored across the normal; it bends the wrong way and does not
    /// become the incoming ray when μ → 1.
    WrongBend,
    /// Both wrong: −T, pointing back toward where the ray came from.
    Reversed,
}

impl Rejection {
    /// All three, in the order the source meets them (a first, then b).
    pub const ALL: [Self; 3] = [Self::WrongBend, Self::WrongSide, Self::Reversed];

    /// A short stable name, as used in JSON: `wrong_side`, `wrong_bend`, `reversed`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::WrongSide => "wrong_side",
            Self::WrongBend => "wrong_bend",
            Self::Reversed => "reversed",
        }
    }

    /// The rule broken, in a sentence a student can follow.
    #[must_use]
    pub fn rule(self) -> &'static str {
        match self {
            Self::WrongSide => {
                "wrong side of the surface: the other root for b sends the ray back into the \
                 medium it came from"
            }
            Self::WrongBend => {
                "bends the wrong way: the other sign of a flips the part along the surface, so \
                 it does not become the incoming ray as mu -> 1"
            }
            Self::Reversed => {
                "both wrong (wrong sign of a and wrong root for b): it is -T, pointing back \
                 where the ray came from"
            }
        }
    }
}

/// One solution (a, b) of the squared constraints, T = a·Ŵ + b·N̂ with Ŵ, N̂ as given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate<S: Real> {
    /// Weight of Ŵ: ±μ.
    pub a: S,
    /// Weight of N̂: one of the two roots of eq. 21 for this a.
    pub b: S,
    /// The candidate direction a·Ŵ + b·N̂, computed by mirroring T so that it is as accurate as T.
    pub t: S::Vec3,
    /// `None` for the physical ray; otherwise the rule this candidate breaks.
    pub rejection: Option<Rejection>,
}

impl<S: Real> Candidate<S> {
    /// Whether this is the refracted ray the kernel returns.
    #[must_use]
    pub fn is_chosen(&self) -> bool {
        self.rejection.is_none()
    }
}

/// The four candidates given the chosen (a, b), T, wn = Ŵ·N̂ and N̂, ordered as the source
/// enumerates them: a = +μ then a = −μ (eq. 18), and for each the +√k root then the −√k root
/// (eq. 21).
///
/// `normal_flipped` says whether the kernel turned N̂ around, which decides the chosen root.
#[must_use]
pub fn candidates<S: Real>(
    chosen: (S, S),
    t: S::Vec3,
    wn: S,
    n: S::Vec3,
    normal_flipped: bool,
) -> [Candidate<S>; 4] {
    let (a, b) = chosen;
    let normal_part = n * t.dot(n);
    let across_surface = t - normal_part * S::TWO;
    let across_normal = normal_part * S::TWO - t;
    let make = |a, b, t, rejection| Candidate { a, b, t, rejection };
    let mut all = [
        make(a, b, t, None),
        make(
            a,
            -S::TWO * a * wn - b,
            across_surface,
            Some(Rejection::WrongSide),
        ),
        make(
            -a,
            S::TWO * a * wn + b,
            across_normal,
            Some(Rejection::WrongBend),
        ),
        make(-a, -b, -t, Some(Rejection::Reversed)),
    ];
    // Source order: a > 0 first, then the +√k root (normal part along +N̂) first. The chosen
    // ray and its mirror across the normal share a root; the chosen root is +√k exactly when
    // the kernel flipped N̂ (T then leaves along +N̂).
    all.sort_by_key(|c| {
        let same_root_as_chosen = matches!(c.rejection, None | Some(Rejection::WrongBend));
        let plus_root = same_root_as_chosen == normal_flipped;
        u8::from(c.a < S::ZERO) * 2 + u8::from(!plus_root)
    });
    all
}

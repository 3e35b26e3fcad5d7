//! The four (a, b) pairs that satisfy the paper's squared constraints, and why three of them
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
    /// All three, in the order the paper meets them (a first, then b).
    pub const ALL: [Self; 3] = [Self::WrongBend, Self::WrongSide, Self::Reversed];

    /// A short stable name, as used in JSON: `wrong_side`, `wrong_bend`, `reversed`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Rejection;
    /// let names = Rejection::ALL.map(Rejection::name);
    /// assert_eq!(names, ["wrong_bend", "wrong_side", "reversed"]);
    /// ```
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::WrongSide => "wrong_side",
            Self::WrongBend => "wrong_bend",
            Self::Reversed => "reversed",
        }
    }

    /// The rule broken, in a sentence a student can follow.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Rejection;
    /// assert!(Rejection::WrongSide.rule().starts_with("wrong side of the surface"));
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::{Convention, Incidence, refract};
    /// let w = DVec3::new(0.6, -0.8, 0.0);
    /// let incidence = Incidence::<f64> {
    ///     w, n: DVec3::Y, mu_i: 1.0, mu_t: 1.5, convention: Convention::AlongRay,
    /// };
    /// let answer = refract(&incidence)?;
    /// let chosen: Vec<_> = answer.candidates.iter().filter(|c| c.is_chosen()).collect();
    /// assert_eq!(chosen.len(), 1);
    /// assert_eq!(Some(chosen[0].t), answer.t());
    /// # Ok::<(), refraction_kernel::InputError>(())
    /// ```
    #[must_use]
    pub fn is_chosen(&self) -> bool {
        self.rejection.is_none()
    }
}

/// The four candidates given the chosen (a, b), T, wn = Ŵ·N̂ and N̂, ordered as the paper
/// enumerates them: a = +μ then a = −μ (eq. 18), and for each the +√k root then the −√k root
/// (eq. 21).
///
/// `normal_flipped` says whether the kernel turned N̂ around, which decides the chosen root.
/// [`crate::refract`] calls it and keeps the result in [`crate::Refraction::candidates`].
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::{Rejection, candidates, transmit};
/// // Air into glass along the ray (Section 2): a = μ, b = −μ·wn − √k, N as given.
/// let (w, n, mu) = (DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0 / 1.5);
/// let t = transmit(w, n, mu).unwrap();
/// let b = -mu * w.dot(n) - (1.0 - mu * mu * (1.0 - w.dot(n).powi(2))).sqrt();
/// let all = candidates((mu, b), t, w.dot(n), n, false);
/// let rejections: Vec<_> = all.iter().map(|c| c.rejection).collect();
/// assert_eq!(
///     rejections,
///     [Some(Rejection::WrongSide), None, Some(Rejection::Reversed), Some(Rejection::WrongBend)]
/// );
/// assert!(all.iter().all(|c| (c.t.length() - 1.0).abs() < 1e-15)); // all four unit length
/// ```
#[must_use]
pub fn candidates<V: Vector3>(
    chosen: (V::Scalar, V::Scalar),
    t: V,
    wn: V::Scalar,
    n: V,
    normal_flipped: bool,
) -> [Candidate<V::Scalar>; 4] {
    let (a, b) = chosen;
    let two = V::Scalar::TWO;
    let normal_part = n * t.dot(n);
    let across_surface = t - normal_part * two;
    let across_normal = normal_part * two - t;
    let make = |a, b, t, rejection| Candidate { a, b, t, rejection };
    let mut all = [
        make(a, b, t, None),
        make(
            a,
            -two * a * wn - b,
            across_surface,
            Some(Rejection::WrongSide),
        ),
        make(
            -a,
            two * a * wn + b,
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
        u8::from(c.a < V::Scalar::ZERO) * 2 + u8::from(!plus_root)
    });
    all
}

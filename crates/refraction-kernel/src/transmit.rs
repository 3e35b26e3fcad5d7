//! The calls a ray tracer makes: [`transmit`] in this project's terms (the direction of travel,
//! μ = `n_from/n_to`) and [`transmit_pbrt`] in pbrt-v4's (wi pointing away from the surface, eta a
//! property of the surface, the relative index `etap` returned). Both run the default kernel's
//! fast path (the arithmetic and error bound of [`crate::refract_facing`]) and check their
//! preconditions in debug builds only, because a tracer calls them once per ray.

use super::input::{UNIT_LENGTH_TOLERANCE, is_accepted_ratio, is_unit};
use super::real::{Real, Vector3};
use super::stable;

/// The refracted direction of travel for a ray crossing a surface, or `None` on total internal
/// reflection: the default kernel's fast path.
///
/// - `d`: the unit direction the ray travels in, toward the surface.
/// - `n`: the unit surface normal, on **either side** of the surface: the kernel turns it to
///   face the ray (−n when d·n > 0), so a sphere's outward normal serves for entering and for
///   leaving alike.
/// - `mu`: μ = `n_from/n_to`, the index of the medium the ray travels in over the index of the
///   one it enters. Turning the normal does **not** change μ: on leaving glass (1.5) for air,
///   μ = 1.5 whichever way `n` points.
///
/// Writing `transmit(d, n, mu)` is enough: the vector type (`glam::Vec3` or `glam::DVec3`)
/// picks the precision.
///
/// # Against pbrt
///
/// pbrt-v4's `Refract(wi, n, eta, &etap, &wt)` decides the side for you: when cosθi = n·wi < 0
/// it flips `n` **and** inverts `eta`, because its `eta` belongs to the surface
/// (`n_inside/n_outside` for an outward `n`) and its `wi` points away from the surface. This
/// function turns only `n`: `mu` belongs to the crossing and is the caller's to choose on each
/// side, and `d` points along the ray. pbrt also returns `false` at exactly the critical angle
/// (sin²θt = 1), where this returns the T that lies in the surface. [`transmit_pbrt`] takes
/// pbrt's arguments and returns its `etap`.
///
/// # Returns
///
/// `Some(T)`: T is unit length (within a few ε for unit `d` and `n`, within
/// 6·[`UNIT_LENGTH_TOLERANCE`] for vectors that are unit within that tolerance) and never NaN for
/// inputs that meet the preconditions; T = `d` bit for bit when μ = 1; at the critical angle
/// (k = 0) T lies in the surface. The angle between T and the exact refracted ray is at most
/// 32·ε·κ, with κ the problem's condition number ([`crate::condition_number`]). Within a few ε
/// of grazing (|d·n| tiny) the side `n` is turned to is the sign of the rounded d·n.
///
/// `None`: total internal reflection, μ²·sin²θi > 1 (k < 0); the reflected ray is
/// d − 2(d·n)·n.
///
/// # Panics
///
/// In debug builds only, when a precondition is broken: `d` or `n` is not unit length within
/// [`UNIT_LENGTH_TOLERANCE`] (relative; NaN or infinite components fail too), or `mu` is not
/// within ε² ≤ μ ≤ 1/ε² (ε the precision's machine epsilon: about 1.4e-14 to 7e13 in `f32`, 5e-32
/// to 2e31 in `f64`; NaN, ∞ and μ ≤ 0 fail). Release builds do not check: there a `d` of length
/// 10 gives a wrong T or a false `None` (at 36.87° with μ = 1/1.5, `None`), and μ = 0 gives a
/// vector straight through the surface. For vectors of any length and indices of any value,
/// checked and reported, call [`crate::refract`].
///
/// # Examples
///
/// ```
/// use glam::{DVec3, Vec3};
/// use refraction_kernel::transmit;
/// // Air into glass at 36.87° from the normal, in f32 and in f64 alike.
/// let t = transmit(Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5).expect("no TIR here");
/// assert!((t.x - 0.4).abs() < 1e-6 && t.y < 0.0); // Snell: sinθt = μ·sinθi
/// let t64 = transmit(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0 / 1.5).unwrap();
/// assert!((t64.length() - 1.0).abs() < 1e-15 && (t64.x - 0.4).abs() < 1e-15);
/// // The normal on the far side is turned to face the ray: the same T.
/// assert_eq!(transmit(DVec3::new(0.6, -0.8, 0.0), -DVec3::Y, 1.0 / 1.5), Some(t64));
/// // Leaving glass at 53.13° from the normal, past the critical angle (41.8°).
/// assert_eq!(transmit(Vec3::new(0.8, 0.6, 0.0), Vec3::Y, 1.5), None);
/// ```
#[inline]
#[must_use]
#[track_caller]
pub fn transmit<V: Vector3>(d: V, n: V, mu: V::Scalar) -> Option<V> {
    debug_assert_preconditions("transmit", [("d", d), ("n", n)], ("mu", mu));
    stable::transmit::<V::Scalar>(d, n, mu)
}

/// What [`transmit_pbrt`] returns: pbrt-v4's `*wt` and `*etap`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transmitted<S: Real> {
    /// The transmitted direction of travel (pbrt's `*wt`), unit length (see [`transmit`]).
    pub t: S::Vec3,
    /// The relative index of refraction along the ray, `n_to/n_from` (pbrt's `*etap`): `eta`
    /// when `wi` is on the side `n` points to, 1/`eta` when pbrt flips. pbrt divides the
    /// radiance it carries across by etap².
    pub etap: S,
}

/// pbrt-v4's `Refract(wi, n, eta, &etap, &wt)` with the default kernel's arithmetic: the
/// transmitted direction and the relative index along the ray, or `None` where pbrt returns
/// `false`.
///
/// - `wi`: the unit direction back toward where the ray came from (−d: pbrt's `wi` points
///   away from the surface).
/// - `n`: the unit surface normal, on either side.
/// - `eta`: the index on the side `n` points away from over the index on the side it points
///   to: a glass surface with an outward normal has `eta` = `n_glass/n_air` = 1.5 however the ray
///   crosses it.
///
/// As pbrt-v4 does (commit 5f7a606, `src/pbrt/util/scattering.h`, `Refract`): cosθi = n·wi;
/// when cosθi < 0 the ray comes from the side `n` points away from, and pbrt flips `n` to −n and
/// inverts `eta` to 1/`eta`; the returned `etap` is `eta` after that flip, `n_to/n_from`. The
/// ray's μ = `n_from/n_to` of [`transmit`] is then 1/`etap`, computed here without a second
/// rounding (μ = `eta` itself when flipped).
///
/// # Returns
///
/// `Some(Transmitted { t, etap })`, with `t` as [`transmit`] returns it for d = −`wi` and that μ
/// (unit length, never NaN for inputs that meet the preconditions); pbrt's `*wt` is the same
/// direction with pbrt's roundings, which lose digits where this does not: 1 − cos²θi near
/// normal incidence, 1 − sin²θt between near-equal indices at grazing incidence.
///
/// `None` on total internal reflection: sin²θt = sin²θi/etap² ≥ 1, **including sin²θt = 1
/// exactly**, where pbrt too returns `false` (and [`transmit`] returns a T along the surface);
/// with `eta` = 1 that is a `wi` in the surface. pbrt's rounded sin²θi = 1 − cos²θi is 1 for
/// every ray within about √ε of grazing, so with `eta` = 1 it returns `false` for all of them
/// (for `f32`, cosθi below about 2.4e-4); this function transmits them. For pbrt's own bits,
/// rounding for rounding, see `api::pbrt::refract` (the `api` feature).
///
/// # Panics
///
/// In debug builds only, as [`transmit`]'s: `wi` or `n` not unit length within
/// [`UNIT_LENGTH_TOLERANCE`], or `eta` not within ε² ≤ eta ≤ 1/ε² (NaN, ∞ and eta ≤ 0 fail).
/// Release builds do not check; see [`transmit`] for what broken preconditions give.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::transmit_pbrt;
/// let n = Vec3::Y; // the outward normal of a glass surface: eta = 1.5 / 1.0
/// // Entering: wi (= −d) is on the side n points to.
/// let enter = transmit_pbrt(-Vec3::new(0.6, -0.8, 0.0), n, 1.5).expect("air to glass");
/// assert_eq!(enter.etap, 1.5);
/// assert!((enter.t.x - 0.4).abs() < 1e-6 && enter.t.y < 0.0);
/// // Leaving through the same outward normal: pbrt's flip, etap = 1/eta.
/// let up = Vec3::new(0.4, 0.84_f32.sqrt(), 0.0);
/// let leave = transmit_pbrt(-up, n, 1.5).expect("below the critical angle");
/// assert_eq!(leave.etap, 1.0 / 1.5);
/// assert!((leave.t - Vec3::new(0.6, 0.8, 0.0)).length() < 1e-6);
/// // Leaving at 53.13°, past the critical angle: total internal reflection.
/// assert_eq!(transmit_pbrt(-Vec3::new(0.8, 0.6, 0.0), n, 1.5), None);
/// // sin²θt = 1 exactly (eta = 1, wi in the surface): pbrt's `false`; `transmit` would
/// // return the ray itself.
/// assert_eq!(transmit_pbrt(-Vec3::X, n, 1.0), None);
/// assert_eq!(refraction_kernel::transmit(Vec3::X, n, 1.0), Some(Vec3::X));
/// ```
#[inline]
#[must_use]
#[track_caller]
pub fn transmit_pbrt<V: Vector3>(wi: V, n: V, eta: V::Scalar) -> Option<Transmitted<V::Scalar>> {
    debug_assert_preconditions("transmit_pbrt", [("wi", wi), ("n", n)], ("eta", eta));
    let d = -wi;
    // d·n > 0 is pbrt's Dot(n, wi) < 0 (negation is exact): the ray leaves through the side n
    // points to, and pbrt flips. The fast path turns n on the same test, so the two agree.
    let flipped = d.dot(n) > V::Scalar::ZERO;
    let inverse = V::Scalar::ONE / eta;
    let (mu, etap) = if flipped {
        (eta, inverse)
    } else {
        (inverse, eta)
    };
    stable::transmit_crossing::<V::Scalar>(d, n, mu).map(|t| Transmitted { t, etap })
}

/// Asserts, in debug builds, the preconditions that [`transmit`] and [`transmit_pbrt`] list
/// under `# Panics`, naming the caller's arguments.
#[inline]
#[track_caller]
fn debug_assert_preconditions<V: Vector3>(
    function: &str,
    vectors: [(&str, V); 2],
    (ratio, value): (&str, V::Scalar),
) {
    for (name, v) in vectors {
        debug_assert!(
            is_unit(v),
            "{function}: `{name}` = {:?} has length {}, not 1 within {UNIT_LENGTH_TOLERANCE:e}: \
             normalise it, or call `refract`, which accepts any length",
            v.to_array(),
            v.length()
        );
    }
    debug_assert!(
        is_accepted_ratio::<V::Scalar>(value.to_f64()),
        "{function}: `{ratio}` = {value} is not a finite index ratio from ε² to 1/ε² ({} \
         refracts {:e} to {:e}): check the indices, or call `refract`, which reports them",
        V::Scalar::NAME,
        (V::Scalar::EPSILON * V::Scalar::EPSILON).to_f64(),
        1.0 / (V::Scalar::EPSILON * V::Scalar::EPSILON).to_f64(),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec3, Vec3};

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "transmit: `d` = [6.0, -8.0, 0.0] has length 10")]
    fn a_long_direction_is_refused_in_debug_builds() {
        let _ = transmit(Vec3::new(6.0, -8.0, 0.0), Vec3::Y, 1.0 / 1.5);
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "transmit: `mu` = 0 is not a finite index ratio")]
    fn a_zero_ratio_is_refused_in_debug_builds() {
        let _ = transmit(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 0.0);
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "transmit_pbrt: `n` = [NaN, 1.0, 0.0] has length NaN")]
    fn a_nan_normal_is_refused_in_debug_builds() {
        let _ = transmit_pbrt(
            DVec3::new(-0.6, 0.8, 0.0),
            DVec3::new(f64::NAN, 1.0, 0.0),
            1.5,
        );
    }

    #[test]
    fn pbrt_style_agrees_with_transmit_on_both_sides() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        // The outward normal: entering; the normal flipped: pbrt reads it as leaving.
        for (n, mu, etap) in [(DVec3::Y, 1.0 / 1.5, 1.5), (-DVec3::Y, 1.5, 1.0 / 1.5)] {
            let pbrt = transmit_pbrt(-d, n, 1.5).unwrap();
            assert_eq!(Some(pbrt.t), transmit(d, n, mu));
            assert_eq!(pbrt.etap, etap);
        }
    }
}

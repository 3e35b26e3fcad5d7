//! Residuals that say whether a direction is a physical refracted ray, usable by tests, by the
//! explorer's candidates table and by a student checking their own T.

use super::real::{Real as _, Vector3};

/// How far a candidate direction is from satisfying each law of refraction.
///
/// All residuals are absolute and, for the kernel's T, at most about ε·κ (see
/// [`condition_number`]); compare them with the predicates below and a tolerance such as
/// [`super::Refraction::tolerance`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checks {
    /// | |T| − 1 |.
    pub unit_length: f64,
    /// Signed Snell: |`T_tan` − `μ·d_tan`|, the tangential part of T against μ times that of the
    /// travel direction d. Fails for every rejected candidate.
    pub snell: f64,
    /// Squared Snell (source eq. 10): |(1 − cos²θi)·μ² − (1 − (T·n)²)|. All four candidates pass.
    pub squared_snell: f64,
    /// |T·(d × n)|: T must lie in the plane of incidence.
    pub coplanarity: f64,
    /// T·n for the normal n that faces the ray: ≤ 0 when T crosses into the new medium.
    pub normal_part: f64,
    /// `T_tan·d_tan`: ≥ 0 when T bends the same way the ray was going along the surface.
    pub tangential_part: f64,
}

impl Checks {
    /// The residuals of `t` as the refraction of the unit travel direction `d` at the unit
    /// normal `n` facing it (d·n ≤ 0) with μ = `μ_i/μ_t`: how a ray tracer's author checks their
    /// own T.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::{Checks, transmit};
    /// let (d, n, mu) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5);
    /// let right = Checks::of(transmit(d, n, mu).unwrap(), d, n, mu);
    /// assert!(right.is_unit(1e-6) && right.obeys_snell(1e-6) && right.is_on_correct_side(1e-6));
    /// // The textbook bug of the wrong root: T mirrored back into the first medium.
    /// let t = transmit(d, n, mu).unwrap();
    /// let mirrored = Vec3::new(t.x, -t.y, t.z);
    /// assert!(!Checks::of(mirrored, d, n, mu).is_on_correct_side(1e-6));
    /// ```
    #[must_use]
    pub fn of<V: Vector3>(t: V, d: V, n: V, mu: V::Scalar) -> Self {
        let tangential = |v: V| v - n * v.dot(n);
        let (t_tan, d_tan) = (tangential(t), tangential(d));
        let (tn, dn) = (t.dot(n).to_f64(), d.dot(n).to_f64());
        let mu64 = mu.to_f64();
        Self {
            unit_length: (t.length().to_f64() - 1.0).abs(),
            snell: (t_tan - d_tan * mu).length().to_f64(),
            squared_snell: ((1.0 - dn * dn) * mu64 * mu64 - (1.0 - tn * tn)).abs(),
            coplanarity: t.dot(d.cross(n)).to_f64().abs(),
            normal_part: tn,
            tangential_part: t_tan.dot(d_tan).to_f64(),
        }
    }

    /// Whether T is unit length within `tolerance`.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// assert!(Checks::of(d, d, n, 1.0).is_unit(1e-6));
    /// assert!(!Checks::of(d * 1.5, d, n, 1.0).is_unit(1e-6)); // an un-normalised T
    /// ```
    #[must_use]
    pub fn is_unit(&self, tolerance: f64) -> bool {
        self.unit_length <= tolerance
    }

    /// Whether T satisfies Snell's law with its sign (tangential parts agree) within `tolerance`.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// assert!(Checks::of(d, d, n, 1.0).obeys_snell(1e-6)); // μ = 1: T = d
    /// assert!(!Checks::of(d, d, n, 1.0 / 1.5).obeys_snell(1e-6)); // not bent at all
    /// ```
    #[must_use]
    pub fn obeys_snell(&self, tolerance: f64) -> bool {
        self.snell <= tolerance
    }

    /// Whether T satisfies the squared Snell equation (eq. 10) within `tolerance`.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// // −d, pointing back, passes the squared law although it is no refraction.
    /// let back = Checks::of(-d, d, n, 1.0);
    /// assert!(back.obeys_squared_snell(1e-6) && !back.obeys_snell(1e-6));
    /// ```
    #[must_use]
    pub fn obeys_squared_snell(&self, tolerance: f64) -> bool {
        self.squared_snell <= tolerance
    }

    /// Whether T lies in the plane of incidence within `tolerance`.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// assert!(Checks::of(d, d, n, 1.0).is_coplanar(1e-6));
    /// assert!(!Checks::of(Vec3::new(0.0, -0.8, 0.6), d, n, 1.0).is_coplanar(1e-6));
    /// ```
    #[must_use]
    pub fn is_coplanar(&self, tolerance: f64) -> bool {
        self.coplanarity <= tolerance
    }

    /// Whether T goes into the new medium (or along the surface, within `tolerance`).
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// assert!(Checks::of(d, d, n, 1.0).is_on_correct_side(1e-6));
    /// let reflected = Vec3::new(0.6, 0.8, 0.0);
    /// assert!(!Checks::of(reflected, d, n, 1.0).is_on_correct_side(1e-6));
    /// ```
    #[must_use]
    pub fn is_on_correct_side(&self, tolerance: f64) -> bool {
        self.normal_part <= tolerance
    }

    /// Whether T's part along the surface points the way the incoming ray's does: the paper's
    /// μ → 1 argument for the sign of a.
    ///
    /// # Examples
    ///
    /// ```
    /// # use glam::Vec3;
    /// # use refraction_kernel::Checks;
    /// let (d, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y);
    /// assert!(Checks::of(d, d, n, 1.0).bends_correctly(1e-6));
    /// // The wrong sign of a: mirrored across the normal.
    /// assert!(!Checks::of(Vec3::new(-0.6, -0.8, 0.0), d, n, 1.0).bends_correctly(1e-6));
    /// ```
    #[must_use]
    pub fn bends_correctly(&self, tolerance: f64) -> bool {
        self.tangential_part >= -tolerance
    }
}

/// The refraction problem's own condition number
/// κ = 1 + μ + (μ²·sinθi·cosθi + μ·sinθi)/max(cosθt, ε): how much a relative perturbation of
/// the inputs of size ε can turn T. The default kernel's angular error is at most 32·ε·κ.
///
/// `cos_i` and `cos_t` are the cosines of the incidence and refraction angles (`cos_t` ≥ 0, and 0
/// at or beyond the critical angle); `epsilon` is the working precision's machine epsilon.
///
/// # Examples
///
/// ```
/// use refraction_kernel::condition_number;
/// // Normal incidence with equal indices: 1 + μ, the least there is.
/// assert_eq!(condition_number(1.0, 1.0, 1.0, f64::EPSILON), 2.0);
/// // Glass to air with T a millionth of a radian from the surface: ill-conditioned.
/// let (sin_t, cos_t) = (1e-6_f64.cos(), 1e-6_f64.sin());
/// let sin_i = sin_t / 1.5; // Snell: sinθt = μ·sinθi
/// let kappa = condition_number(1.5, (1.0 - sin_i * sin_i).sqrt(), cos_t, f64::EPSILON);
/// assert!(kappa > 1e6);
/// ```
#[must_use]
pub fn condition_number(mu: f64, cos_i: f64, cos_t: f64, epsilon: f64) -> f64 {
    let cos_i = cos_i.abs().min(1.0);
    let sin_i = (1.0 - cos_i * cos_i).sqrt();
    1.0 + mu + (mu * mu * sin_i * cos_i + mu * sin_i) / cos_t.max(epsilon)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn a_reflected_ray_fails_side_but_passes_squared_snell() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let r = DVec3::new(0.6, 0.8, 0.0);
        let checks = Checks::of(r, d, DVec3::Y, 1.0);
        assert!(checks.obeys_squared_snell(1e-15));
        assert!(checks.obeys_snell(1e-15));
        assert!(!checks.is_on_correct_side(1e-15));
        assert!(checks.bends_correctly(1e-15));
    }

    #[test]
    fn condition_number_grows_toward_the_critical_angle() {
        let far = condition_number(1.5, 0.9, 0.8, f64::EPSILON);
        let near = condition_number(1.5, 0.75, 1e-6, f64::EPSILON);
        assert!(near > 1e5 * far);
        assert_eq!(condition_number(1.0, 1.0, 1.0, f64::EPSILON), 2.0);
    }
}

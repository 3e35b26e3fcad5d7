//! The two precisions the kernel runs at, behind two small sealed traits.
//!
//! glam has separate types for `f32` (`Vec3`) and `f64` (`DVec3`) with the same method names
//! but no shared trait; [`Real`] and [`Vector3`] name exactly the operations the kernel needs
//! so that every formula is written once. They are sealed (a supertrait in a private module):
//! the error bounds are stated, and tested, for IEEE `f32` and `f64` only, and a method can be
//! added without breaking anyone's impl.

use core::fmt::{Debug, Display};
use core::ops::{Add, Div, Mul, Neg, Sub};

/// Seals [`Real`] and [`Vector3`]: `Sealed` is public, so that the two traits may name it, but
/// in a private module, so that no other crate can implement it (nor them).
mod sealed {
    /// Implemented for `f32`, `f64`, `glam::Vec3` and `glam::DVec3` only.
    pub trait Sealed {}
}

/// A floating-point scalar the kernel can refract with: `f32` or `f64`, nothing else (the
/// trait is sealed).
///
/// Use it as a bound to write code once for both precisions; the vector of the same precision
/// is [`Real::Vec3`].
///
/// # Examples
///
/// ```
/// use refraction_kernel::{Real, Vector3};
/// /// cosθi for a unit travel direction and a unit normal facing it, in either precision.
/// fn cos_incidence<S: Real>(d: S::Vec3, n: S::Vec3) -> S {
///     (-d.dot(n)).min(S::ONE)
/// }
/// let cos = cos_incidence::<f32>(glam::Vec3::new(0.6, -0.8, 0.0), glam::Vec3::Y);
/// assert_eq!(cos, 0.8);
/// assert_eq!(<f64 as Real>::NAME, "f64");
/// ```
pub trait Real:
    sealed::Sealed
    + Copy
    + Debug
    + Display
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// The 3D vector of this precision (`glam::Vec3` or `glam::DVec3`).
    type Vec3: Vector3<Scalar = Self>;
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// ½.
    const HALF: Self;
    /// Machine epsilon: the gap between 1 and the next larger number.
    const EPSILON: Self;
    /// A short name of the precision, as used in JSON: `"f32"` or `"f64"`.
    const NAME: &'static str;
    /// Square root (correctly rounded, IEEE 754).
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(<f32 as Real>::sqrt(2.25), 1.5);
    /// ```
    #[must_use]
    fn sqrt(self) -> Self;
    /// Absolute value.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(<f64 as Real>::abs(-0.5), 0.5);
    /// ```
    #[must_use]
    fn abs(self) -> Self;
    /// Whether the value is neither infinite nor NaN.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert!(<f32 as Real>::is_finite(1e38) && !<f32 as Real>::is_finite(f32::INFINITY));
    /// ```
    #[must_use]
    fn is_finite(self) -> bool;
    /// Whether the value is NaN.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert!(<f64 as Real>::is_nan(f64::NAN) && !<f64 as Real>::is_nan(0.0));
    /// ```
    #[must_use]
    fn is_nan(self) -> bool;
    /// Whether the sign bit is set (true for −0.0 and for NaN with the sign bit set).
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert!(<f32 as Real>::is_sign_negative(-0.0) && !<f32 as Real>::is_sign_negative(0.0));
    /// ```
    #[must_use]
    fn is_sign_negative(self) -> bool;
    /// `self · a + b` with one rounding (a true fused multiply-add, in software where the CPU
    /// has none): what C's `fma` and Rust's `mul_add` compute. The API adapters need it to
    /// reproduce pbrt-v4 and Mitsuba 3 bit for bit.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// // One rounding: (1 + ε)(1 − ε) − 1 = −ε² exactly, which a multiply then an add rounds to 0.
    /// let e = f64::EPSILON;
    /// assert_eq!(<f64 as Real>::mul_add(1.0 + e, 1.0 - e, -1.0), -e * e);
    /// ```
    #[must_use]
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// The nearest value of this precision to `x` (may overflow to ±∞).
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(<f32 as Real>::from_f64(0.1), 0.1_f32);
    /// assert_eq!(<f32 as Real>::from_f64(1e300), f32::INFINITY);
    /// ```
    #[must_use]
    fn from_f64(x: f64) -> Self;
    /// The value widened (exactly) to `f64`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(Real::to_f64(0.1_f32), 0.100_000_001_490_116_12);
    /// ```
    #[must_use]
    fn to_f64(self) -> f64;
    /// The larger of two values.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(<f64 as Real>::max(0.5, 2.0), 2.0);
    /// ```
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// The smaller of two values.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Real;
    /// assert_eq!(<f32 as Real>::min(0.5, 2.0), 0.5);
    /// ```
    #[must_use]
    fn min(self, other: Self) -> Self;
}

/// The vector operations the kernel uses, implemented by `glam::Vec3` and `glam::DVec3` and
/// nothing else (the trait is sealed).
///
/// The kernel's entry points for a ray tracer ([`crate::transmit`], [`crate::transmit_pbrt`],
/// [`crate::refract_facing`]) are generic over the vector, so that glam's type alone picks the
/// precision and no turbofish is needed.
///
/// # Examples
///
/// ```
/// use refraction_kernel::Vector3;
/// /// The part of `v` along the surface with unit normal `n`, in either precision.
/// fn tangential<V: Vector3>(v: V, n: V) -> V {
///     v - n * v.dot(n)
/// }
/// assert_eq!(tangential(glam::DVec3::new(0.6, -0.8, 0.0), glam::DVec3::Y).y, 0.0);
/// assert_eq!(tangential(glam::Vec3::new(0.6, -0.8, 0.0), glam::Vec3::Y).x, 0.6);
/// ```
pub trait Vector3:
    sealed::Sealed
    + Copy
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<<Self as Vector3>::Scalar, Output = Self>
    + Neg<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// The scalar of this precision (`f32` for `Vec3`, `f64` for `DVec3`).
    type Scalar: Real<Vec3 = Self>;
    /// A vector from its components.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(<Vec3 as Vector3>::new(1.0, 2.0, 3.0), Vec3::new(1.0, 2.0, 3.0));
    /// ```
    #[must_use]
    fn new(x: Self::Scalar, y: Self::Scalar, z: Self::Scalar) -> Self;
    /// The components `[x, y, z]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::to_array(DVec3::new(1.0, 2.0, 3.0)), [1.0, 2.0, 3.0]);
    /// ```
    #[must_use]
    fn to_array(self) -> [Self::Scalar; 3];
    /// Dot product.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::dot(Vec3::new(0.6, -0.8, 0.0), Vec3::Y), -0.8);
    /// ```
    #[must_use]
    fn dot(self, other: Self) -> Self::Scalar;
    /// Cross product.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::cross(DVec3::X, DVec3::Y), DVec3::Z);
    /// ```
    #[must_use]
    fn cross(self, other: Self) -> Self;
    /// Squared Euclidean length.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::length_squared(Vec3::new(3.0, 4.0, 0.0)), 25.0);
    /// ```
    #[must_use]
    fn length_squared(self) -> Self::Scalar;
    /// Euclidean length.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::length(DVec3::new(3.0, 4.0, 0.0)), 5.0);
    /// ```
    #[must_use]
    fn length(self) -> Self::Scalar;
    /// Each component divided by `s`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Vector3;
    /// use glam::{DVec3, Vec3};
    /// assert_eq!(Vector3::div_scalar(Vec3::new(3.0, -4.0, 0.0), 5.0), Vec3::new(0.6, -0.8, 0.0));
    /// ```
    #[must_use]
    fn div_scalar(self, s: Self::Scalar) -> Self;
}

// Every method is `#[inline]`: the kernel's generic code is instantiated in the crates that
// call it, and without the attribute these one-line methods could not be inlined there.
macro_rules! impl_real {
    ($s:ty, $v:ty, $name:literal, $from:path) => {
        impl sealed::Sealed for $s {}
        impl sealed::Sealed for $v {}

        impl Real for $s {
            type Vec3 = $v;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const EPSILON: Self = <$s>::EPSILON;
            const NAME: &'static str = $name;
            #[inline]
            fn sqrt(self) -> Self {
                <$s>::sqrt(self)
            }
            #[inline]
            fn abs(self) -> Self {
                <$s>::abs(self)
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$s>::is_finite(self)
            }
            #[inline]
            fn is_nan(self) -> bool {
                <$s>::is_nan(self)
            }
            #[inline]
            fn is_sign_negative(self) -> bool {
                <$s>::is_sign_negative(self)
            }
            #[inline]
            fn mul_add(self, a: Self, b: Self) -> Self {
                <$s>::mul_add(self, a, b)
            }
            #[inline]
            fn from_f64(x: f64) -> Self {
                $from(x)
            }
            #[inline]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
            #[inline]
            fn max(self, other: Self) -> Self {
                <$s>::max(self, other)
            }
            #[inline]
            fn min(self, other: Self) -> Self {
                <$s>::min(self, other)
            }
        }

        impl Vector3 for $v {
            type Scalar = $s;
            #[inline]
            fn new(x: $s, y: $s, z: $s) -> Self {
                <$v>::new(x, y, z)
            }
            #[inline]
            fn to_array(self) -> [$s; 3] {
                <$v>::to_array(&self)
            }
            #[inline]
            fn dot(self, other: Self) -> $s {
                <$v>::dot(self, other)
            }
            #[inline]
            fn cross(self, other: Self) -> Self {
                <$v>::cross(self, other)
            }
            #[inline]
            fn length_squared(self) -> $s {
                <$v>::length_squared(self)
            }
            #[inline]
            fn length(self) -> $s {
                <$v>::length(self)
            }
            #[inline]
            fn div_scalar(self, s: $s) -> Self {
                self / s
            }
        }
    };
}

/// f64 to f32 rounds to nearest, as a cast does (values past f32's range become infinite).
#[expect(
    clippy::cast_possible_truncation,
    reason = "rounding to f32 is the conversion asked for"
)]
const fn round_to_f32(x: f64) -> f32 {
    x as f32
}

/// f64 to f64: no conversion.
const fn same_f64(x: f64) -> f64 {
    x
}

impl_real!(f32, glam::Vec3, "f32", round_to_f32);
impl_real!(f64, glam::DVec3, "f64", same_f64);

/// `single(values)` when `S` is `f32`, `double(values)` when it is `f64`: for the variants that
/// call what [`Real`] and [`Vector3`] leave out because no one else needs it (the trigonometric
/// variant's angle functions, glam's own `refract`). The traits are sealed, so `S` is one of the
/// two, told apart by its epsilon; the values go through `f64`, which is exact both ways for an
/// `f32`, and the optimiser removes the conversions.
#[cfg(feature = "variants")]
#[inline(always)]
pub(crate) fn per_precision<S: Real, const N: usize, const M: usize>(
    values: [S; N],
    single: impl FnOnce([f32; N]) -> [f32; M],
    double: impl FnOnce([f64; N]) -> [f64; M],
) -> [S; M] {
    let wide = values.map(Real::to_f64);
    if S::EPSILON.to_f64() == f64::from(f32::EPSILON) {
        // Exact: each value is an f32.
        #[expect(clippy::cast_possible_truncation)]
        let narrow = wide.map(|x| x as f32);
        single(narrow).map(|y| S::from_f64(f64::from(y)))
    } else {
        double(wide).map(S::from_f64)
    }
}

//! The two precisions the kernel runs at, behind one small trait.
//!
//! glam has separate types for `f32` (`Vec3`) and `f64` (`DVec3`) with the same method names
//! but no shared trait; [`Real`] and [`Vector3`] name exactly the operations the kernel needs
//! so that every formula is written once.

use std::fmt::{Debug, Display};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A floating-point scalar the kernel can refract with: `f32` or `f64`.
pub trait Real:
    Copy
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
    type Vec3: Vector3<Self>;
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
    #[must_use]
    fn sqrt(self) -> Self;
    /// Absolute value.
    #[must_use]
    fn abs(self) -> Self;
    /// Whether the value is neither infinite nor NaN.
    #[must_use]
    fn is_finite(self) -> bool;
    /// The nearest value of this precision to `x` (may overflow to ±∞).
    #[must_use]
    fn from_f64(x: f64) -> Self;
    /// The value widened (exactly) to `f64`.
    #[must_use]
    fn to_f64(self) -> f64;
    /// The larger of two values.
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// The smaller of two values.
    #[must_use]
    fn min(self, other: Self) -> Self;
    /// Arccosine in radians (the `trig` variant only).
    #[must_use]
    fn acos(self) -> Self;
    /// Arcsine in radians (the `trig` variant only).
    #[must_use]
    fn asin(self) -> Self;
    /// Sine and cosine of an angle in radians (the `trig` variant only).
    #[must_use]
    fn sin_cos(self) -> (Self, Self);
}

/// The vector operations the kernel uses, implemented by `glam::Vec3` and `glam::DVec3`.
pub trait Vector3<S>:
    Copy
    + Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<S, Output = Self>
    + Neg<Output = Self>
    + Send
    + Sync
    + 'static
{
    /// A vector from its components.
    #[must_use]
    fn new(x: S, y: S, z: S) -> Self;
    /// The components `[x, y, z]`.
    #[must_use]
    fn to_array(self) -> [S; 3];
    /// Dot product.
    #[must_use]
    fn dot(self, other: Self) -> S;
    /// Cross product.
    #[must_use]
    fn cross(self, other: Self) -> Self;
    /// Squared Euclidean length.
    #[must_use]
    fn length_squared(self) -> S;
    /// Euclidean length.
    #[must_use]
    fn length(self) -> S;
    /// Each component divided by `s`.
    #[must_use]
    fn div_scalar(self, s: S) -> Self;
    /// glam's own `refract` (the GLSL formula): zero on total internal reflection.
    #[must_use]
    fn glam_refract(self, normal: Self, eta: S) -> Self;
}

// Every method is `#[inline]`: the kernel's generic code is instantiated in the crates that
// call it, and without the attribute these one-line methods could not be inlined there.
macro_rules! impl_real {
    ($s:ty, $v:ty, $name:literal) => {
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
            #[allow(clippy::cast_possible_truncation, trivial_numeric_casts)]
            fn from_f64(x: f64) -> Self {
                x as $s
            }
            #[inline]
            #[allow(trivial_numeric_casts)]
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
            #[inline]
            fn acos(self) -> Self {
                <$s>::acos(self)
            }
            #[inline]
            fn asin(self) -> Self {
                <$s>::asin(self)
            }
            #[inline]
            fn sin_cos(self) -> (Self, Self) {
                <$s>::sin_cos(self)
            }
        }

        impl Vector3<$s> for $v {
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
            #[inline]
            fn glam_refract(self, normal: Self, eta: $s) -> Self {
                <$v>::refract(self, normal, eta)
            }
        }
    };
}

impl_real!(f32, glam::Vec3, "f32");
impl_real!(f64, glam::DVec3, "f64");

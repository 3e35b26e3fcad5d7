//! The refraction variants whose accuracy and speed the `bench` command compares, behind one
//! enum so that every caller runs them the same way.

use super::batch::{RayBatch, Transmissions, for_each_ray, transmit_batch};
use super::input::Convention;
use super::real::{Real, Vector3, per_precision};
use super::{seed, stable, trig};

/// One way of computing T.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Variant {
    /// The paper's formula taken literally ([`seed`]).
    Seed,
    /// The default kernel ([`crate::transmit`]).
    Stable,
    /// Through acos, asin, sin and cos: θi = acos(cosθi), θt = asin(μ·sinθi), and T as −N
    /// rotated by θt toward the surface (Rodrigues' formula).
    Trig,
    /// glam's own `refract`, the GLSL formula, with the normal turned to face the ray.
    Glam,
    /// The default kernel over structure-of-arrays, vectorised ([`transmit_batch`]).
    Batch,
}

impl Variant {
    /// Every variant, in the order reports list them.
    pub const ALL: [Self; 5] = [
        Self::Seed,
        Self::Stable,
        Self::Trig,
        Self::Glam,
        Self::Batch,
    ];

    /// The short name used in reports and JSON.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::Variant;
    /// let names: Vec<_> = Variant::ALL.iter().map(|v| v.name()).collect();
    /// assert_eq!(names, ["seed", "stable", "trig", "glam", "batch"]);
    /// ```
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Seed => "seed",
            Self::Stable => "stable",
            Self::Trig => "trig",
            Self::Glam => "glam",
            Self::Batch => "batch",
        }
    }

    /// T for one ray (unit travel direction `d`, unit normal `n` facing it, μ), or `None` on
    /// total internal reflection. [`Variant::Batch`] answers as [`Variant::Stable`], which it
    /// equals bit for bit. No precondition is checked: the `bench` command feeds the variants
    /// its hard cases as they are.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::Variant;
    /// let d = DVec3::new(0.6, -0.8, 0.0);
    /// for variant in Variant::ALL {
    ///     let t = variant.transmit(d, DVec3::Y, 1.0 / 1.5).expect("no TIR here");
    ///     assert!((t.x - 0.4).abs() < 1e-12, "{variant:?}");
    /// }
    /// assert_eq!(Variant::Glam.transmit(DVec3::new(0.8, -0.6, 0.0), DVec3::Y, 1.5), None);
    /// ```
    #[inline]
    #[must_use]
    pub fn transmit<V: Vector3>(self, d: V, n: V, mu: V::Scalar) -> Option<V> {
        match self {
            Self::Seed => seed::refract(d, n, mu, Convention::AlongRay),
            Self::Stable | Self::Batch => stable::transmit::<V::Scalar>(d, n, mu),
            Self::Trig => trig::transmit::<V::Scalar>(d, n, mu),
            Self::Glam => {
                let t = glam_refract::<V::Scalar>(d, stable::facing::<V::Scalar>(d, n), mu);
                (t.to_array() != [V::Scalar::ZERO; 3]).then_some(t)
            }
        }
    }

    /// T for every ray of `rays` into `out` (resized to match): one call per ray for the scalar
    /// variants, one vectorised pass for [`Variant::Batch`].
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::Variant;
    /// use refraction_kernel::batch::{RayBatch, Transmissions};
    /// let mut rays = RayBatch::<f32>::new();
    /// rays.push(Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5);
    /// rays.push(Vec3::new(0.8, -0.6, 0.0), Vec3::Y, 1.5); // past the critical angle
    /// let mut out = Transmissions::for_batch(&rays);
    /// Variant::Trig.transmit_all(&rays, &mut out);
    /// assert!((out.get(0).unwrap().x - 0.4).abs() < 1e-6);
    /// assert_eq!(out.get(1), None);
    /// ```
    pub fn transmit_all<S: Real>(self, rays: &RayBatch<S>, out: &mut Transmissions<S>) {
        if out.len() != rays.len() {
            *out = Transmissions::for_batch(rays);
        }
        match self {
            Self::Batch => transmit_batch(rays, out),
            Self::Seed => each_ray(rays, out, |d, n, mu| Self::Seed.transmit(d, n, mu)),
            Self::Stable => each_ray(rays, out, |d, n, mu| Self::Stable.transmit(d, n, mu)),
            Self::Trig => each_ray(rays, out, |d, n, mu| Self::Trig.transmit(d, n, mu)),
            Self::Glam => each_ray(rays, out, |d, n, mu| Self::Glam.transmit(d, n, mu)),
        }
    }
}

/// glam's own `refract` (`Vec3::refract` or `DVec3::refract`: the GLSL formula, zero on total
/// internal reflection) in the precision of `S`.
#[inline(always)]
fn glam_refract<S: Real>(i: S::Vec3, n: S::Vec3, eta: S) -> S::Vec3 {
    let ([ix, iy, iz], [nx, ny, nz]) = (i.to_array(), n.to_array());
    let [x, y, z] = per_precision(
        [ix, iy, iz, nx, ny, nz, eta],
        |[ix, iy, iz, nx, ny, nz, eta]| {
            glam::Vec3::new(ix, iy, iz)
                .refract(glam::Vec3::new(nx, ny, nz), eta)
                .to_array()
        },
        |[ix, iy, iz, nx, ny, nz, eta]| {
            glam::DVec3::new(ix, iy, iz)
                .refract(glam::DVec3::new(nx, ny, nz), eta)
                .to_array()
        },
    );
    S::Vec3::new(x, y, z)
}

/// Calls `transmit` on each ray in turn, as a ray tracer calls a scalar kernel: one loop per
/// variant (each closure is a distinct type), kept from being vectorised across rays so that
/// its time is the cost of one call per ray (which is how a tracer, with other work between
/// calls, runs it).
#[inline(always)]
fn each_ray<S: Real>(
    rays: &RayBatch<S>,
    out: &mut Transmissions<S>,
    transmit: impl Fn(S::Vec3, S::Vec3, S) -> Option<S::Vec3>,
) {
    let zero = S::Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    for_each_ray(rays, out, core::hint::black_box, |d, n, mu| {
        let t = transmit(d, n, mu);
        (t.unwrap_or(zero), t.is_none())
    });
}

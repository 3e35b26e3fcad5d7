//! The refraction variants whose accuracy and speed the `bench` command compares, behind one
//! enum so that every caller runs them the same way.

use super::batch::{RayBatch, Transmissions, for_each_ray, transmit_batch};
use super::input::Convention;
use super::real::{Real, Vector3};
use super::{seed, stable, trig};

/// One way of computing T.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Variant {
    /// The source's formula taken literally ([`seed`]).
    Seed,
    /// The default kernel ([`stable::transmit`]).
    Stable,
    /// Through acos, asin, sin and cos ([`trig::transmit`]).
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
    /// equals bit for bit.
    #[inline]
    #[must_use]
    pub fn transmit<S: Real>(self, d: S::Vec3, n: S::Vec3, mu: S) -> Option<S::Vec3> {
        match self {
            Self::Seed => seed::refract(d, n, mu, Convention::AlongRay),
            Self::Stable | Self::Batch => stable::transmit(d, n, mu),
            Self::Trig => trig::transmit(d, n, mu),
            Self::Glam => {
                let t = d.glam_refract(stable::facing::<S>(d, n), mu);
                (t.to_array() != [S::ZERO; 3]).then_some(t)
            }
        }
    }

    /// T for every ray of `rays` into `out` (resized to match): one call per ray for the scalar
    /// variants, one vectorised pass for [`Variant::Batch`].
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
    for_each_ray(rays, out, std::hint::black_box, |d, n, mu| {
        let t = transmit(d, n, mu);
        (t.unwrap_or(zero), t.is_none())
    });
}

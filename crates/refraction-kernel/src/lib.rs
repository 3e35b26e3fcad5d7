//! Refraction of a ray at one interface without trigonometry: T = a·W + b·N, after Ross
//! Beveridge, "Refraction Ray Calculation without Trig. Function Calls" (2013), explained in
//! this repository's `docs/derivation.md`. Depends on glam only (serde is the optional `serde`
//! feature): no pixels, no files, no JSON.
//!
//! - [`refract`]: the default kernel's full answer ([`Refraction`]) for one [`Incidence`]:
//!   T or total internal reflection, the reflected ray, the four sign candidates and the
//!   warnings, with any W and N (not unit, the normal on either side).
//! - [`stable`]: its arithmetic, and the fast path [`stable::transmit`] for a ray tracer.
//! - [`seed`]: the source's formula taken literally, to show what it loses.
//! - [`trig`], [`batch`] and [`Variant`]: the variants the `bench` command compares.
//! - [`candidates`](candidates()) and [`Checks`]: the four sign choices and the laws they break.
//! - [`api`]: what GLSL, pbrt-v4, Ray Tracing in One Weekend and Mitsuba 3 return for a
//!   `refract` call, bit for bit, and what their arguments mean here.
//! - [`Fresnel`]: how much of the light is reflected and transmitted, for s and p polarisation,
//!   from the kernel's own cosines.
//!
//! # Examples
//!
//! A ray tracer's call: a unit travel direction, a unit normal on either side, μ = μ_i/μ_t.
//!
//! ```
//! use glam::Vec3;
//! let d = Vec3::new(0.6, -0.8, 0.0); // 36.87° from the normal, travelling down
//! let t = refraction_kernel::stable::transmit::<f32>(d, Vec3::Y, 1.0 / 1.5).expect("no TIR here");
//! assert!((t.length() - 1.0).abs() < 1e-6 && t.x > 0.0 && t.y < 0.0);
//! assert!((t.x - 0.6 / 1.5).abs() < 1e-6); // Snell: sinθt = μ·sinθi
//! // Glass to air beyond the critical angle (53.13° > 41.8°): total internal reflection.
//! let grazing = Vec3::new(0.8, -0.6, 0.0);
//! assert_eq!(refraction_kernel::stable::transmit::<f32>(grazing, Vec3::Y, 1.5), None);
//! ```
//!
//! The full answer, with the rejected candidates and the reason for each:
//!
//! ```
//! use glam::DVec3;
//! use refraction_kernel::{Convention, Incidence, refract};
//! let answer = refract(&Incidence::<f64> {
//!     w: DVec3::new(0.6, -0.8, 0.0),
//!     n: DVec3::new(0.0, -2.0, 0.0), // an outward normal, not unit: turned round and normalised
//!     mu_i: 1.0,
//!     mu_t: 1.5,
//!     convention: Convention::AlongRay,
//! })?;
//! assert!(answer.normal_flipped);
//! assert_eq!(answer.candidates.iter().filter(|c| c.is_chosen()).count(), 1);
//! let t = answer.t().expect("air to glass always refracts");
//! assert!((t.x - 0.4).abs() < 1e-12);
//! # Ok::<(), refraction_kernel::InputError>(())
//! ```

pub mod api;
pub mod batch;
mod candidates;
mod checks;
mod fresnel;
mod input;
mod real;
mod refraction;
pub mod seed;
pub mod stable;
pub mod trig;
mod variants;

pub use candidates::{Candidate, Rejection, candidates};
pub use checks::{Checks, condition_number};
pub use fresnel::Fresnel;
pub use input::{
    Convention, Incidence, IndexName, InputError, UNIT_LENGTH_TOLERANCE, VectorName, Warning,
};
pub use real::{Real, Vector3};
pub use refraction::{Refraction, Transmission, refract};
pub use variants::Variant;

//! Refraction of a ray at one interface without trigonometry: T = a·W + b·N, after Ross
//! Beveridge, "Refraction Ray Calculation without Trig. Function Calls" (2013), explained in
//! this repository's `docs/derivation.md`. Depends on glam only: no pixels, no files, no JSON.
//!
//! # For a ray tracer: [`transmit`]
//!
//! ```
//! use glam::Vec3;
//! // d: the unit direction of travel; n: the unit normal, on either side; mu = n_from / n_to.
//! let (d, n, mu) = (Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5);
//! let t = refraction_kernel::transmit(d, n, mu); // None on total internal reflection
//! assert!((t.unwrap().x - 0.4).abs() < 1e-6); // Snell: sinθt = μ·sinθi
//! ```
//!
//! The same call takes `glam::DVec3` and an `f64` μ. The normal is turned to face the ray, so
//! a sphere's outward normal serves on the way in and on the way out; μ is not inverted with
//! it (unlike pbrt's `eta`): it is always `n_from/n_to`. T is unit length, never NaN, exactly `d`
//! when μ = 1, and within 32·ε·κ of the exact ray ([`condition_number`] κ), also where the
//! textbook formula loses its digits (near-equal indices at grazing incidence, large μ near
//! normal incidence). Unit vectors and ε² ≤ μ ≤ 1/ε² are preconditions, asserted in debug
//! builds. Around it:
//!
//! - [`transmit_pbrt`]: pbrt-v4's `Refract(wi, n, eta, &etap, &wt)` convention (wi pointing
//!   away from the surface, eta = `n_inside/n_outside`, flipped with the normal), returning the
//!   relative index `etap` with T.
//! - [`refract_facing`]: the same T for a normal that faces the ray, with cosθi, cosθt and the
//!   discriminant, for [`Fresnel::new`].
//! - [`Fresnel`]: how much of the light is reflected and transmitted, for s and p
//!   polarisation, from the kernel's own cosines.
//!
//! # For teaching and debugging: [`refract`]
//!
//! [`refract`] takes an [`Incidence`] with any non-zero W and N (normalised and oriented for
//! you, with a [`Warning`] for each), either [`Convention`] and two indices, and returns the
//! full answer ([`Refraction`]): T or total internal reflection, the reflected ray, the
//! source's numbers, and the four sign [`candidates`](candidates()) that satisfy the squared
//! equations, each rejected one with the [`Rejection`] it breaks, measured by [`Checks`].
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
//!
//! # Generic over the precision
//!
//! Every function works in `f32` (`glam::Vec3`) and `f64` (`glam::DVec3`) through the sealed
//! traits [`Real`] and [`Vector3`]; the functions that take vectors infer the precision from
//! them.
//!
//! # Features
//!
//! None is on by default; [`seed`], the paper's formula taken literally (to show what it
//! loses and the outward-normal bug it makes), is always there.
//! - `serde`: serialisation of the input types and of [`Fresnel`].
//! - `variants`: the variants the explorer's `bench` command compares: `batch` (the default
//!   kernel over structure-of-arrays batches with SIMD, bit for bit the scalar result) and
//!   `Variant` (`seed`, the trigonometric form and glam's own `refract`).
//! - `api`: what GLSL, pbrt-v4, Ray Tracing in One Weekend and Mitsuba 3 return for a `refract`
//!   call, bit for bit, and what their arguments mean here.

#[cfg(feature = "api")]
pub mod api;
#[cfg(feature = "variants")]
pub mod batch;
mod candidates;
mod checks;
mod fresnel;
mod input;
mod real;
mod refraction;
pub mod seed;
mod side;
mod stable;
mod transmission;
mod transmit;
#[cfg(feature = "variants")]
mod trig;
#[cfg(feature = "variants")]
mod variants;

pub use candidates::{Candidate, Rejection, candidates};
pub use checks::{Checks, condition_number};
pub use fresnel::Fresnel;
pub use input::{
    Convention, Incidence, IndexName, InputError, UNIT_LENGTH_TOLERANCE, VectorName, Warning,
};
pub use real::{Real, Vector3};
pub use refraction::{Refraction, refract};
pub use side::Side;
pub use stable::{Facing, refract_facing};
pub use transmission::Transmission;
pub use transmit::{Transmitted, transmit, transmit_pbrt};
#[cfg(feature = "variants")]
pub use variants::Variant;

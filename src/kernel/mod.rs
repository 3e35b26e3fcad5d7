//! Refraction math, trig-free, after the source derivation (`shared/reference`). Depends on glam
//! only: no pixels, no files.
//!
//! - [`refract`]: the default kernel's full answer ([`Refraction`]) for one [`Incidence`].
//! - [`stable`]: its arithmetic, and the fast path [`stable::transmit`].
//! - [`seed`]: the source's formula taken literally, to show what it loses.
//! - [`trig`], [`batch`] and [`Variant`]: the variants the `bench` command compares.
//! - [`candidates`](candidates()) and [`Checks`]: the four sign choices and the laws they break.

pub mod batch;
mod candidates;
mod checks;
mod input;
mod real;
mod refraction;
pub mod seed;
pub mod stable;
pub mod trig;
mod variants;

pub use candidates::{Candidate, Rejection, candidates};
pub use checks::{Checks, condition_number};
pub use input::{
    Convention, Incidence, IndexName, InputError, UNIT_LENGTH_TOLERANCE, VectorName, Warning,
};
pub use real::{Real, Vector3};
pub use refraction::{Refraction, Transmission, refract};
pub use variants::Variant;

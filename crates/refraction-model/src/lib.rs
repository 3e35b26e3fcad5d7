//! What the refraction explorer shows, with no drawing and no window: the state being explored
//! ([`ExplorerState`]: W, N, the two indices and the convention, always valid, with the
//! kernel's answer), the lessons that start one, the angles at which something happens for a
//! pair of media ([`SpecialAngles`]), the figures the `bench` command measures
//! ([`report::Report`]) and those of a judged log that its failure map draws ([`log_map`]);
//! and the state in words for a student who cannot see the diagram ([`describe`]).
//!
//! It sits below the diagram, which draws it, and the tools, which read and write it (a state
//! file is one `solve` line), so neither needs the other.
//!
//! ```
//! use refraction_model::{ExplorerState, SpecialAngles};
//! let mut state = ExplorerState::default(); // W 40° from air into glass
//! assert!(!state.refraction().is_tir());
//! state.set_mu_i(1.5)?;
//! state.set_mu_t(1.0)?; // glass into air: 40° is short of the critical angle
//! assert!(!state.refraction().is_tir());
//! let critical = SpecialAngles::for_ratio(1.5).critical_deg.unwrap();
//! assert!((critical - 41.81).abs() < 0.01);
//! # Ok::<(), refraction_kernel::InputError>(())
//! ```

pub mod describe;
pub mod log_map;
mod polarisation;
pub mod report;
mod special_angles;
mod state;

pub use polarisation::Polarisation;
pub use special_angles::SpecialAngles;
pub use state::{
    AngleError, ExplorerState, HandleId, INDEX_RANGE, Lesson, MATERIALS, Material, Plane,
    material_of,
};

//! The log diagnosis as a Python package, `refraction_check`: a renderer's refraction calls
//! held in arrays (`NumPy`, `Dr.Jit`, torch on the CPU, lists) judged one by one and diagnosed as
//! a whole by `refraction-check`, the code `check` runs on the same calls logged as JSON Lines.
//!
//! ```python
//! import refraction_check as rc
//! r = rc.check(api="mitsuba", wi=wi, eta=eta, wo=wo, inside=1.5, outside=1.0)
//! r.ok        # one bool per call
//! r.codes     # one code per call, as `check` counts them
//! r.summary   # what `check --summary` writes
//! ```
//!
//! The crate holds only what lies between arrays and calls, so that every part but the last
//! is tested in Rust without Python:
//!
//! - [`arrays`]: an argument's numbers and shape (as numpy hands them over) into one value per
//!   call, or one for every call, each row that logged nothing read as JSON's `null`;
//! - [`options`]: the keywords that are `check`'s options (`inside`, `outside`, `normal`,
//!   `convention`, `precision`, `renderer`) into [`refraction_check::Options`];
//! - [`calls`]: the columns into one [`refraction_check::Record`] per call, judged by
//!   [`refraction_check::check_records`];
//! - [`Report`]: what was found, as Python shows it: a short text and a notebook's table;
//! - `module` (with the `extension-module` feature, which only maturin turns on): the Python
//!   module itself, `PyO3` and numpy.
//!
//! Every argument that cannot be used is an [`ArgumentError`] naming it (Python's
//! `ValueError`).

pub mod arrays;
pub mod calls;
mod error;
#[cfg(feature = "extension-module")]
mod module;
pub mod options;
mod report;

pub use error::ArgumentError;
pub use report::Report;

//! The files of the refraction explorer, read and written safely: every file the project writes
//! goes through [`write_atomically`] (a crash, a full disk or a planted link never leaves a
//! half-written or clobbered file), and every file it reads whole goes through [`read_capped`]
//! (a huge or endless file is refused, not read into memory).
//!
//! ```
//! let folder = tempfile::tempdir()?;
//! let path = folder.path().join("state.json");
//! refraction_files::write_atomically(&path, b"{}")?;
//! assert_eq!(refraction_files::read_capped(&path, 1 << 20, "a state file")?, "{}");
//! # Ok::<(), std::io::Error>(())
//! ```
//!
//! In a browser (`wasm32`) there is no file system: the same functions read the files the
//! user gave the page and keep what is written for the page to download (`browser`).

#[cfg(not(target_arch = "wasm32"))]
mod atomic;
#[cfg(any(target_arch = "wasm32", test))]
pub mod browser;
mod capped;
mod identity;

#[cfg(not(target_arch = "wasm32"))]
pub use atomic::{check_writable, write_all_atomically, write_atomically};
#[cfg(target_arch = "wasm32")]
pub use browser::{check_writable, write_all_atomically, write_atomically};
pub use capped::{read_capped, read_capped_bytes};
pub use identity::{first_bytes, names_open_file, same_regular_file, standard_input};

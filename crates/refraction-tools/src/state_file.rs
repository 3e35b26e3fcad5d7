//! The explorer's state as a JSON file, in the field names of the `solve` command: `w`, `n`,
//! `mu_i`, `mu_t` and optional `convention` (`precision` is accepted and ignored: the explorer
//! works in f64). The same line is the "share" string that reproduces a state elsewhere.

use std::path::Path;

use glam::DVec3;

use crate::error::RequestError;
use crate::solve::{Precision, Request};
use refraction_model::ExplorerState;

/// Reads a state from JSON text.
///
/// # Errors
/// Malformed JSON, a missing or ill-typed field, or input the kernel refuses; the message names
/// what was wrong.
pub fn parse_state(text: &str) -> Result<ExplorerState, RequestError> {
    // Not trimmed: JSON allows the white space around it, and a leading blank line would shift
    // the line numbers of malformed JSON. A byte order mark some editors write is not JSON.
    let request = Request::parse(text.strip_prefix('\u{feff}').unwrap_or(text))?;
    // The explorer works in f64, but a state that says f32 keeps f32's limits, as `solve`.
    if request.precision == Precision::F32 {
        request.incidence::<f32>()?;
    }
    ExplorerState::new(
        DVec3::from_array(request.w),
        DVec3::from_array(request.n),
        request.mu_i,
        request.mu_t,
        request.convention,
    )
    .map_err(RequestError::from)
}

/// The largest state file [`open_state_file`] reads: 1 MiB (a state is one line of about 150 bytes).
pub const MAX_STATE_FILE_BYTES: u64 = 1 << 20;

/// Why a state file could not be opened: kept apart so that the window can say it in the
/// user's language around the reader's own reason.
#[derive(Debug, thiserror::Error)]
pub enum StateFileError {
    /// The file cannot be read, is too long or is not UTF-8.
    #[error("cannot read state file {path}: {source}")]
    Read {
        /// The file, as displayed.
        path: String,
        /// What reading it said.
        source: std::io::Error,
    },
    /// The file was read and [`parse_state`] refused it.
    #[error("state file {path}: {reason}")]
    Refused {
        /// The file, as displayed.
        path: String,
        /// Why [`parse_state`] refused it (malformed JSON names its line and column).
        reason: RequestError,
    },
}

/// Reads a state from a JSON file of at most [`MAX_STATE_FILE_BYTES`].
///
/// # Errors
/// [`StateFileError::Read`] when the file cannot be read or is too long, [`StateFileError::Refused`]
/// when [`parse_state`] refuses it.
pub fn open_state_file(path: &Path) -> Result<ExplorerState, StateFileError> {
    let shown = || path.display().to_string();
    let text = refraction_files::read_capped(path, MAX_STATE_FILE_BYTES, "a state file").map_err(
        |source| StateFileError::Read {
            path: shown(),
            source,
        },
    )?;
    parse_state(&text).map_err(|reason| StateFileError::Refused {
        path: shown(),
        reason,
    })
}

/// The state as a `solve` request (in f64, the explorer's precision).
#[must_use]
pub fn state_request(state: &ExplorerState) -> Request {
    Request {
        w: state.w().to_array(),
        n: state.n().to_array(),
        mu_i: state.mu_i(),
        mu_t: state.mu_t(),
        convention: state.convention(),
        precision: Precision::F64,
    }
}

/// The state as one line of JSON that [`parse_state`] (and `solve`) read back bit for bit: numbers
/// are written in their shortest form that reads back to the same bits.
#[must_use]
pub fn state_to_json(state: &ExplorerState) -> String {
    state_request(state).to_json_line()
}

/// Writes the state to `path` as one line of JSON, atomically: a failed write leaves no
/// half-written file.
///
/// # Errors
/// The file cannot be written (see [`refraction_files::write_atomically`]).
pub fn save_state_file(state: &ExplorerState, path: &Path) -> std::io::Result<()> {
    let text = format!("{}\n", state_to_json(state));
    refraction_files::write_atomically(path, text.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::Convention;

    #[test]
    fn states_round_trip_and_bad_files_are_named() {
        let mut state = ExplorerState::default();
        state.set_convention(Convention::TowardOrigin);
        assert_eq!(parse_state(&state_to_json(&state)).unwrap(), state);
        // Issue 23: `render --state` took what `solve` refuses in f32.
        let huge = r#"{"w":[1e300,-1,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"precision":"f32"}"#;
        assert!(
            parse_state(huge)
                .unwrap_err()
                .to_string()
                .contains("too large for f32"),
            "{huge}"
        );
        assert!(parse_state(&huge.replace("f32", "f64")).is_ok());
        let marked = format!("\u{feff}{}", state_to_json(&state));
        assert_eq!(
            parse_state(&marked).unwrap(),
            state,
            "a byte order mark is read past"
        );
        assert_eq!(
            parse_state(r#"{"w":[1,0,0]}"#).unwrap_err(),
            RequestError::Missing("n".into())
        );
        let err = parse_state(r#"{"w":[1,-1,0],"n":[0,1,0],"mu_i":-1,"mu_t":1}"#)
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("mu_i is -1"), "{err}");
        let err = open_state_file(Path::new("/nonexistent/state.json"))
            .unwrap_err()
            .to_string();
        assert!(err.starts_with("cannot read state file /nonexistent/state.json"));
        let err = save_state_file(&state, Path::new("/nonexistent/state.json"))
            .unwrap_err()
            .to_string();
        assert!(err.contains("/nonexistent/state.json"), "{err}");
    }

    #[test]
    fn a_multi_line_file_names_line_and_column_and_a_huge_one_is_refused() {
        let folder = std::env::temp_dir().join(format!("state-file-lines-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("state.json");
        std::fs::write(
            &path,
            "\n{\n  \"w\": [0.6, -0.8, 0],\n  \"n\": [0, 1 0],\n  \"mu_i\": 1, \"mu_t\": 1.5\n}\n",
        )
        .unwrap();
        let err = open_state_file(&path).unwrap_err().to_string();
        assert!(
            err.contains("state.json: malformed JSON at line 4, column 14"),
            "{err}"
        );
        std::fs::write(&path, " ".repeat(2 << 20)).unwrap();
        let err = open_state_file(&path).unwrap_err().to_string();
        assert!(
            err.contains("state.json") && err.contains("larger than 1 MiB"),
            "{err}"
        );
        let err = open_state_file(&folder).unwrap_err().to_string();
        assert!(err.contains(&folder.display().to_string()), "{err}");
        std::fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_saved_file_opens_to_the_same_bits() {
        let w = glam::DVec3::new(0.1, -1.0 / 3.0, 1e-300);
        let state = ExplorerState::new(
            w,
            glam::DVec3::Y,
            1.000_293,
            core::f64::consts::E,
            Convention::TowardOrigin,
        )
        .unwrap();
        let path =
            std::env::temp_dir().join(format!("state-file-test-{}.json", std::process::id()));
        save_state_file(&state, &path).unwrap();
        let back = open_state_file(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(back, state);
        assert_eq!(back.w().z.to_bits(), state.w().z.to_bits());
    }
}

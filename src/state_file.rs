//! The explorer's state as a JSON file, in the field names of the `solve` command: `w`, `n`,
//! `mu_i`, `mu_t` and optional `convention` (`precision` is accepted and ignored: the explorer
//! works in f64).

use std::path::Path;

use glam::DVec3;

use crate::diagram::ExplorerState;
use crate::solve::Request;

/// Reads a state from JSON text.
///
/// # Errors
/// Malformed JSON, a missing or ill-typed field, or input the kernel refuses; the message names
/// what was wrong.
pub fn parse(text: &str) -> Result<ExplorerState, String> {
    let request = Request::parse(text.trim())?;
    ExplorerState::new(
        DVec3::from_array(request.w),
        DVec3::from_array(request.n),
        request.mu_i,
        request.mu_t,
        request.convention,
    )
    .map_err(|e| e.to_string())
}

/// Reads a state from a JSON file.
///
/// # Errors
/// The file cannot be read, or [`parse`] refuses it; the message names the file.
pub fn load(path: &Path) -> Result<ExplorerState, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read state file {}: {e}", path.display()))?;
    parse(&text).map_err(|e| format!("state file {}: {e}", path.display()))
}

/// The state as one line of JSON that [`parse`] (and `solve`) read back.
#[must_use]
pub fn to_json(state: &ExplorerState) -> String {
    serde_json::json!({
        "w": state.w().to_array(),
        "n": state.n().to_array(),
        "mu_i": state.mu_i(),
        "mu_t": state.mu_t(),
        "convention": state.convention().name(),
    })
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Convention;

    #[test]
    fn states_round_trip_and_bad_files_are_named() {
        let mut state = ExplorerState::default();
        state.set_convention(Convention::TowardOrigin);
        assert_eq!(parse(&to_json(&state)).unwrap(), state);
        assert_eq!(parse(r#"{"w":[1,0,0]}"#).unwrap_err(), "missing field `n`");
        let err = parse(r#"{"w":[1,-1,0],"n":[0,1,0],"mu_i":-1,"mu_t":1}"#).unwrap_err();
        assert!(err.starts_with("mu_i is -1"), "{err}");
        let err = load(Path::new("/nonexistent/state.json")).unwrap_err();
        assert!(err.starts_with("cannot read state file /nonexistent/state.json"));
    }
}

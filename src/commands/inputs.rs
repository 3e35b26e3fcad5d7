//! The files a command reads, so that what it writes never replaces one of them: an output
//! path that names an input (under any name: a hard link, `/dev/stdin` redirected from it, a
//! picture's name in `--out ./`) is refused before anything is written.

use std::path::{Path, PathBuf};

/// A file a command reads, with what it is to the command (`the deck`).
pub(crate) struct Input {
    /// The file, as given or found.
    pub path: PathBuf,
    /// What it is, for the message (`the deck`, `a scene of the deck`, `the state file`).
    pub what: &'static str,
}

/// An output path that names a file the command reads.
#[derive(Debug, thiserror::Error)]
#[error(
    "cannot write {}: it is {what} being read ({}); nothing was written: choose another {option}",
    out.display(),
    input.display()
)]
pub(crate) struct OutputIsInput {
    /// The output path, as given or made.
    pub out: PathBuf,
    /// The input it names, as given.
    pub input: PathBuf,
    /// What the input is.
    pub what: &'static str,
    /// The option that names the output (`--out`).
    pub option: &'static str,
}

/// Refuses each of `outs` (named by `option`) that is one of `inputs`' regular files.
///
/// # Errors
/// The first output that names an input, with both paths.
pub(crate) fn refuse_inputs<'a>(
    outs: impl IntoIterator<Item = &'a Path>,
    option: &'static str,
    inputs: &[Input],
) -> Result<(), OutputIsInput> {
    for out in outs {
        if let Some(input) = inputs
            .iter()
            .find(|i| refraction_files::same_regular_file(out, &i.path))
        {
            return Err(OutputIsInput {
                out: out.to_path_buf(),
                input: input.path.clone(),
                what: input.what,
                option,
            });
        }
    }
    Ok(())
}

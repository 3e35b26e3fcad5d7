//! What a command's output may replace: never a file it reads (under any name: a hard link,
//! `/dev/stdin` redirected from it, a picture's name in `--out ./`), and never a file of
//! another kind than the one it writes (told by its first bytes); both are refused before
//! anything is drawn.

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

/// The first bytes of each kind of file the commands write, as they write it.
const STARTS: [(&str, &[u8]); 5] = [
    ("a PDF", b"%PDF-"),
    ("a PNG image", b"\x89PNG"),
    ("an SVG picture", b"<?xml"),
    ("an SVG picture", b"<svg"),
    ("a GIF animation", b"GIF8"),
];

/// An output path that holds a file of another kind than the one written there.
#[derive(Debug, thiserror::Error)]
#[error(
    "cannot write {}: it holds something that is not {kind}{why}, which is never replaced; \
     nothing was written: move it away or choose another {option}",
    path.display()
)]
pub(crate) struct OtherKind {
    /// The output path.
    pub path: PathBuf,
    /// The kind written there (`a PDF`).
    pub kind: &'static str,
    /// Why it could not be told, if its start could not be read.
    pub why: String,
    /// The option that names it (`--out`).
    pub option: &'static str,
}

/// Refuses each of `outs` (named by `option`) that is a regular file of another kind than
/// `kind` (one of [`STARTS`]' kinds), told by its first bytes only: a file of that kind, or
/// an empty one, is the command's to replace; a teacher's notes named `handout.pdf` are not.
///
/// # Errors
/// The first output that holds something else, or whose start cannot be read.
pub(crate) fn refuse_other_kinds<'a>(
    outs: impl IntoIterator<Item = &'a Path>,
    option: &'static str,
    kind: &'static str,
) -> Result<(), OtherKind> {
    for out in outs {
        let refused = |why: String| OtherKind {
            path: out.to_path_buf(),
            kind,
            why,
            option,
        };
        let start = match refraction_files::first_bytes(out, 8) {
            Ok(None) => continue,
            Ok(Some(start)) => start,
            Err(e) => return Err(refused(format!(" (its start cannot be read: {e})"))),
        };
        let ours = start.is_empty()
            || STARTS
                .iter()
                .any(|(k, magic)| *k == kind && start.starts_with(magic));
        if !ours {
            return Err(refused(String::new()));
        }
    }
    Ok(())
}

/// The kind of file `format` writes, as [`refuse_other_kinds`] names it.
pub(crate) fn kind_of(format: refraction_render::ImageFormat) -> &'static str {
    use refraction_render::ImageFormat;
    match format {
        ImageFormat::Png => "a PNG image",
        ImageFormat::Svg => "an SVG picture",
        ImageFormat::Gif => "a GIF animation",
    }
}

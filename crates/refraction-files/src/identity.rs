//! Whether a path names a file already open, so that a command never writes its output over
//! its own input (`check --summary log.jsonl log.jsonl`, or `< log.jsonl`), and what a file
//! starts with, to tell its kind without reading it whole.

use std::fs::File;
use std::io;
#[cfg(not(target_arch = "wasm32"))]
use std::io::Read as _;
use std::path::Path;

/// Whether `path` names the same file as `open` (the same device and inode, whatever the
/// name, links included). `false` when `path` names nothing or cannot be examined.
#[cfg(unix)]
#[must_use]
pub fn names_open_file(path: &Path, open: &File) -> bool {
    use std::os::unix::fs::MetadataExt as _;
    match (std::fs::metadata(path), open.metadata()) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Whether `path` names the same file as `open` (the same volume and file index, whatever the
/// name, links included; `same-file` asks Windows). `false` when `path` names nothing or
/// cannot be opened to be examined.
#[cfg(windows)]
#[must_use]
pub fn names_open_file(path: &Path, open: &File) -> bool {
    let theirs = same_file::Handle::from_path(path);
    let ours = open.try_clone().and_then(same_file::Handle::from_file);
    matches!((theirs, ours), (Ok(a), Ok(b)) if a == b)
}

/// Whether `path` names the same file as `open`: never, where the platform cannot tell (a
/// browser's page has no files to name).
#[cfg(not(any(unix, windows)))]
#[must_use]
pub fn names_open_file(_path: &Path, _open: &File) -> bool {
    false
}

/// Whether `a` and `b` name one regular file (the same device and inode, links followed,
/// whatever the names: a hard link, `/dev/stdin` redirected from it, a bind mount), so that a
/// command never writes over a file it reads. `false` when either names nothing, cannot be
/// examined or is no regular file (a FIFO or a terminal can be read and written at once).
#[cfg(unix)]
#[must_use]
pub fn same_regular_file(a: &Path, b: &Path) -> bool {
    use std::os::unix::fs::MetadataExt as _;
    match (std::fs::metadata(a), std::fs::metadata(b)) {
        (Ok(a), Ok(b)) => a.is_file() && a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Whether `a` and `b` name one regular file: where the platform gives no file identity, the
/// same canonical path (links followed); never in a browser, whose files are not replaced.
#[cfg(not(unix))]
#[must_use]
pub fn same_regular_file(a: &Path, b: &Path) -> bool {
    match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
        (Ok(x), Ok(y)) => x == y && std::fs::metadata(a).is_ok_and(|m| m.is_file()),
        _ => false,
    }
}

/// The process's standard input as a file (a duplicate of its descriptor), to compare with a
/// path; `None` where it cannot be had.
#[cfg(unix)]
#[must_use]
pub fn standard_input() -> Option<File> {
    use std::os::fd::AsFd as _;
    io::stdin()
        .as_fd()
        .try_clone_to_owned()
        .ok()
        .map(File::from)
}

/// The process's standard input as a file (a duplicate of its handle), to compare with a
/// path; `None` where it cannot be had.
#[cfg(windows)]
#[must_use]
pub fn standard_input() -> Option<File> {
    use std::os::windows::io::AsHandle as _;
    io::stdin()
        .as_handle()
        .try_clone_to_owned()
        .ok()
        .map(File::from)
}

/// The process's standard input as a file: never, where the platform cannot tell.
#[cfg(not(any(unix, windows)))]
#[must_use]
pub fn standard_input() -> Option<File> {
    None
}

/// The first `limit` bytes (or fewer) of the regular file at `path`, to tell what it holds:
/// `Ok(None)` when nothing is there or it is not a regular file (a FIFO is never opened, as
/// that would wait for a writer).
///
/// # Errors
/// The file is there but cannot be read.
#[cfg(not(target_arch = "wasm32"))]
pub fn first_bytes(path: &Path, limit: u64) -> io::Result<Option<Vec<u8>>> {
    match std::fs::metadata(path) {
        Ok(found) if found.is_file() => {}
        Ok(_) => return Ok(None),
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e),
    }
    let mut bytes = Vec::new();
    File::open(path)?.take(limit).read_to_end(&mut bytes)?;
    Ok(Some(bytes))
}

/// The first `limit` bytes (or fewer) of the file the page was given as `path` (see
/// [`crate::browser`]); `Ok(None)` when none was.
///
/// # Errors
/// Never: the signature is the desktop's.
#[cfg(target_arch = "wasm32")]
pub fn first_bytes(path: &Path, limit: u64) -> io::Result<Option<Vec<u8>>> {
    if !crate::browser::exists(path) {
        return Ok(None);
    }
    let mut bytes = crate::browser::read(path)?;
    bytes.truncate(usize::try_from(limit).unwrap_or(usize::MAX));
    Ok(Some(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_names_the_open_file_under_any_name_and_no_other() {
        let folder = tempfile::tempdir().unwrap();
        let (log, other) = (folder.path().join("log"), folder.path().join("other"));
        std::fs::write(&log, "line\n").unwrap();
        std::fs::write(&other, "line\n").unwrap();
        let open = File::open(&log).unwrap();
        assert!(names_open_file(&log, &open));
        std::fs::hard_link(&log, folder.path().join("alias")).unwrap();
        assert!(names_open_file(&folder.path().join("alias"), &open));
        assert!(names_open_file(&folder.path().join(".").join("log"), &open));
        assert!(!names_open_file(&other, &open));
        assert!(!names_open_file(&folder.path().join("missing"), &open));
    }

    #[test]
    fn one_regular_file_is_told_under_any_name_and_a_device_is_not_one() {
        let folder = tempfile::tempdir().unwrap();
        let (deck, other) = (folder.path().join("deck.pdf"), folder.path().join("other"));
        std::fs::write(&deck, "[deck]\n").unwrap();
        std::fs::write(&other, "[deck]\n").unwrap();
        let alias = folder.path().join("alias.pdf");
        std::fs::hard_link(&deck, &alias).unwrap();
        std::os::unix::fs::symlink(&deck, folder.path().join("link")).unwrap();
        assert!(same_regular_file(&deck, &alias));
        assert!(same_regular_file(&folder.path().join("link"), &deck));
        assert!(same_regular_file(
            &folder.path().join(".").join("deck.pdf"),
            &deck
        ));
        assert!(!same_regular_file(&deck, &other));
        assert!(!same_regular_file(&deck, &folder.path().join("missing")));
        assert!(!same_regular_file(
            Path::new("/dev/null"),
            Path::new("/dev/null")
        ));
    }

    #[test]
    fn first_bytes_reads_a_regular_file_s_start_and_nothing_else() {
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("f");
        std::fs::write(&path, "0123456789").unwrap();
        assert_eq!(first_bytes(&path, 4).unwrap(), Some(b"0123".to_vec()));
        assert_eq!(first_bytes(&folder.path().join("none"), 4).unwrap(), None);
        assert_eq!(first_bytes(folder.path(), 4).unwrap(), None);
    }
}

//! Files in a browser tab (`wasm32`), where a page has no file system: the files it reads are
//! those the user chose in the browser's file picker or dropped on the page, handed to
//! [`provide`] by the page; the files it writes are kept for the page to hand to the browser
//! as downloads ([`take_written`]). On `wasm32` every reader and writer of this crate goes
//! through here, so the rest of the program opens and saves as it does on a desktop.
//!
//! The page has one thread: the files live in thread-local storage. What it keeps to be read
//! is bounded ([`KEPT_BYTES`]): past that, the files given or written longest ago are
//! forgotten, so that a long lesson's exports do not fill the tab's memory.

use core::cell::RefCell;
use std::io;
use std::path::{Path, PathBuf};

/// The most the page keeps of the files given to it and written, in bytes (four times the
/// largest file a reader of the window takes, a 16 MiB log); the newest file is always kept.
pub const KEPT_BYTES: usize = 64 << 20;

thread_local! {
    /// The files the user gave the page (and those it wrote), by the name they were given
    /// under, the oldest first.
    static OPENED: RefCell<Vec<(PathBuf, Vec<u8>)>> = const { RefCell::new(Vec::new()) };
    /// The files written since the page last took them, in order.
    static WRITTEN: RefCell<Vec<(PathBuf, Vec<u8>)>> = const { RefCell::new(Vec::new()) };
}

/// Makes `bytes` readable as the file `path` (a file the user chose or dropped), replacing
/// a file given under the same name before; the oldest files are forgotten while all kept
/// exceed [`KEPT_BYTES`].
pub fn provide(path: &Path, bytes: Vec<u8>) {
    OPENED.with_borrow_mut(|opened| {
        opened.retain(|(kept, _)| kept != path);
        opened.push((path.to_path_buf(), bytes));
        let mut total: usize = opened.iter().map(|(_, bytes)| bytes.len()).sum();
        while total > KEPT_BYTES && opened.len() > 1 {
            total -= opened.remove(0).1.len();
        }
    });
}

/// The files written since the last call, in the order they were written: each a name and
/// its bytes, for the page to offer as downloads.
#[must_use]
pub fn take_written() -> Vec<(PathBuf, Vec<u8>)> {
    WRITTEN.with_borrow_mut(core::mem::take)
}

/// The bytes of the file given as `path`.
///
/// # Errors
/// No file was given under that name ([`io::ErrorKind::NotFound`]).
pub(crate) fn read(path: &Path) -> io::Result<Vec<u8>> {
    OPENED
        .with_borrow(|opened| {
            let found = opened.iter().find(|(kept, _)| kept == path);
            found.map(|(_, bytes)| bytes.clone())
        })
        .ok_or_else(|| {
            io::Error::new(
                io::ErrorKind::NotFound,
                format!(
                    "{} was not opened in this page: a browser page reads only the files chosen \
                     in its file picker or dropped on it",
                    path.display()
                ),
            )
        })
}

/// Whether a file was given as `path`.
pub(crate) fn exists(path: &Path) -> bool {
    OPENED.with_borrow(|opened| opened.iter().any(|(kept, _)| kept == path))
}

/// Refuses a path that names no file (a download needs a name).
fn named(path: &Path) -> io::Result<()> {
    if path.file_name().is_some() {
        Ok(())
    } else {
        Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("cannot write {}: the path names no file", path.display()),
        ))
    }
}

/// Keeps `bytes` as the file `path` for the page to download (only its name reaches the
/// browser, which chooses the folder); it can be read back as if opened.
///
/// # Errors
/// `path` names no file.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    named(path)?;
    WRITTEN.with_borrow_mut(|written| written.push((path.to_path_buf(), bytes.to_vec())));
    provide(path, bytes.to_vec());
    Ok(())
}

/// Keeps every one of `files` for the page to download, or none.
///
/// # Errors
/// One of the paths names no file; nothing is kept then.
pub fn write_all_atomically(files: &[(&Path, &[u8])]) -> io::Result<()> {
    files.iter().try_for_each(|(path, _)| named(path))?;
    files
        .iter()
        .try_for_each(|(path, bytes)| write_atomically(path, bytes))
}

/// Whether [`write_atomically`] would take `path`.
///
/// # Errors
/// `path` names no file.
pub fn check_writable(path: &Path) -> io::Result<()> {
    named(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn written_files_wait_for_the_page_and_given_files_are_read() {
        let path = Path::new("refraction-state.json");
        assert_eq!(
            read(path).unwrap_err().kind(),
            io::ErrorKind::NotFound,
            "nothing given yet"
        );
        write_atomically(path, b"{}").unwrap();
        write_all_atomically(&[(Path::new("a.svg"), b"<svg/>"), (Path::new("b.svg"), b"")])
            .unwrap();
        let written = take_written();
        let names: Vec<_> = written
            .iter()
            .map(|(p, _)| p.display().to_string())
            .collect();
        assert_eq!(names, ["refraction-state.json", "a.svg", "b.svg"]);
        assert!(take_written().is_empty(), "each file is downloaded once");
        assert_eq!(read(path).unwrap(), b"{}", "a written file reads back");
        provide(Path::new("log.txt"), b"line".to_vec());
        assert!(exists(Path::new("log.txt")));
        assert!(write_atomically(Path::new("/"), b"x").is_err());
        assert!(write_all_atomically(&[(Path::new("c.svg"), b""), (Path::new(""), b"")]).is_err());
        assert!(take_written().is_empty(), "all or nothing");
    }

    #[test]
    fn what_is_kept_is_bounded_the_oldest_forgotten_first() {
        let quarter = vec![0u8; KEPT_BYTES / 4];
        for name in ["1.gif", "2.gif", "3.gif", "4.gif"] {
            provide(Path::new(name), quarter.clone());
        }
        assert!(exists(Path::new("1.gif")), "four quarters fit");
        provide(Path::new("2.gif"), quarter.clone());
        assert!(
            exists(Path::new("1.gif")),
            "a file given again replaces itself"
        );
        provide(Path::new("5.gif"), quarter.clone());
        assert!(!exists(Path::new("1.gif")), "the oldest is forgotten");
        assert!(exists(Path::new("3.gif")) && exists(Path::new("2.gif")));
        provide(Path::new("big.log"), vec![0u8; KEPT_BYTES + 1]);
        assert!(exists(Path::new("big.log")), "the newest is always kept");
        assert!(!exists(Path::new("5.gif")), "alone");
    }
}

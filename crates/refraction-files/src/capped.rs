//! Reading a file with a size cap, so that a huge file or an endless one (`/dev/zero`) is
//! refused rather than read into memory. Scene files and the explorer's state files are read
//! this way.

use std::io::{self, Read as _};
use std::path::Path;

/// `bytes` for messages: whole mebibytes as `N MiB`, anything else in bytes.
fn size_text(bytes: u64) -> String {
    if bytes.is_multiple_of(1 << 20) {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} bytes")
    }
}

/// Reads the UTF-8 text of the file at `path`, refusing it if it is longer than `limit` bytes
/// (no more than `limit` + 1 bytes are ever read). `what` names the kind of file in the
/// message, as in "a scene file".
///
/// # Errors
/// The file cannot be opened or read, is longer than `limit` (kind
/// [`io::ErrorKind::FileTooLarge`], the message giving the limit), or is not UTF-8.
pub fn read_capped(path: &Path, limit: u64, what: &str) -> io::Result<String> {
    let bytes = read_capped_bytes(path, limit, what)?;
    String::from_utf8(bytes).map_err(|e| {
        let message = not_text(e.as_bytes(), e.utf8_error().valid_up_to(), what);
        io::Error::new(io::ErrorKind::InvalidData, message)
    })
}

/// Why `bytes` (UTF-8 only up to `valid_up_to`) are no text `what` can be: the kind of file
/// they are where their first bytes tell it (an image named `.json`, say), else where the
/// first byte that is not UTF-8 lies.
fn not_text(bytes: &[u8], valid_up_to: usize, what: &str) -> String {
    const KINDS: [(&[u8], &str); 6] = [
        (b"\x89PNG", "a PNG image"),
        (b"GIF8", "a GIF image"),
        (b"\xFF\xD8\xFF", "a JPEG image"),
        (b"%PDF", "a PDF document"),
        (b"PK\x03\x04", "a ZIP archive"),
        (b"\x7FELF", "a program"),
    ];
    if let Some((_, kind)) = KINDS.iter().find(|(magic, _)| bytes.starts_with(magic)) {
        return format!("this is {kind}, not text: {what} is UTF-8 text");
    }
    let before = core::str::from_utf8(&bytes[..valid_up_to]).unwrap_or_default();
    let line = before.matches('\n').count() + 1;
    format!(
        "this is not UTF-8 text (byte {} on line {line} is not): {what} is UTF-8 text",
        valid_up_to + 1
    )
}

/// The bytes of the file at `path`, as [`read_capped`] reads them but without asking for UTF-8,
/// for a reader that reports where the first byte that is not UTF-8 lies.
///
/// # Errors
/// The file cannot be opened or read, or is longer than `limit` (kind
/// [`io::ErrorKind::FileTooLarge`], the message giving the limit).
pub fn read_capped_bytes(path: &Path, limit: u64, what: &str) -> io::Result<Vec<u8>> {
    #[cfg(not(target_arch = "wasm32"))]
    let file = std::fs::File::open(path)?;
    #[cfg(target_arch = "wasm32")]
    let file = io::Cursor::new(crate::browser::read(path)?);
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1)).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(io::Error::new(
            io::ErrorKind::FileTooLarge,
            format!(
                "the file is larger than {}, the most {what} may have",
                size_text(limit)
            ),
        ));
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_is_no_text_is_named_for_what_it_is() {
        let dir = tempfile::tempdir().unwrap();
        let png = dir.path().join("picture.json");
        std::fs::write(&png, b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR").unwrap();
        let err = read_capped(&png, 1000, "a state file").unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::InvalidData);
        assert_eq!(
            err.to_string(),
            "this is a PNG image, not text: a state file is UTF-8 text"
        );
        let latin = dir.path().join("latin1.json");
        std::fs::write(&latin, b"{\n\"w\": \"\xE9\"}").unwrap();
        let err = read_capped(&latin, 1000, "a state file").unwrap_err();
        assert_eq!(
            err.to_string(),
            "this is not UTF-8 text (byte 9 on line 2 is not): a state file is UTF-8 text"
        );
    }

    #[test]
    fn a_file_over_the_cap_is_refused_and_an_endless_one_ends() {
        let path = std::env::temp_dir().join(format!("capped-{}.txt", std::process::id()));
        std::fs::write(&path, "x".repeat(2000)).unwrap();
        assert_eq!(read_capped(&path, 2000, "a test file").unwrap().len(), 2000);
        let err = read_capped(&path, 1999, "a test file").unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::FileTooLarge);
        assert_eq!(
            err.to_string(),
            "the file is larger than 1999 bytes, the most a test file may have"
        );
        std::fs::remove_file(&path).unwrap();
        let err = read_capped(Path::new("/dev/zero"), 1 << 20, "a scene file").unwrap_err();
        assert!(err.to_string().contains("larger than 1 MiB"), "{err}");
    }
}

//! Writing files so that a crash, a full disk or a planted link never leaves a half-written or
//! clobbered file behind. Every file the project writes goes through [`write_atomically`].
//!
//! What is at the path decides how it is written:
//! - **nothing, or a regular file**: the bytes go into a new temporary file in the same folder,
//!   created exclusively under an unpredictable name (so a link planted under a guessed name is
//!   never followed), flushed to disk, then renamed over the path. A replaced file keeps its
//!   permissions; a new one gets the usual ones (0666 less the umask).
//! - **a FIFO or a character device** (`/dev/null`, a terminal, a pipe a reader waits on): the
//!   bytes are written straight into it, as a shell's `>` would, without replacing it. Opening
//!   a FIFO waits for its reader.
//! - **a symbolic link** is followed to what it names: a FIFO or character device is written
//!   into as above (so `/dev/stdout` works); a link to a regular file, or to nothing, is
//!   refused. Replacing the link would break it, and replacing its target would let a link
//!   planted in a shared folder (`/tmp`) send the write to any file the user can write.
//! - **a directory, a block device or a socket** is refused.

use std::fs::{self, File, OpenOptions, Permissions};
use std::io::{self, Write as _};
use std::path::Path;

/// How the file at a path is to be written.
#[derive(Debug)]
enum Target {
    /// Through a temporary file renamed over the path; `Some` permissions of the file replaced.
    Replace(Option<Permissions>),
    /// Straight into the FIFO or device at the path.
    Stream,
}

fn refuse(kind: io::ErrorKind, why: String) -> io::Error {
    io::Error::new(kind, why)
}

/// The kind of a file that is neither regular, a directory nor a link, and whether it can be
/// written into; `None` where the platform cannot tell.
#[cfg(unix)]
fn special(kind: fs::FileType) -> Option<(&'static str, bool)> {
    use std::os::unix::fs::FileTypeExt as _;
    if kind.is_fifo() {
        Some(("a FIFO", true))
    } else if kind.is_char_device() {
        Some(("a character device", true))
    } else if kind.is_block_device() {
        Some(("a block device", false))
    } else if kind.is_socket() {
        Some(("a socket", false))
    } else {
        None
    }
}

#[cfg(not(unix))]
fn special(_: fs::FileType) -> Option<(&'static str, bool)> {
    None
}

/// What is at `path` and how it would be written (see the module documentation).
fn target(path: &Path) -> io::Result<Target> {
    let found = match fs::symlink_metadata(path) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Target::Replace(None)),
        other => other?,
    };
    let linked = found.file_type().is_symlink();
    let found = if linked {
        fs::metadata(path).map_err(|e| {
            refuse(
                io::ErrorKind::InvalidInput,
                format!("it is a symbolic link to nothing that can be opened ({e})"),
            )
        })?
    } else {
        found
    };
    let kind = found.file_type();
    if kind.is_file() && linked {
        let to = fs::canonicalize(path).map_or_else(|e| e.to_string(), |p| p.display().to_string());
        return Err(refuse(
            io::ErrorKind::InvalidInput,
            format!(
                "it is a symbolic link to the regular file {to}: links are neither replaced nor \
                 followed to replace their target, so give that path instead"
            ),
        ));
    }
    if kind.is_file() {
        return Ok(Target::Replace(Some(found.permissions())));
    }
    if kind.is_dir() {
        return Err(refuse(
            io::ErrorKind::IsADirectory,
            "it is a directory".to_owned(),
        ));
    }
    match special(kind) {
        Some((_, true)) => Ok(Target::Stream),
        Some((name, false)) => Err(refuse(
            io::ErrorKind::Unsupported,
            format!("it is {name}, which is never written"),
        )),
        None => Err(refuse(
            io::ErrorKind::Unsupported,
            "it is not a regular file".to_owned(),
        )),
    }
}

/// The folder a temporary file for `path` goes in: `path`'s own.
fn folder_of(path: &Path) -> io::Result<&Path> {
    if path.file_name().is_none() {
        return Err(refuse(
            io::ErrorKind::InvalidInput,
            "the path names no file".to_owned(),
        ));
    }
    Ok(match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    })
}

/// The start of the names of the temporary files written for `path`: hidden, and naming the
/// file they will become, so that those a killed writer left can be told and cleaned.
fn temporary_prefix(path: &Path) -> String {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    format!("{PREFIX}{}-", name.unwrap_or_default())
}

/// How old an unlocked temporary file of ours must be to be removed. A writer locks its
/// temporary file as soon as it has made it and holds the lock until the file is renamed
/// (the kernel lets go when a writer is killed), so an unlocked one is a killed writer's:
/// the age only covers the instant between making and locking, and a writer of an older
/// version, which did not lock.
const UNLOCKED_STALE: core::time::Duration = core::time::Duration::from_secs(2);

/// How old a temporary file of ours must be where its lock cannot be tried (a file system
/// without locks): no writer takes this long between creating and renaming it.
const STALE: core::time::Duration = core::time::Duration::from_mins(10);

/// The start of every temporary file's name this writer makes.
const PREFIX: &str = ".refraction-";

/// The age of the file `metadata` describes (zero for one from the future).
fn age(metadata: &fs::Metadata) -> core::time::Duration {
    metadata
        .modified()
        .ok()
        .and_then(|t| t.elapsed().ok())
        .unwrap_or_default()
}

/// Whether the temporary file of ours at `path` was left by a writer that is gone: a regular
/// file (not a link), unlocked and older than [`UNLOCKED_STALE`], or older than [`STALE`]
/// where locks cannot be tried. Opened without following a link or waiting on a FIFO.
#[cfg(unix)]
fn is_stale(path: &Path) -> bool {
    use rustix::fs::{Mode, OFlags};
    let Ok(seen) = fs::symlink_metadata(path) else {
        return false;
    };
    if !seen.is_file() || age(&seen) < UNLOCKED_STALE {
        return false;
    }
    let flags = OFlags::RDONLY | OFlags::NOFOLLOW | OFlags::NONBLOCK | OFlags::CLOEXEC;
    let Ok(file) = rustix::fs::open(path, flags, Mode::empty()).map(File::from) else {
        return false;
    };
    if !crate::names_open_file(path, &file) || !file.metadata().is_ok_and(|m| m.is_file()) {
        return false;
    }
    match file.try_lock() {
        Ok(()) => true,
        Err(fs::TryLockError::WouldBlock) => false,
        Err(fs::TryLockError::Error(_)) => age(&seen) > STALE,
    }
}

/// Whether the temporary file of ours at `path` was left by a writer that is gone: older
/// than [`STALE`].
#[cfg(not(unix))]
fn is_stale(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok_and(|m| m.is_file() && age(&m) > STALE)
}

/// Removes the temporary files in `folder` that a killed writer of ours left behind, whatever
/// file they were to become (a numbered export is never written under the same name again):
/// only those named as [`temporary_prefix`] names them that [`is_stale`] finds left. What
/// cannot be removed is left; the write goes on either way.
fn clean_stale(folder: &Path) {
    let Ok(entries) = fs::read_dir(folder) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        // The temporary crate writes the suffix as given, in lower case.
        let ours =
            name.starts_with(PREFIX) && Path::new(&name).extension().is_some_and(|e| e == "tmp");
        if ours && is_stale(&entry.path()) {
            // Best effort: a file another user owns in a shared folder stays.
            fs::remove_file(entry.path()).ok();
        }
    }
}

/// A new exclusively created, unpredictably named temporary file in `folder` for `path`, with
/// the permissions a new file gets (0666 less the umask: the temporary crate's default is
/// 0600).
fn temporary_in(folder: &Path, path: &Path) -> io::Result<tempfile::NamedTempFile> {
    // A cleaner that took the new file for a killed writer's between its making and its lock
    // (a writer stopped for seconds there) removed it: then make another.
    for _ in 0..3 {
        let temporary = new_temporary(folder, path)?;
        if locked(&temporary) {
            return Ok(temporary);
        }
    }
    Err(io::Error::other(format!(
        "no file can be made in {}: each new one was removed at once",
        folder.display()
    )))
}

/// Locks `temporary` for as long as it is open, so that no other writer's cleaning takes it
/// for a killed writer's; whether it is still there, ours and locked (or locks cannot be
/// tried).
fn locked(temporary: &tempfile::NamedTempFile) -> bool {
    let file = temporary.as_file();
    match file.try_lock() {
        Ok(()) => crate::names_open_file(temporary.path(), file),
        Err(fs::TryLockError::WouldBlock) => false,
        Err(fs::TryLockError::Error(_)) => true,
    }
}

/// A new exclusively created, unpredictably named temporary file in `folder` for `path`.
fn new_temporary(folder: &Path, path: &Path) -> io::Result<tempfile::NamedTempFile> {
    let mut builder = tempfile::Builder::new();
    let prefix = temporary_prefix(path);
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    builder.tempfile_in(folder).map_err(|e| {
        // The temporary crate ends its message with ` at path "RANDOM NAME"`, which would only
        // confuse: name the folder instead. (Its error keeps no other way to the OS's words.)
        let text = e.to_string();
        let why = text
            .rfind(" at path ")
            .map_or(text.as_str(), |i| &text[..i]);
        let folder = folder.display();
        io::Error::new(e.kind(), format!("no file can be made in {folder}: {why}"))
    })
}

/// A temporary file beside `path` that `write` has filled and flushed to disk, ready to be
/// renamed over it; dropping it removes it.
fn stage(
    path: &Path,
    permissions: Option<Permissions>,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> io::Result<tempfile::NamedTempFile> {
    let folder = folder_of(path)?;
    clean_stale(folder);
    let mut temporary = temporary_in(folder, path)?;
    if let Some(permissions) = permissions {
        temporary.as_file().set_permissions(permissions)?;
    }
    write(temporary.as_file_mut())?;
    temporary.as_file().sync_all()?;
    Ok(temporary)
}

/// Writes `path` through a temporary file that `write` fills, renamed over it at the end. The
/// temporary file is removed on every error (dropping it removes it), so `path` is either the
/// old file or the new one, whole.
fn replace(
    path: &Path,
    permissions: Option<Permissions>,
    write: impl FnOnce(&mut File) -> io::Result<()>,
) -> io::Result<()> {
    stage(path, permissions, write)?
        .persist(path)
        .map_err(|e| e.error)?;
    Ok(())
}

/// Writes `bytes` into the FIFO or device at `path` without creating, truncating or replacing
/// it. Re-checks the opened file, in case a regular file was put there since [`target`] looked.
fn stream(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = OpenOptions::new().write(true).open(path)?;
    if file.metadata()?.is_file() {
        return Err(refuse(
            io::ErrorKind::InvalidInput,
            "it became a regular file while being opened".to_owned(),
        ));
    }
    file.write_all(bytes)?;
    file.flush()
}

fn named(path: &Path, e: &io::Error) -> io::Error {
    io::Error::new(e.kind(), format!("cannot write {}: {e}", path.display()))
}

/// Writes `bytes` to `path` as the module documentation describes: atomically through a
/// temporary file for a new or regular file, straight into a FIFO or character device, refused
/// for anything else. On any error a temporary file is removed and an existing file is
/// untouched.
///
/// # Errors
/// The folder is missing or not writable, the disk is full, the rename fails, or what is at
/// `path` is refused (a directory, a link to a regular file, a block device, a socket); the
/// message names `path` and the reason.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    match target(path) {
        Ok(Target::Replace(permissions)) => replace(path, permissions, |f| f.write_all(bytes)),
        Ok(Target::Stream) => stream(path, bytes),
        Err(e) => Err(e),
    }
    .map_err(|e| named(path, &e))
}

/// Writes every one of `files` (a path and its bytes) or none: each into a temporary file
/// beside it, and only once all are written and flushed to disk is each renamed over its path.
/// A failure before that (a refused path, a full disk) leaves every path as it was and no
/// temporary file behind. Only new or regular files are written this way: a FIFO or device
/// cannot be written all or nothing, and is refused.
///
/// # Errors
/// As [`write_atomically`]'s, naming the path at fault; a FIFO or a character device.
pub fn write_all_atomically(files: &[(&Path, &[u8])]) -> io::Result<()> {
    let mut staged = Vec::with_capacity(files.len());
    for &(path, bytes) in files {
        let permissions = match target(path) {
            Ok(Target::Replace(permissions)) => permissions,
            Ok(Target::Stream) => Err(refuse(
                io::ErrorKind::Unsupported,
                "it is a FIFO or a device, which is not written with other files".to_owned(),
            ))
            .map_err(|e| named(path, &e))?,
            Err(e) => return Err(named(path, &e)),
        };
        let temporary =
            stage(path, permissions, |f| f.write_all(bytes)).map_err(|e| named(path, &e))?;
        staged.push((temporary, path));
    }
    for (temporary, path) in staged {
        temporary.persist(path).map_err(|e| named(path, &e.error))?;
    }
    Ok(())
}

/// Checks now what [`write_atomically`] would refuse later, so that a command can find a bad
/// output path before a long computation: what is at `path` is refused, or its folder is
/// missing or not writable (tried by creating and removing a temporary file there). A FIFO or
/// device is not opened (that would wait for a FIFO's reader).
///
/// # Errors
/// As [`write_atomically`]'s refusals, with the same messages.
pub fn check_writable(path: &Path) -> io::Result<()> {
    match target(path) {
        Ok(Target::Replace(_)) => folder_of(path)
            .and_then(|folder| temporary_in(folder, path))
            .map(drop),
        Ok(Target::Stream) => Ok(()),
        Err(e) => Err(e),
    }
    .map_err(|e| named(path, &e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::os::unix::fs::{FileTypeExt as _, PermissionsExt as _, symlink};
    use std::path::PathBuf;

    fn folder(name: &str) -> PathBuf {
        let folder = std::env::temp_dir().join(format!("atomic-{name}-{}", std::process::id()));
        fs::create_dir_all(&folder).unwrap();
        folder
    }

    fn entries(folder: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(folder)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn files_written_together_are_all_written_or_none() {
        let folder = folder("together");
        let (a, b) = (folder.join("a.svg"), folder.join("b.svg"));
        fs::write(&a, "old a").unwrap();
        write_all_atomically(&[(&a, b"new a"), (&b, b"new b")]).unwrap();
        assert_eq!(fs::read_to_string(&a).unwrap(), "new a");
        assert_eq!(fs::read_to_string(&b).unwrap(), "new b");
        let in_the_way = folder.join("c.svg");
        fs::create_dir(&in_the_way).unwrap();
        let e = write_all_atomically(&[(&a, b"newer a"), (&in_the_way, b"c")]).unwrap_err();
        assert!(e.to_string().contains("c.svg: it is a directory"), "{e}");
        assert_eq!(fs::read_to_string(&a).unwrap(), "new a", "nothing written");
        assert_eq!(
            entries(&folder),
            ["a.svg", "b.svg", "c.svg"],
            "no temporary left"
        );
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_temporary_file_a_killed_writer_left_is_cleaned_on_the_next_write() {
        // Issue 23: kill -9 between creating and renaming leaves a hidden temporary file.
        let folder = folder("stale");
        let old = std::time::SystemTime::now() - 2 * STALE;
        for name in [
            ".refraction-out.txt-left.tmp",
            ".refraction-out.txt-busy.tmp",
            ".refraction-other.txt-left.tmp",
        ] {
            let file = File::create(folder.join(name)).unwrap();
            if name.contains("left") {
                file.set_modified(old).unwrap();
            }
        }
        write_atomically(&folder.join("out.txt"), b"new").unwrap();
        assert_eq!(
            entries(&folder),
            [".refraction-out.txt-busy.tmp", "out.txt"],
            "every stale one goes, whatever file it was for; a recent one may be another writer's"
        );
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_killed_writer_s_temporary_file_is_told_by_its_lock_and_a_live_one_s_kept() {
        // Issue 40: kill -9 left a temporary file about once in 40, and the next write kept
        // it for ten minutes.
        let folder = folder("locked");
        let a_while_ago = std::time::SystemTime::now() - 2 * UNLOCKED_STALE;
        let made = |name: &str| {
            let file = File::create(folder.join(name)).unwrap();
            file.set_modified(a_while_ago).unwrap();
            file
        };
        drop(made(".refraction-out.txt-killed.tmp"));
        let writing = made(".refraction-out.txt-writing.tmp");
        writing.lock().unwrap();
        File::create(folder.join(".refraction-out.txt-new.tmp")).unwrap();
        made("notes.tmp");
        let fifo = folder.join(".refraction-out.txt-fifo.tmp");
        assert!(
            std::process::Command::new("mkfifo")
                .arg(&fifo)
                .status()
                .unwrap()
                .success()
        );
        symlink(
            folder.join("notes.tmp"),
            folder.join(".refraction-link.tmp"),
        )
        .unwrap();
        write_atomically(&folder.join("out.txt"), b"new").unwrap();
        assert_eq!(
            entries(&folder),
            [
                ".refraction-link.tmp",
                ".refraction-out.txt-fifo.tmp",
                ".refraction-out.txt-new.tmp",
                ".refraction-out.txt-writing.tmp",
                "notes.tmp",
                "out.txt"
            ],
            "the killed writer's goes; a locked, a new one, a FIFO, a link and others' stay"
        );
        drop(writing);
        write_atomically(&folder.join("out.txt"), b"newer").unwrap();
        assert!(!entries(&folder).contains(&".refraction-out.txt-writing.tmp".to_owned()));
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_writer_holds_its_temporary_file_locked_until_it_is_renamed() {
        let folder = folder("lock-held");
        let path = folder.join("out.txt");
        let staged = stage(&path, None, |f| f.write_all(b"x")).unwrap();
        let other = File::open(staged.path()).unwrap();
        assert!(matches!(
            other.try_lock(),
            Err(fs::TryLockError::WouldBlock)
        ));
        staged.persist(&path).unwrap();
        assert_eq!(entries(&folder), ["out.txt"]);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn replaces_the_file_and_leaves_no_temporary() {
        let folder = folder("replace");
        let path = folder.join("out.txt");
        write_atomically(&path, b"first").unwrap();
        write_atomically(&path, b"second").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"second");
        assert_eq!(fs::read_dir(&folder).unwrap().count(), 1);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_missing_folder_is_an_error_naming_the_path() {
        let err = write_atomically(Path::new("/nonexistent-folder/x.png"), b"x").unwrap_err();
        assert!(err.to_string().contains("/nonexistent-folder/x.png"));
        let err = check_writable(Path::new("/nonexistent-folder/x.png")).unwrap_err();
        assert!(err.to_string().contains("/nonexistent-folder/x.png"));
    }

    #[test]
    fn a_link_planted_at_the_old_temporary_name_is_not_followed() {
        let folder = folder("planted");
        let victim = folder.join("victim.txt");
        fs::write(&victim, b"precious").unwrap();
        let path = folder.join("out.png");
        // The name the writer used to pick: `.NAME.PID.tmp`.
        let planted = folder.join(format!(".out.png.{}.tmp", std::process::id()));
        symlink(&victim, &planted).unwrap();
        write_atomically(&path, b"image").unwrap();
        assert_eq!(fs::read(&victim).unwrap(), b"precious");
        assert_eq!(fs::read(&path).unwrap(), b"image");
        assert!(
            !fs::symlink_metadata(&path)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_link_to_a_regular_file_is_refused_and_both_stay() {
        let folder = folder("link");
        let target = folder.join("target.png");
        fs::write(&target, b"old").unwrap();
        let link = folder.join("link.png");
        symlink(&target, &link).unwrap();
        for result in [write_atomically(&link, b"new"), check_writable(&link)] {
            let err = result.unwrap_err().to_string();
            assert!(
                err.contains("link.png") && err.contains("symbolic link to the regular file"),
                "{err}"
            );
        }
        assert_eq!(fs::read(&target).unwrap(), b"old");
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        let dangling = folder.join("dangling.png");
        symlink(folder.join("nothing"), &dangling).unwrap();
        let err = write_atomically(&dangling, b"new").unwrap_err().to_string();
        assert!(err.contains("symbolic link to nothing"), "{err}");
        assert_eq!(entries(&folder), ["dangling.png", "link.png", "target.png"]);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_fifo_is_written_into_and_stays_a_fifo() {
        let folder = folder("fifo");
        let fifo = folder.join("pipe.png");
        let made = std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap();
        assert!(made.success());
        check_writable(&fifo).unwrap();
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || fs::read(fifo).unwrap())
        };
        write_atomically(&fifo, b"through the pipe").unwrap();
        // Before joining: a writer that replaced the FIFO would leave the reader waiting.
        assert!(fs::metadata(&fifo).unwrap().file_type().is_fifo());
        assert_eq!(reader.join().unwrap(), b"through the pipe");
        assert_eq!(entries(&folder), ["pipe.png"]);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_link_to_dev_null_writes_into_it_and_a_directory_is_refused() {
        let folder = folder("device");
        let link = folder.join("null.png");
        symlink("/dev/null", &link).unwrap();
        write_atomically(&link, b"discarded").unwrap();
        assert!(
            fs::metadata("/dev/null")
                .unwrap()
                .file_type()
                .is_char_device()
        );
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        let err = write_atomically(&folder, b"x").unwrap_err().to_string();
        assert!(err.contains("it is a directory"), "{err}");
        assert_eq!(entries(&folder), ["null.png"]);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_failed_write_leaves_the_old_file_and_no_temporary() {
        let folder = folder("failed");
        let path = folder.join("out.png");
        fs::write(&path, b"old").unwrap();
        let err = replace(&path, None, |file| {
            file.write_all(b"half")?;
            Err(io::Error::other("the disk is full"))
        })
        .unwrap_err();
        assert_eq!(err.to_string(), "the disk is full");
        assert_eq!(fs::read(&path).unwrap(), b"old");
        assert_eq!(entries(&folder), ["out.png"]);
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn a_replaced_file_keeps_its_permissions() {
        let folder = folder("mode");
        let path = folder.join("out.png");
        fs::write(&path, b"old").unwrap();
        fs::set_permissions(&path, Permissions::from_mode(0o640)).unwrap();
        write_atomically(&path, b"new").unwrap();
        let mode = fs::metadata(&path).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        fs::remove_dir_all(&folder).unwrap();
    }
}

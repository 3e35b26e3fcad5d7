//! `cargo xtask web [OUT_DIR]`: the explorer for a browser. Builds `crates/refraction-web` for
//! `wasm32-unknown-unknown` with Debian's web toolchain (in `target/wasm`, so that the desktop
//! build in `target/` is never invalidated), runs wasm-bindgen on it, and writes into `OUT_DIR`
//! (default `target/web`): `index.html` with the `.js` and `.wasm` it loads, for any static web
//! server, and `refraction-explorer.html`, one file with both inlined, which opens from
//! `file://` with no network.
//!
//! It installs nothing: it checks for the toolchain first and names the command that installs
//! what is missing.

use std::path::{Path, PathBuf};
use std::process::Command;

use refraction_explorer::web_page::{self, Script};

use crate::Failure;

/// The Debian packages that build the standard library for WebAssembly and link it.
const PACKAGES: &str = "rustc-web cargo-web rust-web-src lld-22";

/// Debian's compiler and cargo from `rustc-web` and `cargo-web` (rustup's stay first on PATH).
const RUSTC: &str = "/usr/bin/rustc";
const CARGO: &str = "/usr/bin/cargo";

/// The linker `lld-22` installs.
const LINKER: &str = "wasm-ld-22";

/// The crate built, and the name of what wasm-bindgen writes for it.
const CRATE: &str = "refraction-web";
const MODULE: &str = "refraction_web";

/// The single file's name.
const SINGLE_FILE: &str = "refraction-explorer.html";

/// The version of `name` that `Cargo.lock` pins.
fn locked_version(lock: &str, name: &str) -> Option<String> {
    let entry = format!("name = \"{name}\"\nversion = \"");
    let start = lock.find(&entry)? + entry.len();
    let end = lock[start..].find('"')?;
    Some(lock[start..start + end].to_owned())
}

/// What `program --version` prints, if it runs.
fn version_of(program: &str) -> Option<String> {
    let run = Command::new(program).arg("--version").output().ok()?;
    run.status
        .success()
        .then(|| String::from_utf8_lossy(&run.stdout).trim().to_owned())
}

/// Whether the standard library's source that `rust-web-src` installs is there for
/// `/usr/bin/rustc`.
fn has_library_source() -> bool {
    let sysroot = Command::new(RUSTC).args(["--print", "sysroot"]).output();
    sysroot.is_ok_and(|run| {
        let root = String::from_utf8_lossy(&run.stdout).trim().to_owned();
        Path::new(&root)
            .join("lib/rustlib/src/rust/library/std/Cargo.toml")
            .is_file()
    })
}

/// Checks the toolchain; returns the wasm-bindgen version to use.
///
/// # Errors
/// What is missing, each with the command that installs it.
fn check_toolchain(repository: &Path) -> Result<String, Failure> {
    let lock = std::fs::read_to_string(repository.join("Cargo.lock"))
        .map_err(|e| format!("cannot read Cargo.lock: {e}"))?;
    let bindgen = locked_version(&lock, "wasm-bindgen")
        .ok_or("Cargo.lock pins no wasm-bindgen: run cargo update -p refraction-web")?;
    let mut missing = Vec::new();
    let debian = version_of(RUSTC).is_some()
        && version_of(CARGO).is_some()
        && has_library_source()
        && version_of(LINKER).is_some();
    if !debian {
        missing.push(format!(
            "Debian's web toolchain ({RUSTC}, {CARGO}, the standard library's source, \
             {LINKER}): sudo apt-get install {PACKAGES}"
        ));
    }
    let found = version_of("wasm-bindgen");
    if found.as_deref() != Some(&format!("wasm-bindgen {bindgen}")) {
        let found = found.unwrap_or_else(|| "none".to_owned());
        missing.push(format!(
            "wasm-bindgen {bindgen}, the version in Cargo.lock (found: {found}): \
             cargo install wasm-bindgen-cli --version {bindgen}"
        ));
    }
    if missing.is_empty() {
        Ok(bindgen)
    } else {
        Err(format!(
            "the web build needs what is missing here; install it and run again:\n  {}",
            missing.join("\n  ")
        )
        .into())
    }
}

/// Runs `command`, or says what failed.
fn run(command: &mut Command, what: &str) -> Result<(), Failure> {
    let status = command
        .status()
        .map_err(|e| format!("cannot run {what}: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("{what} failed ({status})").into())
    }
}

/// Builds the module in `target/wasm` and runs wasm-bindgen on it; returns the folder
/// wasm-bindgen wrote.
fn build(repository: &Path) -> Result<PathBuf, Failure> {
    let target = repository.join("target").join("wasm");
    let mut cargo = Command::new(CARGO);
    cargo
        .current_dir(repository)
        .args(["build", "--profile", "web", "-Zbuild-std=std,panic_abort"])
        .args(["--target", "wasm32-unknown-unknown", "-p", CRATE])
        .arg("--target-dir")
        .arg(&target)
        .env("RUSTC", RUSTC)
        .env("RUSTC_BOOTSTRAP", "1")
        .env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER", LINKER);
    // What `cargo xtask` (rustup's cargo) set for itself, or flags meant for the desktop.
    for name in [
        "CARGO",
        "RUSTUP_TOOLCHAIN",
        "RUSTC_WRAPPER",
        "RUSTC_WORKSPACE_WRAPPER",
        "RUSTFLAGS",
        "CARGO_ENCODED_RUSTFLAGS",
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_TARGET",
    ] {
        cargo.env_remove(name);
    }
    run(&mut cargo, "the WebAssembly build")?;
    let wasm = target
        .join("wasm32-unknown-unknown")
        .join("web")
        .join(format!("{MODULE}.wasm"));
    let bindgen = target.join("bindgen");
    run(
        Command::new("wasm-bindgen")
            .arg(&wasm)
            .args(["--target", "web", "--no-typescript", "--out-dir"])
            .arg(&bindgen),
        "wasm-bindgen",
    )?;
    Ok(bindgen)
}

/// `bytes` in base64 (RFC 4648, with padding).
fn base64(bytes: &[u8]) -> String {
    const DIGITS: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let word = chunk
            .iter()
            .enumerate()
            .fold(0u32, |w, (i, &b)| w | (u32::from(b) << (16 - 8 * i)));
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(DIGITS[((word >> (18 - 6 * i)) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Writes the folder's page and files and the single file into `out`, from what wasm-bindgen
/// wrote in `bindgen`; returns the files written.
fn write_pages(bindgen: &Path, out: &Path) -> Result<Vec<PathBuf>, Failure> {
    let read = |name: &str| {
        let path = bindgen.join(name);
        std::fs::read(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))
    };
    let (js_name, wasm_name) = (format!("{MODULE}.js"), format!("{MODULE}_bg.wasm"));
    let (js, wasm) = (read(&js_name)?, read(&wasm_name)?);
    let js_text = String::from_utf8_lossy(&js);
    let index = web_page::html(&Script::Beside { js: &js_name });
    let single = web_page::html(&Script::Inlined {
        js: &js_text,
        wasm_base64: &base64(&wasm),
    });
    std::fs::create_dir_all(out).map_err(|e| format!("cannot make {}: {e}", out.display()))?;
    let files = [
        (js_name.as_str(), js.as_slice()),
        (wasm_name.as_str(), wasm.as_slice()),
        ("index.html", index.as_bytes()),
        (SINGLE_FILE, single.as_bytes()),
    ];
    files
        .iter()
        .map(|(name, bytes)| {
            let path = out.join(name);
            std::fs::write(&path, bytes)
                .map(|()| path.clone())
                .map_err(|e| Failure::from(format!("cannot write {}: {e}", path.display())))
        })
        .collect()
}

/// Runs `cargo xtask web`: checks the toolchain, builds, and writes the pages into `out`.
/// Returns the files written, each with its size in bytes.
///
/// # Errors
/// A missing tool (with the command that installs it), a failed build, or a file that cannot
/// be written.
pub(crate) fn web(repository: &Path, out: &Path) -> Result<Vec<(PathBuf, u64)>, Failure> {
    check_toolchain(repository)?;
    let bindgen = build(repository)?;
    let written = write_pages(&bindgen, out)?;
    Ok(written
        .into_iter()
        .map(|path| {
            let size = std::fs::metadata(&path).map_or(0, |m| m.len());
            (path, size)
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_is_rfc_4648() {
        for (bytes, text) in [
            (&b""[..], ""),
            (b"f", "Zg=="),
            (b"fo", "Zm8="),
            (b"foo", "Zm9v"),
            (b"foobar", "Zm9vYmFy"),
            (b"\x00asm\xff", "AGFzbf8="),
        ] {
            assert_eq!(base64(bytes), text);
        }
    }

    #[test]
    fn the_locked_wasm_bindgen_is_found() {
        let lock = "[[package]]\nname = \"wasm-bindgen-shared\"\nversion = \"9\"\n\n\
                    [[package]]\nname = \"wasm-bindgen\"\nversion = \"0.2.130\"\n";
        assert_eq!(
            locked_version(lock, "wasm-bindgen").as_deref(),
            Some("0.2.130")
        );
        assert_eq!(locked_version(lock, "qrcode"), None);
    }
}

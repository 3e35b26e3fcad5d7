//! `cargo xtask web [OUT_DIR]`: the explorer for a browser. Builds `crates/refraction-web` for
//! `wasm32-unknown-unknown` (in `target/wasm`, so that the desktop build in `target/` is never
//! invalidated), runs wasm-bindgen on it, and writes into `OUT_DIR` (default `target/web`):
//! `index.html` with the `.js` and `.wasm` it loads, for any static web server, and
//! `refraction-explorer.html`, one file with both inlined, which opens from `file://` with no
//! network.
//!
//! The module is built as every eframe app is: with the toolchain's own WebAssembly standard
//! library (`rustup target add wasm32-unknown-unknown`), a stable build linked by the
//! toolchain's `rust-lld`. Where that library is missing, Debian 12's web toolchain is the
//! fallback: it builds the standard library from source (`-Zbuild-std`, allowed on a stable
//! compiler by `RUSTC_BOOTSTRAP`) and links with `wasm-ld-22`.
//!
//! It installs nothing: it checks for the toolchain first and names the command that installs
//! what is missing.

use core::hash::{Hash as _, Hasher as _};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use refraction_explorer::web_page::{self, Script};

use crate::Failure;

/// The target every browser runs.
const TARGET: &str = "wasm32-unknown-unknown";

/// The Debian packages that build the standard library for WebAssembly and link it.
const PACKAGES: &str = "rustc-web cargo-web rust-web-src lld-22";

/// Debian's compiler and cargo from `rustc-web` and `cargo-web` (rustup's stay first on PATH).
const DEBIAN_RUSTC: &str = "/usr/bin/rustc";
const DEBIAN_CARGO: &str = "/usr/bin/cargo";

/// The linker `lld-22` installs.
const DEBIAN_LINKER: &str = "wasm-ld-22";

/// The Cargo profile of the build a school hosts (the root manifest's `[profile.web]`).
pub(crate) const PROFILE: &str = "web";

/// The crate built, and the name of what wasm-bindgen writes for it.
const CRATE: &str = "refraction-web";
const MODULE: &str = "refraction_web";

/// The single file's name.
const SINGLE_FILE: &str = "refraction-explorer.html";

/// What `cargo xtask web` is asked for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Options {
    /// The Cargo profile built with.
    profile: String,
    /// Whether the workspace's crates are linted as they are built.
    lint: bool,
    /// Where the pages go.
    out: Option<PathBuf>,
}

impl Options {
    /// The options `args` (after `web`) give: `[--profile NAME] [--lint] [OUT_DIR]`, in any
    /// order; `None` for anything else.
    pub(crate) fn parse(args: &[&str]) -> Option<Self> {
        let mut options = Self {
            profile: PROFILE.to_owned(),
            lint: false,
            out: None,
        };
        let mut args = args.iter();
        while let Some(&arg) = args.next() {
            match arg {
                "--profile" => (*args.next()?).clone_into(&mut options.profile),
                "--lint" => options.lint = true,
                _ if arg.starts_with('-') || options.out.is_some() => return None,
                _ => options.out = Some(PathBuf::from(arg)),
            }
        }
        Some(options)
    }
}

/// Where clippy's configuration for the WebAssembly build is, in the repository.
const CLIPPY_WASM: &str = ".ci/clippy-wasm";

/// What builds the module.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Toolchain {
    /// The `cargo` and `rustc` on `PATH` (rustup's, or a distribution's), whose sysroot has the
    /// WebAssembly standard library: a stable build, linked by the toolchain's own `rust-lld`.
    /// Holds what `rustc --version` says.
    Installed(String),
    /// Debian's `rustc-web` and `cargo-web`: the standard library built from its source.
    Debian,
}

impl Toolchain {
    /// What `xtask web` says before it builds.
    fn describe(&self) -> String {
        match self {
            Self::Installed(version) => format!(
                "building with {version} and its {TARGET} standard library (a stable build)"
            ),
            Self::Debian => format!(
                "{TARGET}'s standard library is not installed for the rustc on PATH \
                 (rustup target add {TARGET}); building with Debian's web toolchain \
                 ({DEBIAN_RUSTC}, {DEBIAN_CARGO}, {DEBIAN_LINKER}), which builds the \
                 standard library too"
            ),
        }
    }
}

/// The version of `name` that `Cargo.lock` pins.
fn locked_version(lock: &str, name: &str) -> Option<String> {
    let entry = format!("name = \"{name}\"\nversion = \"");
    let start = lock.find(&entry)? + entry.len();
    let end = lock[start..].find('"')?;
    Some(lock[start..start + end].to_owned())
}

/// What `program --version` prints, if it runs.
fn version_of(program: &str) -> Option<String> {
    output_of(program, &["--version"])
}

/// What `program ARGS` prints (trimmed), if it runs and succeeds.
fn output_of(program: &str, args: &[&str]) -> Option<String> {
    let run = Command::new(program).args(args).output().ok()?;
    run.status
        .success()
        .then(|| String::from_utf8_lossy(&run.stdout).trim().to_owned())
}

/// The compiler cargo would run: `RUSTC` if set, else `rustc` on `PATH`.
fn path_rustc() -> String {
    std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_owned())
}

/// Whether `rustc`'s sysroot holds the WebAssembly standard library (what `rustup target add
/// wasm32-unknown-unknown` installs) and the toolchain's `rust-lld` that links it.
fn has_wasm_std(rustc: &str) -> bool {
    let holds = |dir: Option<String>, name: &dyn Fn(&str) -> bool| {
        dir.and_then(|dir| std::fs::read_dir(dir).ok())
            .is_some_and(|entries| {
                entries
                    .flatten()
                    .any(|e| name(&e.file_name().to_string_lossy()))
            })
    };
    let wasm_lib = output_of(rustc, &["--print", "target-libdir", "--target", TARGET]);
    let std_there = holds(wasm_lib, &|n| {
        n.starts_with("libstd-") && Path::new(n).extension().is_some_and(|e| e == "rlib")
    });
    // rust-lld sits in the host's `bin` beside its `lib`.
    let host_bin = output_of(rustc, &["--print", "target-libdir"])
        .map(|lib| Path::new(&lib).with_file_name("bin").display().to_string());
    std_there && holds(host_bin, &|n| n == "rust-lld" || n == "rust-lld.exe")
}

/// Whether the standard library's source that `rust-web-src` installs is there for
/// `/usr/bin/rustc`.
fn has_library_source() -> bool {
    output_of(DEBIAN_RUSTC, &["--print", "sysroot"]).is_some_and(|root| {
        Path::new(&root)
            .join("lib/rustlib/src/rust/library/std/Cargo.toml")
            .is_file()
    })
}

/// The toolchain to build with: the installed one where it has the WebAssembly standard
/// library, Debian's where that is complete, else what to install.
fn toolchain() -> Result<Toolchain, String> {
    let rustc = path_rustc();
    if has_wasm_std(&rustc) {
        let version = version_of(&rustc).unwrap_or(rustc);
        return Ok(Toolchain::Installed(version));
    }
    let debian = version_of(DEBIAN_RUSTC).is_some()
        && version_of(DEBIAN_CARGO).is_some()
        && has_library_source()
        && version_of(DEBIAN_LINKER).is_some();
    if debian {
        Ok(Toolchain::Debian)
    } else {
        Err(format!(
            "the WebAssembly standard library: rustup target add {TARGET} (with rustup, the \
             usual way), or on Debian 12 without it: sudo apt-get install {PACKAGES}"
        ))
    }
}

/// Checks the toolchain and wasm-bindgen; returns the toolchain to build with.
///
/// # Errors
/// What is missing, each with the command that installs it.
fn check_toolchain(repository: &Path) -> Result<Toolchain, Failure> {
    let lock = std::fs::read_to_string(repository.join("Cargo.lock"))
        .map_err(|e| format!("cannot read Cargo.lock: {e}"))?;
    let bindgen = locked_version(&lock, "wasm-bindgen")
        .ok_or("Cargo.lock pins no wasm-bindgen: run cargo update -p refraction-web")?;
    let mut missing = Vec::new();
    let found = toolchain().map_err(|what| missing.push(what)).ok();
    let bindgen_found = version_of("wasm-bindgen");
    if bindgen_found.as_deref() != Some(&format!("wasm-bindgen {bindgen}")) {
        let bindgen_found = bindgen_found.unwrap_or_else(|| "none".to_owned());
        missing.push(format!(
            "wasm-bindgen {bindgen}, the version in Cargo.lock (found: {bindgen_found}): \
             cargo install wasm-bindgen-cli --version {bindgen}"
        ));
    }
    match found {
        Some(toolchain) if missing.is_empty() => Ok(toolchain),
        _ => Err(format!(
            "the web build needs what is missing here; install it and run again:\n  {}",
            missing.join("\n  ")
        )
        .into()),
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

/// The cargo command that builds the module with `toolchain` into `target`.
fn cargo_build(
    toolchain: &Toolchain,
    repository: &Path,
    options: &Options,
    target: &Path,
) -> Command {
    let mut cargo = match toolchain {
        Toolchain::Installed(_) => Command::new("cargo"),
        Toolchain::Debian => {
            let mut cargo = Command::new(DEBIAN_CARGO);
            cargo
                .env("RUSTC", DEBIAN_RUSTC)
                .env("RUSTC_BOOTSTRAP", "1")
                .env("CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER", DEBIAN_LINKER);
            // rustup's choice of toolchain and wrappers are not for Debian's compiler.
            for name in [
                "RUSTUP_TOOLCHAIN",
                "RUSTC_WRAPPER",
                "RUSTC_WORKSPACE_WRAPPER",
            ] {
                cargo.env_remove(name);
            }
            cargo
        }
    };
    cargo
        .current_dir(repository)
        .args([
            "build",
            "--profile",
            &options.profile,
            "--target",
            TARGET,
            "-p",
            CRATE,
        ])
        .arg("--target-dir")
        .arg(target);
    if *toolchain == Toolchain::Debian {
        cargo.arg("-Zbuild-std=std,panic_abort");
    }
    // What `cargo xtask` set for itself, or flags meant for the desktop.
    for name in [
        "CARGO",
        "RUSTFLAGS",
        "CARGO_ENCODED_RUSTFLAGS",
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_TARGET",
    ] {
        cargo.env_remove(name);
    }
    if options.lint {
        // As `cargo clippy` lints, while building: clippy-driver compiles the workspace's
        // crates (not the dependencies), and with -D warnings (capped for the dependencies, as
        // every lint of theirs) a lint stops the build.
        cargo
            .env("RUSTC_WORKSPACE_WRAPPER", "clippy-driver")
            .env("CLIPPY_CONF_DIR", repository.join(CLIPPY_WASM))
            .env("CARGO_ENCODED_RUSTFLAGS", "-Dwarnings");
    }
    cargo
}

/// Builds the module with `toolchain` as `options` say in `target/wasm` and runs wasm-bindgen
/// on it; returns the folder wasm-bindgen wrote.
fn build(toolchain: &Toolchain, repository: &Path, options: &Options) -> Result<PathBuf, Failure> {
    let target = repository.join("target").join("wasm");
    let mut cargo = cargo_build(toolchain, repository, options, &target);
    run(&mut cargo, "the WebAssembly build")?;
    let wasm = target
        .join(TARGET)
        .join(&options.profile)
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

/// The build's name: a hash of what the page loads, so that any change to it names a new
/// service worker cache. (`DefaultHasher` may hash differently under another Rust version,
/// which only renames the cache once more.)
fn build_name(parts: &[&[u8]]) -> String {
    let mut hasher = std::hash::DefaultHasher::new();
    for part in parts {
        part.hash(&mut hasher);
    }
    format!("{:016x}", hasher.finish())
}

/// Writes the folder's page and files and the single file into `out`, from what wasm-bindgen
/// wrote in `bindgen`; returns the files written. The folder also gets the web app manifest,
/// its icons and the service worker that keeps the build for use with no network.
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
    let tree = crate::icon()?;
    let icons = web_page::ICONS
        .iter()
        .map(|&(name, size)| Ok((name, crate::icon_png(&tree, size)?)))
        .collect::<Result<Vec<_>, Failure>>()?;
    let manifest = web_page::manifest();
    let mut offline = vec!["index.html", js_name.as_str(), wasm_name.as_str()];
    offline.push(web_page::MANIFEST);
    offline.extend(icons.iter().map(|(name, _)| *name));
    let build = build_name(&[&js, &wasm, index.as_bytes(), manifest.as_bytes()]);
    let worker = web_page::service_worker(&build, &offline);
    std::fs::create_dir_all(out).map_err(|e| format!("cannot make {}: {e}", out.display()))?;
    let mut files = vec![
        (js_name.as_str(), js.as_slice()),
        (wasm_name.as_str(), wasm.as_slice()),
        ("index.html", index.as_bytes()),
        (SINGLE_FILE, single.as_bytes()),
        (web_page::MANIFEST, manifest.as_bytes()),
        (web_page::SERVICE_WORKER, worker.as_bytes()),
    ];
    files.extend(icons.iter().map(|(name, png)| (*name, png.as_slice())));
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

/// Runs `cargo xtask web`: checks the toolchain, builds as `options` say, and writes the pages
/// into their folder (default `target/web`).
/// Returns the files written, each with its size in bytes.
///
/// # Errors
/// A missing tool (with the command that installs it), a failed build, or a file that cannot
/// be written.
pub(crate) fn web(repository: &Path, options: &Options) -> Result<Vec<(PathBuf, u64)>, Failure> {
    let toolchain = check_toolchain(repository)?;
    if options.lint && toolchain == Toolchain::Debian {
        return Err(format!(
            "--lint needs clippy for the rustc on PATH, with its {TARGET} standard library: \
             rustup component add clippy; rustup target add {TARGET}"
        )
        .into());
    }
    // Said before the build, which takes minutes; a failed write to stderr changes nothing.
    writeln!(std::io::stderr(), "xtask: {}", toolchain.describe()).ok();
    let bindgen = build(&toolchain, repository, options)?;
    let default_out = repository.join("target").join("web");
    let written = write_pages(&bindgen, options.out.as_ref().unwrap_or(&default_out))?;
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
    fn options_are_read_in_any_order() {
        let read = |args: &[&str]| Options::parse(args);
        assert_eq!(read(&[]).unwrap().profile, "web");
        let ci = read(&["--lint", "out", "--profile", "web-ci"]).unwrap();
        assert_eq!(
            ci,
            Options {
                profile: "web-ci".to_owned(),
                lint: true,
                out: Some(PathBuf::from("out")),
            }
        );
        assert_eq!(read(&["--profile"]), None, "a profile needs its name");
        assert_eq!(read(&["a", "b"]), None, "one folder");
        assert_eq!(read(&["--release"]), None, "unknown option");
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

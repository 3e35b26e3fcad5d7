//! The project's build tasks beyond Cargo's, run as `cargo xtask TASK` (the alias is in
//! `.cargo/config.toml`).
//!
//! - `cargo xtask dist-assets [OUT_DIR]`: the man pages (one for the program, one per command)
//!   and the bash, zsh and fish completions, generated from the command line's clap
//!   definitions ([`refraction_explorer::cli::command`]) so that they always say what `--help`
//!   says, and the icon's PNG sizes, rendered from `packaging/refraction-explorer.svg`.
//!   `OUT_DIR` defaults to `target/dist-assets` in the repository, where the Debian package's
//!   manifest (`[package.metadata.deb]` in the root `Cargo.toml`) takes them from.
//! - `cargo xtask web [--profile NAME] [OUT_DIR]`: the explorer for a browser ([`web`]):
//!   `OUT_DIR` (default `target/web`) gets `index.html` and the files it loads, and
//!   `refraction-explorer.html`, one file that opens from `file://`; built with the Cargo
//!   profile `NAME` (default `web`); `--lint` lints the crates with clippy as they are built.

mod web;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap_complete::Shell;

/// Why a task failed: a sentence naming what and where (an I/O error with its path, a missing
/// tool with the command that installs it), printed after `xtask: `.
pub(crate) type Failure = Box<dyn core::error::Error>;

/// What `cargo xtask` without a known task prints.
const USAGE: &str = "usage: cargo xtask dist-assets [OUT_DIR]\n       cargo xtask web [--profile NAME] \
    [--lint] [OUT_DIR]\n\n\
    dist-assets  write the man pages (OUT_DIR/man/*.1) and the bash, zsh and fish completions\n\
    \x20            (OUT_DIR/completions/) generated from the command line's definitions, and\n\
    \x20            the icon's PNG sizes (OUT_DIR/icons/); OUT_DIR defaults to\n\
    \x20            target/dist-assets in the repository\n\
    web          build the explorer for a browser (with the wasm32-unknown-unknown standard\n\
    \x20            library: rustup target add wasm32-unknown-unknown; Debian's rustc-web,\n\
    \x20            cargo-web, rust-web-src and lld-22 where it is missing; and the\n\
    \x20            wasm-bindgen CLI of Cargo.lock's version) and write\n\
    \x20            OUT_DIR/index.html with the files it loads, and\n\
    \x20            OUT_DIR/refraction-explorer.html, one file that opens from file://;\n\
    \x20            OUT_DIR defaults to target/web in the repository; the Cargo profile\n\
    \x20            defaults to web (optimised across crates: what a school hosts); CI's\n\
    \x20            browser tests use web-ci (quicker to build, debug assertions on);\n\
    \x20            --lint runs clippy on the workspace's crates as they are built, with\n\
    \x20            .ci/clippy-wasm/clippy.toml and warnings as errors";

/// The icon's sizes in pixels, as the freedesktop.org hicolor theme names its folders.
const ICON_SIZES: [u32; 7] = [16, 24, 32, 48, 64, 128, 256];

/// The shells completions are written for, and the file each one's completion goes to.
const SHELLS: [(Shell, &str); 3] = [
    (Shell::Bash, "refraction-explorer.bash"),
    (Shell::Zsh, "_refraction-explorer"),
    (Shell::Fish, "refraction-explorer.fish"),
];

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let outcome = match args.as_slice() {
        ["dist-assets"] => dist_assets(&default_out_dir()),
        ["dist-assets", out] => dist_assets(Path::new(out)),
        ["web", rest @ ..] => {
            return web::Options::parse(rest)
                .map_or_else(|| say(USAGE, ExitCode::from(2)), |o| web_task(&o));
        }
        ["help" | "--help" | "-h"] => return say(USAGE, ExitCode::SUCCESS),
        _ => return say(USAGE, ExitCode::from(2)),
    };
    match outcome {
        Ok(written) => say(
            &format!("xtask: wrote {written} files under {}", shown(&args)),
            ExitCode::SUCCESS,
        ),
        Err(e) => say(&format!("xtask: {e}"), ExitCode::FAILURE),
    }
}

/// Runs `cargo xtask web` as `options` say and says what it wrote (or what is missing).
fn web_task(options: &web::Options) -> ExitCode {
    match web::web(repository(), options) {
        Ok(written) => {
            let lines: Vec<String> = written
                .iter()
                .map(|(path, size)| format!("  {} ({size} bytes)", path.display()))
                .collect();
            say(
                &format!("xtask: wrote\n{}", lines.join("\n")),
                ExitCode::SUCCESS,
            )
        }
        Err(e) => say(&format!("xtask: {e}"), ExitCode::FAILURE),
    }
}

/// `message` on stderr (a failed write changes nothing: the status says it all), then `status`.
fn say(message: &str, status: ExitCode) -> ExitCode {
    writeln!(std::io::stderr(), "{message}").ok();
    status
}

/// The output folder the arguments name, as a message shows it.
fn shown(args: &[&str]) -> String {
    args.get(1).map_or_else(
        || default_out_dir().display().to_string(),
        |out| (*out).to_owned(),
    )
}

/// The repository: the workspace's root, this crate's parent.
fn repository() -> &'static Path {
    let xtask = Path::new(env!("CARGO_MANIFEST_DIR"));
    xtask.parent().unwrap_or(xtask)
}

/// `target/dist-assets` in the repository.
fn default_out_dir() -> PathBuf {
    repository().join("target").join("dist-assets")
}

/// Writes the man pages to `out/man`, the completions to `out/completions` and the icon's
/// PNG sizes to `out/icons`, after removing the pages and icons an earlier run wrote there (so
/// that a command removed from the program leaves no page behind). Returns how many files
/// were written.
///
/// # Errors
/// A folder that cannot be made, or a file that cannot be removed or written, named.
fn dist_assets(out: &Path) -> Result<usize, Failure> {
    let man = out.join("man");
    let completions = out.join("completions");
    let icons = out.join("icons");
    remove_earlier(out)?;
    for dir in [&man, &completions, &icons] {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot make {}: {e}", dir.display()))?;
    }
    let pages = man_pages(&man)?;
    for (shell, file) in SHELLS {
        let mut command = refraction_explorer::cli::command();
        let mut text = Vec::new();
        clap_complete::generate(shell, &mut command, "refraction-explorer", &mut text);
        let path = completions.join(file);
        std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    Ok(pages + SHELLS.len() + icon_pngs(&icons)?)
}

/// Removes what an earlier run wrote under `out` and this one may not write again: the man
/// pages (`man/refraction-explorer*.1`) and the icon's PNGs. Nothing else there is touched,
/// whatever folder `out` is.
///
/// # Errors
/// A file that cannot be removed, named.
fn remove_earlier(out: &Path) -> Result<(), Failure> {
    let mut earlier = Vec::new();
    if let Ok(pages) = std::fs::read_dir(out.join("man")) {
        for page in pages.flatten() {
            let name = page.file_name();
            let name = name.to_string_lossy();
            if name.starts_with("refraction-explorer") && name.ends_with(".1") {
                earlier.push(page.path());
            }
        }
    }
    if let Ok(sizes) = std::fs::read_dir(out.join("icons").join("hicolor")) {
        for size in sizes.flatten() {
            let png = size.path().join("apps").join("refraction-explorer.png");
            if png.is_file() {
                earlier.push(png);
            }
        }
    }
    for path in earlier {
        std::fs::remove_file(&path)
            .map_err(|e| format!("cannot remove {}: {e}", path.display()))?;
    }
    Ok(())
}

/// Renders `packaging/refraction-explorer.svg` at each of [`ICON_SIZES`] into
/// `dir/hicolor/NxN/apps/refraction-explorer.png`. Returns how many were written.
///
/// # Errors
/// The SVG cannot be read or parsed, or a PNG cannot be encoded or written.
fn icon_pngs(dir: &Path) -> Result<usize, Failure> {
    let tree = icon()?;
    for size in ICON_SIZES {
        let folder = dir
            .join("hicolor")
            .join(format!("{size}x{size}"))
            .join("apps");
        std::fs::create_dir_all(&folder)
            .map_err(|e| format!("cannot make {}: {e}", folder.display()))?;
        let path = folder.join("refraction-explorer.png");
        std::fs::write(&path, icon_png(&tree, size)?)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    }
    Ok(ICON_SIZES.len())
}

/// The program's icon, `packaging/refraction-explorer.svg`, read.
///
/// # Errors
/// The SVG cannot be read or parsed.
pub(crate) fn icon() -> Result<resvg::usvg::Tree, Failure> {
    let source = repository()
        .join("packaging")
        .join("refraction-explorer.svg");
    let svg =
        std::fs::read(&source).map_err(|e| format!("cannot read {}: {e}", source.display()))?;
    Ok(
        resvg::usvg::Tree::from_data(&svg, &resvg::usvg::Options::default())
            .map_err(|e| format!("cannot parse {}: {e}", source.display()))?,
    )
}

/// The icon drawn `size` pixels square, as PNG bytes.
///
/// # Errors
/// The picture cannot be made or encoded.
pub(crate) fn icon_png(tree: &resvg::usvg::Tree, size: u32) -> Result<Vec<u8>, Failure> {
    // resvg draws with the tiny-skia it was built with; the picture's pixels move to this
    // project's tiny-skia, which writes PNG files.
    let mut drawn = resvg::tiny_skia::Pixmap::new(size, size)
        .ok_or_else(|| format!("cannot make a {size}x{size} picture"))?;
    let scale = size as f32 / tree.size().width();
    resvg::render(
        tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut drawn.as_mut(),
    );
    Ok(tiny_skia::IntSize::from_wh(size, size)
        .and_then(|area| tiny_skia::Pixmap::from_vec(drawn.take(), area))
        .ok_or_else(|| format!("cannot make a {size}x{size} picture"))?
        .encode_png()
        .map_err(|e| format!("cannot encode the {size}x{size} icon: {e}"))?)
}

/// Writes `refraction-explorer.1` and a `refraction-explorer-COMMAND.1` for each command into
/// `dir`, each page's footer naming the program's version. Returns how many pages were written.
///
/// # Errors
/// A page that cannot be written, named.
fn man_pages(dir: &Path) -> Result<usize, Failure> {
    // As clap_mangen's own `generate_to`: built, so that each command's page is named after
    // the program and the command, and without the `help` command, which needs no page.
    let mut program = refraction_explorer::cli::command().disable_help_subcommand(true);
    program.build();
    let source = format!(
        "refraction-explorer {}",
        program.get_version().unwrap_or_default()
    );
    let mut pages = vec![program.clone()];
    pages.extend(
        program
            .get_subcommands()
            .filter(|c| !c.is_hide_set())
            .cloned(),
    );
    for page in &pages {
        clap_mangen::Man::new(page.clone())
            .source(source.clone())
            .generate_to(dir)
            .map_err(|e| format!("cannot write a man page into {}: {e}", dir.display()))?;
    }
    Ok(pages.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every command has its page, the program's page lists them all, and each shell's
    /// completion offers the commands.
    #[test]
    fn dist_assets_cover_every_command() {
        let out = tempfile::tempdir().unwrap();
        let written = dist_assets(out.path()).unwrap();
        let root = std::fs::read_to_string(out.path().join("man/refraction-explorer.1")).unwrap();
        assert!(root.contains(".TH refraction-explorer 1"), "{root}");
        for sub in refraction_explorer::cli::command().get_subcommands() {
            let name = sub.get_name();
            let page = out.path().join(format!("man/refraction-explorer-{name}.1"));
            assert!(page.is_file(), "no man page for {name}");
            assert!(
                root.contains(name),
                "the program's page does not name {name}"
            );
        }
        for (_, file) in SHELLS {
            let text = std::fs::read_to_string(out.path().join("completions").join(file)).unwrap();
            for command in ["solve", "check", "render", "trace", "bench"] {
                assert!(text.contains(command), "{file} does not offer {command}");
            }
        }
        for size in ICON_SIZES {
            let png = out.path().join(format!(
                "icons/hicolor/{size}x{size}/apps/refraction-explorer.png"
            ));
            let picture = tiny_skia::Pixmap::load_png(&png).unwrap();
            assert_eq!((picture.width(), picture.height()), (size, size), "{size}");
            // The tile is opaque in the middle and transparent in its rounded corners.
            let middle = picture.pixel(size / 2, size / 2).unwrap();
            assert_eq!(middle.alpha(), 255, "{size}: the middle is not opaque");
            assert_eq!(
                picture.pixel(0, 0).unwrap().alpha(),
                0,
                "{size}: the corner"
            );
        }
        assert!(
            written >= 6 + SHELLS.len() + ICON_SIZES.len(),
            "only {written} files"
        );
    }

    /// A second run replaces the first's pages and icons, and leaves other files alone.
    #[test]
    fn dist_assets_replace_only_their_own_files() {
        let out = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(out.path().join("man")).unwrap();
        std::fs::write(out.path().join("man/refraction-explorer-gone.1"), "old").unwrap();
        std::fs::write(out.path().join("man/other.1"), "someone else's").unwrap();
        std::fs::create_dir_all(out.path().join("icons/hicolor/20x20/apps")).unwrap();
        let old_icon = out
            .path()
            .join("icons/hicolor/20x20/apps/refraction-explorer.png");
        std::fs::write(&old_icon, "old").unwrap();
        let first = dist_assets(out.path()).unwrap();
        assert!(
            !out.path().join("man/refraction-explorer-gone.1").exists(),
            "a stale page survived"
        );
        assert!(!old_icon.exists(), "a stale icon survived");
        assert!(out.path().join("man/other.1").exists(), "another file went");
        assert_eq!(dist_assets(out.path()).unwrap(), first, "the count changed");
    }
}

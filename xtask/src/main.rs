//! The project's build tasks beyond Cargo's, run as `cargo xtask TASK` (the alias is in
//! `.cargo/config.toml`).
//!
//! - `cargo xtask dist-assets [OUT_DIR]`: the man pages (one for the program, one per command)
//!   and the bash, zsh and fish completions, generated from the command line's clap
//!   definitions ([`refraction_explorer::cli::command`]) so that they always say what `--help`
//!   says. `OUT_DIR` defaults to `target/dist-assets` in the repository, where the Debian
//!   package's manifest (`[package.metadata.deb]` in the root `Cargo.toml`) takes them from.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap_complete::Shell;

/// What `cargo xtask` without a known task prints.
const USAGE: &str = "usage: cargo xtask dist-assets [OUT_DIR]\n\n\
    dist-assets  write the man pages (OUT_DIR/man/*.1) and the bash, zsh and fish completions\n\
    \x20            (OUT_DIR/completions/) generated from the command line's definitions;\n\
    \x20            OUT_DIR defaults to target/dist-assets in the repository";

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

/// `message` on stderr (a failed write changes nothing: the status says it all), then `status`.
fn say(message: &str, status: ExitCode) -> ExitCode {
    let _ = writeln!(std::io::stderr(), "{message}");
    status
}

/// The output folder the arguments name, as a message shows it.
fn shown(args: &[&str]) -> String {
    args.get(1).map_or_else(
        || default_out_dir().display().to_string(),
        |out| (*out).to_owned(),
    )
}

/// `target/dist-assets` in the repository (the workspace's root, this crate's parent).
fn default_out_dir() -> PathBuf {
    let xtask = Path::new(env!("CARGO_MANIFEST_DIR"));
    xtask
        .parent()
        .unwrap_or(xtask)
        .join("target")
        .join("dist-assets")
}

/// Writes the man pages to `out/man` and the completions to `out/completions`, each folder
/// emptied first so that a command removed from the program leaves no page behind. Returns
/// how many files were written.
///
/// # Errors
/// A folder that cannot be made or emptied, or a file that cannot be written, named.
fn dist_assets(out: &Path) -> Result<usize, String> {
    let man = out.join("man");
    let completions = out.join("completions");
    for dir in [&man, &completions] {
        if dir.exists() {
            std::fs::remove_dir_all(dir)
                .map_err(|e| format!("cannot empty {}: {e}", dir.display()))?;
        }
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
    Ok(pages + SHELLS.len())
}

/// Writes `refraction-explorer.1` and a `refraction-explorer-COMMAND.1` for each command into
/// `dir`, each page's footer naming the program's version. Returns how many pages were written.
///
/// # Errors
/// A page that cannot be written, named.
fn man_pages(dir: &Path) -> Result<usize, String> {
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
        assert!(written >= 6 + SHELLS.len(), "only {written} files");
    }

    /// A second run replaces the first's files rather than adding to them.
    #[test]
    fn dist_assets_start_from_empty_folders() {
        let out = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(out.path().join("man")).unwrap();
        std::fs::write(out.path().join("man/refraction-explorer-gone.1"), "old").unwrap();
        let first = dist_assets(out.path()).unwrap();
        assert!(
            !out.path().join("man/refraction-explorer-gone.1").exists(),
            "a stale page survived"
        );
        assert_eq!(dist_assets(out.path()).unwrap(), first, "the count changed");
    }
}

//! The `xtask` binary as `cargo xtask` runs it. (These tests also make `cargo test --workspace`
//! build the binary with the test run's features, so that `.ci/run` runs it without building
//! the program's dependencies a second time.)

use std::path::Path;
use std::process::Command;

fn xtask(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_xtask"))
        .args(args)
        .output()
        .expect("the xtask binary runs")
}

/// `dist-assets OUT_DIR` writes the pages, completions and icons there and says how many.
#[test]
fn dist_assets_writes_into_the_folder_given() {
    let out = tempfile::tempdir().unwrap();
    let run = xtask(&["dist-assets", out.path().to_str().unwrap()]);
    let said = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{said}");
    assert!(said.contains("wrote 17 files"), "{said}");
    for file in [
        "man/refraction-explorer.1",
        "man/refraction-explorer-solve.1",
        "man/refraction-explorer-check.1",
        "man/refraction-explorer-bench.1",
        "man/refraction-explorer-trace.1",
        "man/refraction-explorer-render.1",
        "man/refraction-explorer-lessons.1",
        "completions/refraction-explorer.bash",
        "completions/_refraction-explorer",
        "completions/refraction-explorer.fish",
        "icons/hicolor/48x48/apps/refraction-explorer.png",
    ] {
        assert!(Path::new(out.path()).join(file).is_file(), "no {file}");
    }
}

/// Anything else is refused with the usage and exit status 2.
#[test]
fn an_unknown_task_is_refused_with_the_usage() {
    for args in [&[][..], &["dist"], &["dist-assets", "a", "b"]] {
        let run = xtask(args);
        let said = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {said}");
        assert!(said.starts_with("usage: cargo xtask dist-assets"), "{said}");
    }
    let help = xtask(&["--help"]);
    assert!(help.status.success(), "--help");
}

//! Running the command end to end, for the CLI tests: on a file (`check --api`), or `render`
//! into a folder of the test's own.

use core::sync::atomic::{AtomicUsize, Ordering};
use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

/// Runs the binary with `args` on a file holding `input`.
pub fn run(args: &[&str], input: &str) -> Output {
    static RUNS: AtomicUsize = AtomicUsize::new(0);
    let name = format!(
        "api-{}-{}.log",
        std::process::id(),
        RUNS.fetch_add(1, Ordering::Relaxed)
    );
    let path = std::env::temp_dir().join(name);
    std::fs::write(&path, input).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .args(args)
        .arg(&path)
        .output()
        .unwrap();
    std::fs::remove_file(&path).unwrap();
    output
}

/// The JSON lines the command wrote.
pub fn answers(output: &Output) -> Vec<Value> {
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// A folder of this test run's own under the temporary directory, named `prefix-PID-name`.
pub fn folder(prefix: &str, name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("{prefix}-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

/// Runs `render` with `args`.
pub fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("render")
        .args(args)
        .output()
        .expect("the binary starts")
}

//! Running the command end to end, for the CLI tests: on a file (`check --api`), or `render`
//! into a folder of the test's own.

use core::sync::atomic::{AtomicUsize, Ordering};
use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

/// Runs the binary with `args` on a file holding `input`.
pub(crate) fn run(args: &[&str], input: &str) -> Output {
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
pub(crate) fn answers(output: &Output) -> Vec<Value> {
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// A folder of this test run's own under the temporary directory, named `prefix-PID-name`.
pub(crate) fn folder(prefix: &str, name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("{prefix}-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

/// Runs `render` with `args`.
pub(crate) fn render(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("render")
        .args(args)
        .output()
        .expect("the binary starts")
}

/// What `check` made of a log: its `--summary`, its answers, its stderr and exit status.
pub(crate) struct Checked {
    /// The `--summary` file's JSON.
    pub summary: Value,
    /// The answer lines.
    pub answers: Vec<Value>,
    /// The tally and the diagnosis.
    pub stderr: String,
    /// The exit status.
    pub status: i32,
}

/// Runs `check ARGS --summary FILE LOG` on a log holding `text`, in a folder named after
/// `prefix` and `name` (kept, with the log, in the folder `FAMILIES_KEEP` names if set).
pub(crate) fn check_log(prefix: &str, name: &str, args: &[&str], text: &str) -> Checked {
    let folder = folder(prefix, name);
    let (input, summary) = (folder.join("log.txt"), folder.join("s.json"));
    std::fs::write(&input, text).unwrap();
    if let Some(keep) = std::env::var_os("FAMILIES_KEEP") {
        std::fs::write(PathBuf::from(keep).join(format!("{name}.log")), text).unwrap();
    }
    let output = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("check")
        .args(args)
        .arg("--summary")
        .arg(&summary)
        .arg(&input)
        .output()
        .unwrap();
    let checked = Checked {
        summary: serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap(),
        answers: answers(&output),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
        status: output.status.code().unwrap_or(-1),
    };
    std::fs::remove_dir_all(&folder).unwrap();
    checked
}

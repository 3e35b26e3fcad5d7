//! `bench`: the accuracy-against-time table or JSON.

use std::io::{self, IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;

use refraction_bench::Config;

use super::render::Destination;
use super::{fail, output, output_error};

/// The size of the `--plot` image, in pixels.
const PLOT_SIZE: (u32, u32) = (1600, 1000);

/// The progress line on stderr while measuring; the first failed write is kept and reported
/// after the run (and stops the progress line).
struct Progress {
    shown: bool,
    failed: Option<io::Error>,
}

impl Progress {
    fn update(&mut self, fraction: f64) {
        if self.shown && self.failed.is_none() {
            let mut err = io::stderr().lock();
            let written =
                write!(err, "\rmeasuring... {:3.0}%", fraction * 100.0).and_then(|()| err.flush());
            self.failed = written.err();
        }
    }

    /// Ends the progress line; the error of a failed write, if any.
    fn finish(mut self) -> Option<io::Error> {
        if self.shown && self.failed.is_none() {
            self.failed = output::to_stderr("").err();
        }
        self.failed
    }
}

/// Runs the measurement, with a progress line on stderr when it is a terminal; prints the
/// table (or JSON), then draws the plot into `plot` if given. The plot's path is checked
/// before the measurement, so a bad one is found at once and a failed plot keeps the table.
pub fn run(quick: bool, json: bool, plot: Option<&Path>) -> ExitCode {
    if let Some(Err(message)) = plot.map(|p| Destination::check(p, "--plot", false)) {
        return fail("bench", &message);
    }
    let config = if quick { Config::QUICK } else { Config::FULL };
    let mut progress = Progress {
        shown: io::stderr().is_terminal(),
        failed: None,
    };
    let report = refraction_bench::run(&config, &mut |fraction| progress.update(fraction));
    if let Some(e) = progress.finish() {
        return fail(
            "bench",
            &format!("cannot write the progress to stderr: {e}"),
        );
    }
    let text = if json {
        match serde_json::to_string(&report) {
            Ok(text) => text + "\n",
            Err(e) => return fail("bench", &e),
        }
    } else {
        report.table()
    };
    if let Err(e) = output::to_stdout(text.as_bytes()) {
        return output_error("bench", &e);
    }
    let Some(path) = plot else {
        return ExitCode::SUCCESS;
    };
    let (width, height) = PLOT_SIZE;
    match refraction_render::export_accuracy_plot(&report, width, height, path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail("bench", &e),
    }
}

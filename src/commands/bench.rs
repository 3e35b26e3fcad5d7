//! `bench`: the accuracy-against-time table or JSON.

use std::io::{self, IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;

use refraction_bench::Config;

use super::fail;

/// The size of the `--plot` image, in pixels.
const PLOT_SIZE: (u32, u32) = (1600, 1000);

/// Runs the measurement, with a progress line on stderr when it is a terminal, and writes the
/// plot to `plot` if given.
pub fn run(quick: bool, json: bool, plot: Option<&Path>) -> ExitCode {
    let config = if quick { Config::QUICK } else { Config::FULL };
    let show_progress = io::stderr().is_terminal();
    let report = refraction_bench::run(&config, &mut |fraction| {
        if show_progress {
            eprint!("\rmeasuring... {:3.0}%", fraction * 100.0);
            // Progress on a terminal only: if stderr cannot be flushed the line shows late or
            // not at all, and the measurement and its report are still right.
            let _ = io::stderr().flush();
        }
    });
    if show_progress {
        eprintln!();
    }
    if let Some(path) = plot {
        let (width, height) = PLOT_SIZE;
        if let Err(e) = refraction_render::export_accuracy_plot(&report, width, height, path) {
            return fail("bench", &e);
        }
    }
    if json {
        match serde_json::to_string(&report) {
            Ok(text) => println!("{text}"),
            Err(e) => return fail("bench", &e),
        }
    } else {
        print!("{}", report.table());
    }
    ExitCode::SUCCESS
}

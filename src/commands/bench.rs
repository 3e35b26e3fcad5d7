//! `bench`: the accuracy-against-time table or JSON.

use std::path::Path;
use std::process::ExitCode;

use refraction_bench::Config;

use super::output::ProgressLine;
use super::render::{Destination, STILL};
use super::{fail, output, output_error};

/// The size of the `--plot` image, in pixels.
const PLOT_SIZE: (u32, u32) = (1600, 1000);

/// Runs the measurement, with a progress line on stderr when it is a terminal; prints the
/// table (or JSON), then draws the plot into `plot` if given. The plot's path (never a file
/// of another kind) is checked before the measurement, so a bad one is found at once and a failed plot keeps the table.
pub(crate) fn run(quick: bool, json: bool, plot: Option<&Path>) -> ExitCode {
    let checked = plot.map(|p| {
        Destination::check(p, "--plot", false, &STILL)?;
        let kind = super::inputs::kind_of(super::render::format_of(p, "--plot", &STILL)?);
        Ok::<_, super::render::RenderFailure>(super::inputs::refuse_other_kinds(
            [p],
            "--plot",
            kind,
        )?)
    });
    if let Some(Err(message)) = checked {
        return fail("bench", &message);
    }
    let config = if quick { Config::QUICK } else { Config::FULL };
    let mut progress = ProgressLine::on_terminal("measuring...");
    let report = refraction_bench::run(&config, &mut |fraction| progress.update(fraction));
    if let Some(e) = progress.finish() {
        return fail(
            "bench",
            &format!("cannot write the progress to stderr: {e}"),
        );
    }
    let text = if json {
        match serde_json::to_string(&report) {
            Ok(text) => format!("{text}\n"),
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
    let picture = refraction_render::Picture::AccuracyPlot(&report);
    match refraction_render::write(picture, (width, height), path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail("bench", &e),
    }
}

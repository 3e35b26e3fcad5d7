//! `trace`: a scene's counts, or its whole trace as JSON.

use std::io::{self, Write as _};
use std::process::ExitCode;

use refraction_scene::{Scene, TraceReport, catalogue};

use super::output::{printable, to_stderr};
use super::output_error;

/// Runs `trace`: the scene's summary or JSON on stdout, or the load error on stderr. Titles and
/// names from a scene file are printed with control characters escaped (in JSON, serde
/// escapes them).
pub(crate) fn run(scene: &str, json: bool, list: bool) -> ExitCode {
    let mut out = io::stdout().lock();
    let written = if list {
        catalogue()
            .iter()
            .try_for_each(|info| writeln!(out, "{:<20}{}", info.name, printable(&info.title)))
    } else {
        let scene = match Scene::load(scene) {
            Ok(scene) => scene,
            Err(e) => {
                let message = format!("refraction-explorer trace: {e}");
                // Exit status 1 says it failed even when stderr cannot say why.
                to_stderr(&printable(&message)).ok();
                return ExitCode::from(1);
            }
        };
        let traced = scene.trace();
        if json {
            serde_json::to_writer(&mut out, &TraceReport::new(&scene, &traced))
                .map_err(io::Error::from)
                .and_then(|()| writeln!(out))
        } else {
            writeln!(
                out,
                "{} ({})\n{}",
                printable(scene.title()),
                printable(scene.name()),
                traced.counts
            )
        }
    };
    written
        .and_then(|()| out.flush())
        .map_or_else(|e| output_error("trace", &e), |()| ExitCode::SUCCESS)
}

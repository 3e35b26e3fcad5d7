//! `bench`: the accuracy-against-time table or JSON.

use std::io::{self, IsTerminal, Write};
use std::process::ExitCode;

use refraction_explorer::bench::{self, Config};

use super::fail;

/// Runs the measurement, with a progress line on stderr when it is a terminal.
pub fn run(quick: bool, json: bool) -> ExitCode {
    let config = if quick { Config::QUICK } else { Config::FULL };
    let show_progress = io::stderr().is_terminal();
    let report = bench::run(&config, &mut |fraction| {
        if show_progress {
            eprint!("\rmeasuring... {:3.0}%", fraction * 100.0);
            let _ = io::stderr().flush();
        }
    });
    if show_progress {
        eprintln!();
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

//! The `refraction-explorer` command: subcommands for scripts.

use std::io::{self, ErrorKind};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Makes refraction visible: a trig-free refraction kernel and its four sign candidates.
#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Read refraction problems as JSON Lines on stdin; write one JSON answer per line.
    ///
    /// Input: {"w":[x,y,z],"n":[x,y,z],"mu_i":1,"mu_t":1.5} with optional
    /// "convention" ("along_ray" | "toward_origin") and "precision" ("f64" | "f32").
    /// Exit status 0 when every line was solved, 1 when any line was an error.
    Solve,
    /// Measure what accuracy costs in time: every kernel variant at f32 and f64, timed on
    /// this machine and compared with a double-double oracle.
    Bench {
        /// A shorter run (under 20 s on 2 cores); the default run is steadier.
        #[arg(long)]
        quick: bool,
        /// Print one JSON document instead of the table.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Some(Command::Solve) => {
            match refraction_explorer::solve::run(io::stdin().lock(), io::stdout().lock()) {
                Ok(true) => ExitCode::SUCCESS,
                Ok(false) => ExitCode::from(1),
                Err(e) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("refraction-explorer solve: {e}");
                    ExitCode::from(2)
                }
            }
        }
        Some(Command::Bench { quick, json }) => bench(quick, json),
        None => {
            use clap::CommandFactory;
            let _ = Cli::command().print_help();
            ExitCode::from(2)
        }
    }
}

fn bench(quick: bool, json: bool) -> ExitCode {
    use std::io::{IsTerminal, Write};
    let config = if quick {
        refraction_explorer::bench::Config::QUICK
    } else {
        refraction_explorer::bench::Config::FULL
    };
    let show_progress = io::stderr().is_terminal();
    let report = refraction_explorer::bench::run(&config, &mut |fraction| {
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
            Err(e) => {
                eprintln!("refraction-explorer bench: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        print!("{}", report.table());
    }
    ExitCode::SUCCESS
}

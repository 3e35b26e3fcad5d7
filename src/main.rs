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
        None => {
            use clap::CommandFactory;
            let _ = Cli::command().print_help();
            ExitCode::from(2)
        }
    }
}

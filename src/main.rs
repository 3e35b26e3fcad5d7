//! The `refraction-explorer` command: the explorer window by default, subcommands for scripts.

use std::io::{self, ErrorKind};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use refraction_explorer::diagram::ExplorerState;
use refraction_explorer::{render, state_file};

/// Makes refraction visible: a trig-free refraction kernel, its four sign candidates, and an
/// interactive explorer (opened when no subcommand is given).
#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Open the explorer on the problem in this JSON file (fields as for `solve`); without it
    /// the explorer reopens where it was last closed.
    #[arg(long, value_name = "FILE.json")]
    state: Option<PathBuf>,
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
    /// Draw the explorer's diagram into a PNG file, without a window.
    Render {
        /// The PNG file to write (replaced atomically).
        #[arg(long, value_name = "FILE.png")]
        out: PathBuf,
        /// Width in pixels.
        #[arg(long, default_value_t = render::DEFAULT_SIZE.0)]
        width: u32,
        /// Height in pixels.
        #[arg(long, default_value_t = render::DEFAULT_SIZE.1)]
        height: u32,
        /// The problem to draw, as JSON with the fields of `solve` (default: 40° from air into
        /// glass).
        #[arg(long, value_name = "FILE.json")]
        state: Option<PathBuf>,
    },
}

fn initial_state(path: Option<&Path>) -> Result<ExplorerState, String> {
    path.map_or_else(|| Ok(ExplorerState::default()), state_file::load)
}

fn fail(command: &str, message: &str) -> ExitCode {
    eprintln!("refraction-explorer{command}: {message}");
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Some(Command::Solve) => {
            match refraction_explorer::solve::run(io::stdin().lock(), io::stdout().lock()) {
                Ok(true) => ExitCode::SUCCESS,
                Ok(false) => ExitCode::from(1),
                Err(e) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
                Err(e) => fail(" solve", &e.to_string()),
            }
        }
        Some(Command::Bench { quick, json }) => bench(quick, json),
        Some(Command::Render {
            out,
            width,
            height,
            state,
        }) => match initial_state(state.as_deref())
            .and_then(|s| render::export(&s, width, height, &out).map_err(|e| e.to_string()))
        {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => fail(" render", &message),
        },
        None => match cli
            .state
            .as_deref()
            .map(state_file::load)
            .transpose()
            .and_then(|s| refraction_explorer::app::run(s).map_err(|e| e.to_string()))
        {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => fail("", &message),
        },
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

//! The `refraction-explorer` command: subcommands for scripts.

use std::io::{self, ErrorKind, Write};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use refraction_explorer::scene::{DEFAULT_SCENE, Report, Scene, catalogue};

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
    /// Trace a scene: a ray, beam or fan crossing interface after interface.
    ///
    /// Prints a summary and the counts of what the tracer computed; with --json, the ray paths
    /// (points, medium per segment, wavelength, intensity), every hit, the shapes' outlines,
    /// the world bounds and the counts.
    Trace {
        /// A built-in scene's name (see --list) or the path of a scene file (TOML).
        #[arg(default_value = DEFAULT_SCENE)]
        scene: String,
        /// Print the trace as one JSON object.
        #[arg(long)]
        json: bool,
        /// List the built-in scenes (name and title) and exit.
        #[arg(long)]
        list: bool,
    },
}

/// Runs `trace`: the scene's summary or JSON on stdout, or the load error on stderr.
fn trace(scene: &str, json: bool, list: bool) -> ExitCode {
    let mut out = io::stdout().lock();
    let written = if list {
        catalogue()
            .iter()
            .try_for_each(|info| writeln!(out, "{:<20}{}", info.name, info.title))
    } else {
        let scene = match Scene::load(scene) {
            Ok(scene) => scene,
            Err(e) => {
                eprintln!("refraction-explorer trace: {e}");
                return ExitCode::from(1);
            }
        };
        let traced = scene.trace();
        if json {
            serde_json::to_writer(&mut out, &Report::new(&scene, &traced))
                .map_err(io::Error::from)
                .and_then(|()| writeln!(out))
        } else {
            writeln!(
                out,
                "{} ({})\n{}",
                scene.title(),
                scene.name(),
                traced.counts
            )
        }
    };
    match written {
        Err(e) if e.kind() != ErrorKind::BrokenPipe => {
            eprintln!("refraction-explorer trace: {e}");
            ExitCode::from(2)
        }
        _ => ExitCode::SUCCESS,
    }
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
        Some(Command::Trace { scene, json, list }) => trace(&scene, json, list),
        None => {
            use clap::CommandFactory;
            let _ = Cli::command().print_help();
            ExitCode::from(2)
        }
    }
}

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
    /// Check the T your ray tracer produced: JSON Lines with the `solve` fields plus
    /// "t_yours" (an array, or a string such as "vec3(0.1, -0.9, 0)"), from FILE or stdin.
    ///
    /// Answers each line with "ok", "matches" (chosen, wrong_side, wrong_bend, reversed,
    /// total_internal_reflection or null) and "explanation"; a summary of the mistakes goes to
    /// stderr. Exit status 0 when every line is ok, 1 otherwise.
    Check {
        /// JSON Lines file to read (stdin when absent).
        file: Option<std::path::PathBuf>,
    },
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
        Some(Command::Bench { quick, json }) => bench(quick, json),
        Some(Command::Check { file }) => check(file.as_deref()),
        Some(Command::Trace { scene, json, list }) => trace(&scene, json, list),
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

fn check(file: Option<&std::path::Path>) -> ExitCode {
    use refraction_explorer::check::Match;
    use std::collections::BTreeMap;
    let input: Box<dyn io::BufRead> = match file {
        None => Box::new(io::stdin().lock()),
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => Box::new(io::BufReader::new(f)),
            Err(e) => {
                eprintln!(
                    "refraction-explorer check: cannot read {}: {e}",
                    path.display()
                );
                return ExitCode::from(2);
            }
        },
    };
    let mut tally: BTreeMap<&'static str, usize> = BTreeMap::new();
    let mut all_ok = true;
    let result = refraction_explorer::jsonl::answer_lines(input, io::stdout().lock(), |line| {
        let kind = match refraction_explorer::check::answer(line) {
            Ok((text, verdict)) => {
                all_ok &= verdict.ok;
                let kind = match (verdict.ok, verdict.matches) {
                    (true, _) => "ok",
                    (false, Some(Match::Chosen)) => "not unit length",
                    (false, Some(m)) => m.name(),
                    (false, None) => "matching no candidate",
                };
                (kind, Ok(text))
            }
            Err(e) => ("unreadable", Err(e)),
        };
        *tally.entry(kind.0).or_default() += 1;
        kind.1
    });
    match result {
        Ok(answered) => {
            let summary: Vec<String> = tally.iter().map(|(k, n)| format!("{n} {k}")).collect();
            eprintln!("check: {}", summary.join(", "));
            if answered && all_ok {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("refraction-explorer check: {e}");
            ExitCode::from(2)
        }
    }
}

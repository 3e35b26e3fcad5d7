//! The `refraction-explorer` command: the explorer window by default, subcommands for scripts.

// `println!` and `eprintln!` panic when a stream cannot be written: every write goes through
// `commands::output` and its error sets the exit status.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod commands;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use refraction_diagram::palette::Theme;
use refraction_explorer::app::View;
use refraction_i18n::Locale;
use refraction_scene::DEFAULT_SCENE;
use refraction_tools::api_check::Dialect;

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
    /// Open the explorer on a lesson deck at its first step: a built-in deck's name (see
    /// `lessons`) or a deck file (TOML). Page Down and Page Up step through it, R reveals a
    /// step's answer.
    #[arg(long, value_name = "NAME|FILE", conflicts_with = "state")]
    lesson: Option<String>,
    /// Open the explorer in presentation mode: full screen, everything larger, the side panels
    /// closed (F11 leaves it).
    #[arg(long)]
    present: bool,
    /// The explorer's view to open on (default: the one shown when it was last closed, or
    /// `one` with --state).
    #[arg(long, value_enum, value_name = "VIEW")]
    view: Option<ViewName>,
    /// The explorer's theme (default: the one chosen last time).
    #[arg(long, value_enum, value_name = "NAME")]
    theme: Option<ThemeName>,
    /// The language of the explorer and of the text `render` draws: en, de, es, fr, pt-BR or
    /// ru (default: the one chosen in the explorer last time, else the system's). The JSON of
    /// `solve` and `check` is the same in every language.
    #[arg(long, global = true, value_name = "CODE", value_parser = language)]
    lang: Option<Locale>,
}

/// The language `--lang` names.
fn language(code: &str) -> Result<Locale, String> {
    Locale::from_tag(code).ok_or_else(|| {
        let known: Vec<&str> = Locale::ALL.iter().map(|l| l.code()).collect();
        format!(
            "no translation for `{code}`: choose one of {}",
            known.join(", ")
        )
    })
}

/// The views as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum ViewName {
    /// One interface: drag W, N and μ.
    One,
    /// A traced scene.
    Scenes,
    /// Accuracy against time.
    Accuracy,
}

impl From<ViewName> for View {
    fn from(name: ViewName) -> Self {
        match name {
            ViewName::One => Self::Interface,
            ViewName::Scenes => Self::Scenes,
            ViewName::Accuracy => Self::Accuracy,
        }
    }
}

/// The themes as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum ThemeName {
    /// Soft media shading on white.
    Standard,
    /// Black on white, for a bright room.
    HighContrastLight,
    /// White on black, for a dark room.
    HighContrastDark,
}

impl From<ThemeName> for Theme {
    fn from(name: ThemeName) -> Self {
        match name {
            ThemeName::Standard => Self::Standard,
            ThemeName::HighContrastLight => Self::HighContrastLight,
            ThemeName::HighContrastDark => Self::HighContrastDark,
        }
    }
}

#[derive(Subcommand)]
#[expect(
    clippy::doc_markdown,
    reason = "clap prints these comments as the commands' help, where backticks would show"
)]
enum Command {
    /// Read refraction problems as JSON Lines on stdin; write one JSON answer per line.
    ///
    /// Input: {"w":[x,y,z],"n":[x,y,z],"mu_i":1,"mu_t":1.5} with optional
    /// "convention" ("along_ray" | "toward_origin") and "precision" ("f64" | "f32").
    /// Exit status 0 when every line was solved, 1 when any line was an error.
    Solve,
    /// Check the T your ray tracer produced, line by line and as a whole log: which mistake in
    /// your code explains the lines that are wrong, and its fix.
    ///
    /// Without --api, each line (JSON Lines from FILE or stdin, a --pattern log or --csv) has
    /// the `solve` fields "w", "n", "mu_i", "mu_t" (or "entering" with --inside and
    /// --outside), "t_yours" (your T: an array, a string such as "vec3(0.1, -0.9, 0)", or null
    /// where your code reported total internal reflection) and optionally "ratio" (the ratio
    /// your code used). With --api, each line is the call your code made in that API's own
    /// terms (glsl: I, N, eta, result; pbrt: wi, n, eta, returned, wt, etap; rtiow: uv, n,
    /// etai_over_etat, refracted, front_face; mitsuba: wi, n, eta, wo), with optional truth
    /// "from", "to", "travel", "entering".
    ///
    /// Answers each line with "ok", "matches" (chosen, wrong_side, wrong_bend, reversed,
    /// total_internal_reflection or null), "explanation" and "mistakes"; the tally and the
    /// diagnosis of the whole log go to stderr (and with --summary to a JSON file). Exit
    /// status 0 when every line is ok, 1 otherwise.
    Check {
        /// JSON Lines file to read (stdin when absent).
        file: Option<PathBuf>,
        /// Check calls of this API: glsl (or hlsl, wgsl, glm, glam), pbrt, rtiow, mitsuba.
        #[arg(long, value_name = "NAME", value_parser = commands::lines::parse_api)]
        api: Option<refraction_kernel::api::Api>,
        /// The index inside the object: with --outside, "entering" gives "from" and "to".
        #[arg(long, value_name = "X", requires = "outside", value_parser = commands::lines::parse_index)]
        inside: Option<f64>,
        /// The index outside the object.
        #[arg(long, value_name = "Y", requires = "inside", value_parser = commands::lines::parse_index)]
        outside: Option<f64>,
        /// The precision your code computes in, unless a line says (default: f32 for glsl,
        /// pbrt and mitsuba, f64 for rtiow and without --api).
        #[arg(long, value_name = "f32|f64", value_parser = commands::lines::parse_precision)]
        precision: Option<refraction_tools::solve::Precision>,
        /// Read printf-style log lines: each {field} takes a number or a vector as programs
        /// print it, {_} anything; lines that do not match are skipped and counted.
        #[arg(long, value_name = "PATTERN", conflicts_with = "csv")]
        pattern: Option<String>,
        /// Read CSV with a header line naming the fields.
        #[arg(long)]
        csv: bool,
        /// Also write the diagnosis of the whole log to this JSON file: {"lines", "judged",
        /// "ok", "skipped", "diagnosis": [{"code", "lines", "where", "fix"}, ...]}, the verdict
        /// first ("none" when nothing is wrong).
        #[arg(long, value_name = "FILE.json")]
        summary: Option<PathBuf>,
        /// With --pattern, answer a line that does not match with an error instead of skipping it.
        #[arg(long, requires = "pattern")]
        strict: bool,
        /// Consecutive lines with the same "path" are one ray's hits: after each path, a
        /// summary line {"path","hits","first_wrong","exit_ok","explanation"}.
        #[arg(long, requires = "api")]
        paths: bool,
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
        /// Also draw error against time per variant (log scales) into this PNG file (checked
        /// before the measurement starts).
        #[arg(long, value_name = "FILE.png")]
        plot: Option<PathBuf>,
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
    /// Draw the explorer's diagram, or a traced scene, into a PNG or SVG file, or an animation
    /// of the diagram into a GIF, or a lesson deck into a handout (PDF) or one SVG per step,
    /// without a window.
    Render(commands::render::RenderArgs),
    /// List the built-in lesson decks, one per line: NAME, TITLE and the number of steps,
    /// separated by tabs (the titles in the language of --lang).
    Lessons,
}

/// The command line, or the exit status after `--help`, `--version` or a usage error. A usage
/// error is one line, as every other error is: clap's first line, without its usage block.
fn parse() -> Result<Cli, ExitCode> {
    Cli::try_parse().map_err(|e| {
        use clap::error::ErrorKind;
        if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion)
            || e.exit_code() == 0
        {
            return match e.print() {
                Ok(()) => ExitCode::SUCCESS,
                Err(_) => ExitCode::from(2),
            };
        }
        // clap's message, up to its usage block, on one line.
        let rendered = e.render().to_string();
        let said: Vec<&str> = rendered
            .lines()
            .map(str::trim)
            .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
            .filter(|l| !l.is_empty() && !l.starts_with("tip:"))
            .collect();
        let said = said.join(" ");
        let said = said.strip_prefix("error: ").unwrap_or(&said);
        commands::fail("", &format!("{said} (--help lists the options)"))
    })
}

fn main() -> ExitCode {
    let cli = match parse() {
        Ok(cli) => cli,
        Err(status) => return status,
    };
    // Only what is drawn speaks the language: the JSON and messages of `solve`, `check`,
    // `trace` and `bench` are the same for every user.
    let draws = matches!(
        cli.command,
        None | Some(Command::Render(_) | Command::Lessons)
    );
    if let Some(language) = cli.lang.filter(|_| draws) {
        refraction_i18n::set_locale(language);
    }
    match cli.command {
        Some(Command::Solve) => commands::lines::solve(),
        Some(Command::Check {
            file,
            api,
            inside,
            outside,
            precision,
            pattern,
            csv,
            strict,
            paths,
            summary,
        }) => commands::lines::check(
            file.as_deref(),
            &refraction_tools::api_check::Options {
                dialect: api.map_or(Dialect::Physics, Dialect::Api),
                inside,
                outside,
                precision,
            },
            &commands::lines::Reading {
                pattern: pattern.as_deref(),
                csv,
                strict,
                paths,
                summary: summary.as_deref(),
            },
        ),
        Some(Command::Bench { quick, json, plot }) => {
            commands::bench::run(quick, json, plot.as_deref())
        }
        Some(Command::Trace { scene, json, list }) => commands::trace::run(&scene, json, list),
        Some(Command::Render(args)) => commands::render::run(&args),
        Some(Command::Lessons) => commands::lessons::list(),
        None => commands::render::explorer(&commands::render::Window {
            state: cli.state,
            lesson: cli.lesson,
            present: cli.present,
            view: cli.view.map(View::from),
            theme: cli.theme.map(Theme::from),
            language: cli.lang,
        }),
    }
}

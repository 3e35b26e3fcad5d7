//! The `refraction-explorer` command: the explorer window by default, subcommands for scripts.
//! The command line itself is defined in the library (`refraction_explorer::cli`), where the
//! man pages and completions are generated from too.

// `println!` and `eprintln!` panic when a stream cannot be written: every write goes through
// `commands::output` and its error sets the exit status.
#![deny(clippy::print_stdout, clippy::print_stderr)]

mod commands;

use std::process::ExitCode;

use clap::Parser as _;
use refraction_check::Dialect;
use refraction_diagram::palette::Theme;
use refraction_explorer::app::View;
use refraction_explorer::cli::{Cli, Command};

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
            replace,
            tests,
            convention,
            normal,
            renderer,
            suggest_pattern,
        }) => {
            let options = refraction_check::Options {
                dialect: api.map_or(Dialect::Physics, Dialect::Api),
                inside,
                outside,
                precision,
                convention,
                normal,
                renderer,
            };
            let reading = commands::lines::Reading {
                pattern: pattern.as_deref(),
                csv,
                strict,
                paths,
                summary: summary.as_deref(),
                replace,
                tests: tests.as_deref(),
            };
            if suggest_pattern {
                commands::lines::suggest_pattern(file.as_deref(), &options, &reading)
            } else {
                commands::lines::check(file.as_deref(), &options, &reading)
            }
        }
        Some(Command::Bench { quick, json, plot }) => {
            commands::bench::run(quick, json, plot.as_deref())
        }
        Some(Command::Trace { scene, json, list }) => commands::trace::run(&scene, json, list),
        Some(Command::Render(args)) => commands::render::run(&args),
        Some(Command::Lessons) => commands::lessons::list(),
        None => commands::window::open(&commands::window::Window {
            state: cli.state,
            lesson: cli.lesson,
            present: cli.present,
            view: cli.view.map(View::from),
            theme: cli.theme.map(Theme::from),
            language: cli.lang,
            web_base: cli.web_base,
        }),
    }
}

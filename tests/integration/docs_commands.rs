//! The commands of the README and the user guide, run as they are written, as rustdoc runs the
//! examples of its docs: every line of a `sh` code block that starts with `refraction-explorer` is
//! run (the built binary in its place) in a folder of its own where `docs/` is the
//! repository's, and must end with the exit status its `# exit N` comment gives (0 without
//! one). A command that opens the window is checked as far as it can be without a display:
//! its arguments parse, and the state file it names loads.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::cli;

const BIN: &str = env!("CARGO_BIN_EXE_refraction-explorer");

/// One command of a `sh` code block.
#[derive(Debug, PartialEq)]
struct Example {
    /// Where it is written: `docs/check.md:12`.
    place: String,
    /// The arguments after `refraction-explorer`.
    args: Vec<String>,
    /// The file after `<`, relative to the repository.
    stdin: Option<String>,
    /// The file after `>`.
    stdout: Option<String>,
    /// The exit status its comment gives.
    exit: i32,
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Splits a shell line into words: spaces separate, single and double quotes group, `#`
/// starts a comment. `None` for what this runner does not take (a pipe, `$`, a backslash).
fn words(line: &str) -> Option<(Vec<String>, String)> {
    let (mut words, mut word, mut quote, mut started) = (Vec::new(), String::new(), None, false);
    let mut chars = line.chars();
    while let Some(c) = chars.next() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => (quote, started) = (Some(c), true),
            (None, '#') => return Some((words, chars.collect())),
            (None, '|' | '$' | '\\' | '&' | ';' | '`') => return None,
            (None, c) if c.is_whitespace() => {
                if started {
                    words.push(core::mem::take(&mut word));
                }
                started = false;
            }
            (None, c) => {
                word.push(c);
                started = true;
            }
        }
    }
    if started {
        words.push(word);
    }
    (quote.is_none()).then_some((words, String::new()))
}

/// The example on `line`, or why it cannot be run.
fn example(place: String, line: &str) -> Result<Example, String> {
    let (words, comment) = words(line).ok_or_else(|| format!("{place}: unsupported shell"))?;
    let exit = match comment.trim().strip_prefix("exit ") {
        Some(code) => code
            .parse()
            .map_err(|e| format!("{place}: bad `# exit`: {e}"))?,
        None => 0,
    };
    let mut example = Example {
        place,
        args: Vec::new(),
        stdin: None,
        stdout: None,
        exit,
    };
    let mut rest = words.into_iter().skip(1);
    while let Some(word) = rest.next() {
        match word.as_str() {
            "<" => example.stdin = rest.next(),
            ">" => example.stdout = rest.next(),
            _ => example.args.push(word),
        }
    }
    Ok(example)
}

/// Every `refraction-explorer` line of the `sh` code blocks of `file`.
fn examples_in(file: &Path) -> Vec<Result<Example, String>> {
    let text = std::fs::read_to_string(file).unwrap();
    let name = file.strip_prefix(root()).unwrap_or(file).display();
    let mut in_sh = false;
    let mut found = Vec::new();
    for (i, line) in text.lines().enumerate() {
        match line.trim_start() {
            "```sh" => in_sh = true,
            "```" => in_sh = false,
            command if in_sh && command.starts_with("refraction-explorer") => {
                found.push(example(format!("{name}:{}", i + 1), command));
            }
            _ => {}
        }
    }
    found
}

/// The subcommands, as `--help` lists them.
fn subcommands() -> Vec<String> {
    let help = Command::new(BIN).arg("--help").output().unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_owned)
        .collect()
}

/// Runs `example` in `folder` (holding a link to the repository's `docs/`); `None` when it
/// ended as its comment says.
fn run(example: &Example, folder: &Path, subcommands: &[String]) -> Option<String> {
    let opens_window = !example.args.iter().any(|a| subcommands.contains(a));
    let mut command = Command::new(BIN);
    command.args(&example.args).current_dir(folder);
    if opens_window {
        // No display here: the arguments are parsed (clap stops at --help only once all the
        // arguments before it have been read) and the state file loaded.
        command.arg("--help");
        if let Some(state) = example.args.iter().skip_while(|a| *a != "--state").nth(1)
            && let Err(e) = refraction_tools::open_state_file(&folder.join(state))
        {
            return Some(format!("{}: {e}", example.place));
        }
        // A deck by its name, or a file from the example's folder, loads as the window would.
        if let Some(lesson) = example.args.iter().skip_while(|a| *a != "--lesson").nth(1) {
            let built_in = refraction_deck::builtin::names().contains(&lesson.as_str());
            let path = folder.join(lesson);
            let named = if built_in {
                lesson.clone()
            } else {
                path.display().to_string()
            };
            if let Err(e) = refraction_deck::Deck::load(&named) {
                return Some(format!("{}: {e}", example.place));
            }
        }
    }
    let open = |name: &Option<String>, write: bool| -> Stdio {
        name.as_ref().map_or_else(Stdio::null, |file| {
            let path = folder.join(file);
            let file = if write {
                std::fs::File::create(path)
            } else {
                std::fs::File::open(path)
            };
            file.map_or_else(|_| Stdio::null(), Stdio::from)
        })
    };
    command
        .stdin(open(&example.stdin, false))
        .stdout(open(&example.stdout, true));
    let output = command.output().unwrap();
    let code = output.status.code().unwrap_or(-1);
    let expected = if opens_window { 0 } else { example.exit };
    (code != expected).then(|| {
        format!(
            "{}: exit {code}, not {expected}: {}",
            example.place,
            String::from_utf8_lossy(&output.stderr).trim()
        )
    })
}

/// Runs the examples of `page` (relative to the repository) and says what failed.
fn run_page(page: &str) {
    let subcommands = subcommands();
    assert!(
        subcommands.contains(&"render".to_owned()),
        "{subcommands:?}"
    );
    let folder = cli::folder("docs", &page.replace(['/', '.'], "-"));
    let docs: PathBuf = folder.join("docs");
    if !docs.exists() {
        std::os::unix::fs::symlink(root().join("docs"), &docs).unwrap();
    }
    let examples = examples_in(&root().join(page));
    assert!(!examples.is_empty(), "{page} has no commands");
    let problems: Vec<String> = examples
        .iter()
        .filter_map(|example| match example {
            Ok(example) => run(example, &folder, &subcommands),
            Err(why) => Some(why.clone()),
        })
        .collect();
    std::fs::remove_dir_all(&folder).unwrap();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_readmes_commands_run_as_written() {
    run_page("README.md");
}

#[test]
fn the_classroom_guides_commands_run_as_written() {
    run_page("docs/classroom.md");
}

#[test]
fn the_check_guides_commands_run_as_written() {
    run_page("docs/check.md");
}

#[test]
fn the_solve_and_scene_guides_commands_run_as_written() {
    run_page("docs/solve.md");
    run_page("docs/scenes.md");
}

#[test]
fn the_deck_guides_commands_run_as_written() {
    run_page("docs/decks.md");
}

#[test]
fn the_accuracy_guides_commands_run_as_written() {
    run_page("docs/accuracy.md");
}

#[test]
fn the_install_guides_commands_run_as_written() {
    run_page("docs/install.md");
}

#[test]
fn the_web_guides_commands_run_as_written() {
    run_page("docs/web.md");
}

#[test]
fn every_page_of_the_guide_is_run() {
    let mut pages: Vec<String> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .filter_map(|entry| {
            let name = entry.ok()?.file_name().into_string().ok()?;
            let page = root().join("docs").join(&name);
            let markdown = Path::new(&name)
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("md"));
            (markdown && !examples_in(&page).is_empty()).then_some(name)
        })
        .collect();
    pages.sort();
    assert_eq!(
        pages,
        [
            "accuracy.md",
            "check.md",
            "classroom.md",
            "decks.md",
            "install.md",
            "scenes.md",
            "solve.md",
            "web.md"
        ],
        "a page with commands needs its test above"
    );
}

#[test]
fn the_runner_reads_shell_as_the_docs_write_it_and_catches_what_fails() {
    let line = "refraction-explorer check --pattern 'a {b} # c' < docs/in.log > out.txt  # exit 1";
    assert_eq!(
        example("x:1".into(), line),
        Ok(Example {
            place: "x:1".into(),
            args: vec!["check".into(), "--pattern".into(), "a {b} # c".into()],
            stdin: Some("docs/in.log".into()),
            stdout: Some("out.txt".into()),
            exit: 1,
        })
    );
    assert!(example("x:2".into(), "refraction-explorer solve | jq").is_err());
    // A window command with a bad value, and a command whose status differs, are caught.
    let folder = cli::folder("docs", "runner");
    let subcommands = subcommands();
    for line in [
        "refraction-explorer --theme purple",
        "refraction-explorer render --out x.jpg",
        "refraction-explorer --state docs/none.json",
    ] {
        let example = example("x:3".into(), line).unwrap();
        assert!(
            run(&example, &folder, &subcommands).is_some(),
            "{line} passed"
        );
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

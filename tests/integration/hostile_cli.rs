//! The commands under careless or hostile use: unwritable and closed streams, an over-long
//! line, huge files, control characters from files, bad output paths found before the work.

use core::time::Duration;
use std::fs::{self, File};
use std::io::{BufRead as _, BufReader, Write as _};
use std::os::unix::fs::FileTypeExt as _;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::Instant;

const BIN: &str = env!("CARGO_BIN_EXE_refraction-explorer");
const GOOD: &str = r#"{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}"#;
/// The exit status of a closed pipe (see `commands::CLOSED_PIPE`).
const CLOSED_PIPE: i32 = 141;

fn folder(name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("hostile-cli-{}-{name}", std::process::id()));
    fs::create_dir_all(&folder).unwrap();
    folder
}

fn dev_full() -> Stdio {
    Stdio::from(File::options().write(true).open("/dev/full").unwrap())
}

/// Runs the binary with `args` and `stdin`, stdout and stderr captured.
fn run(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(BIN)
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    let text = stdin.to_owned();
    let writer = std::thread::spawn(move || input.write_all(text.as_bytes()));
    let output = child.wait_with_output().unwrap();
    writer.join().unwrap().unwrap();
    output
}

/// Runs `sh -c 'exec BIN ARGS >&-'`: the binary with stdout closed.
fn with_stdout_closed(args: &str, stdin: &str) -> Output {
    let mut child = Command::new("sh")
        .arg("-c")
        .arg(format!("exec '{BIN}' {args} >&-"))
        .stdin(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    // The command may refuse to run before reading: a closed pipe here is expected.
    let _ = input.write_all(stdin.as_bytes());
    drop(input);
    child.wait_with_output().unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

#[test]
fn output_discarded_by_another_program_is_written_and_a_full_stdout_reported() {
    // Issue 23: Python's subprocess.DEVNULL and Go's exec open /dev/null read-write, as the
    // runtime does for a stdout closed with >&-: the output goes there, it is not refused.
    let check =
        r#"{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"t_yours":[0.4,-0.9165151,0]}"#;
    for (args, stdin) in [("solve", GOOD), ("trace --json", ""), ("check", check)] {
        let output = with_stdout_closed(args, stdin);
        assert_eq!(output.status.code(), Some(0), "{args}: {output:?}");
        let discarded = Command::new(BIN)
            .args(args.split(' '))
            .stdin(Stdio::piped())
            .stdout(
                fs::OpenOptions::new()
                    .read(true)
                    .write(true)
                    .open("/dev/null")
                    .unwrap(),
            )
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut discarded = discarded;
        let mut input = discarded.stdin.take().unwrap();
        input.write_all(stdin.as_bytes()).unwrap();
        drop(input);
        let output = discarded.wait_with_output().unwrap();
        assert_eq!(output.status.code(), Some(0), "{args}: {output:?}");
    }
    let lines = file_with_lines("full", 3);
    let output = Command::new(BIN)
        .arg("solve")
        .stdin(Stdio::from(File::open(&lines).unwrap()))
        .stdout(dev_full())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("No space left on device"),
        "{output:?}"
    );
    let help = Command::new(BIN).arg("--help").stdout(dev_full()).status();
    assert_eq!(help.unwrap().code(), Some(2));
    fs::remove_dir_all(lines.parent().unwrap()).unwrap();
}

/// A file of `count` `check` lines, all of them wrong (T on the wrong side).
fn file_with_lines(name: &str, count: usize) -> PathBuf {
    let path = folder(name).join("lines.jsonl");
    let line = r#"{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"t_yours":[0.4,0.9165,0]}"#;
    fs::write(&path, format!("{line}\n").repeat(count)).unwrap();
    path
}

#[test]
fn check_and_trace_with_stderr_full_exit_non_zero_without_panicking() {
    let lines = file_with_lines("stderr-full", 2);
    let check = Command::new(BIN)
        .arg("check")
        .arg(&lines)
        .stdout(Stdio::null())
        .stderr(dev_full())
        .status()
        .unwrap();
    assert_eq!(check.code(), Some(2), "the summary could not be written");
    let trace = Command::new(BIN)
        .args(["trace", "no-such-scene"])
        .stderr(dev_full())
        .status()
        .unwrap();
    assert_eq!(trace.code(), Some(1));
    fs::remove_dir_all(lines.parent().unwrap()).unwrap();
}

#[test]
fn a_closed_pipe_after_some_output_is_not_success() {
    let lines = file_with_lines("pipe", 20_000);
    for command in ["check", "solve"] {
        let mut child = Command::new(BIN)
            .arg(command)
            .stdin(Stdio::from(File::open(&lines).unwrap()))
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // As `| head -1` does: read one line, then close the pipe.
        let mut first = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut first)
            .unwrap();
        assert!(first.starts_with('{'), "{first}");
        let output = child.wait_with_output().unwrap();
        assert_eq!(output.status.code(), Some(CLOSED_PIPE), "{command}");
        assert!(!stderr(&output).contains("panicked"), "{command}");
    }
    fs::remove_dir_all(lines.parent().unwrap()).unwrap();
}

#[test]
fn check_of_a_directory_names_it() {
    let folder = folder("directory");
    let output = run(&["check", folder.to_str().unwrap()], "");
    assert_eq!(output.status.code(), Some(2));
    let message = stderr(&output);
    assert!(
        message.contains(&format!("cannot read {}", folder.display())),
        "{message}"
    );
    fs::remove_dir_all(&folder).unwrap();
}

/// The peak resident memory of process `pid` in KiB (`VmHWM`).
fn peak_memory_kib(pid: u32) -> u64 {
    let status = fs::read_to_string(format!("/proc/{pid}/status")).unwrap();
    let line = status.lines().find(|l| l.starts_with("VmHWM:")).unwrap();
    line.split_whitespace().nth(1).unwrap().parse().unwrap()
}

#[test]
fn an_over_long_line_is_answered_without_growing_memory_and_the_next_one_solved() {
    let mut child = Command::new(BIN)
        .arg("solve")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    let output = BufReader::new(child.stdout.take().unwrap());
    let (lines, answers) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in output.lines() {
            // The test may have stopped listening: nothing to do then.
            let _ = lines.send(line.unwrap());
        }
    });
    // 64 MiB of an ignored array and no newline, as a generator that never ends would send.
    input.write_all(&GOOD.as_bytes()[..GOOD.len() - 1]).unwrap();
    input.write_all(br#","junk":["#).unwrap();
    let chunk = "0,".repeat(1 << 19);
    for _ in 0..64 {
        input.write_all(chunk.as_bytes()).unwrap();
    }
    // The error is written as soon as the line passes the cap, before its end.
    let first = answers
        .recv_timeout(Duration::from_secs(30))
        .expect("an answer while the line is still coming");
    assert!(first.contains("line 1 is longer than 1 MiB"), "{first}");
    let peak = peak_memory_kib(child.id());
    input
        .write_all(format!("0]}}\n{GOOD}\n").as_bytes())
        .unwrap();
    drop(input);
    assert_eq!(child.wait().unwrap().code(), Some(1));
    let rest: Vec<String> = answers.iter().collect();
    assert!(
        rest.len() == 1 && rest[0].starts_with(r#"{"t":"#),
        "{rest:?}"
    );
    assert!(
        peak < 48 * 1024,
        "peak memory {peak} KiB after a 64 MiB line"
    );
}

#[test]
fn trace_escapes_control_characters_from_files() {
    let folder = folder("escapes");
    let scene = folder.join("evil.toml");
    fs::write(
        &scene,
        "title = \"Evil\\u001B[31mred\\u0007\\nline\"\n[source]\nkind = \"ray\"\n\
         origin = [0, 0]\ndirection = [1, 0]\n",
    )
    .unwrap();
    let output = run(&["trace", scene.to_str().unwrap()], "");
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(
        text.starts_with("Evil\\u{1b}[31mred\\u{7}\\nline (evil)\n"),
        "{text}"
    );
    let missing = folder.join("no\u{1b}[2Jfile.toml");
    let output = run(&["trace", missing.to_str().unwrap()], "");
    let message = stderr(&output);
    assert!(!message.contains('\u{1b}') && message.contains("no\\u{1b}[2Jfile.toml"));
    assert_eq!(message.lines().count(), 1, "{message}");
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn huge_scene_and_state_files_are_refused_naming_them() {
    let folder = folder("huge");
    let scene = folder.join("huge.toml");
    fs::write(&scene, format!("# {}\n", "x".repeat(2 << 20))).unwrap();
    let output = run(&["trace", scene.to_str().unwrap()], "");
    let message = stderr(&output);
    assert!(
        message.contains("huge.toml") && message.contains("larger than 1 MiB"),
        "{message}"
    );
    let out = folder.join("x.png");
    let output = run(
        &[
            "render",
            "--out",
            out.to_str().unwrap(),
            "--state",
            "/dev/zero",
        ],
        "",
    );
    let message = stderr(&output);
    assert!(
        message.contains("/dev/zero") && message.contains("larger than 1 MiB"),
        "{message}"
    );
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn render_writes_to_stdout_with_a_dash_and_refuses_other_formats() {
    let output = run(
        &["render", "--out", "-", "--width", "320", "--height", "200"],
        "",
    );
    assert!(output.status.success(), "{output:?}");
    let png = tiny_skia::Pixmap::decode_png(&output.stdout).unwrap();
    assert_eq!((png.width(), png.height()), (320, 200));
    assert!(!PathBuf::from("-").exists());
    let folder = folder("formats");
    let jpg = folder.join("x.JPG");
    let output = run(&["render", "--out", jpg.to_str().unwrap()], "");
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("it writes PNG (.png)"),
        "{output:?}"
    );
    assert_eq!(fs::read_dir(&folder).unwrap().count(), 0);
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn render_checks_the_output_path_and_size_before_loading_or_tracing() {
    let output = run(
        &[
            "render",
            "no-such-scene",
            "--out",
            "/nonexistent-folder/x.png",
        ],
        "",
    );
    let message = stderr(&output);
    assert!(
        message.contains("/nonexistent-folder") && !message.contains("no-such-scene"),
        "{message}"
    );
    let output = run(
        &["render", "no-such-scene", "--out", "-", "--width", "9"],
        "",
    );
    assert!(stderr(&output).contains("9×1080"), "{output:?}");
}

#[test]
fn render_writes_into_a_fifo_and_refuses_a_link_to_a_file() {
    let folder = folder("special");
    let fifo = folder.join("pipe");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || fs::read(fifo).unwrap())
    };
    let output = run(&["render", "--out", fifo.to_str().unwrap()], "");
    assert!(output.status.success(), "{output:?}");
    assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    assert!(tiny_skia::Pixmap::decode_png(&reader.join().unwrap()).is_ok());
    let target = folder.join("target.png");
    fs::write(&target, b"old").unwrap();
    let link = folder.join("link.png");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    let output = run(&["render", "--out", link.to_str().unwrap()], "");
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).contains("symbolic link"), "{output:?}");
    assert_eq!(fs::read(&target).unwrap(), b"old");
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn bench_finds_a_bad_plot_path_before_measuring() {
    let started = Instant::now();
    let output = run(&["bench", "--plot", "/nonexistent-folder/plot.png"], "");
    // The full measurement takes minutes in a test build; the check takes milliseconds.
    assert!(started.elapsed() < Duration::from_secs(10), "{output:?}");
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("/nonexistent-folder"),
        "{output:?}"
    );
    let output = run(&["bench", "--plot", "plot.gif"], "");
    assert!(stderr(&output).contains("`.gif`"), "{output:?}");
}

#[test]
fn bench_to_a_full_disk_exits_non_zero_without_panicking() {
    let output = Command::new(BIN)
        .args(["bench", "--quick"])
        .stdout(dev_full())
        .stderr(Stdio::piped())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2), "{output:?}");
    assert!(stderr(&output).contains("No space left on device"));
}

#[test]
fn a_usage_error_is_one_line_as_every_other_error_is() {
    // Issue 23: clap's usage errors took three lines (the error, its usage block, a tip).
    for args in [
        &["solve", "--bogus"][..],
        &["check", "--api"],
        &["nonsense"],
        &["render", "--size", "wide", "--out", "x.png"],
    ] {
        let output = run(args, "");
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        let said = stderr(&output);
        assert_eq!(said.lines().count(), 1, "{args:?}: {said}");
        assert!(
            said.starts_with("refraction-explorer: ") && said.contains("--help lists the options"),
            "{args:?}: {said}"
        );
        assert!(!said.contains("Usage:"), "{args:?}: {said}");
    }
    let help = run(&["solve", "--help"], "");
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("Usage:"));
}

#[test]
fn a_message_quoting_a_megabyte_of_input_is_cut_to_a_few_hundred_characters() {
    // Issue 23: an error echoed up to about 1 MB of the line it refused.
    let line = format!("{{\"w\":\"{}\"}}\n", "a".repeat(900_000));
    let output = run(&["check"], &line);
    let answer = String::from_utf8_lossy(&output.stdout);
    assert!(answer.len() < 1_000, "{} bytes", answer.len());
    assert!(answer.contains("characters left out"), "{answer}");
    let path = folder("long-name").join(format!("{}.png", "n".repeat(5_000)));
    let output = run(&["render", "--out", &path.display().to_string()], "");
    assert_eq!(output.status.code(), Some(2));
    assert!(stderr(&output).len() < 1_000, "{}", stderr(&output));
}

#[test]
fn summary_never_replaces_the_log_it_reads_nor_a_file_of_another_kind() {
    // Issue 31: `--summary mylog.jsonl mylog.jsonl` (or `< mylog.jsonl`) replaced the log.
    let folder = folder("summary-targets");
    let log = folder.join("mylog.jsonl");
    let line = r#"{"I":[0.6,-0.8,0],"N":[0,1,0],"eta":0.6666667,"result":[0.4,-0.916515,0],"from":1,"to":1.5}"#;
    fs::write(&log, format!("{line}\n")).unwrap();
    let (log_arg, dir) = (log.to_str().unwrap(), folder.to_str().unwrap());
    let by_name = run(
        &["check", "--api", "glsl", "--summary", log_arg, log_arg],
        "",
    );
    assert_eq!(by_name.status.code(), Some(2), "{by_name:?}");
    assert!(
        stderr(&by_name).contains("it is the log being read"),
        "{by_name:?}"
    );
    let piped = Command::new(BIN)
        .args(["check", "--api", "glsl", "--replace", "--summary", log_arg])
        .stdin(File::open(&log).unwrap())
        .output()
        .unwrap();
    assert_eq!(piped.status.code(), Some(2), "{piped:?}");
    assert!(stderr(&piped).contains("(standard input)"), "{piped:?}");
    assert_eq!(fs::read_to_string(&log).unwrap(), format!("{line}\n"));
    // A file of another kind is refused unless --replace says so; a summary is replaced.
    let notes = folder.join("notes.txt");
    fs::write(&notes, "my notes\n").unwrap();
    let notes_arg = notes.to_str().unwrap();
    let refused = run(
        &["check", "--api", "glsl", "--summary", notes_arg, log_arg],
        "",
    );
    assert_eq!(refused.status.code(), Some(2), "{refused:?}");
    assert!(stderr(&refused).contains("add --replace"), "{refused:?}");
    assert_eq!(fs::read_to_string(&notes).unwrap(), "my notes\n");
    let replaced = run(
        &[
            "check",
            "--api",
            "glsl",
            "--replace",
            "--summary",
            notes_arg,
            log_arg,
        ],
        "",
    );
    assert_eq!(replaced.status.code(), Some(0), "{replaced:?}");
    let again = run(
        &["check", "--api", "glsl", "--summary", notes_arg, log_arg],
        "",
    );
    assert_eq!(
        again.status.code(),
        Some(0),
        "a summary replaces a summary: {again:?}"
    );
    assert!(refraction_check::looks_like_summary(
        &fs::read(&notes).unwrap()
    ));
    // One message for a folder, naming it once.
    let folder_refused = run(&["check", "--api", "glsl", "--summary", dir, log_arg], "");
    let said = stderr(&folder_refused);
    assert_eq!(said.matches(dir).count(), 1, "{said}");
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn check_that_judged_no_line_exits_with_its_own_status() {
    // Issue 31: a CI job's `check` passed on a pattern's typo.
    const NOTHING_JUDGED: i32 = 3;
    let line = r#"{"I":[0.6,-0.8,0],"N":[0,1,0],"eta":0.6666667,"result":[0.4,-0.916515,0],"from":1,"to":1.5}"#;
    let judged = run(&["check", "--api", "glsl"], line);
    assert_eq!(judged.status.code(), Some(0), "{judged:?}");
    // Issue 34: right by GLSL's own rules, but nothing says which ratio is right: not a pass.
    let unchecked_line = line.replace(r#","from":1,"to":1.5"#, "");
    let unchecked = run(&["check", "--api", "glsl"], &unchecked_line);
    assert_eq!(unchecked.status.code(), Some(4), "{unchecked:?}");
    for (args, input) in [
        (vec!["check", "--api", "glsl"], ""),
        (vec!["check", "--api", "glsl"], "\n  \n\n"),
        (vec!["check", "--api", "glsl", "--csv"], "I,N,eta,result\n"),
        (
            vec![
                "check",
                "--api",
                "glsl",
                "--pattern",
                "I={I} N={N} eta={eta} r={result}",
            ],
            "I=1 2 3 Nope\n",
        ),
        (vec!["check"], ""),
    ] {
        let output = run(&args, input);
        assert_eq!(
            output.status.code(),
            Some(NOTHING_JUDGED),
            "{args:?} {input:?}: {output:?}"
        );
        assert!(stderr(&output).contains("No line was judged"), "{output:?}");
    }
}

/// A one-step deck file's text (the step's scene `scene`, if any).
fn deck_text(title: &str, scene: Option<&str>) -> String {
    let scene = scene.map_or_else(String::new, |s| {
        format!("view = \"scenes\"\nscene = \"{s}\"\n")
    });
    format!(
        "[deck]\nversion = 1\ntitle = \"{title}\"\n\n[[step]]\ntitle = \"One\"\n{scene}\
         w = [0.6, -0.8, 0]\nn = [0, 1, 0]\nmu_i = 1\nmu_t = 1.5\n"
    )
}

#[test]
fn render_never_writes_over_a_file_it_reads_under_any_name() {
    // Issue 40: `render --lesson deck.pdf --out deck.pdf` replaced the deck with the handout.
    let folder = folder("output-is-input");
    let deck = folder.join("deck.pdf");
    let text = deck_text("Mine", None);
    fs::write(&deck, &text).unwrap();
    fs::hard_link(&deck, folder.join("alias.pdf")).unwrap();
    let state = folder.join("state.svg");
    fs::write(&state, GOOD).unwrap();
    let scene = folder.join("step-01.svg");
    fs::write(
        &scene,
        "title = \"Ray\"\n[source]\nkind = \"ray\"\norigin = [0, 0]\ndirection = [1, 0]\n",
    )
    .unwrap();
    let scene_deck = folder.join("scenes.toml");
    fs::write(&scene_deck, deck_text("Scenes", Some("step-01.svg"))).unwrap();
    let path = |name: &str| folder.join(name).display().to_string();
    let (deck_arg, state_arg) = (path("deck.pdf"), path("state.svg"));
    for (args, stdin) in [
        (
            vec!["render", "--lesson", &deck_arg, "--out", &deck_arg],
            None,
        ),
        (
            vec!["render", "--lesson", &deck_arg, "--out", &path("alias.pdf")],
            None,
        ),
        (
            vec!["render", "--lesson", "/dev/stdin", "--out", &deck_arg],
            Some(&deck),
        ),
        (
            vec![
                "render",
                "--lesson",
                &path("scenes.toml"),
                "--out",
                &path(""),
            ],
            None,
        ),
        (
            vec!["render", "--state", &state_arg, "--out", &state_arg],
            None,
        ),
        (
            vec![
                "render",
                &path("step-01.svg"),
                "--out",
                &path("step-01.svg"),
            ],
            None,
        ),
    ] {
        let mut command = Command::new(BIN);
        command.args(&args);
        if let Some(stdin) = stdin {
            command.stdin(File::open(stdin).unwrap());
        }
        let output = command.output().unwrap();
        assert_eq!(output.status.code(), Some(2), "{args:?}: {output:?}");
        let said = stderr(&output);
        assert!(
            said.contains("being read") && said.contains("nothing was written"),
            "{args:?}: {said}"
        );
    }
    let appended = Command::new(BIN)
        .args(["render", "--state", &state_arg, "--out", "-"])
        .stdout(File::options().append(true).open(&state).unwrap())
        .output()
        .unwrap();
    assert_eq!(appended.status.code(), Some(2), "{appended:?}");
    assert_eq!(fs::read_to_string(&deck).unwrap(), text);
    assert_eq!(fs::read_to_string(&state).unwrap(), GOOD);
    assert!(fs::read_to_string(&scene).unwrap().starts_with("title"));
    let handout = path("handout.pdf");
    let output = run(&["render", "--lesson", &deck_arg, "--out", &handout], "");
    assert!(
        output.status.success(),
        "another name is written: {output:?}"
    );
    fs::remove_dir_all(&folder).unwrap();
}

/// Whether `program` runs here.
fn installed(program: &str) -> bool {
    Command::new(program)
        .arg("-v")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok()
}

/// The QR codes `zbarimg` reads on the PNG at `path`, one text each.
fn scanned(path: &std::path::Path) -> Vec<String> {
    let output = Command::new("zbarimg")
        .args(["--quiet", "--raw", "-Sdisable", "-Sqrcode.enable"])
        .arg(path)
        .output()
        .unwrap();
    String::from_utf8(output.stdout)
        .unwrap()
        .lines()
        .map(str::to_owned)
        .collect()
}

#[test]
#[expect(clippy::print_stderr, reason = "a skipped run says why")]
fn every_qr_code_of_a_handout_scans_at_150_dpi_and_its_link_is_printed_whole() {
    // Issue 40: a long link's code decoded only at 600 dpi, a longer one was left off, and
    // the printed link was cut with "…".
    let required = std::env::var("REFRACTION_QR_TESTS").is_ok_and(|v| v == "1");
    if !(installed("pdftoppm") && installed("zbarimg")) {
        assert!(
            !required,
            "REFRACTION_QR_TESTS=1 but pdftoppm or zbarimg is not installed"
        );
        eprintln!("skipped: apt-get install poppler-utils zbar-tools to scan the QR codes");
        return;
    }
    let folder = folder("qr-scan");
    let deck = folder.join("own.toml");
    fs::write(&deck, deck_text("Own", None)).unwrap();
    // The longest address accepted: a state's link is then about 450 bytes.
    let base = format!("https://school.example/{}/", "a".repeat(276));
    assert_eq!(base.len(), refraction_tools::link::MAX_WEB_BASE_BYTES);
    for (lesson, steps) in [("snell", 5), (deck.to_str().unwrap(), 1)] {
        let pdf = folder.join("handout.pdf");
        let output = run(
            &[
                "render",
                "--lesson",
                lesson,
                "--web-base",
                &base,
                "--out",
                pdf.to_str().unwrap(),
            ],
            "",
        );
        assert!(output.status.success(), "{output:?}");
        let prefix = folder.join("page");
        let rendered = Command::new("pdftoppm")
            .args(["-r", "150", "-png"])
            .arg(&pdf)
            .arg(&prefix)
            .status()
            .unwrap();
        assert!(rendered.success());
        let mut pages: Vec<PathBuf> = fs::read_dir(&folder)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "png"))
            .collect();
        pages.sort();
        assert_eq!(pages.len(), steps, "{lesson}");
        let texts = pdf_extract::extract_text_from_mem_by_pages(&fs::read(&pdf).unwrap());
        let texts = texts.unwrap();
        for (index, page) in pages.iter().enumerate() {
            let codes = scanned(page);
            assert_eq!(codes.len(), 1, "{lesson} page {}: {codes:?}", index + 1);
            let link = &codes[0];
            assert!(link.starts_with(&format!("{base}#")), "{link}");
            if lesson == "snell" {
                assert!(
                    link.ends_with(&format!("#lesson=snell&step={}", index + 1)),
                    "{link}"
                );
            } else {
                // The longest address and a state (its numbers rounded as the diagram shows
                // them): the longest link a handout prints.
                assert!(
                    link.contains("#state=") && link.len() > base.len() + 80,
                    "a state's link: {link}"
                );
            }
            let printed: String = texts[index].split_whitespace().collect();
            assert!(
                printed.contains(link.as_str()),
                "printed whole: {link} in {printed}"
            );
            fs::remove_file(page).unwrap();
        }
    }
    fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_web_address_that_cannot_start_a_link_is_refused_saying_why() {
    // Issue 40: U+202E (the printed link read backwards), port 99999 and bad escapes passed.
    for (base, why) in [
        ("https://school.example/\u{202e}explorer/", "\\u{202e}"),
        ("https://school.example:99999/", "port"),
        ("https://school.example/%zz/", "“%zz” is no percent escape"),
        ("javascript:alert(1)", "not http://, https:// or file://"),
        (
            "https://user:secret@school.example/",
            "user name or password",
        ),
        ("https://", "host"),
        (
            &format!("https://school.example/{}/", "a".repeat(400)),
            "bytes long",
        ),
    ] {
        let output = run(
            &[
                "render",
                "--lesson",
                "snell",
                "--web-base",
                base,
                "--out",
                "unused.pdf",
            ],
            "",
        );
        assert_eq!(output.status.code(), Some(2), "{base}");
        let said = stderr(&output);
        assert!(
            said.contains(why) && said.lines().count() == 1,
            "{base}: {said}"
        );
        assert!(!said.contains('\u{202e}'), "{said}");
    }
    assert!(!PathBuf::from("unused.pdf").exists());
}

#[test]
fn an_output_of_another_kind_is_never_replaced() {
    // Issue 40's second pass: `render --lesson snell --out notes.pdf` replaced a text file.
    let folder = folder("other-kind");
    let notes = folder.join("notes.pdf");
    fs::write(&notes, "my lesson plan\n").unwrap();
    let picture = folder.join("plan.png");
    fs::write(&picture, "not a picture").unwrap();
    let step = folder.join("steps").join("step-01.svg");
    fs::create_dir_all(step.parent().unwrap()).unwrap();
    fs::write(&step, "[deck]\n").unwrap();
    let steps = format!("{}/", step.parent().unwrap().display());
    for args in [
        vec![
            "render",
            "--lesson",
            "snell",
            "--out",
            notes.to_str().unwrap(),
        ],
        vec!["render", "--out", picture.to_str().unwrap()],
        vec!["render", "--lesson", "snell", "--out", &steps],
        vec!["bench", "--quick", "--plot", picture.to_str().unwrap()],
    ] {
        let output = run(&args, "");
        assert_eq!(output.status.code(), Some(2), "{args:?}: {output:?}");
        assert!(
            stderr(&output).contains("which is never replaced"),
            "{output:?}"
        );
    }
    assert_eq!(fs::read_to_string(&notes).unwrap(), "my lesson plan\n");
    assert_eq!(fs::read_to_string(&picture).unwrap(), "not a picture");
    assert_eq!(fs::read_to_string(&step).unwrap(), "[deck]\n");
    // A file of the kind written, or an empty one, is replaced.
    fs::write(&notes, "").unwrap();
    let handout = [
        "render",
        "--lesson",
        "snell",
        "--out",
        notes.to_str().unwrap(),
    ];
    for time in ["over an empty file", "over its own handout"] {
        let output = run(&handout, "");
        assert!(output.status.success(), "{time}: {output:?}");
    }
    fs::remove_dir_all(&folder).unwrap();
}

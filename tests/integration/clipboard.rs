//! The system clipboard in both directions. The window hands what it copies to egui as a copy
//! command, and takes a paste as egui's paste event (tested here headlessly); eframe's
//! `clipboard` feature carries both to and from the desktop's clipboard through arboard, which
//! is tested against a real X clipboard under Xvfb, read and written by `xclip` as another
//! program would.
//!
//! The X test needs `Xvfb` and `xclip` (Debian's `xvfb` and `xclip`, which `.ci/run` installs).
//! Where they are missing it says so and passes, unless `REFRACTION_X11_TESTS=1` (set by
//! `.ci/run`) asks that it run.

use refraction_tools::state_to_json;
use std::io::{BufRead as _, BufReader, Write as _};
use std::process::{Child, Command, Stdio};

use egui_kittest::kittest::Queryable as _;
use refraction_model::ExplorerState;

use crate::common::{click, harness, paste_log, reach};

#[test]
fn a_copied_share_string_goes_to_the_system_clipboard() {
    let state = ExplorerState::default();
    let mut h = harness(state.clone());
    click(&mut h, "💾 Save, open, share");
    h.get_by_label("🔗 Copy share string").scroll_to_me();
    h.run();
    h.get_by_label("🔗 Copy share string").click();
    // The frame of the click hands the text over.
    h.step();
    let copied: Vec<&String> = h
        .output()
        .platform_output
        .commands
        .iter()
        .filter_map(|c| match c {
            egui::OutputCommand::CopyText(text) => Some(text),
            _ => None,
        })
        .collect();
    assert_eq!(copied, [&state_to_json(&state)]);
}

#[test]
fn a_log_pasted_from_the_system_clipboard_is_judged() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    click(&mut h, "GLSL");
    reach(&mut h, "📋 Paste log lines");
    // Focus the box, then paste as egui-winit does on Ctrl+V with the desktop's clipboard.
    paste_log(&mut h, "");
    let log =
        r#"{"I":[0.6,-0.8,0],"N":[0,1,0],"eta":1.5,"result":[0.9,-0.435890,0],"from":1,"to":1.5}"#;
    h.event(egui::Event::Paste(log.to_owned()));
    h.run();
    reach(&mut h, "Check the lines");
    assert!(
        h.query_by_label_contains("The bug: eta_inverted").is_some(),
        "the pasted line was judged"
    );
}

/// An X server of its own on a free display, stopped when dropped.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    /// Starts Xvfb on a display it finds free; `None` where it does not start. Xvfb writes the
    /// display's number once it accepts connections (`-displayfd`), so no client can come too
    /// early, and it never resets (`-noreset`): by default an X server resets when its last
    /// client leaves, and refuses connections while it does, which failed this test under load
    /// between the copy and the paste.
    fn start() -> Option<Self> {
        let mut child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-noreset",
                "-screen",
                "0",
                "640x480x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .ok()?;
        let mut number = String::new();
        let told = child
            .stdout
            .take()
            .map(|out| BufReader::new(out).read_line(&mut number));
        let number = number.trim();
        if !matches!(told, Some(Ok(_))) || number.is_empty() {
            child.kill().ok();
            child.wait().ok();
            return None;
        }
        let display = format!(":{number}");
        Some(Self { child, display })
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        // SIGTERM, so that Xvfb removes its lock file and socket (a killed one leaves both, and
        // the displays run out over many runs); SIGKILL only if that cannot be sent.
        let terminated = Command::new("kill")
            .arg(self.child.id().to_string())
            .status()
            .is_ok_and(|s| s.success());
        if !terminated {
            self.child.kill().ok();
        }
        self.child.wait().ok();
    }
}

/// Whether a program runs here.
fn installed(program: &str) -> bool {
    Command::new("sh")
        .args(["-c", &format!("command -v {program}")])
        .stdout(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// What `xclip` reads from the clipboard of `display`.
fn xclip_read(display: &str) -> String {
    let output = Command::new("xclip")
        .args(["-selection", "clipboard", "-o"])
        .env("DISPLAY", display)
        .output()
        .unwrap();
    String::from_utf8(output.stdout).unwrap()
}

/// Puts `text` on the clipboard of `display` with `xclip`, which keeps serving it in the
/// background (it exits once another program owns the clipboard).
fn xclip_write(display: &str, text: &str) {
    let mut child = Command::new("xclip")
        .args(["-selection", "clipboard", "-i"])
        .env("DISPLAY", display)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    child.wait().unwrap();
}

/// The variable that tells [`x_clipboard_peer`] what to do, and the display it works on.
const PEER: &str = "REFRACTION_CLIPBOARD_PEER";

/// Runs [`x_clipboard_peer`] in a process of its own on `display` (so that no thread of this
/// binary sees another `DISPLAY`), told `task`; it is killed when the returned child drops.
fn peer(display: &str, task: &str) -> Child {
    Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "clipboard::x_clipboard_peer",
            "--ignored",
            "--nocapture",
        ])
        .args(["--test-threads", "1"])
        .env("DISPLAY", display)
        .env(PEER, task)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

/// Reads `child`'s output up to a line starting with `mark`; the rest of that line.
fn read_until(child: &mut Child, mark: &str) -> String {
    use std::io::BufRead as _;
    let out = child.stdout.as_mut().unwrap();
    for line in std::io::BufReader::new(out).lines() {
        let line = line.unwrap();
        // The harness prints the test's name before the test's own output, on that line.
        if let Some((_, rest)) = line.split_once(mark) {
            return rest.to_owned();
        }
    }
    panic!("the peer ended before saying {mark}");
}

#[test]
#[ignore = "the peer process of the_x_clipboard_the_window_uses_carries_text_both_ways"]
#[expect(clippy::print_stdout, reason = "the peer answers its test on stdout")]
fn x_clipboard_peer() {
    let task = std::env::var(PEER).expect("run by the X clipboard test, which sets the task");
    let mut clipboard = arboard::Clipboard::new().expect("arboard connects to the X server");
    if let Some(text) = task.strip_prefix("copy:") {
        clipboard.set_text(text.to_owned()).unwrap();
        println!("copied:");
        // Own the clipboard until the test is done reading it.
        let mut rest = String::new();
        std::io::stdin().read_line(&mut rest).ok();
    } else {
        let text = clipboard.get_text().unwrap();
        println!("pasted:{}", text.replace('\n', "\\n"));
    }
}

#[test]
#[expect(clippy::print_stderr, reason = "a skipped run says why")]
fn the_x_clipboard_the_window_uses_carries_text_both_ways() {
    let required = std::env::var("REFRACTION_X11_TESTS").is_ok_and(|v| v == "1");
    if !(installed("Xvfb") && installed("xclip")) {
        assert!(
            !required,
            "REFRACTION_X11_TESTS=1 but Xvfb or xclip is not installed"
        );
        eprintln!("skipped: Xvfb and xclip are not installed (apt-get install xvfb xclip)");
        return;
    }
    let server = Xvfb::start().expect("Xvfb starts on a free display");
    let display = server.display.clone();
    // What the window copies, another program (xclip, a terminal) pastes.
    let share = state_to_json(&ExplorerState::default());
    let mut copier = peer(&display, &format!("copy:{share}"));
    read_until(&mut copier, "copied:");
    assert_eq!(xclip_read(&display), share);
    drop(copier.stdin.take());
    copier.wait().unwrap();
    // What another program copied, the window pastes.
    let log = "Refract wi=(0.6, 0.8, 0) n=(0, 0, 1) eta=1.5";
    xclip_write(&display, log);
    let mut paster = peer(&display, "paste");
    assert_eq!(read_until(&mut paster, "pasted:"), log);
    paster.wait().unwrap();
}

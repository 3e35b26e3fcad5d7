//! Writing to stdout and stderr without panicking (`println!` and `eprintln!` panic when the
//! stream cannot be written), and text from files made safe to print on a terminal.

use std::borrow::Cow;
use std::io::{self, IsTerminal as _, Write as _};

/// Whether `c` would act on a terminal rather than show: a control character (ESC, BEL, a
/// newline, ...), or a bidirectional override that reorders the text after it.
fn acts(c: char) -> bool {
    c.is_control() || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// `text` with every character that would act on a terminal escaped as Rust writes it
/// (`\u{1b}`, `\n`, `\t`), so that a scene title, a medium name or a path from a file cannot
/// move the cursor, ring the bell, recolour the terminal or break a one-line message.
pub(crate) fn printable(text: &str) -> Cow<'_, str> {
    if !text.chars().any(acts) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if acts(c) {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// Writes `bytes` to stdout and flushes it.
///
/// # Errors
/// Stdout cannot be written (full disk, closed pipe).
pub(crate) fn to_stdout(bytes: &[u8]) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(bytes)?;
    out.flush()
}

/// Writes `text` and a newline to stderr.
///
/// # Errors
/// Stderr cannot be written.
pub(crate) fn to_stderr(text: &str) -> io::Result<()> {
    let mut err = io::stderr().lock();
    err.write_all(text.as_bytes())?;
    err.write_all(b"\n")?;
    err.flush()
}

/// A progress line on stderr, `WHAT  42%`, drawn over itself, when stderr is a terminal (a
/// log file gets no progress noise); the first failed write is kept, stops the line, and is
/// reported by [`ProgressLine::finish`].
pub(crate) struct ProgressLine {
    what: &'static str,
    shown: bool,
    failed: Option<io::Error>,
}

impl ProgressLine {
    /// A progress line for `what` (e.g. `measuring...`), shown if stderr is a terminal.
    pub(crate) fn on_terminal(what: &'static str) -> Self {
        Self {
            what,
            shown: io::stderr().is_terminal(),
            failed: None,
        }
    }

    /// Shows `fraction` (0 to 1) done.
    pub(crate) fn update(&mut self, fraction: f64) {
        if self.shown && self.failed.is_none() {
            let mut err = io::stderr().lock();
            let percent = (fraction * 100.0).clamp(0.0, 100.0);
            let written = write!(err, "\r{} {percent:3.0}%", self.what).and_then(|()| err.flush());
            self.failed = written.err();
        }
    }

    /// Ends the progress line; the error of a failed write, if any.
    pub(crate) fn finish(mut self) -> Option<io::Error> {
        if self.shown && self.failed.is_none() {
            self.failed = to_stderr("").err();
        }
        self.failed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_the_rest_kept() {
        assert_eq!(printable("Prism — 60° (n = 1.5)"), "Prism — 60° (n = 1.5)");
        assert_eq!(
            printable("a\u{1b}[31mred\u{7}\nline\u{202e}"),
            "a\\u{1b}[31mred\\u{7}\\nline\\u{202e}"
        );
    }
}

//! JSON Lines: the `solve` and `check` commands' requests and answers, and the explorer's state
//! file (one `solve` line). [`answer_lines`] is the loop both commands share: one answer per
//! non-empty input line, in order, streaming, with bad lines answered rather than fatal.

pub mod api_check;
pub mod check;
pub mod solve;
pub mod state_file;
pub mod vector_text;

use std::io::{self, BufRead, Write};

/// The error line for input line `line` (1-based).
#[must_use]
pub fn error_line(line: usize, message: &str) -> String {
    serde_json::json!({ "line": line, "error": message }).to_string()
}

/// Writes `answer(line)` for every non-empty line of `input` to `output`, one line at a time
/// (nothing is held beyond the current line). A line that `answer` rejects, or that is not
/// UTF-8, is answered with `{"line": K, "error": "..."}` (K counts every input line from 1) and
/// the run goes on. An empty answer writes nothing (a log line that is not a call, a CSV
/// header); an answer may hold several lines. Returns whether every line was answered without
/// error.
///
/// # Errors
/// Reading `input` or writing `output` failed.
pub fn answer_lines(
    mut input: impl BufRead,
    mut output: impl Write,
    mut answer: impl FnMut(&str) -> Result<String, String>,
) -> io::Result<bool> {
    let mut all_answered = true;
    let mut buffer = Vec::new();
    let mut number = 0;
    loop {
        buffer.clear();
        if input.read_until(b'\n', &mut buffer)? == 0 {
            break;
        }
        number += 1;
        let reply = match std::str::from_utf8(&buffer) {
            Err(e) => Err(format!(
                "the line is not valid UTF-8 (byte {})",
                e.valid_up_to() + 1
            )),
            Ok(text) if text.trim().is_empty() => continue,
            Ok(text) => answer(text.trim()),
        };
        let text = reply.unwrap_or_else(|message| {
            all_answered = false;
            error_line(number, &message)
        });
        if !text.is_empty() {
            writeln!(output, "{text}")?;
        }
    }
    output.flush()?;
    Ok(all_answered)
}

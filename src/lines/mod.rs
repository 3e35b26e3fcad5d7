//! JSON Lines: the `solve` and `check` commands' requests and answers, and the explorer's state
//! file (one `solve` line). [`answer_lines`] is the loop both commands share: one answer per
//! non-empty input line, in order, streaming, with bad lines answered rather than fatal.

pub mod api_check;
pub mod check;
mod fields;
pub mod solve;
pub mod state_file;
pub mod vector_text;

use std::io::{self, BufRead, Read, Write};

/// The longest line `solve` and `check` read, in bytes, its newline not counted: 1 MiB. A
/// longer line is answered with an error as soon as it passes the limit, without being held in
/// memory, and the run goes on after its newline.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Why [`answer_lines`] stopped: the input could not be read or the output not written.
#[derive(Debug, thiserror::Error)]
pub enum LinesError {
    /// Reading the input failed.
    #[error("cannot read the input: {0}")]
    Read(#[source] io::Error),
    /// Writing the output failed (a closed pipe included).
    #[error("cannot write the output: {0}")]
    Write(#[source] io::Error),
}

/// The error line for input line `line` (1-based).
#[must_use]
pub fn error_line(line: usize, message: &str) -> String {
    serde_json::json!({ "line": line, "error": message }).to_string()
}

/// One input line as [`next_line`] read it.
enum Next {
    /// A line, in the buffer without its newline.
    Line,
    /// A line longer than [`MAX_LINE_BYTES`]; what was read of it is dropped.
    TooLong,
    /// The end of the input.
    End,
}

/// Reads the next line into `buffer` (cleared first), reading no more than
/// [`MAX_LINE_BYTES`] + 1 bytes of it.
fn next_line(input: &mut impl BufRead, buffer: &mut Vec<u8>) -> io::Result<Next> {
    buffer.clear();
    let limit = MAX_LINE_BYTES as u64 + 1;
    if input.by_ref().take(limit).read_until(b'\n', buffer)? == 0 {
        return Ok(Next::End);
    }
    if buffer.last() == Some(&b'\n') {
        buffer.pop();
    } else if buffer.len() > MAX_LINE_BYTES {
        buffer.clear();
        return Ok(Next::TooLong);
    }
    Ok(Next::Line)
}

/// The message for an over-long line `number`.
fn too_long(number: usize) -> String {
    format!(
        "line {number} is longer than 1 MiB ({MAX_LINE_BYTES} bytes), the longest line read: \
         skipped to its end"
    )
}

/// Writes `answer(line)` for every non-empty line of `input` to `output`, one line at a time
/// (nothing is held beyond the current line, and no more than [`MAX_LINE_BYTES`] of it). A line
/// that `answer` rejects, that is not UTF-8 or that is too long is answered with
/// `{"line": K, "error": "..."}` (K counts every input line from 1) and the run goes on; a
/// too-long line is answered as soon as it passes the limit, and the rest of it is read past
/// without being kept. An empty answer writes nothing (a log line that is not a call, a CSV
/// header); an answer may hold several lines. Returns whether every line was answered without
/// error.
///
/// # Errors
/// Reading `input` or writing `output` failed.
pub fn answer_lines(
    mut input: impl BufRead,
    mut output: impl Write,
    mut answer: impl FnMut(&str) -> Result<String, String>,
) -> Result<bool, LinesError> {
    let mut all_answered = true;
    let mut buffer = Vec::new();
    let mut number = 0;
    loop {
        let next = next_line(&mut input, &mut buffer).map_err(LinesError::Read)?;
        number += 1;
        let reply = match next {
            Next::End => break,
            Next::TooLong => Err(too_long(number)),
            Next::Line => match std::str::from_utf8(&buffer) {
                Err(e) => Err(format!(
                    "the line is not valid UTF-8 (byte {})",
                    e.valid_up_to() + 1
                )),
                Ok(text) if text.trim().is_empty() => continue,
                Ok(text) => answer(text.trim()),
            },
        };
        let text = reply.unwrap_or_else(|message| {
            all_answered = false;
            error_line(number, &message)
        });
        if !text.is_empty() {
            writeln!(output, "{text}").map_err(LinesError::Write)?;
        }
        if matches!(next, Next::TooLong) {
            // Say so before reading on: the rest of the line may be long or endless.
            output.flush().map_err(LinesError::Write)?;
            input.skip_until(b'\n').map_err(LinesError::Read)?;
        }
    }
    output.flush().map_err(LinesError::Write)?;
    Ok(all_answered)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn answers(input: impl BufRead) -> (bool, Vec<serde_json::Value>) {
        let mut out = Vec::new();
        let all = answer_lines(input, &mut out, |line| {
            Ok(format!("{{\"len\":{}}}", line.len()))
        })
        .unwrap();
        let lines = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        (all, lines)
    }

    #[test]
    fn a_line_over_the_cap_is_answered_and_the_next_one_read() {
        let long = io::repeat(b' ').take(3 * MAX_LINE_BYTES as u64);
        let exact = "x".repeat(MAX_LINE_BYTES);
        let rest = format!("\n{exact}\nab\n");
        let input = io::BufReader::new(long.chain(rest.as_bytes()));
        let (all, lines) = answers(input);
        assert!(!all);
        assert_eq!(lines.len(), 3, "{lines:?}");
        assert_eq!(lines[0]["line"], 1);
        let message = lines[0]["error"].as_str().unwrap();
        assert!(message.starts_with("line 1 is longer than 1 MiB (1048576 bytes)"));
        assert_eq!(lines[1]["len"], MAX_LINE_BYTES);
        assert_eq!(lines[2]["len"], 2);
    }

    #[test]
    fn input_without_a_newline_is_one_error_and_the_end() {
        let zeros = io::BufReader::new(io::repeat(0).take(5 * MAX_LINE_BYTES as u64));
        let (all, lines) = answers(zeros);
        assert!(!all);
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert_eq!(lines[0]["line"], 1);
    }

    /// A reader that fails on its first read, as reading a directory does.
    struct Failing;

    impl Read for Failing {
        fn read(&mut self, _: &mut [u8]) -> io::Result<usize> {
            Err(io::Error::from(io::ErrorKind::IsADirectory))
        }
    }

    #[test]
    fn read_and_write_errors_are_told_apart() {
        let err = answer_lines(io::BufReader::new(Failing), Vec::new(), |l| Ok(l.into()));
        assert!(matches!(err, Err(LinesError::Read(_))), "{err:?}");
        let mut full = [0_u8; 4];
        let err = answer_lines(&b"abcdef\n"[..], &mut full[..], |l| Ok(l.into()));
        assert!(matches!(err, Err(LinesError::Write(_))), "{err:?}");
    }
}

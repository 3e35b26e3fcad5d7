//! The refraction explorer's tools, with no window: the JSON Lines of the `solve` command and
//! the loop every JSON Lines command shares ([`answer_lines`]: one answer per non-empty input
//! line, in order, streaming, with bad lines answered rather than fatal); one T checked against
//! the four candidates ([`check_t`], in the physics convention W, N, μ: the window's *Check my
//! T* and each line of `check`); vectors as programs print them ([`vector_text`]); the
//! explorer's state file (one `solve` line, [`open_state_file`]), its links ([`link`]) and the
//! case as code to paste elsewhere ([`snippets`]).
//!
//! The diagnosis of a renderer's whole log (`check`, `check --api`) is the crate
//! `refraction-check`, built on this one.

mod candidate_check;
mod error;
mod fields;
pub mod link;
pub mod snippets;
mod solve;
mod state_file;
pub mod vector_text;

pub use candidate_check::{
    CheckAnswer, LENGTH_TOLERANCE, MATCH_ANGLE, Match, TVerdict, check_line, check_t,
    parse_check_line, parse_t,
};
pub use error::{CheckError, JsonError, RequestError, VectorError};
pub use solve::{Precision, Request, solve_line, solve_lines};
pub use state_file::{
    MAX_STATE_FILE_BYTES, StateFileError, open_state_file, parse_state, save_state_file,
    state_request, state_to_json,
};

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

/// `answer` as one JSON line.
///
/// # Panics
/// If `answer` does not serialise: every answer type of this crate and of the log diagnosis is
/// a struct of numbers, strings, vectors and options with string keys, which `serde_json`
/// always writes (NaN as `null`), so a failure is a bug and panics rather than dropping the
/// line in silence.
#[must_use]
pub fn json_line(answer: &impl serde::Serialize) -> String {
    serde_json::to_string(answer).expect("an answer of plain fields serialises")
}

/// The error line for input line `line` (1-based), its message [`brief`].
#[must_use]
pub fn error_line(line: usize, message: &str) -> String {
    serde_json::json!({ "line": line, "error": brief(message) }).to_string()
}

/// The most characters a message keeps: it may quote the input it refuses, and a line can be
/// a megabyte long.
pub const MAX_MESSAGE_CHARS: usize = 600;

/// `message` cut to about [`MAX_MESSAGE_CHARS`]: its beginning and its end (where a message
/// says what was wrong with what it quoted), the middle left out and counted.
#[must_use]
pub fn brief(message: &str) -> std::borrow::Cow<'_, str> {
    let count = message.chars().count();
    if count <= MAX_MESSAGE_CHARS {
        return std::borrow::Cow::Borrowed(message);
    }
    let (head, tail) = (MAX_MESSAGE_CHARS * 3 / 4, MAX_MESSAGE_CHARS / 6);
    let start: String = message.chars().take(head).collect();
    let end: String = message.chars().skip(count - tail).collect();
    let left_out = count - head - tail;
    std::borrow::Cow::Owned(format!(
        "{start} … ({left_out} characters left out) … {end}"
    ))
}

/// One input line as [`next_line`] read it.
enum Next {
    /// A line, in the buffer without its newline.
    Line,
    /// A line longer than [`MAX_LINE_BYTES`] (its newline not counted); what was read of it is
    /// dropped, and its rest is still to be read past when `rest_unread`.
    TooLong { rest_unread: bool },
    /// The end of the input.
    End,
}

/// Reads the next line into `buffer` (cleared first) without its newline (`\n` or `\r\n`),
/// reading no more than [`MAX_LINE_BYTES`] + 2 bytes of it.
fn next_line(input: &mut impl BufRead, buffer: &mut Vec<u8>) -> io::Result<Next> {
    buffer.clear();
    let limit = MAX_LINE_BYTES as u64 + 2;
    if input.by_ref().take(limit).read_until(b'\n', buffer)? == 0 {
        return Ok(Next::End);
    }
    let ended = buffer.last() == Some(&b'\n');
    if ended {
        buffer.pop();
        if buffer.last() == Some(&b'\r') {
            buffer.pop();
        }
    }
    if buffer.len() > MAX_LINE_BYTES {
        buffer.clear();
        return Ok(Next::TooLong {
            rest_unread: !ended,
        });
    }
    Ok(Next::Line)
}

/// A UTF-8 byte order mark, as Excel's "CSV UTF-8" and some editors put before a file's first
/// line: not part of the text.
const BYTE_ORDER_MARK: &[u8] = b"\xEF\xBB\xBF";

/// Why [`answer_lines`] answers a line itself, with an error line, before any work on it.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UnreadLine {
    /// Longer than [`MAX_LINE_BYTES`]: skipped to its end.
    #[error(
        "line {number} is longer than 1 MiB ({MAX_LINE_BYTES} bytes), the longest line read: \
         skipped to its end"
    )]
    TooLong {
        /// The line's number, from 1.
        number: usize,
    },
    /// Not UTF-8 text.
    #[error("the line is not valid UTF-8 (byte {byte})")]
    NotUtf8 {
        /// The first byte that is not, from 1.
        byte: usize,
    },
}

/// The most lines read before they are answered together: enough to keep every core busy for
/// a while, few enough that memory stays flat.
const CHUNK_LINES: usize = 4096;

/// The most bytes of lines read before they are answered together (one line may take the chunk
/// past it, by at most [`MAX_LINE_BYTES`]).
const CHUNK_BYTES: usize = 4 << 20;

/// The read buffer: a file's lines come a chunk at a time (a pipe gives at most what it holds).
const READ_BUFFER_BYTES: usize = 1 << 20;

/// One input line of a chunk, as it is handed to the workers.
struct Item {
    /// Its number, counting every input line from 1.
    number: usize,
    /// Where its bytes lie in the chunk's buffer, or why it has none (too long).
    bytes: Result<core::ops::Range<usize>, UnreadLine>,
}

/// What a worker made of one line.
enum Outcome<W> {
    /// Blank: no answer.
    Blank,
    /// Not answerable (not UTF-8, too long): why, for its error line.
    Bad(UnreadLine),
    /// The work's result.
    Done(W),
}

/// A chunk of input lines read into one buffer.
#[derive(Default)]
struct Chunk {
    bytes: Vec<u8>,
    items: Vec<Item>,
    /// The chunk ended at a line over the limit whose rest is unread: say so before reading
    /// past it.
    ended_too_long: bool,
    /// The input has ended.
    ended: bool,
}

impl Chunk {
    /// Reads up to [`CHUNK_LINES`] lines or [`CHUNK_BYTES`] bytes, the line numbers following
    /// `number` (updated). A line over the limit ends the chunk, and so does an empty read
    /// buffer: the lines read so far are answered before waiting for more input (a log piped
    /// in as it is written gets its answers as it goes).
    fn read<R: Read>(input: &mut io::BufReader<R>, number: &mut usize) -> io::Result<Self> {
        let mut chunk = Self::default();
        let mut line = Vec::new();
        while chunk.items.len() < CHUNK_LINES && chunk.bytes.len() < CHUNK_BYTES {
            let next = next_line(input, &mut line)?;
            if matches!(next, Next::End) {
                chunk.ended = true;
                break;
            }
            *number += 1;
            let text = match line.strip_prefix(BYTE_ORDER_MARK) {
                Some(rest) if *number == 1 => rest,
                _ => &line,
            };
            let bytes = if let Next::TooLong { .. } = next {
                Err(UnreadLine::TooLong { number: *number })
            } else {
                let start = chunk.bytes.len();
                chunk.bytes.extend_from_slice(text);
                Ok(start..chunk.bytes.len())
            };
            chunk.items.push(Item {
                number: *number,
                bytes,
            });
            if let Next::TooLong { rest_unread } = next {
                chunk.ended_too_long = rest_unread;
                break;
            }
            if input.buffer().is_empty() {
                break;
            }
        }
        Ok(chunk)
    }

    /// `work` on each line, the lines shared out in order among `threads` threads, each of
    /// which speaks the calling thread's language (`work` may word what it finds).
    fn work<W: Send>(&self, threads: usize, work: &(impl Fn(&str) -> W + Sync)) -> Vec<Outcome<W>> {
        let one = |item: &Item| match &item.bytes {
            Err(unread) => Outcome::Bad(unread.clone()),
            Ok(range) => match core::str::from_utf8(&self.bytes[range.clone()]) {
                Err(e) => Outcome::Bad(UnreadLine::NotUtf8 {
                    byte: e.valid_up_to() + 1,
                }),
                Ok(text) if text.trim().is_empty() => Outcome::Blank,
                Ok(text) => Outcome::Done(work(text.trim())),
            },
        };
        let share = self.items.len().div_ceil(threads.max(1)).max(1);
        if threads <= 1 || self.items.len() <= share {
            return self.items.iter().map(one).collect();
        }
        self.shared_out(share, &one)
    }

    /// `one` on each line, in parts of `share` lines, each part on a thread of its own that
    /// speaks the calling thread's language.
    #[cfg(not(target_arch = "wasm32"))]
    fn shared_out<W: Send>(
        &self,
        share: usize,
        one: &(impl Fn(&Item) -> Outcome<W> + Sync),
    ) -> Vec<Outcome<W>> {
        let locale = refraction_i18n::locale();
        std::thread::scope(|scope| {
            let parts: Vec<_> = self
                .items
                .chunks(share)
                .map(|part| {
                    scope.spawn(move || {
                        refraction_i18n::set_locale(locale);
                        part.iter().map(one).collect::<Vec<_>>()
                    })
                })
                .collect();
            // A worker panics only if `work` does; pass that on rather than lose lines.
            parts
                .into_iter()
                .flat_map(|part| part.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
                .collect()
        })
    }

    /// In a browser page, which has one thread and spawns none: `one` on each line, in order,
    /// on this thread (the wasm32 build is linted with threads disallowed).
    #[cfg(target_arch = "wasm32")]
    fn shared_out<W: Send>(
        &self,
        _share: usize,
        one: &(impl Fn(&Item) -> Outcome<W> + Sync),
    ) -> Vec<Outcome<W>> {
        self.items.iter().map(one).collect()
    }
}

/// The number of threads [`answer_lines`] answers on: one per core this process may run on
/// (`taskset` and container limits included).
#[must_use]
pub fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, core::num::NonZeroUsize::get)
}

/// Writes an answer for every non-empty line of `input` to `output`, in input order. The lines
/// are read in chunks (at most 4,096 lines or about 4 MiB, and no
/// line over [`MAX_LINE_BYTES`] is kept), `work` runs on each line of a chunk on `threads`
/// threads, then `finish` turns each result into the answer, in order, on this thread, with
/// the line's number (it may keep a tally or other state). A line that `finish` rejects, that is not UTF-8 or that is
/// too long is answered with `{"line": K, "error": "..."}` (K counts every input line from 1)
/// and the run goes on; a too-long line is answered as soon as it passes the limit, and the
/// rest of it is read past without being kept. An empty answer writes nothing (a log line that
/// is not a call, a CSV header); an answer may hold several lines. `refused` hears of each line
/// the loop answers itself (not UTF-8, too long), so that a tally can count it. A UTF-8 byte
/// order mark before the first line is not part of it. Returns whether every line was answered
/// without error.
///
/// # Errors
/// Reading `input` or writing `output` failed.
pub fn answer_lines<W: Send, E: core::fmt::Display>(
    input: impl Read,
    output: impl Write,
    threads: usize,
    work: impl Fn(&str) -> W + Sync,
    mut finish: impl FnMut(usize, W) -> Result<String, E>,
    mut refused: impl FnMut(),
) -> Result<bool, LinesError> {
    let mut input = io::BufReader::with_capacity(READ_BUFFER_BYTES, input);
    // One write per chunk, not one per line (stdout is line-buffered: two system calls a line).
    let mut output = io::BufWriter::with_capacity(READ_BUFFER_BYTES, output);
    let mut all_answered = true;
    let mut number = 0;
    loop {
        let chunk = Chunk::read(&mut input, &mut number).map_err(LinesError::Read)?;
        for (item, outcome) in chunk.items.iter().zip(chunk.work(threads, &work)) {
            let reply = match outcome {
                Outcome::Blank => continue,
                Outcome::Bad(unread) => {
                    refused();
                    Err(unread.to_string())
                }
                Outcome::Done(result) => finish(item.number, result).map_err(|e| e.to_string()),
            };
            let text = reply.unwrap_or_else(|message| {
                all_answered = false;
                error_line(item.number, &message)
            });
            if !text.is_empty() {
                writeln!(output, "{text}").map_err(LinesError::Write)?;
            }
        }
        // A chunk's answers go out before more input is awaited (the input may be a live log,
        // or the rest of an over-long line, which may be endless).
        output.flush().map_err(LinesError::Write)?;
        if chunk.ended_too_long {
            input.skip_until(b'\n').map_err(LinesError::Read)?;
        }
        if chunk.ended {
            break;
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
        let all = answer_lines(
            input,
            &mut out,
            2,
            |line| line.len(),
            |_, len| Ok::<_, String>(format!("{{\"len\":{len}}}")),
            || {},
        )
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
    fn a_message_quoting_a_huge_input_keeps_its_ends() {
        // Issue 23: an error echoed up to a megabyte of the line it refused.
        let message = format!("\"{}\" is not a number", "9".repeat(1_000_000));
        let short = brief(&message);
        assert!(
            short.chars().count() < MAX_MESSAGE_CHARS + 60,
            "{}",
            short.len()
        );
        assert!(
            short.starts_with("\"999") && short.ends_with("\" is not a number"),
            "{short}"
        );
        assert!(short.contains("characters left out"), "{short}");
        assert_eq!(brief("short"), "short");
    }

    #[test]
    fn the_newline_is_not_counted_whether_it_is_lf_or_crlf() {
        // Issue 23: a 1 MiB line was refused with CRLF and taken with LF.
        let exact = "x".repeat(MAX_LINE_BYTES);
        let over = "y".repeat(MAX_LINE_BYTES + 1);
        let input = format!("{exact}\r\n{over}\r\nab\r\n{over}\ncd");
        let (all, lines) = answers(input.as_bytes());
        assert!(!all);
        assert_eq!(lines.len(), 5, "{lines:?}");
        assert_eq!(lines[0]["len"], MAX_LINE_BYTES);
        assert_eq!(lines[1]["line"], 2, "the line over the cap is refused");
        assert_eq!(lines[2]["len"], 2, "and the next one read whole");
        assert_eq!(lines[3]["line"], 4);
        assert_eq!(lines[4]["len"], 2);
    }

    #[test]
    fn a_byte_order_mark_before_the_first_line_is_not_part_of_it() {
        // Issue 23: Excel's "CSV UTF-8" starts with one.
        let (all, lines) = answers(&b"\xEF\xBB\xBFabc\n\xEF\xBB\xBFab\n"[..]);
        assert!(all);
        assert_eq!(lines[0]["len"], 3);
        assert_eq!(lines[1]["len"], 5, "only the first line's is dropped");
    }

    #[test]
    fn lines_the_loop_refuses_are_told_to_the_caller() {
        let mut refused = 0;
        let input = &b"ok\n\xFF\xFE\nok\n"[..];
        let all = answer_lines(
            input,
            Vec::new(),
            1,
            str::len,
            |_, len| Ok::<_, String>(len.to_string()),
            || refused += 1,
        )
        .unwrap();
        assert!(!all);
        assert_eq!(refused, 1, "the line that is not UTF-8");
    }

    #[test]
    fn answers_keep_the_input_order_and_line_numbers_on_many_threads() {
        let mut text = String::new();
        for k in 1..=3 * CHUNK_LINES {
            text.push_str(&match k % 7 {
                0 => String::new(),
                3 => "\u{7f}bad".to_owned(),
                _ => k.to_string(),
            });
            text.push('\n');
        }
        let run = |threads: usize| {
            let mut out = Vec::new();
            let mut order = Vec::new();
            let work = |line: &str| {
                line.parse::<usize>()
                    .map_err(|e| format!("not {line}: {e}"))
            };
            let finish = |_, parsed: Result<usize, _>| {
                let k = parsed?;
                order.push(k);
                Ok::<_, String>(format!("{{\"k\":{k}}}"))
            };
            let all =
                answer_lines(text.as_bytes(), &mut out, threads, work, finish, || {}).unwrap();
            (all, String::from_utf8(out).unwrap(), order)
        };
        let (one, many) = (run(1), run(3));
        assert_eq!(one, many);
        let (all, out, order) = many;
        assert!(!all);
        assert!(
            order.windows(2).all(|w| w[0] < w[1]),
            "finish sees the lines in order"
        );
        let lines: Vec<serde_json::Value> = out
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        let blanks = (1..=3 * CHUNK_LINES).filter(|k| k % 7 == 0).count();
        assert_eq!(lines.len(), 3 * CHUNK_LINES - blanks);
        assert_eq!(lines[2]["line"], 3, "an error names its line");
        assert_eq!(
            lines[2]["error"],
            "not \u{7f}bad: invalid digit found in string"
        );
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
        let echo = |l: &str| Ok::<_, String>(l.to_owned());
        let err = answer_lines(
            io::BufReader::new(Failing),
            Vec::new(),
            2,
            echo,
            |_, r| r,
            || {},
        );
        assert!(matches!(err, Err(LinesError::Read(_))), "{err:?}");
        let mut full = [0_u8; 4];
        let err = answer_lines(&b"abcdef\n"[..], &mut full[..], 2, echo, |_, r| r, || {});
        assert!(matches!(err, Err(LinesError::Write(_))), "{err:?}");
    }
}

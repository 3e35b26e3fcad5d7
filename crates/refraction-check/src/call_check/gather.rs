//! Records printed over several lines: a `--pattern` log's lines gathered, in order, into the
//! texts the pattern is matched against.
//!
//! Two things spread a record over lines. A value printed over several lines, as Node prints a
//! typed array (`d Float32Array(3) [`, one element a line, `]`): a line that leaves a bracket
//! open and ends with an opening bracket or a comma is joined with the lines after it until
//! its brackets close. And a record printed one value a line, as Cycles' `print_float3` does:
//! a pattern with line breaks (`wi: {w}\nN: {n}\nwo: {t_yours}`) is matched against that many
//! consecutive (joined) lines, joined with line breaks; when they do not match, the first of
//! them is skipped and the window moves on by one line. Each line is in at most
//! [`super::limits::MAX_PATTERN_LINES`] windows, so the work stays linear in the log's length.

use std::collections::VecDeque;

/// The most lines one value may be printed over (a 3-vector takes 5 in Node).
const MAX_JOINED_LINES: usize = 64;

/// The most bytes one value's joined lines may hold.
const MAX_JOINED_BYTES: usize = 64 * 1024;

/// Lines joined into one: their text (joined with spaces) and how many they were.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Logical {
    text: String,
    physical: usize,
    depth: i64,
}

/// Brackets opened minus brackets closed in `text`.
fn depth(text: &str) -> i64 {
    text.bytes()
        .map(|b| match b {
            b'[' | b'(' | b'{' => 1,
            b']' | b')' | b'}' => -1,
            _ => 0,
        })
        .sum()
}

/// Whether `line` starts a value printed over several lines.
fn opens(line: &str) -> bool {
    depth(line) > 0 && line.trim_end().ends_with(|c| "[({,".contains(c))
}

/// `lines` with each value printed over several lines joined into one line (the first step
/// of [`Gather`]), for a suggestion read from a log's first lines.
#[must_use]
pub(crate) fn joined<'a>(lines: impl IntoIterator<Item = &'a str>) -> Vec<String> {
    let mut out = Vec::new();
    let mut open: Option<Logical> = None;
    for line in lines {
        let mut logical = match open.take() {
            Some(mut l) => {
                l.text.push(' ');
                l.text.push_str(line.trim());
                l.physical += 1;
                l.depth += depth(line);
                l
            }
            None if opens(line) => Logical {
                text: line.trim_end().to_owned(),
                physical: 1,
                depth: depth(line),
            },
            None => {
                out.push(line.to_owned());
                continue;
            }
        };
        if logical.depth > 0 && logical.physical < MAX_JOINED_LINES {
            open = Some(logical);
        } else {
            logical.depth = 0;
            out.push(logical.text);
        }
    }
    out.extend(open.map(|l| l.text));
    out
}

/// What one more line gave: lines now known to be no part of a record, and a record.
#[derive(Debug, Default, PartialEq, Eq)]
pub(crate) struct Step {
    /// Lines left out: not part of any record.
    pub skipped: usize,
    /// A record's text, to match and judge.
    pub record: Option<String>,
}

/// The lines gathered so far.
#[derive(Clone, Debug)]
pub(crate) struct Gather {
    lines: usize,
    open: Option<Logical>,
    window: VecDeque<Logical>,
}

impl Gather {
    /// Gathers records of `lines` lines (a pattern's [`super::Pattern::lines`]).
    #[must_use]
    pub(crate) fn new(lines: usize) -> Self {
        Self {
            lines: lines.max(1),
            open: None,
            window: VecDeque::new(),
        }
    }

    /// Takes `line`, which the pattern did not match on its own; `matches` says whether a
    /// gathered text is a record.
    pub(crate) fn push(&mut self, line: &str, matches: impl Fn(&str) -> bool) -> Step {
        let logical = match self.open.take() {
            Some(mut open) => {
                open.text.push(' ');
                open.text.push_str(line.trim());
                open.physical += 1;
                open.depth += depth(line);
                let full = open.physical >= MAX_JOINED_LINES || open.text.len() >= MAX_JOINED_BYTES;
                if open.depth > 0 && !full {
                    self.open = Some(open);
                    return Step::default();
                }
                open
            }
            None if opens(line) => {
                self.open = Some(Logical {
                    text: line.trim_end().to_owned(),
                    physical: 1,
                    depth: depth(line),
                });
                return Step::default();
            }
            None => Logical {
                text: line.to_owned(),
                physical: 1,
                depth: 0,
            },
        };
        self.take(logical, matches)
    }

    /// A line (joined or not) into the window.
    fn take(&mut self, logical: Logical, matches: impl Fn(&str) -> bool) -> Step {
        if self.lines == 1 {
            // A single line was tried already; a joined one is tried now.
            let record = (logical.physical > 1 && matches(&logical.text)).then_some(logical.text);
            return match record {
                Some(text) => Step {
                    skipped: 0,
                    record: Some(text),
                },
                None => Step {
                    skipped: logical.physical,
                    record: None,
                },
            };
        }
        self.window.push_back(logical);
        if self.window.len() < self.lines {
            return Step::default();
        }
        let texts: Vec<&str> = self.window.iter().map(|l| l.text.as_str()).collect();
        let joined = texts.join("\n");
        if matches(&joined) {
            self.window.clear();
            return Step {
                skipped: 0,
                record: Some(joined),
            };
        }
        Step {
            skipped: self.window.pop_front().map_or(0, |l| l.physical),
            record: None,
        }
    }

    /// Forgets what was gathered (a line matched on its own, or the input ended): how many
    /// lines that leaves out.
    pub(crate) fn clear(&mut self) -> usize {
        let open = self.open.take().map_or(0, |l| l.physical);
        let window: usize = self.window.drain(..).map(|l| l.physical).sum();
        open + window
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn records(lines: usize, log: &str, matches: impl Fn(&str) -> bool) -> (Vec<String>, usize) {
        let mut gather = Gather::new(lines);
        let (mut found, mut skipped) = (Vec::new(), 0);
        for line in log.lines() {
            let step = gather.push(line, &matches);
            skipped += step.skipped;
            found.extend(step.record);
        }
        (found, skipped + gather.clear())
    }

    #[test]
    fn node_s_typed_arrays_over_several_lines_are_joined() {
        let log = "begin\nd Float32Array(3) [\n  0.39162999391555786,\n  -0.5874453186988831,\n  \
                   -0.7080398797988892\n] t Float32Array(3) [ 0.5, -0.25, -0.800000011920929 ]\nend";
        let (found, skipped) = records(1, log, |t| t.starts_with("d "));
        assert_eq!(
            found,
            [
                "d Float32Array(3) [ 0.39162999391555786, -0.5874453186988831, -0.7080398797988892 ] \
              t Float32Array(3) [ 0.5, -0.25, -0.800000011920929 ]"
            ]
        );
        assert_eq!(skipped, 2, "begin and end");
    }

    #[test]
    fn a_record_over_three_lines_moves_on_by_one_line_when_it_does_not_match() {
        let log = "noise\nwi: 1 2 3\nN: 0 0 1\nwo: 4 5 6\nwi: 1 2 3\nN: 0 0 1\nnoise";
        let matches = |t: &str| t.starts_with("wi:") && t.contains("\nwo:");
        let (found, skipped) = records(3, log, matches);
        assert_eq!(found, ["wi: 1 2 3\nN: 0 0 1\nwo: 4 5 6"]);
        assert_eq!(
            skipped, 4,
            "the first noise, and the unfinished record at the end"
        );
    }

    #[test]
    fn a_bracket_left_open_stops_joining_at_the_limit() {
        let log = format!("x [\n{}", "1,\n".repeat(100));
        let (found, skipped) = records(1, &log, |_| false);
        assert!(found.is_empty());
        assert_eq!(skipped, 101);
    }
}

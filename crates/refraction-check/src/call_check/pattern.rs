//! `--pattern`: log lines as a program printed them, such as
//! `LOG {uv} | {n} | {etai_over_etat} | {refracted} | {entering}`. Each `{field}` takes a value
//! of that field's kind (a number, a vector in any printed form, a flag); `{_}` takes anything;
//! `{{` and `}}` are literal braces; a run of spaces in the pattern matches any run of spaces
//! (or none). The pattern may start anywhere in the line (a timestamp before it is skipped) and
//! must run to its end (trailing spaces aside). `{!field}` reads a flag negated (a renderer that
//! prints `backfacing` or `inside` where the field is `entering`), and `\n` (or a line break)
//! ends one of the record's lines: a record printed over several lines, one vector a line, is
//! matched against that many of the log's lines joined (see [`super::gather`]).
//!
//! A pattern is user input, so it is bounded ([`MAX_PLACEHOLDERS`], [`MAX_PATTERN_BYTES`], each
//! field named once), and matching is a search without recursion that never tries the same
//! piece at the same place twice: its time and memory grow linearly with the line's length.

use super::error::PatternError;
use super::fields::{self, Dialect, Kind};
use super::limits::{MAX_PATTERN_BYTES, MAX_PATTERN_LINES, MAX_PLACEHOLDERS};
use super::record::accepts;

/// The longest text a field can take: a vector in its longest printed form fits easily.
const MAX_FIELD: usize = 512;

/// The most words (runs of non-space) a field's text can have: a vector's longest printed
/// form, `Vec3 { x: 0.6, y: -0.8, z: 0.0 }`, has 9, Node's `Float32Array(3) [ 1, 2, 3 ]` 6.
const MAX_FIELD_WORDS: usize = 12;

#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Literal(String),
    /// A field, its kind, and whether its flag is printed negated (`{!entering}`).
    Field(&'static str, Kind, bool),
    Anything,
}

impl Piece {
    /// The longest text the piece takes when it is not a literal.
    fn limit(&self, line: &str) -> usize {
        match self {
            Self::Anything => line.len(),
            _ => MAX_FIELD,
        }
    }

    /// The most words the piece's text can hold: a number or a flag is one word.
    fn max_words(&self) -> usize {
        match self {
            Self::Field(_, Kind::Number | Kind::Flag, _) => 1,
            Self::Field(_, Kind::Vector | Kind::VectorOrNull, _) => MAX_FIELD_WORDS,
            Self::Field(_, Kind::Label, _) | Self::Anything | Self::Literal(_) => usize::MAX,
        }
    }
}

/// A parsed `--pattern`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern {
    pieces: Vec<Piece>,
}

fn push_literal(pieces: &mut Vec<Piece>, c: char) {
    match pieces.last_mut() {
        Some(Piece::Literal(text)) => text.push(c),
        _ => pieces.push(Piece::Literal(c.to_string())),
    }
}

/// For each byte offset of `line` (and its end), where the run of white space starting there
/// ends: the offset itself where none starts. Worked out once per line, so that a literal's
/// space is matched in constant time however long the run (issue 40: a run of 80,000 spaces
/// took a minute when each place scanned it again).
fn space_ends(line: &str) -> Vec<usize> {
    let mut ends: Vec<usize> = (0..=line.len()).collect();
    for (i, c) in line.char_indices().rev() {
        if c.is_whitespace() {
            ends[i] = ends[i + c.len_utf8()];
        }
    }
    ends
}

/// A literal's match at `at` in `line`: its end, with a run of spaces matching any (or none);
/// `space_ends` is [`space_ends`] of `line`.
fn literal_at(literal: &str, line: &str, space_ends: &[usize], at: usize) -> Option<usize> {
    let mut pos = at;
    let mut chars = literal.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_whitespace() {
            while chars.peek().is_some_and(|c| c.is_whitespace()) {
                chars.next();
            }
            pos = space_ends[pos];
        } else if line[pos..].starts_with(c) {
            pos += c.len_utf8();
        } else {
            return None;
        }
    }
    Some(pos)
}

/// The pieces of `text`: literals, `{field}`s and `{_}`s.
fn pieces_of(dialect: Dialect, text: &str) -> Result<Vec<Piece>, PatternError> {
    let mut pieces = Vec::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '{' if chars.peek() == Some(&'{') => {
                chars.next();
                push_literal(&mut pieces, '{');
            }
            '}' if chars.peek() == Some(&'}') => {
                chars.next();
                push_literal(&mut pieces, '}');
            }
            '\\' if chars.peek() == Some(&'n') => {
                chars.next();
                push_literal(&mut pieces, '\n');
            }
            '{' => {
                let mut name = String::new();
                loop {
                    match chars.next() {
                        Some('}') => break,
                        Some(c) => name.push(c),
                        None => {
                            let pattern = text.to_owned();
                            return Err(PatternError::Unclosed { pattern });
                        }
                    }
                }
                pieces.push(Pattern::field(dialect, name.trim())?);
            }
            _ => push_literal(&mut pieces, c),
        }
    }
    Ok(pieces)
}

impl Pattern {
    /// Reads a pattern for `api`'s fields.
    ///
    /// # Errors
    /// A pattern longer than [`MAX_PATTERN_BYTES`] or with more than [`MAX_PLACEHOLDERS`]
    /// placeholders, an unknown field, a field named twice, an unclosed `{`, two fields with
    /// nothing between them, or no field.
    pub fn parse(dialect: impl Into<Dialect>, text: &str) -> Result<Self, PatternError> {
        if text.len() > MAX_PATTERN_BYTES {
            let bytes = text.len();
            return Err(PatternError::TooLong { bytes });
        }
        let pieces = pieces_of(dialect.into(), text)?;
        let placeholders = pieces
            .iter()
            .filter(|p| !matches!(p, Piece::Literal(_)))
            .count();
        if placeholders > MAX_PLACEHOLDERS {
            let count = placeholders;
            return Err(PatternError::TooManyPlaceholders { count });
        }
        let names: Vec<&str> = pieces
            .iter()
            .filter_map(|p| match p {
                Piece::Field(name, ..) => Some(*name),
                _ => None,
            })
            .collect();
        let twice = (1..names.len()).find(|&i| names[..i].contains(&names[i]));
        if let Some(i) = twice {
            let (field, pattern) = (names[i], text.to_owned());
            return Err(PatternError::Twice { field, pattern });
        }
        let adjacent = pieces
            .windows(2)
            .any(|w| !matches!(w[0], Piece::Literal(_)) && !matches!(w[1], Piece::Literal(_)));
        if adjacent {
            let pattern = text.to_owned();
            return Err(PatternError::Adjacent { pattern });
        }
        if names.is_empty() {
            let pattern = text.to_owned();
            return Err(PatternError::NoField { pattern });
        }
        let pattern = Self { pieces };
        if pattern.lines() > MAX_PATTERN_LINES {
            let count = pattern.lines();
            return Err(PatternError::TooManyLines { count });
        }
        Ok(pattern)
    }

    /// How many lines of the log a record takes: one more than the line breaks in the pattern.
    #[must_use]
    pub fn lines(&self) -> usize {
        let breaks: usize = self
            .pieces
            .iter()
            .map(|p| match p {
                Piece::Literal(text) => text.matches('\n').count(),
                _ => 0,
            })
            .sum();
        breaks + 1
    }

    /// The fields whose flags are printed negated (`{!entering}`).
    pub fn negated(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.pieces.iter().filter_map(|p| match p {
            Piece::Field(name, _, true) => Some(*name),
            _ => None,
        })
    }

    fn field(dialect: Dialect, name: &str) -> Result<Piece, PatternError> {
        if name == "_" {
            return Ok(Piece::Anything);
        }
        if let Some(flag) = name.strip_prefix('!') {
            return match fields::find(dialect, flag.trim()) {
                Some((name, Kind::Flag)) => Ok(Piece::Field(name, Kind::Flag, true)),
                _ => Err(PatternError::NegatedNotFlag {
                    field: flag.trim().to_owned(),
                }),
            };
        }
        fields::find(dialect, name)
            .map(|(name, kind)| Piece::Field(name, kind, false))
            .ok_or_else(|| PatternError::UnknownField {
                field: name.to_owned(),
                dialect,
            })
    }

    /// The texts of `line`'s fields, or `None` when it does not match.
    ///
    /// The literal parts are placed first (`Skeleton`: where each piece can start so that the
    /// rest of the pattern still fits, in one pass over the line per piece), then a search
    /// parses a field's text only where the skeleton leaves it room, and remembers every
    /// piece and place it has ruled out: a line that almost matches (the renderer's other log
    /// lines) is refused in time linear in its length, as a match is found.
    #[must_use]
    pub fn capture<'a>(&self, line: &'a str) -> Option<Vec<(&'static str, &'a str)>> {
        let (found, search) = self.search(line);
        found.then_some(search.out)
    }

    /// Whether `line` matches, and the search that found out.
    fn search<'p, 'a>(&'p self, line: &'a str) -> (bool, Search<'p, 'a>) {
        let mut search = Search::new(&self.pieces, line);
        let found = if matches!(self.pieces.first(), Some(Piece::Literal(_))) {
            boundaries(line).any(|start| search.run(start))
        } else {
            search.run(line.len() - line.trim_start().len())
        };
        (found, search)
    }
}

/// The byte offsets of `line`'s characters, and its end.
fn boundaries(line: &str) -> impl Iterator<Item = usize> + '_ {
    line.char_indices()
        .map(|(i, _)| i)
        .chain(core::iter::once(line.len()))
}

/// One bit for each piece of a pattern (and its end) at each byte offset of a line.
struct Grid {
    width: usize,
    bits: Vec<u64>,
}

impl Grid {
    fn new(pieces: usize, line: &str) -> Self {
        let width = line.len() + 1;
        Self {
            width,
            bits: vec![0; ((pieces + 1) * width).div_ceil(64)],
        }
    }

    fn get(&self, piece: usize, at: usize) -> bool {
        let i = piece * self.width + at;
        self.bits[i / 64] & (1 << (i % 64)) != 0
    }

    fn set(&mut self, piece: usize, at: usize) {
        let i = piece * self.width + at;
        self.bits[i / 64] |= 1 << (i % 64);
    }
}

/// Where each piece of a pattern can start in a line so that it and the pieces after it fit,
/// with a field taking any text of its length limit: the literal parts placed, nothing parsed.
struct Skeleton {
    fits: Grid,
    /// [`space_ends`] of the line.
    space_ends: Vec<usize>,
}

impl Skeleton {
    fn new(pieces: &[Piece], line: &str) -> Self {
        let len = line.len();
        let space_ends = space_ends(line);
        let mut fits = Grid::new(pieces.len(), line);
        let trailing = line.trim_end().len();
        for at in boundaries(line).filter(|&at| at >= trailing) {
            fits.set(pieces.len(), at);
        }
        // How many fitting places lie before each byte, to ask a field about a range of ends.
        let mut counted = vec![0_u32; len + 2];
        for (k, piece) in pieces.iter().enumerate().rev() {
            if let Piece::Literal(text) = piece {
                for at in boundaries(line) {
                    let end = literal_at(text, line, &space_ends, at);
                    if end.is_some_and(|end| fits.get(k + 1, end)) {
                        fits.set(k, at);
                    }
                }
                continue;
            }
            for at in 0..=len {
                counted[at + 1] = counted[at] + u32::from(fits.get(k + 1, at));
            }
            let limit = piece.limit(line);
            for at in boundaries(line).filter(|&at| at < len) {
                let last = (at + limit).min(len);
                if counted[last + 1] > counted[at + 1] {
                    fits.set(k, at);
                }
            }
        }
        Self { fits, space_ends }
    }

    /// Whether pieces `k..` fit from byte `at`.
    fn fits(&self, k: usize, at: usize) -> bool {
        self.fits.get(k, at)
    }
}

/// A piece being matched at a place: the next end to try for its text, and the words its
/// text holds up to there.
struct Frame {
    index: usize,
    at: usize,
    next: usize,
    words: usize,
    in_word: bool,
    /// How many captures were made before this piece.
    mark: usize,
}

impl Frame {
    fn new(index: usize, at: usize, mark: usize) -> Self {
        Self {
            index,
            at,
            next: at,
            words: 0,
            in_word: false,
            mark,
        }
    }
}

/// One line being matched: the skeleton, what has been ruled out, and the captures so far.
struct Search<'p, 'a> {
    pieces: &'p [Piece],
    line: &'a str,
    skeleton: Skeleton,
    /// Pieces found not to match from a place.
    failed: Grid,
    /// For each `{_}`, the first place it was found not to match from: it cannot match from any
    /// later place either, as its texts from there are a part of those it tried.
    anything_fails_from: Vec<usize>,
    out: Vec<(&'static str, &'a str)>,
    /// Texts parsed as a field's value: the work that grows with the line.
    parsed: usize,
}

impl<'p, 'a> Search<'p, 'a> {
    fn new(pieces: &'p [Piece], line: &'a str) -> Self {
        Self {
            pieces,
            line,
            skeleton: Skeleton::new(pieces, line),
            failed: Grid::new(pieces.len(), line),
            anything_fails_from: vec![usize::MAX; pieces.len()],
            out: Vec::new(),
            parsed: 0,
        }
    }

    /// Whether pieces `index..` may still match from `at`.
    fn open(&self, index: usize, at: usize) -> bool {
        self.skeleton.fits(index, at)
            && !self.failed.get(index, at)
            && self
                .anything_fails_from
                .get(index)
                .is_none_or(|&from| at < from)
    }

    /// Matches the whole pattern from `start`, depth first with a stack of its own, leaving
    /// the captures in `out`.
    fn run(&mut self, start: usize) -> bool {
        if !self.open(0, start) {
            return false;
        }
        let mut stack = vec![Frame::new(0, start, 0)];
        while let Some(top) = stack.last_mut() {
            if top.index == self.pieces.len() {
                return true;
            }
            if let Some(end) = self.next_end(top) {
                let next = Frame::new(top.index + 1, end, self.out.len());
                stack.push(next);
            } else if let Some(done) = stack.pop() {
                self.failed.set(done.index, done.at);
                if self.pieces[done.index] == Piece::Anything {
                    let from = &mut self.anything_fails_from[done.index];
                    *from = (*from).min(done.at);
                }
            }
        }
        false
    }

    /// The next end for `frame`'s piece after those tried, where the rest may still match
    /// (its capture pushed); `None` when none is left.
    fn next_end(&mut self, frame: &mut Frame) -> Option<usize> {
        self.out.truncate(frame.mark);
        let (piece, line, index) = (&self.pieces[frame.index], self.line, frame.index);
        if let Piece::Literal(text) = piece {
            // A literal has one place to end: tried once.
            if frame.next == usize::MAX {
                return None;
            }
            frame.next = usize::MAX;
            let ends = &self.skeleton.space_ends;
            return literal_at(text, line, ends, frame.at).filter(|&end| self.open(index + 1, end));
        }
        let (bytes, last) = (
            line.as_bytes(),
            (frame.at + piece.limit(line)).min(line.len()),
        );
        while frame.next < last {
            let space = bytes[frame.next].is_ascii_whitespace();
            frame.words += usize::from(!space && !frame.in_word);
            frame.in_word = !space;
            frame.next += 1;
            if frame.words > piece.max_words() {
                frame.next = last;
                return None;
            }
            let end = frame.next;
            if !line.is_char_boundary(end) || !self.open(index + 1, end) {
                continue;
            }
            let text = line[frame.at..end].trim();
            if let Piece::Field(name, kind, _) = piece {
                self.parsed += 1;
                if text.is_empty() || !accepts(*kind, text) {
                    continue;
                }
                self.out.push((name, text));
            }
            return Some(end);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::api::Api;

    fn rtiow(pattern: &str) -> Pattern {
        Pattern::parse(Api::Rtiow, pattern).unwrap()
    }

    #[test]
    #[expect(
        clippy::literal_string_with_formatting_args,
        reason = "a log pattern: its braces name fields"
    )]
    fn the_book_s_printf_line_in_every_vector_form() {
        let pattern = rtiow("LOG {uv} | {n} | {etai_over_etat} | {refracted} | {entering}");
        for (uv, n) in [
            ("0.6 -0.8 0", "0 1 0"),
            ("0.6, -0.8, 0", "[ 0, 1, 0 ]"),
            ("(0.6, -0.8, 0)", "vec3(0, 1, 0)"),
            (
                "Vec3 { x: 0.6, y: -0.8, z: 0.0 }",
                "glm::vec3(0.0f, 1.0f, 0.0f)",
            ),
        ] {
            let line = format!("12:00:01 LOG {uv} | {n} | 0.666667 | 0.4 -0.916515 0 | 1");
            let captured = pattern.capture(&line).unwrap_or_else(|| panic!("{line}"));
            assert_eq!(captured[0], ("uv", uv));
            assert_eq!(captured[1], ("n", n));
            assert_eq!(captured[4], ("entering", "1"));
        }
        assert_eq!(pattern.capture("LOG hit the sky"), None);
        assert_eq!(pattern.capture("LOG 1 2 3 | 0 1 0 | x | 1 2 3 | 1"), None);
    }

    #[test]
    fn fields_separated_by_spaces_or_commas_find_their_vectors() {
        let pattern = rtiow("{uv} {n} {etai_over_etat} {refracted}");
        let captured = pattern
            .capture("0.6 -0.8 0 0 1 0 1.5 inf nan -inf")
            .unwrap();
        assert_eq!(
            captured.iter().map(|c| c.1).collect::<Vec<_>>(),
            ["0.6 -0.8 0", "0 1 0", "1.5", "inf nan -inf"]
        );
        let pattern = rtiow("uv={uv}, n={n}, e={etai_over_etat}, r={refracted} {_}");
        let line = "uv=0.6, -0.8, 0, n=0, 1, 0, e=1.5, r=1, 2, 3 (depth 2)";
        assert_eq!(pattern.capture(line).unwrap()[1], ("n", "0, 1, 0"));
    }

    #[test]
    fn a_long_line_of_numbers_is_not_a_match() {
        // Its speed is measured in benches/diagnosis.rs; here only the answer.
        let pattern = rtiow("LOG {uv} | {n} {etai_over_etat} | {refracted} {_}");
        let line = format!("LOG {}", "1 | ".repeat(200_000));
        assert_eq!(pattern.capture(&line), None);
    }

    #[test]
    fn a_line_that_almost_matches_is_refused_without_parsing_a_field() {
        let pattern = rtiow("uv={uv} n={n} ratio={etai_over_etat} refracted={refracted}");
        let near = "uv=0.642788 -0.766044 0 n=0 1 0 ratio=0.666667 reflected=0.6 0.7 0";
        let skeleton = Skeleton::new(&pattern.pieces, near);
        assert!(
            !skeleton.fits(0, 0),
            "no place for the literal \"refracted=\""
        );
        assert_eq!(pattern.capture(near), None);
        let right = near.replace("reflected", "refracted");
        assert_eq!(pattern.capture(&right).unwrap()[3].1, "0.6 0.7 0");
    }

    #[test]
    fn a_field_named_twice_or_a_pattern_past_its_limits_is_refused() {
        let e = Pattern::parse(Api::Glsl, "I={I} N={N} again={I} eta={eta}")
            .unwrap_err()
            .to_string();
        assert!(e.contains("{I} is named twice"), "{e}");
        // Issue 31: 10,000 placeholders overflowed a worker's stack; now a usage error.
        let many = format!("{}{{I}}", "{_} ".repeat(10_000));
        let e = Pattern::parse(Api::Glsl, &many).unwrap_err().to_string();
        assert!(e.contains("at most 4096 are read"), "{e}");
        let many = format!("{}{{I}}", "{_} ".repeat(MAX_PLACEHOLDERS));
        let e = Pattern::parse(Api::Glsl, &many).unwrap_err().to_string();
        assert!(e.contains("33 placeholders: at most 32"), "{e}");
        let most = format!("{}{{I}}", "{_} ".repeat(MAX_PLACEHOLDERS - 1));
        assert!(Pattern::parse(Api::Glsl, &most).is_ok());
    }

    /// Fields parsed to refuse `line`, which must not match.
    fn parsed_to_refuse(pattern: &Pattern, line: &str) -> usize {
        let (found, search) = pattern.search(line);
        assert!(!found, "{line}");
        search.parsed
    }

    #[test]
    fn a_long_run_of_spaces_is_crossed_once() {
        // Issue 40: a run of 80,000 spaces between two fields took 64 s, each place of the run
        // scanning the rest of it again (quadratic); now each run's end is known once.
        let ends = space_ends("a  \u{a0}b ");
        assert_eq!(ends, vec![0, 5, 5, 5, 4, 5, 7, 7]);
        let pattern = rtiow("uv={uv} n={n} ratio={etai_over_etat} refracted={refracted}");
        let gap = " ".repeat(400_000);
        let line = format!("uv=0.6 -0.8 0 n=0 1 0{gap}ratio=0.666667 refracted=0.4 -0.9 0");
        assert!(pattern.capture(&line).is_some());
        let near = |gap: &str| format!("uv=0.6 -0.8 0 n=0 1 0{gap}ratio=0.666667 refracted=");
        let (long, short) = (near(&gap), near(&gap[..1000]));
        assert!(parsed_to_refuse(&pattern, &long) <= parsed_to_refuse(&pattern, &short) + 8);
        let spaces_only = format!("uv={gap}n={gap}");
        assert!(pattern.capture(&spaces_only).is_none());
    }

    #[test]
    fn near_misses_cost_work_linear_in_their_length() {
        // Issue 31: a line that repeats the pattern's literals without completing it cost 11
        // times a matching line per byte, and a 59 KB line with a large pattern 7.5 s.
        let pattern = rtiow(
            "uv={uv} n={n} ratio={etai_over_etat} front_face={entering} refracted={refracted}",
        );
        let unit = "uv=0.642788 -0.766044 0 n=0 1 0 ratio=0.666667 front_face=1 ";
        let short = parsed_to_refuse(&pattern, &unit.repeat(50));
        let long = parsed_to_refuse(&pattern, &unit.repeat(100));
        assert!(
            long <= 2 * short + 8,
            "{short} fields parsed for 50 repeats, {long} for 100"
        );
        let placeholders: String = (0..MAX_PLACEHOLDERS - 5).map(|_| "{_} | ").collect();
        let large = rtiow(&format!(
            "{placeholders}{{uv}} | {{n}} | {{etai_over_etat}} | {{refracted}} | {{entering}}"
        ));
        let line = "1 | 0.5 0.5 | x | ".repeat(3_500);
        assert!(line.len() > 59_000);
        let short = parsed_to_refuse(&large, &line[..line.len() / 2]);
        let long = parsed_to_refuse(&large, &line);
        assert!(
            long <= 2 * short + 64,
            "{short} fields parsed for half the line, {long} for all"
        );
    }

    #[test]
    fn bad_patterns_say_why() {
        let e = Pattern::parse(Api::Glsl, "{uv} {N}")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("unknown field {uv}") && e.contains("I, N, eta"),
            "{e}"
        );
        assert!(
            Pattern::parse(Api::Glsl, "{I}{N}")
                .unwrap_err()
                .to_string()
                .contains("nothing between")
        );
        assert!(
            Pattern::parse(Api::Glsl, "{I")
                .unwrap_err()
                .to_string()
                .contains("unclosed")
        );
        assert!(
            Pattern::parse(Api::Glsl, "just text")
                .unwrap_err()
                .to_string()
                .contains("no field")
        );
        assert!(Pattern::parse(Api::Glsl, "{{ {I} }}").is_ok());
    }
}

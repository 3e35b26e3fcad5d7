//! `--pattern`: log lines as a program printed them, such as
//! `LOG {uv} | {n} | {etai_over_etat} | {refracted} | {entering}`. Each `{field}` takes a value
//! of that field's kind (a number, a vector in any printed form, a flag); `{_}` takes anything;
//! `{{` and `}}` are literal braces; a run of spaces in the pattern matches any run of spaces
//! (or none). The pattern may start anywhere in the line (a timestamp before it is skipped) and
//! must run to its end (trailing spaces aside).

use refraction_i18n::t;

use super::fields::{self, Dialect, Kind};
use super::record::from_text;

/// Most attempts spent matching one line before it counts as not matching.
const BUDGET: usize = 100_000;

/// The longest text a field can take: a vector in its longest printed form fits easily.
const MAX_FIELD: usize = 512;

#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Literal(String),
    Field(&'static str, Kind),
    Anything,
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

/// A literal's match at `at` in `line`: its end, with a run of spaces matching any (or none).
fn literal_at(literal: &str, line: &str, at: usize) -> Option<usize> {
    let mut pos = at;
    let mut chars = literal.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_whitespace() {
            while chars.peek().is_some_and(|c| c.is_whitespace()) {
                chars.next();
            }
            pos += line[pos..].len() - line[pos..].trim_start().len();
        } else if line[pos..].starts_with(c) {
            pos += c.len_utf8();
        } else {
            return None;
        }
    }
    Some(pos)
}

impl Pattern {
    /// Reads a pattern for `api`'s fields.
    ///
    /// # Errors
    /// An unknown field, an unclosed `{`, two fields with nothing between them, or no field.
    pub fn parse(dialect: impl Into<Dialect>, text: &str) -> Result<Self, String> {
        let dialect = dialect.into();
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
                '{' => {
                    let mut name = String::new();
                    loop {
                        match chars.next() {
                            Some('}') => break,
                            Some(c) => name.push(c),
                            None => return Err(t!("check-pattern-unclosed", pattern = text)),
                        }
                    }
                    pieces.push(Self::field(dialect, name.trim())?);
                }
                _ => push_literal(&mut pieces, c),
            }
        }
        let adjacent = pieces
            .windows(2)
            .any(|w| !matches!(w[0], Piece::Literal(_)) && !matches!(w[1], Piece::Literal(_)));
        if adjacent {
            return Err(t!("check-pattern-adjacent", pattern = text));
        }
        if !pieces.iter().any(|p| matches!(p, Piece::Field(..))) {
            return Err(t!("check-pattern-no-field", pattern = text));
        }
        Ok(Self { pieces })
    }

    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn field(dialect: Dialect, name: &str) -> Result<Piece, String> {
        if name == "_" {
            return Ok(Piece::Anything);
        }
        fields::find(dialect, name)
            .map(|(name, kind)| Piece::Field(name, kind))
            .ok_or_else(|| {
                let (a, listed) = (dialect.name(), fields::listed(dialect));
                t!("check-pattern-unknown-field", field = name, api = a, expected = listed)
            })
    }

    /// The texts of `line`'s fields, or `None` when it does not match.
    ///
    /// The literal parts are placed first (`Skeleton`: where each piece can start so that the
    /// rest of the pattern still fits, in one pass over the line per piece), and a field's text
    /// is parsed only where the skeleton leaves it room: a line that almost matches (the
    /// renderer's other log lines) is refused in time linear in its length, as a match is
    /// found.
    #[must_use]
    pub fn capture<'a>(&self, line: &'a str) -> Option<Vec<(&'static str, &'a str)>> {
        let skeleton = Skeleton::new(&self.pieces, line);
        let first_literal = matches!(self.pieces.first(), Some(Piece::Literal(_)));
        let starts: Vec<usize> = if first_literal {
            boundaries(line).filter(|&i| skeleton.fits(0, i)).collect()
        } else {
            vec![line.len() - line.trim_start().len()]
        };
        let mut matching = Matching {
            pieces: &self.pieces,
            line,
            skeleton: &skeleton,
            out: Vec::new(),
            budget: BUDGET,
        };
        starts
            .into_iter()
            .any(|start| matching.from(0, start))
            .then_some(matching.out)
    }
}

/// The byte offsets of `line`'s characters, and its end.
fn boundaries(line: &str) -> impl Iterator<Item = usize> + '_ {
    line.char_indices()
        .map(|(i, _)| i)
        .chain(core::iter::once(line.len()))
}

/// Where each piece of a pattern can start in a line so that it and the pieces after it fit,
/// with a field taking any text of its length limit: the literal parts placed, nothing parsed.
struct Skeleton {
    /// `fits[k][at]`: pieces `k..` fit from byte `at`.
    fits: Vec<Vec<bool>>,
}

impl Skeleton {
    fn new(pieces: &[Piece], line: &str) -> Self {
        let len = line.len();
        let mut fits = vec![vec![false; len + 1]; pieces.len() + 1];
        for at in boundaries(line) {
            fits[pieces.len()][at] = line[at..].trim().is_empty();
        }
        // How many fitting ends lie before each byte, to ask a field about a range of ends.
        let mut counted = vec![0_u32; len + 2];
        for (k, piece) in pieces.iter().enumerate().rev() {
            let (before, after) = fits.split_at_mut(k + 1);
            let (here, next) = (&mut before[k], &after[0]);
            match piece {
                Piece::Literal(text) => {
                    for at in boundaries(line) {
                        here[at] = literal_at(text, line, at).is_some_and(|end| next[end]);
                    }
                }
                Piece::Field(..) | Piece::Anything => {
                    let limit = if *piece == Piece::Anything {
                        len
                    } else {
                        MAX_FIELD
                    };
                    for at in 0..=len {
                        counted[at + 1] = counted[at] + u32::from(next[at]);
                    }
                    for at in boundaries(line) {
                        let last = (at + limit).min(len);
                        here[at] = at < len && counted[last + 1] > counted[at + 1];
                    }
                }
            }
        }
        Self { fits }
    }

    /// Whether pieces `k..` fit from byte `at`.
    fn fits(&self, k: usize, at: usize) -> bool {
        self.fits[k][at]
    }
}

/// One line being matched: the captures so far and the attempts left.
struct Matching<'p, 'a> {
    pieces: &'p [Piece],
    line: &'a str,
    skeleton: &'p Skeleton,
    out: Vec<(&'static str, &'a str)>,
    budget: usize,
}

impl Matching<'_, '_> {
    /// Matches pieces `index..` at byte `at`, pushing captures.
    fn from(&mut self, index: usize, at: usize) -> bool {
        if self.budget == 0 || !self.skeleton.fits(index, at) {
            return false;
        }
        self.budget -= 1;
        match self.pieces.get(index) {
            None => true,
            Some(Piece::Literal(text)) => {
                literal_at(text, self.line, at).is_some_and(|end| self.from(index + 1, end))
            }
            Some(_) => self.field_from(index, at),
        }
    }

    /// Tries every end for the field at `index` (shortest first) where the rest of the pattern
    /// fits, parsing the field's text only there.
    fn field_from(&mut self, index: usize, at: usize) -> bool {
        let (piece, line) = (&self.pieces[index], self.line);
        let limit = if *piece == Piece::Anything {
            line.len()
        } else {
            MAX_FIELD
        };
        let ends: Vec<usize> = boundaries(line)
            .filter(|&end| end > at && end - at <= limit)
            .filter(|&end| self.skeleton.fits(index + 1, end))
            .collect();
        for end in ends {
            self.budget = self.budget.saturating_sub(1);
            let text = line[at..end].trim();
            let fits = match piece {
                Piece::Field(name, kind) => {
                    !text.is_empty() && from_text(*kind, name, text).is_ok()
                }
                _ => true,
            };
            if fits {
                let mark = self.out.len();
                if let Piece::Field(name, _) = piece {
                    self.out.push((name, text));
                }
                if self.from(index + 1, end) {
                    return true;
                }
                self.out.truncate(mark);
            }
            if self.budget == 0 {
                return false;
            }
        }
        false
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
    fn bad_patterns_say_why() {
        let e = Pattern::parse(Api::Glsl, "{uv} {N}").unwrap_err();
        assert!(
            e.contains("unknown field {uv}") && e.contains("I, N, eta"),
            "{e}"
        );
        assert!(
            Pattern::parse(Api::Glsl, "{I}{N}")
                .unwrap_err()
                .contains("nothing between")
        );
        assert!(
            Pattern::parse(Api::Glsl, "{I")
                .unwrap_err()
                .contains("unclosed")
        );
        assert!(
            Pattern::parse(Api::Glsl, "just text")
                .unwrap_err()
                .contains("no field")
        );
        assert!(Pattern::parse(Api::Glsl, "{{ {I} }}").is_ok());
    }
}

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
    #[must_use]
    pub fn capture<'a>(&self, line: &'a str) -> Option<Vec<(&'static str, &'a str)>> {
        let starts: Vec<usize> = match self.pieces.first() {
            Some(Piece::Literal(first)) => {
                let key = first.trim_start().chars().next();
                line.char_indices()
                    .map(|(i, _)| i)
                    .filter(|&i| key.is_none_or(|k| line[i..].starts_with(k)))
                    .collect()
            }
            _ => vec![line.len() - line.trim_start().len()],
        };
        let mut matching = Matching {
            pieces: &self.pieces,
            line,
            out: Vec::new(),
            budget: BUDGET,
        };
        starts
            .into_iter()
            .any(|start| matching.from(0, start))
            .then_some(matching.out)
    }
}

/// One line being matched: the captures so far and the attempts left.
struct Matching<'p, 'a> {
    pieces: &'p [Piece],
    line: &'a str,
    out: Vec<(&'static str, &'a str)>,
    budget: usize,
}

impl Matching<'_, '_> {
    /// Matches pieces `index..` at byte `at`, pushing captures.
    fn from(&mut self, index: usize, at: usize) -> bool {
        if self.budget == 0 {
            return false;
        }
        self.budget -= 1;
        match self.pieces.get(index) {
            None => self.line[at..].trim().is_empty(),
            Some(Piece::Literal(text)) => {
                literal_at(text, self.line, at).is_some_and(|end| self.from(index + 1, end))
            }
            Some(_) => self.field_from(index, at),
        }
    }

    /// Tries every end for the field at `index` (shortest first) where the next piece fits.
    fn field_from(&mut self, index: usize, at: usize) -> bool {
        let (piece, line) = (&self.pieces[index], self.line);
        let ends: Vec<usize> = match self.pieces.get(index + 1) {
            None => vec![line.len()],
            Some(_) => line[at..]
                .char_indices()
                .skip(1)
                .map(|(i, _)| at + i)
                .take_while(|&end| end - at <= MAX_FIELD || *piece == Piece::Anything)
                .collect(),
        };
        for end in ends {
            self.budget = self.budget.saturating_sub(1);
            let next_fits = match self.pieces.get(index + 1) {
                Some(Piece::Literal(next)) => literal_at(next, line, end).is_some(),
                _ => true,
            };
            let text = line[at..end].trim();
            let fits = next_fits
                && match piece {
                    Piece::Field(name, kind) => {
                        !text.is_empty()
                            && text.len() <= MAX_FIELD
                            && from_text(*kind, name, text).is_ok()
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
    fn a_long_line_of_numbers_ends_quickly_as_not_matching() {
        let pattern = rtiow("LOG {uv} | {n} {etai_over_etat} | {refracted} {_}");
        let line = format!("LOG {}", "1 | ".repeat(200_000));
        let start = std::time::Instant::now();
        assert_eq!(pattern.capture(&line), None);
        assert!(start.elapsed().as_secs_f64() < 5.0, "{:?}", start.elapsed());
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

//! `check --suggest-pattern`: a `--pattern` guessed from a log's first lines. Each value a
//! line prints (a vector in any printed form, a number, a flag, `None`) is found, named by the
//! word printed before it (`wi=`, `N:`, `tdir=`, Node's `d Float32Array(3) [...]`) through a
//! table of the names renderers use, and the rest of the line is kept as the pattern's words.
//! A record printed one value a line (Cycles' `print_float3`) is gathered over consecutive
//! lines. The guess is kept only if the pattern it makes reads the lines it came from.

use refraction_i18n::t;

use super::fields::{self, Dialect, Kind};
use super::gather;
use super::limits::MAX_PATTERN_LINES;
use super::pattern::Pattern;
use refraction_tools::vector_text::{parse_number, parse_vector};

/// The most lines of a log read for a suggestion.
pub const LINES_READ: usize = 200;

/// What a value printed in a line is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Value {
    Vector,
    Number,
    Flag,
    Null,
}

/// A value found in a line: where it is, its kind, and the word printed before it.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Span {
    start: usize,
    end: usize,
    value: Value,
    label: String,
    /// Where the word before it starts (the pattern starts there for the first field).
    label_start: usize,
}

/// What a log's name for a value means: a field, and how it is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Meaning {
    field: &'static str,
    negated: bool,
    toward_origin: bool,
}

/// The names renderers print before each value (lower case, `_` and letters only), by the
/// project's field for any renderer's lines.
const NAMES: [(&str, &[&str]); 7] = [
    (
        "w",
        &[
            "w",
            "d",
            "dir",
            "direction",
            "rd",
            "raydir",
            "ray",
            "uv",
            "i",
            "incident",
            "unit_direction",
            "r_d",
        ],
    ),
    ("n", &["n", "nl", "normal", "nf", "ns", "ng", "nn"]),
    (
        "t_yours",
        &[
            "t",
            "tdir",
            "wt",
            "wo",
            "refracted",
            "refraction",
            "result",
            "out",
            "transmitted",
            "t_yours",
            "refractionvector",
            "dir_out",
        ],
    ),
    (
        "ratio",
        // Not `eta`: GLSL's is μ, but pbrt's and Mitsuba's are the index inside over the one
        // outside, so without `--api` a printed `eta` is read as `{_}` (issue 40: read as μ,
        // pbrt's right lines were called wrong).
        &[
            "nnt",
            "ri",
            "ratio",
            "eta_ti",
            "inv_eta",
            "etai_over_etat",
            "refraction_ratio",
            "mu",
        ],
    ),
    (
        "entering",
        &[
            "entering",
            "into",
            "front_face",
            "frontface",
            "frontfacing",
            "front_facing",
            "outside",
            "enter",
        ],
    ),
    (
        "!entering",
        &["inside", "backfacing", "back_face", "exiting", "leaving"],
    ),
    ("returned", &["ok", "returned", "valid"]),
];

/// Names that print the incident vector pointing back toward the ray's origin.
const TOWARD_ORIGIN: [&str; 3] = ["wi", "v", "view"];

/// The field a printed name means in `dialect`, if any.
fn meaning(dialect: Dialect, label: &str, value: Value) -> Option<Meaning> {
    let label = label.to_ascii_lowercase();
    let toward = TOWARD_ORIGIN.contains(&label.as_str());
    let physics_name = if toward {
        Some("w")
    } else {
        NAMES
            .iter()
            .find(|(_, names)| names.contains(&label.as_str()))
            .map(|(field, _)| *field)
    };
    let (negated, name) = match physics_name {
        Some(name) => name
            .strip_prefix('!')
            .map_or((false, name), |rest| (true, rest)),
        None => (false, label.as_str()),
    };
    let field = match dialect {
        Dialect::Physics => name,
        Dialect::Api(api) => {
            let names = fields::names(api);
            match (fields::find(dialect, &label), name) {
                (Some((field, _)), _) => field,
                (None, "w") => names.incident,
                (None, "n") => names.normal,
                (None, "ratio") => names.eta,
                (None, "t_yours") => names.result,
                (None, other) => other,
            }
        }
    };
    let (field, kind) = fields::find(dialect, field)?;
    let fits = match kind {
        Kind::Vector => value == Value::Vector,
        Kind::VectorOrNull => matches!(value, Value::Vector | Value::Null),
        Kind::Number => value == Value::Number,
        Kind::Flag => matches!(value, Value::Flag | Value::Number),
        Kind::Label => false,
    };
    fits.then_some(Meaning {
        field,
        negated,
        toward_origin: toward && dialect == Dialect::Physics,
    })
}

/// The longest line part read for a suggestion, in bytes (a record is a few hundred).
const MAX_LINE: usize = 4096;

/// The longest bracket group read as a value, in bytes.
const MAX_GROUP: usize = 512;

/// The end of the bracket group opening at `open`, if it closes within [`MAX_GROUP`] bytes.
fn group_end(line: &str, open: usize) -> Option<usize> {
    let mut depth = 0_i64;
    for (i, b) in line.bytes().enumerate().skip(open).take(MAX_GROUP) {
        match b {
            b'[' | b'(' | b'{' => depth += 1,
            b']' | b')' | b'}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
    }
    None
}

/// The end of the word (a number's text) starting at `at`.
fn word_end(line: &str, at: usize) -> usize {
    line[at..]
        .find(|c: char| c.is_whitespace() || ",;)]}|".contains(c))
        .map_or(line.len(), |i| at + i)
}

/// A vector in brackets starting at `at` (after an optional type name such as `vec3` or
/// Node's `Float32Array(3) `): its end.
fn bracketed(line: &str, at: usize) -> Option<usize> {
    let rest = &line[at..];
    let name = rest
        .find(|c: char| !(c.is_alphanumeric() || matches!(c, '_' | ':')))
        .unwrap_or(rest.len());
    let mut open = at + name;
    if line[open..].starts_with('(') && !line[at..open].is_empty() {
        // Node's `Float32Array(3) [`: the count, then the elements.
        let count_end = group_end(line, open)?;
        let after = line[count_end..].trim_start();
        if after.starts_with('[') {
            open = line.len() - after.len();
        }
    }
    if !line[open..].starts_with(|c| "([{".contains(c)) {
        return None;
    }
    let end = group_end(line, open)?;
    parse_vector(&line[at..end]).is_ok().then_some(end)
}

/// Three numbers from `at`, separated by spaces or commas: their end.
fn bare_vector(line: &str, at: usize) -> Option<usize> {
    let mut end = at;
    for i in 0..3 {
        let start = if i == 0 {
            at
        } else {
            let skipped = line[end..]
                .find(|c: char| !(c.is_whitespace() || c == ','))
                .unwrap_or(line.len() - end);
            end + skipped
        };
        let word_end = word_end(line, start);
        if start >= word_end || parse_number(&line[start..word_end]).is_err() {
            return None;
        }
        end = word_end;
    }
    Some(end)
}

/// The value starting at `at`, if one does: its end and kind.
fn value_at(line: &str, at: usize) -> Option<(usize, Value)> {
    let before = line[..at].chars().next_back();
    if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '.') {
        return None;
    }
    if let Some(end) = bracketed(line, at) {
        return Some((end, Value::Vector));
    }
    if let Some(end) = bare_vector(line, at) {
        return Some((end, Value::Vector));
    }
    let end = word_end(line, at);
    let word = &line[at..end];
    match word.to_ascii_lowercase().as_str() {
        "true" | "false" => Some((end, Value::Flag)),
        "none" | "null" | "nullptr" | "undefined" => Some((end, Value::Null)),
        _ if word.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '-' | '+' | '.'))
            && parse_number(word).is_ok() =>
        {
            Some((end, Value::Number))
        }
        _ => None,
    }
}

/// The word just before `at` (the value's name) and where it starts.
fn label_before(line: &str, from: usize, at: usize) -> (String, usize) {
    let text = &line[from..at];
    let trimmed = text.trim_end_matches(|c: char| !(c.is_alphanumeric() || c == '_'));
    let start = trimmed
        .char_indices()
        .rev()
        .find(|(_, c)| !(c.is_alphanumeric() || *c == '_'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    (trimmed[start..].to_owned(), from + start)
}

/// The values printed in `line` (its first [`MAX_LINE`] bytes), in order.
fn spans(line: &str) -> Vec<Span> {
    let mut cut = line.len().min(MAX_LINE);
    while !line.is_char_boundary(cut) {
        cut -= 1;
    }
    let line = &line[..cut];
    let mut out = Vec::new();
    let (mut at, mut from) = (0, 0);
    while at < line.len() {
        if !line.is_char_boundary(at) {
            at += 1;
            continue;
        }
        match value_at(line, at) {
            Some((end, value)) => {
                let (label, label_start) = label_before(line, from, at);
                out.push(Span {
                    start: at,
                    end,
                    value,
                    label,
                    label_start,
                });
                (at, from) = (end, end);
            }
            None => at += 1,
        }
    }
    out
}

/// Text of a log kept as a pattern's words: braces doubled.
fn literal(text: &str) -> String {
    text.replace('{', "{{").replace('}', "}}")
}

/// A suggested `--pattern` and what else the command needs.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Suggestion {
    /// The pattern, with `\n` between the lines of a record.
    pub pattern: String,
    /// `--convention toward-origin` is needed: the incident vector is printed as `wi`.
    pub toward_origin: bool,
    /// No normal is printed: `--normal` is needed (a local frame's +z).
    pub no_normal: bool,
    /// Nothing printed says which side the ray arrives from.
    pub no_side: bool,
    /// The object's index as `--inside` takes it (with `--outside 1`) where the lines print
    /// `entering`: read from the ratio they print (see [`inside_index`]), else glass's
    /// ([`GLASS`], `inside_assumed`); `None` when they print no side, or the ratios of more
    /// than one material.
    pub inside: Option<String>,
    /// Whether `inside` is glass's, assumed because the lines print no ratio of one material.
    pub inside_assumed: bool,
}

/// The index `--suggest-pattern` assumes for an object whose lines print no ratio: glass's,
/// the one the book, smallpt and pbrt's scenes use.
pub const GLASS: &str = "1.5";

/// The pattern for one record's lines, if they print the fields a check needs.
fn pattern_for(dialect: Dialect, lines: &[&str]) -> Option<Suggestion> {
    let mut taken: Vec<&'static str> = Vec::new();
    let mut parts: Vec<String> = Vec::new();
    let mut toward_origin = false;
    for (i, line) in lines.iter().enumerate() {
        let spans = spans(line);
        let vectors_left = |from: usize| {
            spans[from..]
                .iter()
                .filter(|s| s.value == Value::Vector)
                .count()
        };
        let mut text = String::new();
        let mut cursor = None;
        for (k, span) in spans.iter().enumerate() {
            let mut found =
                meaning(dialect, &span.label, span.value).filter(|m| !taken.contains(&m.field));
            let result = result_field(dialect);
            if found.is_none()
                && span.value == Value::Vector
                && vectors_left(k) == 1
                && i + 1 == lines.len()
                && !taken.contains(&result)
            {
                found = Some(Meaning {
                    field: result,
                    negated: false,
                    toward_origin: false,
                });
            }
            let start = match cursor {
                Some(c) => c,
                None if found.is_some() => {
                    if i == 0 {
                        span.label_start
                    } else {
                        0
                    }
                }
                None => continue,
            };
            text.push_str(&literal(&line[start..span.start]));
            match found {
                Some(m) => {
                    taken.push(m.field);
                    toward_origin |= m.toward_origin;
                    let bang = if m.negated { "!" } else { "" };
                    text.push_str(&format!("{{{bang}{}}}", m.field));
                }
                None => text.push_str("{_}"),
            }
            cursor = Some(span.end);
        }
        match cursor {
            Some(c) => {
                let rest = &line[c..];
                text.push_str(&literal(rest.trim_end()));
            }
            None if i == 0 => return None,
            None => text.push_str(&literal(line.trim())),
        }
        parts.push(text);
    }
    complete(dialect, &taken).then(|| Suggestion {
        pattern: parts.join("\\n"),
        toward_origin,
        no_normal: !taken.contains(&normal_field(dialect)),
        no_side: !taken.contains(&"entering"),
        inside: None,
        inside_assumed: false,
    })
}

fn result_field(dialect: Dialect) -> &'static str {
    dialect
        .api()
        .map_or("t_yours", |api| fields::names(api).result)
}

fn normal_field(dialect: Dialect) -> &'static str {
    dialect.api().map_or("n", |api| fields::names(api).normal)
}

/// Whether the fields taken make a record: the incident vector and the result, and for an
/// API its ratio.
fn complete(dialect: Dialect, taken: &[&'static str]) -> bool {
    match dialect.api() {
        None => taken.contains(&"w") && taken.contains(&"t_yours"),
        Some(api) => {
            let n = fields::names(api);
            [n.incident, n.eta, n.result]
                .iter()
                .all(|f| taken.contains(f))
        }
    }
}

/// Whether `pattern` reads the record it was made from.
fn reads(dialect: Dialect, suggestion: &Suggestion, lines: &[&str]) -> bool {
    Pattern::parse(dialect, &suggestion.pattern)
        .is_ok_and(|p| p.capture(&lines.join("\n")).is_some())
}

/// The object's index read from the ratio `pattern` reads in `lines`: a ratio r printed for
/// a ray entering or leaving is the object's index over its surroundings' or the inverse,
/// whichever way round the code (right or not) puts it, so the object's index is the larger
/// of r and 1/r for an object denser than what is outside it (glass or water in air, taken
/// as 1). Written to the digits the ratio was printed with.
#[must_use]
pub fn inside_index(dialect: Dialect, pattern: &Pattern, lines: &[&str]) -> Index {
    let field = dialect.api().map_or("ratio", |api| fields::names(api).eta);
    let span = pattern.lines();
    let mut best: Option<(f64, u32)> = None;
    for record in lines.windows(span) {
        let text = record.join("\n");
        let Some(found) = pattern.capture(&text) else {
            continue;
        };
        let Some(number) = found
            .iter()
            .find(|(name, _)| *name == field)
            .and_then(|(_, text)| parse_number(text).ok())
            .filter(|n| n.value.is_finite() && n.value > 0.0)
        else {
            continue;
        };
        let index = number.value.max(1.0 / number.value);
        match best {
            Some((seen, _)) if (index / seen - 1.0).abs() > 0.01 => return Index::Several,
            Some((_, digits)) if digits >= number.digits => {}
            _ => best = Some((index, number.digits)),
        }
    }
    let Some((index, digits)) = best.filter(|(index, _)| *index > 1.0 + 1e-6) else {
        return Index::Unprinted;
    };
    let digits = usize::try_from(digits.clamp(1, 9)).unwrap_or(9);
    // `{:.*e}` rounds to that many significant digits; read back, it prints plainly.
    format!("{index:.*e}", digits - 1)
        .parse::<f64>()
        .map_or(Index::Unprinted, |rounded| Index::Read(rounded.to_string()))
}

/// What a log's printed ratios say of the object's index ([`inside_index`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Index {
    /// The index, as `--inside` takes it.
    Read(String),
    /// No line prints a ratio (other than 1).
    Unprinted,
    /// Lines print the ratios of more than one material.
    Several,
}

/// How a JSON line starts: such a line is read as it is, with no pattern.
const JSON_OBJECT: char = '{';

/// The pattern for the first record found in `lines` (a log's first lines): a record on one
/// line, else over up to [`MAX_PATTERN_LINES`] consecutive lines (values printed over several
/// lines, as Node prints a typed array, are joined first).
#[must_use]
pub fn suggest(dialect: Dialect, lines: &[&str]) -> Option<Suggestion> {
    let logical = gather::joined(lines.iter().copied());
    let logical: Vec<&str> = logical
        .iter()
        .map(String::as_str)
        .filter(|l| !l.trim().is_empty())
        .collect();
    for first in 0..logical.len() {
        if logical[first].trim_start().starts_with(JSON_OBJECT) {
            continue; // a JSON line needs no pattern
        }
        for count in 1..=MAX_PATTERN_LINES.min(logical.len() - first) {
            let record = &logical[first..first + count];
            if let Some(mut s) = pattern_for(dialect, record).filter(|s| reads(dialect, s, record))
            {
                if !s.no_side {
                    let read = Pattern::parse(dialect, &s.pattern)
                        .map_or(Index::Unprinted, |p| inside_index(dialect, &p, &logical));
                    s.inside_assumed = read == Index::Unprinted;
                    s.inside = match read {
                        Index::Read(index) => Some(index),
                        Index::Unprinted => Some(GLASS.to_owned()),
                        Index::Several => None,
                    };
                }
                return Some(s);
            }
        }
    }
    None
}

/// Whether `lines` print vectors one number a line (Eigen's `cout << v` of a `Vector3d`, a
/// column): three or more lines in a row that hold a single number and nothing else.
#[must_use]
pub fn column_printed(lines: &[&str]) -> bool {
    let lone = |line: &&str| {
        let t = line.trim().trim_end_matches([',', ';']);
        !t.is_empty() && parse_number(t).is_ok()
    };
    let mut run = 0;
    for line in lines {
        run = if lone(line) { run + 1 } else { 0 };
        if run >= 3 {
            return true;
        }
    }
    false
}

/// What to tell the user besides the pattern: the options the log needs, in sentences.
#[must_use]
pub fn hints(suggestion: &Suggestion, dialect: Dialect) -> Vec<String> {
    let mut out = Vec::new();
    if suggestion.toward_origin {
        out.push(t!("check-suggest-toward-origin"));
    }
    if suggestion.no_normal && dialect == Dialect::Physics {
        out.push(t!("check-suggest-no-normal"));
    }
    if suggestion.no_side {
        out.push(t!("check-suggest-no-side"));
    }
    match &suggestion.inside {
        Some(inside) if suggestion.inside_assumed => {
            out.push(t!(
                "check-suggest-indices-assumed",
                inside = inside.as_str()
            ));
        }
        Some(inside) => out.push(t!("check-suggest-indices-read", inside = inside.as_str())),
        None => {}
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_kernel::api::Api;

    fn pattern(dialect: Dialect, log: &str) -> String {
        let lines: Vec<&str> = log.lines().collect();
        suggest(dialect, &lines)
            .map(|s| s.pattern)
            .unwrap_or_default()
    }

    #[test]
    fn a_printf_line_with_names_before_its_values() {
        let log =
            "Rendering (4 spp)\nREFR d=(0.1 -0.9 0.0) nl=(0 1 0) into=1 tdir=(0.2 -0.97 0) depth 3";
        assert_eq!(
            pattern(Dialect::Physics, log),
            "d={w} nl={n} into={entering} tdir={t_yours} depth {_}"
        );
        let pbrt =
            "Refract wi=[ 0.6, 0.8, 0 ] n=[ 0, 1, 0 ] eta=1.5 -> wt=[ -0.4, -0.9, 0 ] ok=true";
        assert_eq!(
            pattern(Dialect::Api(Api::Pbrt), pbrt),
            "wi={wi} n={n} eta={eta} -> wt={wt} ok={returned}"
        );
    }

    #[test]
    fn python_s_none_and_a_backfacing_flag_negated() {
        let log = "wi [0.1, 0.2, 0.97] backfacing True wo None";
        let s = suggest(Dialect::Physics, &[log]).unwrap();
        assert_eq!(s.pattern, "wi {w} backfacing {!entering} wo {t_yours}");
        assert!(s.toward_origin && s.no_normal && !s.no_side);
    }

    #[test]
    fn cycles_one_vector_a_line_and_node_s_arrays_over_lines() {
        let cycles = "wi: 0.10000000 0.20000000 0.97467943\nN: 0.00000000 0.00000000 1.00000000\n\
                      wo: -0.06666667 -0.13333334 -0.98882646";
        assert_eq!(
            pattern(Dialect::Physics, cycles),
            "wi: {w}\\nN: {n}\\nwo: {t_yours}"
        );
        let node = "d Float32Array(3) [\n  0.39162999391555786,\n  -0.5874453186988831,\n  \
                    -0.7080398797988892\n] n Float32Array(3) [ 0, 0, 1 ] -> Float32Array(3) [ 0.5, -0.25, -0.800000011920929 ]";
        assert_eq!(pattern(Dialect::Physics, node), "d {w} n {n} -> {t_yours}");
    }

    #[test]
    fn names_after_other_scripts_and_long_lines_cost_little() {
        let log = "→wi=[0.1, 0.2, 0.97] é wo=[0.1, 0.2, 0.97]";
        assert_eq!(pattern(Dialect::Physics, log), "wi={w} é wo={t_yours}");
        let long = format!("{} t=1 2 3", "[".repeat(100_000));
        assert_eq!(pattern(Dialect::Physics, &long), "");
    }

    #[test]
    fn the_object_s_index_is_read_from_the_printed_ratio_where_entering_is_printed() {
        let glsl = Dialect::Api(Api::Glsl);
        let log = "I (0.6, -0.8, 0) N (0, 1, 0) eta 0.666667 entering true -> (0.4, -0.9, 0)\n\
                   I (0.6, 0.8, 0) N (0, -1, 0) eta 1.5 entering false -> (0.9, 0.4, 0)";
        let lines: Vec<&str> = log.lines().collect();
        let s = suggest(glsl, &lines).unwrap();
        assert_eq!(
            (s.inside.as_deref(), s.inside_assumed),
            (Some("1.5"), false)
        );
        // An inverted ratio (the student's bug) gives the same index: it is not trusted.
        let inverted = log
            .replace("0.666667", "1.5 ")
            .replace("eta 1.5 entering false", "eta 0.666667 entering false");
        let lines: Vec<&str> = inverted.lines().collect();
        assert_eq!(
            suggest(glsl, &lines).unwrap().inside.as_deref(),
            Some("1.5")
        );
        // Two materials: no one index; no ratio printed: glass assumed; no side: none needed.
        let two = format!(
            "{log}\nI (0.6, -0.8, 0) N (0, 1, 0) eta 0.75 entering true -> (0.45, -0.89, 0)"
        );
        let lines: Vec<&str> = two.lines().collect();
        assert_eq!(suggest(glsl, &lines).unwrap().inside, None);
        let smallpt = "REFR d=(0.6 -0.8 0) nl=(0 1 0) into=1 tdir=(0.4 -0.9 0)";
        let s = suggest(Dialect::Physics, &[smallpt]).unwrap();
        assert_eq!((s.inside.as_deref(), s.inside_assumed), (Some(GLASS), true));
        let sideless = "I (0.6, -0.8, 0) N (0, 1, 0) eta 0.666667 -> (0.4, -0.9, 0)";
        assert_eq!(suggest(glsl, &[sideless]).unwrap().inside, None);
    }

    #[test]
    fn lines_without_a_refraction_suggest_nothing() {
        assert_eq!(pattern(Dialect::Physics, "hello\n12 apples"), "");
        assert_eq!(pattern(Dialect::Physics, r#"{"w":[0,-1,0]}"#), "");
    }
}

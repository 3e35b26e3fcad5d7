//! The glossary holds: in every language, no message uses a variant the glossary forbids.
//!
//! `locales/GLOSSARY.md` has one section per language (`## de …`) with a table whose
//! `Forbidden` column lists, in backticks, the words and spellings that language must not use
//! for the term of the row, and whose `Allowed in` column names the messages where such a word
//! means something else (the fibre's core, the computer's screen). A variant matches:
//!
//! - at the edges of words: `Kern` is not found in `Kernel`, but is in `b-Kern`;
//! - with a trailing `*`, followed by anything: `Kernaufruf*` finds `Kernaufrufe`;
//! - in any case when written in lowercase, and exactly as written when it holds a capital
//!   (`tg` finds `Tg`; `Sie` does not find `sie`);
//! - with `␣` standing for an ordinary space (`␣:` is a space before a colon, where French
//!   puts a no-break space), and `{…}` for any placeable (`em {…} nm`).
//!
//! Only what a user reads is searched: message values, their attributes and every variant of a
//! selector, with each placeable (`{ $mu }`) read as a mark that is not a word.

use std::path::{Path, PathBuf};

use fluent_syntax::ast::{Entry, Expression, InlineExpression, Pattern, PatternElement};
use refraction_i18n::{FILES, Locale};

/// What a placeable reads as: not a letter, so that it ends a word.
const PLACEABLE: char = '\u{FFFC}';

/// One row of a language's glossary table.
#[derive(Debug)]
struct Rule {
    /// The English term, as the first column names it.
    term: String,
    /// The variants the language must not use for it.
    forbidden: Vec<String>,
    /// The keys of the messages where a forbidden variant means something else.
    allowed_in: Vec<String>,
}

fn locales() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("locales")
}

fn glossary_text() -> String {
    std::fs::read_to_string(locales().join("GLOSSARY.md")).expect("locales/GLOSSARY.md")
}

/// The texts between backticks in a table cell.
fn quoted(cell: &str) -> Vec<String> {
    cell.split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_owned)
        .collect()
}

/// The cells of a table row, without the outer bars.
fn cells(row: &str) -> Vec<&str> {
    let inner = row.trim().trim_start_matches('|').trim_end_matches('|');
    inner.split('|').map(str::trim).collect()
}

/// Every language's rules, in the order the glossary gives them. A table's columns are found
/// by their headings, so that the prose columns can be moved or renamed freely.
fn rules(glossary: &str) -> Vec<(Locale, Vec<Rule>)> {
    let mut sections: Vec<(Locale, Vec<Rule>)> = Vec::new();
    let mut columns: Option<(usize, usize)> = None;
    // A heading that names no language ends the section before it.
    let mut in_section = false;
    for line in glossary.lines() {
        if let Some(heading) = line.strip_prefix("## ") {
            let code = heading.split_whitespace().next().unwrap_or_default();
            let locale = Locale::ALL.into_iter().find(|l| l.code() == code);
            sections.extend(locale.map(|l| (l, Vec::new())));
            in_section = locale.is_some();
            columns = None;
            continue;
        }
        if !line.trim_start().starts_with('|') {
            continue;
        }
        let row = cells(line);
        let heading = |name: &str| row.iter().position(|c| c.eq_ignore_ascii_case(name));
        if let (Some(forbidden), Some(allowed)) = (heading("forbidden"), heading("allowed in")) {
            columns = Some((forbidden, allowed));
            continue;
        }
        let is_rule = row
            .iter()
            .any(|c| !c.chars().all(|c| matches!(c, '-' | ':')));
        let (Some((forbidden, allowed)), Some((_, section)), true) =
            (columns, sections.last_mut(), is_rule && in_section)
        else {
            continue;
        };
        section.push(Rule {
            term: row.first().copied().unwrap_or_default().to_owned(),
            forbidden: quoted(row.get(forbidden).copied().unwrap_or_default()),
            allowed_in: quoted(row.get(allowed).copied().unwrap_or_default()),
        });
    }
    sections
}

fn text_of_pattern(pattern: &Pattern<&str>, into: &mut String) {
    for element in &pattern.elements {
        match element {
            PatternElement::TextElement { value } => into.push_str(value),
            PatternElement::Placeable { expression } => text_of_expression(expression, into),
        }
    }
}

/// A selector's variants each on a line of their own, a string literal as its text (`{"{"}`),
/// any other placeable as [`PLACEABLE`].
fn text_of_expression(expression: &Expression<&str>, into: &mut String) {
    match expression {
        Expression::Select { variants, .. } => {
            for variant in variants {
                into.push('\n');
                text_of_pattern(&variant.value, into);
            }
            into.push('\n');
        }
        Expression::Inline(InlineExpression::StringLiteral { value }) => into.push_str(value),
        Expression::Inline(InlineExpression::Placeable { expression }) => {
            text_of_expression(expression, into);
        }
        Expression::Inline(_) => into.push(PLACEABLE),
    }
}

/// The key and the text a user reads of every message in `source`.
fn message_texts(source: &str) -> Vec<(String, String)> {
    let resource = fluent_syntax::parser::parse(source).expect("the translations test parses");
    resource
        .body
        .iter()
        .filter_map(|entry| match entry {
            Entry::Message(message) => Some(message),
            _ => None,
        })
        .map(|message| {
            let mut text = String::new();
            if let Some(value) = &message.value {
                text_of_pattern(value, &mut text);
            }
            for attribute in &message.attributes {
                text.push('\n');
                text_of_pattern(&attribute.value, &mut text);
            }
            (message.id.name.to_owned(), text)
        })
        .collect()
}

/// Every message of `locale`, each with the file it is in.
fn messages_of(locale: Locale) -> Vec<(&'static str, String, String)> {
    FILES
        .iter()
        .flat_map(|file| {
            let path = locales().join(locale.code()).join(file);
            let source = std::fs::read_to_string(&path).expect("a locale file");
            message_texts(&source)
                .into_iter()
                .map(move |(key, text)| (*file, key, text))
        })
        .collect()
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether `variant` occurs in `text`, by the rules in this file's header.
fn occurs(text: &str, variant: &str) -> bool {
    let (body, open_end) = variant
        .strip_suffix('*')
        .map_or((variant, false), |body| (body, true));
    let body = body.replace("{…}", &PLACEABLE.to_string());
    let pattern: Vec<char> = body
        .chars()
        .map(|c| if c == '␣' { ' ' } else { c })
        .collect();
    let (Some(&first), Some(&last)) = (pattern.first(), pattern.last()) else {
        return false;
    };
    let any_case = !pattern.iter().any(|c| c.is_uppercase());
    let same = |t: char, p: char| {
        if any_case {
            t.to_lowercase().eq(p.to_lowercase())
        } else {
            t == p
        }
    };
    let chars: Vec<char> = text.chars().collect();
    (0..chars.len()).any(|at| {
        let end = at + pattern.len();
        let here = chars
            .get(at..end)
            .is_some_and(|found| found.iter().zip(&pattern).all(|(t, p)| same(*t, *p)));
        let joined_before = is_word(first) && at > 0 && is_word(chars[at - 1]);
        let joined_after =
            !open_end && is_word(last) && chars.get(end).is_some_and(|c| is_word(*c));
        here && !joined_before && !joined_after
    })
}

/// Every use of a forbidden variant among `messages` (file, key, text), as a line to report.
fn violations(rules: &[Rule], messages: &[(&str, String, String)]) -> Vec<String> {
    let mut found = Vec::new();
    for rule in rules {
        for (file, key, text) in messages {
            if rule.allowed_in.iter().any(|allowed| allowed == key) {
                continue;
            }
            for variant in rule.forbidden.iter().filter(|v| occurs(text, v)) {
                let shown = text.replace(PLACEABLE, "{…}").replace('\n', " ");
                found.push(format!(
                    "{file} `{key}`: `{variant}` is forbidden for “{}”: {shown}",
                    rule.term
                ));
            }
        }
    }
    found
}

#[test]
fn every_translation_has_a_glossary_whose_exceptions_exist() {
    let sections = rules(&glossary_text());
    let mut problems = Vec::new();
    for locale in Locale::ALL.into_iter().filter(|l| *l != Locale::En) {
        let Some((_, rules)) = sections.iter().find(|(l, _)| *l == locale) else {
            problems.push(format!(
                "{locale}: no section `## {locale}` in the glossary"
            ));
            continue;
        };
        if rules.iter().filter(|r| !r.forbidden.is_empty()).count() < 10 {
            problems.push(format!("{locale}: fewer than 10 rules forbid anything"));
        }
        let keys: Vec<String> = messages_of(locale).into_iter().map(|(_, k, _)| k).collect();
        for rule in rules {
            for key in rule.allowed_in.iter().filter(|k| !keys.contains(k)) {
                problems.push(format!("{locale} “{}”: no message `{key}`", rule.term));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn no_message_uses_a_variant_its_glossary_forbids() {
    let mut problems = Vec::new();
    for (locale, rules) in rules(&glossary_text()) {
        let found = violations(&rules, &messages_of(locale));
        problems.extend(found.into_iter().map(|v| format!("{locale} {v}")));
    }
    assert!(
        problems.is_empty(),
        "{} uses of forbidden variants (see crates/refraction-i18n/locales/GLOSSARY.md):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn a_planted_violation_is_found_and_an_exception_is_not() {
    let sections = rules(&glossary_text());
    let (_, german) = sections
        .iter()
        .find(|(l, _)| *l == Locale::De)
        .expect("a German section");
    let mut messages = messages_of(Locale::De);
    assert!(violations(german, &messages).is_empty());
    messages.push((
        "diagram.ftl",
        "planted".to_owned(),
        format!("{PLACEABLE} Kernaufrufe"),
    ));
    let found = violations(german, &messages);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("`planted`"), "{found:?}");
    // The fibre's core is a Kern: the glossary allows it there.
    let core = (
        "diagram.ftl",
        "diagram-medium-core".to_owned(),
        "Kern".to_owned(),
    );
    assert!(violations(german, &[core]).is_empty());
}

#[test]
fn variants_match_whole_words_in_smart_case_with_open_ends_and_spaces() {
    assert!(occurs("der Kern dreht", "Kern"));
    assert!(occurs("andere b-Kern", "Kern"));
    assert!(!occurs("der Kernel dreht", "Kern"));
    assert!(!occurs("der kern", "Kern"));
    assert!(occurs("3 Kernaufrufe", "Kernaufruf*"));
    assert!(occurs("Tg θB", "tg"));
    assert!(!occurs("sie dreht", "Sie"));
    assert!(occurs("sinθi = 0,5", "sinθ*"));
    assert!(!occurs("sin2Theta_t", "sin"));
    assert!(!occurs("sin_theta", "sin"));
    assert!(occurs("champ : valeur", "␣:"));
    assert!(!occurs("champ\u{a0}: valeur", "␣:"));
    assert!(occurs("l'angle", "'"));
    assert!(occurs(&format!("{PLACEABLE} nm"), "nm"));
    assert!(occurs(&format!("em {PLACEABLE} nm"), "em {…} nm"));
    assert!(!occurs("em 5 nm", "em {…} nm"));
    assert!(!occurs("", "nm"));
}

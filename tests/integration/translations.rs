//! The translations are complete and the window's code holds no English of its own:
//!
//! - every Fluent file of every language parses, and defines exactly the keys English does,
//!   each once;
//! - every placeable (`{ $mu }`) of an English message is in each translation, and no
//!   translation has one English lacks;
//! - every key the code asks for (`t!("key")`) exists, and every key exists because the code
//!   asks for it;
//! - no string literal in the window's code or the diagram's reads as text for a user: such
//!   text comes from the Fluent files. A literal that only looks like text (a font's name, a
//!   formula) carries the comment `// untranslated: why` on its line or the line before.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use fluent_syntax::ast::{Entry, Expression, InlineExpression, Pattern, PatternElement};
use refraction_i18n::{FILES, Locale};

/// The root of the repository.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A message's key and the variables its value and attributes use.
type Messages = BTreeMap<String, BTreeSet<String>>;

fn variables_of_pattern(pattern: &Pattern<&str>, into: &mut BTreeSet<String>) {
    for element in &pattern.elements {
        if let PatternElement::Placeable { expression } = element {
            variables_of_expression(expression, into);
        }
    }
}

fn variables_of_expression(expression: &Expression<&str>, into: &mut BTreeSet<String>) {
    match expression {
        Expression::Inline(inline) => variables_of_inline(inline, into),
        Expression::Select { selector, variants } => {
            variables_of_inline(selector, into);
            for variant in variants {
                variables_of_pattern(&variant.value, into);
            }
        }
    }
}

fn variables_of_inline(inline: &InlineExpression<&str>, into: &mut BTreeSet<String>) {
    match inline {
        InlineExpression::VariableReference { id } => {
            into.insert(id.name.to_owned());
        }
        InlineExpression::Placeable { expression } => variables_of_expression(expression, into),
        _ => {}
    }
}

/// The messages of one file, or what is wrong with it.
fn messages(path: &Path) -> Result<Messages, String> {
    let source = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let resource = fluent_syntax::parser::parse(source.as_str())
        .map_err(|(_, errors)| format!("{}: does not parse: {errors:?}", path.display()))?;
    let mut found = Messages::new();
    for entry in resource.body {
        match entry {
            Entry::Message(message) => {
                let mut variables = BTreeSet::new();
                if let Some(value) = &message.value {
                    variables_of_pattern(value, &mut variables);
                }
                for attribute in &message.attributes {
                    variables_of_pattern(&attribute.value, &mut variables);
                }
                let key = message.id.name.to_owned();
                if found.insert(key.clone(), variables).is_some() {
                    return Err(format!("{}: `{key}` is defined twice", path.display()));
                }
            }
            Entry::Junk { content } => {
                return Err(format!("{}: cannot read `{content}`", path.display()));
            }
            _ => {}
        }
    }
    Ok(found)
}

fn locale_file(locale: Locale, file: &str) -> PathBuf {
    root()
        .join("crates/refraction-i18n/locales")
        .join(locale.code())
        .join(file)
}

/// English's messages, all files together.
fn english() -> Messages {
    let mut all = Messages::new();
    for file in FILES {
        let found = messages(&locale_file(Locale::En, file)).unwrap();
        for (key, variables) in found {
            assert!(
                all.insert(key.clone(), variables).is_none(),
                "`{key}` twice"
            );
        }
    }
    all
}

#[test]
fn every_language_has_every_key_with_its_placeables_and_nothing_more() {
    let mut problems = Vec::new();
    for file in FILES {
        let source = messages(&locale_file(Locale::En, file)).unwrap();
        for locale in Locale::ALL {
            let path = locale_file(locale, file);
            let translated = match messages(&path) {
                Ok(found) => found,
                Err(problem) => {
                    problems.push(problem);
                    continue;
                }
            };
            for (key, variables) in &source {
                match translated.get(key) {
                    None => problems.push(format!("{locale} {file}: `{key}` is missing")),
                    Some(theirs) if theirs != variables => problems.push(format!(
                        "{locale} {file}: `{key}` uses {theirs:?}, English uses {variables:?}"
                    )),
                    Some(_) => {}
                }
            }
            for key in translated.keys().filter(|k| !source.contains_key(*k)) {
                problems.push(format!("{locale} {file}: `{key}` is not an English key"));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The Rust files of `folder`, recursively.
fn rust_files(folder: &Path, into: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(&path, into);
        } else if path.extension().is_some_and(|e| e == "rs") {
            into.push(path);
        }
    }
}

/// The program's source files: the root package's and every crate's, tests excluded.
fn program_sources() -> Vec<PathBuf> {
    let mut files = Vec::new();
    rust_files(&root().join("src"), &mut files);
    for crate_dir in std::fs::read_dir(root().join("crates")).unwrap() {
        let src = crate_dir.unwrap().path().join("src");
        if src.is_dir() {
            rust_files(&src, &mut files);
        }
    }
    files
}

/// The keys `source` asks for with `t!("key"…)` (the key may be on the next line), outside
/// comments.
fn keys_asked(source: &str) -> Vec<String> {
    let code: String = source
        .lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    code.match_indices("t!(")
        // `format!(` and `print!(` end the same way: only `t!` itself asks.
        .filter(|(at, _)| {
            let before = code[..*at].chars().next_back();
            !before.is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
        .filter_map(|(at, opening)| {
            let rest = code[at + opening.len()..].trim_start().strip_prefix('"')?;
            rest.find('"').map(|end| rest[..end].to_owned())
        })
        .collect()
}

#[test]
fn every_key_the_code_asks_for_exists_and_every_key_is_asked_for() {
    let english = english();
    let mut asked = BTreeSet::new();
    let mut problems = Vec::new();
    for path in program_sources() {
        let source = std::fs::read_to_string(&path).unwrap();
        for key in keys_asked(without_tests(&source)) {
            if !english.contains_key(&key) {
                problems.push(format!(
                    "{}: asks for `{key}`, which English lacks",
                    path.display()
                ));
            }
            asked.insert(key);
        }
    }
    for key in english.keys().filter(|k| !asked.contains(*k)) {
        problems.push(format!("`{key}` is defined but no code asks for it"));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The part of a source file that is not its unit tests (`#[cfg(test)] mod …` to the end).
fn without_tests(source: &str) -> &str {
    source
        .find("#[cfg(test)]\nmod ")
        .map_or(source, |at| &source[..at])
}

/// The string literals of `source` with the number of the line each starts on. Comments,
/// character literals and byte strings are skipped; raw strings are read.
fn string_literals(source: &str) -> Vec<(usize, String)> {
    let chars: Vec<char> = source.chars().collect();
    let mut found = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '\n' {
            line += 1;
        }
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
            continue;
        }
        if c == '/' && next == Some('*') {
            while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                line += usize::from(chars[i] == '\n');
                i += 1;
            }
            i += 2;
            continue;
        }
        if c == '\'' {
            // A character literal ('"', '\'', 'x'), or a lifetime, which ends at no quote.
            let end = (i + 1..chars.len().min(i + 12)).find(|&j| chars[j] == '\'');
            let is_char = end.is_some_and(|e| e - i <= 3 || chars[i + 1] == '\\');
            i = if is_char { end.unwrap() + 1 } else { i + 1 };
            continue;
        }
        let is_raw = c == 'r' && matches!(next, Some('"' | '#'));
        let previous_is_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if (c == '"' || is_raw) && !previous_is_word {
            let start_line = line;
            let (text, end) = read_literal(&chars, i);
            line += text.matches('\n').count();
            found.push((start_line, text));
            i = end;
            continue;
        }
        if c == 'b' && next == Some('"') && !previous_is_word {
            let (text, end) = read_literal(&chars, i + 1);
            line += text.matches('\n').count();
            i = end;
            continue;
        }
        i += 1;
    }
    found
}

/// The literal starting at `chars[start]` (`"` or `r`), and the index after it.
fn read_literal(chars: &[char], start: usize) -> (String, usize) {
    let mut i = start;
    if chars[i] == 'r' {
        i += 1;
        let hashes = chars[i..].iter().take_while(|c| **c == '#').count();
        i += hashes + 1;
        let closing: String = core::iter::once('"')
            .chain(core::iter::repeat_n('#', hashes))
            .collect();
        let rest: String = chars[i..].iter().collect();
        let end = rest.find(&closing).unwrap_or(rest.len());
        let text: String = rest[..end].to_owned();
        return (
            text.clone(),
            i + text.chars().count() + closing.chars().count(),
        );
    }
    i += 1;
    let mut text = String::new();
    while i < chars.len() && chars[i] != '"' {
        if chars[i] == '\\' && i + 1 < chars.len() {
            text.push(chars[i]);
            i += 1;
        }
        text.push(chars[i]);
        i += 1;
    }
    (text, i + 1)
}

/// Whether a literal reads as text for a user: words with spaces between them, or a
/// capitalised word. Format placeholders (`{x:.2}`), escapes and symbols (`θi`, `μ`) are not
/// words; a lone lowercase word without spaces is an identifier (`canvas`, `png`).
fn reads_as_text(literal: &str) -> bool {
    let mut plain = String::new();
    let mut depth = 0;
    for c in literal.chars() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ if depth == 0 => plain.push(c),
            _ => {}
        }
    }
    let plain = plain.replace("\\n", " ").replace("\\t", " ");
    let words: Vec<&str> = plain
        .split(|c: char| !c.is_ascii_alphabetic())
        .filter(|w| w.len() >= 2)
        .collect();
    // "{n} rays": a placeable joined to words by a space is text too.
    let placeable = literal.contains('{');
    let spaced = if placeable {
        plain.contains(char::is_whitespace)
    } else {
        plain.trim().contains(char::is_whitespace)
    };
    let capitalised = words
        .iter()
        .any(|w| w.len() >= 3 && w.starts_with(|c: char| c.is_ascii_uppercase()));
    (spaced && !words.is_empty()) || capitalised
}

/// The folders and files whose code draws or shows text to a user (not the tools' snippets:
/// code in other languages, not text).
fn interface_sources() -> Vec<PathBuf> {
    let mut files = Vec::new();
    rust_files(&root().join("src/app"), &mut files);
    rust_files(&root().join("crates/refraction-diagram/src"), &mut files);
    // The sentences of "Check my T" that the window shows (and `check` prints in English).
    for file in [
        "crates/refraction-tools/src/candidate_check.rs",
        "crates/refraction-check/src/call_check/explain.rs",
        "crates/refraction-check/src/diagnosis/code.rs",
        "crates/refraction-check/src/call_check/call.rs",
        "crates/refraction-check/src/call_check/csv.rs",
        "crates/refraction-check/src/call_check/error.rs",
        "crates/refraction-check/src/call_check/mod.rs",
        "crates/refraction-check/src/call_check/pattern.rs",
        "crates/refraction-check/src/call_check/record.rs",
        "crates/refraction-check/src/call_check/result.rs",
        "crates/refraction-tools/src/vector_text.rs",
    ] {
        files.push(root().join(file));
    }
    files
}

#[test]
fn the_window_and_the_diagram_hold_no_text_of_their_own() {
    let mut problems = Vec::new();
    for path in interface_sources() {
        let source = std::fs::read_to_string(&path).unwrap();
        let lines: Vec<&str> = source.lines().collect();
        let exempt = |line: usize| {
            let here = lines
                .get(line - 1)
                .is_some_and(|l| l.contains("// untranslated:"));
            let before = line >= 2 && lines[line - 2].trim_start().starts_with("// untranslated:");
            // A lint expectation's reason is for developers.
            let reason = lines
                .get(line - 1)
                .is_some_and(|l| l.trim_start().starts_with("reason = "));
            here || before || reason
        };
        for (line, literal) in string_literals(without_tests(&source)) {
            if reads_as_text(&literal) && !exempt(line) {
                let name = path.strip_prefix(root()).unwrap_or(&path).display();
                problems.push(format!("{name}:{line}: \"{literal}\""));
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} literals read as text; put them in crates/refraction-i18n/locales/*/ and ask with t!:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
#[expect(
    clippy::literal_string_with_formatting_args,
    reason = "Rust source as test input"
)]
fn the_literal_finder_finds_text_and_leaves_code_alone() {
    let source = "let a = \"Reset\"; let b = \"canvas\"; // \"not this\"\n\
                  let c = format!(\"{x:.2} rays left\"); let d = '\"'; let e = \"{}: {}\";\n\
                  let u = \"{n} rays\"; let i = \"{tool:?}-presentation\";\n\
                  let f = r#\"Raw \"text\"\"#; let g = \"θi = {}°\"; let h = b\"Bytes here\";";
    let found: Vec<(usize, String)> = string_literals(source)
        .into_iter()
        .filter(|(_, l)| reads_as_text(l))
        .collect();
    assert_eq!(
        found,
        vec![
            (1, "Reset".to_owned()),
            (2, "{x:.2} rays left".to_owned()),
            (3, "{n} rays".to_owned()),
            (4, "Raw \"text\"".to_owned()),
        ]
    );
}

#[test]
fn the_key_finder_reads_t_and_not_format() {
    let source = "let a = t!(\"one-key\"); let b = format!(\"{x} rays\");\n\
                  let c = t!(\"other-key\", count = n); print!(\"no\"); (t!(\"third\"))\n\
                  // t!(\"in-a-comment\")\n\
                  let d = t!(\n    \"next-line\",\n    n = 1\n);";
    assert_eq!(
        keys_asked(source),
        ["one-key", "other-key", "third", "next-line"]
    );
}

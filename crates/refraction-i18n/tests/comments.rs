//! The shipped Fluent files hold no notes between translators: a translation's comments are
//! English's, translated.
//!
//! English's comments describe the messages (what a placeable holds, where a label stands).
//! A translation may carry those descriptions, in its language, but nothing of its own: a
//! comment on a message English leaves uncommented, or more free-standing comments than
//! English has, is a note to or from a translator ("bitte prüfen", "to check"), which belongs
//! in the glossary's decisions or nowhere. Words that mark such a note are refused in any
//! comment, so that a note appended to a translated description is found too.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use fluent_syntax::ast::{Comment, Entry};
use refraction_i18n::{FILES, Locale};

/// Words that mark a note about the translation rather than a description of a message, in
/// every language's way (lowercase; found in any case).
const NOTE_MARKERS: [&str; 21] = [
    "todo",
    "fixme",
    "translator",
    "bitte prüfen",
    "unsicher",
    "abgleichen",
    "dudoso",
    "revisar",
    "compruébese",
    "à vérifier",
    "verificar:",
    "conferir",
    "проверить:",
    ": проверить",
    "проверить термин",
    "сверить",
    "бриф",
    "переводчик",
    "traductor",
    "traducteur",
    "tradutor",
];

/// A file's comments: the keys of the messages that carry one, how many stand free (resource,
/// group and plain comments), and the text of all of them.
struct Comments {
    on_messages: BTreeSet<String>,
    free_standing: usize,
    lines: Vec<String>,
}

fn comments(locale: Locale, file: &str) -> Comments {
    let path: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("locales")
        .join(locale.code())
        .join(file);
    let source = std::fs::read_to_string(&path).expect("a locale file");
    let resource = fluent_syntax::parser::parse(source.as_str()).expect("the file parses");
    let mut found = Comments {
        on_messages: BTreeSet::new(),
        free_standing: 0,
        lines: Vec::new(),
    };
    for entry in &resource.body {
        match entry {
            Entry::Message(message) => {
                if let Some(comment) = &message.comment {
                    found.on_messages.insert(message.id.name.to_owned());
                    keep(comment, &mut found.lines);
                }
            }
            Entry::Term(term) => {
                if let Some(comment) = &term.comment {
                    found.on_messages.insert(format!("-{}", term.id.name));
                    keep(comment, &mut found.lines);
                }
            }
            Entry::Comment(comment)
            | Entry::GroupComment(comment)
            | Entry::ResourceComment(comment) => {
                found.free_standing += 1;
                keep(comment, &mut found.lines);
            }
            Entry::Junk { .. } => {}
        }
    }
    found
}

/// The lines of `comment`, kept to be searched for note markers.
fn keep(comment: &Comment<&str>, lines: &mut Vec<String>) {
    lines.extend(comment.content.iter().map(|l| (*l).to_owned()));
}

#[test]
fn translations_comment_only_where_english_does() {
    let mut problems = Vec::new();
    for file in FILES {
        let english = comments(Locale::En, file);
        for locale in Locale::ALL.into_iter().filter(|l| *l != Locale::En) {
            let theirs = comments(locale, file);
            for key in theirs.on_messages.difference(&english.on_messages) {
                problems.push(format!(
                    "{locale}/{file}: `{key}` has a comment English's lacks"
                ));
            }
            if theirs.free_standing > english.free_standing {
                problems.push(format!(
                    "{locale}/{file}: {} free-standing comments, English has {}",
                    theirs.free_standing, english.free_standing
                ));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn no_comment_is_a_note_about_the_translation() {
    let mut problems = Vec::new();
    for locale in Locale::ALL {
        for file in FILES {
            for line in comments(locale, file).lines {
                let lower = line.to_lowercase();
                if let Some(marker) = NOTE_MARKERS.iter().find(|m| lower.contains(*m)) {
                    problems.push(format!("{locale}/{file}: “{marker}” in “{line}”"));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

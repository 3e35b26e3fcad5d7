//! The Fluent files compiled into the binary: the same files in every language's folder.

use crate::Locale;

/// The files of every language's folder under the crate's `locales/`, by what their messages are
/// about: the window, its tools and panels (`explorer`), what is drawn on the diagram, the
/// scenes and the plots (`diagram`), Check my T and its verdicts (`check`), files, saving and
/// exporting (`files`), and a whole log judged in the window: opening it, its diagnosis, its
/// failure map and its failing lines saved as tests (`logs`), and lesson decks: the tool that
/// builds one, stepping through it, its notes and handout, the built-in decks (`decks`), and the
/// explorer in a browser: links to it, the QR code, what a page does otherwise (`web`), and the
/// Python package `refraction_check`: its arguments refused, its table of what was found
/// (`python`).
pub const FILES: [&str; 8] = [
    "explorer.ftl",
    "diagram.ftl",
    "check.ftl",
    "files.ftl",
    "logs.ftl",
    "decks.ftl",
    "web.ftl",
    "python.ftl",
];

/// One language's files, in the order of [`FILES`].
macro_rules! folder {
    ($code:literal) => {
        [
            include_str!(concat!("../locales/", $code, "/explorer.ftl")),
            include_str!(concat!("../locales/", $code, "/diagram.ftl")),
            include_str!(concat!("../locales/", $code, "/check.ftl")),
            include_str!(concat!("../locales/", $code, "/files.ftl")),
            include_str!(concat!("../locales/", $code, "/logs.ftl")),
            include_str!(concat!("../locales/", $code, "/decks.ftl")),
            include_str!(concat!("../locales/", $code, "/web.ftl")),
            include_str!(concat!("../locales/", $code, "/python.ftl")),
        ]
    };
}

const EN: [&str; 8] = folder!("en");
const DE: [&str; 8] = folder!("de");
const ES: [&str; 8] = folder!("es");
const FR: [&str; 8] = folder!("fr");
const PT_BR: [&str; 8] = folder!("pt-BR");
const RU: [&str; 8] = folder!("ru");

/// The text of `locale`'s files, in the order of [`FILES`].
pub(crate) fn sources(locale: Locale) -> &'static [&'static str; 8] {
    match locale {
        Locale::En => &EN,
        Locale::De => &DE,
        Locale::Es => &ES,
        Locale::Fr => &FR,
        Locale::PtBr => &PT_BR,
        Locale::Ru => &RU,
    }
}

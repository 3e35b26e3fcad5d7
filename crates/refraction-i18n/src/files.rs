//! The Fluent files compiled into the binary: the same files in every language's folder.

use crate::Locale;

/// The files of every language's folder under the crate's `locales/`, by what their messages are
/// about: the window, its tools and panels (`explorer`), what is drawn on the diagram, the
/// scenes and the plots (`diagram`), Check my T and its verdicts (`check`), files, saving and
/// exporting (`files`), and a whole log judged in the window: opening it, its diagnosis, its
/// failure map and its failing lines saved as tests (`logs`), and lesson decks: the tool that
/// builds one, stepping through it, its notes and handout, the built-in decks (`decks`), and the
/// explorer in a browser: links to it, the QR code, what a page does otherwise (`web`), what
/// a screen reader says: the controls' names and values, the diagram in words, the step buttons
/// and the page's own controls (`access`), and the Python package `refraction_check`: its
/// arguments refused, its table of what was found (`python`).
pub const FILES: [&str; 9] = [
    "explorer.ftl",
    "diagram.ftl",
    "check.ftl",
    "files.ftl",
    "logs.ftl",
    "decks.ftl",
    "web.ftl",
    "access.ftl",
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
            include_str!(concat!("../locales/", $code, "/access.ftl")),
            include_str!(concat!("../locales/", $code, "/python.ftl")),
        ]
    };
}

const EN: [&str; FILES.len()] = folder!("en");
const DE: [&str; FILES.len()] = folder!("de");
const ES: [&str; FILES.len()] = folder!("es");
const FR: [&str; FILES.len()] = folder!("fr");
const PT_BR: [&str; FILES.len()] = folder!("pt-BR");
const RU: [&str; FILES.len()] = folder!("ru");

/// The text of `locale`'s files, in the order of [`FILES`].
pub(crate) fn sources(locale: Locale) -> &'static [&'static str; FILES.len()] {
    match locale {
        Locale::En => &EN,
        Locale::De => &DE,
        Locale::Es => &ES,
        Locale::Fr => &FR,
        Locale::PtBr => &PT_BR,
        Locale::Ru => &RU,
    }
}

//! The Fluent files compiled into the binary: the same files in every language's folder.

use crate::Locale;

/// The files of every language's folder under the crate's `locales/`, by what their messages are
/// about: the window, its tools and panels (`explorer`), what is drawn on the diagram, the
/// scenes and the plots (`diagram`), Check my T and its verdicts (`check`), and files, saving
/// and exporting (`files`).
pub const FILES: [&str; 4] = ["explorer.ftl", "diagram.ftl", "check.ftl", "files.ftl"];

/// One language's files, in the order of [`FILES`].
macro_rules! folder {
    ($code:literal) => {
        [
            include_str!(concat!("../locales/", $code, "/explorer.ftl")),
            include_str!(concat!("../locales/", $code, "/diagram.ftl")),
            include_str!(concat!("../locales/", $code, "/check.ftl")),
            include_str!(concat!("../locales/", $code, "/files.ftl")),
        ]
    };
}

const EN: [&str; 4] = folder!("en");
const DE: [&str; 4] = folder!("de");
const ES: [&str; 4] = folder!("es");
const FR: [&str; 4] = folder!("fr");
const PT_BR: [&str; 4] = folder!("pt-BR");
const RU: [&str; 4] = folder!("ru");

/// The text of `locale`'s files, in the order of [`FILES`].
pub(crate) fn sources(locale: Locale) -> &'static [&'static str; 4] {
    match locale {
        Locale::En => &EN,
        Locale::De => &DE,
        Locale::Es => &ES,
        Locale::Fr => &FR,
        Locale::PtBr => &PT_BR,
        Locale::Ru => &RU,
    }
}

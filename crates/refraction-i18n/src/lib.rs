//! The explorer's words in every language it speaks.
//!
//! Every sentence a user reads comes from a [Project Fluent](https://projectfluent.org) file:
//! one folder per language under the crate's `locales/` (`en`, `de`, `es`, `fr`, `pt-BR`, `ru`),
//! each with the same files ([`FILES`]), compiled into the binary. Code asks for a message by
//! its key with [`t!`]; the words come from the language chosen for the current thread
//! ([`set_locale`]), and from English where a translation lacks the key, so a missing
//! translation shows English rather than nothing.
//!
//! Numbers are passed to messages already written: [`decimal`] turns a number written with a
//! point into the language's own way (a decimal comma in German, Spanish, French, Portuguese
//! and Russian), and [`read_number`] reads typed numbers in either form. Copied code, JSON and
//! files always keep the point; they never pass through [`decimal`].
//!
//! The language is per thread, English unless set, so that the command line's JSON and the
//! tests that drive the window in English are not changed by a user's desktop language, and
//! tests of different languages can run side by side.

mod files;

use core::cell::{Cell, RefCell};
use std::borrow::Cow;
use std::rc::Rc;

use fluent_bundle::{FluentArgs, FluentBundle, FluentResource, FluentValue};

pub use files::FILES;

/// A language the explorer speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum Locale {
    /// English, the language of the source and the fallback for a missing key.
    #[default]
    En,
    /// German.
    De,
    /// Spanish.
    Es,
    /// French.
    Fr,
    /// Brazilian Portuguese.
    PtBr,
    /// Russian.
    Ru,
}

impl Locale {
    /// Every language, in the order the language menu lists them.
    pub const ALL: [Self; 6] = [Self::En, Self::De, Self::Es, Self::Fr, Self::PtBr, Self::Ru];

    /// The language's tag and folder name under the crate's `locales/` (`pt-BR`).
    #[must_use]
    pub const fn code(self) -> &'static str {
        match self {
            Self::En => "en",
            Self::De => "de",
            Self::Es => "es",
            Self::Fr => "fr",
            Self::PtBr => "pt-BR",
            Self::Ru => "ru",
        }
    }

    /// The language's name in itself, as the language menu shows it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::En => "English",
            Self::De => "Deutsch",
            Self::Es => "Español",
            Self::Fr => "Français",
            Self::PtBr => "Português (Brasil)",
            Self::Ru => "Русский",
        }
    }

    /// The language a tag names: `de`, `de-AT`, `pt_BR.UTF-8`, `ru-RU` (case and `_` or `-`
    /// as systems write them; any Portuguese is Brazilian Portuguese, the only one there is).
    /// `None` for a language the explorer does not speak.
    #[must_use]
    pub fn from_tag(tag: &str) -> Option<Self> {
        let primary = tag
            .split(['-', '_', '.', '@'])
            .next()
            .unwrap_or_default()
            .to_ascii_lowercase();
        Self::ALL.into_iter().find(|locale| {
            let own = locale.code().split('-').next().unwrap_or_default();
            own == primary
        })
    }

    /// The character between a number's whole part and its decimals.
    #[must_use]
    pub const fn decimal_separator(self) -> char {
        match self {
            Self::En => '.',
            _ => ',',
        }
    }

    /// What separates the numbers of a list such as a vector's components: `", "`, or `"; "`
    /// where the decimal separator is a comma.
    #[must_use]
    pub const fn list_separator(self) -> &'static str {
        match self {
            Self::En => ", ",
            _ => "; ",
        }
    }
}

impl core::fmt::Display for Locale {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.code())
    }
}

/// A value for a message's placeable (`{ $mu }`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Arg<'a> {
    /// Text put in as it is: names, and numbers already written (with [`decimal`]).
    Text(Cow<'a, str>),
    /// A count, which picks the plural form (`{ $count -> [one] … *[other] … }`).
    Count(i64),
}

impl<'a> From<&'a str> for Arg<'a> {
    fn from(text: &'a str) -> Self {
        Self::Text(Cow::Borrowed(text))
    }
}

impl<'a> From<&'a String> for Arg<'a> {
    fn from(text: &'a String) -> Self {
        Self::Text(Cow::Borrowed(text))
    }
}

impl From<String> for Arg<'_> {
    fn from(text: String) -> Self {
        Self::Text(Cow::Owned(text))
    }
}

impl From<usize> for Arg<'_> {
    fn from(count: usize) -> Self {
        Self::Count(i64::try_from(count).unwrap_or(i64::MAX))
    }
}

impl From<u32> for Arg<'_> {
    fn from(count: u32) -> Self {
        Self::Count(i64::from(count))
    }
}

impl From<i64> for Arg<'_> {
    fn from(count: i64) -> Self {
        Self::Count(count)
    }
}

thread_local! {
    static CURRENT: Cell<Locale> = const { Cell::new(Locale::En) };
    static BUNDLES: RefCell<Vec<(Locale, Rc<Bundle>)>> = const { RefCell::new(Vec::new()) };
    static REPORTED: RefCell<std::collections::HashSet<String>> =
        RefCell::new(std::collections::HashSet::new());
}

type Bundle = FluentBundle<FluentResource>;

/// Chooses the language of this thread's messages and numbers.
pub fn set_locale(locale: Locale) {
    CURRENT.with(|current| current.set(locale));
}

/// The language of this thread's messages and numbers (English unless [`set_locale`] chose
/// another).
#[must_use]
pub fn locale() -> Locale {
    CURRENT.with(Cell::get)
}

/// The message `key` in the current language with `args` filled in; English where the
/// language lacks the key.
///
/// # Panics
/// In debug builds (and so in every test), when the translation is broken: English lacks
/// the key, a placeable was not filled, or a file does not parse. A release
/// build shows `[key]` for a missing key and the placeable's name for a missing value, and
/// says so on stderr once per problem.
#[must_use]
pub fn text(key: &str, args: &[(&str, Arg<'_>)]) -> String {
    let locale = locale();
    format_in(locale, key, args)
        .or_else(|| format_in(Locale::En, key, args))
        .unwrap_or_else(|| {
            broken(&format!("no message `{key}` in English"));
            format!("[{key}]")
        })
}

/// The message `key` in `locale`, or `None` if that language's files lack it.
fn format_in(locale: Locale, key: &str, args: &[(&str, Arg<'_>)]) -> Option<String> {
    let bundle = bundle(locale);
    let pattern = bundle.get_message(key)?.value()?;
    let mut fluent_args = FluentArgs::new();
    for (name, value) in args {
        let value = match value {
            Arg::Text(text) => FluentValue::from(text.as_ref()),
            Arg::Count(count) => FluentValue::from(*count),
        };
        fluent_args.set(*name, value);
    }
    let mut errors = Vec::new();
    let text = bundle.format_pattern(pattern, Some(&fluent_args), &mut errors);
    if !errors.is_empty() {
        broken(&format!("{locale} message `{key}`: {errors:?}"));
    }
    Some(text.into_owned())
}

/// A translation that cannot be shown as written: a panic in debug builds, so that a test
/// or a developer's run finds it at once; a line on stderr in a release build, where a user
/// is better served by the rest of the window than by a crash.
#[expect(
    clippy::manual_assert,
    reason = "a panic in debug builds only, with the release build's fallback after it"
)]
#[expect(
    clippy::print_stderr,
    reason = "a release build's one way to say so without a crash or a lost message"
)]
fn broken(what: &str) {
    if cfg!(debug_assertions) {
        panic!("broken translation: {what}");
    }
    // Once per problem, not once per frame that shows it.
    if REPORTED.with(|reported| reported.borrow_mut().insert(what.to_owned())) {
        eprintln!("refraction-explorer: broken translation: {what}");
    }
}

/// This thread's bundle for `locale`, built on first use.
fn bundle(locale: Locale) -> Rc<Bundle> {
    BUNDLES.with(|bundles| {
        if let Some((_, bundle)) = bundles.borrow().iter().find(|(l, _)| *l == locale) {
            return Rc::clone(bundle);
        }
        let bundle = Rc::new(build(locale));
        bundles.borrow_mut().push((locale, Rc::clone(&bundle)));
        bundle
    })
}

/// The bundle of `locale`'s files. A file that does not parse, or defines a key twice, is
/// [`broken`]; in a release build it contributes the messages that do parse (Fluent's own
/// recovery) and a key defined twice keeps its first definition.
fn build(locale: Locale) -> Bundle {
    let tag = locale
        .code()
        .parse()
        .unwrap_or_else(|_| unic_langid::LanguageIdentifier::default());
    let mut bundle = FluentBundle::new(vec![tag]);
    // Isolation marks (U+2068, U+2069) around placeables are for mixing right-to-left text;
    // none of these languages needs them and egui's fonts have no glyph for them.
    bundle.set_use_isolating(false);
    for (file, source) in FILES.iter().zip(files::sources(locale)) {
        let resource = FluentResource::try_new((*source).to_owned()).unwrap_or_else(|(r, e)| {
            broken(&format!("{locale}/{file} does not parse: {e:?}"));
            r
        });
        if let Err(errors) = bundle.add_resource(resource) {
            broken(&format!("{locale}/{file}: {errors:?}"));
        }
    }
    bundle
}

/// `number`, written with a point (as Rust's formatting writes it), in the current language's
/// way: the point becomes a decimal comma where the language uses one. Nothing else changes.
#[must_use]
pub fn decimal(number: &str) -> String {
    match locale().decimal_separator() {
        '.' => number.to_owned(),
        separator => number.replace('.', &separator.to_string()),
    }
}

/// A number a user typed: with a decimal point or a decimal comma (in any language, so that a
/// value copied from elsewhere still reads), a true minus sign or a hyphen, surrounding
/// spaces. `None` if it is not one number (`1,234.5` is refused rather than guessed).
#[must_use]
pub fn read_number(typed: &str) -> Option<f64> {
    let text = typed.trim().replace('−', "-");
    if text.contains(',') && text.contains('.') || text.matches(',').count() > 1 {
        return None;
    }
    text.replace(',', ".").parse().ok()
}

/// A message by its key, in the current language: `t!("key")`, or with placeables,
/// `t!("key", mu = text, count = n)`. See [`text`].
#[macro_export]
macro_rules! t {
    ($key:literal) => {
        $crate::text($key, &[])
    };
    ($key:literal, $($name:ident = $value:expr),+ $(,)?) => {
        $crate::text($key, &[$((stringify!($name), $crate::Arg::from($value))),+])
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_as_systems_write_them_name_a_language() {
        assert_eq!(Locale::from_tag("de-AT"), Some(Locale::De));
        assert_eq!(Locale::from_tag("pt_BR.UTF-8"), Some(Locale::PtBr));
        assert_eq!(Locale::from_tag("pt-PT"), Some(Locale::PtBr));
        assert_eq!(Locale::from_tag("RU"), Some(Locale::Ru));
        assert_eq!(Locale::from_tag("en-GB"), Some(Locale::En));
        assert_eq!(Locale::from_tag("ja-JP"), None);
        assert_eq!(Locale::from_tag(""), None);
        for locale in Locale::ALL {
            assert_eq!(Locale::from_tag(locale.code()), Some(locale));
        }
    }

    #[test]
    fn numbers_are_written_the_local_way_and_read_either_way() {
        set_locale(Locale::De);
        assert_eq!(decimal("−1.25"), "−1,25");
        set_locale(Locale::En);
        assert_eq!(decimal("−1.25"), "−1.25");
        assert_eq!(read_number(" 1,5 "), Some(1.5));
        assert_eq!(read_number("1.5"), Some(1.5));
        assert_eq!(read_number("−0,25"), Some(-0.25));
        assert_eq!(read_number("1,234.5"), None);
        assert_eq!(read_number("1,2,3"), None);
        assert_eq!(read_number("glass"), None);
    }

    #[test]
    fn the_language_is_the_threads_own() {
        set_locale(Locale::Ru);
        let other = std::thread::spawn(locale).join().unwrap();
        assert_eq!(other, Locale::En);
        assert_eq!(locale(), Locale::Ru);
        set_locale(Locale::En);
    }

    #[test]
    fn a_message_comes_in_the_chosen_language_with_its_placeables() {
        set_locale(Locale::De);
        let german = t!("language-hover");
        set_locale(Locale::En);
        let english = t!("language-hover");
        assert_ne!(german, english);
        assert!(!english.starts_with('['), "{english}");
    }

    #[test]
    #[should_panic(expected = "broken translation: no message `no-such-key` in English")]
    fn a_key_english_lacks_fails_loudly_in_a_debug_build() {
        let _ = t!("no-such-key");
    }

    #[test]
    #[should_panic(expected = "broken translation: en message")]
    fn a_placeable_not_filled_fails_loudly_in_a_debug_build() {
        // The first English message with a placeable, asked for without it.
        let key = FILES
            .iter()
            .zip(files::sources(Locale::En))
            .flat_map(|(_, source)| source.lines())
            .find(|line| line.contains("{ $") && !line.starts_with([' ', '#']))
            .and_then(|line| line.split(" =").next())
            .expect("a message with a placeable");
        let _ = text(key, &[]);
    }
}

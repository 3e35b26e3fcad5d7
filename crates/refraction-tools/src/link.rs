//! The link of what the class sees: the web build's address with a fragment that opens a state
//! (`#state=` and the state file's JSON, URL-encoded: the line `--state` reads and *Copy share
//! string* copies) or a built-in lesson deck at a step (`#lesson=NAME&step=K`, K from 1).
//!
//! ```
//! use refraction_model::ExplorerState;
//! use refraction_tools::link::{self, Link};
//!
//! let url = link::url("https://school.example/explorer/", &Link::Lesson { name: "snell".into(), step: 2 });
//! assert_eq!(url, "https://school.example/explorer/#lesson=snell&step=2");
//! let state = ExplorerState::default();
//! let shared = link::url("https://school.example/explorer/", &Link::State(Box::new(state.clone())));
//! let fragment = &shared[shared.find('#').unwrap()..];
//! let Ok(Some(Link::State(opened))) = link::parse(fragment) else { panic!("{shared}") };
//! // The link keeps W and N to a millionth: the same diagram, to far below what it shows.
//! assert!((opened.incidence_degrees() - state.incidence_degrees()).abs() < 1e-4);
//! ```
//!
//! A fragment is a list of `name=value` parts joined by `&`, each value percent-encoded. This
//! version reads `state`, `lesson`, `step`, `view=student` (the student's view, whatever the
//! screen: see [`student_url`]) and `v` (the link format, [`FORMAT`]); a later format, or a
//! part (or a field of the state) this version does not know, is refused as a link from a
//! newer version, never half read; a part given twice is refused as damaged. What a refusal
//! quotes of the link is cut to [`ECHO_CHARS`] characters, its control characters escaped
//! ([`echo`]).
//!
//! The web build's address a link starts with is checked in one place, [`web_base`], for the
//! command line, the window and the page alike.

use refraction_i18n::t;
use refraction_model::ExplorerState;

use crate::state_file;

/// The link format this version writes and reads (`v=1` may be given; it is not written).
pub const FORMAT: u32 = 1;

/// What a link opens.
#[derive(Clone, Debug, PartialEq)]
pub enum Link {
    /// A single-interface problem (boxed: a state is large beside a deck's name).
    State(Box<ExplorerState>),
    /// A built-in lesson deck (its name, as `lessons` lists it) at a step, counted from 1.
    Lesson {
        /// The deck's name.
        name: String,
        /// The step, from 1.
        step: usize,
    },
}

/// Why a link's fragment cannot be opened.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum LinkError {
    /// The link ends in the middle of its text: it was cut short when copied or typed.
    #[error("the link is cut short")]
    CutShort,
    /// The link's text is damaged; the reason says where.
    #[error("the link is damaged: {0}")]
    Malformed(String),
    /// The link was made by a newer version: a later format, or a part this one does not read.
    #[error("the link comes from a newer version ({0})")]
    Newer(String),
}

/// The most characters of a link a message quotes: a name or a part, not a page of them.
pub const ECHO_CHARS: usize = 60;

/// The most characters of a reader's own message a refusal quotes (it may quote the link).
const REASON_CHARS: usize = 200;

/// Whether `c` would not show as itself in a message: a control character, or a mark that
/// reorders or hides the text around it (bidirectional overrides, embeddings, isolates and
/// marks, zero-width characters, the byte order mark).
#[must_use]
pub fn is_unseen(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{ad}'
                | '\u{61c}'
                | '\u{200b}'..='\u{200f}'
                | '\u{2028}'..='\u{202e}'
                | '\u{2060}'..='\u{2069}'
                | '\u{feff}'
        )
}

/// `text` as a message quotes it: at most `most` characters (then `…` and how many were left
/// out), each that would not show as itself ([`is_unseen`]) escaped as Rust writes it
/// (`\u{202e}`). Linear in `text`'s length, its output in `most`.
#[must_use]
pub fn echo(text: &str, most: usize) -> String {
    let mut out = String::new();
    for (count, c) in text.chars().enumerate() {
        if count == most {
            let left = text.chars().count() - most;
            out.push_str(&format!("… (+{left})"));
            break;
        }
        if is_unseen(c) {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    out
}

impl LinkError {
    /// What the window says, in the current language.
    #[must_use]
    pub fn message(&self) -> String {
        match self {
            Self::CutShort => t!("link-cut-short"),
            Self::Malformed(reason) => t!("link-malformed", reason = reason.as_str()),
            Self::Newer(part) => t!("link-newer", part = part.as_str()),
        }
    }
}

/// Whether `byte` stands for itself in a fragment this module writes: the unreserved
/// characters, and `:` and `,`, which a fragment allows and JSON is full of.
fn kept(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || b"-._~:,".contains(&byte)
}

/// `text` percent-encoded for a fragment's value (UTF-8, every other byte as `%XX`).
#[must_use]
pub fn encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len() * 3 / 2);
    for &byte in text.as_bytes() {
        if kept(byte) {
            out.push(char::from(byte));
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

/// `text` percent-decoded: every `%XX` as its byte, the rest as it is, the whole read as UTF-8.
///
/// # Errors
/// A `%` without two hex digits after it, or bytes that are not UTF-8: [`LinkError::CutShort`]
/// where that happens at the end, [`LinkError::Malformed`] elsewhere.
pub fn decode(text: &str) -> Result<String, LinkError> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] != b'%' {
            out.push(bytes[i]);
            i += 1;
            continue;
        }
        let digits = bytes.get(i + 1..i + 3).and_then(|hex| {
            let hex = core::str::from_utf8(hex).ok()?;
            u8::from_str_radix(hex, 16).ok()
        });
        match digits {
            Some(byte) => out.push(byte),
            None if i + 3 > bytes.len() => return Err(LinkError::CutShort),
            None => {
                // The three characters from `%` (a character may be longer than a byte).
                let bad: String = text[i..].chars().take(3).collect();
                return Err(LinkError::Malformed(format!(
                    "“{}”",
                    echo(&bad, ECHO_CHARS)
                )));
            }
        }
        i += 3;
    }
    String::from_utf8(out).map_err(|e| match e.utf8_error().error_len() {
        None => LinkError::CutShort,
        Some(_) => LinkError::Malformed(e.utf8_error().to_string()),
    })
}

/// The longest web address a link may start with, in bytes: with a state's fragment (about
/// 250 bytes) a step's link stays within a QR code a phone reads on a printed page.
pub const MAX_WEB_BASE_BYTES: usize = 300;

/// Why a web address cannot start a link.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum WebBaseError {
    /// Nothing was given.
    #[error("no address was given")]
    Empty,
    /// A scheme other than http, https or file (`javascript:`, `data:`, `ftp:`), or none.
    #[error("it starts with `{0}`, not http://, https:// or file://")]
    Scheme(String),
    /// A character that would not show as itself or would break the link: white space, a
    /// control character, a reordering or invisible mark.
    #[error(
        "it holds {0}, which an address cannot hold (white space, control characters and invisible marks are not allowed)"
    )]
    Unseen(String),
    /// A `%` without two hexadecimal digits after it.
    #[error("“{0}” is no percent escape (a % is followed by two hexadecimal digits)")]
    Escape(String),
    /// A user name or password before the host, which would go into every link and QR code.
    #[error("it holds a user name or password, which would be printed in every link")]
    Credentials,
    /// Longer than [`MAX_WEB_BASE_BYTES`].
    #[error(
        "it is {0} bytes long: an address of at most {MAX_WEB_BASE_BYTES} bytes keeps the links' QR codes readable on paper"
    )]
    TooLong(usize),
    /// A port that is no number from 0 to 65535.
    #[error("its port is not a number from 0 to 65535")]
    Port,
    /// No host, or one that is no valid name or IP address.
    #[error("its host is missing or is no valid name or IP address ({0})")]
    Host(String),
}

impl WebBaseError {
    /// What the window says, in the current language: the address cannot be used, and why.
    #[must_use]
    pub fn message(&self) -> String {
        t!("link-web-base-refused", reason = self.reason())
    }

    /// Why the address cannot be used, in the current language.
    #[must_use]
    pub fn reason(&self) -> String {
        match self {
            Self::Empty => t!("link-web-base-empty"),
            Self::Scheme(scheme) => t!("link-web-base-scheme", scheme = scheme.as_str()),
            Self::Unseen(what) => t!("link-web-base-unseen", character = what.as_str()),
            Self::Escape(escape) => t!("link-web-base-escape", escape = escape.as_str()),
            Self::Credentials => t!("link-web-base-credentials"),
            Self::TooLong(bytes) => t!(
                "link-web-base-too-long",
                bytes = bytes.to_string(),
                most = MAX_WEB_BASE_BYTES.to_string()
            ),
            Self::Port => t!("link-web-base-port"),
            Self::Host(reason) => t!("link-web-base-host", reason = reason.as_str()),
        }
    }
}

/// The web build's address `text` as links start with it: an `http`, `https` or `file` URL
/// (the WHATWG URL rules: a host for http and https, a port up to 65535), written as the URL
/// standard writes it (`HTTPS://School.Example` becomes `https://school.example/`), without
/// a fragment (a link puts its own). The one check of an address, for `--web-base`, the
/// window's field and what a browser page was opened at.
///
/// # Errors
/// Nothing given; another scheme (`javascript:`); white space, a control character or an
/// invisible or reordering mark anywhere (a U+202E would make the printed link read
/// backwards); a `%` not followed by two hexadecimal digits; a user name or password; an
/// address longer than [`MAX_WEB_BASE_BYTES`]; what the URL parser refuses (a port over
/// 65535, no host or one that is not valid).
pub fn web_base(text: &str) -> Result<String, WebBaseError> {
    let text = text.trim_matches(|c: char| c == ' ' || c == '\t' || c == '\n' || c == '\r');
    if text.is_empty() {
        return Err(WebBaseError::Empty);
    }
    if let Some(c) = text.chars().find(|&c| is_unseen(c) || c.is_whitespace()) {
        return Err(WebBaseError::Unseen(c.escape_unicode().to_string()));
    }
    let scheme = text.split_once(':').map_or("", |(scheme, _)| scheme);
    if !["http", "https", "file"].contains(&scheme.to_ascii_lowercase().as_str()) {
        return Err(WebBaseError::Scheme(echo(
            text.split_once(':').map_or(text, |(s, _)| s),
            ECHO_CHARS,
        )));
    }
    if let Some(at) = text.match_indices('%').map(|(i, _)| i).find(|&i| {
        let hex = text.as_bytes().get(i + 1..i + 3);
        !hex.is_some_and(|h| h.iter().all(u8::is_ascii_hexdigit))
    }) {
        let bad: String = text[at..].chars().take(3).collect();
        return Err(WebBaseError::Escape(echo(&bad, ECHO_CHARS)));
    }
    let mut url = url::Url::parse(text).map_err(|e| match e {
        url::ParseError::InvalidPort => WebBaseError::Port,
        url::ParseError::Overflow => WebBaseError::TooLong(text.len()),
        other => WebBaseError::Host(other.to_string()),
    })?;
    if !url.username().is_empty() || url.password().is_some() {
        return Err(WebBaseError::Credentials);
    }
    url.set_fragment(None);
    let base = String::from(url);
    match base.len() {
        0..=MAX_WEB_BASE_BYTES => Ok(base),
        bytes => Err(WebBaseError::TooLong(bytes)),
    }
}

/// How many decimals a link keeps of W's and N's components: a millionth turns a direction by
/// under 0.0001°, a thousandth of the 0.1° the diagram shows.
const DIRECTION_DECIMALS: i32 = 6;

/// How many significant digits a link keeps of an index: air's 1.000293 whole.
const INDEX_DIGITS: i32 = 7;

/// `x` rounded to `decimals` decimals (`-0` written as `0`).
fn rounded(x: f64, decimals: i32) -> f64 {
    let scale = 10_f64.powi(decimals);
    (x * scale).round() / scale + 0.0
}

/// The state's JSON as a link carries it: the fields `--state` reads, W's and N's components
/// to [`DIRECTION_DECIMALS`] and the indices to [`INDEX_DIGITS`] significant digits (the
/// numbers as the diagram can show them: a short link is a QR code a phone reads from the
/// back of the room), the convention only when it is not the default. *Copy share string*
/// keeps every bit.
fn state_json(state: &ExplorerState) -> String {
    let vector = |v: glam::DVec3| v.to_array().map(|c| rounded(c, DIRECTION_DECIMALS));
    let index = |mu: f64| {
        let decimals = INDEX_DIGITS - 1 - mu.abs().log10().floor() as i32;
        rounded(mu, decimals.max(0))
    };
    let mut json = serde_json::json!({
        "w": vector(state.w()),
        "n": vector(state.n()),
        "mu_i": index(state.mu_i()),
        "mu_t": index(state.mu_t()),
    });
    if state.convention() != refraction_kernel::Convention::default() {
        json["convention"] = serde_json::Value::from(state.convention().name());
    }
    json.to_string()
}

/// The fragment of `link`, without the `#`.
#[must_use]
pub fn fragment(link: &Link) -> String {
    match link {
        Link::State(state) => format!("state={}", encode(&state_json(state))),
        Link::Lesson { name, step } => format!("lesson={}&step={step}", encode(name)),
    }
}

/// The link of `link` at the web build's address `base` (any fragment of `base` replaced).
#[must_use]
pub fn url(base: &str, link: &Link) -> String {
    let base = base.split('#').next().unwrap_or_default().trim();
    format!("{base}#{}", fragment(link))
}

/// The part that asks for the student's view: the question, the diagram across the screen,
/// handles a finger can take, and nothing of the teacher's.
pub const STUDENT_VIEW: &str = "view=student";

/// [`url()`] for the class's own devices (what a QR code opens): the link that also asks for
/// the student's view ([`STUDENT_VIEW`]).
#[must_use]
pub fn student_url(base: &str, link: &Link) -> String {
    format!("{}&{STUDENT_VIEW}", url(base, link))
}

/// Whether the fragment `fragment` (with or without its `#`) asks for the student's view.
/// A fragment that cannot be read asks for nothing ([`parse`] says why).
#[must_use]
pub fn asks_student_view(fragment: &str) -> bool {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    fragment.split('&').any(|part| part == STUDENT_VIEW)
}

/// The parts of a fragment, each name with its decoded value, in order.
///
/// # Errors
/// A value that does not decode; a part without a name (`=x`); a name given twice.
fn parts(fragment: &str) -> Result<Vec<(&str, String)>, LinkError> {
    let mut parts: Vec<(&str, String)> = Vec::new();
    for part in fragment.split('&').filter(|part| !part.is_empty()) {
        let (name, value) = part.split_once('=').unwrap_or((part, ""));
        if name.is_empty() {
            return Err(LinkError::Malformed(t!(
                "link-part-without-name",
                part = echo(part, ECHO_CHARS)
            )));
        }
        if parts.iter().any(|(known, _)| *known == name) {
            return Err(LinkError::Malformed(t!(
                "link-part-twice",
                part = echo(name, ECHO_CHARS)
            )));
        }
        parts.push((name, decode(value)?));
    }
    Ok(parts)
}

/// The fields a state's JSON may have (those `solve` reads).
const STATE_FIELDS: [&str; 6] = ["w", "n", "mu_i", "mu_t", "convention", "precision"];

/// The step a `step=` part gives (from 1).
fn step_of(value: Option<&String>) -> Result<usize, LinkError> {
    let Some(value) = value else {
        return Ok(1);
    };
    match value.trim().parse::<usize>() {
        Ok(step) if step >= 1 => Ok(step),
        _ => Err(LinkError::Malformed(t!(
            "link-bad-step",
            step = echo(value, ECHO_CHARS)
        ))),
    }
}

/// The state a `state=` part gives; text that stops before its closing brace was cut short,
/// and a field this version does not read comes from a newer one (a state file may carry
/// more, as a `solve` line may; a link is all this version's or refused).
fn state_of(json: &str) -> Result<ExplorerState, LinkError> {
    let state = state_file::parse_state(json).map_err(|e| {
        if json.trim_end().ends_with('}') {
            LinkError::Malformed(echo(&e.to_string(), REASON_CHARS))
        } else {
            LinkError::CutShort
        }
    })?;
    let fields = serde_json::from_str::<serde_json::Map<String, serde_json::Value>>(json)
        .map_err(|e| LinkError::Malformed(echo(&e.to_string(), REASON_CHARS)))?;
    match fields.keys().find(|k| !STATE_FIELDS.contains(&k.as_str())) {
        Some(unknown) => Err(LinkError::Newer(echo(unknown, ECHO_CHARS))),
        None => Ok(state),
    }
}

/// What the fragment `fragment` (with or without its `#`) opens: `None` for an empty one.
///
/// # Errors
/// A fragment cut short, damaged, naming a later format or holding a part this version does
/// not read; giving both a state and a lesson, or a step without a lesson.
pub fn parse(fragment: &str) -> Result<Option<Link>, LinkError> {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    let parts = parts(fragment)?;
    let value = |wanted: &str| parts.iter().find(|(n, _)| *n == wanted).map(|(_, v)| v);
    if let Some(version) = value("v") {
        match version.trim().parse::<u32>() {
            Ok(v) if v <= FORMAT => {}
            Ok(v) => return Err(LinkError::Newer(format!("v={v}"))),
            Err(_) => {
                return Err(LinkError::Malformed(format!(
                    "v={}",
                    echo(version, ECHO_CHARS)
                )));
            }
        }
    }
    if let Some((name, _)) = parts
        .iter()
        .find(|(n, _)| !["state", "lesson", "step", "view", "v"].contains(n))
    {
        return Err(LinkError::Newer(echo(name, ECHO_CHARS)));
    }
    // Only the student's view is a view a link names; another is a newer version's.
    if let Some(view) = value("view").filter(|v| *v != "student") {
        return Err(LinkError::Newer(format!("view={view}")));
    }
    match (value("state"), value("lesson")) {
        (Some(_), Some(_)) => Err(LinkError::Malformed(t!("link-state-and-lesson"))),
        (Some(json), None) => state_of(json).map(|s| Some(Link::State(Box::new(s)))),
        (None, Some(name)) if name.trim().is_empty() => Err(LinkError::CutShort),
        (None, Some(name)) => Ok(Some(Link::Lesson {
            name: name.trim().to_owned(),
            step: step_of(value("step"))?,
        })),
        (None, None) if value("step").is_some() => {
            Err(LinkError::Malformed(t!("link-step-without-lesson")))
        }
        (None, None) => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;
    use refraction_kernel::Convention;

    fn beyond_critical() -> ExplorerState {
        let w = DVec3::new(0.8, -0.6, 0.0);
        ExplorerState::new(w, DVec3::Y, 1.5, 1.0, Convention::AlongRay).unwrap()
    }

    #[test]
    fn a_state_goes_through_its_link_as_the_diagram_shows_it() {
        let state = beyond_critical();
        let url = url(
            "https://school.example/explorer/index.html#old",
            &Link::State(Box::new(state.clone())),
        );
        assert!(
            url.starts_with("https://school.example/explorer/index.html#state=%7B%22"),
            "{url}"
        );
        assert!(
            !url[url.find('#').unwrap() + 1..].contains(['{', '"', ' ', '#']),
            "{url}"
        );
        let fragment = &url[url.find('#').unwrap()..];
        assert_eq!(
            parse(fragment),
            Ok(Some(Link::State(Box::new(state.clone()))))
        );
        // A ray at 40° into air's 1.000293, Section 1: its numbers to a millionth (the 231
        // characters of every bit made a dense QR code), its indices whole.
        let a = 40_f64.to_radians();
        let w = glam::DVec3::new(-a.sin(), a.cos(), 0.0);
        let forty = ExplorerState::new(w, glam::DVec3::Y, 1.000_293, 1.5, Convention::TowardOrigin)
            .unwrap();
        let link = super::fragment(&Link::State(Box::new(forty.clone())));
        let json = decode(&link["state=".len()..]).unwrap();
        assert_eq!(
            json,
            r#"{"convention":"toward_origin","mu_i":1.000293,"mu_t":1.5,"n":[0.0,1.0,0.0],"w":[-0.642788,0.766044,0.0]}"#
        );
        let Ok(Some(Link::State(opened))) = parse(&link) else {
            panic!("{link}")
        };
        assert!((opened.incidence_degrees() - 40.0).abs() < 1e-4);
        assert_eq!(
            (opened.mu_i(), opened.convention()),
            (1.000_293, Convention::TowardOrigin)
        );
        // The plain form, as `--state` reads it, fully encoded or not encoded at all.
        let json = state_file::state_to_json(&state);
        let every_byte = json.bytes().fold(String::new(), |mut out, b| {
            out.push_str(&format!("%{b:02x}"));
            out
        });
        assert_eq!(
            parse(&format!("state={every_byte}")),
            Ok(Some(Link::State(Box::new(state.clone()))))
        );
        assert_eq!(
            parse(&format!("#state={json}")),
            Ok(Some(Link::State(Box::new(state))))
        );
    }

    #[test]
    fn a_lesson_link_names_the_deck_and_the_step() {
        let link = Link::Lesson {
            name: "snell".to_owned(),
            step: 2,
        };
        assert_eq!(fragment(&link), "lesson=snell&step=2");
        assert_eq!(parse("#lesson=snell&step=2"), Ok(Some(link)));
        assert_eq!(
            parse("#lesson=tir"),
            Ok(Some(Link::Lesson {
                name: "tir".to_owned(),
                step: 1
            }))
        );
        assert_eq!(
            parse("#lesson=tir&step=2&v=1").map(|l| l.is_some()),
            Ok(true)
        );
        assert_eq!(parse(""), Ok(None));
        assert_eq!(parse("#"), Ok(None));
    }

    #[test]
    fn broken_links_say_why_and_open_nothing() {
        let json = state_file::state_to_json(&beyond_critical());
        let encoded = fragment(&Link::State(Box::new(beyond_critical())));
        for cut in [
            &encoded[..encoded.len() - 1],
            &encoded[..encoded.len() - 2],
            &encoded[..40],
        ] {
            assert_eq!(parse(cut), Err(LinkError::CutShort), "{cut}");
        }
        assert_eq!(
            parse(&format!("state={}", &json[..json.len() - 1])),
            Err(LinkError::CutShort)
        );
        assert!(matches!(
            parse("state=%7Bnonsense%7D"),
            Err(LinkError::Malformed(_))
        ));
        assert!(matches!(
            parse("state=%zz%7D"),
            Err(LinkError::Malformed(_))
        ));
        assert!(matches!(
            parse("lesson=snell&step=0"),
            Err(LinkError::Malformed(_))
        ));
        assert!(matches!(
            parse("lesson=snell&step=two"),
            Err(LinkError::Malformed(_))
        ));
        assert!(matches!(parse("step=2"), Err(LinkError::Malformed(_))));
        assert!(matches!(
            parse(&format!("{encoded}&lesson=snell")),
            Err(LinkError::Malformed(_))
        ));
        assert_eq!(
            parse("lesson=snell&v=2"),
            Err(LinkError::Newer("v=2".to_owned()))
        );
        assert_eq!(
            parse("lesson=snell&zoom=2"),
            Err(LinkError::Newer("zoom".to_owned()))
        );
        assert_eq!(parse("lesson="), Err(LinkError::CutShort));
        for error in [LinkError::CutShort, LinkError::Newer("v=2".to_owned())] {
            assert!(!error.message().is_empty());
        }
    }

    #[test]
    fn a_link_for_the_class_asks_for_the_student_s_view() {
        let link = Link::Lesson {
            name: "snell".to_owned(),
            step: 2,
        };
        let url = student_url("https://school.example/explorer/", &link);
        assert_eq!(
            url,
            "https://school.example/explorer/#lesson=snell&step=2&view=student"
        );
        let fragment = &url[url.find('#').unwrap()..];
        assert_eq!(parse(fragment), Ok(Some(link.clone())));
        assert!(asks_student_view(fragment));
        assert!(!asks_student_view("#lesson=snell&step=2"));
        let state = student_url("x", &Link::State(Box::new(beyond_critical())));
        assert!(asks_student_view(&state[state.find('#').unwrap()..]));
        assert_eq!(
            parse("lesson=snell&view=teacher"),
            Err(LinkError::Newer("view=teacher".to_owned()))
        );
    }

    #[test]
    fn text_round_trips_through_percent_encoding() {
        for text in ["", "plain", "{\"a\": [1, -2.5e-7]}", "μ → 1 & #?=%"] {
            assert_eq!(decode(&encode(text)).as_deref(), Ok(text));
        }
        assert_eq!(encode("a b"), "a%20b");
        assert_eq!(decode("%CE"), Err(LinkError::CutShort));
        assert!(matches!(decode("%CEx"), Err(LinkError::Malformed(_))));
    }

    #[test]
    fn a_web_address_is_checked_once_for_every_way_it_comes_in() {
        // Issue 40: U+202E, port 99999, bad escapes and `javascript:` were accepted.
        assert_eq!(
            web_base(" HTTPS://School.Example/explorer/#old "),
            Ok("https://school.example/explorer/".to_owned())
        );
        assert_eq!(
            web_base("file:///home/teacher/explorer/index.html"),
            Ok("file:///home/teacher/explorer/index.html".to_owned())
        );
        assert_eq!(
            web_base("http://localhost:8080/%C3%A9/"),
            Ok("http://localhost:8080/%C3%A9/".to_owned())
        );
        let refused = |text: &str| web_base(text).unwrap_err();
        assert_eq!(refused(""), WebBaseError::Empty);
        assert_eq!(
            refused("https://school.example/\u{202e}lmth.x"),
            WebBaseError::Unseen("\\u{202e}".to_owned())
        );
        assert!(matches!(refused("https://a b/"), WebBaseError::Unseen(_)));
        assert!(matches!(
            refused("https://a.example/\u{200b}"),
            WebBaseError::Unseen(_)
        ));
        assert_eq!(refused("https://school.example:99999/"), WebBaseError::Port);
        assert_eq!(
            refused("https://school.example/%zz/"),
            WebBaseError::Escape("%zz".to_owned())
        );
        assert_eq!(
            refused("https://school.example/%4"),
            WebBaseError::Escape("%4".to_owned())
        );
        assert_eq!(
            refused("javascript:alert(1)"),
            WebBaseError::Scheme("javascript".to_owned())
        );
        assert!(matches!(
            refused("data:text/html,x"),
            WebBaseError::Scheme(_)
        ));
        assert!(matches!(refused("school.example"), WebBaseError::Scheme(_)));
        assert_eq!(
            refused("https://me:pw@school.example/"),
            WebBaseError::Credentials
        );
        assert!(matches!(refused("https://"), WebBaseError::Host(_)));
        assert!(matches!(
            refused("https://exa%20mple/"),
            WebBaseError::Host(_)
        ));
        let long = format!("https://school.example/{}/", "a".repeat(MAX_WEB_BASE_BYTES));
        assert_eq!(refused(&long), WebBaseError::TooLong(long.len()));
        for error in [
            WebBaseError::Port,
            WebBaseError::Empty,
            WebBaseError::Credentials,
        ] {
            assert!(error.message().contains(&error.reason()));
        }
    }

    #[test]
    fn a_link_s_parts_are_named_once_and_what_a_refusal_quotes_is_bounded() {
        // Issue 40: `===` was "a newer version … ()", a state given twice opened the first.
        assert!(matches!(parse("==="), Err(LinkError::Malformed(_))));
        assert!(matches!(
            parse("#=x&lesson=snell"),
            Err(LinkError::Malformed(_))
        ));
        let state = fragment(&Link::State(Box::new(beyond_critical())));
        assert!(matches!(
            parse(&format!("{state}&{state}")),
            Err(LinkError::Malformed(reason)) if reason.contains("state")
        ));
        assert!(matches!(
            parse("lesson=snell&lesson=tir"),
            Err(LinkError::Malformed(_))
        ));
        // A field of the state this version does not read: a newer version's link.
        let json = state_file::state_to_json(&beyond_critical());
        let more = format!("state={}", encode(&json.replace('}', ",\"zoom\":2}")));
        assert_eq!(parse(&more), Err(LinkError::Newer("zoom".to_owned())));
        // A 20,000-character part is quoted by its first 60 characters.
        let long = format!("lesson=snell&{}=1", "x".repeat(20_000));
        let Err(LinkError::Newer(part)) = parse(&long) else {
            panic!("a part this version does not read")
        };
        assert!(part.chars().count() < ECHO_CHARS + 12, "{part}");
        assert!(part.ends_with("… (+19940)"), "{part}");
        assert_eq!(echo("a\u{202e}b\u{1b}", ECHO_CHARS), "a\\u{202e}b\\u{1b}");
        // A bad escape before a character of several bytes is quoted, not a panic.
        assert!(matches!(decode("%aé"), Err(LinkError::Malformed(m)) if m.contains("%aé")));
        assert!(matches!(
            parse("lesson=%a\u{1F600}"),
            Err(LinkError::Malformed(_))
        ));
    }

    /// A generator of hostile text: pieces a link or an address is made of, and worse.
    fn hostile(seed: &mut u64, pieces: usize) -> String {
        const PIECES: [&str; 24] = [
            "%", "%4", "%zz", "%C3", "%A9", "=", "&", "#", "state", "lesson", "step", "v", "1",
            "é", "\u{202e}", "\u{0}", "\u{1b}", "\u{200b}", "{", "}", "\"", ":", "/", "https://",
        ];
        let mut out = String::new();
        for _ in 0..pieces {
            // xorshift64: the same inputs every run.
            *seed ^= *seed << 13;
            *seed ^= *seed >> 7;
            *seed ^= *seed << 17;
            out.push_str(PIECES[(*seed % PIECES.len() as u64) as usize]);
        }
        out
    }

    #[test]
    fn hostile_links_and_addresses_never_panic_and_are_quoted_briefly() {
        let mut seed = 0x9e37_79b9_7f4a_7c15;
        for round in 0..3_000 {
            let text = hostile(&mut seed, 1 + round % 40);
            if let Err(e) = parse(&text) {
                let said = e.message();
                assert!(said.chars().count() < 400, "{text:?}: {said}");
                assert!(!said.chars().any(is_unseen), "{text:?}: {said:?}");
            }
            match web_base(&text) {
                Ok(base) => {
                    assert_eq!(web_base(&base).as_ref(), Ok(&base), "{text:?}");
                    assert!(!base.chars().any(|c| is_unseen(c) || c.is_whitespace()));
                }
                Err(e) => assert!(!e.message().chars().any(is_unseen), "{text:?}"),
            }
        }
    }
}

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
//! part this version does not know, is refused as a link from a newer version, never half
//! read.

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
            None => return Err(LinkError::Malformed(format!("“{}”", &text[i..i + 3]))),
        }
        i += 3;
    }
    String::from_utf8(out).map_err(|e| match e.utf8_error().error_len() {
        None => LinkError::CutShort,
        Some(_) => LinkError::Malformed(e.utf8_error().to_string()),
    })
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

/// [`url`] for the class's own devices (what a QR code opens): the link that also asks for
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
fn parts(fragment: &str) -> Result<Vec<(&str, String)>, LinkError> {
    fragment
        .split('&')
        .filter(|part| !part.is_empty())
        .map(|part| {
            let (name, value) = part.split_once('=').unwrap_or((part, ""));
            Ok((name, decode(value)?))
        })
        .collect()
}

/// The step a `step=` part gives (from 1).
fn step_of(value: Option<&String>) -> Result<usize, LinkError> {
    let Some(value) = value else {
        return Ok(1);
    };
    match value.trim().parse::<usize>() {
        Ok(step) if step >= 1 => Ok(step),
        _ => Err(LinkError::Malformed(t!(
            "link-bad-step",
            step = value.as_str()
        ))),
    }
}

/// The state a `state=` part gives; text that stops before its closing brace was cut short.
fn state_of(json: &str) -> Result<ExplorerState, LinkError> {
    state_file::parse(json).map_err(|e| {
        if json.trim_end().ends_with('}') {
            LinkError::Malformed(e.to_string())
        } else {
            LinkError::CutShort
        }
    })
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
            Err(_) => return Err(LinkError::Malformed(format!("v={version}"))),
        }
    }
    if let Some((name, _)) = parts
        .iter()
        .find(|(n, _)| !["state", "lesson", "step", "view", "v"].contains(n))
    {
        return Err(LinkError::Newer((*name).to_owned()));
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
        let json = state_file::to_json(&state);
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
        let json = state_file::to_json(&beyond_critical());
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
}

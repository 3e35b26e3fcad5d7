//! What a panel says after it acted (a file written, a link copied, or why nothing was), the
//! words for a file written or not exported, and the one function every panel shows it with.

use core::fmt::Display;
use std::path::Path;

use egui::{Label, RichText, Ui, WidgetText};
use refraction_i18n::t;

use super::typed::warning;

/// A line a panel shows after it acted: what it did, or why it did not. Its words are the
/// window's own, put in the user's language when the panel acted; they are only shown.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// What was done: a file written, a string copied, a file left as it was.
    Done(String),
    /// Why nothing was done: a name refused, a file that cannot be read or written.
    Refused(String),
}

/// What a panel says after it wrote the file at `path`.
pub(super) fn wrote(path: &Path) -> Status {
    Status::Done(t!("files-wrote", path = path.display().to_string()))
}

/// Why an export wrote nothing, in the window's language around the reason's own words.
pub(super) fn not_exported(reason: &impl Display) -> String {
    t!("files-not-exported", reason = reason.to_string())
}

/// What an export came to: the file at `path` written, or why nothing was.
pub(super) fn exported(result: Result<(), impl Display>, path: &Path) -> Status {
    match result {
        Ok(()) => wrote(path),
        Err(reason) => Status::Refused(not_exported(&reason)),
    }
}

/// How a panel shows its status line. A refusal looks the same in each: after ⚠, in the alarm
/// colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Look {
    /// In the panel's text, on as many lines as it takes.
    Plain,
    /// What was done in small text (under a log's verdicts, which are the news).
    SmallDone,
    /// On one line, cut at the row's end (all of it on hover).
    Cut,
}

/// Shows `status`, if there is one, the panel's way (`look`).
pub(super) fn show(ui: &mut Ui, status: Option<&Status>, look: Look) {
    let text: WidgetText = match (status, look) {
        (None, _) => return,
        (Some(Status::Done(done)), Look::Plain) => done.into(),
        (Some(Status::Done(done)), Look::SmallDone) => RichText::new(done).small().into(),
        (Some(Status::Done(done)), Look::Cut) => RichText::new(done).into(),
        (Some(Status::Refused(why)), _) => warning(ui, why).into(),
    };
    let label = Label::new(text);
    ui.add(if look == Look::Cut {
        label.truncate()
    } else {
        label
    });
}

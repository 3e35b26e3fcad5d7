//! "Check my T": a student pastes what their ray tracer logged, either in this project's own
//! fields (W, N, `μ_i`, `μ_t` and the T they got, or a whole `check` JSON line) or in their own
//! API's (GLSL's `I, N, eta, result`, pbrt's `wi, n, eta, returned, wt`, the book's `uv, n,
//! etai_over_etat, refracted`, Mitsuba's `wi, n, eta, wo`, with the optional truth). The
//! explorer opens that case, drawn in the convention in use (shown in the panel), says what is
//! wrong and why, and draws the student's vector beside the right one. The verdicts are those of
//! [`refraction_tools::check_t`] and [`refraction_check`], so the window and
//! `check` agree.

mod api;
mod bulk;
mod log_files;
mod refusal;

use egui::{RichText, TextEdit, Ui};
use glam::DVec3;

use super::paint::verdict_colour;
use super::typed::error_label;
use refraction_check::{Case, Dialect, Record};
use refraction_diagram::{StudentRay, numbers::vector};
use refraction_i18n::t;
use refraction_kernel::Convention;
use refraction_kernel::api::Api;
use refraction_model::ExplorerState;
use refraction_tools::{
    Match, Precision, Request, TVerdict, check_t, parse_check_line, parse_t, state_request,
};
use refusal::Refusal;

/// Whose fields the panel reads.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum Source {
    /// This project's W, N, `μ_i`, `μ_t` and T.
    #[default]
    Own,
    /// A student's API call.
    Api(Api),
}

/// The selector's choices, in order.
const SOURCES: [Source; 5] = [
    Source::Own,
    Source::Api(Api::Glsl),
    Source::Api(Api::Pbrt),
    Source::Api(Api::Rtiow),
    Source::Api(Api::Mitsuba),
];

/// A choice's label in the selector: the API's own name, or this project's fields.
fn source_label(source: Source) -> String {
    match source {
        Source::Own => t!("check-source-own"),
        Source::Api(api) => api::owner(api).to_owned(),
    }
}

/// What a checked case said.
#[derive(Clone, Debug, PartialEq)]
enum Shown {
    /// The verdict on a T in this project's fields.
    Own(TVerdict),
    /// The verdict on an API call.
    Api(Box<api::Judged>),
}

/// A case that was checked: what the explorer opened for it, what to draw over it, the verdict.
#[derive(Clone, Debug, PartialEq)]
struct Checked {
    /// The state opened (`None`: the case could not be drawn; the verdict says why).
    opened: Option<ExplorerState>,
    /// The student's vector, drawn while `opened` is shown.
    student: StudentRay,
    shown: Shown,
}

/// This project's own fields, with the convention they are read in.
#[derive(Clone, Debug, Default, PartialEq)]
struct Own {
    w: String,
    n: String,
    mu_i: String,
    mu_t: String,
    yours: String,
    convention: Convention,
}

/// The panel's fields and its last verdict.
#[derive(Debug, Default)]
pub(super) struct CheckPanel {
    source: Source,
    own: Own,
    api: api::ApiFields,
    bulk: bulk::Bulk,
    outcome: Option<Result<Checked, Refusal>>,
    copied: Option<String>,
    /// Scroll the verdict into view next frame: it is new.
    reveal: bool,
}

/// What a verdict's match is called on the diagram and in the headline.
fn match_words(verdict: &TVerdict) -> String {
    match verdict.matches {
        Some(Match::Chosen) if verdict.ok => t!("check-match-refracted"),
        Some(Match::Chosen) => t!("check-match-not-unit"),
        Some(Match::Rejected(r)) => match r {
            refraction_kernel::Rejection::WrongSide => t!("check-match-wrong-side"),
            refraction_kernel::Rejection::WrongBend => t!("check-match-wrong-bend"),
            refraction_kernel::Rejection::Reversed => t!("check-match-reversed"),
        },
        Some(Match::TotalInternalReflection) => t!("check-match-tir"),
        None => t!("check-match-none"),
    }
}

/// How a whole `check` JSON line (an object) starts, which separate fields never do.
const JSON_LINE_START: char = '{';

/// The two conventions of this project's fields, as the panel offers them.
const CONVENTIONS: [Convention; 2] = [Convention::AlongRay, Convention::TowardOrigin];

/// A convention's name in the panel and what it means for W.
fn convention_words(convention: Convention) -> (String, String) {
    match convention {
        Convention::AlongRay => (
            t!("check-convention-along-ray"),
            t!("check-convention-along-ray-about"),
        ),
        Convention::TowardOrigin => (
            t!("check-convention-toward-origin"),
            t!("check-convention-toward-origin-about"),
        ),
    }
}

/// Reads a number typed into the field named `name`, with a decimal point or comma.
fn number(text: &str, name: &str) -> Result<f64, Refusal> {
    refraction_i18n::read_number(text).ok_or_else(|| Refusal::NotANumber {
        field: name.to_owned(),
        text: text.to_owned(),
    })
}

/// Reads a vector typed into the field named `name`.
fn vector_field(text: &str, name: &str) -> Result<[f64; 3], Refusal> {
    parse_t(text).map_err(|error| Refusal::Vector {
        field: name.to_owned(),
        error,
    })
}

/// A text field labelled `label`, at most `width` wide (less in a narrow panel); whether Enter
/// was pressed in it. In a wrapping row the label and its field start a new row together
/// rather than be split across two.
fn field(ui: &mut Ui, label: &str, text: &mut String, width: f32) -> bool {
    let font = egui::TextStyle::Body.resolve(ui.style());
    let label_width = ui
        .painter()
        .layout_no_wrap(label.to_owned(), font, egui::Color32::PLACEHOLDER)
        .size()
        .x;
    let gap = ui.spacing().item_spacing.x;
    let width = width
        .min(ui.max_rect().width() - label_width - gap)
        .max(60.0);
    if ui.available_size_before_wrap().x < label_width + gap + width {
        ui.end_row();
    }
    let name = ui.label(label);
    let response = ui
        .add(TextEdit::singleline(text).desired_width(width))
        .labelled_by(name.id);
    response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter))
}

/// The headline of a verdict: ✔ in the normal's colour, ✖ in the alarm colour.
fn headline(ui: &mut Ui, ok: bool, text: &str) {
    let mark = if ok { "✔" } else { "✖" };
    let colour = verdict_colour(ui, ok);
    ui.label(
        RichText::new(format!("{mark} {text}"))
            .strong()
            .color(colour),
    );
}

impl Own {
    /// Fills the case fields from a case, every digit kept so that checking the current case
    /// does not move it.
    fn fill(&mut self, request: &Request) {
        let exact = |v: [f64; 3]| format!("{}, {}, {}", v[0], v[1], v[2]);
        self.w = exact(request.w);
        self.n = exact(request.n);
        self.mu_i = request.mu_i.to_string();
        self.mu_t = request.mu_t.to_string();
        self.convention = request.convention;
    }

    /// Fills the case fields and "Your T" from a line of any renderer's log (the zero vector
    /// where its code reported total internal reflection, as `check` reads it).
    fn fill_case(&mut self, case: &Case) {
        self.fill(&case.request);
        self.yours = case.yours.map_or_else(
            || "0, 0, 0".to_owned(),
            |t| format!("{}, {}, {}", t[0], t[1], t[2]),
        );
    }

    /// The case and the student's T from the fields: a whole JSON line in "Your T", or the
    /// separate fields in the panel's convention.
    fn read(&self) -> Result<(Request, [f64; 3]), Refusal> {
        if self.yours.trim_start().starts_with(JSON_LINE_START) {
            return Ok(parse_check_line(self.yours.trim())?);
        }
        let request = Request {
            w: vector_field(&self.w, "W")?,
            n: vector_field(&self.n, "N")?,
            mu_i: number(&self.mu_i, "μi")?,
            mu_t: number(&self.mu_t, "μt")?,
            convention: self.convention,
            precision: Precision::F64,
        };
        Ok((
            request,
            vector_field(&self.yours, &t!("check-your-t-in-error"))?,
        ))
    }

    /// Checks the T in the fields; the case to open and the verdict.
    fn check(&mut self) -> Result<Checked, Refusal> {
        let (request, yours) = self.read()?;
        let verdict = check_t(&request, yours)?;
        let [w, n] = [request.w, request.n].map(DVec3::from_array);
        let case = ExplorerState::new(w, n, request.mu_i, request.mu_t, request.convention)?;
        self.fill(&request);
        Ok(Checked {
            opened: Some(case),
            student: StudentRay {
                t: DVec3::from_array(yours),
                label: t!("check-student-own", verdict = match_words(&verdict)),
                names: None,
            },
            shown: Shown::Own(verdict),
        })
    }

    /// The convention the fields are read in, chosen here (filled from the explorer's).
    fn convention_ui(&mut self, ui: &mut Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label(t!("check-convention"));
            for convention in CONVENTIONS {
                let (label, _) = convention_words(convention);
                ui.selectable_value(&mut self.convention, convention, label);
            }
        });
        let (_, about) = convention_words(self.convention);
        ui.label(t!("check-convention-note", about = about));
    }

    /// The fields; whether the user asked to check.
    fn show(&mut self, ui: &mut Ui, state: &ExplorerState) -> bool {
        self.convention_ui(ui);
        ui.label(t!("check-paste-hint"));
        ui.horizontal_wrapped(|ui| {
            for (label, text, width) in [
                ("W", &mut self.w, 150.0),
                ("N", &mut self.n, 150.0),
                ("μi", &mut self.mu_i, 60.0),
                ("μt", &mut self.mu_t, 60.0),
            ] {
                field(ui, label, text, width);
            }
            if ui
                .button(t!("check-use-current-case"))
                .on_hover_text(t!("check-use-current-case-own-hover"))
                .clicked()
            {
                self.fill(&state_request(state));
            }
        });
        ui.horizontal_wrapped(|ui| {
            let width = (ui.available_width() - 80.0).clamp(120.0, 520.0);
            let entered = field(ui, &t!("check-your-t"), &mut self.yours, width);
            ui.button(t!("check-button")).clicked() || entered
        })
        .inner
    }
}

/// Shows a verdict on a T in this project's fields.
fn own_verdict(ui: &mut Ui, v: &TVerdict) {
    headline(
        ui,
        v.ok,
        &t!("check-headline-own", verdict = match_words(v)),
    );
    ui.label(&v.explanation);
    right_t(ui, v.correct, |t| vector(DVec3::from_array(t), 4));
}

/// The right T written for reading (`written`), or that there is none; with a button that
/// copies it at full precision (each component as its shortest exact decimal), which its
/// hover shows too.
fn right_t(ui: &mut Ui, t: Option<[f64; 3]>, written: impl Fn([f64; 3]) -> String) {
    let Some(t) = t else {
        ui.label(t!("check-no-refracted-ray"));
        return;
    };
    let exact = format!("[{}, {}, {}]", t[0], t[1], t[2]);
    ui.horizontal_wrapped(|ui| {
        ui.label(t!("check-right-t", t = written(t)))
            .on_hover_text(&exact);
        let copy = ui
            .button(format!("📋 {}", t!("check-copy-right-t")))
            .on_hover_text(&exact);
        if copy.clicked() {
            ui.ctx().copy_text(exact.clone());
        }
    });
}

impl CheckPanel {
    /// Checks what the fields hold: opens the case in the explorer and keeps the verdict. A
    /// case that cannot be read leaves the state as it was and says why; an API call whose
    /// case cannot be drawn keeps its verdict and says why it is not drawn.
    pub(super) fn check(&mut self, state: &mut ExplorerState) {
        let outcome = match self.source {
            Source::Own => self.own.check(),
            Source::Api(api) => self.api.check(api),
        };
        if let Ok(Checked {
            opened: Some(case), ..
        }) = &outcome
        {
            *state = case.clone();
        }
        self.copied = None;
        self.outcome = Some(outcome);
        self.reveal = true;
    }

    /// The verdict shown, if the explorer still shows the case it was made for.
    fn current(&self, state: &ExplorerState) -> Option<&Checked> {
        let checked = self.outcome.as_ref()?.as_ref().ok()?;
        (checked.opened.as_ref() == Some(state)).then_some(checked)
    }

    /// The student's vector to draw, while the explorer shows the case it was checked against.
    #[must_use]
    pub(super) fn student(&self, state: &ExplorerState) -> Option<StudentRay> {
        self.current(state).map(|c| c.student.clone())
    }

    /// The selector of whose fields to read. Another choice is another question: the last
    /// verdict (and the vector it drew) goes.
    fn selector(&mut self, ui: &mut Ui) {
        let before = self.source;
        ui.horizontal_wrapped(|ui| {
            ui.label(t!("check-code-calls"));
            for source in SOURCES {
                ui.selectable_value(&mut self.source, source, source_label(source));
            }
        });
        if self.source != before {
            self.outcome = None;
            self.copied = None;
        }
    }

    /// The last verdict, or why the fields could not be checked; a new one is scrolled into
    /// view (the panel is short at the desk and narrow in presentation).
    fn verdict(&mut self, ui: &mut Ui, state: &ExplorerState) {
        let shown = ui.scope(|ui| self.verdict_ui(ui, state)).response;
        if core::mem::take(&mut self.reveal) {
            shown.scroll_to_me(Some(egui::Align::Min));
        }
    }

    fn verdict_ui(&mut self, ui: &mut Ui, state: &ExplorerState) {
        let drawn = self.current(state).is_some();
        match &self.outcome {
            None => {}
            Some(Err(refusal)) => error_label(ui, &refusal.to_string()),
            Some(Ok(checked)) => {
                match &checked.shown {
                    Shown::Own(v) => own_verdict(ui, v),
                    Shown::Api(judged) => {
                        judged.show(ui);
                        if let Some(text) = api::copy_buttons(ui, judged) {
                            self.copied = Some(text);
                        }
                    }
                }
                if !drawn && checked.opened.is_some() {
                    ui.label(RichText::new(t!("check-not-drawn-changed")).small());
                }
            }
        }
        if let Some(text) = &self.copied {
            ui.label(RichText::new(text).monospace());
        }
    }

    /// The selector, the fields, the Check button, the verdict and (for an API) the pasted
    /// log lines.
    pub(super) fn show(&mut self, ui: &mut Ui, state: &mut ExplorerState) {
        if [&self.own.w, &self.own.n, &self.own.mu_i, &self.own.mu_t]
            .iter()
            .all(|f| f.is_empty())
        {
            self.own.fill(&state_request(state));
        }
        self.selector(ui);
        let asked = match self.source {
            Source::Own => self.own.show(ui, state),
            Source::Api(api) => self.api.show(ui, api, state),
        };
        if asked {
            self.check(state);
        }
        self.verdict(ui, state);
        let dialect = match self.source {
            Source::Own => Dialect::Physics,
            Source::Api(api) => Dialect::Api(api),
        };
        if let Some(record) = self.bulk.show(ui, dialect) {
            self.open_row(&record, dialect, state);
        }
    }

    /// Opens a row of the log in the panel's fields and checks it there.
    fn open_row(&mut self, record: &Record, dialect: Dialect, state: &mut ExplorerState) {
        match dialect {
            Dialect::Api(api) => self.api.fill_from(api, record),
            Dialect::Physics => match Case::from_record(record, &self.bulk.options(dialect)) {
                Ok(case) => self.own.fill_case(&case),
                Err(e) => {
                    self.outcome = Some(Err(e.into()));
                    return;
                }
            },
        }
        self.check(state);
    }

    /// Opens the log file at `path` (dropped on the window) in the log section.
    pub(super) fn open_log(&mut self, path: &std::path::Path) {
        self.bulk.open_file(path);
    }
}

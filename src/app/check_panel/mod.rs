//! "Check my T": a student pastes W, N, μ_i, μ_t and the T their ray tracer produced (or a
//! whole `check` JSON line); the explorer opens that case, says which candidate their T is and
//! why, and draws it beside the right one. The verdict is [`crate::lines::check`]'s.

use egui::{RichText, TextEdit, Ui};
use glam::DVec3;

use super::paint::color;
use super::typed::error_label;
use crate::lines::check::{self, Match, Verdict};
use crate::lines::solve::{Precision, Request};
use crate::lines::state_file;
use refraction_diagram::ExplorerState;
use refraction_diagram::numbers::vector;
use refraction_diagram::overlay::StudentRay;
use refraction_diagram::palette;

/// A T that was checked, with the case it was checked against.
#[derive(Clone, Debug, PartialEq)]
struct Checked {
    request: Request,
    yours: [f64; 3],
    verdict: Verdict,
}

/// The panel's fields and its last verdict.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CheckPanel {
    w: String,
    n: String,
    mu_i: String,
    mu_t: String,
    yours: String,
    outcome: Option<Result<Checked, String>>,
}

/// What a verdict's match is called on the diagram and in the headline.
fn match_words(verdict: &Verdict) -> &'static str {
    match verdict.matches {
        Some(Match::Chosen) if verdict.ok => "the refracted ray T",
        Some(Match::Chosen) => "T's direction, but not unit length",
        Some(Match::Rejected(r)) => match r {
            refraction_kernel::Rejection::WrongSide => "wrong side (the other root for b)",
            refraction_kernel::Rejection::WrongBend => "wrong bend (the other sign of a)",
            refraction_kernel::Rejection::Reversed => "reversed (−T: both signs wrong)",
        },
        Some(Match::TotalInternalReflection) => "total internal reflection, answered right",
        None => "none of the four candidates",
    }
}

/// How a whole `check` JSON line (an object) starts, which separate fields never do.
const JSON_LINE_START: char = '{';

/// Reads a number typed into the field named `name`.
fn number(text: &str, name: &str) -> Result<f64, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("{name}: “{}” is not a number", text.trim()))
}

/// Reads a vector typed into the field named `name`.
fn vector_field(text: &str, name: &str) -> Result<[f64; 3], String> {
    check::parse_vector(text).map_err(|e| format!("{name}: {e}"))
}

impl CheckPanel {
    /// Fills the case fields from a case, every digit kept so that checking the current case
    /// does not move it.
    fn fill(&mut self, w: [f64; 3], n: [f64; 3], mu_i: f64, mu_t: f64) {
        let exact = |v: [f64; 3]| format!("{}, {}, {}", v[0], v[1], v[2]);
        self.w = exact(w);
        self.n = exact(n);
        self.mu_i = mu_i.to_string();
        self.mu_t = mu_t.to_string();
    }

    /// Fills the case fields from the explorer's state.
    fn take_case(&mut self, state: &ExplorerState) {
        let r = state_file::request(state);
        self.fill(r.w, r.n, r.mu_i, r.mu_t);
    }

    /// The case and the student's T from the fields: a whole JSON line in "Your T", or the
    /// separate fields with the explorer's convention.
    fn read(&self, state: &ExplorerState) -> Result<(Request, [f64; 3]), String> {
        if self.yours.trim_start().starts_with(JSON_LINE_START) {
            return check::parse_line(self.yours.trim());
        }
        let request = Request {
            w: vector_field(&self.w, "W")?,
            n: vector_field(&self.n, "N")?,
            mu_i: number(&self.mu_i, "μi")?,
            mu_t: number(&self.mu_t, "μt")?,
            convention: state.convention(),
            precision: Precision::F64,
        };
        Ok((request, vector_field(&self.yours, "your T")?))
    }

    /// Checks the T in the fields: opens its case in the explorer and keeps the verdict. A case
    /// that cannot be opened leaves the state as it was and says why.
    pub fn check(&mut self, state: &mut ExplorerState) {
        let outcome = self.read(state).and_then(|(request, yours)| {
            let verdict = check::check(&request, yours)?;
            let [w, n] = [request.w, request.n].map(DVec3::from_array);
            let case = ExplorerState::new(w, n, request.mu_i, request.mu_t, request.convention)
                .map_err(|e| e.to_string())?;
            *state = case;
            Ok(Checked {
                request,
                yours,
                verdict,
            })
        });
        if let Ok(Checked { request: r, .. }) = &outcome {
            self.fill(r.w, r.n, r.mu_i, r.mu_t);
        }
        self.outcome = Some(outcome);
    }

    /// The verdict shown, if the explorer still shows the case it was made for.
    fn current(&self, state: &ExplorerState) -> Option<&Checked> {
        let checked = self.outcome.as_ref()?.as_ref().ok()?;
        let now = state_file::request(state);
        let same = Request {
            precision: checked.request.precision,
            ..now
        } == checked.request;
        same.then_some(checked)
    }

    /// The student's T to draw, while the explorer shows the case it was checked against.
    #[must_use]
    pub fn student(&self, state: &ExplorerState) -> Option<StudentRay> {
        self.current(state).map(|c| StudentRay {
            t: DVec3::from_array(c.yours),
            label: format!("your T: {}", match_words(&c.verdict)),
        })
    }

    /// The fields, the Check button and the verdict.
    pub fn show(&mut self, ui: &mut Ui, state: &mut ExplorerState) {
        if [&self.w, &self.n, &self.mu_i, &self.mu_t]
            .iter()
            .all(|f| f.is_empty())
        {
            self.take_case(state);
        }
        ui.label(
            "Paste what your ray tracer logged. Vectors as 0.1, -0.9, 0 or [0.1,-0.9,0] or \
             vec3(0.1, -0.9, 0.0); or paste a whole JSON line with t_yours into \"Your T\".",
        );
        ui.horizontal_wrapped(|ui| {
            for (label, text, width) in [
                ("W", &mut self.w, 150.0),
                ("N", &mut self.n, 150.0),
                ("μi", &mut self.mu_i, 60.0),
                ("μt", &mut self.mu_t, 60.0),
            ] {
                let name = ui.label(label);
                ui.add(TextEdit::singleline(text).desired_width(width))
                    .labelled_by(name.id);
            }
            if ui
                .button("Use the current case")
                .on_hover_text("Fill W, N and μ from the explorer")
                .clicked()
            {
                self.take_case(state);
            }
        });
        ui.horizontal_wrapped(|ui| {
            let name = ui.label("Your T");
            let width = (ui.available_width() - 80.0).clamp(120.0, 520.0);
            let field = ui
                .add(TextEdit::singleline(&mut self.yours).desired_width(width))
                .labelled_by(name.id);
            let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            if ui.button("Check").clicked() || entered {
                self.check(state);
            }
        });
        match &self.outcome {
            None => {}
            Some(Err(message)) => error_label(ui, message),
            Some(Ok(checked)) => {
                let v = &checked.verdict;
                let (mark, ink) = if v.ok {
                    ("✔", palette::N)
                } else {
                    ("✖", palette::ALARM)
                };
                let headline = format!("{mark} Your T matches {}", match_words(v));
                ui.label(RichText::new(headline).strong().color(color(ink)));
                ui.label(&v.explanation);
                let right = v.correct.map_or_else(
                    || "There is no refracted ray: total internal reflection.".to_owned(),
                    |t| format!("The right T = {}", vector(DVec3::from_array(t), 4)),
                );
                ui.label(right);
                if self.current(state).is_none() {
                    ui.label(
                        RichText::new("(The case has changed since: the verdict is not drawn.)")
                            .small(),
                    );
                }
            }
        }
    }
}

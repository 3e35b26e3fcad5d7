//! Check my T in a student's API: that API's own argument fields and the optional truth, the
//! verdict of [`refraction_check`] (the mistakes with what each means, the
//! explanation in the API's language, what the API returns, the right T), and the case drawn in
//! the API's convention: the right call's incident vector as the API means it (GLSL's I and the
//! book's uv along the ray, pbrt's and Mitsuba's wi back toward the origin), μ as the API's eta
//! means.

use std::collections::HashMap;

use egui::{RichText, Ui};
use glam::DVec3;

use super::refusal::Refusal;
use super::{Checked, Shown, field, headline, right_t};
use refraction_check::Got;
use refraction_check::Value;
use refraction_check::fields::{self, Kind, names};
use refraction_check::{ApiCase, Language};
use refraction_check::{Call, CallVerdict, Options, Record, check_record};
use refraction_diagram::{StudentRay, VectorNames};
use refraction_i18n::t;
use refraction_kernel::Convention;
use refraction_kernel::api::{Api, Args};
use refraction_model::ExplorerState;
use refraction_model::INDEX_RANGE;
use refraction_tools::state_request;
use refraction_tools::vector_text::{spoken, spoken_vector};
use serde_json::Value as Json;

/// The truth fields the panel offers (`path` and `point` belong to logs of whole paths).
const TRUTH: [&str; 4] = ["from", "to", "travel", "entering"];

/// The precision the student's code computes in, shown with the call (it sets the tolerance).
const PRECISION: &str = "precision";

/// The API's short name, as the selector shows it.
pub(super) fn owner(api: Api) -> &'static str {
    match api {
        // untranslated: the shading language's name
        Api::Glsl => "GLSL",
        Api::Pbrt => "pbrt",
        // untranslated: the book's short name
        Api::Rtiow => "RTIOW",
        // untranslated: the renderer's name
        Api::Mitsuba => "Mitsuba",
    }
}

/// The explorer's convention that draws the API's incident vector as the API means it.
fn convention(api: Api) -> Convention {
    match api {
        Api::Glsl | Api::Rtiow => Convention::AlongRay,
        Api::Pbrt | Api::Mitsuba => Convention::TowardOrigin,
    }
}

/// The label of the incident vector's arrow.
fn incident_label(api: Api) -> String {
    t!("check-drawn-incident", api = api.name())
}

/// What the arguments mean and how the diagram shows them.
fn about(api: Api) -> String {
    t!("check-drawn-about", api = api.name())
}

/// The width of a field holding `kind`.
fn width(kind: Kind) -> f32 {
    match kind {
        Kind::Vector | Kind::VectorOrNull => 170.0,
        Kind::Number | Kind::Label => 80.0,
        Kind::Flag => 60.0,
    }
}

/// A record's value as the text a field shows, every digit kept (and no "-0": a flipped zero
/// is 0 to the reader and to every API).
fn value_text(value: &Value) -> String {
    let digits = |x: f64| if x == 0.0 { 0.0 } else { x }.to_string();
    match value {
        Value::Number(x) => digits(*x),
        Value::Vector(v) => format!("{}, {}, {}", digits(v[0]), digits(v[1]), digits(v[2])),
        Value::Flag(b) => b.to_string(),
        Value::Null => "null".to_owned(),
        Value::Label(text) => text.clone(),
    }
}

/// The API's answer (`api_result`) for reading: vectors as `(x, y, z)` and numbers with six
/// digits, an object's fields as `name: value`, separated as the language separates lists.
fn readable(json: &Json) -> String {
    let separator = refraction_i18n::locale().list_separator();
    match json {
        Json::Number(x) => x.as_f64().map_or_else(|| x.to_string(), spoken),
        Json::Array(items) => {
            let numbers: Option<Vec<f64>> = items.iter().map(Json::as_f64).collect();
            match numbers.as_deref() {
                Some(&[x, y, z]) => spoken_vector([x, y, z]),
                _ => format!(
                    "[{}]",
                    items
                        .iter()
                        .map(readable)
                        .collect::<Vec<_>>()
                        .join(separator)
                ),
            }
        }
        Json::Object(fields) => fields
            .iter()
            .map(|(name, value)| format!("{name}: {}", readable(value)))
            .collect::<Vec<_>>()
            .join(separator),
        other => other.to_string(),
    }
}

/// The API's own fields (arguments and result), then the truth fields offered.
fn shown_fields(api: Api) -> [Vec<(&'static str, Kind)>; 2] {
    let all = fields::all(api);
    let own = all
        .iter()
        .filter(|(name, _)| *name == PRECISION || !fields::COMMON.iter().any(|(c, _)| c == name))
        .copied()
        .collect();
    let truth = all
        .into_iter()
        .filter(|(name, _)| TRUTH.contains(name))
        .collect();
    [own, truth]
}

/// The indices to draw μ = `mu` with: the truth's when it agrees, otherwise 1 on the side of
/// the lower index.
fn indices(from_to: Option<(f64, f64)>, mu: f64) -> (f64, f64) {
    match from_to {
        Some((from, to)) if (from / to - mu).abs() <= 1e-9 * mu => (from, to),
        _ if mu < 1.0 => (1.0, 1.0 / mu),
        _ => (mu, 1.0),
    }
}

/// A checked API call: the call, its verdict, and the right call in the API's convention.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Judged {
    call: Call,
    verdict: CallVerdict,
    /// The right arguments for the ray, in the API's convention.
    right: Args<f64>,
    /// The right call as the explorer's state, or why it cannot be drawn.
    picture: Result<ExplorerState, Refusal>,
}

/// The right call in `api`'s convention as the explorer's state, with μ = `mu` drawn by the
/// truth's indices when they agree.
fn picture(
    api: Api,
    right: Args<f64>,
    mu: f64,
    from_to: Option<(f64, f64)>,
) -> Result<ExplorerState, Refusal> {
    let (low, high) = INDEX_RANGE;
    let (mu_i, mu_t) = indices(from_to, mu);
    if ![mu_i, mu_t].iter().all(|x| (low..=high).contains(x)) {
        return Err(Refusal::PictureOutside { mu, low, high });
    }
    let Args {
        incident, normal, ..
    } = right;
    Ok(ExplorerState::new(
        incident,
        normal,
        mu_i,
        mu_t,
        convention(api),
    )?)
}

impl Judged {
    fn new(call: Call, verdict: CallVerdict) -> Self {
        let m = verdict.right;
        let right = refraction_check::right_args(&call, &verdict);
        let picture = picture(call.api, right, m.mu, call.truth.from_to);
        Self {
            call,
            verdict,
            right,
            picture,
        }
    }

    /// The student's result with the API's names for the vectors.
    fn student(&self) -> StudentRay {
        let n = names(self.call.api);
        let t = match self.call.got {
            Got::Vector(v) => v,
            Got::Nothing => DVec3::ZERO,
        };
        let what = if self.verdict.ok {
            t!("check-student-right")
        } else {
            self.mistake_names()
                .unwrap_or_else(|| t!("check-student-wrong"))
        };
        StudentRay {
            t,
            label: t!("check-student-api", result = n.result, verdict = what),
            names: Some(VectorNames {
                incident: incident_label(self.call.api),
                normal: n.normal.to_owned(),
            }),
        }
    }

    fn mistake_names(&self) -> Option<String> {
        let codes: Vec<&str> = self.verdict.mistakes.iter().map(|c| c.name()).collect();
        (!codes.is_empty()).then(|| codes.join(", "))
    }

    /// The case a unit test is written from.
    fn case(&self) -> ApiCase<'_> {
        ApiCase::of(&self.call, &self.verdict)
    }

    /// The verdict: headline, each mistake with what it means, the explanation, what the API
    /// returns, the right T and what is drawn.
    pub(super) fn show(&self, ui: &mut Ui) {
        let d = &self.verdict;
        let api = self.call.api;
        let head = match self.mistake_names() {
            _ if d.ok => t!("check-api-right-headline", signature = api.signature()),
            Some(codes) => t!("check-api-mistakes", codes = codes),
            None => t!("check-api-unexplained-headline"),
        };
        headline(ui, d.ok, &head);
        for code in &d.mistakes {
            ui.label(format!("• {}: {}", code.name(), code.meaning()));
        }
        ui.label(&d.explanation);
        let (owner, value) = (owner(api), readable(&d.api_result));
        ui.label(t!("check-api-returns", owner = owner, value = value))
            .on_hover_text(d.api_result.to_string());
        right_t(ui, d.t, spoken_vector);
        let drawn = match &self.picture {
            Ok(state) => self.drawn(state),
            Err(why) => t!("check-api-not-drawn", why = why.to_string()),
        };
        ui.label(drawn);
    }

    /// What the diagram shows of the right call: its arguments and the indices drawn.
    #[rustfmt::skip] // the t! keys stay where the translation tests find them
    fn drawn(&self, state: &ExplorerState) -> String {
        let n = names(self.call.api);
        t!("check-api-drawn",
            incident = n.incident,
            incident_value = spoken_vector(self.right.incident.to_array()),
            normal = n.normal,
            normal_value = spoken_vector(self.right.normal.to_array()),
            eta = n.eta,
            eta_value = spoken(self.right.eta),
            mu_i = spoken(state.mu_i()),
            mu_t = spoken(state.mu_t())
        )
    }
}

/// The copy buttons for the student's languages; the text copied, if one was clicked.
pub(super) fn copy_buttons(ui: &mut Ui, judged: &Judged) -> Option<String> {
    ui.horizontal_wrapped(|ui| {
        ui.label(t!("check-copy-as-test"));
        let mut copied = None;
        for &language in Language::of(judged.call.api) {
            if ui.button(language.label()).clicked() {
                let text = refraction_check::call_test(language, &judged.case());
                ui.ctx().copy_text(text.clone());
                copied = Some(text);
            }
        }
        copied
    })
    .inner
}

/// The texts of every API's fields, kept apart per API (GLSL's eta is not pbrt's).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(super) struct ApiFields {
    texts: HashMap<(Api, &'static str), String>,
}

impl ApiFields {
    /// Fills `api`'s argument fields and the indices from the explorer's case, in the API's
    /// convention, and the API's usual precision; the result is left for the student to fill.
    fn take_case(&mut self, api: Api, state: &ExplorerState) {
        let r = state_request(state);
        let w = DVec3::from_array(r.w);
        let travel = match r.convention {
            Convention::AlongRay => w,
            Convention::TowardOrigin => -w,
        };
        let n = DVec3::from_array(r.n);
        let facing = if travel.dot(n) > 0.0 { -n } else { n };
        let args = api.arguments::<f64>(travel, facing, r.mu_i / r.mu_t);
        let v = |v: DVec3| value_text(&Value::Vector(v.to_array()));
        let names = names(api);
        for (name, text) in [
            (names.incident, v(args.incident)),
            (names.normal, v(args.normal)),
            (names.eta, args.eta.to_string()),
            ("from", r.mu_i.to_string()),
            ("to", r.mu_t.to_string()),
            (PRECISION, fields::usual_precision(api).name().to_owned()),
        ] {
            self.texts.insert((api, name), text);
        }
    }

    /// Fills `api`'s fields from a pasted line's record: its values, the rest emptied.
    pub(super) fn fill_from(&mut self, api: Api, record: &Record) {
        for (name, _) in fields::all(api) {
            let text = match record.get(name) {
                Some(value) => value_text(value),
                // What the judge assumed, shown rather than left implicit.
                None if name == PRECISION => fields::usual_precision(api).name().to_owned(),
                None => String::new(),
            };
            self.texts.insert((api, name), text);
        }
    }

    /// Reads and judges `api`'s fields (those the panel shows: a pasted line's `path` and
    /// `point` are not kept).
    pub(super) fn check(&self, api: Api) -> Result<Checked, Refusal> {
        let texts = shown_fields(api)
            .into_iter()
            .flatten()
            .filter_map(|(name, _)| {
                let text = self.texts.get(&(api, name))?;
                (!text.trim().is_empty()).then_some((name, text.as_str()))
            });
        let record = Record::from_texts(api, texts)?;
        let (call, verdict) = check_record(&record, &Options::new(api))?;
        let judged = Judged::new(call, verdict);
        Ok(Checked {
            opened: judged.picture.clone().ok(),
            student: judged.student(),
            shown: Shown::Api(Box::new(judged)),
        })
    }

    /// The convention in use, the API's fields and the truth; whether the user asked to check.
    pub(super) fn show(&mut self, ui: &mut Ui, api: Api, state: &ExplorerState) -> bool {
        let [own, truth] = shown_fields(api);
        if own
            .iter()
            .all(|(name, _)| self.texts.get(&(api, name)).is_none_or(String::is_empty))
        {
            self.take_case(api, state);
        }
        ui.label(RichText::new(api.signature()).strong());
        ui.label(t!("check-convention-about", about = about(api)));
        let mut asked = false;
        for (title, list) in [(t!("check-your-call"), own), (t!("check-truth"), truth)] {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(title).italics());
                for (name, kind) in list {
                    let text = self.texts.entry((api, name)).or_default();
                    asked |= field(ui, name, text, width(kind));
                }
            });
        }
        ui.horizontal_wrapped(|ui| {
            if ui
                .button(t!("check-use-current-case"))
                .on_hover_text(t!("check-use-current-case-api-hover"))
                .clicked()
            {
                self.take_case(api, state);
            }
            asked |= ui.button(t!("check-button")).clicked();
        });
        asked
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_prefilled_field_never_shows_minus_zero() {
        assert_eq!(
            value_text(&Value::Vector([-0.0, -1.0, 0.25])),
            "0, -1, 0.25"
        );
        assert_eq!(value_text(&Value::Number(-0.0)), "0");
    }

    #[test]
    fn indices_follow_the_truth_when_it_agrees() {
        assert_eq!(indices(Some((1.0, 1.5)), 1.0 / 1.5), (1.0, 1.5));
        assert_eq!(indices(Some((1.0, 1.5)), 1.5), (1.5, 1.0));
        assert_eq!(indices(None, 0.5), (1.0, 2.0));
    }

    #[test]
    fn every_api_shows_its_own_fields_and_the_truth() {
        let [own, truth] = shown_fields(Api::Pbrt);
        let own: Vec<&str> = own.iter().map(|(n, _)| *n).collect();
        assert_eq!(
            own,
            ["wi", "n", "eta", "wt", "returned", "etap", "precision"]
        );
        let truth: Vec<&str> = truth.iter().map(|(n, _)| *n).collect();
        assert_eq!(truth, TRUTH);
    }
}

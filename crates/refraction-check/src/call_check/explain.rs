//! The explanation of a verdict in the API's own language: its argument names, what it means
//! by eta, how it signals total internal reflection, and which truth field would settle a tie.

use refraction_kernel::api::Api;

use super::call::Call;
use super::fields::names;
use super::readings::{Reading, normal_points_inward};
use super::result::{Resemblance, Returns, Seen};
use crate::diagnosis::Code;
use refraction_i18n::t;
use refraction_tools::vector_text::{length, spoken, spoken_vector};

/// Everything the explanation draws on.
pub(super) struct Context<'a> {
    /// The call.
    pub call: &'a Call,
    /// The readings of its arguments, the likeliest first.
    pub readings: &'a [Reading],
    /// The result mistake and what the result resembles.
    pub finding: Option<(Code, Resemblance)>,
    /// What the API returns.
    pub returns: &'a Returns,
    /// What came back, as judged.
    pub seen: Seen,
    /// Mitsuba's F, where a null `wo` on a right call may be a sampled reflection.
    pub sampled: Option<f64>,
}

/// How each API speaks, in the current language.
struct Words {
    owner: String,
    call: String,
    eta_means: String,
    incident_means: String,
    root_hint: String,
    usual: String,
}

fn words(api: Api) -> Words {
    let api = api.name();
    Words {
        owner: t!("check-api-owner", api = api),
        call: t!("check-api-call", api = api),
        eta_means: t!("check-api-eta-means", api = api),
        incident_means: t!("check-api-incident-means", api = api),
        root_hint: t!("check-api-root-hint", api = api),
        usual: t!("check-api-usual", api = api),
    }
}

/// "entering the object (from n = 1 into n = 1.5)" and the like, when the truth says.
fn situation(call: &Call) -> Option<String> {
    let t = &call.truth;
    let (from, to) = t.from_to?;
    let (from, to) = (spoken(from), spoken(to));
    let said = match t.entering {
        Some(true) if t.from_entering => t!("check-situation-entering", from = from, to = to),
        Some(false) if t.from_entering => t!("check-situation-leaving", from = from, to = to),
        _ => t!("check-situation-going", from = from, to = to),
    };
    Some(if t.entering_from_normal {
        let normal = names(call.api).normal;
        format!(
            "{said} ({})",
            t!("check-situation-outward", normal = normal)
        )
    } else {
        said
    })
}

/// The words for what came back when nothing was transmitted ([`Seen::Nothing`]'s names).
fn nothing_words(what: &str) -> String {
    match what {
        // untranslated: the name result.rs gives this answer, matched to its words
        "the zero vector" => t!("check-nothing-zero-vector"),
        // untranslated: the name result.rs gives this answer, matched to its words
        "the reflection" => t!("check-nothing-reflection"),
        _ => t!("check-nothing-false-or-null"),
    }
}

/// `items` joined by "and" (or the language's word for it).
fn and_list(items: &[String]) -> String {
    items.join(&format!(" {} ", t!("check-and")))
}

/// 1 − μ²·sin²θi for the call as the API reads it: k, cos²θt, 1 − sin²θt.
fn discriminant(call: &Call) -> f64 {
    let m = call.api.meaning(call.args);
    let cos = m.travel.dot(m.normal) / (length(m.travel) * length(m.normal));
    1.0 - m.mu * m.mu * (1.0 - cos * cos)
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn argument_sentence(ctx: &Context<'_>, reading: &Reading, code: Code) -> String {
    let (call, w, n) = (ctx.call, words(ctx.call.api), names(ctx.call.api));
    let a = call.args;
    match code {
        Code::EtaInverted => {
            let (owner, eta, means) = (w.owner, n.eta, w.eta_means);
            let (value, inverse) = (spoken(a.eta), spoken(1.0 / a.eta));
            match situation(call) {
                Some(situation) => t!("check-eta-inverted",
                    owner = owner,
                    eta = eta,
                    means = means,
                    value = value,
                    situation = situation,
                    inverse = inverse
                ),
                None => t!("check-eta-inverted-this-ray",
                    owner = owner,
                    eta = eta,
                    means = means,
                    value = value,
                    inverse = inverse
                ),
            }
        }
        Code::IncidentReversed => {
            let (owner, incident, means) = (w.owner, n.incident, w.incident_means);
            let reversed = spoken_vector((-a.incident).to_array());
            match call.truth.travel {
                Some(travel) => t!("check-incident-reversed-travel",
                    owner = owner,
                    incident = incident,
                    means = means,
                    reversed = reversed,
                    travel = spoken_vector(travel.to_array())
                ),
                None => t!("check-incident-reversed",
                    owner = owner,
                    incident = incident,
                    means = means,
                    reversed = reversed
                ),
            }
        }
        Code::NormalNotFacing => normal_sentence(call, reading, &w),
        Code::NotUnitInput => t!("check-not-unit-input",
            call = w.call,
            incident = n.incident,
            normal = n.normal,
            incident_length = spoken(length(a.incident)),
            normal_length = spoken(length(a.normal))
        ),
        Code::NotTheApiResult
        | Code::MissedTir
        | Code::NoFlipInside
        | Code::NormalTermSign
        | Code::OtherRoot
        | Code::FalseTir
        | Code::AcrossSign
        | Code::RefractedTwice
        | Code::FresnelCosSign
        | Code::NormalsMixed => String::new(),
    }
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn normal_sentence(call: &Call, reading: &Reading, w: &Words) -> String {
    let (n, a) = (names(call.api), call.args);
    let flipped = spoken_vector((-a.normal).to_array());
    match call.api {
        Api::Glsl | Api::Rtiow => t!("check-normal-against",
            call = &w.call,
            normal = n.normal,
            incident = n.incident,
            dot = spoken(a.incident.dot(a.normal)),
            flipped = flipped,
            // Not GLSL's faceforward: a glam or HLSL caller logs the same fields.
            fix = if call.api == Api::Glsl {
                t!("check-normal-fix-facing")
            } else {
                t!("check-normal-fix-rtiow")
            }
        ),
        Api::Pbrt | Api::Mitsuba => {
            let inward = match (normal_points_inward(call, reading), call.truth.entering) {
                (true, Some(true)) => format!(" ({})", t!("check-normal-inward-entering")),
                (true, Some(false)) => format!(" ({})", t!("check-normal-inward-leaving")),
                _ => String::new(),
            };
            t!("check-normal-either-side",
                call = &w.call,
                normal = n.normal,
                eta = n.eta,
                means = &w.eta_means,
                value = spoken(a.eta),
                inward = inward,
                flipped = flipped
            )
        }
    }
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn detail(ctx: &Context<'_>, looks: Resemblance) -> String {
    let w = words(ctx.call.api);
    match looks {
        Resemblance::OtherRoot => t!("check-looks-other-root", hint = w.root_hint),
        Resemblance::WrongBend => t!("check-looks-wrong-bend"),
        Resemblance::Reversed => t!("check-looks-reversed"),
        Resemblance::Length(ratio) => t!("check-looks-length", ratio = spoken(ratio)),
        Resemblance::Reflection => t!("check-looks-reflection"),
        Resemblance::Variant(code) => t!("check-looks-variant",
            call = w.call,
            variant = match code {
                Code::EtaInverted => t!("check-variant-eta-inverted"),
                Code::NormalNotFacing => t!("check-variant-normal-flipped"),
                _ => t!("check-variant-incident-reversed"),
            }
        ),
        Resemblance::Nothing(what) => t!("check-looks-nothing",
            what = nothing_words(what),
            k = spoken(discriminant(ctx.call))
        ),
        Resemblance::NotFinite => t!("check-looks-not-finite"),
        Resemblance::Off(degrees) if degrees.is_finite() => {
            t!("check-looks-off", degrees = spoken(degrees))
        }
        Resemblance::Off(_) => t!("check-looks-off-unmeasurable"),
        Resemblance::NormalTerm => t!("check-looks-normal-term"),
        Resemblance::NoFlip => t!("check-looks-no-flip"),
        Resemblance::Etap { logged, used } => t!("check-looks-etap",
            logged = spoken(logged),
            used = spoken(used)
        ),
        Resemblance::Formula | Resemblance::Direction => String::new(),
    }
}

/// The API's answer in a few words.
fn returned_text(ctx: &Context<'_>) -> String {
    let r = ctx.returns;
    match (ctx.call.api, r.transmitted) {
        (Api::Glsl | Api::Rtiow, Some(t)) => spoken_vector(t.to_array()),
        (Api::Glsl, None) => t!("check-nothing-zero-vector"),
        (Api::Pbrt, Some(t)) => t!("check-returned-pbrt-true", wt = spoken_vector(t.to_array())),
        (Api::Pbrt, None) => "false".to_owned(),
        (Api::Rtiow, None) => t!("check-returned-rtiow-cannot-refract"),
        // untranslated: Mitsuba's variable and a vector
        (Api::Mitsuba, Some(t)) => format!("wo = {}", spoken_vector(t.to_array())),
        (Api::Mitsuba, None) => t!("check-returned-mitsuba-reflects"),
    }
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn tir_sentence(ctx: &Context<'_>, looks: Resemblance) -> String {
    let k = spoken(discriminant(ctx.call));
    let signal = match ctx.call.api {
        Api::Glsl => t!("check-tir-glsl", k = k),
        Api::Pbrt => t!("check-tir-pbrt",
            sin2 = spoken(1.0 - discriminant(ctx.call))
        ),
        Api::Rtiow => t!("check-tir-rtiow",
            sine = spoken((1.0 - discriminant(ctx.call)).max(0.0).sqrt())
        ),
        Api::Mitsuba => t!("check-tir-mitsuba", k = k),
    };
    let got = match (looks, ctx.seen) {
        (Resemblance::Formula, Seen::Direction(v)) => t!("check-tir-got-formula",
            vector = spoken_vector(v.to_array()),
            length = spoken(length(v))
        ),
        (_, Seen::Direction(v)) => t!("check-tir-got-direction",
            vector = spoken_vector(v.to_array())
        ),
        _ => t!("check-tir-got-not-finite"),
    };
    format!("{signal} {got}")
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn result_sentence(ctx: &Context<'_>, code: Code, looks: Resemblance) -> String {
    if code == Code::MissedTir {
        return tir_sentence(ctx, looks);
    }
    let got = match ctx.seen {
        Seen::Direction(v) | Seen::NotFinite(v) => spoken_vector(v.to_array()),
        Seen::Nothing(what) => nothing_words(what),
    };
    t!("check-result-differs",
        call = words(ctx.call.api).call,
        returned = returned_text(ctx),
        got = got,
        detail = detail(ctx, looks)
    )
}

/// The truth fields that would tell reading `a` from reading `b`.
fn telling_fields(call: &Call, a: &Reading, b: &Reading) -> Vec<String> {
    let mut fields = Vec::new();
    if call.truth.travel.is_none() && a.meaning.travel.dot(b.meaning.travel) < 0.0 {
        fields.push("travel".to_owned());
    }
    let mu_differs = (a.meaning.mu / b.meaning.mu - 1.0).abs() > 1e-9;
    if call.truth.mu().is_none() && mu_differs {
        fields.push(t!("check-field-from-and-to"));
    }
    let normal_differs =
        a.codes.contains(&Code::NormalNotFacing) != b.codes.contains(&Code::NormalNotFacing);
    if matches!(call.api, Api::Pbrt | Api::Mitsuba)
        && (call.truth.entering.is_none() || call.truth.entering_from_normal)
        && normal_differs
    {
        fields.push("entering".to_owned());
    }
    fields
}

fn ties_sentence(ctx: &Context<'_>) -> Option<String> {
    let (first, others) = ctx.readings.split_first()?;
    if others.is_empty() {
        return None;
    }
    let list: Vec<String> = others
        .iter()
        .map(|r| {
            and_list(
                &r.codes
                    .iter()
                    .map(|c| c.name().to_owned())
                    .collect::<Vec<_>>(),
            )
        })
        .collect();
    let mut fields: Vec<String> = Vec::new();
    for other in others {
        for field in telling_fields(ctx.call, first, other) {
            if !fields.contains(&field) {
                fields.push(field);
            }
        }
    }
    let hint = if fields.is_empty() {
        let w = words(ctx.call.api);
        t!("check-ties-no-field", call = w.call, usual = w.usual)
    } else {
        t!("check-ties-give", fields = and_list(&fields))
    };
    let or = format!(", {} ", t!("check-or"));
    Some(t!("check-ties", readings = list.join(&or), hint = hint))
}

fn unchecked_note(call: &Call) -> String {
    let n = names(call.api);
    let mut missing = Vec::new();
    if call.truth.mu().is_none() {
        missing.push(t!("check-unchecked-mu", eta = n.eta));
    }
    if call.truth.travel.is_none() {
        missing.push(t!("check-unchecked-travel", incident = n.incident));
    }
    if missing.is_empty() {
        String::new()
    } else {
        let and = format!(", {} ", t!("check-and"));
        // The note follows the verdict's sentence, one space after it.
        format!(" {}", t!("check-unchecked", missing = missing.join(&and)))
    }
}

#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn unexplained(ctx: &Context<'_>) -> String {
    let (call, n) = (ctx.call, names(ctx.call.api));
    let m = call.api.meaning(call.args);
    if let Some(travel) = call.truth.travel {
        let d = refraction_tools::vector_text::angle(m.travel, travel).to_degrees();
        if (3.0..177.0).contains(&d) {
            return t!("check-unexplained-travel",
                incident = n.incident,
                degrees = spoken(d),
                travel = spoken_vector(travel.to_array())
            );
        }
    }
    match call.truth.mu() {
        Some(mu) => t!("check-unexplained-eta",
            eta = n.eta,
            value = spoken(call.args.eta),
            mu = spoken(mu),
            call = words(call.api).call
        ),
        None => t!("check-unexplained"),
    }
}

/// `text` with a leading "the" capitalised (the API names and functions keep their case).
/// Only English starts a sentence so; the translations start theirs capitalised.
fn capitalised(text: &str) -> String {
    text.strip_prefix("the ")
        // untranslated: English's own article, only ever put back capitalised
        .map_or_else(|| text.to_owned(), |rest| format!("The {rest}"))
}

/// The sentence of a call that is right.
#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn right_sentence(ctx: &Context<'_>) -> String {
    let (call, returned) = (words(ctx.call.api).call, returned_text(ctx));
    let right = match (ctx.seen, situation(ctx.call)) {
        (Seen::Nothing(_), _) if ctx.sampled.is_some() => t!("check-right-sampled",
            call = call,
            returned = returned,
            f = spoken(ctx.sampled.unwrap_or(1.0))
        ),
        (Seen::Nothing(what), _) => t!("check-right-tir",
            call = call,
            returned = returned,
            what = nothing_words(what)
        ),
        (_, Some(situation)) => t!("check-right-for-ray",
            call = call,
            returned = returned,
            situation = situation
        ),
        (_, None) => t!("check-right", call = call, returned = returned),
    };
    format!("{right}{}", unchecked_note(ctx.call))
}

/// The explanation of a call whose printed digits cannot tell it right or wrong: it looks
/// like `shown` (the mistakes as printed, or none named), yet numbers within their rounding
/// make it a right call.
pub(super) fn undecided(shown: &str) -> String {
    let shown = if shown.is_empty() {
        "unexplained"
    } else {
        shown
    };
    t!("check-undecided", shown = shown)
}

/// The explanation of one verdict.
#[must_use]
pub(super) fn explanation(ctx: &Context<'_>) -> String {
    let Some(best) = ctx.readings.first() else {
        let mut text = unexplained(ctx);
        if let Some((code, looks)) = ctx.finding {
            text = format!("{text} {}", capitalised(&result_sentence(ctx, code, looks)));
        }
        return text;
    };
    let mut sentences: Vec<String> = best
        .codes
        .iter()
        .map(|&code| argument_sentence(ctx, best, code))
        .collect();
    if let Some((code, looks)) = ctx.finding {
        sentences.push(result_sentence(ctx, code, looks));
    }
    sentences.extend(ties_sentence(ctx));
    for sentence in &mut sentences {
        *sentence = capitalised(sentence);
    }
    if sentences.is_empty() {
        return right_sentence(ctx);
    }
    sentences.join(" ")
}

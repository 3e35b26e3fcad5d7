//! The explanation of a verdict in the API's own language: its argument names, what it means
//! by eta, how it signals total internal reflection, and which truth field would settle a tie.

use refraction_kernel::api::Api;

use super::call::Call;
use super::code::Code;
use super::diagnose::Resemblance;
use super::fields::names;
use super::readings::{Reading, normal_points_inward};
use super::result::{Returns, Seen};
use crate::lines::vector_text::{length, short, short_vector};

/// Everything the explanation draws on.
pub struct Context<'a> {
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
}

/// How each API speaks.
struct Words {
    owner: &'static str,
    call: &'static str,
    eta_means: &'static str,
    incident_means: &'static str,
    root_hint: &'static str,
    usual: &'static str,
}

fn words(api: Api) -> Words {
    match api {
        Api::Glsl => Words {
            owner: "GLSL",
            call: "GLSL's refract(I, N, eta)",
            eta_means: "n_from/n_to, the index the ray leaves over the one it enters",
            incident_means: "the direction the ray travels, toward the surface",
            root_hint: "GLSL subtracts (eta * dot(N, I) + sqrt(k)) * N",
            usual: "",
        },
        Api::Pbrt => Words {
            owner: "pbrt",
            call: "pbrt's Refract(wi, n, eta)",
            eta_means: "the index on the side n points away from over the index on the side \
                        it points to (n_inside/n_outside with the outward normal)",
            incident_means: "the direction back toward where the ray came from (-ray.d)",
            root_hint: "wt takes (cosTheta_i / eta - cosTheta_t) * n",
            usual: "the outward normal with the material's eta (n_inside/n_outside)",
        },
        Api::Rtiow => Words {
            owner: "The book",
            call: "the book's refract(uv, n, etai_over_etat)",
            eta_means: "etai/etat = n_from/n_to (1/refraction_index on a front face, \
                        refraction_index on a back face)",
            incident_means: "the unit direction the ray travels (unit_vector(r_in.direction()))",
            root_hint: "r_out_parallel is -sqrt(fabs(1 - r_out_perp.length_squared())) * n",
            usual: "",
        },
        Api::Mitsuba => Words {
            owner: "Mitsuba",
            call: "Mitsuba's fresnel(cos_theta_i, eta) with refract",
            eta_means: "int_ior/ext_ior, the index on the side the normal points away from over \
                        the index on the side it points to",
            incident_means: "wi, pointing away from the surface back along the ray (-ray.d)",
            root_hint: "cos_theta_t has the opposite sign to cos_theta_i",
            usual: "the exterior normal with eta = int_ior/ext_ior",
        },
    }
}

/// "entering the object (from n = 1 into n = 1.5)" and the like, when the truth says.
fn situation(call: &Call) -> Option<String> {
    let t = &call.truth;
    let (from, to) = t.from_to?;
    Some(match t.entering {
        Some(entering) if t.from_entering => format!(
            "{} the object (from n = {} into n = {})",
            if entering { "entering" } else { "leaving" },
            short(from),
            short(to)
        ),
        _ => format!("going from n = {} into n = {}", short(from), short(to)),
    })
}

/// 1 − μ²·sin²θi for the call as the API reads it: k, cos²θt, 1 − sin²θt.
fn discriminant(call: &Call) -> f64 {
    let m = call.api.meaning(call.args);
    let cos = m.travel.dot(m.normal) / (length(m.travel) * length(m.normal));
    1.0 - m.mu * m.mu * (1.0 - cos * cos)
}

fn argument_sentence(ctx: &Context<'_>, reading: &Reading, code: Code) -> String {
    let (call, w, n) = (ctx.call, words(ctx.call.api), names(ctx.call.api));
    let a = call.args;
    match code {
        Code::EtaInverted => format!(
            "{}'s {} is {}: you passed {} for a ray {}; pass 1/{} = {}.",
            w.owner,
            n.eta,
            w.eta_means,
            short(a.eta),
            situation(call).unwrap_or_else(|| "this ray".to_owned()),
            short(a.eta),
            short(1.0 / a.eta)
        ),
        Code::IncidentReversed => format!(
            "{}'s {} is {}; yours points the other way{}: pass -{} = {}.",
            w.owner,
            n.incident,
            w.incident_means,
            call.truth.travel.map_or(String::new(), |t| format!(
                " (the ray travels along {})",
                short_vector(t.to_array())
            )),
            n.incident,
            short_vector((-a.incident).to_array())
        ),
        Code::NormalNotFacing => normal_sentence(call, reading, &w),
        Code::NotUnitInput => format!(
            "{} assumes unit {} and {} and does not normalise them: |{}| = {}, |{}| = {}; \
             normalise them first.",
            w.call,
            n.incident,
            n.normal,
            n.incident,
            short(length(a.incident)),
            n.normal,
            short(length(a.normal))
        ),
        Code::NotTheApiResult | Code::MissedTir => String::new(),
    }
}

fn normal_sentence(call: &Call, reading: &Reading, w: &Words) -> String {
    let (n, a) = (names(call.api), call.args);
    let flipped = short_vector((-a.normal).to_array());
    match call.api {
        Api::Glsl | Api::Rtiow => format!(
            "{} needs {} against {} (dot({1}, {2}) < 0) and does not flip it; yours has \
             dot({1}, {2}) = {}, as an outward normal has where the ray leaves the object: pass \
             -{1} = {} ({}).",
            w.call,
            n.normal,
            n.incident,
            short(a.incident.dot(a.normal)),
            flipped,
            if call.api == Api::Glsl {
                "faceforward(N, I, N)"
            } else {
                "the hit record's normal after set_face_normal"
            }
        ),
        Api::Pbrt | Api::Mitsuba => format!(
            "{} takes {} on either side, but {} must go with it: it is {}. Your {1} points \
             the other way from the one {2} = {} was meant for{}; pass -{1} = {} with the same \
             {2} (or keep {1} and pass 1/{2}).",
            w.call,
            n.normal,
            n.eta,
            w.eta_means,
            short(a.eta),
            match (normal_points_inward(call, reading), call.truth.entering) {
                (true, Some(true)) => " (it points into the object, and the ray is entering)",
                (true, Some(false)) => " (it points into the object, and the ray is leaving)",
                _ => "",
            },
            flipped
        ),
    }
}

fn detail(ctx: &Context<'_>, looks: Resemblance) -> String {
    let w = words(ctx.call.api);
    match looks {
        Resemblance::OtherRoot => format!(
            "the other root, with the square root's sign flipped ({})",
            w.root_hint
        ),
        Resemblance::WrongBend => "the part along the surface flipped".to_owned(),
        Resemblance::Reversed => "minus the API's answer".to_owned(),
        Resemblance::Length(ratio) => format!(
            "the same direction with {} times the length: your code scales or normalises \
             differently",
            short(ratio)
        ),
        Resemblance::Reflection => "the reflection, although this ray refracts (log only the \
                                    refraction, not a reflection chosen by Fresnel or Schlick)"
            .to_owned(),
        Resemblance::Variant(code) => format!(
            "what {} returns with {}: your implementation does that inside",
            w.call,
            match code {
                Code::EtaInverted => "eta inverted",
                Code::NormalNotFacing => "the normal flipped",
                _ => "the incident vector reversed",
            }
        ),
        Resemblance::Nothing(what) => format!(
            "{what}, which says nothing is transmitted, although this ray refracts (k = {} >= 0)",
            short(discriminant(ctx.call))
        ),
        Resemblance::NotFinite => {
            "NaN or infinite components, although this ray refracts".to_owned()
        }
        Resemblance::Off(degrees) if degrees.is_finite() => {
            format!("{} degrees from it", short(degrees))
        }
        Resemblance::Off(_) => "at no angle that can be measured from it".to_owned(),
        Resemblance::Formula | Resemblance::Direction => String::new(),
    }
}

/// The API's answer in a few words.
fn returned_text(ctx: &Context<'_>) -> String {
    let r = ctx.returns;
    match (ctx.call.api, r.transmitted) {
        (Api::Glsl, Some(t)) => short_vector(t.to_array()),
        (Api::Glsl, None) => "the zero vector".to_owned(),
        (Api::Pbrt, Some(t)) => format!("true with wt = {}", short_vector(t.to_array())),
        (Api::Pbrt, None) => "false".to_owned(),
        (Api::Rtiow, Some(t)) => short_vector(t.to_array()),
        (Api::Rtiow, None) => "cannot_refract (dielectric::scatter reflects)".to_owned(),
        (Api::Mitsuba, Some(t)) => format!("wo = {}", short_vector(t.to_array())),
        (Api::Mitsuba, None) => "F = 1 (the BSDF always reflects)".to_owned(),
    }
}

fn tir_sentence(ctx: &Context<'_>, looks: Resemblance) -> String {
    let k = short(discriminant(ctx.call));
    let sin2 = short(1.0 - discriminant(ctx.call));
    let signal = match ctx.call.api {
        Api::Glsl => format!(
            "GLSL's refract returns the zero vector here (k = {k} < 0: total internal \
             reflection); test for it and reflect instead."
        ),
        Api::Pbrt => format!(
            "pbrt's Refract returns false here (sin2Theta_t = {sin2} >= 1: total internal \
             reflection); reflect instead."
        ),
        Api::Rtiow => format!(
            "dielectric::scatter's cannot_refract holds here (ri * sin_theta = {} > 1): the \
             book reflects instead of calling refract.",
            short((1.0 - discriminant(ctx.call)).max(0.0).sqrt())
        ),
        Api::Mitsuba => format!(
            "fresnel returns F = 1 here (cos_theta_t_sqr = {k} < 0): Mitsuba always reflects."
        ),
    };
    let got = match (looks, ctx.seen) {
        (Resemblance::Formula, Seen::Direction(v)) => format!(
            " Your code used the formula's vector anyway, {} of length {}: not a ray.",
            short_vector(v.to_array()),
            short(length(v))
        ),
        (_, Seen::Direction(v)) => format!(
            " Your code gave a direction, {}, where there is none.",
            short_vector(v.to_array())
        ),
        _ => " Your code gave NaN or infinite components (the square root of a negative k, or \
              normalize() of the zero vector)."
            .to_owned(),
    };
    signal + &got
}

fn result_sentence(ctx: &Context<'_>, code: Code, looks: Resemblance) -> String {
    if code == Code::MissedTir {
        return tir_sentence(ctx, looks);
    }
    let got = match ctx.seen {
        Seen::Direction(v) | Seen::NotFinite(v) => short_vector(v.to_array()),
        Seen::Nothing(what) => what.to_owned(),
    };
    format!(
        "{} returns {} for these arguments, but the call gave {}: {}. Your own implementation \
         of it differs from the API's.",
        words(ctx.call.api).call,
        returned_text(ctx),
        got,
        detail(ctx, looks)
    )
}

/// The truth fields that would tell reading `a` from reading `b`.
fn telling_fields(call: &Call, a: &Reading, b: &Reading) -> Vec<&'static str> {
    let mut fields = Vec::new();
    if call.truth.travel.is_none() && a.meaning.travel.dot(b.meaning.travel) < 0.0 {
        fields.push("travel");
    }
    let mu_differs = (a.meaning.mu / b.meaning.mu - 1.0).abs() > 1e-9;
    if call.truth.mu().is_none() && mu_differs {
        fields.push("from and to (or entering with --inside and --outside)");
    }
    let normal_differs =
        a.codes.contains(&Code::NormalNotFacing) != b.codes.contains(&Code::NormalNotFacing);
    if matches!(call.api, Api::Pbrt | Api::Mitsuba)
        && call.truth.entering.is_none()
        && normal_differs
    {
        fields.push("entering");
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
            let codes: Vec<&str> = r.codes.iter().map(|c| c.name()).collect();
            codes.join(" and ")
        })
        .collect();
    let mut fields: Vec<&str> = Vec::new();
    for other in others {
        for field in telling_fields(ctx.call, first, other) {
            if !fields.contains(&field) {
                fields.push(field);
            }
        }
    }
    let hint = if fields.is_empty() {
        format!(
            "No truth field tells them apart: {} reads both alike; the usual call passes {}.",
            words(ctx.call.api).call,
            words(ctx.call.api).usual
        )
    } else {
        format!("Give {} to tell them apart.", fields.join(" and "))
    };
    Some(format!(
        "Equally possible: {} instead. {hint}",
        list.join(", or ")
    ))
}

fn unchecked_note(call: &Call) -> String {
    let n = names(call.api);
    let mut missing = Vec::new();
    if call.truth.mu().is_none() {
        missing.push(format!(
            "from and to (or entering with --inside and --outside) to check {}",
            n.eta
        ));
    }
    if call.truth.travel.is_none() {
        missing.push(format!("travel to check which way {} points", n.incident));
    }
    if missing.is_empty() {
        String::new()
    } else {
        format!(
            " Checked against the API's own rules only: give {}.",
            missing.join(", and ")
        )
    }
}

fn unexplained(ctx: &Context<'_>) -> String {
    let (call, n) = (ctx.call, names(ctx.call.api));
    let m = call.api.meaning(call.args);
    if let Some(travel) = call.truth.travel {
        let d = crate::lines::vector_text::angle(m.travel, travel).to_degrees();
        if (3.0..177.0).contains(&d) {
            return format!(
                "The logged {} is {} degrees from this ray's travel {}: it is not this ray's \
                 direction (nor its reverse).",
                n.incident,
                short(d),
                short_vector(travel.to_array())
            );
        }
    }
    match call.truth.mu() {
        Some(mu) => format!(
            "{} = {} fits neither n_from/n_to = {} nor its inverse as {} reads it: these are \
             not this interface's indices.",
            n.eta,
            short(call.args.eta),
            short(mu),
            words(call.api).call
        ),
        None => {
            "No combination of argument mistakes makes this call fit the truth given.".to_owned()
        }
    }
}

/// `text` with a leading "the" capitalised (the API names and functions keep their case).
fn capitalised(text: &str) -> String {
    text.strip_prefix("the ")
        .map_or_else(|| text.to_owned(), |rest| format!("The {rest}"))
}

/// The explanation of one verdict.
#[must_use]
pub fn explanation(ctx: &Context<'_>) -> String {
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
        let right = match ctx.seen {
            Seen::Nothing(what) => format!(
                "Right: {} signals total internal reflection here ({}), and the call gave {what}.",
                words(ctx.call.api).call,
                returned_text(ctx)
            ),
            _ => format!(
                "Right: {} returns {} for these arguments{}.",
                words(ctx.call.api).call,
                returned_text(ctx),
                situation(ctx.call).map_or(String::new(), |s| format!(", a ray {s}"))
            ),
        };
        return right + &unchecked_note(ctx.call);
    }
    sentences.join(" ")
}

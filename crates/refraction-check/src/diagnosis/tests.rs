use glam::DVec3;

use super::formula::{self, Outcome, Situation, Variant};
use super::hypotheses::{Family, Hypothesis, Mistake, Sides, Slip};
use super::*;

/// A line given only its own explanations (no readings of the formula).
fn line(codes: &[&[Code]], side: Side) -> Evidence {
    Evidence {
        ok: codes.is_empty(),
        alternatives: codes.iter().map(|c| c.to_vec()).collect(),
        side: Some(side),
        ..Evidence::default()
    }
}

fn tally(lines: &[(Evidence, usize)]) -> LogTally {
    let mut tally = LogTally::default();
    for (evidence, count) in lines {
        for _ in 0..*count {
            tally.add(evidence.clone());
        }
    }
    tally
}

fn codes(summary: &Summary) -> Vec<&'static str> {
    summary.diagnosis.iter().map(|f| f.code).collect()
}

/// A ray at `degrees` onto glass (1.5 in air), from outside or inside, normal +y outward.
fn situation(degrees: f64, side: Side) -> Situation {
    let a = degrees.to_radians();
    let inside = side == Side::Inside;
    Situation {
        travel: DVec3::new(a.sin(), if inside { a.cos() } else { -a.cos() }, 0.0),
        normal: DVec3::Y,
        mu: if inside { 1.5 } else { 1.0 / 1.5 },
    }
}

/// The line a renderer whose code has `mistakes` logs for a ray at `degrees` from `side`
/// (any renderer's own refraction: no arguments logged).
fn observed(mistakes: &[Mistake], degrees: f64, side: Side) -> Evidence {
    let s = situation(degrees, side);
    let h = Hypothesis {
        mistakes: mistakes.to_vec(),
    };
    let variant = h.variant(Family::Along, side == Side::Outside);
    let logged = formula::outcome(&s, variant);
    let right = formula::outcome(&s, Variant::RIGHT);
    let ok = same(logged, right);
    let past_critical = right == Outcome::Nothing;
    let transmitted = matches!(logged, Outcome::Direction(_));
    let views = vec![View {
        arguments: Codes::default(),
        variants: if ok {
            formula::agreeing(&s, 1e-6)
        } else {
            formula::reproducing(&s, logged, 1e-6)
        },
    }];
    let alternatives = match (ok, past_critical, transmitted) {
        (true, ..) => Vec::new(),
        (false, true, true) => vec![vec![Code::MissedTir]],
        (false, false, false) => vec![vec![Code::FalseTir]],
        _ => vec![vec![Code::NotTheApiResult]],
    };
    Evidence {
        ok,
        alternatives,
        views,
        side: Some(side),
        past_critical,
        band: band(refraction_model::log_map::incidence_deg(s.travel, s.normal)),
        transmitted,
        told: Told {
            entering: true,
            travel: true,
        },
        ..Evidence::default()
    }
}

fn same(a: Outcome, b: Outcome) -> bool {
    match (a, b) {
        (Outcome::Direction(a), Outcome::Direction(b)) => a.angle_between(b) < 1e-9,
        (Outcome::Nothing, Outcome::Nothing) => true,
        _ => false,
    }
}

/// A log of rays every 3° from 0° to 87°, from both sides, from code with `mistakes`.
fn log_of(mistakes: &[Mistake]) -> LogTally {
    let mut tally = LogTally::default();
    for step in 0..30 {
        for side in [Side::Outside, Side::Inside] {
            tally.add(observed(mistakes, f64::from(step) * 3.0, side));
        }
    }
    tally
}

fn mistake(slip: Slip, sides: Sides) -> Mistake {
    Mistake { slip, sides }
}

#[test]
fn a_log_with_no_mistake_says_none() {
    let t = tally(&[(line(&[], Side::Outside), 5), (line(&[], Side::Inside), 3)]);
    let s = t.summary(Some(Api::Glsl), None);
    assert_eq!(codes(&s), ["none"]);
    assert_eq!(
        (s.lines, s.judged, s.ok, s.diagnosis[0].lines),
        (8, 8, 8, 8)
    );
    assert!(s.diagnosis[0].fix.is_empty(), "no fix for no mistake");
    assert_eq!(s.verdict(), Verdict::None);
    assert_eq!(codes(&log_of(&[]).summary(None, None)), ["none"]);
}

/// Each single mistake of the formula, alone in a log, is the verdict, named by its code.
#[test]
fn each_hypothesis_is_found_alone_and_named() {
    let cases = [
        (mistake(Slip::Ratio, Sides::Both), "eta_inverted"),
        (mistake(Slip::Ratio, Sides::Leaving), "eta_inverted"),
        (mistake(Slip::Ratio, Sides::Entering), "eta_inverted"),
        (mistake(Slip::RatioAcross, Sides::Both), "eta_inverted"),
        (mistake(Slip::RatioAlong, Sides::Leaving), "eta_inverted"),
        (mistake(Slip::RatioAlong, Sides::Both), "eta_inverted"),
        (mistake(Slip::Normal, Sides::Leaving), "normal_not_facing"),
        // Without the arguments logged, a reversed incident vector is the part across N with
        // the wrong sign: the likelier line of code (a lost minus) names it.
        (mistake(Slip::Incident, Sides::Both), "across_sign"),
        (mistake(Slip::AcrossSign, Sides::Both), "across_sign"),
        (mistake(Slip::Term, Sides::Both), "normal_term_sign"),
        (mistake(Slip::Term, Sides::Leaving), "normal_not_facing"),
        (mistake(Slip::NoFlip, Sides::Leaving), "no_flip_inside"),
    ];
    for (m, code) in cases {
        let s = log_of(&[m]).summary(None, None);
        assert_eq!(codes(&s)[0], code, "{m:?}: {:?}", s.diagnosis);
        assert_eq!(codes(&s).len(), 1, "{m:?}: one finding, {:?}", s.diagnosis);
        let wrong = s.judged - s.ok;
        assert_eq!(s.diagnosis[0].lines, wrong, "{m:?}: every wrong line");
    }
}

#[test]
fn the_root_s_sign_on_both_sides_is_the_other_root_not_an_inward_normal() {
    // The same T as a normal that faces no ray, entering or leaving: an inward normal is the
    // less likely line of code where rays entering show it.
    let s = log_of(&[mistake(Slip::Root, Sides::Both)]).summary(None, None);
    assert_eq!(codes(&s), ["other_root"], "{:?}", s.diagnosis);
    assert!(
        !s.sentences()[0].contains("log entering"),
        "{:?}",
        s.sentences()
    );
    let fix = &s.diagnosis[0].fix;
    assert!(
        !fix.contains("−√k"),
        "no root a renderer may not have: {fix}"
    );
}

#[test]
fn the_ratio_inverted_beats_its_symptoms() {
    // False total internal reflection entering past sinθ = 1/1.5, missed total internal
    // reflection leaving past the critical angle, and wrong directions elsewhere: one cause.
    let s = log_of(&[mistake(Slip::Ratio, Sides::Both)]).summary(None, None);
    assert_eq!(codes(&s), ["eta_inverted"], "{:?}", s.diagnosis);
    assert!(
        s.diagnosis[0].fix.contains("upside down"),
        "{}",
        s.diagnosis[0].fix
    );
    // On the leaving rays only, the finding says so and beats the ratio inverted everywhere.
    let s = log_of(&[mistake(Slip::Ratio, Sides::Leaving)]).summary(None, None);
    assert!(
        s.diagnosis[0].place.contains("inside"),
        "{:?}",
        s.diagnosis[0]
    );
    assert!(
        s.diagnosis[0].fix.contains("leaving"),
        "{}",
        s.diagnosis[0].fix
    );
}

#[test]
fn a_ratio_in_one_part_of_t_says_which_part() {
    let across = log_of(&[mistake(Slip::RatioAcross, Sides::Both)]).summary(None, None);
    assert!(
        across.diagnosis[0].fix.contains("across N"),
        "{:?}",
        across.diagnosis[0]
    );
    let along = log_of(&[mistake(Slip::RatioAlong, Sides::Leaving)])
        .summary(None, Some(Renderer::Tungsten));
    let fix = &along.diagnosis[0].fix;
    assert!(
        fix.contains("cosθt") && fix.contains("std::abs(event.wi.z())"),
        "{fix}"
    );
}

#[test]
fn a_pair_of_mistakes_is_named_by_both() {
    let s = log_of(&[
        mistake(Slip::Root, Sides::Both),
        mistake(Slip::Ratio, Sides::Leaving),
    ])
    .summary(None, None);
    let first = &s.diagnosis[0];
    let named: Vec<&str> = core::iter::once(first.code)
        .chain(first.with.iter().copied())
        .collect();
    assert!(
        named.contains(&"eta_inverted")
            && (named.contains(&"other_root") || named.contains(&"normal_not_facing")),
        "{:?}",
        s.diagnosis
    );
}

#[test]
fn reflections_where_the_log_transmits_at_the_same_angles_are_sampling() {
    let mut t = log_of(&[]);
    let mut sampled = observed(&[], 30.0, Side::Outside);
    let s = situation(30.0, Side::Outside);
    sampled.views = vec![View {
        arguments: Codes::default(),
        variants: formula::reproducing(&s, Outcome::Nothing, 1e-6),
    }];
    sampled.sample = Some(formula::reflectance(&s).ln());
    sampled.alternatives = vec![vec![Code::FalseTir]];
    sampled.transmitted = false;
    for _ in 0..5 {
        t.add(sampled.clone());
    }
    let s = t.summary(None, None);
    assert_eq!(codes(&s), ["none"], "{:?}", s.diagnosis);
    assert_eq!((s.sampled, s.ok, s.judged), (5, 65, 65));
    // A band where nothing ever transmits: the code never transmits there.
    let mut never = LogTally::default();
    for degrees in [31.0, 32.0, 33.0, 34.0, 31.5, 32.5, 33.5] {
        let mut e = sampled.clone();
        let s = situation(degrees, Side::Outside);
        e.sample = Some(formula::reflectance(&s).ln());
        never.add(e);
    }
    never.add(observed(&[], 10.0, Side::Outside));
    let s = never.summary(None, None);
    assert_eq!(codes(&s), ["false_tir"], "{:?}", s.diagnosis);
    assert_eq!(s.ok, 1);
}

#[test]
fn lines_nothing_can_check_say_so_and_what_to_log() {
    let mut unchecked = line(&[], Side::Outside);
    unchecked.side = None;
    unchecked.unchecked = Some(Missing::Entering);
    let s = tally(&[(unchecked, 4)]).summary(Some(Api::Glsl), None);
    assert_eq!(codes(&s), ["unchecked"]);
    assert_eq!(s.verdict(), Verdict::Unchecked);
    assert!(
        s.sentences()[0].contains("Cannot be checked"),
        "{:?}",
        s.sentences()
    );
    assert!(
        s.sentences()[0].contains("Log entering"),
        "{:?}",
        s.sentences()
    );
}

#[test]
fn the_hypothesis_that_explains_most_lines_is_the_verdict() {
    let eta = [Code::EtaInverted];
    let t = tally(&[
        (line(&[&eta, &[Code::IncidentReversed]], Side::Outside), 4),
        (line(&[&eta], Side::Inside), 4),
        (line(&[], Side::Inside), 1),
    ]);
    let s = t.summary(Some(Api::Rtiow), None);
    assert_eq!(codes(&s), ["eta_inverted"]);
    assert_eq!(s.diagnosis[0].lines, 8);
    assert!(
        s.diagnosis[0].fix.contains("front_face"),
        "{:?}",
        s.diagnosis[0]
    );
    assert_eq!(s.verdict(), Verdict::Mistake);
}

#[test]
fn a_reversed_incident_vector_on_one_side_only_is_not_one_line_of_code() {
    // The book's outward normal: each leaving line ties normal_not_facing and
    // incident_reversed; only leaving lines fail.
    let tie: &[&[Code]] = &[&[Code::IncidentReversed], &[Code::NormalNotFacing]];
    let t = tally(&[(line(tie, Side::Inside), 6), (line(&[], Side::Outside), 6)]);
    let s = t.summary(Some(Api::Rtiow), None);
    assert_eq!(codes(&s), ["normal_not_facing"]);
    assert_eq!(s.diagnosis[0].lines, 6);
    assert!(s.diagnosis[0].alike.is_empty(), "{:?}", s.diagnosis[0]);
    assert!(
        s.diagnosis[0].place.contains("inside"),
        "{}",
        s.diagnosis[0].place
    );
}

#[test]
fn an_outward_normal_on_every_line_leaves_eta_as_the_cause() {
    // pbrt, 1/eta passed: every line ties three readings; the normal is outward on all.
    let tie: &[&[Code]] = &[
        &[Code::IncidentReversed],
        &[Code::EtaInverted],
        &[Code::NormalNotFacing],
    ];
    let mut outward = line(tie, Side::Outside);
    outward.normal_outward = Some(true);
    let mut leaving = line(tie, Side::Inside);
    leaving.normal_outward = Some(true);
    let s = tally(&[(outward, 3), (leaving, 3)]).summary(Some(Api::Pbrt), None);
    assert_eq!(codes(&s), ["eta_inverted"]);
    assert!(
        s.diagnosis[0].fix.contains("not 1 / eta") || s.diagnosis[0].fix.contains("cosTheta_i < 0"),
        "{:?}",
        s.diagnosis[0]
    );
}

#[test]
fn hypotheses_the_log_cannot_tell_apart_name_the_field_that_would() {
    let tie: &[&[Code]] = &[&[Code::EtaInverted], &[Code::IncidentReversed]];
    let mut unknown = line(tie, Side::Outside);
    unknown.side = None;
    let s = tally(&[(unknown.clone(), 4)]).summary(Some(Api::Glsl), None);
    assert_eq!(codes(&s), ["eta_inverted"]);
    assert_eq!(s.diagnosis[0].alike, ["incident_reversed"]);
    assert_eq!(s.diagnosis[0].tell_apart, ["travel", "entering"]);
    // A field every line logs already is not asked for.
    unknown.told.travel = true;
    let s = tally(&[(unknown, 4)]).summary(Some(Api::Glsl), None);
    assert_eq!(s.diagnosis[0].tell_apart, ["entering"]);
}

#[test]
fn lines_the_verdict_leaves_get_the_next_finding() {
    let t = tally(&[
        (line(&[&[Code::NoFlipInside]], Side::Inside), 5),
        (line(&[&[Code::NotUnitInput]], Side::Outside), 2),
        (line(&[], Side::Outside), 3),
    ]);
    let s = t.summary(Some(Api::Pbrt), None);
    assert_eq!(codes(&s), ["no_flip_inside", "not_unit_input"]);
    assert_eq!(s.diagnosis[0].lines, 5);
    assert!(
        s.diagnosis[0].fix.contains("cosTheta_i < 0"),
        "{:?}",
        s.diagnosis[0]
    );
}

#[test]
fn a_normal_term_from_inside_only_is_a_normal_that_does_not_face_the_ray() {
    let t = tally(&[
        (line(&[&[Code::NormalTermSign]], Side::Inside), 5),
        (line(&[], Side::Outside), 5),
    ]);
    assert_eq!(codes(&t.summary(None, None)), ["normal_not_facing"]);
    let everywhere = tally(&[
        (line(&[&[Code::NormalTermSign]], Side::Inside), 5),
        (line(&[&[Code::NormalTermSign]], Side::Outside), 5),
    ]);
    assert_eq!(codes(&everywhere.summary(None, None)), ["normal_term_sign"]);
}

#[test]
fn lines_nothing_explains_are_not_the_api_result() {
    let mut bad = line(&[], Side::Inside);
    bad.ok = false;
    let s = tally(&[(line(&[], Side::Outside), 2), (bad, 1)]).summary(Some(Api::Glsl), None);
    assert_eq!(codes(&s), ["not_the_api_result"]);
    assert_eq!(s.diagnosis[0].lines, 1);
    assert_eq!(s.ok, 2);
    assert!(
        !s.diagnosis[0].fix.contains("compare"),
        "{}",
        s.diagnosis[0].fix
    );
}

#[test]
fn a_log_with_no_judged_line_has_no_diagnosis_and_says_so() {
    let mut t = LogTally::default();
    t.skip();
    t.skip();
    let s = t.summary(Some(Api::Glsl), None);
    assert!(s.diagnosis.is_empty());
    assert_eq!((s.lines, s.skipped, s.judged), (2, 2, 0));
    assert_eq!(s.verdict(), Verdict::NothingJudged);
    assert!(
        s.sentences()[0].contains("No line was judged"),
        "{:?}",
        s.sentences()
    );
}

#[test]
fn the_place_names_the_kind_of_line() {
    let mut past = line(&[&[Code::MissedTir]], Side::Inside);
    past.past_critical = true;
    let t = tally(&[
        (past, 3),
        (line(&[], Side::Inside), 2),
        (line(&[], Side::Outside), 4),
    ]);
    let s = t.summary(Some(Api::Glsl), None);
    assert!(
        s.diagnosis[0].place.contains("critical angle"),
        "{}",
        s.diagnosis[0].place
    );
}

#[test]
fn a_summary_is_known_by_its_keys_in_any_order() {
    // Issue 45: it was known only by serde_json's sorted keys (`diagnosis` first).
    let summary = tally(&[(line(&[&[Code::EtaInverted]], Side::Inside), 3)]).summary(None, None);
    let written = refraction_tools::json_line(&summary);
    assert!(written.starts_with(r#"{"lines":"#), "{written}");
    assert!(looks_like_summary(written.as_bytes()));
    let sorted = serde_json::to_value(&summary).unwrap().to_string();
    assert!(sorted.starts_with(r#"{"diagnosis":"#), "{sorted}");
    assert!(looks_like_summary(sorted.as_bytes()));
    let reordered =
        r#"{"ok": 0, "sampled": 0, "skipped": 0, "diagnosis": [], "judged": 0, "lines": 0}"#;
    assert!(looks_like_summary(reordered.as_bytes()));
    for other in [
        r#"{"diagnosis": 1, "judged": 0, "lines": 0, "ok": 0, "sampled": 0, "skipped": 0}"#,
        r#"{"lines": 0, "judged": 0, "ok": 0, "skipped": 0, "sampled": 0}"#,
        r#"{"diagnosis": [], "judged": 0, "lines": 0, "ok": 0, "sampled": 0, "skipped": 0, "w": 1}"#,
        r#"{"diagnosis": [], "judged": 0, "lines": 0, "ok": 0, "sampled": 0, "skipped": 0} trailing"#,
        "[1, 2, 3]",
        "#include <cmath>\n",
    ] {
        assert!(!looks_like_summary(other.as_bytes()), "{other}");
    }
}

#[test]
fn a_log_of_many_kinds_each_explained_alone_gets_a_bounded_number_of_findings() {
    // Issue 45: the ranked search took one ranking per finding, each over every kind left.
    let all = [
        Code::EtaInverted,
        Code::IncidentReversed,
        Code::NormalNotFacing,
        Code::NotUnitInput,
        Code::MissedTir,
        Code::FalseTir,
        Code::NotTheApiResult,
    ];
    let mut lines = Vec::new();
    for (i, &a) in all.iter().enumerate() {
        for &b in &all[i + 1..] {
            lines.push((line(&[&[a, b]], Side::Inside), 1 + i));
        }
    }
    let summary = tally(&lines).summary(None, None);
    assert!(
        summary.diagnosis.len() <= rank::MAX_FINDINGS + 1,
        "{:?}",
        codes(&summary)
    );
    let explained: usize = summary.diagnosis.iter().map(|f| f.lines).sum();
    let failing: usize = lines.iter().map(|(_, n)| n).sum();
    assert_eq!(explained, failing, "every failing line is in one finding");
}

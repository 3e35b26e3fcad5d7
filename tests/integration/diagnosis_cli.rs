//! The diagnosis of a whole log, tried as a student would: each real renderer's `refract` call
//! path (pbrt-v4, smallpt, Ray Tracing in One Weekend, a GLSL shader: `renderers`) prints its
//! log with one real bug injected at a time, `check` reads it with the pattern the log needs,
//! and its `--summary` must name the bug and the fix in that renderer's own code, flag no line
//! the bug left right, and say `none` for the bug-free log.

use crate::cli::{self, Checked};
use crate::renderers::{self, Bug, Log, Renderer};

const LINES: usize = 300;

fn check(log: &Log, name: &str) -> Checked {
    let text: String = log
        .lines
        .iter()
        .flat_map(|l| [l.text.as_str(), "\n"])
        .collect();
    let (inside, outside) = (log.inside.to_string(), log.outside.to_string());
    // smallpt's log is read without an API: its code is named for the fix's words (without
    // it, the fix says which part of T is wrong in no renderer's variables).
    let mut args: Vec<&str> = log
        .api
        .map_or_else(|| vec!["--renderer", "smallpt"], |api| vec!["--api", api]);
    args.extend([
        "--inside",
        &inside,
        "--outside",
        &outside,
        "--pattern",
        log.pattern,
    ]);
    cli::check_log("diagnosis", name, &args, &text)
}

/// A piece of the fix each bug must be given, in the renderer's own code.
fn fix_names(bug: Bug) -> &'static str {
    match bug {
        Bug::None => "",
        Bug::PbrtEtaInverted => "not 1 / eta",
        Bug::PbrtNoFlipInside => "if (cosTheta_i < 0) { eta = 1 / eta;",
        Bug::PbrtNormalTermSign => "-wi / eta + (cosTheta_i / eta - cosTheta_t)",
        Bug::SmallptNormalsSwapped => "n*((into?1:-1)*(ddn*nnt+sqrt(cos2t)))",
        Bug::SmallptNntInverted => "nnt=into?nc/nt:nt/nc",
        Bug::RtiowRatioNotInverted => "rec.front_face ? (1.0/refraction_index)",
        Bug::RtiowOutwardNormal => "front_face ? outward_normal : -outward_normal",
        Bug::GlslOutwardNormal => "faceforward(N, I, N)",
        Bug::GlslEtaInverted => "entering ? 1.0 / ior : ior",
        Bug::GlslIncidentReversed => "refract(rd, N, eta)",
    }
}

/// Checks one renderer's log with `bug`, plain or with mixed printed precision.
fn assert_diagnosed(renderer: Renderer, bug: Bug, mixed: bool) {
    let log = renderers::log(renderer, bug, LINES, 7, mixed);
    let what = format!("{renderer:?} {bug:?} mixed={mixed}");
    let checked = check(&log, &format!("{renderer:?}-{bug:?}-{mixed}"));
    let verdict = &checked.summary["diagnosis"][0];
    assert_eq!(
        verdict["code"], log.expected_code,
        "{what}: {}",
        checked.summary
    );
    let fix = verdict["fix"].as_str().unwrap();
    assert!(fix.contains(fix_names(bug)), "{what}: the fix {fix:?}");
    assert_eq!(checked.summary["judged"], LINES, "{what}");
    // Nothing the bug left right is flagged; the verdict explains (almost) every wrong line.
    let mut wrong = 0;
    for (line, answer) in log.lines.iter().zip(&checked.answers) {
        if !line.wrong {
            assert_eq!(answer["ok"], true, "{what}: {} -> {answer}", line.text);
        }
        wrong += usize::from(line.wrong);
    }
    let explained = verdict["lines"].as_u64().unwrap();
    if bug == Bug::None {
        assert_eq!(wrong, 0, "{what}");
        assert_eq!(checked.summary["ok"], LINES, "{what}");
    } else {
        // A line within the match angle of the right T (near normal incidence) is judged right.
        assert!(
            explained * 100 >= wrong as u64 * 99,
            "{what}: {explained} of {wrong}"
        );
    }
    let said = checked.stderr.lines().nth(1).unwrap_or_default();
    let words = if bug == Bug::None {
        "No mistake"
    } else {
        log.expected_code
    };
    assert!(said.contains(words), "{what}: {}", checked.stderr);
}

#[test]
fn pbrt_s_three_bugs_are_named_with_pbrt_s_fix() {
    for bug in Renderer::Pbrt.bugs() {
        for mixed in [false, true] {
            assert_diagnosed(Renderer::Pbrt, *bug, mixed);
        }
    }
}

#[test]
fn smallpt_s_bugs_are_named_through_check_without_an_api() {
    for bug in Renderer::Smallpt.bugs() {
        for mixed in [false, true] {
            assert_diagnosed(Renderer::Smallpt, *bug, mixed);
        }
    }
}

#[test]
fn the_book_s_bugs_are_named_with_the_book_s_fix() {
    for bug in Renderer::Rtiow.bugs() {
        for mixed in [false, true] {
            assert_diagnosed(Renderer::Rtiow, *bug, mixed);
        }
    }
}

#[test]
fn a_glsl_shader_s_bugs_are_named_with_glsl_s_fix() {
    for bug in Renderer::Glsl.bugs() {
        for mixed in [false, true] {
            assert_diagnosed(Renderer::Glsl, *bug, mixed);
        }
    }
}

#[test]
fn every_right_log_says_none_and_flags_nothing() {
    for renderer in Renderer::ALL {
        for mixed in [false, true] {
            assert_diagnosed(renderer, Bug::None, mixed);
        }
    }
}

#[test]
fn pbrt_s_missing_flip_is_told_apart_from_an_inverted_eta_by_etap() {
    // Without etap (skipped with {_}), the lines from inside still fail; with it, the logged
    // etap equal to eta on every line is the flip that never happened.
    let log = renderers::log(Renderer::Pbrt, Bug::PbrtNoFlipInside, LINES, 3, false);
    let checked = check(&log, "no-flip");
    let verdict = &checked.summary["diagnosis"][0];
    assert!(
        verdict["where"].as_str().unwrap().contains("from inside"),
        "{verdict}"
    );
    let inside = log.lines.iter().filter(|l| l.from_inside).count();
    assert_eq!(verdict["lines"], inside, "{verdict}");
}

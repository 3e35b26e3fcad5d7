//! `check` on renderers beyond the four APIs it names, tried as a student would (issue 34):
//! each emulated renderer's log ([`crate::renderer_families`]) with one bug injected at a time,
//! read with the options and pattern docs/check.md gives for its family, must have the bug as
//! its first finding with a fix that quotes the line to change, flag no line the bug left
//! right, and say `none` for the bug-free log, sampled reflections included. Logs that cannot
//! tell a right line from a wrong one say so, and what to log.

use crate::cli::{self, Checked};
use crate::renderer_families::{self, Bug, Family, Line};
use crate::renderers::{self, Renderer};

const RECORDS: usize = 300;

fn check(args: &[&str], text: &str, name: &str) -> Checked {
    cli::check_log("families", name, args, text)
}

/// The words of a command line written as one string.
fn words(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

fn family_args(family: Family) -> Vec<&'static str> {
    let mut args = words(family.options());
    args.extend(["--pattern", family.pattern()]);
    args
}

/// Checks `family`'s log with `bug`.
fn assert_named(family: Family, bug: Bug) {
    let lines: Vec<Line> = renderer_families::log(family, bug, RECORDS, 11);
    let what = format!("{family:?} {bug:?}");
    let text = renderer_families::text(family, &lines);
    let checked = check(&family_args(family), &text, &what.replace(' ', "-"));
    let verdict = &checked.summary["diagnosis"][0];
    let (code, fix) = bug.expected();
    assert_eq!(
        verdict["code"], code,
        "{what}: {}\n{}",
        checked.summary, checked.stderr
    );
    let said = verdict["fix"].as_str().unwrap();
    assert!(
        said.contains(fix),
        "{what}: the fix {said:?} does not quote {fix:?}"
    );
    assert_eq!(
        checked.summary["judged"], RECORDS,
        "{what}: {}",
        checked.summary
    );
    assert_eq!(checked.answers.len(), RECORDS, "{what}");
    for (line, answer) in lines.iter().zip(&checked.answers) {
        if !line.wrong {
            assert_eq!(answer["ok"], true, "{what}: {}\n-> {answer}", line.text);
        }
    }
    let wrong = lines.iter().filter(|l| l.wrong).count();
    let explained = verdict["lines"].as_u64().unwrap();
    if bug == Bug::None {
        assert_eq!(checked.status, 0, "{what}: {}", checked.stderr);
        assert!(
            checked.stderr.contains("No mistake"),
            "{what}: {}",
            checked.stderr
        );
    } else {
        assert_eq!(checked.status, 1, "{what}");
        // Lines within rounding of right (near normal incidence), and reflections in a band
        // where the code also transmits, may be read as right.
        assert!(
            explained * 100 >= wrong as u64 * 90,
            "{what}: {explained} of {wrong}"
        );
    }
}

#[test]
fn mitsuba_s_bugs_are_named_with_the_line_in_fresnel_h() {
    for &bug in core::iter::once(&Bug::None).chain(Family::Mitsuba.bugs()) {
        assert_named(Family::Mitsuba, bug);
    }
}

#[test]
fn tungsten_s_bugs_are_named_in_its_local_frame() {
    for &bug in core::iter::once(&Bug::None).chain(Family::Tungsten.bugs()) {
        assert_named(Family::Tungsten, bug);
    }
}

#[test]
fn cycles_records_over_four_lines_are_read_and_its_bugs_named() {
    for &bug in core::iter::once(&Bug::None).chain(Family::Cycles.bugs()) {
        assert_named(Family::Cycles, bug);
    }
}

#[test]
fn three_js_logged_by_node_is_read_and_its_bugs_named() {
    for &bug in core::iter::once(&Bug::None).chain(Family::ThreeJs.bugs()) {
        assert_named(Family::ThreeJs, bug);
    }
}

#[test]
fn a_local_frame_log_is_read_by_the_generic_check_with_normal_z() {
    // Mitsuba's log without --api: the normal +z, wi toward the origin, None for a reflection.
    let mut args =
        words("--normal +z --convention toward-origin --inside 1.5 --outside 1 --renderer mitsuba");
    args.extend(["--pattern", "wi={w} inside={_} eta={_} wo={t_yours}"]);
    for (bug, code) in [(Bug::None, "none"), (Bug::MitsubaMulsign, "other_root")] {
        let lines = renderer_families::log(Family::Mitsuba, bug, RECORDS, 4);
        let text = renderer_families::text(Family::Mitsuba, &lines);
        let checked = check(&args, &text, &format!("generic-{bug:?}"));
        assert_eq!(
            checked.summary["diagnosis"][0]["code"], code,
            "{}",
            checked.summary
        );
        if bug == Bug::None {
            assert!(
                checked.summary["sampled"].as_u64().unwrap() > 10,
                "{}",
                checked.summary
            );
            assert!(
                checked.stderr.contains("reflected (sampled)"),
                "{}",
                checked.stderr
            );
        }
    }
}

/// The pbrt log of the earlier checks without its `entering` field.
fn pbrt_without_entering(bug: renderers::Bug) -> String {
    let log = renderers::log(Renderer::Pbrt, bug, RECORDS, 7, false);
    let mut text = String::new();
    for line in &log.lines {
        text.push_str(line.text.split(" entering=").next().unwrap());
        text.push('\n');
    }
    text
}

const PBRT: &str = "Refract wi={wi} n={n} eta={eta} -> wt={wt} etap={etap} ok={returned}";

#[test]
fn pbrt_s_caller_passing_one_over_eta_is_named_from_the_indices_alone() {
    let text = pbrt_without_entering(renderers::Bug::PbrtEtaInverted);
    let mut args = words("--api pbrt --inside 1.5 --outside 1");
    args.extend(["--pattern", PBRT]);
    let checked = check(&args, &text, "pbrt-no-entering");
    let verdict = &checked.summary["diagnosis"][0];
    assert_eq!(verdict["code"], "eta_inverted", "{}", checked.summary);
    assert!(
        verdict["fix"].as_str().unwrap().contains("not 1 / eta"),
        "{verdict}"
    );
    assert_eq!(verdict["lines"], RECORDS, "{verdict}");
    assert_eq!(checked.status, 1);
    // The bug-free log read the same way: right.
    let right = check(
        &args,
        &pbrt_without_entering(renderers::Bug::None),
        "pbrt-right",
    );
    assert_eq!(
        right.summary["diagnosis"][0]["code"], "none",
        "{}",
        right.summary
    );
    assert_eq!(right.status, 0);
}

#[test]
fn a_log_that_cannot_be_checked_says_so_and_what_to_log() {
    // pbrt without the indices: every line is right by pbrt's rules, eta unchecked.
    let text = pbrt_without_entering(renderers::Bug::PbrtEtaInverted);
    let checked = check(
        &["--api", "pbrt", "--pattern", PBRT],
        &text,
        "pbrt-unchecked",
    );
    assert_eq!(
        checked.summary["diagnosis"][0]["code"], "unchecked",
        "{}",
        checked.summary
    );
    assert_eq!(checked.status, 4, "{}", checked.stderr);
    assert!(
        checked.stderr.contains("Cannot be checked"),
        "{}",
        checked.stderr
    );
    assert!(
        checked.stderr.contains("--inside and --outside"),
        "{}",
        checked.stderr
    );
    // A GLSL shader's log with the indices but not the side: its eta cannot be told.
    let glsl = renderers::log(
        Renderer::Glsl,
        renderers::Bug::GlslEtaInverted,
        RECORDS,
        7,
        false,
    );
    let mut text = String::new();
    for line in &glsl.lines {
        text.push_str(
            &line
                .text
                .replace(" entering=1", "")
                .replace(" entering=0", ""),
        );
        text.push('\n');
    }
    let mut args = words("--api glsl --inside 1.5 --outside 1");
    args.extend(["--pattern", "rd={travel} I={I} N={N} eta={eta} -> {result}"]);
    let checked = check(&args, &text, "glsl-unchecked");
    assert_eq!(
        checked.summary["diagnosis"][0]["code"], "unchecked",
        "{}",
        checked.summary
    );
    assert!(
        checked.stderr.contains("Log entering"),
        "{}",
        checked.stderr
    );
    assert_eq!(checked.status, 4);
}

#[test]
fn a_suggested_pattern_reads_each_family_s_log() {
    for family in Family::ALL {
        let lines = renderer_families::log(family, Bug::None, 20, 2);
        let text = renderer_families::text(family, &lines);
        let api: Vec<&str> = match family {
            Family::Mitsuba => vec!["--api", "mitsuba"],
            Family::ThreeJs => vec!["--api", "glsl"],
            Family::Tungsten | Family::Cycles => Vec::new(),
        };
        let mut args = vec!["check"];
        args.extend(&api);
        args.push("--suggest-pattern");
        let output = cli::run(&args, &text);
        assert_eq!(output.status.code(), Some(0), "{family:?}: {output:?}");
        let suggested = String::from_utf8_lossy(&output.stdout).into_owned();
        let pattern = suggested
            .split("--pattern '")
            .nth(1)
            .and_then(|rest| rest.split('\'').next())
            .unwrap_or_else(|| panic!("{family:?}: {suggested}"));
        let mut check_args = words(family.options());
        check_args.extend(["--pattern", pattern]);
        let checked = check(&check_args, &text, &format!("suggested-{family:?}"));
        assert_eq!(
            checked.summary["judged"], 20,
            "{family:?}: {pattern} {}",
            checked.summary
        );
    }
    let output = cli::run(&["check", "--suggest-pattern"], "hello\nworld\n");
    assert_eq!(output.status.code(), Some(3));
    assert!(String::from_utf8_lossy(&output.stderr).contains("no line of the first 2"));
}

/// The example logs of docs/check.md's sections per renderer family, each the log its
/// renderer's emulated code prints with the bug the section shows (`UPDATE_EXAMPLES=1`
/// writes them).
fn examples() -> Vec<(&'static str, String)> {
    let family = |family, bug, seed| {
        renderer_families::text(family, &renderer_families::log(family, bug, 40, seed))
    };
    let pbrt = pbrt_without_entering(renderers::Bug::PbrtEtaInverted);
    let pbrt: String = pbrt.lines().take(40).flat_map(|l| [l, "\n"]).collect();
    vec![
        ("mitsuba-right.log", family(Family::Mitsuba, Bug::None, 21)),
        (
            "mitsuba.log",
            family(Family::Mitsuba, Bug::MitsubaTernarySwapped, 22),
        ),
        (
            "tungsten.log",
            family(Family::Tungsten, Bug::TungstenAbsDropped, 23),
        ),
        ("cycles.log", family(Family::Cycles, Bug::CyclesCosSign, 24)),
        (
            "threejs.log",
            family(Family::ThreeJs, Bug::ThreeEtaInverted, 25),
        ),
        ("pbrt-eta.log", pbrt),
    ]
}

#[test]
fn the_docs_examples_are_the_emulated_renderers_logs() {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/examples");
    for (name, text) in examples() {
        let path = folder.join(name);
        if std::env::var_os("UPDATE_EXAMPLES").is_some() {
            std::fs::write(&path, &text).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert_eq!(
            committed, text,
            "{name}: run with UPDATE_EXAMPLES=1 to write it"
        );
    }
}

//! The explorer's "Check my T" panel driven headlessly with `egui_kittest`: every sign and
//! convention mix-up named and drawn, whole JSON lines opened, bad ones refused. No display and
//! no GPU needed.

use crate::common;

use common::{click, harness, paste_log, reach, type_into};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use glam::DVec3;
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

/// The case of the default state as the check panel's fields and a T, checked.
fn check_t(h: &mut Harness<'_, Explorer>, t: &str) {
    type_into(h, "Your T", t);
}

fn vector_text(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

#[test]
fn check_my_t_names_every_sign_and_convention_mix_up_and_draws_the_students_t() {
    use refraction_kernel::Rejection;
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    let r = h.state().state().refraction().clone();
    let t = r.t().unwrap();
    let candidate = |rejection| {
        r.candidates
            .iter()
            .find(|c| c.rejection == Some(rejection))
            .unwrap()
            .t
    };
    let swapped_t = refraction_kernel::refract(&refraction_kernel::Incidence {
        w: r.w,
        n: r.n,
        mu_i: 1.5,
        mu_t: 1.000293,
        convention: r.convention,
    })
    .unwrap()
    .t()
    .unwrap();
    let cases = [
        (
            vector_text(t),
            "✔ Your T matches the refracted ray T",
            "Right",
        ),
        (
            vector_text(candidate(Rejection::WrongSide)),
            "✖ Your T matches wrong side (the other root for b)",
            "outward normal",
        ),
        (
            vector_text(candidate(Rejection::WrongBend)),
            "✖ Your T matches wrong bend (the other sign of a)",
            "mixing the conventions",
        ),
        (
            vector_text(candidate(Rejection::Reversed)),
            "✖ Your T matches reversed (−T: both signs wrong)",
            "both signs are wrong",
        ),
        (
            vector_text(swapped_t),
            "✖ Your T matches none of the four candidates",
            "index ratio upside down",
        ),
        (
            vector_text((t + DVec3::new(0.0, 0.0, 0.3)).normalize()),
            "✖ Your T matches none of the four candidates",
            "leaves the plane of incidence",
        ),
        (
            vector_text(t * 2.0),
            "✖ Your T matches T's direction, but not unit length",
            "not 1: normalise",
        ),
        (
            "vec3(nan, 0.0, 1.0)".to_owned(),
            "✖ Your T matches none of the four candidates",
            "NaN or infinite",
        ),
    ];
    check_t(&mut h, &vector_text(t));
    assert_eq!(
        h.state().state(),
        &ExplorerState::default(),
        "the case kept exactly"
    );
    assert_eq!(h.state().history().undo_steps(), 0);
    for (yours, headline, explanation) in cases {
        check_t(&mut h, &yours);
        assert!(
            h.query_by_label(headline).is_some(),
            "{yours}: no {headline}"
        );
        assert!(
            h.query_by_label_contains(explanation).is_some(),
            "{yours}: no {explanation}"
        );
    }
    check_t(&mut h, "1, 2");
    assert!(
        h.query_by_label_contains("your T: expected 3 numbers")
            .is_some()
    );
    check_t(&mut h, &vector_text(candidate(Rejection::WrongSide)));
    let student = h.state().overlay().student.unwrap();
    assert_eq!(student.label, "your T: wrong side (the other root for b)");
    assert_eq!(student.t, candidate(Rejection::WrongSide));
    // Changing the case drops the drawn T.
    click(&mut h, "Flip N");
    assert_eq!(h.state().overlay().student, None);
    assert!(
        h.query_by_label_contains("the verdict is not drawn")
            .is_some()
    );
}

#[test]
fn check_my_t_opens_a_whole_json_line_and_refuses_bad_ones_without_changing_the_state() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    // A Section 1 W fed to the Section 2 formula: the classic convention mix-up.
    let line = r#"{"w":[-0.6,0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5,"convention":"toward_origin","t_yours":"vec3(-0.4, -0.916515, 0)"}"#;
    check_t(&mut h, line);
    let state = h.state().state().clone();
    assert_eq!(state.w(), DVec3::new(-0.6, 0.8, 0.0));
    assert_eq!(state.mu_t(), 1.5);
    assert!(
        h.query_by_label("✖ Your T matches wrong bend (the other sign of a)")
            .is_some()
    );
    let tir =
        r#"{"w":[0.9,-0.43588989435406733,0],"n":[0,1,0],"mu_i":1.5,"mu_t":1,"t_yours":[0,0,0]}"#;
    check_t(&mut h, tir);
    assert!(
        h.query_by_label("✔ Your T matches total internal reflection, answered right")
            .is_some()
    );
    let before = h.state().state().clone();
    for (bad, message) in [
        ("{\"w\":[1,0,0]", "malformed JSON"),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1}"#,
            "missing field `t_yours`",
        ),
        (
            r#"{"w":[0,0,0],"n":[0,1,0],"mu_i":1,"mu_t":1,"t_yours":[1,0,0]}"#,
            "w is the zero vector",
        ),
    ] {
        check_t(&mut h, bad);
        assert!(h.query_by_label_contains(message).is_some(), "{bad}");
        assert_eq!(h.state().state(), &before);
    }
    click(&mut h, "Use the current case");
    type_into(&mut h, "μt", "x");
    check_t(&mut h, "0.5, -0.5, 0");
    assert!(
        h.query_by_label_contains("μt: “x” is not a number")
            .is_some()
    );
}

/// The text fields the panel shows now, by their labels.
fn has_field(h: &Harness<'_, Explorer>, label: &str) -> bool {
    h.query_by_role_and_label(egui::Role::TextInput, label)
        .is_some()
}

#[test]
fn each_api_shows_its_own_fields_the_truth_and_its_convention() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    // This project's own fields, with the convention they are read in shown in the panel.
    for label in ["W", "N", "μi", "μt", "Your T"] {
        assert!(has_field(&h, label), "own: no {label}");
    }
    assert!(h.query_by_label("Convention:").is_some());
    assert!(h.query_by_label("Section 2: W along the ray").is_some());
    assert!(
        h.query_by_label_contains("W is the direction the ray travels")
            .is_some()
    );
    let apis: [(&str, &[&str], &str); 4] = [
        (
            "GLSL",
            &["I", "N", "eta", "result"],
            "I is the direction the ray travels",
        ),
        (
            "pbrt",
            &["wi", "n", "eta", "wt", "returned"],
            "wi points back toward where the ray came from",
        ),
        (
            "RTIOW",
            &["uv", "n", "etai_over_etat", "refracted"],
            "uv is the unit direction the ray travels",
        ),
        (
            "Mitsuba",
            &["wi", "n", "eta", "wo"],
            "wi points away from the surface",
        ),
    ];
    for (api, fields, convention) in apis {
        click(&mut h, api);
        for label in fields
            .iter()
            .chain(&["precision", "from", "to", "travel", "entering"])
        {
            assert!(has_field(&h, label), "{api}: no {label}");
        }
        assert!(!has_field(&h, "Your T"), "{api}: the own fields are hidden");
        assert!(
            h.query_by_label_contains(convention).is_some(),
            "{api}: no convention {convention}"
        );
    }
    // The precision the judge assumes is shown: the book computes in double, GLSL in float.
    click(&mut h, "RTIOW");
    let precision = h.get_by_role_and_label(egui::Role::TextInput, "precision");
    assert_eq!(precision.value().unwrap(), "f64");
    click(&mut h, "GLSL");
    let precision = h.get_by_role_and_label(egui::Role::TextInput, "precision");
    assert_eq!(precision.value().unwrap(), "f32");
    // pbrt's wi is filled from the current case back toward the origin, eta = μt/μi.
    click(&mut h, "pbrt");
    let w = h.state().state().w();
    let wi = h.get_by_role_and_label(egui::Role::TextInput, "wi");
    // A zero component reads 0, not "-0" (issue 22).
    let plain = |x: f64| if x == 0.0 { 0.0 } else { -x };
    assert_eq!(
        wi.value().unwrap(),
        format!("{}, {}, {}", plain(w.x), plain(w.y), plain(w.z))
    );
}

/// Types a GLSL call into the panel (the fields as logged) and checks it.
fn check_glsl(h: &mut Harness<'_, Explorer>, fields: &[(&str, &str)]) {
    click(h, "GLSL");
    for (label, text) in fields {
        common::replace_text(h, label, text);
    }
    reach(h, "Check");
}

#[test]
fn a_glsl_call_with_eta_upside_down_is_named_drawn_in_glsls_convention_and_copied_as_a_test() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    check_glsl(
        &mut h,
        &[
            ("I", "0.3, -0.953939, 0"),
            ("N", "0, 1, 0"),
            ("eta", "1.5"),
            ("result", "vec3(0.45, -0.893029, 0)"),
            ("from", "1"),
            ("to", "1.5"),
        ],
    );
    assert!(h.query_by_label("✖ Mistakes: eta_inverted").is_some());
    assert!(
        h.query_by_label_contains("• eta_inverted: the index ratio upside down")
            .is_some()
    );
    assert!(h.query_by_label_contains("pass 1/1.5").is_some());
    assert!(
        h.query_by_label("GLSL returns (0.45, -0.893028, 0)")
            .is_some()
    );
    assert!(
        h.query_by_label_contains("The right T = (0.2, -0.979796, 0)")
            .is_some()
    );
    // The right call is drawn: I along the ray, μ = 1/1.5, the API's names on the arrows.
    let state = h.state().state().clone();
    assert_eq!(state.convention(), refraction_kernel::Convention::AlongRay);
    assert!((state.w() - DVec3::new(0.3, -0.953939, 0.0)).length() < 1e-12);
    assert_eq!((state.mu_i(), state.mu_t()), (1.0, 1.5));
    let student = h.state().overlay().student.unwrap();
    assert_eq!(student.label, "your result: eta_inverted");
    let names = student.names.unwrap();
    assert_eq!(
        (names.incident.as_str(), names.normal.as_str()),
        ("I (direction of travel)", "N")
    );
    assert!(
        h.query_by_label_contains("Drawn: the right call, I = (0.3, -0.953939, 0)")
            .is_some()
    );
    reach(&mut h, "GLSL test");
    assert!(h.query_by_label_contains("float eta = 1.5;").is_some());
    reach(&mut h, "Python test");
    assert!(h.query_by_label_contains("def test_refract():").is_some());
    // A right pbrt call: ok, wi drawn back toward the origin.
    reach(&mut h, "pbrt");
    for (label, text) in [
        ("wi", "-0.6, 0.8, 0"),
        ("n", "0, 1, 0"),
        ("eta", "1.5"),
        ("wt", "[ 0.4, -0.916515, 0 ]"),
        ("returned", "true"),
    ] {
        common::replace_text(&mut h, label, text);
    }
    reach(&mut h, "Check");
    assert!(h.query_by_label_contains("✔ Right: what pbrt-v4").is_some());
    let state = h.state().state().clone();
    assert_eq!(
        state.convention(),
        refraction_kernel::Convention::TowardOrigin
    );
    assert!((state.w() - DVec3::new(-0.6, 0.8, 0.0)).length() < 1e-12);
    let names = h.state().overlay().student.unwrap().names.unwrap();
    assert_eq!(names.incident, "wi (back toward the origin)");
    assert!(
        h.query_by_label("pbrt returns etap: 1.5, returned: true, wt: (0.4, -0.916515, 0)")
            .is_some()
    );
    // Another API is another question: the verdict and its drawn vector go.
    reach(&mut h, "RTIOW");
    assert!(h.query_by_label_contains("Right: what pbrt-v4").is_none());
    assert_eq!(h.state().overlay().student, None);
    reach(&mut h, "pbrt");
    // A bad field says which, and the state stays.
    common::replace_text(&mut h, "eta", "-2");
    reach(&mut h, "Check");
    assert!(
        h.query_by_label_contains("`eta` must be a finite number > 0")
            .is_some()
    );
    assert_eq!(h.state().state(), &state);
}

#[test]
#[expect(
    clippy::literal_string_with_formatting_args,
    reason = "a log pattern: its braces name fields"
)]
fn a_pasted_rtiow_log_gives_a_row_per_call_and_a_click_opens_one() {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    click(&mut h, "RTIOW");
    reach(&mut h, "📋 Paste log lines");
    let log = "LOG (0.6, -0.8, 0) | (0, 1, 0) | 0.666667 | (0.4, -0.916515, 0) | 1 -> 1.5\n\
               LOG (0.6, -0.8, 0) | (0, 1, 0) | 1.5 | (0.9, -0.43589, 0) | 1 -> 1.5\n\
               scatter: other output\n\
               LOG (0.3, -0.953939, 0) | (0, 1, 0) | 1.5 | (0.45, -0.893029, 0) | 1.5 -> 1";
    common::replace_text(
        &mut h,
        "Pattern",
        "LOG {uv} | {n} | {etai_over_etat} | {refracted} | {from} -> {to}",
    );
    paste_log(&mut h, log);
    reach(&mut h, "Check the lines");
    assert!(
        h.query_by_label_contains("Read as the pattern: 3 calls")
            .is_some()
    );
    for line in ["line 1", "line 2", "line 4"] {
        assert!(h.query_by_label(line).is_some(), "no row {line}");
    }
    assert!(
        h.query_by_label("line 3").is_none(),
        "the other output is skipped"
    );
    assert!(
        h.query_by_label("eta_inverted").is_some(),
        "row 2's mistakes"
    );

    reach(&mut h, "line 2");
    assert!(h.query_by_label("✖ Mistakes: eta_inverted").is_some());
    let uv = h.get_by_role_and_label(egui::Role::TextInput, "etai_over_etat");
    assert_eq!(uv.value().unwrap(), "1.5");
    let state = h.state().state().clone();
    assert!((state.w() - DVec3::new(0.6, -0.8, 0.0)).length() < 1e-12);
    assert_eq!((state.mu_i(), state.mu_t()), (1.0, 1.5));
    assert_eq!(
        h.state().overlay().student.unwrap().label,
        "your refracted: eta_inverted"
    );
    // Bad lines show their error in the table.
    common::replace_text(&mut h, "Pattern", "x");
    h.key_press(egui::Key::Backspace);
    h.run();
    paste_log(&mut h, "{\"uv\":[1,0\n{\"uv\":[0,-1,0],\"n\":[0,1,0]}");
    reach(&mut h, "Check the lines");
    assert!(
        h.query_by_label("Read as JSON Lines: 2 calls (2 unreadable)")
            .is_some()
    );
    // In the row, and in the diagnosis, which says why no line was judged.
    assert!(
        h.query_all_by_label_contains("malformed JSON")
            .next()
            .is_some()
    );
    assert!(
        h.query_by_label_contains("missing field `etai_over_etat`")
            .is_some()
    );
}

#[test]
fn the_panel_reads_at_13_px_and_leaves_the_diagram_its_room_at_1280_by_720() {
    for present in [false, true] {
        let mut h = Harness::builder()
            .with_context_setup(refraction_explorer::app::install_fonts)
            .with_size(egui::Vec2::new(1280.0, 720.0))
            .with_theme(egui::Theme::Light)
            .build_ui_state(
                |ui, app: &mut Explorer| app.show(ui),
                Explorer::new(ExplorerState::default()),
            );
        h.run();
        if present {
            click(&mut h, "🖵 Presentation");
        }
        click(&mut h, "✔ Check my T");
        check_glsl(&mut h, &[("eta", "1.5"), ("result", "0.45, -0.893029, 0")]);
        reach(&mut h, "📋 Paste log lines");
        paste_log(
            &mut h,
            "I,N,eta,result\n\"0.6,-0.8,0\",\"0,1,0\",1.5,\"0,0,0\"\n1,2",
        );
        reach(&mut h, "Check the lines");
        assert!(h.query_by_label("line 2").is_some());
        let least = if present { 20.0 } else { 13.0 };
        let window = h.ctx.content_rect();
        let canvas = h.get_by_role(egui::Role::Image).rect();
        let smallest = common::smallest_text_px(&h, canvas);
        assert!(smallest >= least, "present {present}: {smallest} px");
        let share = canvas.area() / window.area();
        // In presentation the tool sits beside the diagram (the layout audit's 45 %); at the
        // desk it takes at most 45 % of the height under it.
        if present {
            assert!(share >= 0.45, "the diagram has {share} of the window");
        } else {
            assert!(canvas.height() >= window.height() * 0.4, "{canvas:?}");
        }
    }
}

#[test]
fn check_my_t_gives_its_verdict_in_german_with_decimal_commas() {
    use refraction_i18n::Locale;
    use refraction_kernel::Rejection;
    // An explorer made on a German thread speaks German (the system's language, in a test).
    refraction_i18n::set_locale(Locale::De);
    let mut h = harness(ExplorerState::default());
    click(&mut h, &format!("✔ {}", refraction_i18n::t!("tool-check")));
    assert!(
        h.query_by_label("✔ Mein T prüfen").is_some(),
        "the bar in German"
    );
    let r = h.state().state().refraction().clone();
    let wrong_side = r
        .candidates
        .iter()
        .find(|c| c.rejection == Some(Rejection::WrongSide))
        .unwrap()
        .t;
    type_into(&mut h, "Dein T", &vector_text(wrong_side));
    let headline = h
        .query_by_label("✖ Dein T ist: falsche Seite (die andere Lösung für b)")
        .is_some();
    let explained = h
        .query_by_label_contains("Dein T läuft zurück in das Medium")
        .is_some();
    let right = format!(
        "Das richtige T = {}",
        refraction_diagram::numbers::vector(r.t().unwrap(), 4)
    );
    let right_shown = h.query_by_label(&right).is_some();
    refraction_i18n::set_locale(Locale::En);
    assert!(headline && explained, "the German verdict");
    assert!(right.contains("0,") && right.contains("; "), "{right}");
    assert!(right_shown, "no {right}");
}

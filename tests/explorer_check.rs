//! The explorer's "Check my T" panel driven headlessly with egui_kittest: every sign and
//! convention mix-up named and drawn, whole JSON lines opened, bad ones refused. No display and
//! no GPU needed.

mod common;

use common::{click, harness, type_into};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use refraction_diagram::ExplorerState;
use refraction_explorer::app::Explorer;

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

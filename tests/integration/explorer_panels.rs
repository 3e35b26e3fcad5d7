//! The explorer's panels driven headlessly with `egui_kittest`: the candidates table and typed
//! values and vectors. No display and no GPU needed.

use crate::common;

use common::{center_of, harness, type_into};
use egui::Pos2;
use egui_kittest::kittest::Queryable as _;
use glam::DVec3;
use refraction_model::ExplorerState;

#[test]
fn the_table_has_four_rows_with_the_right_marks() {
    let h = harness(ExplorerState::default());
    let marks = |mark: &str| -> Vec<Pos2> {
        h.query_all_by_label(mark)
            .map(|n| n.rect().center())
            .collect()
    };
    let (passes, fails) = (marks("✔"), marks("✖"));
    let expected = [
        ("T (chosen)", [true, true, true, true]),
        ("wrong side", [true, true, false, true]),
        ("wrong bend", [true, true, true, false]),
        ("reversed", [true, true, false, false]),
    ];
    for (role, columns) in expected {
        let y = center_of(&h, role).y;
        let mut row: Vec<(f32, bool)> = passes
            .iter()
            .map(|p| (p, true))
            .chain(fails.iter().map(|p| (p, false)))
            .filter(|(p, _)| (p.y - y).abs() < 4.0)
            .map(|(p, passed)| (p.x, passed))
            .collect();
        row.sort_by(|a, b| a.0.total_cmp(&b.0));
        let got: Vec<bool> = row.iter().map(|(_, passed)| *passed).collect();
        assert_eq!(got, columns, "{role}");
    }
    assert_eq!(passes.len() + fails.len(), 16);
}

#[test]
fn bad_typed_values_show_an_inline_error_and_keep_the_last_good_state() {
    let mut h = harness(ExplorerState::default());
    let good = h.state().state().clone();
    for (bad, message) in [
        ("NaN", "mu_t is NaN"),
        ("0", "mu_t is 0"),
        ("-1.5", "mu_t is -1.5"),
        ("glass", "is not a number"),
    ] {
        type_into(&mut h, "μt value", bad);
        assert!(
            h.query_by_label_contains(message).is_some(),
            "no error for {bad}"
        );
        assert_eq!(h.state().state(), &good);
    }
    type_into(&mut h, "W =", "0, 0, 0");
    assert!(h.query_by_label_contains("w is the zero vector").is_some());
    assert_eq!(h.state().state(), &good);
    type_into(&mut h, "μt value", "1.333");
    assert_eq!(h.state().state().mu_t(), 1.333);
    assert!(h.query_by_label_contains("mu_t is").is_none());
}

#[test]
fn typed_3d_vectors_are_refracted_in_their_plane() {
    let mut h = harness(ExplorerState::default());
    type_into(&mut h, "W =", "0.3, -0.5, 0.8");
    type_into(&mut h, "N =", "0, 0.6, 0.8");
    let state = h.state().state();
    assert_eq!(state.w(), DVec3::new(0.3, -0.5, 0.8));
    let plane = state.plane();
    let t = state.refraction().t().unwrap();
    assert!((plane.lift(plane.project(t)) - t).length() < 1e-12);
}

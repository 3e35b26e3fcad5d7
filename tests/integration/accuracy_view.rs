//! The "Accuracy vs time" view driven headlessly: the measurement runs in the background while
//! the window keeps drawing frames, then the verdict, plot and table appear. No time is
//! asserted; the test only waits (up to a generous limit) for the measurement to finish.

use crate::common;

use core::time::Duration;
use std::time::Instant;

use egui_kittest::kittest::Queryable as _;
use refraction_model::ExplorerState;

#[test]
fn measuring_shows_progress_then_the_verdict() {
    let mut h = common::harness(ExplorerState::default());
    h.get_by_label("Accuracy vs time").click();
    h.run();
    h.get_by_label("Quick run (a few seconds)").click();
    h.run();
    h.get_by_label("Measure").click();
    h.step();
    h.step();
    assert!(
        h.query_by_label_contains("measuring").is_some(),
        "no progress bar while measuring"
    );
    let give_up = Instant::now() + Duration::from_mins(5);
    while h.query_by_label_contains("Fastest within").is_none() {
        assert!(Instant::now() < give_up, "the measurement never finished");
        std::thread::sleep(Duration::from_millis(50));
        h.step();
    }
    assert!(h.query_by_label_contains("measuring").is_none());
    // Each variant and precision is named beside its marker on the plot (painted, as the
    // export draws it) and in the table, the SIMD peer too.
    let painted = common::painted_texts(&h);
    for row in ["stable f32", "batch f64", "trig f32", "ultraviolet f32"] {
        assert_eq!(h.query_all_by_label(row).count(), 1, "{row} in the table");
        assert!(
            painted.iter().any(|t| t == row),
            "{row} on the plot: {painted:?}"
        );
    }
    assert!(
        h.query_by_label_contains("Accuracy against time: ")
            .is_some()
    );
}

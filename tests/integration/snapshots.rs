//! Image snapshots of the lesson states, drawn on the CPU as egui's wgpu renderer draws them
//! (`software_renderer`; the committed pictures were drawn by wgpu on Mesa's software Vulkan
//! driver, and the CPU's agree with them), at 1280×720 and 1920×1080, at the desk and in
//! presentation. A change to the layout shows in review as a changed PNG under
//! `tests/snapshots/`; after a deliberate change, regenerate them with
//! `UPDATE_SNAPSHOTS=1 cargo test --test integration snapshots` and look at each one before committing.

use egui::Vec2;
use egui_kittest::{Harness, SnapshotOptions};
use refraction_explorer::app::{self, Explorer, Launch};
use refraction_model::Lesson;

use crate::software_renderer::SoftwareRenderer;

const SIZES: [(f32, f32); 2] = [(1280.0, 720.0), (1920.0, 1080.0)];

/// The window on `lesson` at `size`, in presentation if `present`, after it has settled.
fn window(lesson: Lesson, size: (f32, f32), present: bool) -> Harness<'static, Explorer> {
    let launch = Launch {
        state: Some(lesson.state()),
        present,
        ..Launch::default()
    };
    let mut harness = Harness::builder()
        .with_context_setup(app::install_fonts)
        .with_size(Vec2::new(size.0, size.1))
        .with_theme(egui::Theme::Light)
        .renderer(SoftwareRenderer::default())
        .build_ui_state(
            crate::common::whole_window,
            Explorer::launched(launch, |_| None),
        );
    harness.run();
    harness
}

/// The snapshot's name: the lesson, the size and the mode.
fn name(lesson: Lesson, (width, height): (f32, f32), present: bool) -> String {
    let mode = if present { "presentation" } else { "desk" };
    format!("{lesson:?}_{width}x{height}_{mode}").to_lowercase()
}

#[test]
fn every_lesson_at_both_sizes_looks_as_reviewed() {
    // Text is antialiased by the rasterizer: allow a few pixels to differ in shade, not layout.
    let options = SnapshotOptions::new().threshold(1.0).max_failed_pixels(200);
    // Every snapshot is taken (and written when updating) before any failure is reported.
    let mut failed = Vec::new();
    for lesson in Lesson::ALL {
        for size in SIZES {
            for present in [false, true] {
                let name = name(lesson, size, present);
                let taken = window(lesson, size, present).try_snapshot_options(&name, &options);
                if let Err(e) = taken {
                    failed.push(format!("{name}: {e}"));
                }
            }
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

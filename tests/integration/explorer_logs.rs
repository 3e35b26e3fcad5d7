//! A whole renderer's log judged in the Check my T panel, driven headlessly with
//! `egui_kittest`: pasted or opened from a file or dropped on the window, its diagnosis names
//! the bug and the fix above the table, the failure map says which side fails, and the failing
//! lines are saved as a file of tests that replaces only a test file of ours.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;

use crate::common::{click, harness, paste_log, reach, replace_text};
use crate::renderers::{Bug, Renderer, log};

/// A file dropped on the window, as a desktop hands it over.
#[derive(Debug)]
struct Dropped(PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

fn folder(name: &str) -> PathBuf {
    let folder = std::env::temp_dir().join(format!("explorer-logs-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

/// The explorer with Check my T open on `source` (`pbrt`, …) and the log section unfolded,
/// the log's pattern and the glass's indices typed.
fn panel_for(source: &str, pattern: &str) -> Harness<'static, Explorer> {
    let mut h = harness(ExplorerState::default());
    click(&mut h, "✔ Check my T");
    click(&mut h, source);
    reach(&mut h, "📋 Paste log lines");
    replace_text(&mut h, "Index inside", "1.5");
    replace_text(&mut h, "outside", "1");
    replace_text(&mut h, "Pattern", pattern);
    h
}

/// The text of the first label shown that holds `words`.
fn label_with(h: &Harness<'_, Explorer>, words: &str) -> String {
    let node = h
        .query_all_by_label_contains(words)
        .next()
        .unwrap_or_else(|| panic!("no label holds {words:?}"));
    let node = node.accesskit_node();
    node.label().or_else(|| node.value()).unwrap_or_default()
}

#[test]
fn a_pasted_pbrt_log_is_diagnosed_above_its_table_and_mapped_by_side() {
    let log = log(Renderer::Pbrt, Bug::PbrtNoFlipInside, 120, 7, false);
    let mut h = panel_for("pbrt", log.pattern);
    let text: Vec<&str> = log.lines.iter().map(|l| l.text.as_str()).collect();
    paste_log(&mut h, &text.join("\n"));
    reach(&mut h, "Check the lines");
    let verdict = label_with(&h, &format!("The bug: {}", log.expected_code));
    assert!(
        verdict.contains("cosTheta_i < 0"),
        "the fix in pbrt's code: {verdict}"
    );
    let (inside, wrong) = (
        log.lines.iter().filter(|l| l.from_inside).count(),
        log.lines.iter().filter(|l| l.wrong).count(),
    );
    let outside = log.lines.len() - inside;
    let about = label_with(&h, "Failure map. ");
    assert!(
        about.contains(&format!(
            "Arriving from outside: {outside} lines, none wrong"
        )),
        "{about}"
    );
    assert!(
        about.contains(&format!(
            "Arriving from inside: {inside} lines, {wrong} wrong"
        )),
        "{about}"
    );
}

#[test]
fn any_renderer_s_log_opened_from_a_file_is_judged_whole() {
    let log = log(Renderer::Smallpt, Bug::SmallptNntInverted, 600, 3, false);
    let path = folder("open").join("smallpt.log");
    let text: Vec<&str> = log.lines.iter().map(|l| l.text.as_str()).collect();
    std::fs::write(&path, text.join("\n")).unwrap();
    let mut h = panel_for("W, N, μ (this project)", log.pattern);
    reach(&mut h, "🗁 Open log…");
    let place = path.parent().unwrap().display().to_string();
    replace_text(&mut h, "Folder", &place);
    replace_text(&mut h, "File name", "smallpt.log");
    click(&mut h, "Open file");
    assert!(label_with(&h, "Judging the file").contains("600 lines"));
    label_with(&h, log.expected_code);
    label_with(&h, "100 more lines judged but not listed");
}

#[test]
fn a_log_dropped_on_the_window_opens_check_my_t_on_it() {
    let log = log(Renderer::Pbrt, Bug::PbrtEtaInverted, 40, 11, false);
    let path = folder("drop").join("pbrt.log");
    let text: Vec<&str> = log.lines.iter().map(|l| l.text.as_str()).collect();
    std::fs::write(&path, text.join("\n")).unwrap();
    // The log's pattern is typed first, as a student who drops several logs has it.
    let mut h = panel_for("pbrt", log.pattern);
    click(&mut h, "✔ Check my T");
    assert!(h.query_by_label("Pattern").is_none(), "the tool is closed");
    h.input_mut().dropped_files.push(Arc::new(Dropped(path)));
    h.run();
    h.run();
    label_with(&h, "Judging the file");
    label_with(&h, "eta_inverted");
}

#[test]
fn failing_lines_are_saved_as_tests_that_replace_only_tests_of_ours() {
    let log = log(Renderer::Pbrt, Bug::PbrtNormalTermSign, 30, 5, false);
    let mut h = panel_for("pbrt", log.pattern);
    let text: Vec<&str> = log.lines.iter().map(|l| l.text.as_str()).collect();
    paste_log(&mut h, &text.join("\n"));
    reach(&mut h, "Check the lines");
    let place = folder("save");
    let save = |h: &mut Harness<'_, Explorer>, name: &str| {
        reach(h, "💾 C++ test (pbrt's Refract)");
        replace_text(h, "Folder", &place.display().to_string());
        replace_text(h, "File name", name);
        click(h, "Save file");
    };
    save(&mut h, "regression.cpp");
    let written = std::fs::read_to_string(place.join("regression.cpp")).unwrap();
    assert!(
        written.starts_with("// Regression tests written by refraction-explorer"),
        "{written}"
    );
    let wrong = log.lines.iter().filter(|l| l.wrong).count();
    assert_eq!(
        written.matches("TEST(Refract, Line").count(),
        wrong,
        "{written}"
    );
    assert_eq!(written.matches("#include <gtest/gtest.h>").count(), 1);
    // Saving again asks; a student's own file is never replaced.
    save(&mut h, "regression.cpp");
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Replace");
    std::fs::write(place.join("mine.cpp"), "int main() { return 0; }\n").unwrap();
    save(&mut h, "mine.cpp");
    assert_eq!(
        std::fs::read_to_string(place.join("mine.cpp")).unwrap(),
        "int main() { return 0; }\n"
    );
    label_with(&h, "is not a test file this tool wrote");
    std::fs::remove_dir_all(&place).unwrap();
}

//! The explorer's "Save, open, share" panel driven headlessly with `egui_kittest`: state files
//! saved and opened bit for bit, bad files refused, share strings and code snippets. No display
//! and no GPU needed.

use crate::common;

use common::{click, harness, leaving_glass, type_into, undo};
use egui_kittest::kittest::Queryable as _;
use glam::DVec3;
use refraction_model::ExplorerState;

fn temp_file(name: &str) -> std::path::PathBuf {
    std::env::temp_dir().join(format!("explorer-ui-{}-{name}", std::process::id()))
}

#[test]
fn save_then_open_is_bit_exact_and_corrupt_or_foreign_files_change_nothing() {
    let w = DVec3::new(0.1, -1.0 / 3.0, 1e-300);
    let start = ExplorerState::new(
        w,
        DVec3::new(-0.0, 1.0, 0.0),
        1.000_293,
        core::f64::consts::E,
        Default::default(),
    )
    .unwrap();
    let mut h = harness(start.clone());
    click(&mut h, "💾 Save, open, share");
    let path = temp_file("state.json");
    type_into(&mut h, "State file", path.to_str().unwrap());
    click(&mut h, "💾 Save");
    assert!(h.query_by_label_contains("saved").is_some());
    click(&mut h, "Flip N");
    assert_ne!(h.state().state(), &start);
    click(&mut h, "🗁 Open");
    let opened = h.state().state().clone();
    assert_eq!(opened, start);
    let bits = |s: &ExplorerState| {
        let mut all: Vec<u64> = [s.w(), s.n()]
            .iter()
            .flat_map(|v| v.to_array())
            .map(f64::to_bits)
            .collect();
        all.extend([s.mu_i().to_bits(), s.mu_t().to_bits()]);
        all
    };
    assert_eq!(bits(&opened), bits(&start));
    undo(&mut h);
    click(&mut h, "⟳ Redo");
    for (contents, message) in [
        ("{\"w\":[0.6,-0.8", "malformed JSON"),
        ("title = \"Glass slab\"\n", "malformed JSON"),
        (r#"{"scene":"slab"}"#, "missing field `w`"),
        (
            r#"{"w":[1,0,0],"n":[0,1,0],"mu_i":-1,"mu_t":1}"#,
            "mu_i is -1",
        ),
    ] {
        std::fs::write(&path, contents).unwrap();
        click(&mut h, "🗁 Open");
        assert!(h.query_by_label_contains(message).is_some(), "{contents}");
        assert_eq!(bits(h.state().state()), bits(&start), "{contents}");
    }
    std::fs::remove_file(&path).unwrap();
    click(&mut h, "🗁 Open");
    assert!(
        h.query_by_label_contains("cannot read state file")
            .is_some()
    );
}

#[test]
fn the_share_string_reproduces_the_state_and_the_case_copies_as_code() {
    let mut h = harness(leaving_glass());
    click(&mut h, "💾 Save, open, share");
    click(&mut h, "🔗 Copy share string");
    let share = refraction_tools::state_to_json(h.state().state());
    assert!(h.query_by_label(&share).is_some());
    let shared = h.state().state().clone();
    click(&mut h, "Flip N");
    type_into(&mut h, "Paste a share string", &share);
    click(&mut h, "Apply");
    assert_eq!(h.state().state(), &shared);
    type_into(&mut h, "Paste a share string", "not a state");
    click(&mut h, "Apply");
    assert!(
        h.query_by_label_contains("share string: malformed JSON")
            .is_some()
    );
    assert_eq!(h.state().state(), &shared);
    for (button, text) in [
        ("Rust", "use refraction_kernel"),
        ("GLSL", "vec3 T = refract("),
        ("C++ (glm)", "glm::refract("),
        ("test vector", "\"t_expected\""),
        ("solve line", "\"precision\":\"f64\""),
    ] {
        click(&mut h, button);
        assert!(h.query_by_label_contains(text).is_some(), "{button}");
    }
}

#[test]
fn files_ask_before_replacing_refuse_the_wrong_kind_and_open_through_the_dialog() {
    let dir = temp_file("dialog");
    std::fs::create_dir_all(&dir).unwrap();
    let lesson = dir.join("lesson.json");
    let mut h = harness(leaving_glass());
    click(&mut h, "💾 Save, open, share");
    type_into(&mut h, "State file", lesson.to_str().unwrap());
    click(&mut h, "💾 Save");
    assert!(h.query_by_label_contains("saved").is_some());
    // Saving again asks first; Cancel leaves the file, Replace writes it.
    std::fs::write(&lesson, "{}").unwrap();
    click(&mut h, "💾 Save");
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Cancel");
    assert!(h.query_by_label_contains("left as it was").is_some());
    assert_eq!(std::fs::read_to_string(&lesson).unwrap(), "{}");
    click(&mut h, "💾 Save");
    click(&mut h, "Replace");
    assert!(std::fs::read_to_string(&lesson).unwrap().contains("\"w\""));
    // Never a state over an image, nor under an image's name.
    let picture = dir.join("picture.png");
    std::fs::write(&picture, b"\x89PNG\r\n\x1a\n").unwrap();
    type_into(&mut h, "State file", picture.to_str().unwrap());
    click(&mut h, "💾 Save");
    assert!(h.query_by_label_contains("ending in .json").is_some());
    let disguised = dir.join("disguised.json");
    std::fs::write(&disguised, b"\x89PNG\r\n\x1a\n").unwrap();
    type_into(&mut h, "State file", disguised.to_str().unwrap());
    click(&mut h, "💾 Save");
    assert!(h.query_by_label_contains("holds a PNG image").is_some());
    assert_eq!(std::fs::read(&disguised).unwrap(), b"\x89PNG\r\n\x1a\n");
    // The open dialog lists the folder's state files (not the PNG) and opens the one chosen.
    click(&mut h, "Flip N");
    let flipped = h.state().state().clone();
    click(&mut h, "🗁 Open…");
    assert!(h.query_by_label("picture.png").is_none());
    click(&mut h, "lesson.json");
    click(&mut h, "Open file");
    assert_ne!(h.state().state(), &flipped);
    assert!(h.query_by_label_contains("opened").is_some());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Clicks the export button (the heading above it has the same words).
fn export(h: &mut egui_kittest::Harness<'_, refraction_explorer::app::Explorer>) {
    h.get_by_role_and_label(egui::Role::Button, "Export picture")
        .click();
    h.run();
}

#[test]
fn exports_without_a_name_are_numbered() {
    let dir = temp_file("exports");
    std::fs::create_dir_all(&dir).unwrap();
    let mut h = harness(leaving_glass());
    type_into(&mut h, "File", dir.to_str().unwrap());
    export(&mut h);
    export(&mut h);
    assert!(dir.join("diagram-001.png").is_file());
    assert!(dir.join("diagram-002.png").is_file());
    // A name given is used; an existing image is replaced only when the user says so.
    let named = dir.join("lesson.png");
    type_into(&mut h, "File", named.to_str().unwrap());
    export(&mut h);
    assert!(named.is_file());
    export(&mut h);
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Replace");
    assert!(h.query_by_label("Replace the file?").is_none());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_scene_or_a_deck_opened_as_a_state_opens_as_what_it_is() {
    // Issue 32: a scene file opened as a state said "malformed JSON".
    let mut h = harness(leaving_glass());
    click(&mut h, "💾 Save, open, share");
    let scene = temp_file("slab.toml");
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/docs/examples/slab.toml"),
        &scene,
    )
    .unwrap();
    type_into(&mut h, "State file", scene.to_str().unwrap());
    click(&mut h, "🗁 Open");
    assert_eq!(h.state().view(), refraction_explorer::app::View::Scenes);
    assert_eq!(
        h.state().state(),
        &leaving_glass(),
        "the state is as it was"
    );
    click(&mut h, "One interface");
    assert!(
        h.query_by_label_contains("is a scene, not a state")
            .is_some()
    );
    let deck = temp_file("prisms.toml");
    std::fs::copy(
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/docs/examples/prisms-deck.toml"
        ),
        &deck,
    )
    .unwrap();
    type_into(&mut h, "State file", deck.to_str().unwrap());
    click(&mut h, "🗁 Open");
    // The deck's first step shows (with its own tools: the panel gives way to them).
    assert!(h.state().lesson().current().is_some());
    assert_eq!(h.state().lesson().deck.as_ref().unwrap().title, "Prisms");
    click(&mut h, "💾 Save, open, share");
    std::fs::write(&scene, "title = \"Broken\"\n").unwrap();
    type_into(&mut h, "State file", scene.to_str().unwrap());
    click(&mut h, "🗁 Open");
    assert!(h.query_by_label_contains("read as a scene").is_some());
    std::fs::remove_file(&scene).unwrap();
    std::fs::remove_file(&deck).unwrap();
}

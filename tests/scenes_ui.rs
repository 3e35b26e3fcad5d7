//! The Scenes view driven headlessly with egui_kittest: picking a scene, dragging the source,
//! clicking a hit point to open it in the single-interface view. No display and no GPU needed.

mod common;

use common::{drag, harness_for, press_move_release};
use egui::{Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use refraction_diagram::ExplorerState;
use refraction_explorer::app::{Explorer, View};
use refraction_scene::{Scene, Side};

fn droplet() -> Harness<'static, Explorer> {
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(Scene::embedded("droplet").unwrap());
    harness_for(explorer)
}

#[test]
fn the_bar_switches_to_scenes_and_the_picker_opens_a_scene() {
    let mut h = harness_for(Explorer::new(ExplorerState::default()));
    h.get_by_label("Scenes").click();
    h.run();
    assert_eq!(h.state().view(), View::Scenes);
    assert_eq!(h.state().scenes().scene().name(), "interface");
    h.get_by_label("Scene").click();
    h.run();
    h.get_by_label("Water droplet (rainbow)").click();
    h.run();
    let scenes = h.state().scenes();
    assert_eq!(scenes.scene().name(), "droplet");
    assert!(scenes.trace().counts.wavelengths > 1);
    assert!(h.query_by_label_contains("reflections spawned").is_some());
    assert!(h.query_by_label("Shape 1 handle (water)").is_some());
}

#[test]
fn dragging_the_source_retraces_the_scene() {
    let mut h = droplet();
    let origin = h.state().scenes().scene().source().origin;
    let first = h.state().scenes().trace().segments[0];
    let from = h.get_by_label("Source handle").rect().center();
    let to = from + Vec2::new(0.0, 40.0);
    drag(&mut h, from, to);
    let scenes = h.state().scenes();
    let moved = scenes.scene().source().origin;
    assert!(moved.y < origin.y - 0.1, "{origin} → {moved}");
    assert_ne!(scenes.trace().segments[0], first);
    let handle = h.get_by_label("Source handle").rect().center();
    assert!(
        handle.distance(to) < 2.0,
        "{handle:?} is not under the pointer {to:?}"
    );
}

#[test]
fn clicking_the_droplets_exit_opens_it_with_the_flipped_normal() {
    let mut h = droplet();
    let scenes = h.state().scenes();
    let exit = *scenes
        .trace()
        .hits
        .iter()
        .find(|hit| hit.side == Side::Leaving)
        .unwrap();
    let at = scenes.to_screen(exit.point).unwrap();
    press_move_release(&mut h, &[at]);
    assert_eq!(h.state().view(), View::Interface);
    let state = h.state().state();
    let refraction = state.refraction();
    assert!(refraction.normal_flipped);
    assert!(state.mu_i() > 1.3 && state.mu_t() < 1.01, "water into air");
    assert!(h.query_by_label("W handle").is_some());
}

#[test]
fn a_click_away_from_every_hit_stays_in_the_scene() {
    let mut h = droplet();
    let at = h
        .state()
        .scenes()
        .to_screen(glam::DVec2::new(2.5, -2.2))
        .unwrap();
    press_move_release(&mut h, &[at]);
    assert_eq!(h.state().view(), View::Scenes);
}

#[test]
fn undo_puts_the_scene_back_one_drag_at_a_time() {
    let mut h = droplet();
    let origin = h.state().scenes().scene().source().origin;
    let from = h.get_by_label("Source handle").rect().center();
    let path: Vec<Pos2> = (0..=4)
        .map(|step| from + Vec2::new(0.0, 10.0 * step as f32))
        .collect();
    press_move_release(&mut h, &path);
    let moved = h.state().scenes().scene().source().origin;
    assert_ne!(moved, origin);
    h.get_by_label("⟲ Undo").click();
    h.run();
    assert_eq!(h.state().scenes().scene().source().origin, origin);
    assert_eq!(h.state().scenes().scene().name(), "droplet");
    h.get_by_label("⟳ Redo").click();
    h.run();
    assert_eq!(h.state().scenes().scene().source().origin, moved);
}

#[test]
fn an_edited_scene_saves_and_opens_again_and_a_corrupt_file_changes_nothing() {
    let folder = std::env::temp_dir().join(format!("scene-files-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let saved = folder.join("moved.toml");
    let mut h = droplet();
    let from = h.get_by_label("Source handle").rect().center();
    press_move_release(
        &mut h,
        &[
            from,
            from + Vec2::new(0.0, 20.0),
            from + Vec2::new(0.0, 40.0),
        ],
    );
    let edited = h.state().scenes().scene().clone();
    common::replace_text(&mut h, "Scene file", saved.to_str().unwrap());
    h.get_by_label("Save file").click();
    h.run();
    h.get_by_label("Reset").click();
    h.run();
    assert_ne!(h.state().scenes().scene().source(), edited.source());
    h.get_by_label("Open file").click();
    h.run();
    // Equal in everything the file holds; the name comes from the file's name.
    let opened = h.state().scenes().scene().clone();
    assert_eq!(opened.name(), "moved");
    assert_eq!(opened.to_toml(), edited.to_toml());
    assert_eq!(opened.source(), edited.source());

    let corrupt = folder.join("corrupt.toml");
    std::fs::write(&corrupt, "title = \"x\"\n[source]\nkind = \"laser\"\n").unwrap();
    common::replace_text(&mut h, "Scene file", corrupt.to_str().unwrap());
    h.get_by_label("Open file").click();
    h.run();
    assert_eq!(h.state().scenes().scene(), &opened);
    assert!(
        h.query_by_label_contains("corrupt.toml:3:").is_some(),
        "the error names the file, line and column"
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

//! The Scenes view driven headlessly with `egui_kittest`: picking a scene, dragging the source,
//! clicking a hit point to open it in the single-interface view. No display and no GPU needed.

use crate::common;

use common::{click, drag, harness_for, press_move_release};
use egui::{Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use refraction_explorer::app::{Explorer, View};
use refraction_model::ExplorerState;
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

/// The droplet at 1,000 rays per colour (43,396 segments): too big to trace every frame of a
/// drag on a classroom machine.
fn dense_droplet() -> Harness<'static, Explorer> {
    let mut scene = Scene::embedded("droplet").unwrap();
    scene.set_ray_count(1000).unwrap();
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(scene);
    harness_for(explorer)
}

#[test]
fn a_dense_scene_drags_as_a_draft_and_is_whole_again_when_the_pointer_lets_go() {
    let mut h = dense_droplet();
    h.run();
    let full = h.state().scenes().trace().counts;
    assert_eq!(full.source_rays, 7000, "{full:?}");
    assert_eq!(h.state().scenes().draft(), None);
    let from = h.get_by_label("Source handle").rect().center();
    h.hover_at(from);
    h.run();
    h.drag_at(from);
    h.run();
    for step in 1..=3 {
        h.hover_at(from + Vec2::new(0.0, 8.0 * step as f32));
        h.run();
        let scenes = h.state().scenes();
        let every = scenes.draft().expect("a draft while the pointer drags");
        let drafted = scenes.trace().counts;
        assert!(
            drafted.segments < 3_000 && drafted.source_rays < full.source_rays,
            "1 in {every}: {drafted:?}"
        );
        assert_eq!(drafted.wavelengths, full.wavelengths, "every colour kept");
        let note = format!("Draft while dragging: one ray in {every}");
        assert!(
            h.query_by_label_contains(&note).is_some(),
            "the canvas says {note}"
        );
    }
    h.drop_at(from + Vec2::new(0.0, 24.0));
    h.run();
    let scenes = h.state().scenes();
    assert_eq!(scenes.draft(), None);
    assert!(h.query_by_label_contains("Draft while dragging").is_none());
    let whole = scenes.trace();
    assert_eq!(whole.counts.source_rays, full.source_rays);
    // Exactly what a fresh view of the moved scene traces.
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(scenes.scene().clone());
    let mut fresh = harness_for(explorer);
    fresh.run();
    assert_eq!(fresh.state().scenes().trace().segments, whole.segments);
}

#[test]
fn every_built_in_scene_at_its_own_ray_count_drags_in_full() {
    for info in refraction_scene::catalogue() {
        let mut explorer = Explorer::new(ExplorerState::default());
        explorer.open_scene(Scene::embedded(info.name).unwrap());
        let mut h = harness_for(explorer);
        h.run();
        let Some(handle) = h.query_by_label("Source handle").map(|n| n.rect().center()) else {
            continue;
        };
        let rays = h.state().scenes().trace().counts.source_rays;
        h.hover_at(handle);
        h.run();
        h.drag_at(handle);
        h.run();
        h.hover_at(handle + Vec2::new(0.0, 10.0));
        h.run();
        let scenes = h.state().scenes();
        assert_eq!(scenes.draft(), None, "{}", info.name);
        assert_eq!(scenes.trace().counts.source_rays, rays, "{}", info.name);
        h.drop_at(handle + Vec2::new(0.0, 10.0));
        h.run();
    }
}

#[test]
fn clicking_the_droplets_exit_opens_it_with_the_flipped_normal() {
    let mut h = droplet();
    let scenes = h.state().scenes();
    let exit = *scenes
        .trace()
        .hits
        .iter()
        .find(|hit| hit.side == Side::Inside)
        .unwrap();
    let at = scenes.to_screen(exit.point).unwrap();
    press_move_release(&mut h, &[at]);
    assert_eq!(h.state().view(), View::Interface);
    let state = h.state().state();
    let refraction = state.refraction();
    assert!(refraction.normal_flipped);
    assert!(state.mu_i() > 1.3 && state.mu_t() < 1.01, "water into air");
    assert!(h.query_by_label("Angle of incidence θi (W)").is_some());
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

#[test]
fn a_scene_file_is_replaced_only_when_the_user_says_so_and_never_over_another_kind() {
    let folder = std::env::temp_dir().join(format!("scene-replace-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let saved = folder.join("lesson.toml");
    let mut h = droplet();
    common::replace_text(&mut h, "Scene file", saved.to_str().unwrap());
    click(&mut h, "Save file");
    let first = std::fs::read_to_string(&saved).unwrap();
    assert!(first.contains("[source]"));
    // Saving again asks first; Cancel keeps the file, Replace writes the scene as edited.
    std::fs::write(&saved, "# kept\ntitle = \"mine\"\n").unwrap();
    click(&mut h, "Save file");
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Cancel");
    assert_eq!(
        std::fs::read_to_string(&saved).unwrap(),
        "# kept\ntitle = \"mine\"\n"
    );
    assert!(h.query_by_label_contains("left as it was").is_some());
    click(&mut h, "Save file");
    click(&mut h, "Replace");
    assert_eq!(std::fs::read_to_string(&saved).unwrap(), first);
    // Never over a state file or an image, whatever the name says.
    let state = folder.join("state.json");
    std::fs::write(&state, "{\"w\":[0,-1,0]}").unwrap();
    common::replace_text(&mut h, "Scene file", state.to_str().unwrap());
    click(&mut h, "Save file");
    assert!(h.query_by_label_contains("ending in .toml").is_some());
    let disguised = folder.join("picture.toml");
    std::fs::write(&disguised, b"\x89PNG\r\n\x1a\n").unwrap();
    common::replace_text(&mut h, "Scene file", disguised.to_str().unwrap());
    click(&mut h, "Save file");
    assert!(
        h.query_by_label_contains("holds a PNG image, not a scene (TOML)")
            .is_some()
    );
    assert_eq!(std::fs::read(&disguised).unwrap(), b"\x89PNG\r\n\x1a\n");
    assert_eq!(std::fs::read_to_string(&state).unwrap(), "{\"w\":[0,-1,0]}");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_open_dialog_lists_scene_files_and_opens_the_one_chosen() {
    let folder = std::env::temp_dir().join(format!("scene-dialog-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let prism = Scene::embedded("dispersing-prism").unwrap();
    std::fs::write(folder.join("prism.toml"), prism.to_toml().unwrap()).unwrap();
    std::fs::write(folder.join("notes.png"), b"\x89PNG\r\n\x1a\n").unwrap();
    let mut h = droplet();
    common::replace_text(
        &mut h,
        "Scene file",
        folder.join("x.toml").to_str().unwrap(),
    );
    click(&mut h, "🗁 Open…");
    assert!(
        h.query_by_label("notes.png").is_none(),
        "only scene files are listed"
    );
    click(&mut h, "prism.toml");
    // The dialog's own button (the strip has one of the same name behind it).
    let buttons = h.get_all_by_role_and_label(egui::Role::Button, "Open file");
    buttons.last().unwrap().click();
    h.run();
    assert_eq!(h.state().scenes().scene().name(), "prism");
    assert_eq!(h.state().scenes().scene().source(), prism.source());
    assert!(h.query_by_label("File name").is_none(), "the dialog closed");
    // Save as… names a new file in the dialog and writes it there.
    click(&mut h, "💾 Save as…");
    common::replace_text(&mut h, "File name", "copy.toml");
    let buttons = h.get_all_by_role_and_label(egui::Role::Button, "Save file");
    buttons.last().unwrap().click();
    h.run();
    let copy = std::fs::read_to_string(folder.join("copy.toml")).unwrap();
    assert_eq!(copy, prism.to_toml().unwrap());
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_scene_picture_without_a_name_is_numbered_and_an_existing_one_is_asked_about() {
    let folder = std::env::temp_dir().join(format!("scene-pictures-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let mut h = droplet();
    for _ in 0..2 {
        click(&mut h, "Export picture");
        common::replace_text(
            &mut h,
            "Picture file (.png or .svg)",
            folder.to_str().unwrap(),
        );
        h.get_by_label_contains("Export 1920×1080").click();
        h.run();
    }
    assert!(folder.join("scene-001.svg").is_file());
    assert!(folder.join("scene-002.svg").is_file());
    let named = folder.join("slide.png");
    std::fs::write(&named, b"\x89PNG\r\n\x1a\nold").unwrap();
    click(&mut h, "Export picture");
    common::replace_text(
        &mut h,
        "Picture file (.png or .svg)",
        named.to_str().unwrap(),
    );
    h.get_by_label_contains("Export 1920×1080").click();
    h.run();
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Replace");
    let bytes = std::fs::read(&named).unwrap();
    assert!(bytes.len() > 1000, "the picture replaced the old file");
    std::fs::remove_dir_all(&folder).unwrap();
}

/// Steps the window until no trace runs in the background (at most a minute).
fn until_traced(h: &mut Harness<'static, Explorer>) {
    let start = std::time::Instant::now();
    while h.state().scenes().tracing().is_some() {
        assert!(
            start.elapsed().as_secs() < 60,
            "the background trace never ended"
        );
        std::thread::sleep(core::time::Duration::from_millis(20));
        h.step();
    }
    h.run();
}

#[test]
fn a_huge_trace_runs_in_the_background_with_progress_and_cancel() {
    // A mirror box that reflects every ray a thousand times, beside as many lines as a scene
    // may hold, which every ray is tested against at every step: a trace that runs to its full
    // work budget, which the window must not wait for.
    let lines = "[[shapes]]\nline = { point = [50, 0], normal = [1, 0], medium = \"vacuum\" }\n";
    let text = format!(
        "title = \"Mirror box\"\n[media.glass]\nindex = 1.5\n{}[[shapes]]\n\
         polygon = {{ points = [[0, 0], [1, 0], [1, 1], [0, 1]], medium = \"glass\" }}\n\
         [source]\nkind = \"fan\"\norigin = [-1, 0.5]\ndirection = [1, 0.1]\nrays = 1000\n\
         spread_deg = 30\n[effects]\npartial_reflection = true\nmax_depth = 1000\n",
        lines.repeat(refraction_scene::MAX_SHAPES - 1)
    );
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(Scene::from_toml(&text, "box.toml", "box").unwrap());
    assert!(
        explorer.scenes().tracing().is_some(),
        "traced in the background"
    );
    let mut h = harness_for(explorer);
    assert!(
        h.state().scenes().trace().segments.is_empty(),
        "nothing finished yet"
    );
    assert!(h.query_by_label_contains("tracing…").is_some());
    h.get_by_label("Cancel").click();
    h.run();
    until_traced(&mut h);
    let counts = h.state().scenes().trace().counts;
    assert_eq!(counts.stopped, Some(refraction_scene::Stop::Cancelled));
    assert!(h.query_by_label_contains("was cancelled").is_some());
}

#[test]
fn a_runaway_droplet_stops_at_what_the_screen_can_show_and_says_so() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/crates/refraction-scene/tests/data/deep-droplet.toml"
    );
    let scene = Scene::load(path).unwrap_or_else(|e| panic!("{e}"));
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(scene);
    let mut h = harness_for(explorer);
    until_traced(&mut h);
    let trace = h.state().scenes().trace();
    assert_eq!(trace.segments.len(), 200_000);
    assert!(
        h.query_by_label_contains("budget of 200000 segments")
            .is_some()
    );
}

#[test]
fn a_click_in_or_beside_the_file_dialog_never_reaches_the_scene_under_it() {
    for present in [false, true] {
        let mut h = droplet();
        if present {
            click(&mut h, "🖵 Presentation");
            // The scene's files fold away in presentation: unfold them.
            click(&mut h, "⏷ Files and hint");
        }
        let scenes = h.state().scenes();
        let hits: Vec<Pos2> = scenes
            .trace()
            .hits
            .iter()
            .map(|hit| scenes.to_screen(hit.point).unwrap())
            .collect();
        // In an empty folder, so that the dialog's size does not follow the working folder's.
        let empty = std::env::temp_dir().join(format!("scenes-ui-empty-{}", std::process::id()));
        std::fs::create_dir_all(&empty).unwrap();
        let open = |h: &mut Harness<'_, Explorer>| {
            click(h, "🗁 Open…");
            common::replace_text(h, "Folder", &empty.display().to_string());
            h.run();
        };
        open(&mut h);
        // The dialog's Cancel over a hit point, the dim backdrop over the button that opened
        // the dialog, and the backdrop over a hit point beside the dialog (where the window
        // leaves room for one): each closes the dialog and does nothing else.
        let cancel = h.get_by_label("Cancel").rect();
        let heading = h.get_by_label("Open a file").rect();
        let opener = h.get_all_by_label("🗁 Open…").next().unwrap().rect();
        let beside = hits
            .iter()
            .copied()
            .find(|p| p.y > cancel.max.y + 30.0 || p.y < heading.min.y - 30.0);
        if !present {
            assert!(
                hits.iter().any(|p| cancel.contains(*p)),
                "a hit lies under Cancel"
            );
            assert!(beside.is_some(), "a hit lies beside the dialog");
        }
        // The button that opened it, where the dialog leaves it uncovered (at the desk it does).
        let opener = Some(opener.center()).filter(|p| p.y < heading.min.y - 20.0);
        assert!(
            present || opener.is_some(),
            "the opener lies beside the dialog"
        );
        for at in [Some(cancel.center()), opener, beside]
            .into_iter()
            .flatten()
        {
            if h.query_by_label("File name").is_none() {
                open(&mut h);
            }
            // Pressed and released within one frame, as a quick click often is.
            h.hover_at(at);
            h.run();
            h.drag_at(at);
            h.drop_at(at);
            h.run();
            assert_eq!(h.state().view(), View::Scenes, "a click at {at:?}");
            assert!(h.query_by_label("File name").is_none(), "the dialog closed");
        }
    }
}

#[test]
fn in_presentation_the_scene_controls_fold_to_one_row_and_unfold_on_request() {
    // Issue 22: at 1280×720 in presentation the controls took a third of the window.
    let mut h = common::harness_sized(Explorer::new(ExplorerState::default()), (1280.0, 720.0));
    click(&mut h, "Scenes");
    let canvas = |h: &Harness<'_, Explorer>| h.get_by_role(egui::Role::Image).rect().height();
    let desk = canvas(&h);
    assert!(h.query_by_label("Open file").is_some());
    click(&mut h, "🖵 Presentation");
    for _ in 0..3 {
        h.run();
    }
    assert!(h.query_by_label("Open file").is_none(), "folded away");
    let folded = canvas(&h);
    click(&mut h, "⏷ Files and hint");
    assert!(h.query_by_label("Open file").is_some(), "unfolded");
    let unfolded = canvas(&h);
    // Zoomed by 1.6, the folded strip still leaves the scene more of the window than the desk.
    let window = h.ctx.content_rect().height();
    assert!(
        folded / window > desk / 720.0,
        "{folded} of {window} against {desk} of 720"
    );
    assert!(unfolded < folded);
    click(&mut h, "⏶ Fewer controls");
    assert!(h.query_by_label("Open file").is_none());
}

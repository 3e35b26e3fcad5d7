//! The physics a teacher reaches for next, driven headlessly with `egui_kittest`: the Fresnel
//! tool with its cursor following the drag, the Intensities switch (p light at Brewster's angle
//! reflects nothing), the Wavefronts switch, and Export animation with its progress and Cancel;
//! at the desk and in presentation at 1280×720.

use crate::common;

use common::{center_of, click, drag, harness, harness_for, harness_sized as sized, replace_text};
use egui::{Role, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use glam::{DVec3, Vec2 as GVec2};
use refraction_diagram::{Diagram, Figure, Shares};
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;
use refraction_model::Polarisation;

const FRESNEL: &str = "📈 Fresnel";
const EFFECTS: &str = "Effects";

/// From air into glass at Brewster's angle, tanθB = 1.5.
fn at_brewster() -> ExplorerState {
    ExplorerState::new(
        DVec3::new(1.5, -1.0, 0.0),
        DVec3::Y,
        1.0,
        1.5,
        Default::default(),
    )
    .unwrap()
}

/// The diagram as the window draws it now, on its canvas.
fn drawn(h: &Harness<'_, Explorer>) -> Diagram {
    let rect = h.get_by_role(Role::Image).rect();
    let explorer = h.state();
    let size = GVec2::new(rect.width(), rect.height());
    Diagram::with_overlay(explorer.state(), size, &explorer.overlay())
}

fn texts(diagram: &Diagram) -> Vec<String> {
    diagram
        .shapes
        .iter()
        .filter_map(|s| match s {
            Figure::Text(l) => Some(l.text.clone()),
            _ => None,
        })
        .collect()
}

/// The share of the window the diagram's canvas has.
fn share(h: &Harness<'_, Explorer>) -> f32 {
    h.get_by_role(Role::Image).rect().area() / h.ctx.content_rect().area()
}

#[test]
fn the_fresnel_tool_names_its_landmarks_and_its_cursor_follows_the_drag() {
    let mut h = harness(ExplorerState::default());
    assert!(h.query_by_label_contains("Brewster's angle").is_none());
    click(&mut h, FRESNEL);
    assert!(
        h.query_by_label_contains("Brewster's angle θB = 56.3°: no p light")
            .is_some()
    );
    assert!(
        h.query_by_label_contains("No critical angle: the light goes into a medium of higher")
            .is_some()
    );
    // The plot is the export's figure, painted: its legend, values and source are its texts.
    let painted = common::painted_texts(&h);
    for words in [
        "Hecht, Optics",
        "Rp (p light reflected)",
        "Rp\u{a0}=\u{a0}",
        "θi\u{a0}=\u{a0}",
    ] {
        assert!(
            painted.iter().any(|t| t.contains(words)),
            "{words}: {painted:?}"
        );
    }
    assert!(
        h.query_by_label_contains("Fresnel plot: reflected and transmitted light")
            .is_some()
    );
    let before = format!("At θi = {:.1}°", h.state().state().incidence_degrees());
    assert!(h.query_by_label_contains(&before).is_some(), "{before}");
    let from = center_of(&h, "Angle of incidence θi (W)");
    drag(&mut h, from, from + Vec2::new(-70.0, 30.0));
    let degrees = h.state().state().incidence_degrees();
    let after = format!("At θi = {degrees:.1}°");
    assert_ne!(before, after, "the drag turned W");
    assert!(h.query_by_label_contains(&after).is_some(), "{after}");
    // From glass into air the critical angle is named too.
    let mut h = harness(common::leaving_glass());
    click(&mut h, FRESNEL);
    assert!(
        h.query_by_label_contains("Critical angle θc = 41.8°: beyond it all the light")
            .is_some()
    );
    click(&mut h, FRESNEL);
    assert!(
        h.query_by_label_contains("Critical angle").is_none(),
        "closed"
    );
}

#[test]
fn at_brewsters_angle_p_light_reflects_nothing_and_only_with_intensities_on() {
    let mut h = harness(at_brewster());
    assert_eq!(h.state().overlay().intensities, None);
    assert!(!texts(&drawn(&h)).iter().any(|t| t.contains('%')));
    click(&mut h, EFFECTS);
    click(&mut h, "Intensities");
    assert_eq!(
        h.state().overlay().intensities,
        Some(Polarisation::Unpolarised)
    );
    click(&mut h, "p light");
    let overlay = h.state().overlay();
    assert_eq!(overlay.intensities, Some(Polarisation::P));
    let shares = Shares::of(h.state().state().refraction(), Polarisation::P);
    assert!(shares.reflected < 1e-20, "{}", shares.reflected);
    let labels = texts(&drawn(&h));
    assert!(
        labels
            .iter()
            .any(|t| t.starts_with("reflected (p light) 0.0 %: no reflected ray")),
        "{labels:?}"
    );
    assert!(labels.iter().any(|t| t == "T: transmitted 100.0 %"));
    click(&mut h, "s light");
    let labels = texts(&drawn(&h));
    assert!(
        labels
            .iter()
            .any(|t| t.starts_with("reflected (s light) 14.8 %"))
    );
    click(&mut h, "Intensities");
    assert_eq!(h.state().overlay().intensities, None);
}

#[test]
fn the_wavefronts_switch_draws_fronts_and_huygens_and_moves_them_when_asked() {
    let mut h = harness(ExplorerState::default());
    assert!(h.query_by_label("Moving").is_none(), "options show when on");
    let plain = drawn(&h).shapes.len();
    click(&mut h, EFFECTS);
    click(&mut h, "Wavefronts");
    let waves = h.state().overlay().waves.unwrap();
    assert!(!waves.huygens);
    let labels = texts(&drawn(&h));
    assert!(labels.iter().any(|t| t.contains("speed c/1.50 = 0.67 c")));
    assert!(drawn(&h).shapes.len() > plain + 10);
    click(&mut h, "Huygens's construction");
    assert!(h.state().overlay().waves.unwrap().huygens);
    // Drawn, or left out by the placer where the canvas has no room for it (shown on hover).
    let d = drawn(&h);
    let left_out = d.left_out.iter().map(|l| l.text.clone());
    let labels: Vec<String> = texts(&d).into_iter().chain(left_out).collect();
    assert!(
        labels.iter().any(|t| t.starts_with("Huygens")),
        "{labels:?}"
    );
    // Stepped, not run: moving fronts ask for every next frame.
    h.get_by_label("Moving").click();
    h.run_steps(8);
    let phase = h.state().overlay().waves.unwrap().phase;
    assert!(phase > 0.0, "{phase}");
    h.get_by_label("Moving").click();
    h.run_steps(2);
    h.run();
    let stopped = h.state().overlay().waves.unwrap().phase;
    h.run_steps(3);
    assert_eq!(h.state().overlay().waves.unwrap().phase, stopped);
    click(&mut h, "Wavefronts");
    assert_eq!(h.state().overlay().waves, None);
    assert_eq!(drawn(&h).shapes.len(), plain);
}

#[test]
fn in_presentation_at_1280_by_720_the_tool_and_switches_leave_the_diagram_its_share() {
    let mut h = sized(Explorer::new(at_brewster()), (1280.0, 720.0));
    click(&mut h, "🖵 Presentation");
    click(&mut h, EFFECTS);
    click(&mut h, "Intensities");
    click(&mut h, "Wavefronts");
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(h.query_by_label("Moving").is_none(), "the menu closed");
    for _ in 0..3 {
        h.run();
    }
    let alone = share(&h);
    assert!(alone >= 0.60, "the diagram has {:.1} %", alone * 100.0);
    for tool in ["📖 Walk-through", FRESNEL] {
        click(&mut h, tool);
        for _ in 0..3 {
            h.run();
        }
        let beside = share(&h);
        assert!(beside >= 0.45, "with {tool} open {:.1} %", beside * 100.0);
    }
    assert!(
        h.query_by_label_contains("Brewster's angle θB = 56.3°")
            .is_some()
    );
    let labels = texts(&drawn(&h));
    assert!(
        labels.iter().any(|t| t.starts_with("T: transmitted")),
        "{labels:?}"
    );
    assert!(
        labels.iter().any(|t| t.contains("speed c/1.50")),
        "{labels:?}"
    );
}

/// Sets the drag value labelled `label` to `value`, as a screen reader would.
fn set_number(h: &mut Harness<'_, Explorer>, label: &str, value: f64) {
    h.get_by_label(label).set_value_accesskit(value);
    h.run();
}

/// Waits, frame by frame, until the window says something containing `words` (at most about a
/// minute).
fn wait_for(h: &mut Harness<'_, Explorer>, words: &str) {
    for _ in 0..600 {
        if h.query_by_label_contains(words).is_some() {
            return;
        }
        std::thread::sleep(core::time::Duration::from_millis(100));
        h.step();
    }
    panic!("the window never said {words:?}");
}

#[test]
fn export_animation_writes_a_gif_in_the_background_and_cancel_writes_nothing() {
    let folder = std::env::temp_dir().join(format!("explorer-physics-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let mut h = sized(Explorer::new(ExplorerState::default()), (1280.0, 1500.0));
    let out = folder.join("sweep.gif");
    replace_text(&mut h, "GIF file", out.to_str().unwrap());
    set_number(&mut h, "Frames", 3.0);
    set_number(&mut h, "GIF width", 96.0);
    h.get_by_label("Export animation").click();
    h.step();
    let wrote = format!("wrote {}", out.display());
    wait_for(&mut h, &wrote);
    h.run();
    let bytes = std::fs::read(&out).unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(bytes.as_slice())
        .unwrap();
    assert_eq!(decoder.width(), 96);
    let mut frames = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        frames += 1;
    }
    assert_eq!(frames, 3);
    // The same name again: asked first, and Cancel leaves the GIF as it was.
    h.get_by_label("Export animation").click();
    h.run();
    assert!(h.query_by_label("Replace the file?").is_some());
    click(&mut h, "Cancel");
    assert!(h.query_by_label_contains("left as it was").is_some());
    assert_eq!(std::fs::read(&out).unwrap(), bytes);
    // A GIF is never written over a file of another kind with a .gif name.
    let disguised = folder.join("state.gif");
    std::fs::write(&disguised, "{\"w\":[0,-1,0]}").unwrap();
    replace_text(&mut h, "GIF file", disguised.to_str().unwrap());
    h.get_by_label("Export animation").click();
    h.run();
    assert!(
        h.query_by_label_contains("holds a saved state (JSON), not a GIF animation")
            .is_some()
    );
    // A long one, cancelled at once: nothing written, and the window says so.
    let cancelled = folder.join("cancelled.gif");
    replace_text(&mut h, "GIF file", cancelled.to_str().unwrap());
    set_number(&mut h, "Frames", 600.0);
    set_number(&mut h, "GIF width", 900.0);
    h.get_by_label("Export animation").click();
    h.step();
    wait_for(&mut h, "drawing frames");
    h.get_by_label("Cancel").click();
    h.step();
    wait_for(&mut h, "cancelled: nothing was written");
    h.run();
    assert!(h.query_by_label("Export animation").is_some());
    assert!(!cancelled.exists());
    // A file that is not a GIF is refused before anything is drawn.
    replace_text(&mut h, "GIF file", folder.join("x.png").to_str().unwrap());
    click(&mut h, "Export animation");
    assert!(
        h.query_by_label_contains("give a name ending in .gif")
            .is_some()
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_scenes_view_exports_its_picture_as_svg() {
    let folder = std::env::temp_dir().join(format!("explorer-scene-svg-{}", std::process::id()));
    std::fs::create_dir_all(&folder).unwrap();
    let mut explorer = Explorer::new(ExplorerState::default());
    explorer.open_scene(refraction_scene::Scene::embedded("droplet").unwrap());
    let mut h = harness_for(explorer);
    click(&mut h, "Export picture");
    let out = folder.join("droplet.svg");
    replace_text(&mut h, "Picture file (.png or .svg)", out.to_str().unwrap());
    h.get_by_label_contains("Export 1920×1080").click();
    h.run();
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(
        text.starts_with("<svg") || text.starts_with("<?xml"),
        "{}",
        &text[..40]
    );
    // The labels outlined, so that every viewer draws them inside their boxes; the words stay
    // in each label's title.
    assert!(text.contains("<title>") && !text.contains("<text"));
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_brewster_preset_shows_brewster_s_angle_with_p_light() {
    // Issue 32: the preset showed nothing about Brewster's angle.
    let mut h = harness(ExplorerState::default());
    assert_eq!(h.state().overlay().intensities, None);
    h.get_by_role_and_label(Role::ComboBox, "Lesson preset")
        .click();
    h.run();
    click(&mut h, &refraction_model::Lesson::Brewster.label());
    assert_eq!(
        h.state().state(),
        &refraction_model::Lesson::Brewster.state()
    );
    assert_eq!(h.state().overlay().intensities, Some(Polarisation::P));
    let diagram = Diagram::with_overlay(
        h.state().state(),
        GVec2::new(1000.0, 700.0),
        &h.state().overlay(),
    );
    let primitives = diagram.primitives();
    let words = refraction_diagram::primitive_texts(&primitives);
    assert!(
        words.iter().any(|w| w.contains("no reflected ray")),
        "{words:?}"
    );
}

//! The CPU time of one frame of the explorer's Scenes view at 1280×720 with 1,000 source rays
//! (each built-in beam or fan scene, set to 1,000 rays), on egui's headless context: the UI
//! pass (the scene picture built and painted, every widget laid out) and the tessellation of
//! its shapes into meshes; what is left for a GPU is uploading them. Measured at rest and while
//! the source is dragged, where every frame also retraces the scene (a draft of one ray in k
//! for a scene of more than 2,000 segments: see `src/app/scenes.rs`). The target is 4 ms.
//! At rest the view keeps what the window's own frames at rest keep (nothing changed): the
//! picture and its rays tessellated into meshes. What every frame does afresh is measured: the
//! UI pass, and egui's output, allocated anew each frame, into which the kept meshes are
//! copied. That copy is why this case once disagreed with itself (1.6 ms in one run, 8 to 11 ms
//! in others): the droplet's mesh grew the panel's output mesh by doubling, into 9 MB that the
//! system handed over page by page whenever the allocator had given the last frame's back (which
//! depends on what the process freed before, not on this code); each kept mesh now has a clip
//! rectangle of its own and is copied once, at its exact size.
//! And the same for One interface while W's handle is dragged, the figure the web build's is
//! set beside (docs/web.md), at 1280×720 and at 1920×1080 in presentation; and the label
//! placer's worst case: the droplet's 1,000 rays, and one label that must be shown with no
//! free spot anywhere, so that every fallback runs (see [`placer_worst_case`]).
//! `cargo bench --bench frame`.

use criterion::{Criterion, criterion_group, criterion_main};
use egui::{Context, Event, Modifiers, PointerButton, Pos2, RawInput, Rect, Vec2};
use refraction_diagram::{
    Align, Colour, Label, Need, Obstacle, Placer, SceneLayout, ScenePicture, Typeface,
};
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;
use refraction_scene::{Scene, SourceKind, catalogue};

const SCREEN: Vec2 = Vec2::new(1280.0, 720.0);

/// The projector's larger screen.
const FULL_HD: Vec2 = Vec2::new(1920.0, 1080.0);

/// Runs one frame with these input events and tessellates it; returns the number of meshes so
/// that nothing is optimised away.
fn frame(ctx: &Context, explorer: &mut Explorer, events: Vec<Event>) -> usize {
    frame_sized(ctx, explorer, events, SCREEN)
}

/// [`frame`] on a screen of `size` points.
fn frame_sized(ctx: &Context, explorer: &mut Explorer, events: Vec<Event>, size: Vec2) -> usize {
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, size)),
        events,
        ..RawInput::default()
    };
    let output = ctx.run_ui(input, |ui| explorer.show(ui));
    ctx.tessellate(output.shapes, output.pixels_per_point).len()
}

fn press(pos: Pos2, pressed: bool) -> Event {
    Event::PointerButton {
        pos,
        button: PointerButton::Primary,
        pressed,
        modifiers: Modifiers::NONE,
    }
}

fn scenes_frame(c: &mut Criterion) {
    let mut group = c.benchmark_group("scenes_frame_1280x720");
    for info in catalogue() {
        let Ok(mut scene) = Scene::embedded(info.name) else {
            continue;
        };
        if scene.source().kind == SourceKind::Ray || scene.set_ray_count(1000).is_err() {
            continue;
        }
        let ctx = Context::default();
        ctx.set_theme(egui::Theme::Light);
        let mut explorer = Explorer::new(ExplorerState::default());
        explorer.open_scene(scene);
        frame(&ctx, &mut explorer, Vec::new());
        let counts = explorer.scenes().trace().counts;
        let name = format!(
            "{}/{}_source_rays_{}_segments",
            info.name, counts.source_rays, counts.segments
        );
        group.bench_function(format!("{name}/at_rest"), |b| {
            b.iter(|| frame(&ctx, &mut explorer, Vec::new()));
        });

        let scenes = explorer.scenes();
        let Some(source) = scenes.to_screen(scenes.scene().source().origin) else {
            continue;
        };
        let before = scenes.scene().source().origin;
        frame(&ctx, &mut explorer, vec![Event::PointerMoved(source)]);
        frame(&ctx, &mut explorer, vec![press(source, true)]);
        let mut down = true;
        let mut drag = || {
            down = !down;
            let to = source + Vec2::new(0.0, if down { 12.0 } else { -12.0 });
            frame(&ctx, &mut explorer, vec![Event::PointerMoved(to)])
        };
        drag();
        drag();
        group.bench_function(format!("{name}/dragging_the_source"), |b| b.iter(&mut drag));
        assert_ne!(
            explorer.scenes().scene().source().origin,
            before,
            "the drag moved the source"
        );
        frame(&ctx, &mut explorer, vec![press(source, false)]);
    }
    group.finish();
}

/// Where W's handle is on a screen of `size` points, as the window tells screen readers (its
/// accessible node's bounds).
fn w_handle(ctx: &Context, explorer: &mut Explorer, size: Vec2) -> Option<Pos2> {
    ctx.enable_accesskit();
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, size)),
        ..RawInput::default()
    };
    let output = ctx.run_ui(input, |ui| explorer.show(ui));
    let update = output.platform_output.accesskit_update?;
    let (_, node) = update
        .nodes
        .iter()
        .find(|(_, node)| node.label() == Some("Angle of incidence θi (W)"))?;
    let bounds = node.bounds()?;
    Some(Pos2::new(
        f64::midpoint(bounds.x0, bounds.x1) as f32,
        f64::midpoint(bounds.y0, bounds.y1) as f32,
    ))
}

fn interface_frame(c: &mut Criterion) {
    let mut group = c.benchmark_group("interface_frame");
    for (name, size, presenting) in [
        ("1280x720/default_state/dragging_w", SCREEN, false),
        (
            "1920x1080_presentation/default_state/dragging_w",
            FULL_HD,
            true,
        ),
    ] {
        let ctx = Context::default();
        ctx.set_theme(egui::Theme::Light);
        let mut explorer = Explorer::new(ExplorerState::default());
        explorer.presentation_mut().on = presenting;
        let frame = |explorer: &mut Explorer, events| frame_sized(&ctx, explorer, events, size);
        // A few frames for the panels to settle where they stay.
        for _ in 0..3 {
            frame(&mut explorer, Vec::new());
        }
        let Some(w) = w_handle(&ctx, &mut explorer, size) else {
            panic!("no W handle on the screen");
        };
        let before = explorer.state().clone();
        frame(&mut explorer, vec![Event::PointerMoved(w)]);
        frame(&mut explorer, vec![press(w, true)]);
        let mut left = false;
        let mut drag = |explorer: &mut Explorer| {
            left = !left;
            let to = w + Vec2::new(if left { -12.0 } else { 12.0 }, 0.0);
            frame(explorer, vec![Event::PointerMoved(to)])
        };
        drag(&mut explorer);
        drag(&mut explorer);
        group.bench_function(name, |b| b.iter(|| drag(&mut explorer)));
        assert_ne!(explorer.state(), &before, "the drag turned W");
        frame(&mut explorer, vec![press(w, false)]);
    }
    group.finish();
}

/// The placer at its worst: the droplet at 1,000 source rays, whose picture keeps its labels
/// off the hit markers, the handles, 3,000 of its ray segments and its face (what
/// [`ScenePicture::label_obstacles`] gives), then one label that must be shown in the middle of
/// the drawing, and nowhere free: the rings around its anchor, the far rings, the whole drawing
/// in each of its shapes, crossing lesser rays, crossing any ray. Two ways for nowhere to be
/// free: a box over the whole drawing (so that every fallback runs in vain), and rays
/// everywhere (a lesser shaft every 6 pixels across the drawing, given after the droplet's, so
/// that each test reads the cell's rays before it meets one; the label ends crossing them).
fn placer_worst_case(c: &mut Criterion) {
    let Ok(mut scene) = Scene::embedded("droplet") else {
        panic!("the droplet is built in");
    };
    assert!(
        scene.set_ray_count(1000).is_ok(),
        "the droplet takes 1,000 rays"
    );
    let trace = scene.trace();
    let layout = SceneLayout::new(trace.bounds, glam::Vec2::new(SCREEN.x, SCREEN.y));
    let obstacles = ScenePicture::label_obstacles(&scene, &trace, &layout);
    let face = Typeface::egui_default();
    let drawing = layout.drawing;
    let hatching = (0..)
        .map(|k| drawing.min.y + 6.0 * k as f32)
        .take_while(|&y| y <= drawing.max.y)
        .map(|y| Obstacle::Shaft {
            a: glam::Vec2::new(drawing.min.x, y),
            b: glam::Vec2::new(drawing.max.x, y),
            half_width: 1.0,
            firm: false,
        });
    let cases = [
        ("a_box_over_the_drawing", vec![Obstacle::Box(drawing)]),
        ("rays_everywhere", hatching.collect()),
    ];
    let label = Label {
        text: "a label with nowhere to go".to_owned(),
        at: drawing.min + drawing.size() * 0.5,
        h: Align::Center,
        v: Align::Center,
        size: layout.font,
        colour: Colour::hex(0x000000),
        background: None,
    };
    for (name, blockers) in cases {
        let all: Vec<Obstacle> = obstacles.iter().chain(&blockers).cloned().collect();
        let name = format!("droplet_1000_rays/{}_obstacles/{name}", all.len());
        c.bench_function(&format!("placer/{name}"), |b| {
            b.iter(|| {
                let mut placer = Placer::new(&face);
                for obstacle in &all {
                    placer.avoid(obstacle.clone());
                }
                placer.place(label.clone(), &drawing, Need::Shown).is_err()
            });
        });
    }
}

criterion_group!(benches, scenes_frame, interface_frame, placer_worst_case);
criterion_main!(benches);

//! The CPU time of one frame of the explorer's Scenes view at 1280×720 with 1,000 source rays
//! (each built-in beam or fan scene, set to 1,000 rays), on egui's headless context: the UI
//! pass (the scene picture built and painted, every widget laid out) and the tessellation of
//! its shapes into meshes; what is left for a GPU is uploading them. Measured at rest and while
//! the source is dragged, where every frame also retraces the scene. The target is 8 ms.
//! And the same for One interface while W's handle is dragged, the figure the web build's is
//! set beside (docs/web.md). `cargo bench --bench frame`.

use criterion::{Criterion, criterion_group, criterion_main};
use egui::{Context, Event, Modifiers, PointerButton, Pos2, RawInput, Rect, Vec2};
use refraction_explorer::app::Explorer;
use refraction_model::ExplorerState;
use refraction_scene::{Scene, SourceKind, catalogue};

const SCREEN: Vec2 = Vec2::new(1280.0, 720.0);

/// Runs one frame with these input events and tessellates it; returns the number of meshes so
/// that nothing is optimised away.
fn frame(ctx: &Context, explorer: &mut Explorer, events: Vec<Event>) -> usize {
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
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

/// Where W's handle is on the screen, as the window tells screen readers (its accessible
/// node's bounds).
fn w_handle(ctx: &Context, explorer: &mut Explorer) -> Option<Pos2> {
    ctx.enable_accesskit();
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, SCREEN)),
        ..RawInput::default()
    };
    let output = ctx.run_ui(input, |ui| explorer.show(ui));
    let update = output.platform_output.accesskit_update?;
    let (_, node) = update
        .nodes
        .iter()
        .find(|(_, node)| node.label() == Some("W handle"))?;
    let bounds = node.bounds()?;
    Some(Pos2::new(
        f64::midpoint(bounds.x0, bounds.x1) as f32,
        f64::midpoint(bounds.y0, bounds.y1) as f32,
    ))
}

fn interface_frame(c: &mut Criterion) {
    let mut group = c.benchmark_group("interface_frame_1280x720");
    let ctx = Context::default();
    ctx.set_theme(egui::Theme::Light);
    let mut explorer = Explorer::new(ExplorerState::default());
    frame(&ctx, &mut explorer, Vec::new());
    let Some(w) = w_handle(&ctx, &mut explorer) else {
        panic!("no W handle on the screen");
    };
    let before = explorer.state().clone();
    frame(&ctx, &mut explorer, vec![Event::PointerMoved(w)]);
    frame(&ctx, &mut explorer, vec![press(w, true)]);
    let mut left = false;
    let mut drag = || {
        left = !left;
        let to = w + Vec2::new(if left { -12.0 } else { 12.0 }, 0.0);
        frame(&ctx, &mut explorer, vec![Event::PointerMoved(to)])
    };
    drag();
    drag();
    group.bench_function("default_state/dragging_w", |b| b.iter(&mut drag));
    assert_ne!(explorer.state(), &before, "the drag turned W");
    frame(&ctx, &mut explorer, vec![press(w, false)]);
    group.finish();
}

criterion_group!(benches, scenes_frame, interface_frame);
criterion_main!(benches);

//! The projector audit: the explorer driven headlessly (`egui_kittest`) at 1280×720 and
//! 1920×1080, at the desk and in presentation, over many states (random W, N and μ, total
//! internal reflection or not, the lessons), with every tool open in turn and each theme, and
//! the built-in scenes (the droplet at 1,000 rays). For each it measures what a class at the
//! back of the room sees:
//!
//! - the diagram canvas's share of the window (presentation: at least 60 % with the tools
//!   closed, 45 % with one open);
//! - the smallest text on screen, in pixels (at least 13 at the desk, 20 in presentation);
//! - every label inside its canvas, off every arrowhead, handle and hit marker and off every
//!   other label; the banner's text inside the banner.
//!
//! English is audited over every state; each other language (German runs long) over the
//! lessons' kinds, with every tool, theme, size and mode, and the built-in scenes.
//!
//! Run with `--nocapture` to see the measured figures.

use crate::common;

use common::harness_sized;
use egui::{Rect as EguiRect, Role, Shape};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use glam::{DVec3, Vec2 as GVec2};
use refraction_diagram::{
    Diagram, Figure, Label, Primitive, Rect, SceneLayout, ScenePicture, Typeface, palette::Theme,
};
use refraction_explorer::app::Explorer;
use refraction_i18n::{Locale, t};
use refraction_kernel::Convention;
use refraction_model::ExplorerState;
use refraction_scene::Scene;

const SIZES: [(f32, f32); 2] = [(1280.0, 720.0), (1920.0, 1080.0)];

/// The tools' switches in the bar, in the thread's language: none open, then each in turn.
fn tools() -> [Option<String>; 5] {
    [
        None,
        Some(format!("✔ {}", t!("tool-check"))),
        Some(format!("📖 {}", t!("tool-walk-through"))),
        Some(format!("💾 {}", t!("tool-files"))),
        Some(format!("📈 {}", t!("tool-fresnel"))),
    ]
}

/// The themes' names in the menu, in the thread's language.
fn themes() -> Vec<String> {
    Theme::ALL.iter().map(|t| t.label().clone()).collect()
}

/// A small deterministic generator, so that a failure names a state that can be rerun.
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.next()
    }
}

/// The states audited: the lessons' kinds by hand, then random ones.
fn states() -> Vec<ExplorerState> {
    let at = |degrees: f64, n: DVec3, mu_i: f64, mu_t: f64| {
        let a = degrees.to_radians();
        ExplorerState::new(
            DVec3::new(a.sin(), -a.cos(), 0.0),
            n,
            mu_i,
            mu_t,
            Convention::AlongRay,
        )
        .unwrap()
    };
    let mut states = vec![
        ExplorerState::default(),
        at(42.6, DVec3::Y, 1.5, 1.0),
        at(0.5, DVec3::Y, 1.000293, 1.5),
        at(40.0, DVec3::NEG_Y, 1.333, 1.000293),
        at(56.3, DVec3::Y, 1.000293, 1.5),
    ];
    let mut random = Random(0x9E37_79B9_7F4A_7C15);
    for _ in 0..7 {
        let angle = random.between(-1.5, 1.5);
        let turn = random.between(-0.6, 0.6);
        let n =
            DVec3::new(turn.sin(), turn.cos(), 0.0) * if random.next() < 0.3 { -1.0 } else { 1.0 };
        let w = DVec3::new(angle.sin(), -angle.cos(), 0.0);
        let state = ExplorerState::new(
            w,
            n,
            random.between(1.0, 2.5),
            random.between(1.0, 2.5),
            Convention::AlongRay,
        )
        .unwrap();
        states.push(state);
    }
    assert!(
        states.iter().any(|s| s.refraction().is_tir()),
        "a state past the critical angle"
    );
    assert!(
        states.iter().any(|s| !s.refraction().is_tir()),
        "a state that refracts"
    );
    states
}

fn click(h: &mut Harness<'_, Explorer>, label: &str) {
    h.get_by_label(label).click();
    h.run();
}

/// Sets up the window as asked, through its own controls.
fn set_up(h: &mut Harness<'_, Explorer>, present: bool, theme: &str, tool: Option<&str>) {
    if present {
        click(h, &t!("presentation-toggle"));
    }
    if let Some(chosen) = Theme::ALL.into_iter().find(|t| t.label().as_str() == theme) {
        h.state_mut().presentation_mut().theme = chosen;
    }
    if let Some(tool) = tool {
        // In presentation the controls are opened first, as a teacher who set up the case
        // and then opens a tool: the two must not squeeze each other at 1280×720.
        if present {
            h.key_press(egui::Key::F2);
            h.run();
        }
        click(h, tool);
    }
    // Beside the Fresnel tool, the effects it explains are on too: their labels and the
    // diagram's share are audited with everything a physics lesson turns on.
    if tool.is_some_and(|t| t.ends_with(&t!("tool-fresnel"))) {
        click(h, &t!("effects-menu"));
        for switch in [
            t!("effects-intensities"),
            t!("effects-wavefronts"),
            t!("effects-huygens"),
        ] {
            click(h, &switch);
        }
        h.key_press(egui::Key::Escape);
        h.run();
    }
    run_three_more_frames(h);
}

/// A few more frames: panels settle their sizes over a frame or two.
fn run_three_more_frames(h: &mut Harness<'_, Explorer>) {
    for _ in 0..3 {
        h.run();
    }
}

/// What one window showed.
#[derive(Default)]
struct Measured {
    share: f32,
    smallest_text_px: f32,
    /// The least contrast of the window's text with its panels.
    contrast: f32,
    problems: Vec<String>,
}

/// The smallest font size of any text on screen, in pixels.
fn smallest_text(h: &Harness<'_, Explorer>) -> f32 {
    fn visit(shape: &Shape, smallest: &mut f32) {
        match shape {
            Shape::Vec(shapes) => shapes.iter().for_each(|s| visit(s, smallest)),
            Shape::Text(text) => {
                let job = &text.galley.job;
                for section in &job.sections {
                    let range = &section.byte_range;
                    let words = job.text.get(range.start.0..range.end.0).unwrap_or_default();
                    if !words.trim().is_empty() {
                        *smallest = smallest.min(section.format.font_id.size);
                    }
                }
            }
            _ => {}
        }
    }
    let mut smallest = f32::INFINITY;
    for clipped in &h.output().shapes {
        visit(&clipped.shape, &mut smallest);
    }
    smallest * h.ctx.pixels_per_point()
}

fn canvas_rect(h: &Harness<'_, Explorer>) -> EguiRect {
    h.get_by_role(Role::Image).rect()
}

/// The diagram's share of the window: its canvas, less the index scale's strip in the
/// interface view (the scale is a control, not the picture the class reads).
fn share(h: &Harness<'_, Explorer>, scene: bool) -> f32 {
    let window = h.ctx.content_rect();
    let canvas = canvas_rect(h);
    let scale = if scene {
        0.0
    } else {
        let size = GVec2::new(canvas.width(), canvas.height());
        let explorer = h.state();
        let layout = Diagram::with_overlay(explorer.state(), size, &explorer.overlay()).layout;
        (layout.canvas.max.x - layout.drawing.max.x) * canvas.height()
    };
    (canvas.area() - scale) / window.area()
}

/// Every control (button, text field, menu, switch) within the window's width: a row that
/// runs past the window's edge cuts its last controls off.
fn check_controls_inside<S>(h: &Harness<'_, S>, what: &str, problems: &mut Vec<String>) {
    let window = h.ctx.content_rect();
    for role in [
        Role::Button,
        Role::TextInput,
        Role::ComboBox,
        Role::CheckBox,
    ] {
        for node in h.query_all_by_role(role) {
            let r = node.rect();
            if r.max.x > window.max.x + 0.5 || r.min.x < window.min.x - 0.5 {
                let name = node.accesskit_node().label().unwrap_or_default();
                problems.push(format!("{what}: “{name}” is cut off at the window's edge"));
            }
        }
    }
}

/// Whether a galley's rows break a word: a row that ends in a letter (not at a line break of
/// the text) followed by one that starts with a letter.
fn breaks_a_word(galley: &egui::Galley) -> Option<String> {
    let rows = &galley.rows;
    rows.windows(2).find_map(|pair| {
        let (before, after) = (&pair[0], &pair[1]);
        let last = before.glyphs.last()?.chr;
        let first = after.glyphs.first()?.chr;
        (!before.ends_with_newline && last.is_alphanumeric() && first.is_alphanumeric()).then(
            || {
                let end: String = before.glyphs.iter().rev().take(8).map(|g| g.chr).collect();
                let start: String = after.glyphs.iter().take(8).map(|g| g.chr).collect();
                format!("{}/{start}", end.chars().rev().collect::<String>())
            },
        )
    })
}

/// Texts wrapped letter by letter (a panel squeezed below its controls' width): a galley of
/// three rows or more whose rows hold two characters at the most; and words broken inside
/// ("Lektionsvorgab/e").
fn check_squeezed<S>(h: &Harness<'_, S>, what: &str, problems: &mut Vec<String>) {
    fn visit(shape: &Shape, what: &str, problems: &mut Vec<String>) {
        match shape {
            Shape::Vec(shapes) => shapes.iter().for_each(|s| visit(s, what, problems)),
            Shape::Text(text) => {
                if let Some(at) = breaks_a_word(&text.galley) {
                    problems.push(format!("{what}: a word is broken inside: “{at}”"));
                }
                let rows = &text.galley.rows;
                let narrow = rows
                    .iter()
                    .all(|r| r.glyphs.iter().filter(|g| !g.chr.is_whitespace()).count() <= 2);
                if rows.len() >= 3 && narrow {
                    let words = text.galley.job.text.replace('\n', " ");
                    problems.push(format!("{what}: “{words}” is wrapped letter by letter"));
                }
            }
            _ => {}
        }
    }
    for clipped in &h.output().shapes {
        visit(&clipped.shape, what, problems);
    }
}

/// The least contrast of the window's text (outside the diagram's canvas) with the panels'
/// fill, as WCAG measures it; text under 4.5:1 is a problem.
fn check_contrast(h: &Harness<'_, Explorer>, what: &str, problems: &mut Vec<String>) -> f32 {
    let colour = |c: egui::Color32| {
        let [r, g, b, a] = c.to_srgba_unmultiplied();
        refraction_diagram::Colour { r, g, b, a }
    };
    let fill = colour(h.ctx.global_style().visuals.panel_fill);
    let canvas = canvas_rect(h);
    // A control switched off (Undo with nothing to undo) is greyed on purpose: WCAG sets no
    // contrast for inactive controls.
    let disabled: Vec<EguiRect> = h
        .query_all_by(|node| node.is_disabled())
        .map(|node| node.rect())
        .collect();
    let mut least = f32::INFINITY;
    let mut visit = |shape: &Shape, least: &mut f32| {
        let Shape::Text(text) = shape else { return };
        let bounds = text.visual_bounding_rect();
        if canvas.intersects(bounds)
            || text.galley.job.text.trim().is_empty()
            || disabled.iter().any(|d| d.expand(2.0).contains_rect(bounds))
        {
            return;
        }
        let colour_of = |c: egui::Color32| {
            if c == egui::Color32::PLACEHOLDER {
                text.fallback_color
            } else {
                c
            }
        };
        for section in &text.galley.job.sections {
            let c = text
                .override_text_color
                .unwrap_or_else(|| colour_of(section.format.color));
            let ratio = colour(c).over(fill).contrast(fill);
            if ratio < *least {
                *least = ratio;
            }
            if ratio < 4.5 {
                let words = text
                    .galley
                    .job
                    .text
                    .lines()
                    .next()
                    .unwrap_or_default()
                    .to_owned();
                problems.push(format!("{what}: “{words}” has a contrast of {ratio:.1}:1"));
            }
        }
    };
    fn walk(shape: &Shape, f: &mut dyn FnMut(&Shape, &mut f32), least: &mut f32) {
        match shape {
            Shape::Vec(shapes) => shapes.iter().for_each(|s| walk(s, f, least)),
            other => f(other, least),
        }
    }
    for clipped in &h.output().shapes {
        walk(&clipped.shape, &mut visit, &mut least);
    }
    least
}

/// The box of a label's text on its canvas.
fn text_box(face: &Typeface, label: &Label) -> Rect {
    let extent = face.measure(&label.text, label.size);
    let min = label.at - extent * GVec2::new(label.h.fraction(), label.v.fraction());
    Rect {
        min,
        max: min + extent,
    }
}

/// Whether two boxes share more than a sliver (a pixel each way).
fn overlap(a: &Rect, b: &Rect) -> bool {
    let shrink = |r: &Rect| Rect {
        min: r.min + GVec2::splat(0.5),
        max: r.max - GVec2::splat(0.5),
    };
    shrink(a).overlaps(&shrink(b))
}

fn touches_disc(r: &Rect, center: GVec2, radius: f32) -> bool {
    let nearest = center.clamp(r.min, r.max);
    nearest.distance(center) < radius - 0.5
}

fn touches_triangle(r: &Rect, triangle: &[GVec2]) -> bool {
    let &[a, b, c] = triangle else {
        return false;
    };
    // Points on the triangle's edges and inside it.
    (0..=8).any(|i| {
        let s = i as f32 / 8.0;
        [a.lerp(b, s), b.lerp(c, s), c.lerp(a, s), (a + b + c) / 3.0]
            .iter()
            .any(|p| r.contains(*p))
    })
}

/// Checks the labels of a picture: inside `canvas`, off the arrowheads, handles (centre,
/// radius), markers and each other.
struct Obstacles {
    heads: Vec<(String, Vec<GVec2>)>,
    discs: Vec<(String, GVec2, f32)>,
    /// The rays' shafts: what no label may lie on.
    shafts: Vec<(String, refraction_diagram::Obstacle)>,
}

fn check_labels(
    what: &str,
    face: &Typeface,
    canvas: &Rect,
    labels: &[&Label],
    obstacles: &Obstacles,
    problems: &mut Vec<String>,
) {
    let boxes: Vec<Rect> = labels.iter().map(|l| text_box(face, l)).collect();
    for (i, (label, b)) in labels.iter().zip(&boxes).enumerate() {
        let name = label.text.lines().next().unwrap_or_default();
        let inside = canvas.contains(b.min + GVec2::splat(0.5))
            && canvas.contains(b.max - GVec2::splat(0.5));
        if !inside {
            problems.push(format!("{what}: “{name}” is cut off by the canvas edge"));
        }
        for (head, triangle) in &obstacles.heads {
            if touches_triangle(b, triangle) {
                problems.push(format!("{what}: “{name}” covers the arrowhead of {head}"));
            }
        }
        for (disc, center, radius) in &obstacles.discs {
            if touches_disc(b, *center, *radius) {
                problems.push(format!("{what}: “{name}” covers {disc}"));
            }
        }
        // A sliver inside the box: a shaft that grazes its padding does not hide the words.
        let inner = Rect {
            min: b.min + GVec2::splat(1.0),
            max: b.max - GVec2::splat(1.0),
        };
        if let Some((ray, _)) = obstacles.shafts.iter().find(|(_, s)| s.touches(&inner)) {
            problems.push(format!("{what}: “{name}” lies on {ray}"));
        }
        for (other, ob) in labels.iter().zip(&boxes).skip(i + 1) {
            if overlap(b, ob) {
                let other = other.text.lines().next().unwrap_or_default();
                problems.push(format!("{what}: “{name}” overlaps “{other}”"));
            }
        }
    }
}

/// Every label of a picture reads at 4.5:1 or more: on its own box, or (a banner's words) on
/// the fill behind them, `behind`.
fn check_label_contrast(
    what: &str,
    primitives: &[Primitive],
    behind: refraction_diagram::Colour,
    problems: &mut Vec<String>,
) {
    // A marker's words sit on its disc.
    let disc_at = |at: GVec2| {
        primitives.iter().find_map(|p| match p {
            Primitive::Disc { center, fill, .. } if center.distance(at) < 0.5 => Some(*fill),
            _ => None,
        })
    };
    for p in primitives {
        if let Primitive::Text(label) = p {
            let back = label
                .background
                .or_else(|| disc_at(label.at))
                .unwrap_or(behind);
            let ratio = label.colour.over(back).contrast(back);
            if ratio < 4.5 && !label.text.trim().is_empty() {
                let name = label.text.lines().next().unwrap_or_default();
                problems.push(format!(
                    "{what}: the label “{name}” has a contrast of {ratio:.1}:1"
                ));
            }
        }
    }
}

/// The interface diagram as the window drew it, with its labels checked.
fn audit_diagram(h: &Harness<'_, Explorer>, what: &str, problems: &mut Vec<String>) {
    let face = Typeface::egui_default();
    let rect = canvas_rect(h);
    let size = GVec2::new(rect.width(), rect.height());
    let explorer = h.state();
    let diagram = Diagram::with_overlay(explorer.state(), size, &explorer.overlay());
    let mut heads = Vec::new();
    let mut shafts = Vec::new();
    // The lesson's own rays, W, N and T: no label may hide them. (A label a lesson teaches
    // may cross a ghost's or the incoming ray's shaft where a small canvas has no free spot:
    // it is never dropped.)
    let palette = explorer.overlay().palette;
    for shape in &diagram.shapes {
        if let Figure::Arrow {
            from,
            to,
            stroke,
            role,
        } = shape
        {
            if *role == refraction_diagram::ArrowRole::Vector {
                let shaft = refraction_diagram::Obstacle::Shaft {
                    a: *from,
                    b: *to,
                    half_width: stroke.width * 0.5,
                    firm: false,
                };
                shafts.push(("the shaft of W, N or T".to_owned(), shaft));
            }
            let mut lowered = Vec::new();
            shape.lower(&mut lowered);
            for p in lowered {
                if let Primitive::Polygon { points, .. } = p {
                    heads.push(("an arrow".to_owned(), points));
                }
            }
        }
    }
    let discs = diagram
        .handles
        .iter()
        .map(|h| (h.id.label().clone(), h.center, h.radius))
        .collect();
    let labels: Vec<&Label> = diagram
        .shapes
        .iter()
        .filter_map(|s| match s {
            Figure::Text(l) if l.background.is_some() => Some(l),
            _ => None,
        })
        .collect();
    let canvas = diagram.layout.canvas;
    let r = explorer.state().refraction();
    let banner_fill = if r.is_tir() && !explorer.overlay().hide_answer {
        palette.alarm
    } else {
        palette.calm
    };
    check_label_contrast(what, &diagram.primitives(), banner_fill, problems);
    check_labels(
        what,
        &face,
        &canvas,
        &labels,
        &Obstacles {
            heads,
            discs,
            shafts,
        },
        problems,
    );
    let banner = diagram.layout.banner;
    for shape in &diagram.shapes {
        if let Figure::Text(l) = shape
            && l.background.is_none()
            && banner.contains(l.at)
        {
            let b = text_box(&face, l);
            if b.max.x > banner.max.x + 0.5 || b.max.y > banner.max.y + 0.5 || b.min.y < -0.5 {
                let name = l.text.lines().next().unwrap_or_default();
                problems.push(format!("{what}: the banner “{name}” runs out of its box"));
            }
        }
    }
}

/// The Scenes canvas as the window drew it, with its labels checked against the hit markers
/// and handles.
fn audit_scene(h: &Harness<'_, Explorer>, what: &str, problems: &mut Vec<String>) {
    let face = Typeface::egui_default();
    let rect = canvas_rect(h);
    let scenes = h.state().scenes();
    let layout = SceneLayout::for_scene(
        scenes.scene(),
        scenes.trace(),
        GVec2::new(rect.width(), rect.height()),
    );
    let palette = h.state().overlay().palette;
    let picture = ScenePicture::with_palette(scenes.scene(), scenes.trace(), &layout, &palette);
    check_label_contrast(what, &picture.primitives, palette.calm, problems);
    let handle_at: Vec<GVec2> = picture.handles.iter().map(|h| h.center).collect();
    let mut discs: Vec<(String, GVec2, f32)> = picture
        .handles
        .iter()
        .map(|h| (format!("{:?} handle", h.id), h.center, h.radius))
        .collect();
    let mut labels = Vec::new();
    for p in &picture.primitives {
        match p {
            Primitive::Disc { center, radius, .. }
                if !handle_at.iter().any(|c| c.distance(*center) < 0.5) =>
            {
                discs.push(("a hit marker".to_owned(), *center, *radius));
            }
            Primitive::Text(l) if l.background.is_some() => labels.push(l),
            _ => {}
        }
    }
    // A ray faded below a twentieth of its source's light (the droplet's thousands of weak
    // reflections, which fill the whole canvas at 1,000 rays) is drawn almost transparent: a
    // label over it hides nothing.
    let shafts = scenes
        .trace()
        .segments
        .iter()
        .filter(|s| s.intensity.is_none_or(|i| i >= 0.05))
        .map(|s| {
            let shaft = refraction_diagram::Obstacle::Shaft {
                a: layout.at(s.from),
                b: layout.at(s.to),
                half_width: 0.5,
                firm: false,
            };
            ("a ray".to_owned(), shaft)
        })
        .collect();
    let obstacles = Obstacles {
        heads: Vec::new(),
        discs,
        shafts,
    };
    check_labels(what, &face, &layout.canvas, &labels, &obstacles, problems);
}

fn measure(
    h: &Harness<'_, Explorer>,
    what: &str,
    present: bool,
    tool_open: bool,
    scene: bool,
) -> Measured {
    let mut m = Measured {
        share: share(h, scene),
        smallest_text_px: smallest_text(h),
        contrast: f32::INFINITY,
        problems: Vec::new(),
    };
    let least_share = match (present, tool_open, scene) {
        (true, false, false) => Some(0.60),
        (true, _, _) => Some(0.50),
        _ => None,
    };
    if let Some(least) = least_share
        && m.share < least
    {
        m.problems.push(format!(
            "{what}: the diagram has {:.0} % of the window, less than {:.0} %",
            m.share * 100.0,
            least * 100.0
        ));
    }
    let least_text = if present { 20.0 } else { 13.0 };
    if m.smallest_text_px < least_text {
        m.problems.push(format!(
            "{what}: text of {:.1} px, smaller than {least_text} px",
            m.smallest_text_px
        ));
    }
    check_controls_inside(h, what, &mut m.problems);
    check_squeezed(h, what, &mut m.problems);
    m.contrast = check_contrast(h, what, &mut m.problems);
    if scene {
        audit_scene(h, what, &mut m.problems);
    } else {
        audit_diagram(h, what, &mut m.problems);
    }
    m
}

/// The figures of one group of windows as JSON, for the audit's file.
fn figures(name: &str, measured: &[(String, Measured)]) -> serde_json::Value {
    let least = |f: fn(&Measured) -> f32| {
        measured
            .iter()
            .map(|(_, m)| f(m))
            .fold(f32::INFINITY, f32::min)
    };
    serde_json::json!({
        "group": name,
        "windows": measured.len(),
        "least_diagram_share": least(|m| m.share),
        "smallest_text_px": least(|m| m.smallest_text_px),
        "least_text_contrast": least(|m| m.contrast),
    })
}

/// Adds `run`'s figures to the audit's JSON file (one per audit, by name) in the target
/// folder, which CI prints after the tests.
fn write_figures(run: &str, groups: &[serde_json::Value], problems: usize) {
    // The audits run on several threads of this process: one writes at a time.
    static WRITING: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _writing = WRITING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("layout-audit.json");
    let mut all: serde_json::Map<String, serde_json::Value> = std::fs::read_to_string(&path)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default();
    all.insert(
        run.to_owned(),
        serde_json::json!({ "groups": groups, "problems": problems }),
    );
    let text = serde_json::Value::Object(all).to_string();
    // Best effort, and atomic: a reader never sees half a file.
    let temporary = path.with_extension(format!("{}.tmp", std::process::id()));
    if std::fs::write(&temporary, text).is_ok() {
        std::fs::rename(&temporary, &path).ok();
    }
}

/// The figures of one group of windows, for the report.
fn summary(name: &str, measured: &[(String, Measured)]) -> String {
    let least_share = measured
        .iter()
        .map(|(_, m)| m.share)
        .fold(f32::INFINITY, f32::min);
    let least_text = measured
        .iter()
        .map(|(_, m)| m.smallest_text_px)
        .fold(f32::INFINITY, f32::min);
    format!(
        "{name}: {} windows, diagram share at least {:.1} %, smallest text {:.1} px",
        measured.len(),
        least_share * 100.0,
        least_text
    )
}

#[expect(clippy::print_stdout, reason = "the measured figures, for --nocapture")]
fn report(run: &str, measured: &[(String, Measured)]) {
    let mut found = Vec::new();
    let groups = [
        ("desk, tools closed", false, false),
        ("desk, a tool open", false, true),
        ("presentation, tools closed", true, false),
        ("presentation, a tool open", true, true),
    ];
    for (name, present, tool) in groups {
        let group: Vec<_> = measured
            .iter()
            .filter(|(what, _)| {
                what.contains("presentation") == present
                    && (what.contains("tool ") || what.contains("panel ")) == tool
            })
            .map(|(w, m)| {
                (
                    w.clone(),
                    Measured {
                        share: m.share,
                        smallest_text_px: m.smallest_text_px,
                        contrast: m.contrast,
                        problems: Vec::new(),
                    },
                )
            })
            .collect();
        if !group.is_empty() {
            println!("{}", summary(name, &group));
            found.push(figures(name, &group));
        }
    }
    let problems: Vec<&String> = measured.iter().flat_map(|(_, m)| &m.problems).collect();
    write_figures(run, &found, problems.len());
    for p in problems.iter().take(60) {
        println!("  {p}");
    }
    assert!(
        problems.is_empty(),
        "{} layout problems (first: {})",
        problems.len(),
        problems[0]
    );
}

/// The interface view over `states` in the thread's language, at both sizes, at the desk and
/// in presentation, with each tool open in turn, the themes taken in turn. One window per
/// size, mode and tool, whose state and theme are switched through the model, as a teacher
/// switches lessons in one window.
fn audit_interface(states: &[ExplorerState]) -> Vec<(String, Measured)> {
    let (themes, language) = (themes(), refraction_i18n::locale());
    let mut measured = Vec::new();
    for size in SIZES {
        for present in [false, true] {
            for (t, tool) in tools().into_iter().enumerate() {
                let mut h = harness_sized(Explorer::new(states[0].clone()), size);
                set_up(&mut h, present, &themes[t % themes.len()], tool.as_deref());
                for (i, state) in states.iter().enumerate() {
                    let theme = (i + t) % themes.len();
                    h.state_mut().set_state(state.clone());
                    h.state_mut().presentation_mut().theme = Theme::ALL[theme];
                    run_three_more_frames(&mut h);
                    let what = format!(
                        "{language} {}×{} {} {}, state {i}, {}",
                        size.0,
                        size.1,
                        if present { "presentation" } else { "desk" },
                        tool.as_ref()
                            .map_or_else(|| "no tool".to_owned(), |t| format!("tool {t}")),
                        themes[theme],
                    );
                    let m = measure(&h, &what, present, tool.is_some(), false);
                    measured.push((what, m));
                }
            }
            measured.extend(audit_panels(&states[..2], size, present));
        }
    }
    measured
}

/// The interface view with each side panel open in turn (F2 the controls, F3 the numbers),
/// no tool: at the desk both start open, so there the other is closed.
fn audit_panels(
    states: &[ExplorerState],
    size: (f32, f32),
    present: bool,
) -> Vec<(String, Measured)> {
    let language = refraction_i18n::locale();
    let mut measured = Vec::new();
    for (key, name) in [(egui::Key::F2, "controls"), (egui::Key::F3, "numbers")] {
        let mut h = harness_sized(Explorer::new(states[0].clone()), size);
        set_up(&mut h, present, &themes()[0], None);
        let other = if key == egui::Key::F2 {
            egui::Key::F3
        } else {
            egui::Key::F2
        };
        h.key_press(if present { key } else { other });
        run_three_more_frames(&mut h);
        for (i, state) in states.iter().enumerate() {
            h.state_mut().set_state(state.clone());
            run_three_more_frames(&mut h);
            let what = format!(
                "{language} {}×{} {} panel {name}, state {i}",
                size.0,
                size.1,
                if present { "presentation" } else { "desk" },
            );
            // An open panel gives way to the diagram as a tool does.
            let m = measure(&h, &what, present, true, false);
            measured.push((what, m));
        }
    }
    measured
}

#[test]
fn the_interface_view_owns_the_screen_and_nothing_covers_anything() {
    report("interface", &audit_interface(&states()));
}

/// The Scenes view, every built-in scene (the droplet at 1,000 rays), in the thread's
/// language: one window per size and mode, each scene opened in it in turn.
fn audit_scenes() -> Vec<(String, Measured)> {
    let (themes, language) = (themes(), refraction_i18n::locale());
    let mut measured = Vec::new();
    for size in SIZES {
        for present in [false, true] {
            let mut h = harness_sized(Explorer::new(ExplorerState::default()), size);
            set_up(&mut h, present, &themes[0], None);
            for info in refraction_scene::catalogue() {
                let mut scene = Scene::embedded(info.name).unwrap();
                if info.name == "droplet" {
                    scene.set_ray_count(1000).unwrap();
                }
                h.state_mut().open_scene(scene);
                run_three_more_frames(&mut h);
                let what = format!(
                    "{language} {}×{} {} scene {}",
                    size.0,
                    size.1,
                    if present { "presentation" } else { "desk" },
                    info.name
                );
                let m = measure(&h, &what, present, false, true);
                measured.push((what, m));
            }
        }
    }
    measured
}

#[test]
fn the_scenes_view_owns_the_screen_and_labels_leave_the_hit_markers_free() {
    report("scenes", &audit_scenes());
}

/// The audit in `language`: the lessons' kinds (the first states: the default, total
/// internal reflection, near-normal incidence, leaving water, Brewster's angle) and the scenes.
fn audit_in(language: Locale) {
    refraction_i18n::set_locale(language);
    let mut measured = audit_interface(&states()[..5]);
    measured.extend(audit_scenes());
    report(&language.to_string(), &measured);
}

#[test]
fn german_keeps_the_layout_rules() {
    audit_in(Locale::De);
}

#[test]
fn spanish_keeps_the_layout_rules() {
    audit_in(Locale::Es);
}

#[test]
fn french_keeps_the_layout_rules() {
    audit_in(Locale::Fr);
}

#[test]
fn brazilian_portuguese_keeps_the_layout_rules() {
    audit_in(Locale::PtBr);
}

#[test]
fn russian_keeps_the_layout_rules() {
    audit_in(Locale::Ru);
}

#[test]
fn the_audit_finds_what_it_looks_for() {
    // The checks themselves: a label on an arrowhead, on a handle, on another label, or out
    // of the canvas is found.
    let face = Typeface::egui_default();
    let canvas = Rect::from_min_size(GVec2::ZERO, GVec2::new(200.0, 100.0));
    let label = |text: &str, at: GVec2| Label {
        text: text.to_owned(),
        at,
        h: refraction_diagram::Align::Start,
        v: refraction_diagram::Align::Start,
        size: 14.0,
        colour: refraction_diagram::palette::INK,
        background: Some(refraction_diagram::palette::BACKGROUND),
    };
    let (a, b, c) = (
        label("one", GVec2::new(10.0, 10.0)),
        label("two", GVec2::new(14.0, 12.0)),
        label("three", GVec2::new(190.0, 80.0)),
    );
    let obstacles = Obstacles {
        heads: vec![(
            "T".to_owned(),
            vec![
                GVec2::new(12.0, 15.0),
                GVec2::new(0.0, 0.0),
                GVec2::new(0.0, 30.0),
            ],
        )],
        discs: vec![("W handle".to_owned(), GVec2::new(20.0, 20.0), 5.0)],
        shafts: vec![(
            "T's shaft".to_owned(),
            refraction_diagram::Obstacle::Shaft {
                a: GVec2::new(150.0, 80.0),
                b: GVec2::new(250.0, 95.0),
                half_width: 1.0,
                firm: false,
            },
        )],
    };
    let mut problems = Vec::new();
    check_labels(
        "test",
        &face,
        &canvas,
        &[&a, &b, &c],
        &obstacles,
        &mut problems,
    );
    let all = problems.join("\n");
    for expected in [
        "“three” is cut off",
        "arrowhead of T",
        "covers W handle",
        "“one” overlaps “two”",
        "“three” lies on T's shaft",
    ] {
        assert!(all.contains(expected), "{expected} not found in:\n{all}");
    }
}

#[test]
fn the_audit_finds_words_wrapped_letter_by_letter() {
    let mut h = Harness::builder()
        .with_size(egui::Vec2::new(200.0, 300.0))
        .build_ui(|ui| {
            ui.horizontal_top(|ui| {
                let down = egui::Layout::top_down(egui::Align::Min);
                ui.allocate_ui_with_layout(egui::vec2(14.0, 300.0), down, |ui| {
                    ui.add(egui::Label::new("Lesson preset").wrap());
                });
                ui.label("Reset");
            });
        });
    h.run();
    let mut problems = Vec::new();
    check_squeezed(&h, "test", &mut problems);
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(
        problems[0].contains("a word is broken inside"),
        "{problems:?}"
    );
    assert!(problems[1].contains("Lesson preset"), "{problems:?}");
}

#[test]
fn the_audit_finds_a_row_of_controls_cut_off_at_the_window_edge() {
    let mut h = Harness::builder()
        .with_size(egui::Vec2::new(190.0, 100.0))
        .build_ui(|ui| {
            ui.horizontal(|ui| {
                for name in ["Open file", "Save file", "Export picture"] {
                    let _ = ui.button(name);
                }
            });
        });
    h.run();
    let mut problems = Vec::new();
    check_controls_inside(&h, "row", &mut problems);
    assert_eq!(
        problems,
        ["row: “Export picture” is cut off at the window's edge"]
    );
}

/// Before a step's answer is revealed nothing is drawn past the interface but N: no arrow of
/// W, T, a candidate or the reflection ends on the far side.
fn check_nothing_past_the_interface(
    h: &Harness<'_, Explorer>,
    what: &str,
    problems: &mut Vec<String>,
) {
    let rect = canvas_rect(h);
    let explorer = h.state();
    let overlay = explorer.overlay();
    let size = GVec2::new(rect.width(), rect.height());
    let diagram = Diagram::with_overlay(explorer.state(), size, &overlay);
    let r = explorer.state().refraction();
    let normal = explorer.state().plane().project(r.facing_normal);
    let origin = diagram.layout.view.to_canvas(glam::DVec2::ZERO);
    let into_incident = diagram.layout.view.direction(normal);
    for shape in &diagram.shapes {
        if let Figure::Arrow {
            from, to, stroke, ..
        } = shape
            && stroke.colour != overlay.palette.n
        {
            let past = |p: &GVec2| (*p - origin).dot(into_incident) < -1.0;
            if past(from) || past(to) {
                problems.push(format!(
                    "{what}: an arrow is drawn past the interface before the reveal"
                ));
            }
        }
    }
}

/// Every frame of *Animate μ to 1* on *A droplet's exit*, walk-through open, in presentation
/// at 1280×720: no label on W, N or T in any frame, as at rest.
#[test]
fn every_frame_of_the_mu_animation_keeps_w_n_and_t_clear() {
    let mut measured = Vec::new();
    for language in [Locale::En, Locale::De, Locale::Ru] {
        refraction_i18n::set_locale(language);
        let state = refraction_model::Lesson::DropletExit.state();
        let mut h = harness_sized(Explorer::new(state), SIZES[0]);
        set_up(
            &mut h,
            true,
            &themes()[0],
            Some(&format!("📖 {}", t!("tool-walk-through"))),
        );
        // One frame at a time: the animation asks for the next one until it ends.
        h.get_by_label(&t!("walk-animate")).click();
        h.step();
        let mut frame = 0;
        while h.state().animating() && frame < 400 {
            let what = format!(
                "{language} 1280×720 presentation tool walk-through, droplet exit, μ → 1, frame {frame}"
            );
            let mut problems = Vec::new();
            audit_diagram(&h, &what, &mut problems);
            measured.push((
                what,
                Measured {
                    share: share(&h, false),
                    smallest_text_px: smallest_text(&h),
                    contrast: f32::INFINITY,
                    problems,
                },
            ));
            h.step();
            frame += 1;
        }
        assert!(frame > 10 && !h.state().animating(), "{frame} frames");
    }
    refraction_i18n::set_locale(Locale::En);
    report("animation", &measured);
}

/// A lesson deck's steps that ask a question, in presentation at 1280×720 in every language:
/// the step's strip (its number, title and question) above the diagram, its answer hidden,
/// with the tools closed and with the deck's own tool open; and a scene's step.
#[test]
fn a_lesson_step_with_a_question_keeps_the_layout_rules_in_presentation() {
    let mut measured = Vec::new();
    for language in Locale::ALL {
        refraction_i18n::set_locale(language);
        for tool in [None, Some(format!("📚 {}", t!("tool-deck")))] {
            let mut explorer = Explorer::new(ExplorerState::default());
            explorer.open_deck(refraction_deck::Deck::load("total-internal-reflection").unwrap());
            let mut h = harness_sized(explorer, SIZES[0]);
            set_up(&mut h, true, &themes()[0], tool.as_deref());
            // Steps 1 to 3 (a question each, past the critical angle last), then the fibre.
            // The rectangle of the last step shown in each view (a scene's step shows the
            // Scenes view, with its own controls).
            let mut rects: [Option<EguiRect>; 2] = [None, None];
            for step in 0..5 {
                let (index, shown) = h.state().lesson().current().unwrap();
                assert!(shown.hides_answer() && h.state().overlay().hide_answer);
                let what = format!(
                    "{language} 1280×720 presentation, lesson step {} {}",
                    index + 1,
                    tool.as_ref()
                        .map_or_else(|| "no tool".to_owned(), |t| format!("tool {t}")),
                );
                let scene = h.state().view() == refraction_explorer::app::View::Scenes;
                let mut m = measure(&h, &what, true, tool.is_some(), scene);
                // The diagram keeps its rectangle while the teacher steps.
                let here = canvas_rect(&h);
                let rect = &mut rects[usize::from(scene)];
                let moved =
                    |r: &EguiRect| (r.min - here.min).length() + (r.max - here.max).length();
                if let Some(before) = rect.filter(|r| moved(r) > 0.5) {
                    m.problems.push(format!(
                        "{what}: the diagram moved from {before:?} to {here:?}"
                    ));
                }
                *rect = Some(here);
                if !scene {
                    check_nothing_past_the_interface(&h, &what, &mut m.problems);
                }
                measured.push((what.clone(), m));
                if step < 4 {
                    h.key_press(egui::Key::PageDown);
                    run_three_more_frames(&mut h);
                }
            }
        }
    }
    refraction_i18n::set_locale(Locale::En);
    report("lesson steps", &measured);
}

/// The layouts a hidden step is audited in: the desk and the projector at 1280×720, and a
/// phone's student view.
const HIDDEN_STEP_LAYOUTS: [(&str, (f32, f32), bool); 3] = [
    ("desk", (1280.0, 720.0), false),
    ("presentation", (1280.0, 720.0), true),
    ("phone", (390.0, 844.0), false),
];

/// The words that give a hidden step's answer away. On the one interface: every line of the
/// revealed diagram's labels that gives θt, the critical angle, a candidate's (a, b), a·W,
/// a share of the light or the discriminant k, and under total internal reflection its words
/// (the banner's first line, "reflected ray (all the light)"). In a scene: the whole trace's
/// counts of kernel calls, reflections and total internal reflections, Fresnel evaluations,
/// the words "total internal reflection" where the light meets one, and the scene's
/// description (the fibre's "repeated total internal reflection", the slab's parallel exit).
fn answer_words(deck: &refraction_deck::Deck, step: &refraction_deck::Step) -> Vec<String> {
    use refraction_deck::{Effect, StepView};
    let mut words = Vec::new();
    if step.view == StepView::Scenes {
        let scene = deck.scene(step).unwrap();
        let trace = scene.trace();
        let c = &trace.counts;
        words.extend([
            t!("diagram-count-kernel-calls", count = c.kernel_calls),
            t!("diagram-count-tir", count = c.total_internal_reflections),
            t!("diagram-count-reflections", count = c.reflections_spawned),
            t!("diagram-count-fresnel", count = c.fresnel_evaluations),
            refraction_diagram::scene_description(&scene),
        ]);
        if c.total_internal_reflections > 0 {
            words.push(t!("diagram-hit-tir"));
        }
        return words;
    }
    let overlay = refraction_diagram::Overlay {
        intensities: step.has(Effect::Intensities).then_some(step.light),
        ..refraction_diagram::Overlay::default()
    };
    let revealed = Diagram::with_overlay(&step.state, GVec2::new(1280.0, 720.0), &overlay);
    let telling = ["θt", "θc", "(a, b)", "a = ", "%", "k = "];
    for shape in &revealed.shapes {
        if let Figure::Text(label) = shape {
            words.extend(
                label
                    .text
                    .lines()
                    .filter(|line| telling.iter().any(|t| line.contains(t)))
                    .map(str::to_owned),
            );
        }
    }
    if step.state.refraction().is_tir() {
        words.push(t!("diagram-reflected-all"));
        words.extend(revealed.summary.lines().next().map(str::to_owned));
    }
    words.sort();
    words.dedup();
    words
}

/// Every text the window drew in its last frame, and every name and value its accessibility
/// tree gives (what a screen reader says), and the window's title.
fn every_text(h: &Harness<'_, Explorer>) -> Vec<String> {
    fn visit(shape: &Shape, texts: &mut Vec<String>) {
        match shape {
            Shape::Vec(shapes) => shapes.iter().for_each(|s| visit(s, texts)),
            Shape::Text(text) => texts.push(text.galley.job.text.clone()),
            _ => {}
        }
    }
    let mut texts = vec![h.state().title()];
    for clipped in &h.output().shapes {
        visit(&clipped.shape, &mut texts);
    }
    for node in h.query_all_by(|_| true) {
        let node = node.accesskit_node();
        texts.extend(node.label());
        texts.extend(node.value());
    }
    texts
}

/// The answer words (`words`) that `texts` give, where `what` was seen; the deck's title is
/// its topic, named before any question, and left out.
fn told(texts: &[String], words: &[String], deck_title: &str) -> Vec<String> {
    let mut found = Vec::new();
    for text in texts {
        let text = text.replace(deck_title, "");
        for word in words.iter().filter(|w| text.contains(w.as_str())) {
            found.push(format!("“{word}” in “{}”", text.replace('\n', " ")));
        }
    }
    found.sort();
    found.dedup();
    found
}

/// The words of a step's page on the student sheet: its diagram's labels as the sheet draws
/// it (hidden, on paper), with the title and question the window shows too.
fn sheet_texts(deck: &refraction_deck::Deck, step: &refraction_deck::Step) -> Vec<String> {
    use refraction_explorer::app::handout::{Drawn, picture};
    let drawn = Drawn {
        hidden: true,
        paper: true,
    };
    let primitives = picture(deck, step, GVec2::new(700.0, 525.0), drawn).unwrap();
    primitives
        .into_iter()
        .filter_map(|p| match p {
            Primitive::Text(label) => Some(label.text),
            _ => None,
        })
        .collect()
}

/// Issue 41: until the reveal nothing on any surface states the answer, in words as in lines:
/// every step that asks of every built-in deck, in every language, at the desk, on the
/// projector and on a phone (the strips, the readouts, the tools, the diagram's labels and
/// banner, the screen reader's names, the window's title) and on the student sheet. Revealed,
/// the same audit finds the words on screen: it sees what it looks for.
#[test]
fn no_surface_states_a_hidden_answer_before_the_reveal() {
    let mut problems = Vec::new();
    for language in Locale::ALL {
        refraction_i18n::set_locale(language);
        for name in refraction_deck::builtin::names() {
            let deck = refraction_deck::Deck::load(name).unwrap();
            audit_hidden_steps((name, &deck), language, &mut problems);
        }
    }
    refraction_i18n::set_locale(Locale::En);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// [`no_surface_states_a_hidden_answer_before_the_reveal`] for one deck in one language.
fn audit_hidden_steps(
    (name, deck): (&str, &refraction_deck::Deck),
    language: Locale,
    problems: &mut Vec<String>,
) {
    for (index, step) in deck.steps.iter().enumerate() {
        if !step.hides_answer() {
            continue;
        }
        let words = answer_words(deck, step);
        let what = |layout: &str| format!("{language} {} step {} {layout}", deck.title, index + 1);
        if words.is_empty() {
            problems.push(format!("{}: no answer words to look for", what("")));
            continue;
        }
        for found in told(&sheet_texts(deck, step), &words, &deck.title) {
            problems.push(format!("{}: {found}", what("student sheet")));
        }
        for (layout, size, present) in HIDDEN_STEP_LAYOUTS {
            let mut explorer = Explorer::new(ExplorerState::default());
            let link = format!("#lesson={name}&step={}", index + 1);
            explorer.open_link(&link).unwrap();
            explorer.presentation_mut().on = present;
            let mut h = harness_sized(explorer, size);
            run_three_more_frames(&mut h);
            assert!(h.state().lesson().hides_answer(), "{}", what(layout));
            for found in told(&every_text(&h), &words, &deck.title) {
                problems.push(format!("{}: {found}", what(layout)));
            }
            if layout == "desk" {
                h.key_press(egui::Key::R);
                run_three_more_frames(&mut h);
                if told(&every_text(&h), &words, &deck.title).is_empty() {
                    problems.push(format!(
                        "{}: revealed, no answer word is seen",
                        what(layout)
                    ));
                }
            }
        }
    }
}

/// The student's view on a phone, upright (390 × 844) and sideways (844 × 390), in every
/// language, over a deck's steps of each kind (normal incidence, past the critical angle,
/// p light at Brewster's angle, the fibre's scene), hidden and revealed: the diagram's share,
/// no text under 13 px, every control inside the window and no word broken inside, the
/// labels off W, N and the handles, and every button a finger's size (44 px).
#[test]
fn the_students_view_keeps_the_layout_rules_on_a_phone() {
    let mut measured = Vec::new();
    let links = [
        "#lesson=snell&step=2",
        "#lesson=total-internal-reflection&step=3",
        "#lesson=fresnel-brewster&step=3",
        "#lesson=total-internal-reflection&step=5",
    ];
    for language in Locale::ALL {
        refraction_i18n::set_locale(language);
        for (size, held) in [((390.0, 844.0), "upright"), ((844.0, 390.0), "sideways")] {
            for link in links {
                let mut explorer = Explorer::new(ExplorerState::default());
                explorer.open_link(link).unwrap();
                let mut h = harness_sized(explorer, size);
                run_three_more_frames(&mut h);
                for revealed in [false, true] {
                    let what = format!("{language} phone {held} {link} revealed {revealed}");
                    assert!(h.state().shows_student_view(&h.ctx), "{what}");
                    let scene = h.state().view() == refraction_explorer::app::View::Scenes;
                    let mut m = measure(&h, &what, false, false, scene);
                    if m.share < 0.4 {
                        let share = m.share * 100.0;
                        m.problems
                            .push(format!("{what}: the diagram has {share:.0} %"));
                    }
                    for node in h.query_all_by_role(Role::Button) {
                        let (r, name) = (node.rect(), node.accesskit_node().label());
                        if r.height() < 43.5 || r.width() < 43.5 {
                            let name = name.unwrap_or_default();
                            m.problems.push(format!("{what}: “{name}” is {r:?}"));
                        }
                    }
                    measured.push((what, m));
                    h.key_press(egui::Key::R);
                    run_three_more_frames(&mut h);
                }
            }
        }
    }
    refraction_i18n::set_locale(Locale::En);
    report("student's view", &measured);
}

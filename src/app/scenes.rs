//! The Scenes view: a picker of the built-in scenes and the traced scene on a canvas, where the
//! source, its direction and each shape are dragged (the scene is retraced into the same
//! [`Trace`] on every change) and a click on a hit point opens it in the single-interface view.

use core::time::Duration;
use egui::emath::RectTransform;
use egui::{
    CentralPanel, ComboBox, CursorIcon, Painter, Panel, Pos2, ProgressBar, Rect, Response,
    RichText, Role, Sense, Slider, SliderClamping, Ui, WidgetInfo,
};
use refraction_i18n::t;

use glam::{DVec2, Vec2};

use super::paint::{KeptShapes, color, hover_left_out, meshed, paint, paint_kept};
use super::retrace::{Retracer, empty};
use super::scene_files::SceneFiles;
use super::typed::error_label;
use refraction_diagram::{
    Align, Label, Primitive, SMALLEST_TEXT, SceneLayout, ScenePicture, built_in_scene_title,
    medium_name, numbers::number, palette::Palette, scene_description, scene_title,
};
use refraction_model::ExplorerState;
use refraction_scene::{
    DEFAULT_SCENE, EditError, Hit, Scene, SceneInfo, Side, SourceKind, Stop, Trace, catalogue,
    traced_wavelength,
};

/// The most rays the slider offers: enough to see a caustic, few enough to drag smoothly.
const MAX_SLIDER_RAYS: usize = 1000;

/// The most segments a frame traces and draws while a handle is dragged. A scene whose full
/// trace has more (hundreds of rays per colour: the droplet at 1,000 has 43,396 segments and
/// takes 23 ms a frame) is traced with every k-th ray while the pointer moves, so that a drag
/// keeps under 4 ms a frame (`cargo bench --bench frame`), and in full again when it ends.
/// Every built-in scene at its own ray count traces in full.
const DRAFT_SEGMENTS: usize = 2_000;

/// The Scenes view's state: the scene as edited, its trace, and what the canvas remembers
/// between frames.
#[derive(Debug)]
pub struct ScenesView {
    catalogue: Vec<SceneInfo>,
    /// The scene as loaded, for *Reset*.
    original: Scene,
    scene: Scene,
    /// The last finished trace (of the scene as edited, or of an earlier edit while a bigger
    /// trace runs in the background).
    trace: Trace,
    retracer: Retracer,
    /// The layout at the start of the drag under way: a scene without a `[view]` is fitted to
    /// its source and shapes, and refitting while dragging would move the world under the
    /// pointer.
    drag_layout: Option<SceneLayout>,
    error: Option<String>,
    /// Where the canvas was drawn in the last frame, with the layout it used.
    drawn: Option<(Rect, SceneLayout)>,
    /// The scene file, the picture export and their dialogs.
    files: SceneFiles,
    /// A lesson step's question is asked: the rays are drawn up to the first surface only.
    answer_hidden: bool,
    /// A lesson step is shown: its strip stands above, and the hint line is left out.
    in_lesson: bool,
    /// The handles are sized for a finger (the student's view).
    touch: bool,
    /// In presentation, the scene's files, description and hint are shown (they start
    /// folded away, so that the scene owns the projector).
    more_shown: bool,
    /// The shape (width over height) of the canvas's drawing area the scene was last traced
    /// for: the world is widened to it, so that the scene fills the canvas, not a square in it.
    aspect: Option<f64>,
    /// Counts the changes of the scene and its trace: the picture is drawn again only when
    /// it, or anything else the picture is drawn from, has changed.
    generation: u64,
    /// The picture drawn last, what it was drawn from, and its egui shapes.
    kept: Option<Kept>,
    /// While a drag shows a draft: one ray in how many is traced ([`DRAFT_SEGMENTS`]).
    draft: Option<usize>,
}

/// The scene's picture as the last frame drew it.
#[derive(Debug)]
struct Kept {
    /// What it was drawn from.
    key: PictureKey,
    picture: ScenePicture,
    /// Its egui shapes, its rays tessellated into one mesh, with where on the screen they were
    /// laid out and at how many pixels per point (none while a handle is dragged: the picture
    /// changes every frame then).
    shapes: Option<(Rect, f32, KeptShapes)>,
}

impl Kept {
    /// Paints the picture with `painter`, through `to_screen`: while a handle is `dragging`,
    /// as it is; at rest, the shapes kept from the last frame when they were laid out at the
    /// same place, else its shapes made afresh (and kept for the next frame).
    fn paint(&mut self, painter: &Painter, to_screen: &RectTransform, dragging: bool) {
        if dragging {
            self.shapes = None;
            paint(painter, to_screen, &self.picture.primitives);
            return;
        }
        let (rect, ppp) = (*to_screen.to(), painter.ctx().pixels_per_point());
        if self
            .shapes
            .as_ref()
            .is_none_or(|(r, p, _)| (*r, *p) != (rect, ppp))
        {
            let shapes = super::paint::shapes(painter, to_screen, &self.picture.primitives);
            self.shapes = Some((rect, ppp, meshed(painter.ctx(), shapes)));
        }
        if let Some((.., shapes)) = &self.shapes {
            paint_kept(painter, shapes);
        }
    }
}

/// What the scene's picture is drawn from, besides the scene and its trace (counted by
/// [`ScenesView::generation`]): an unchanged key reuses the last picture, so that a frame at
/// rest (a hover, a background trace's progress bar) neither rebuilds the picture of tens of
/// thousands of segments nor places its labels again.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PictureKey {
    generation: u64,
    layout: SceneLayout,
    palette: Palette,
    hidden: bool,
    language: refraction_i18n::Locale,
}

impl Default for ScenesView {
    /// The default built-in scene.
    fn default() -> Self {
        let scene = Scene::embedded(DEFAULT_SCENE)
            // untranslated: a panic message for the engineer, never shown to a user.
            .unwrap_or_else(|e| unreachable!("the built-in scenes load (tested): {e}"));
        Self::new(scene)
    }
}

/// Paints `note` (a drag shows a draft: one ray in so many, the full picture returns when the
/// pointer lets go) in the canvas's lower left corner.
fn draft_note(painter: &Painter, canvas: Rect, note: &str, font_px: f32, palette: &Palette) {
    let margin = font_px * 0.5;
    let at = canvas.left_bottom() + egui::vec2(margin, -margin);
    let galley = painter.layout_no_wrap(
        note.to_owned(),
        egui::FontId::proportional(font_px),
        color(palette.ink),
    );
    let rect = egui::Align2::LEFT_BOTTOM.anchor_size(at, galley.size());
    painter.rect_filled(rect.expand(margin * 0.5), 0.0, color(palette.background));
    painter.galley(rect.min, galley, color(palette.ink));
}

/// The canvas point (pixels from the canvas's corner) under the screen point `p`.
fn canvas_point(to_screen: &RectTransform, p: Pos2) -> Vec2 {
    let p = to_screen.inverse().transform_pos(p);
    Vec2::new(p.x, p.y)
}

/// What the overlay beside a hovered hit says.
fn hit_text(scene: &Scene, hit: &Hit) -> String {
    let name = |m: usize| {
        scene
            .media()
            .get(m)
            .map_or_else(|| "?".to_owned(), |m| medium_name(&m.name))
    };
    let (from, to) = (name(hit.from_medium), name(hit.to_medium));
    let (mu_i, mu_t) = (number(hit.mu_i, 4), number(hit.mu_t, 4));
    let wavelength = number(traced_wavelength(hit.light), 1);
    let side = match hit.side {
        Side::Outside => "entering",
        Side::Inside => "leaving",
    };
    t!(
        "scenes-hit",
        side = side,
        from = from,
        to = to,
        mu_i = mu_i,
        mu_t = mu_t,
        wavelength = wavelength
    )
}

/// Why a trace stopped early, in words.
fn stop_text(stop: &Stop) -> String {
    match stop {
        Stop::Segments(n) => t!("scenes-stopped-segments", budget = number(*n as f64, 0)),
        Stop::Tests(n) => t!("scenes-stopped-tests", budget = number(*n as f64, 0)),
        Stop::Cancelled => t!("scenes-stopped-cancelled"),
    }
}

impl ScenesView {
    /// The view showing `scene`, traced.
    #[must_use]
    pub fn new(scene: Scene) -> Self {
        let (mut retracer, mut trace) = (Retracer::default(), empty(&scene));
        retracer.retrace(&scene, &mut trace);
        Self {
            catalogue: catalogue(),
            original: scene.clone(),
            scene,
            trace,
            retracer,
            drag_layout: None,
            error: None,
            drawn: None,
            files: SceneFiles::default(),
            answer_hidden: false,
            in_lesson: false,
            touch: false,
            more_shown: false,
            aspect: None,
            generation: 0,
            kept: None,
            draft: None,
        }
    }

    /// Shows a lesson step (`shown`): the hint line under the controls is left out, so that
    /// the step's strip above keeps the scene its room; while `hidden` (the step's question is
    /// asked) the rays are drawn only up to the first surface they meet.
    pub fn for_lesson(&mut self, shown: bool, hidden: bool) {
        self.in_lesson = shown;
        self.answer_hidden = hidden;
    }

    /// The scene as edited.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Its last finished trace (a bigger one may be running in the background: see
    /// [`Self::tracing`]).
    #[must_use]
    pub fn trace(&self) -> &Trace {
        &self.trace
    }

    /// How far the trace running in the background has got (0 to 1), or `None` when none is.
    #[must_use]
    pub fn tracing(&self) -> Option<f64> {
        self.retracer.progress()
    }

    /// Where the world point `world` was drawn in the last frame, in screen points (`None`
    /// before the view was first shown).
    #[must_use]
    pub fn to_screen(&self, world: DVec2) -> Option<Pos2> {
        self.drawn.map(|(rect, layout)| {
            let p = layout.at(world);
            rect.min + egui::vec2(p.x, p.y)
        })
    }

    /// Shows the scene afresh, and keeps it for *Reset*.
    fn open(&mut self, scene: Scene) {
        self.original = scene.clone();
        self.scene = scene;
        self.error = None;
        self.drag_layout = None;
        self.retrace();
    }

    /// Traces the scene again, its world widened to the canvas's shape once that is known;
    /// while a drag shows a draft, with one ray in [`Self::draft`]'s count.
    fn retrace(&mut self) {
        self.generation += 1;
        let mut scene = match self.aspect {
            Some(aspect) => self.scene.framed(aspect),
            None => self.scene.clone(),
        };
        if let Some(every) = self.draft {
            let rays = scene.source().rays.div_ceil(every).max(1);
            // A count from 1 to the scene's own is always accepted.
            scene.set_ray_count(rays).ok();
        }
        self.retracer.retrace(&scene, &mut self.trace);
    }

    /// One ray in how many a drag's frames trace, while a handle is dragged in a scene whose
    /// full trace has more segments than a frame may draw (2,000).
    #[must_use]
    pub fn draft(&self) -> Option<usize> {
        self.draft
    }

    /// On a frame of a drag, before its edit is traced: a scene whose full trace is too big to
    /// trace every frame is traced as a draft until the drag ends, one ray in as many as
    /// bring it to [`DRAFT_SEGMENTS`] segments.
    fn start_draft(&mut self) {
        if self.draft.is_none() {
            let every = self.trace.counts.segments.div_ceil(DRAFT_SEGMENTS);
            self.draft = (every > 1 && self.scene.source().rays > 1).then_some(every);
        }
    }

    /// Traces again for a canvas whose drawing area has another shape than the last one's
    /// (a window resized, presentation switched), unless a handle is being dragged; returns
    /// whether it did (the layout of this frame is then the old world's).
    fn frame_to(&mut self, layout: &SceneLayout) -> bool {
        let size = layout.drawing.size();
        let aspect = f64::from(size.x) / f64::from(size.y.max(1.0));
        let changed = self
            .aspect
            .is_none_or(|before| (before / aspect - 1.0).abs() > 0.01);
        let retrace = changed && self.drag_layout.is_none() && aspect.is_finite();
        if retrace {
            self.aspect = Some(aspect);
            self.retrace();
        }
        retrace
    }

    /// Puts back a scene from the undo history: the same scene edited differently is retraced
    /// in place (*Reset* still goes back to it as loaded); another scene is opened afresh.
    pub fn restore(&mut self, scene: Scene) {
        if scene == self.scene {
            return;
        }
        if scene.name() == self.original.name() {
            self.scene = scene;
            self.error = None;
            self.retrace();
        } else {
            self.open(scene);
        }
    }

    /// Applies an edit and retraces, or keeps the scene and says why the edit was refused.
    fn edit(&mut self, edit: impl FnOnce(&mut Scene) -> Result<(), EditError>) {
        match edit(&mut self.scene) {
            Ok(()) => {
                self.error = None;
                self.retrace();
            }
            Err(e) => self.error = Some(e.to_string()),
        }
    }

    /// Shows the view in `ui`: the controls strip, then the canvas. Returns the single-interface
    /// problem of the hit point clicked, if one was. In presentation (`presenting`) the strip
    /// keeps to its first row (the scene, its rays, *Reset*) unless its switch unfolds the
    /// scene's files, description and hint.
    pub fn show(
        &mut self,
        ui: &mut Ui,
        palette: &Palette,
        presenting: bool,
    ) -> Option<ExplorerState> {
        Panel::top("scene-controls").show(ui, |ui| {
            self.controls(ui, presenting);
            self.trace_status(ui);
        });
        self.show_canvas(ui, palette)
    }

    /// The canvas alone, over what `ui` has left, its handles for a finger (the student's
    /// view, which shows no scene controls): returns the single-interface problem of the hit
    /// point clicked, if one was.
    pub(super) fn show_for_touch(
        &mut self,
        ui: &mut Ui,
        palette: &Palette,
    ) -> Option<ExplorerState> {
        self.touch = true;
        let clicked = self.show_canvas(ui, palette);
        self.touch = false;
        clicked
    }

    /// The canvas alone, over what `ui` has left: returns the single-interface problem of the
    /// hit point clicked, if one was.
    fn show_canvas(&mut self, ui: &mut Ui, palette: &Palette) -> Option<ExplorerState> {
        if let Some(done) = self.retracer.poll() {
            let shown = core::mem::replace(&mut self.trace, done);
            self.retracer.recycle(shown);
            self.generation += 1;
        }
        CentralPanel::no_frame()
            .show(ui, |ui| self.canvas(ui, palette))
            .inner
    }

    fn controls(&mut self, ui: &mut Ui, presenting: bool) {
        ui.horizontal(|ui| {
            let mut picked = self.scene.name().to_owned();
            ComboBox::from_label(t!("scenes-scene"))
                .selected_text(scene_title(&self.scene))
                .show_ui(ui, |ui| {
                    for info in &self.catalogue {
                        let title = built_in_scene_title(info.name);
                        let title = title.unwrap_or_else(|| info.title.clone());
                        ui.selectable_value(&mut picked, info.name.to_owned(), title);
                    }
                });
            if picked != self.scene.name() {
                match Scene::embedded(&picked) {
                    Ok(scene) => self.open(scene),
                    Err(e) => self.error = Some(e.to_string()),
                }
            }
            if self.scene.source().kind != SourceKind::Ray {
                let mut rays = self.scene.source().rays;
                let slider = Slider::new(&mut rays, 1..=MAX_SLIDER_RAYS)
                    .logarithmic(true)
                    .clamping(SliderClamping::Never)
                    .text(t!("scenes-rays"));
                if ui.add(slider).changed() {
                    self.edit(|s| s.set_ray_count(rays));
                }
            }
            if ui
                .button(t!("controls-reset"))
                .on_hover_text(t!("scenes-reset-hover"))
                .clicked()
            {
                self.open(self.original.clone());
            }
            if presenting {
                let (arrow, words) = if self.more_shown {
                    ("⏶", t!("scenes-less"))
                } else {
                    ("⏷", t!("scenes-more"))
                };
                if ui.button(format!("{arrow} {words}")).clicked() {
                    self.more_shown = !self.more_shown;
                }
            }
        });
        if !presenting || self.more_shown {
            if let Some(scene) = self.files.show(ui, &self.scene) {
                self.open(scene);
            }
            // One line each, whatever the language: a cut line shows its whole text on hover,
            // and the scene keeps the window's height. A scene's description says what its
            // light does (the fibre's total internal reflection, the slab's parallel exit): the
            // answer of a question asked about it, left out until it is revealed.
            if !self.answer_hidden {
                ui.add(egui::Label::new(scene_description(&self.scene)).truncate());
            }
            if !self.in_lesson {
                ui.add(egui::Label::new(RichText::new(t!("scenes-hint")).weak()).truncate());
            }
        }
        if let Some(error) = &self.error {
            error_label(ui, error);
        }
    }

    /// While a trace runs in the background: its progress and *Cancel*; and why the trace shown
    /// stopped early, if it did.
    fn trace_status(&self, ui: &mut Ui) {
        if let Some(done) = self.retracer.progress() {
            // Wake up to show the progress, and the trace once it is done.
            ui.ctx().request_repaint_after(Duration::from_millis(50));
            ui.horizontal(|ui| {
                let text = t!("scenes-tracing", percent = number(done * 100.0, 0));
                // A fraction from 0 to 1: f32 holds it to far better than a pixel.
                ui.add(
                    ProgressBar::new(done as f32)
                        .desired_width(320.0)
                        .text(text),
                );
                if ui
                    .button(t!("scenes-cancel"))
                    .on_hover_text(t!("scenes-cancel-hover"))
                    .clicked()
                {
                    self.retracer.cancel();
                }
            });
        }
        if let Some(stop) = self.trace.counts.stopped {
            let why = stop_text(&stop);
            error_label(ui, &why);
        }
    }

    /// The layout of the scene on a canvas `size` pixels across, its handles for a finger in
    /// the student's view.
    fn layout(&self, size: Vec2) -> SceneLayout {
        let layout = SceneLayout::for_scene(&self.scene, &self.trace, size);
        if self.touch {
            layout.for_touch()
        } else {
            layout
        }
    }

    /// The canvas: handles dragged first (retracing), then the picture painted once; a click
    /// near a hit point returns its problem.
    fn canvas(&mut self, ui: &mut Ui, palette: &Palette) -> Option<ExplorerState> {
        let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::click());
        let rect = response.rect;
        let to_screen = RectTransform::from_to(Rect::from_min_size(Pos2::ZERO, rect.size()), rect);
        let layout = self
            .drag_layout
            .unwrap_or_else(|| self.layout(Vec2::new(rect.width(), rect.height())));
        let mut clicked_at = response
            .interact_pointer_pos()
            .filter(|_| response.clicked());
        let dragging = self.handles(ui, &response, &to_screen, &layout, &mut clicked_at);
        self.after_handles(ui, dragging, &layout);
        self.drawn = Some((rect, layout));
        // The layout fits the whole trace, so that revealing the answer does not move the view.
        let hidden = self
            .answer_hidden
            .then(|| refraction_deck::answer::up_to_first_surface(&self.trace));
        let shown = hidden.as_ref().unwrap_or(&self.trace);
        let key = PictureKey {
            generation: self.generation,
            layout,
            palette: *palette,
            hidden: self.answer_hidden,
            language: refraction_i18n::locale(),
        };
        if self.kept.as_ref().is_some_and(|kept| kept.key != key) {
            self.kept = None;
        }
        let scene = &self.scene;
        let kept = self.kept.get_or_insert_with(|| Kept {
            key,
            picture: if hidden.is_some() {
                ScenePicture::asking(scene, shown, &layout, palette)
            } else {
                ScenePicture::with_palette(scene, shown, &layout, palette)
            },
            shapes: None,
        });
        kept.paint(&painter, &to_screen, dragging);
        let note = self.draft.map(|every| t!("scenes-draft", every = every));
        if let Some(note) = &note {
            draft_note(&painter, rect, note, layout.font, palette);
        }
        let picture = &kept.picture;
        hover_left_out(&response, &to_screen, &picture.left_out, layout.font * 2.0);
        // Worded only when asked for (a screen reader, the tests), not on every frame.
        response.widget_info(|| {
            let about = match &note {
                Some(note) => format!("{} {note}", picture.summary),
                None => picture.summary.clone(),
            };
            WidgetInfo::labeled(Role::Image, true, about)
        });
        let hovered = response
            .hover_pos()
            .and_then(|p| layout.hit_near(shown, canvas_point(&to_screen, p)));
        if let Some(hit) = hovered {
            self.show_hit(ui, &painter, (&to_screen, &layout), hit, palette);
        }
        let clicked =
            clicked_at.and_then(|p| layout.hit_near(shown, canvas_point(&to_screen, p)))?;
        let problem = clicked.incidence();
        ExplorerState::new(
            problem.w,
            problem.n,
            problem.mu_i,
            problem.mu_t,
            problem.convention,
        )
        .map_err(|e| self.error = Some(e.to_string()))
        .ok()
    }

    /// After the handles of a frame drawn with `layout`: a drag keeps that layout; a drag that
    /// has ended traces the scene in full again, in this frame; the world is widened to a
    /// canvas of another shape.
    fn after_handles(&mut self, ui: &Ui, dragging: bool, layout: &SceneLayout) {
        self.drag_layout = dragging.then_some(*layout);
        if !dragging && self.draft.take().is_some() {
            self.retrace();
        }
        if self.frame_to(layout) {
            // Drawn again at once in the widened world, not at the next pointer move (a
            // projector left alone would keep this frame's letterbox).
            ui.ctx().request_repaint();
        }
    }

    /// One draggable, named widget per handle of `layout`; a drag edits the scene (and
    /// retraces it). Returns whether a handle is being dragged. A handle may sit on a hit point
    /// (a line's anchor where the ray meets it): a click on it, without a drag, replaces
    /// `clicked_at`, so that it still picks the hit.
    fn handles(
        &mut self,
        ui: &Ui,
        canvas: &Response,
        to_screen: &RectTransform,
        layout: &SceneLayout,
        clicked_at: &mut Option<Pos2>,
    ) -> bool {
        let mut dragging = false;
        for handle in layout.handles(&self.scene) {
            let area = handle.grab_area();
            let grab_rect = Rect::from_min_max(
                to_screen.transform_pos(Pos2::new(area.min.x, area.min.y)),
                to_screen.transform_pos(Pos2::new(area.max.x, area.max.y)),
            );
            let id = canvas.id.with(handle.id);
            let grab = ui.interact(grab_rect, id, Sense::click_and_drag());
            if grab.clicked() {
                *clicked_at = grab.interact_pointer_pos();
            }
            let label = handle.id.label(&self.scene);
            grab.widget_info(|| WidgetInfo::labeled(Role::Button, true, &label));
            if let Some(pointer) = grab.interact_pointer_pos().filter(|_| grab.dragged()) {
                dragging = true;
                let at = canvas_point(to_screen, pointer);
                self.start_draft();
                self.edit(|scene| layout.drag(scene, handle.id, at));
            }
            if grab.hovered() || grab.dragged() {
                ui.ctx().set_cursor_icon(CursorIcon::Grab);
            }
        }
        dragging
    }

    /// A ring around the hit under the pointer and what happens there, beside it on the side
    /// with more room.
    fn show_hit(
        &self,
        ui: &Ui,
        painter: &Painter,
        (to_screen, layout): (&RectTransform, &SceneLayout),
        hit: &Hit,
        palette: &Palette,
    ) {
        let center = layout.at(hit.point);
        let ring = egui::Stroke::new(2.0, color(palette.ink));
        painter.circle_stroke(
            to_screen.transform_pos(Pos2::new(center.x, center.y)),
            layout.pick_radius(),
            ring,
        );
        let size = (layout.font * 0.8).max(SMALLEST_TEXT);
        let side = if center.x < layout.canvas.center().x {
            1.0
        } else {
            -1.0
        };
        let label = Label {
            text: hit_text(&self.scene, hit),
            at: center + Vec2::new(side * (layout.pick_radius() + size * 0.5), 0.0),
            h: Align::away(side),
            v: Align::Center,
            size,
            colour: palette.ink,
            background: Some(palette.background),
        };
        paint(painter, to_screen, &[Primitive::Text(label)]);
        ui.ctx().set_cursor_icon(CursorIcon::PointingHand);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_i18n::Locale;

    #[test]
    fn a_hovered_hit_says_which_way_the_ray_crosses_in_the_windows_language() {
        let scene = Scene::embedded("droplet").unwrap();
        let trace = scene.trace();
        let entering = trace.hits.iter().find(|h| h.side == Side::Outside).unwrap();
        let leaving = trace.hits.iter().find(|h| h.side == Side::Inside).unwrap();
        let english = (hit_text(&scene, entering), hit_text(&scene, leaving));
        refraction_i18n::set_locale(Locale::De);
        let german = hit_text(&scene, leaving);
        refraction_i18n::set_locale(Locale::En);
        assert!(
            english
                .0
                .starts_with("air into water (entering)\nμi = 1.0003"),
            "{}",
            english.0
        );
        assert!(
            english.1.contains("(leaving: the kernel turns N round)\n"),
            "{}",
            english.1
        );
        assert!(
            english.1.ends_with("nm\nclick: open in One interface"),
            "{}",
            english.1
        );
        assert!(
            german.starts_with("von Wasser in Luft (Austritt"),
            "{german}"
        );
        assert!(
            german.contains("μi = 1,3436, μt = 1,0003, 400,0 nm"),
            "{german}"
        );
    }
}

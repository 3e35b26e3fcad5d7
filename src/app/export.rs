//! *Export animation*: the μ → 1 morph, the sweep through the critical angle or the moving
//! wavefronts of the diagram as a GIF for a slide, drawn in a background thread (the window
//! never freezes) with a progress bar and *Cancel*; and the Scenes view's picture export, PNG
//! or SVG by the file's extension.

use core::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use core::time::Duration;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use egui::{ComboBox, DragValue, ProgressBar, TextEdit, Ui};

use super::background::{self, Job as Background};
use super::file_dialog::{self, Kind, Target, WriteRefusal};
use super::status::{self, Look, Status, not_exported};
use refraction_diagram::{Animation, Overlay, PanZoom, numbers::number};
use refraction_files::check_writable;
use refraction_i18n::t;
use refraction_model::ExplorerState;
use refraction_render::animation::{AnimationSpec, FPS_LIMITS, FRAME_LIMITS, export_gif};
use refraction_render::{ImageFormat, UnsupportedFormat};
use refraction_render::{RenderError, SIZE_LIMITS};
use refraction_scene::Scene;

/// The size of an exported animation when none is chosen: 720p, whose smallest words (15
/// pixels) read on a slide shown full screen, and small enough to draw in seconds.
pub(super) const DEFAULT_ANIMATION_SIZE: (u32, u32) = (1280, 720);

/// An export running in the background.
#[derive(Debug)]
struct Job {
    /// Frames drawn so far.
    done: Arc<AtomicUsize>,
    /// Frames in all.
    all: usize,
    /// Set to stop the export after the frame being drawn.
    cancel: Arc<AtomicBool>,
    /// The file being written.
    path: PathBuf,
    /// How the export ended, put in words on the window's thread (whose language it is).
    handle: Background<Result<(), RenderError>>,
}

/// The *Export animation* controls, the export running and what the last one said.
#[derive(Debug)]
pub(super) struct AnimationExport {
    animation: Animation,
    frames: usize,
    fps: u32,
    size: (u32, u32),
    path: String,
    running: Option<Job>,
    status: Option<Status>,
    /// A GIF the user is asked about replacing.
    replace: Option<PathBuf>,
}

impl Default for AnimationExport {
    fn default() -> Self {
        let spec = AnimationSpec::new(Animation::Sweep, DEFAULT_ANIMATION_SIZE);
        Self {
            animation: spec.animation,
            frames: spec.frames,
            fps: spec.fps,
            size: spec.size,
            path: "refraction.gif".to_owned(),
            running: None,
            status: None,
            replace: None,
        }
    }
}

/// What an export that ended says: the file written, that it was cancelled, or why nothing
/// was written.
pub(super) fn outcome(result: Result<(), RenderError>, path: &Path) -> Status {
    match result {
        Err(RenderError::Cancelled) => Status::Refused(t!("files-export-cancelled")),
        result => status::exported(result, path),
    }
}

/// Why an animation export does not start: what was asked for, or where, is refused. Worded
/// when shown, in the window's language.
#[derive(Debug, thiserror::Error)]
enum NotStarted {
    /// The frames, rate or size are outside their limits.
    #[error("{}", not_exported(.0))]
    Spec(RenderError),
    /// The name is not a GIF's.
    #[error("{}", t!("files-gif-needed", path = .0.display().to_string()))]
    NotAGif(PathBuf),
    /// The name's extension names no format.
    #[error("{}", not_exported(.0))]
    Format(UnsupportedFormat),
    /// No file can be written there.
    #[error("{}", not_exported(.0))]
    Unwritable(std::io::Error),
    /// The path is a folder, or a file of another kind is there.
    #[error(transparent)]
    Target(#[from] WriteRefusal),
}

/// Checks `path` as the GIF to write: a `.gif` name (in any case) where a file can be written.
fn check_gif_path(path: &Path) -> Result<(), NotStarted> {
    match ImageFormat::for_path(path) {
        Ok(ImageFormat::Gif) => check_writable(path).map_err(NotStarted::Unwritable),
        Ok(_) => Err(NotStarted::NotAGif(path.to_path_buf())),
        Err(e) => Err(NotStarted::Format(e)),
    }
}

impl AnimationExport {
    /// The animation as chosen.
    fn spec(&self) -> AnimationSpec {
        AnimationSpec {
            animation: self.animation,
            frames: self.frames,
            fps: self.fps,
            size: self.size,
        }
    }

    /// Starts exporting from `state` drawn with `overlay` (in the fitted view) in a background
    /// thread, to the GIF named (or the next free `refraction-NNN.gif` when none is): at once
    /// to a new file, after a question over an existing GIF, never over a file of another
    /// kind; a bad spec or path is refused at once. Nothing starts while one runs.
    pub(super) fn start(&mut self, state: &ExplorerState, overlay: &Overlay, ctx: &egui::Context) {
        if self.running.is_some() {
            return;
        }
        let path = file_dialog::or_numbered(&self.path, "refraction", "gif");
        let checked = self
            .spec()
            .check()
            .map_err(NotStarted::Spec)
            .and_then(|()| check_gif_path(&path))
            .and_then(|()| Ok(file_dialog::target(&path, Kind::Gif)?));
        match checked {
            Ok(Target::New) => self.begin(path, state, overlay, ctx),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(why) => self.status = Some(Status::Refused(why.to_string())),
        }
    }

    /// Draws the animation into `path` in a background thread.
    fn begin(
        &mut self,
        path: PathBuf,
        state: &ExplorerState,
        overlay: &Overlay,
        ctx: &egui::Context,
    ) {
        let spec = self.spec();
        let (done, cancel) = (
            Arc::new(AtomicUsize::new(0)),
            Arc::new(AtomicBool::new(false)),
        );
        let (state, ctx) = (state.clone(), ctx.clone());
        let overlay = Overlay {
            pan_zoom: PanZoom::default(),
            ..overlay.clone()
        };
        let (counter, stop) = (Arc::clone(&done), Arc::clone(&cancel));
        let target = path.clone();
        // The frames' labels are in the window's language: the thread takes it along.
        let language = refraction_i18n::locale();
        let handle = background::spawn(move || {
            refraction_i18n::set_locale(language);
            let result = export_gif(&state, &overlay, &spec, &target, |frames, _| {
                counter.store(frames, Ordering::Relaxed);
                ctx.request_repaint();
                !stop.load(Ordering::Relaxed)
            });
            ctx.request_repaint();
            result
        });
        self.status = None;
        self.running = Some(Job {
            done,
            all: spec.frames,
            cancel,
            path,
            handle,
        });
    }

    /// Asks the running export to stop after the frame being drawn; nothing is written.
    pub(super) fn cancel(&self) {
        if let Some(job) = &self.running {
            job.cancel.store(true, Ordering::Relaxed);
        }
    }

    /// The fraction done of the export running, if one is; takes the outcome of one that
    /// ended.
    pub(super) fn poll(&mut self) -> Option<f32> {
        let job = self.running.as_ref()?;
        if !job.handle.is_finished() {
            let done = job.done.load(Ordering::Relaxed);
            return Some(done as f32 / job.all.max(1) as f32);
        }
        let job = self.running.take()?;
        self.status = Some(match job.handle.join() {
            Ok(result) => outcome(result, &job.path),
            Err(_) => Status::Refused(t!("files-export-crashed")),
        });
        None
    }

    /// The controls: which animation, frames, rate, size and file; *Export animation*, or
    /// while it runs a progress bar and *Cancel*.
    pub(super) fn show(&mut self, ui: &mut Ui, state: &ExplorerState, overlay: &Overlay) {
        ui.heading(t!("files-animation-heading"));
        // The label above the menu, and the menu one line as wide as the panel, cut if the
        // animation's name is long (the menu and the hover show it all).
        let label = ui.label(t!("files-animation"));
        let response = ComboBox::from_id_salt("animation")
            .width(ui.available_width())
            .wrap_mode(egui::TextWrapMode::Truncate)
            .selected_text(self.animation.label())
            .show_ui(ui, |ui| {
                for a in Animation::ALL {
                    ui.selectable_value(&mut self.animation, a, a.label());
                }
            })
            .response
            .labelled_by(label.id);
        response.on_hover_text(self.animation.label());
        self.numbers(ui);
        ui.horizontal(|ui| {
            let label = ui.label(t!("files-gif-file"));
            ui.add(TextEdit::singleline(&mut self.path).desired_width(170.0))
                .labelled_by(label.id);
        });
        if background::ONE_THREAD {
            ui.label(egui::RichText::new(t!("web-one-thread")).weak());
        }
        match self.poll() {
            Some(fraction) => {
                ui.ctx().request_repaint_after(Duration::from_millis(100));
                ui.horizontal(|ui| {
                    let percent = number(f64::from(fraction) * 100.0, 0);
                    let text = t!("files-drawing-frames", percent = percent);
                    ui.add(ProgressBar::new(fraction).desired_width(170.0).text(text));
                    if ui.button(t!("files-cancel")).clicked() {
                        self.cancel();
                    }
                });
            }
            None => {
                if ui
                    .button(t!("files-export-animation"))
                    .on_hover_text(t!("files-export-animation-hover"))
                    .clicked()
                {
                    self.start(state, overlay, ui.ctx());
                }
            }
        }
        if let Some(path) = file_dialog::answer_replace(ui, &mut self.replace, &mut self.status) {
            self.begin(path, state, overlay, ui.ctx());
        }
        status::show(ui, self.status.as_ref(), Look::Plain);
    }

    /// Frames, rate and size, within their limits.
    fn numbers(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            let label = ui.label(t!("files-frames"));
            let (fewest, most) = FRAME_LIMITS;
            ui.add(DragValue::new(&mut self.frames).range(fewest..=most))
                .labelled_by(label.id);
            let label = ui.label(t!("files-per-second"));
            let (slowest, fastest) = FPS_LIMITS;
            ui.add(DragValue::new(&mut self.fps).range(slowest..=fastest))
                .labelled_by(label.id);
        });
        ui.horizontal(|ui| {
            let (low, high) = SIZE_LIMITS;
            let (width, height) = &mut self.size;
            for (name, value) in [(t!("files-gif-width"), width), (t!("files-height"), height)] {
                let label = ui.label(name);
                ui.add(DragValue::new(value).range(low..=high).suffix(" px"))
                    .labelled_by(label.id);
            }
        });
    }
}

/// Writes `scene`, traced, at `path` as PNG or SVG by its extension, at `size`; what happened,
/// in words: the file written, or the message of a bad path, size or extension, or of a failed
/// write.
pub(super) fn scene_picture(scene: &Scene, size: (u32, u32), path: &Path) -> Status {
    outcome(
        refraction_render::write(refraction_render::Picture::Scene(scene), size, path),
        path,
    )
}

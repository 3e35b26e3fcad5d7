//! *Export animation*: the μ → 1 morph, the sweep through the critical angle or the moving
//! wavefronts of the diagram as a GIF for a slide, drawn in a background thread (the window
//! never freezes) with a progress bar and *Cancel*; and the Scenes view's picture export, PNG
//! or SVG by the file's extension.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use egui::{ComboBox, DragValue, ProgressBar, TextEdit, Ui};

use super::typed::status;
use refraction_diagram::animation::Animation;
use refraction_diagram::overlay::PanZoom;
use refraction_diagram::{ExplorerState, Overlay};
use refraction_render::SIZE_LIMITS;
use refraction_render::animation::{AnimationSpec, FPS_LIMITS, FRAME_LIMITS, export_gif};
use refraction_render::atomic::check_writable;
use refraction_render::format::ImageFormat;
use refraction_scene::Scene;

/// The size of an exported animation when none is chosen: a slide's width, small enough to
/// draw in seconds.
pub const DEFAULT_ANIMATION_SIZE: (u32, u32) = (960, 540);

/// An export running in the background.
#[derive(Debug)]
struct Job {
    /// Frames drawn so far.
    done: Arc<AtomicUsize>,
    /// Frames in all.
    all: usize,
    /// Set to stop the export after the frame being drawn.
    cancel: Arc<AtomicBool>,
    /// What the export says when it ends.
    handle: JoinHandle<Result<String, String>>,
}

/// The *Export animation* controls, the export running and what the last one said.
#[derive(Debug)]
pub struct AnimationExport {
    animation: Animation,
    frames: usize,
    fps: u32,
    size: (u32, u32),
    path: String,
    running: Option<Job>,
    status: Option<Result<String, String>>,
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
        }
    }
}

/// Checks `path` as the GIF to write: a `.gif` name (in any case) where a file can be written.
fn check_gif_path(path: &Path) -> Result<(), String> {
    match ImageFormat::for_path(path) {
        Ok(ImageFormat::Gif) => check_writable(path).map_err(|e| e.to_string()),
        Ok(_) => Err(format!(
            "{}: an animation is written as a GIF; give a name ending in .gif",
            path.display()
        )),
        Err(e) => Err(e.to_string()),
    }
}

impl AnimationExport {
    /// Starts exporting from `state` drawn with `overlay` (in the fitted view) in a background
    /// thread; a bad spec or path is refused at once. Nothing starts while one runs.
    pub fn start(&mut self, state: &ExplorerState, overlay: &Overlay, ctx: &egui::Context) {
        if self.running.is_some() {
            return;
        }
        let spec = AnimationSpec {
            animation: self.animation,
            frames: self.frames,
            fps: self.fps,
            size: self.size,
        };
        let path = PathBuf::from(self.path.trim());
        let checked = spec
            .check()
            .map_err(|e| e.to_string())
            .and_then(|()| check_gif_path(&path));
        if let Err(why) = checked {
            self.status = Some(Err(why));
            return;
        }
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
        let handle = std::thread::spawn(move || {
            let result = export_gif(&state, &overlay, &spec, &path, |frames, _| {
                counter.store(frames, Ordering::Relaxed);
                ctx.request_repaint();
                !stop.load(Ordering::Relaxed)
            });
            ctx.request_repaint();
            // A cancelled export says so in the error's words: nothing was written.
            result
                .map(|()| format!("wrote {}", path.display()))
                .map_err(|e| e.to_string())
        });
        self.status = None;
        self.running = Some(Job {
            done,
            all: spec.frames,
            cancel,
            handle,
        });
    }

    /// Asks the running export to stop after the frame being drawn; nothing is written.
    pub fn cancel(&self) {
        if let Some(job) = &self.running {
            job.cancel.store(true, Ordering::Relaxed);
        }
    }

    /// The fraction done of the export running, if one is; takes the outcome of one that
    /// ended.
    pub fn poll(&mut self) -> Option<f32> {
        let job = self.running.as_ref()?;
        if !job.handle.is_finished() {
            let done = job.done.load(Ordering::Relaxed);
            return Some(done as f32 / job.all.max(1) as f32);
        }
        let job = self.running.take()?;
        self.status = Some(
            job.handle
                .join()
                .unwrap_or_else(|_| Err("the export stopped with an internal error".to_owned())),
        );
        None
    }

    /// The controls: which animation, frames, rate, size and file; *Export animation*, or
    /// while it runs a progress bar and *Cancel*.
    pub fn show(&mut self, ui: &mut Ui, state: &ExplorerState, overlay: &Overlay) {
        ui.heading("Animation for a slide");
        ComboBox::from_label("Animation")
            .selected_text(self.animation.label())
            .show_ui(ui, |ui| {
                for a in Animation::ALL {
                    ui.selectable_value(&mut self.animation, a, a.label());
                }
            });
        self.numbers(ui);
        ui.horizontal(|ui| {
            let label = ui.label("GIF file");
            ui.add(TextEdit::singleline(&mut self.path).desired_width(170.0))
                .labelled_by(label.id);
        });
        match self.poll() {
            Some(fraction) => {
                ui.ctx().request_repaint_after(Duration::from_millis(100));
                ui.horizontal(|ui| {
                    let text = format!("drawing frames… {:.0} %", fraction * 100.0);
                    ui.add(ProgressBar::new(fraction).desired_width(170.0).text(text));
                    if ui.button("Cancel").clicked() {
                        self.cancel();
                    }
                });
            }
            None => {
                if ui
                    .button("Export animation")
                    .on_hover_text("Draws every frame in the background; the window stays live")
                    .clicked()
                {
                    self.start(state, overlay, ui.ctx());
                }
            }
        }
        status(ui, self.status.as_ref());
    }

    /// Frames, rate and size, within their limits.
    fn numbers(&mut self, ui: &mut Ui) {
        ui.horizontal(|ui| {
            let label = ui.label("Frames");
            let (fewest, most) = FRAME_LIMITS;
            ui.add(DragValue::new(&mut self.frames).range(fewest..=most))
                .labelled_by(label.id);
            let label = ui.label("per second");
            let (slowest, fastest) = FPS_LIMITS;
            ui.add(DragValue::new(&mut self.fps).range(slowest..=fastest))
                .labelled_by(label.id);
        });
        ui.horizontal(|ui| {
            let (low, high) = SIZE_LIMITS;
            let (width, height) = &mut self.size;
            for (name, value) in [("GIF width", width), ("height", height)] {
                let label = ui.label(name);
                ui.add(DragValue::new(value).range(low..=high).suffix(" px"))
                    .labelled_by(label.id);
            }
        });
    }
}

/// Writes `scene`, traced, at `path` as PNG or SVG by its extension, at `size`; what happened,
/// in words.
///
/// # Errors
/// The message of a bad path, size or extension, or of a failed write.
pub fn scene_picture(scene: &Scene, size: (u32, u32), path: &str) -> Result<String, String> {
    let path = PathBuf::from(path.trim());
    refraction_render::export_scene(scene, size.0, size.1, &path)
        .map(|()| format!("wrote {}", path.display()))
        .map_err(|e| e.to_string())
}

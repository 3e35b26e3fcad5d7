//! The explorer window (eframe/egui): controls on the left, the interactive diagram in the
//! middle, the kernel's numbers on the right; or, in the Scenes view ([`ScenesView`]), a traced
//! scene whose hit points open here. The state lives in [`ExplorerState`]; drawing
//! comes from [`refraction_diagram`]; nothing here computes refraction.
//!
//! The classroom tools each live in their own module: [`history`] (undo/redo), [`presentation`],
//! and under the diagram (`tools`) check my T, the walk-through and save/open/share.

mod accuracy;
mod canvas;
mod check_panel;
mod controls;
mod files_panel;
pub mod history;
mod paint;
pub mod presentation;
mod readouts;
mod retrace;
mod scenes;
pub mod snippets;
mod tools;
mod typed;
pub mod walkthrough;

use egui::{Panel, ScrollArea, Ui};

use crate::lines::state_file;
use accuracy::AccuracyView;
use controls::Controls;
use history::{History, Snapshot};
use presentation::Presentation;
use refraction_diagram::{ExplorerState, Overlay};
use refraction_scene::Scene;
pub use scenes::ScenesView;
use tools::Tools;

/// The window title.
pub const TITLE: &str = "Refraction explorer";

/// The narrowest window (in points) that keeps the controls panel in presentation mode.
const PRESENTATION_CONTROLS_WIDTH: f32 = 1000.0;

/// Where eframe keeps the last state between runs.
const STORAGE_KEY: &str = "explorer_state";

/// Where eframe keeps the theme and palette between runs.
const LOOK_KEY: &str = "explorer_look";

/// The explorer's views, chosen in the bar at the top of the window.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum View {
    /// One interface at a hit point: drag W, N and μ.
    #[default]
    Interface,
    /// A traced scene: drag the source and the shapes, click a hit to open it.
    Scenes,
    /// What accuracy costs in time: the `bench` measurement, plotted.
    Accuracy,
}

impl View {
    /// Every view, in the order of the bar.
    pub const ALL: [Self; 3] = [Self::Interface, Self::Scenes, Self::Accuracy];

    /// The view's name in the bar (also its accessible name).
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Interface => "One interface",
            Self::Scenes => "Scenes",
            Self::Accuracy => "Accuracy vs time",
        }
    }
}

/// The whole explorer: the state being explored, the view shown, each view's own memory,
/// the undo history, the presentation settings and the classroom tools.
#[derive(Debug)]
pub struct Explorer {
    state: ExplorerState,
    view: View,
    controls: Controls,
    accuracy: AccuracyView,
    history: History<Snapshot>,
    presentation: Presentation,
    tools: Tools,
    scenes: ScenesView,
}

impl Explorer {
    /// An explorer opened on `state`.
    #[must_use]
    pub fn new(state: ExplorerState) -> Self {
        let scenes = ScenesView::default();
        Self {
            history: History::new(Snapshot {
                interface: state.clone(),
                scene: scenes.scene().clone(),
            }),
            state,
            view: View::default(),
            controls: Controls::default(),
            accuracy: AccuracyView::default(),
            scenes,
            presentation: Presentation::default(),
            tools: Tools::default(),
        }
    }

    /// The undo history.
    #[must_use]
    pub fn history(&self) -> &History<Snapshot> {
        &self.history
    }

    /// The presentation settings.
    #[must_use]
    pub fn presentation(&self) -> &Presentation {
        &self.presentation
    }

    /// What is drawn over the diagram now: palette, view, the student's T, the highlights.
    #[must_use]
    pub fn overlay(&self) -> Overlay {
        Overlay {
            palette: self.presentation.palette(),
            pan_zoom: self.presentation.pan_zoom,
            student: self.tools.student(&self.state),
            focus: self.tools.focus(&self.state),
        }
    }

    /// Shows `scene` in the Scenes view, and that view.
    pub fn open_scene(&mut self, scene: Scene) {
        self.scenes = ScenesView::new(scene);
        self.view = View::Scenes;
    }

    /// The Scenes view's state.
    #[must_use]
    pub fn scenes(&self) -> &ScenesView {
        &self.scenes
    }

    /// The state being explored.
    #[must_use]
    pub fn state(&self) -> &ExplorerState {
        &self.state
    }

    /// The view shown.
    #[must_use]
    pub fn view(&self) -> View {
        self.view
    }

    /// Shows the explorer in `ui` (the whole window): the bar of views and tools, then the
    /// view; records a step of history once the user lets go.
    pub fn show(&mut self, ui: &mut Ui) {
        self.presentation.apply(ui.ctx());
        self.tools.walk.animate(ui.ctx(), &mut self.state);
        Panel::top("views").show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                for view in View::ALL {
                    ui.selectable_value(&mut self.view, view, view.label());
                }
                ui.separator();
                if let Some(travel) = history::controls(ui, &self.history)
                    && let Some(snapshot) = self.history.travel(travel)
                {
                    self.state = snapshot.interface;
                    self.scenes.restore(snapshot.scene);
                }
                ui.separator();
                self.presentation.controls(ui);
                ui.separator();
                self.tools.bar(ui);
            });
        });
        match self.view {
            View::Interface => self.show_interface(ui),
            View::Scenes => {
                if let Some(state) = self.scenes.show(ui) {
                    self.state = state;
                    self.view = View::Interface;
                }
            }
            View::Accuracy => {
                egui::CentralPanel::default().show(ui, |ui| {
                    ScrollArea::vertical().show(ui, |ui| self.accuracy.show(ui));
                });
            }
        }
        let settled = !ui.input(|i| i.pointer.any_down()) && !self.tools.walk.animating();
        if settled {
            let (state, scene) = (&self.state, self.scenes.scene());
            self.history.record_unless(
                |present| present.holds(state, scene),
                || Snapshot {
                    interface: state.clone(),
                    scene: scene.clone(),
                },
            );
        }
    }

    /// The single-interface view: controls, diagram, the kernel's numbers, the open tool.
    fn show_interface(&mut self, ui: &mut Ui) {
        // First, so that the tool spans the whole width under the three columns.
        self.tools.panel(ui, &mut self.state);
        let mut overlay = self.overlay();
        // Zoomed for presentation the window is narrow in points: the diagram keeps at least
        // half of it, and on a small projector (1280×720 is 800 points wide zoomed) the
        // controls give way altogether; the handles and keys still edit everything.
        let width = ui.available_width();
        let controls_fit = !self.presentation.on || width >= PRESENTATION_CONTROLS_WIDTH;
        if controls_fit {
            Panel::left("controls")
                .default_size(290.0)
                .max_size(width * 0.25)
                .resizable(true)
                .show(ui, |ui| {
                    ScrollArea::vertical().show(ui, |ui| {
                        self.controls.show(ui, &mut self.state, &overlay);
                    });
                });
        }
        Panel::right("readouts")
            .default_size(440.0)
            .max_size(width * 0.38)
            .resizable(true)
            .show(ui, |ui| {
                // Both ways: narrowed for presentation, the table scrolls instead of clipping.
                ScrollArea::both().show(ui, |ui| {
                    readouts::show(ui, self.state.refraction());
                });
            });
        egui::CentralPanel::no_frame()
            .show(ui, |ui| canvas::show(ui, &mut self.state, &mut overlay));
        self.presentation.pan_zoom = overlay.pan_zoom;
    }
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(STORAGE_KEY, state_file::to_json(&self.state));
        storage.set_string(LOOK_KEY, self.presentation.look());
    }
}

/// Opens the explorer window on `state` (or, when `state` is `None`, on the state of the last
/// run, falling back to the default) and returns when it is closed.
///
/// # Errors
/// The window could not be created (no display, no OpenGL).
pub fn run(state: Option<ExplorerState>) -> Result<(), eframe::Error> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(TITLE)
            .with_inner_size([1200.0, 680.0])
            .with_min_inner_size([900.0, 560.0]),
        multisampling: 0,
        ..eframe::NativeOptions::default()
    };
    eframe::run_native(
        TITLE,
        options,
        Box::new(move |cc| {
            cc.egui_ctx.set_theme(egui::Theme::Light);
            let state = state.unwrap_or_else(|| {
                cc.storage
                    .and_then(|s| s.get_string(STORAGE_KEY))
                    .and_then(|json| state_file::parse(&json).ok())
                    .unwrap_or_default()
            });
            let mut explorer = Explorer::new(state);
            if let Some(look) = cc.storage.and_then(|s| s.get_string(LOOK_KEY)) {
                explorer.presentation.restore_look(&look);
            }
            Ok(Box::new(explorer))
        }),
    )
}

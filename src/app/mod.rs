//! The explorer window (eframe/egui): controls on the left, the interactive diagram in the
//! middle, the kernel's numbers on the right; or, in the Scenes view ([`ScenesView`]), a traced
//! scene whose hit points open here. The state lives in [`ExplorerState`]; drawing
//! comes from [`crate::diagram`]; nothing here computes refraction.

mod canvas;
mod controls;
mod paint;
mod readouts;
mod scenes;
mod typed;

use egui::{Panel, ScrollArea, Ui};

use crate::diagram::ExplorerState;
use crate::scene::Scene;
use crate::state_file;
use controls::Controls;
pub use scenes::ScenesView;

/// The window title.
pub const TITLE: &str = "Refraction explorer";

/// Where eframe keeps the last state between runs.
const STORAGE_KEY: &str = "explorer_state";

/// The explorer's views, chosen in the bar at the top of the window.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum View {
    /// One interface at a hit point: drag W, N and μ.
    #[default]
    Interface,
    /// A traced scene: drag the source and the shapes, click a hit to open it.
    Scenes,
}

impl View {
    /// Every view, in the order of the bar.
    pub const ALL: [Self; 2] = [Self::Interface, Self::Scenes];

    /// The view's name in the bar (also its accessible name).
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Interface => "One interface",
            Self::Scenes => "Scenes",
        }
    }
}

/// The whole explorer: the state being explored, the view shown and the controls' own memory.
#[derive(Clone, Debug, PartialEq)]
pub struct Explorer {
    state: ExplorerState,
    view: View,
    controls: Controls,
    scenes: ScenesView,
}

impl Explorer {
    /// An explorer opened on `state`.
    #[must_use]
    pub fn new(state: ExplorerState) -> Self {
        Self {
            state,
            view: View::default(),
            controls: Controls::default(),
            scenes: ScenesView::default(),
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

    /// Shows the explorer in `ui` (the whole window): the bar of views, then the view.
    pub fn show(&mut self, ui: &mut Ui) {
        Panel::top("views").show(ui, |ui| {
            ui.horizontal(|ui| {
                for view in View::ALL {
                    ui.selectable_value(&mut self.view, view, view.label());
                }
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
        }
    }

    /// The single-interface view: controls, diagram, the kernel's numbers.
    fn show_interface(&mut self, ui: &mut Ui) {
        Panel::left("controls")
            .default_size(290.0)
            .resizable(true)
            .show(ui, |ui| {
                ScrollArea::vertical().show(ui, |ui| {
                    self.controls.show(ui, &mut self.state);
                });
            });
        Panel::right("readouts")
            .default_size(440.0)
            .resizable(true)
            .show(ui, |ui| {
                ScrollArea::vertical().show(ui, |ui| {
                    readouts::show(ui, self.state.refraction());
                });
            });
        egui::CentralPanel::no_frame().show(ui, |ui| canvas::show(ui, &mut self.state));
    }
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(STORAGE_KEY, state_file::to_json(&self.state));
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
            Ok(Box::new(Explorer::new(state)))
        }),
    )
}

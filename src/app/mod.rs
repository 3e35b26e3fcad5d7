//! The explorer window (eframe/egui): controls on the left, the interactive diagram in the
//! middle, the kernel's numbers on the right; or, in the Scenes view ([`ScenesView`]), a traced
//! scene whose hit points open here. The state lives in [`ExplorerState`]; drawing
//! comes from [`refraction_diagram`]; nothing here computes refraction.
//!
//! The classroom tools each live in their own module: `history` (undo/redo), `presentation`,
//! and under the diagram (`tools`) check my T, the walk-through and save/open/share. The
//! modules are private: the commands, the web build and the tests reach the window through
//! [`Explorer`], [`Launch`], [`View`], [`ScenesView`], [`handout`], [`Status`] and
//! `browser::start`.

mod accuracy;
mod announce;
mod background;
#[cfg(target_arch = "wasm32")]
pub mod browser;
mod canvas;
mod check_panel;
mod controls;
mod deck;
mod effects_menu;
mod export;
mod file_dialog;
mod files_panel;
mod fonts;
mod fresnel_panel;
mod history;
mod link;
mod paint;
mod panels;
mod presentation;
mod readouts;
mod retrace;
mod scene_files;
mod scenes;
mod status;
mod steps;
mod student;
mod tools;
mod typed;
mod walkthrough;
mod widgets;

pub use deck::handout;
pub use fonts::install as install_fonts;
pub use presentation::ZOOM as PRESENTATION_ZOOM;

use egui::{Panel, RichText, ScrollArea, Ui};
use refraction_tools::{parse_state, state_to_json};

use accuracy::AccuracyView;
use controls::Controls;
use effects_menu::EffectsMenu;
use export::AnimationExport;
use history::{History, Snapshot};
use panels::{CONTROLS, NUMBERS, Panels};
use presentation::Presentation;
use refraction_diagram::{Overlay, palette::Theme};
use refraction_i18n::{Locale, t};
use refraction_model::ExplorerState;
use refraction_scene::Scene;
pub use scenes::ScenesView;
pub use status::Status;
use tools::Tools;

/// Where eframe keeps the last state between runs.
const STORAGE_KEY: &str = "explorer_state";

/// Where eframe keeps the theme and palette between runs.
const LOOK_KEY: &str = "explorer_look";

/// Where eframe keeps the view shown and the Scenes view's scene between runs.
const VIEW_KEY: &str = "explorer_view";

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
    pub fn label(self) -> String {
        match self {
            Self::Interface => t!("view-interface"),
            Self::Scenes => t!("view-scenes"),
            Self::Accuracy => t!("view-accuracy"),
        }
    }

    /// The view's name on the command line (`--view`) and in the saved settings.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Interface => "one",
            Self::Scenes => "scenes",
            Self::Accuracy => "accuracy",
        }
    }

    /// The view named `name` ([`View::name`]).
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|v| v.name() == name)
    }
}

/// How the window opens: what the command line asked for. What it leaves out comes from the
/// last run (the state, the view and its scene, the theme) or the defaults.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Launch {
    /// The single-interface problem to open on (`--state`); it also shows One interface
    /// unless `view` says otherwise.
    pub state: Option<ExplorerState>,
    /// Start in presentation mode (`--present`).
    pub present: bool,
    /// The view to show (`--view`).
    pub view: Option<View>,
    /// The theme (`--theme`).
    pub theme: Option<Theme>,
    /// The language (`--lang`), for this run: over the one chosen last time and the system's.
    pub language: Option<Locale>,
    /// The system's language, which the window speaks unless one is chosen.
    pub system_language: Option<Locale>,
    /// The lesson deck to open on, at its first step (`--lesson`): a built-in deck's name
    /// (read in the window's language) or a deck file's path, checked by the command line
    /// before the window opens.
    pub lesson: Option<String>,
    /// The web build's address for links (`--web-base`), over the one set last time.
    pub web_base: Option<String>,
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
    panels: Panels,
    effects: EffectsMenu,
    animation_export: AnimationExport,
    /// The lesson deck and the step shown.
    lesson: deck::LessonDeck,
    /// What the last undo or redo did, in words.
    travelled: Option<String>,
    /// The language given on the command line, until one is chosen in the bar.
    command_line_language: Option<Locale>,
    /// The system's language, spoken unless one is chosen.
    system_language: Option<Locale>,
    /// The QR code shown, and what a link that could not be opened said.
    sharing: link::Sharing,
    /// The window's title last given to the window ([`Explorer::title`]).
    titled: String,
    /// Whether the student's view is asked for or turned down.
    student: student::StudentView,
    /// Whether the last frame showed the student's view (its diagram has no index scale and
    /// handles for a finger: [`Explorer::overlay`]).
    student_shown: bool,
}

impl Explorer {
    /// An explorer opened on `state`, speaking this thread's language
    /// ([`refraction_i18n::locale`]) until another is chosen.
    #[must_use]
    pub fn new(state: ExplorerState) -> Self {
        let scenes = ScenesView::default();
        Self {
            history: History::new(Snapshot::of(&state, scenes.scene())),
            state,
            view: View::default(),
            controls: Controls::default(),
            accuracy: AccuracyView::default(),
            scenes,
            presentation: Presentation::default(),
            tools: Tools::default(),
            panels: Panels::default(),
            effects: EffectsMenu::default(),
            animation_export: AnimationExport::default(),
            lesson: deck::LessonDeck::default(),
            travelled: None,
            command_line_language: None,
            system_language: Some(refraction_i18n::locale()),
            sharing: link::Sharing::default(),
            titled: crate::TITLE.to_owned(),
            student: student::StudentView::default(),
            student_shown: false,
        }
    }

    /// An explorer as the command line asked for it, over what the last run left (`saved`
    /// reads a value eframe kept, by key).
    #[must_use]
    pub fn launched(launch: Launch, saved: impl Fn(&str) -> Option<String>) -> Self {
        let from_state_file = launch.state.is_some();
        // The state kept from last time, unless a state file was given: one that cannot be
        // read is said (in the window's language, once it is set) rather than dropped.
        let (restored, unreadable) = match saved(STORAGE_KEY).filter(|_| !from_state_file) {
            None => (None, None),
            Some(json) => match parse_state(&json) {
                Ok(state) => (Some(state), None),
                Err(e) => (None, Some(e.to_string())),
            },
        };
        let mut explorer = Self::new(launch.state.or(restored).unwrap_or_default());
        if let Some(look) = saved(LOOK_KEY) {
            explorer.presentation.restore_look(&look);
        }
        if let Some(view) = saved(VIEW_KEY) {
            explorer.restore_view(&view);
        }
        // The command line's address is checked already; the one kept may not be (it was
        // typed, or kept by an older version): it is used only if it can start a link.
        let stored_base = launch.web_base.is_none().then(|| saved(link::WEB_BASE_KEY));
        let refused_base = match (launch.web_base, stored_base.flatten()) {
            (Some(base), _) => {
                explorer.set_web_base(&base);
                None
            }
            (None, Some(base)) if !base.trim().is_empty() => {
                refraction_tools::link::web_base(&base)
                    .map(|base| explorer.set_web_base(&base))
                    .err()
            }
            (None, _) => None,
        };
        if from_state_file {
            explorer.view = View::Interface;
        }
        if let Some(view) = launch.view {
            explorer.view = view;
        }
        if let Some(theme) = launch.theme {
            explorer.presentation.theme = theme;
        }
        explorer.presentation.on = launch.present;
        explorer.command_line_language = launch.language;
        explorer.system_language = launch.system_language;
        refraction_i18n::set_locale(explorer.language());
        explorer.sharing.notice = link::storage_notice(unreadable.as_deref(), refused_base);
        if let Some(name) = launch.lesson {
            explorer.open_lesson(&name);
        }
        explorer
    }

    /// The language the window speaks: the command line's (`--lang`) until one is chosen in
    /// the bar, then the chosen one (kept between runs), else the system's, else English.
    #[must_use]
    pub fn language(&self) -> Locale {
        self.command_line_language
            .unwrap_or_else(|| self.presentation.locale(self.system_language))
    }

    /// The view shown and the Scenes view's scene as edited, as JSON text for the next run.
    #[must_use]
    pub fn saved_view(&self) -> String {
        let scene = self.scenes.scene();
        serde_json::json!({
            "view": self.view.name(),
            "scene_name": scene.name(),
            "scene": scene.to_toml().ok(),
        })
        .to_string()
    }

    /// Takes back what [`Explorer::saved_view`] wrote; what cannot be read is left as it is.
    pub fn restore_view(&mut self, text: &str) {
        let Ok(saved) = serde_json::from_str::<serde_json::Value>(text) else {
            return;
        };
        if let Some(view) = saved["view"].as_str().and_then(View::named) {
            self.view = view;
        }
        let name = saved["scene_name"].as_str().unwrap_or_default();
        if let Some(Ok(scene)) = saved["scene"]
            .as_str()
            .map(|toml| Scene::from_toml(toml, &t!("view-last-run-scene"), name))
        {
            // A built-in scene edited last time keeps its file's version for *Reset*.
            let base = Scene::embedded(name).unwrap_or_else(|_| scene.clone());
            self.scenes = ScenesView::new(base);
            self.scenes.restore(scene);
            self.history = History::new(Snapshot::of(&self.state, self.scenes.scene()));
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

    /// The presentation settings, to change them as the bar's controls do (they take effect
    /// on the next frame).
    pub fn presentation_mut(&mut self) -> &mut Presentation {
        &mut self.presentation
    }

    /// Explores `state` from now on, as opening a state file does; the undo history records
    /// the change once the frame ends.
    pub fn set_state(&mut self, state: ExplorerState) {
        self.state = state;
    }

    /// What is drawn over the diagram now: palette, view, the student's T, the highlights; in
    /// the student's view, no index scale and handles for a finger.
    #[must_use]
    pub fn overlay(&self) -> Overlay {
        Overlay {
            palette: self.presentation.palette(),
            pan_zoom: self.presentation.pan_zoom,
            student: self.tools.student(&self.state),
            focus: self.tools.focus(&self.state),
            intensities: self.effects.intensities(),
            waves: self.effects.waves(),
            hide_answer: self.lesson.hides_answer(),
            index_scale: !self.diagram_only() && !self.student_shown,
            simple: self.presentation.simple,
            paper: false,
            touch: self.student_shown,
        }
    }

    /// Whether the walk-through's *Animate μ to 1* is running.
    #[must_use]
    pub fn animating(&self) -> bool {
        self.tools.walk.animating()
    }

    /// Whether presentation shows the diagram alone (key D).
    #[must_use]
    pub fn diagram_only(&self) -> bool {
        self.presentation.on && self.presentation.diagram_only
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
        refraction_i18n::set_locale(self.language());
        self.presentation.apply(ui.ctx());
        self.presentation.diagram_only_key(ui.ctx());
        paint::share_palette(ui.ctx(), self.presentation.palette());
        self.tools.walk.animate(ui.ctx(), &mut self.state);
        self.effects.animate(ui.ctx());
        if ui.input(|i| !i.raw.dropped_files.is_empty()) {
            self.tools.take_dropped(ui.ctx());
            self.view = View::Interface;
        }
        self.sharing(ui);
        let title = self.title();
        if title != self.titled {
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.titled = title;
        }
        self.student_shown = self.student.shown(ui.ctx(), self.presentation.on);
        if self.student_shown {
            self.show_student(ui);
        } else {
            self.show_teacher(ui);
        }
        announce::follow(ui, self);
        let settled = !ui.input(|i| i.pointer.any_down()) && !self.tools.walk.animating();
        if settled {
            let (state, scene) = (&self.state, self.scenes.scene());
            self.history.record_unless(
                |present| present.same_as(state, scene),
                |present| Snapshot::after(present, state, scene),
            );
        }
    }

    /// Whether the window shows the student's view now (a small screen, or a link that
    /// asked for it; never in presentation).
    #[must_use]
    pub fn shows_student_view(&self, ctx: &egui::Context) -> bool {
        self.student.shown(ctx, self.presentation.on)
    }

    /// The teacher's window: the bar, the deck's strip and tool, then the view.
    fn show_teacher(&mut self, ui: &mut Ui) {
        Panel::top("views").show(ui, |ui| self.bar(ui));
        if !self.diagram_only() {
            self.deck_frame(ui);
            self.deck_panel(ui);
        }
        let step_shown = self.lesson.current().is_some();
        self.scenes
            .for_lesson(step_shown, self.lesson.hides_answer());
        match self.view {
            View::Interface => self.show_interface(ui),
            View::Scenes => {
                let palette = self.presentation.palette();
                if let Some(state) = self.scenes.show(ui, &palette, self.presentation.on) {
                    self.state = state;
                    self.view = View::Interface;
                }
            }
            View::Accuracy => {
                egui::CentralPanel::default().show(ui, |ui| {
                    let palette = self.presentation.palette();
                    ScrollArea::vertical().show(ui, |ui| self.accuracy.show(ui, &palette));
                });
            }
        }
    }

    /// The bar at the top: views, undo and redo (and what the last one did), presentation,
    /// the tools.
    fn bar(&mut self, ui: &mut Ui) {
        ui.horizontal_wrapped(|ui| {
            self.view_switches(ui);
            ui.separator();
            if let Some(travel) = history::controls(ui, &self.history, self.presentation.on) {
                self.travel(travel);
            }
            ui.separator();
            let chosen = self.presentation.language;
            self.presentation.controls(ui, self.language());
            if self.presentation.language != chosen {
                self.command_line_language = None;
            }
            ui.separator();
            self.tools
                .bar(ui, self.presentation.on, self.lesson.deck.is_some());
            if self.view == View::Interface {
                ui.separator();
                self.effects.menu(ui, self.presentation.on);
                if self.presentation.on {
                    self.panels.bar_switches(ui);
                }
            }
            if !self.presentation.on {
                self.student.switch(ui);
            }
            // What the last undo did, in what is left of the bar's last row, cut with "…"
            // (the whole on hover): it never grows the bar by a row.
            if let Some(done) = self
                .travelled
                .as_ref()
                .filter(|_| ui.available_size_before_wrap().x > 160.0)
            {
                ui.separator();
                ui.add(egui::Label::new(RichText::new(done).weak()).truncate())
                    .on_hover_text(done);
            }
        });
    }

    /// The views: a switch each at the desk; in presentation, where the bar keeps one row, a
    /// menu showing the view's name.
    fn view_switches(&mut self, ui: &mut Ui) {
        if !self.presentation.on {
            for view in View::ALL {
                ui.selectable_value(&mut self.view, view, view.label());
            }
            return;
        }
        let name = t!("view-menu");
        let menu = egui::ComboBox::from_id_salt("view")
            .selected_text(self.view.label())
            .show_ui(ui, |ui| {
                for view in View::ALL {
                    ui.selectable_value(&mut self.view, view, view.label());
                }
            })
            .response;
        menu.widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, &name));
        menu.on_hover_text(name);
    }

    /// Undoes or redoes one step and says what it changed; a step that changed the view not
    /// shown switches to it, so that the class sees what was undone.
    fn travel(&mut self, travel: history::Travel) {
        let before = Snapshot::after(self.history.present(), &self.state, self.scenes.scene());
        let Some(snapshot) = self.history.travel(travel) else {
            return;
        };
        let change = history::describe(travel, &before, &snapshot);
        let other = match (change.in_scene, change.in_interface, self.view) {
            (true, false, View::Interface | View::Accuracy) => Some(View::Scenes),
            (false, true, View::Scenes | View::Accuracy) => Some(View::Interface),
            _ => None,
        };
        self.travelled = Some(match other {
            Some(view) => {
                self.view = view;
                t!("travel-in-view", change = change.words, view = view.label())
            }
            None => change.words,
        });
        self.state = snapshot.interface;
        self.scenes.restore((*snapshot.scene).clone());
    }

    /// The single-interface view: controls, diagram, the kernel's numbers, the open tool.
    fn show_interface(&mut self, ui: &mut Ui) {
        let presenting = self.presentation.on;
        if self.diagram_only() {
            let mut overlay = self.overlay();
            egui::CentralPanel::no_frame().show(ui, |ui| {
                let under = canvas::Under {
                    steps: false,
                    hint: false,
                };
                canvas::show(ui, &mut self.state, &mut overlay, under);
            });
            self.presentation.pan_zoom = overlay.pan_zoom;
            return;
        }
        self.panels.keys(ui, presenting);
        if presenting && self.tools.open.is_some() {
            let opened = self.tools.just_opened().is_some();
            if self.panels.make_room(opened) {
                self.tools.open = None;
            }
        }
        // First, so that the tool has the window's full height beside (or width under) the
        // panels.
        let palette = self.presentation.palette();
        let hidden = self.lesson.hides_answer();
        self.tools
            .panel(ui, &mut self.state, (presenting, hidden), &palette);
        match self.tools.files.take_opened() {
            Some(files_panel::Opened::Scene(scene)) => self.open_scene(*scene),
            Some(files_panel::Opened::Deck(deck)) => self.open_deck(*deck),
            None => {}
        }
        let mut overlay = self.overlay();
        let (state, controls) = (&mut self.state, &mut self.controls);
        let animation_export = &mut self.animation_export;
        self.panels.show(ui, &CONTROLS, presenting, |ui| {
            controls.show(ui, state, &overlay);
            ui.separator();
            animation_export.show(ui, state, &overlay);
        });
        self.panels.show(ui, &NUMBERS, presenting, |ui| {
            // The kernel's numbers are the answer a step's question asks for: hidden with it.
            if overlay.hide_answer {
                ui.label(t!("deck-answer-hidden"));
            } else {
                readouts::show(ui, state.refraction(), &overlay.palette);
            }
        });
        if let Some(lesson) = controls.started.take() {
            self.effects.start(lesson);
            overlay.intensities = self.effects.intensities();
        }
        // No margins (the diagram reaches the panels), but the panel's fill under the key hint.
        let frame = egui::Frame::NONE.fill(ui.visuals().panel_fill);
        // The step buttons give way to a tool or a side panel on a projector (the controls
        // panel has its own way to each value).
        let side = self.panels.presenting;
        let crowded = self.tools.open.is_some() || side.controls || side.numbers;
        let under = canvas::Under {
            steps: !presenting || !crowded,
            hint: !presenting,
        };
        egui::CentralPanel::no_frame()
            .frame(frame)
            .show(ui, |ui| canvas::show(ui, state, &mut overlay, under));
        self.presentation.pan_zoom = overlay.pan_zoom;
    }
}

impl eframe::App for Explorer {
    fn ui(&mut self, ui: &mut Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(STORAGE_KEY, state_to_json(&self.state));
        storage.set_string(LOOK_KEY, self.presentation.look());
        storage.set_string(VIEW_KEY, self.saved_view());
        storage.set_string(link::WEB_BASE_KEY, self.web_base().to_owned());
    }
}

/// Opens the explorer window as `launch` asks (what it leaves out comes from the last run)
/// and returns when it is closed.
///
/// # Errors
/// The window could not be created (no display, no OpenGL).
#[cfg(not(target_arch = "wasm32"))]
pub fn run(launch: Launch) -> Result<(), eframe::Error> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title(crate::TITLE)
            .with_inner_size([1200.0, 680.0])
            .with_min_inner_size([900.0, 560.0])
            .with_fullscreen(launch.present),
        multisampling: 0,
        ..eframe::NativeOptions::default()
    };
    eframe::run_native(
        crate::TITLE,
        options,
        Box::new(move |cc| {
            install_fonts(&cc.egui_ctx);
            cc.egui_ctx.set_theme(egui::Theme::Light);
            let saved = |key: &str| {
                let s = cc.storage?;
                s.get_string(key)
            };
            Ok(Box::new(Explorer::launched(launch, saved)))
        }),
    )
}

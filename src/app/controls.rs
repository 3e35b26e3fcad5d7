//! The left panel: convention, flipping N, the two indices (slider, typed value, preset), typed
//! 3D W and N, the critical-angle snap and the picture export (PNG or SVG).

use refraction_i18n::t;
use std::path::{Path, PathBuf};

use egui::{ComboBox, DragValue, Slider, SliderClamping, Ui};

use super::file_dialog::{self, Choice, FileDialog, Purpose, Target};
use super::status::{self, Look, Status};
use super::typed::{TypedError, TypedField, format_vector, parse_number, parse_vector, short};
use refraction_diagram::{Overlay, PanZoom};
use refraction_kernel::{Convention, InputError};
use refraction_model::{AngleError, ExplorerState, HandleId, Lesson};
use refraction_model::{INDEX_RANGE, MATERIALS, material_of};

/// What the controls keep between frames.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Controls {
    /// The lesson last started here, which *Reset* goes back to (none yet when the window
    /// opened on a state file or where it was last closed: then the first lesson).
    lesson: Option<Lesson>,
    /// A lesson started this frame, for the window to turn on what it shows with it.
    pub started: Option<Lesson>,
    theta_i: TypedField,
    mu_i: TypedField,
    mu_t: TypedField,
    w: TypedField,
    n: TypedField,
    export_size: (u32, u32),
    export_path: String,
    export_status: Option<Status>,
    /// The export's save dialog, while it is up.
    export_dialog: Option<FileDialog>,
    /// An image the user is asked about replacing.
    export_replace: Option<PathBuf>,
}

impl Default for Controls {
    fn default() -> Self {
        Self {
            lesson: None,
            started: None,
            theta_i: TypedField::default(),
            mu_i: TypedField::default(),
            mu_t: TypedField::default(),
            w: TypedField::default(),
            n: TypedField::default(),
            export_size: refraction_render::DEFAULT_SIZE,
            // Empty: exports are numbered diagram-001.png, diagram-002.png, …
            export_path: String::new(),
            export_status: None,
            export_dialog: None,
            export_replace: None,
        }
    }
}

/// Why a value typed, dragged or picked in the controls was not applied, worded when shown.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
enum NotApplied {
    /// The text is not a number, or not a vector.
    #[error(transparent)]
    Typed(#[from] TypedError),
    /// The kernel refuses the index, named by its symbol.
    #[error("{symbol}: {error}")]
    Index {
        /// `μi` or `μt`.
        symbol: &'static str,
        /// Why.
        error: InputError,
    },
    /// The angle of incidence cannot be shown.
    #[error(transparent)]
    Angle(#[from] AngleError),
    /// The kernel refuses W and N (a zero vector, a component that is not finite).
    #[error(transparent)]
    Vectors(#[from] InputError),
}

/// Sets the index of `handle`, named `symbol` in the error if the kernel refuses it.
fn set_index(
    state: &mut ExplorerState,
    handle: HandleId,
    symbol: &'static str,
    index: f64,
) -> Result<(), NotApplied> {
    state
        .set_index(handle, index)
        .map_err(|error| NotApplied::Index { symbol, error })
}

/// The slider, typed value and preset of one index.
fn index_controls(
    ui: &mut Ui,
    state: &mut ExplorerState,
    handle: HandleId,
    field: &mut TypedField,
) {
    let symbol = if handle == HandleId::MuI {
        "μi"
    } else {
        "μt"
    };
    let mut index = state.index(handle);
    let (low, high) = INDEX_RANGE;
    // Never clamping, so that the slider does not round a typed 1.000293 to its own decimals
    // or pull a typed 3.2 into its range.
    let slider = Slider::new(&mut index, low..=high)
        .text(symbol)
        .clamping(SliderClamping::Never)
        // Its number box in the language's way, read with a comma or a point.
        .custom_formatter(|value, decimals| {
            refraction_i18n::decimal(&egui::emath::format_with_decimals_in_range(value, decimals))
        })
        .custom_parser(refraction_i18n::read_number);
    // The slider's number box takes any value typed into it: a refused one shows its error in
    // the field below, as a refused typed value does.
    if ui.add(slider).changed() {
        field.show_outcome(set_index(state, handle, symbol, index));
    }
    let typed = field.show(
        ui,
        &t!("controls-index-value", symbol = symbol),
        short(state.index(handle)),
        90.0,
    );
    if let Some(text) = typed {
        let outcome = parse_number(&text, symbol)
            .map_err(NotApplied::from)
            .and_then(|value| set_index(state, handle, symbol, value));
        field.show_outcome(outcome);
    }
    let current = material_of(state.index(handle));
    let shown = current.map_or_else(|| t!("diagram-material-custom"), |m| m.label());
    // The label on its own row: beside the menu, a narrow panel would break its words.
    let name = t!("controls-material", symbol = symbol);
    ui.label(&name);
    let menu = ComboBox::from_id_salt(("material", symbol))
        .selected_text(shown)
        .show_ui(ui, |ui| {
            for m in MATERIALS {
                let index = refraction_i18n::decimal(&m.index.to_string());
                let text = format!("{} ({index})", m.label());
                let chosen = current.is_some_and(|c| c.name == m.name);
                if ui.selectable_label(chosen, text).clicked() {
                    // A preset is refused only beside an extreme typed other index.
                    field.show_outcome(set_index(state, handle, symbol, m.index));
                }
            }
            ui.label(t!("controls-custom-hint"));
        })
        .response;
    menu.widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, &name));
}

impl Controls {
    /// What the lesson box shows for `state`: the lesson whose start it is, else the lesson
    /// started here as changed, else the user's own case (a state file's, say), never a lesson
    /// the diagram does not show.
    fn lesson_shown(&self, state: &ExplorerState) -> String {
        if let Some(lesson) = Lesson::ALL.into_iter().find(|l| l.state() == *state) {
            lesson.label()
        } else if let Some(lesson) = self.lesson {
            t!("controls-lesson-changed", lesson = lesson.label())
        } else {
            t!("controls-lesson-own")
        }
    }

    /// The lesson presets, *Reset*, and θi typed in degrees.
    fn lesson(&mut self, ui: &mut Ui, state: &mut ExplorerState) {
        ui.heading(t!("controls-lesson"));
        // The label on its own row: beside the menu, a narrow panel would break its words.
        let name = t!("controls-lesson-preset");
        ui.label(&name);
        ui.horizontal_wrapped(|ui| {
            let menu = ComboBox::from_id_salt("lesson_preset")
                .selected_text(self.lesson_shown(state))
                .truncate()
                .width(ui.available_width().min(220.0) - 90.0)
                .show_ui(ui, |ui| {
                    for lesson in Lesson::ALL {
                        if ui
                            .selectable_label(self.lesson == Some(lesson), lesson.label())
                            .clicked()
                        {
                            self.lesson = Some(lesson);
                            self.started = Some(lesson);
                            *state = lesson.state();
                        }
                    }
                })
                .response;
            menu.widget_info(|| egui::WidgetInfo::labeled(egui::Role::ComboBox, true, &name));
            if ui
                .button(t!("controls-reset"))
                .on_hover_text(t!("controls-reset-hover"))
                .clicked()
            {
                *state = self.lesson.unwrap_or(Lesson::AirToGlass).state();
            }
        });
        let current = short((state.incidence_degrees() * 1e4).round() / 1e4);
        if let Some(text) = self
            .theta_i
            .show(ui, &t!("controls-incidence"), current, 90.0)
        {
            let outcome = parse_number(&text, "θi")
                .map_err(NotApplied::from)
                .and_then(|degrees| Ok(state.set_incidence_degrees(degrees)?));
            self.theta_i.show_outcome(outcome);
        }
    }

    /// Shows the controls, editing `state`; the PNG export draws `overlay` too.
    pub(super) fn show(&mut self, ui: &mut Ui, state: &mut ExplorerState, overlay: &Overlay) {
        self.lesson(ui, state);
        ui.separator();
        ui.heading(t!("controls-convention"));
        let mut convention = state.convention();
        ui.radio_value(
            &mut convention,
            Convention::TowardOrigin,
            t!("controls-convention-toward-origin"),
        );
        ui.radio_value(
            &mut convention,
            Convention::AlongRay,
            t!("controls-convention-along-ray"),
        );
        state.set_convention(convention);
        ui.horizontal(|ui| {
            if ui
                .button(t!("controls-flip-normal"))
                .on_hover_text(t!("controls-flip-normal-hover"))
                .clicked()
            {
                state.flip_normal();
            }
            let snap = ui.add_enabled(
                state.critical_angle().is_some(),
                egui::Button::new(t!("controls-snap")),
            );
            if snap
                .on_hover_text(t!("controls-snap-hover"))
                .on_disabled_hover_text(t!("controls-snap-disabled"))
                .clicked()
            {
                state.snap_to_critical_angle();
            }
        });
        ui.separator();
        ui.heading(t!("controls-indices"));
        index_controls(ui, state, HandleId::MuI, &mut self.mu_i);
        index_controls(ui, state, HandleId::MuT, &mut self.mu_t);
        ui.separator();
        ui.heading(t!("controls-typed-vectors"));
        ui.label(t!("controls-typed-vectors-hint"));
        if let Some(text) = self.w.show(ui, "W =", format_vector(state.w()), 170.0) {
            let outcome = parse_vector(&text, "W")
                .map_err(NotApplied::from)
                .and_then(|w| Ok(state.set_vectors(w, state.n())?));
            self.w.show_outcome(outcome);
        }
        if let Some(text) = self.n.show(ui, "N =", format_vector(state.n()), 170.0) {
            let outcome = parse_vector(&text, "N")
                .map_err(NotApplied::from)
                .and_then(|n| Ok(state.set_vectors(state.w(), n)?));
            self.n.show_outcome(outcome);
        }
        ui.separator();
        self.export(ui, state, overlay);
    }

    /// The picture export, PNG or SVG by the file's extension: what the screen shows (palette,
    /// student's T, highlights, the Effects menu's switches) in the fitted view, since the screen's
    /// pan is in its own pixels.
    fn export(&mut self, ui: &mut Ui, state: &ExplorerState, overlay: &Overlay) {
        ui.heading(t!("controls-export-heading"));
        let (low, high) = refraction_render::SIZE_LIMITS;
        ui.horizontal(|ui| {
            let (width, height) = &mut self.export_size;
            let label = ui.label(t!("controls-export-size"));
            ui.add(DragValue::new(width).range(low..=high).suffix(" px"))
                .labelled_by(label.id);
            ui.label("×");
            ui.add(DragValue::new(height).range(low..=high).suffix(" px"))
                .labelled_by(label.id);
        });
        ui.horizontal(|ui| {
            let label = ui.label(t!("controls-export-file"));
            let field = egui::TextEdit::singleline(&mut self.export_path)
                .hint_text(t!("controls-export-file-hint"))
                .desired_width(170.0);
            ui.add(field).labelled_by(label.id);
            if ui.button(t!("controls-browse")).clicked() {
                let start = self.export_path.clone();
                self.export_dialog = Some(FileDialog::new(Purpose::Save, &["png", "svg"], &start));
            }
        });
        if ui.button(t!("controls-export")).clicked() {
            // No name, or a folder: the next free number there.
            let path = file_dialog::or_numbered(&self.export_path, "diagram", "png");
            self.export_to(path, state, overlay);
        }
        match self.export_dialog.as_mut().map(|d| d.show(ui)) {
            Some(Choice::Chosen(path)) => {
                self.export_dialog = None;
                self.export_path = path.display().to_string();
                self.export_to(path, state, overlay);
            }
            Some(Choice::Cancelled) => self.export_dialog = None,
            Some(Choice::Pending) | None => {}
        }
        let replacing = &mut self.export_replace;
        if let Some(path) = file_dialog::answer_replace(ui, replacing, &mut self.export_status) {
            self.write_image(&path, state, overlay);
        }
        status::show(ui, self.export_status.as_ref(), Look::Plain);
    }

    /// Exports to `path` at once when it is new, after a question when it holds an image of
    /// its kind, never over a file of another kind (a saved state).
    fn export_to(&mut self, path: PathBuf, state: &ExplorerState, overlay: &Overlay) {
        match file_dialog::picture_target(&path) {
            Ok(Target::New) => self.write_image(&path, state, overlay),
            Ok(Target::Replaces) => self.export_replace = Some(path),
            Err(e) => self.export_status = Some(Status::Refused(e.to_string())),
        }
    }

    fn write_image(&mut self, path: &Path, state: &ExplorerState, overlay: &Overlay) {
        let overlay = Overlay {
            pan_zoom: PanZoom::default(),
            ..overlay.clone()
        };
        let written = refraction_render::write(
            refraction_render::Picture::Interface {
                state,
                overlay: &overlay,
            },
            self.export_size,
            path,
        );
        self.export_status = Some(match written {
            Ok(()) => Status::Done(t!("controls-exported", path = path.display().to_string())),
            Err(e) => Status::Refused(e.to_string()),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lesson_box_names_only_the_lesson_the_diagram_shows() {
        let mut controls = Controls::default();
        let start = Lesson::AirToGlass.state();
        assert_eq!(controls.lesson_shown(&start), Lesson::AirToGlass.label());
        let mut own = start.clone();
        own.set_incidence_degrees(12.5).unwrap();
        assert_eq!(controls.lesson_shown(&own), t!("controls-lesson-own"));
        controls.lesson = Some(Lesson::AirToGlass);
        assert_eq!(
            controls.lesson_shown(&own),
            t!(
                "controls-lesson-changed",
                lesson = Lesson::AirToGlass.label()
            )
        );
        let brewster = Lesson::ALL[Lesson::ALL.len() - 1];
        assert_eq!(controls.lesson_shown(&brewster.state()), brewster.label());
    }
}

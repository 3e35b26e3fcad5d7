//! The Scenes view's files: the scene file typed or chosen in the file dialog, opened and
//! saved (after a question before a scene file is replaced, never over a file of another
//! kind), and the picture export (numbered `scene-001.svg`, … when no name is given).

use std::path::{Path, PathBuf};

use egui::{Role, TextEdit, Ui, WidgetInfo};
use refraction_i18n::t;

use super::export;
use super::file_dialog::{self, FileDialog, Kind, Purpose, Target, picture_target};
use super::status::{self, Look, Status};
use super::widgets::{OPEN_ICON, SAVE_AS_ICON, icon_button};
use refraction_files::write_atomically;
use refraction_scene::Scene;

/// The scene file offered first.
pub(super) const DEFAULT_SCENE_PATH: &str = "scene.toml";

/// The picture file offered first: SVG, so that a slide can edit the labels.
pub(super) const DEFAULT_PICTURE_PATH: &str = "scene.svg";

/// The icon the picture export's menu shows in a compact row.
const PICTURE_ICON: &str = "🖼";

/// Below this width (in points) the row shows the dialog's buttons and the export menu as
/// icons.
const COMPACT_BELOW: f32 = 1000.0;

/// The extensions the dialog lists for a scene file.
const SCENE_FILES: &[&str] = &["toml"];

/// The extensions the dialog lists for a picture.
const PICTURE_FILES: &[&str] = &["png", "svg"];

/// What a file chosen in the dialog, or a file about to be replaced, is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Use {
    /// The scene file to open.
    OpenScene,
    /// The scene file to save to.
    SaveScene,
    /// The picture to export to.
    Picture,
}

/// The scene file and picture fields, the dialog and the replace question while they are up,
/// and what the last action said.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct SceneFiles {
    /// The scene file to save to or open.
    path: String,
    /// The picture file to export to (PNG or SVG by its extension).
    picture_path: String,
    /// What the last save, open or export said.
    status: Option<Status>,
    /// The file dialog, while it is up, and what its file is for.
    dialog: Option<(Use, FileDialog)>,
    /// A file the user is asked about replacing (its name says whether with the scene or
    /// the picture).
    replace: Option<PathBuf>,
}

impl Default for SceneFiles {
    fn default() -> Self {
        Self {
            path: DEFAULT_SCENE_PATH.to_owned(),
            picture_path: DEFAULT_PICTURE_PATH.to_owned(),
            status: None,
            dialog: None,
            replace: None,
        }
    }
}

impl SceneFiles {
    /// Shows the row: the scene file, *Open file*, *Save file*, the dialog's *Open…* and
    /// *Save as…*, the picture export's menu and what the last action said; then the dialog or
    /// the replace question, while one is up. Returns the scene opened, if one was.
    pub(super) fn show(&mut self, ui: &mut Ui, scene: &Scene) -> Option<Scene> {
        let mut opened = None;
        // On a projector's narrow window the dialog's buttons and the export menu show only
        // their icons, so that the row keeps to one line; it wraps rather than cut anything off.
        let compact = ui.available_width() < COMPACT_BELOW;
        ui.horizontal_wrapped(|ui| {
            let width = if compact { 170.0 } else { 260.0 };
            let field = TextEdit::singleline(&mut self.path).desired_width(width);
            ui.add(field).labelled_by(ui.label(t!("scenes-file")).id);
            if ui.button(t!("scenes-open")).clicked() {
                opened = self.open_typed();
            }
            if ui
                .button(t!("scenes-save"))
                .on_hover_text(t!("scenes-save-hover"))
                .clicked()
            {
                self.save(scene);
            }
            let open = (
                OPEN_ICON,
                t!("files-open-dialog"),
                t!("scenes-open-dialog-hover"),
            );
            if icon_button(ui, open, (true, false), compact) {
                self.ask(Use::OpenScene);
            }
            let save_as = (SAVE_AS_ICON, t!("files-save-as"), t!("files-save-as-hover"));
            if icon_button(ui, save_as, (true, false), compact) {
                self.ask(Use::SaveScene);
            }
            let name = t!("controls-export");
            let shown = if compact { PICTURE_ICON } else { name.as_str() };
            let menu = ui.menu_button(shown, |ui| self.export_menu(ui, scene));
            menu.response
                .widget_info(|| WidgetInfo::labeled(Role::Button, true, &name));
            if compact {
                menu.response.on_hover_text(name);
            }
            // What the last save, open or export said, cut to the row's end.
            status::show(ui, self.status.as_ref(), Look::Cut);
        });
        opened.or_else(|| self.dialogs(ui, scene))
    }

    /// Puts up the file dialog for `usage`, starting from the file in its field.
    fn ask(&mut self, usage: Use) {
        let (purpose, extensions, start) = match usage {
            Use::OpenScene => (Purpose::Open, SCENE_FILES, &self.path),
            Use::SaveScene => (Purpose::Save, SCENE_FILES, &self.path),
            Use::Picture => (Purpose::Save, PICTURE_FILES, &self.picture_path),
        };
        self.dialog = Some((usage, FileDialog::new(purpose, extensions, start)));
    }

    /// Opens the scene file in the path field (or a built-in scene by name); a file that
    /// cannot be read or understood opens nothing and says why, with its line and column.
    fn open_typed(&mut self) -> Option<Scene> {
        let path = self.path.trim().to_owned();
        match Scene::load(&path) {
            Ok(scene) => {
                self.status = Some(Status::Done(t!("scenes-opened", path = path)));
                Some(scene)
            }
            Err(e) => {
                self.status = Some(Status::Refused(e.to_string()));
                None
            }
        }
    }

    /// Saves `scene` to the file in the path field: at once to a new file, after a question
    /// over an existing scene file, never over a file of another kind or to a name that is
    /// not `.toml`; with no name typed, asks for one in the dialog.
    fn save(&mut self, scene: &Scene) {
        if self.path.trim().is_empty() {
            self.ask(Use::SaveScene);
            return;
        }
        let path = PathBuf::from(self.path.trim());
        match file_dialog::target(&path, Kind::Scene) {
            Ok(Target::New) => self.write(scene, &path),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(e) => self.status = Some(Status::Refused(e.to_string())),
        }
    }

    /// The picture export's menu: the file (PNG or SVG by its extension), *Browse…* and
    /// *Export*.
    fn export_menu(&mut self, ui: &mut Ui, scene: &Scene) {
        ui.horizontal(|ui| {
            let field = TextEdit::singleline(&mut self.picture_path)
                .hint_text(t!("scenes-picture-hint"))
                .desired_width(220.0);
            ui.add(field)
                .labelled_by(ui.label(t!("scenes-picture-file")).id);
            if ui.button(t!("controls-browse")).clicked() {
                self.ask(Use::Picture);
                ui.close();
            }
        });
        let (width, height) = refraction_render::DEFAULT_SIZE;
        let text = t!(
            "scenes-export-size",
            width = width.to_string(),
            height = height.to_string()
        );
        if ui.button(text).clicked() {
            let path = file_dialog::or_numbered(&self.picture_path, "scene", "svg");
            self.export(scene, path);
        }
    }

    /// Exports the picture to `path` at once when it is new, after a question when it holds
    /// an image of its kind, never over a file of another kind.
    fn export(&mut self, scene: &Scene, path: PathBuf) {
        match picture_target(&path) {
            Ok(Target::New) => self.write(scene, &path),
            Ok(Target::Replaces) => self.replace = Some(path),
            Err(e) => self.status = Some(Status::Refused(e.to_string())),
        }
    }

    /// Writes `scene` at `path` (checked by [`file_dialog::target`]) as its name says: the
    /// scene file (`.toml`, atomically) or its picture (PNG or SVG); says what happened.
    fn write(&mut self, scene: &Scene, path: &Path) {
        let shown = path.display().to_string();
        self.status = Some(match Kind::of_name(path) {
            Some(Kind::Png | Kind::Svg) => {
                export::scene_picture(scene, refraction_render::DEFAULT_SIZE, path)
            }
            _ => match scene
                .to_toml()
                .map(|text| write_atomically(path, text.as_bytes()))
            {
                Ok(Ok(())) => Status::Done(t!("scenes-saved", path = shown)),
                Ok(Err(e)) => Status::Refused(e.to_string()),
                Err(e) => Status::Refused(e.to_string()),
            },
        });
    }

    /// The dialog and the replace question, while either is up; returns the scene opened
    /// from the dialog, if one was.
    fn dialogs(&mut self, ui: &Ui, scene: &Scene) -> Option<Scene> {
        let mut opened = None;
        if let Some(((usage, _), path)) = file_dialog::chosen_file(ui, &mut self.dialog, |(_, d)| d)
        {
            let shown = path.display().to_string();
            match usage {
                Use::OpenScene => {
                    self.path = shown;
                    opened = self.open_typed();
                }
                Use::SaveScene => {
                    self.path = shown;
                    self.save(scene);
                }
                Use::Picture => {
                    self.picture_path = shown;
                    self.export(scene, path);
                }
            }
        }
        if let Some(path) = file_dialog::answer_replace(ui, &mut self.replace, &mut self.status) {
            self.write(scene, &path);
        }
        opened
    }
}

//! Files as a desktop user expects them: an open/save dialog, a question before a file is
//! replaced, no file written over one of another kind (a state over an image, a scene over a
//! state, …), and exports numbered `diagram-001.png`, `diagram-002.png`, … when no name is
//! given.
//!
//! The dialog is built of egui widgets (a folder field, the folder's listing filtered by
//! extension, a file name field) rather than taken from a crate: `egui-file-dialog` 0.15, the
//! newest at the time of writing, is built for egui 0.36 and the explorer uses 0.37, and `rfd`'s
//! native dialogs need a desktop portal that a projector's kiosk session, Xvfb and the headless
//! `egui_kittest` tests do not have. Widgets work in all three, and the tests drive this dialog
//! like any other part of the window.
//!
//! In a browser there is no file system to list: the dialog is the browser's file picker and a
//! download ([`picker`]), and the listing goes unused.
#![cfg_attr(
    target_arch = "wasm32",
    // untranslated: a lint expectation's reason, for developers.
    expect(dead_code, reason = "in a browser the picker replaces the listing")
)]

use std::path::{Path, PathBuf};

use egui::{Id, Modal, RichText, ScrollArea, TextEdit, Ui};
use refraction_i18n::t;

use super::status::Status;

#[cfg(target_arch = "wasm32")]
pub(super) mod picker;

/// What a file holds, as far as replacing it is concerned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    /// A saved state (a `solve` JSON line, `.json`).
    State,
    /// A PNG image (`.png`).
    Png,
    /// An SVG image (`.svg`).
    Svg,
    /// A scene (the scene format, TOML text, `.toml`).
    Scene,
    /// A GIF animation (`.gif`).
    Gif,
    /// A lesson deck (TOML text with a `[deck]` table, `.toml`): told from a scene by its
    /// contents.
    Deck,
}

impl Kind {
    /// The kind a file of this name should hold, by its extension.
    #[must_use]
    pub(super) fn of_name(path: &Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "json" => Some(Self::State),
            "png" => Some(Self::Png),
            "svg" => Some(Self::Svg),
            "toml" => Some(Self::Scene),
            "gif" => Some(Self::Gif),
            _ => None,
        }
    }

    /// What the first bytes of a file say it holds (`None`: something else).
    #[must_use]
    pub(super) fn of_contents(bytes: &[u8]) -> Option<Self> {
        let text = bytes.trim_ascii_start();
        if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
            Some(Self::Png)
        } else if bytes.starts_with(b"GIF87a") || bytes.starts_with(b"GIF89a") {
            Some(Self::Gif)
        } else if text.starts_with(b"{") {
            Some(Self::State)
        } else if text.starts_with(b"<") {
            Some(Self::Svg)
        } else if utf8_prefix(bytes).is_some_and(refraction_deck::looks_like_deck) {
            Some(Self::Deck)
        } else if utf8_prefix(bytes).is_some_and(looks_like_toml) {
            Some(Self::Scene)
        } else {
            None
        }
    }

    /// The extension a file of this kind is written with, dot included.
    fn extension(self) -> &'static str {
        match self {
            Self::State => ".json",
            Self::Png => ".png",
            Self::Svg => ".svg",
            Self::Scene | Self::Deck => ".toml",
            Self::Gif => ".gif",
        }
    }

    /// The name the messages select this kind's words by (`{ $kind -> [png] … }`), the same
    /// in every language.
    fn id(self) -> &'static str {
        match self {
            Self::State => "state",
            Self::Png => "png",
            Self::Svg => "svg",
            Self::Scene => "scene",
            Self::Gif => "gif",
            Self::Deck => "deck",
        }
    }
}

/// Whether `text` reads as TOML: its first line that is neither blank nor a comment opens a
/// table (`[`) or sets a key (`=`); text of comments only does too.
fn looks_like_toml(text: &str) -> bool {
    text.lines()
        .map(str::trim)
        .find(|line| !line.is_empty() && !line.starts_with('#'))
        .is_none_or(|line| line.starts_with('[') || line.contains('='))
}

/// Where a file is about to be written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Target {
    /// Nothing is there yet: write.
    New,
    /// A file of the same kind (or an empty one) is there: ask before replacing it.
    Replaces,
}

/// Why a file may not be written where it was asked: the path, the kind it was to hold and
/// what is there, worded when shown, in the window's language.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub(super) enum WriteRefusal {
    /// The name does not end in the kind's extension.
    #[error(
        "{}",
        t!(
            "files-wrong-extension",
            path = path.display().to_string(),
            kind = kind.id(),
            extension = kind.extension()
        )
    )]
    WrongExtension {
        /// The path asked for.
        path: PathBuf,
        /// The kind to write.
        kind: Kind,
    },
    /// The path is a folder.
    #[error("{}", t!("files-is-a-folder", path = path.display().to_string()))]
    IsAFolder {
        /// The folder.
        path: PathBuf,
    },
    /// A file of another kind is there.
    #[error(
        "{}",
        t!(
            "files-holds-another-kind",
            path = path.display().to_string(),
            found = found.map_or("other", Kind::id),
            kind = kind.id()
        )
    )]
    AnotherKind {
        /// The file.
        path: PathBuf,
        /// What it holds (`None`: none of the kinds).
        found: Option<Kind>,
        /// The kind to write.
        kind: Kind,
    },
}

/// Whether `kind` may be written at `path`: its name must say that kind and a file already
/// there must hold that kind (or nothing).
///
/// # Errors
/// The name says another kind (or none), the path is a folder, or the file there holds
/// something else; the message names the path and what it holds.
pub(super) fn target(path: &Path, kind: Kind) -> Result<Target, WriteRefusal> {
    // A deck and a scene share `.toml`: the name says the extension, the contents the kind.
    if Kind::of_name(path).map(Kind::extension) != Some(kind.extension()) {
        return Err(WriteRefusal::WrongExtension {
            path: path.to_path_buf(),
            kind,
        });
    }
    if path.is_dir() {
        return Err(WriteRefusal::IsAFolder {
            path: path.to_path_buf(),
        });
    }
    // The first bytes tell the kind; a file that cannot be read is left for the writer to report.
    let Some(bytes) = first_bytes(path) else {
        return Ok(Target::New);
    };
    match Kind::of_contents(&bytes) {
        _ if bytes.is_empty() => Ok(Target::Replaces),
        Some(found) if found == kind => Ok(Target::Replaces),
        found => Err(WriteRefusal::AnotherKind {
            path: path.to_path_buf(),
            found,
            kind,
        }),
    }
}

/// The first bytes of the file at `path`, enough for [`Kind::of_contents`] to tell its kind
/// (never a whole recording); `None` when there is no file there or it cannot be read.
pub(super) fn first_bytes(path: &Path) -> Option<Vec<u8>> {
    refraction_files::first_bytes(path, 64 * 1024)
        .ok()
        .flatten()
}

/// `bytes` as text when they are UTF-8, up to a character cut at their end (a prefix read
/// from a longer file); `None` for any other invalid byte.
fn utf8_prefix(bytes: &[u8]) -> Option<&str> {
    match core::str::from_utf8(bytes) {
        Ok(text) => Some(text),
        Err(cut) if cut.error_len().is_none() => {
            core::str::from_utf8(&bytes[..cut.valid_up_to()]).ok()
        }
        Err(_) => None,
    }
}

/// [`target`] for a picture: a PNG or SVG image as the name of `path` says, a PNG when it
/// says neither (so that the refusal names `.png`).
///
/// # Errors
/// As [`target`].
pub(super) fn picture_target(path: &Path) -> Result<Target, WriteRefusal> {
    let kind = Kind::of_name(path).filter(|kind| matches!(kind, Kind::Png | Kind::Svg));
    target(path, kind.unwrap_or(Kind::Png))
}

/// The path typed, or when none is typed (or a folder is) the next free
/// `stem-NNN.extension` in that folder ([`numbered`]).
#[must_use]
pub(super) fn or_numbered(typed: &str, stem: &str, extension: &str) -> PathBuf {
    let typed = PathBuf::from(typed.trim());
    if typed.as_os_str().is_empty() || typed.is_dir() {
        numbered(&typed, stem, extension)
    } else {
        typed
    }
}

/// The first of `stem-001.ext`, `stem-002.ext`, … that does not exist in `folder` (after
/// 999, `stem-1000.ext` and on).
#[must_use]
pub(super) fn numbered(folder: &Path, stem: &str, extension: &str) -> PathBuf {
    (1..=u64::MAX)
        .map(|i| folder.join(format!("{stem}-{i:03}.{extension}")))
        .find(|p| !p.exists())
        // untranslated: a panic message for developers; some number is always free
        .expect("some number is free")
}

/// Asks whether to replace the file at `pending`, while there is one: `Some(true)` once the
/// user says replace, `Some(false)` once they cancel, `None` while they have not answered.
fn confirm_replace(ui: &Ui, pending: &Path) -> Option<bool> {
    let mut answer = None;
    let modal = Modal::new(Id::unique("confirm_replace")).show(ui.ctx(), |ui| {
        ui.heading(t!("files-replace-question"));
        let path = pending.display().to_string();
        ui.label(t!("files-already-exists", path = path));
        ui.horizontal(|ui| {
            if ui.button(t!("files-replace")).clicked() {
                answer = Some(true);
            }
            if ui.button(t!("files-cancel")).clicked() {
                answer = Some(false);
            }
        });
    });
    if answer.is_none() && modal.should_close() {
        answer = Some(false);
    }
    answer
}

/// While `pending` holds a file, asks whether to replace it ([`confirm_replace`]); once the
/// user answers, clears it and returns the file when they said replace, or leaves `status`
/// saying the file was left as it was when they cancelled.
pub(super) fn answer_replace(
    ui: &Ui,
    pending: &mut Option<PathBuf>,
    status: &mut Option<Status>,
) -> Option<PathBuf> {
    let replace = confirm_replace(ui, pending.as_deref()?)?;
    let path = pending.take()?;
    if replace {
        return Some(path);
    }
    let shown = path.display().to_string();
    *status = Some(Status::Done(t!("files-left-as-it-was", path = shown)));
    None
}

/// Shows the dialog that `slot` holds (alone, or with what it was opened for; `dialog` finds
/// it there) while it is up, and empties the slot once the user chose or cancelled; returns
/// what the slot held and the file chosen.
pub(super) fn chosen_file<T>(
    ui: &Ui,
    slot: &mut Option<T>,
    dialog: impl FnOnce(&mut T) -> &mut FileDialog,
) -> Option<(T, PathBuf)> {
    match dialog(slot.as_mut()?).show(ui) {
        Choice::Pending => None,
        Choice::Cancelled => {
            *slot = None;
            None
        }
        Choice::Chosen(path) => slot.take().map(|held| (held, path)),
    }
}

/// Whether the dialog picks a file to read or a name to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Purpose {
    /// Open: the file must exist.
    Open,
    /// Save: any name in an existing folder.
    Save,
}

/// One row of the listing.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Entry {
    name: String,
    folder: bool,
}

/// An open or save dialog over the file system, listing one folder at a time: its folders
/// and the files with one of the dialog's extensions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct FileDialog {
    purpose: Purpose,
    extensions: &'static [&'static str],
    folder: String,
    name: String,
    entries: Vec<Entry>,
    listed: Option<PathBuf>,
    problem: Option<String>,
}

/// What the user did with the dialog this frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) enum Choice {
    /// Still choosing.
    Pending,
    /// This file.
    Chosen(PathBuf),
    /// Closed without a choice.
    Cancelled,
}

impl FileDialog {
    /// A dialog for `purpose` showing files ending in one of `extensions` (without the dot),
    /// starting in the folder of `start` (a path as typed; relative to the working folder)
    /// with its file name filled in.
    #[must_use]
    pub(super) fn new(purpose: Purpose, extensions: &'static [&'static str], start: &str) -> Self {
        let start = Path::new(start.trim());
        let folder = match start.parent() {
            Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
            _ => std::env::current_dir().unwrap_or_else(|_| PathBuf::from(".")),
        };
        let name = start
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        Self {
            purpose,
            extensions,
            folder: folder.display().to_string(),
            name,
            entries: Vec::new(),
            listed: None,
            problem: None,
        }
    }

    /// Whether the dialog opens or saves.
    #[must_use]
    pub(super) fn purpose(&self) -> Purpose {
        self.purpose
    }

    /// Reads the folder's listing when the folder changed since it was last read.
    fn list(&mut self) {
        let folder = PathBuf::from(self.folder.trim());
        if self.listed.as_ref() == Some(&folder) {
            return;
        }
        self.entries.clear();
        match std::fs::read_dir(&folder) {
            Ok(read) => {
                self.problem = None;
                for entry in read.flatten() {
                    let name = entry.file_name().to_string_lossy().into_owned();
                    let is_folder = entry.path().is_dir();
                    let wanted = Path::new(&name)
                        .extension()
                        .and_then(|e| e.to_str())
                        .is_some_and(|e| self.extensions.iter().any(|x| x.eq_ignore_ascii_case(e)));
                    if (is_folder || wanted) && !name.starts_with('.') {
                        self.entries.push(Entry {
                            name,
                            folder: is_folder,
                        });
                    }
                }
                self.entries
                    .sort_by(|a, b| b.folder.cmp(&a.folder).then(a.name.cmp(&b.name)));
            }
            Err(e) => {
                let (path, reason) = (folder.display().to_string(), e.to_string());
                self.problem = Some(t!("files-cannot-list", path = path, reason = reason));
            }
        }
        self.listed = Some(folder);
    }

    fn enter(&mut self, name: &str) {
        let folder = PathBuf::from(self.folder.trim());
        let next = if name == ".." {
            folder
                .canonicalize()
                .ok()
                .and_then(|f| f.parent().map(Path::to_path_buf))
                .unwrap_or(folder)
        } else {
            folder.join(name)
        };
        self.folder = next.display().to_string();
    }

    /// The file chosen, if it can be: an existing file to open, or a name in an existing
    /// folder to save; else says why not.
    fn choose(&mut self) -> Option<PathBuf> {
        let path = PathBuf::from(self.folder.trim()).join(self.name.trim());
        let ok = match self.purpose {
            Purpose::Open => path.is_file(),
            Purpose::Save => {
                !self.name.trim().is_empty() && path.parent().is_some_and(Path::is_dir)
            }
        };
        if ok {
            return Some(path);
        }
        self.problem = Some(match self.purpose {
            Purpose::Open => t!("files-not-a-file", path = path.display().to_string()),
            Purpose::Save => t!("files-type-a-name"),
        });
        None
    }

    /// The listing: the parent folder, then folders, then the files shown; a click on a
    /// folder enters it, on a file takes its name, a double click on a file chooses it.
    fn listing(&mut self, ui: &mut Ui) -> bool {
        let mut entered = None;
        let mut chosen = false;
        ScrollArea::vertical().max_height(260.0).show(ui, |ui| {
            if ui.selectable_label(false, "⬆ ..").clicked() {
                entered = Some("..".to_owned());
            }
            for entry in &self.entries {
                let text = if entry.folder {
                    format!("📁 {}", entry.name)
                } else {
                    entry.name.clone()
                };
                let row = ui.selectable_label(self.name == entry.name, text);
                if entry.folder && row.clicked() {
                    entered = Some(entry.name.clone());
                } else if row.double_clicked() {
                    self.name.clone_from(&entry.name);
                    chosen = true;
                } else if row.clicked() {
                    self.name.clone_from(&entry.name);
                }
            }
        });
        if let Some(name) = entered {
            self.enter(&name);
        }
        chosen
    }

    /// Shows the dialog over the window: the folder's listing, or in a browser the browser's
    /// file picker (open) or a download (save).
    pub(super) fn show(&mut self, ui: &Ui) -> Choice {
        #[cfg(target_arch = "wasm32")]
        return picker::dialog(
            self.purpose,
            self.extensions,
            &mut self.name,
            self.problem.as_ref(),
            ui,
        );
        #[cfg(not(target_arch = "wasm32"))]
        return self.show_listing(ui);
    }

    /// The dialog over the window, listing the folder.
    fn show_listing(&mut self, ui: &Ui) -> Choice {
        self.list();
        let title = match self.purpose {
            Purpose::Open => t!("files-dialog-open-title"),
            Purpose::Save => t!("files-dialog-save-title"),
        };
        let id = Id::unique(("file_dialog", self.purpose));
        let modal = Modal::new(id).show(ui.ctx(), |ui| {
            ui.heading(title);
            ui.horizontal(|ui| {
                let label = ui.label(t!("files-folder"));
                ui.add(TextEdit::singleline(&mut self.folder).desired_width(360.0))
                    .labelled_by(label.id);
            });
            let shown: Vec<String> = self.extensions.iter().map(|e| format!("*.{e}")).collect();
            let showing = t!("files-showing", patterns = shown.join(", "));
            ui.label(RichText::new(showing).weak());
            let mut chosen = self.listing(ui);
            ui.horizontal(|ui| {
                let label = ui.label(t!("files-file-name"));
                ui.add(TextEdit::singleline(&mut self.name).desired_width(300.0))
                    .labelled_by(label.id);
            });
            if let Some(problem) = &self.problem {
                ui.label(RichText::new(format!("⚠ {problem}")).strong());
            }
            let mut cancelled = false;
            ui.horizontal(|ui| {
                let verb = match self.purpose {
                    Purpose::Open => t!("files-open-file"),
                    Purpose::Save => t!("files-save-file"),
                };
                chosen |= ui.button(verb).clicked();
                cancelled = ui.button(t!("files-cancel")).clicked();
            });
            (chosen, cancelled)
        });
        let (chosen, cancelled) = modal.inner;
        if chosen && let Some(path) = self.choose() {
            return Choice::Chosen(path);
        }
        if cancelled || modal.should_close() {
            return Choice::Cancelled;
        }
        Choice::Pending
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("file-dialog-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_state_is_never_written_over_an_image_nor_an_image_over_a_state() {
        let dir = scratch("kinds");
        let png = dir.join("picture.png");
        std::fs::write(&png, b"\x89PNG\r\n\x1a\nrest").unwrap();
        let state = dir.join("state.json");
        std::fs::write(&state, b"{\"w\":[0,-1,0]}").unwrap();
        let disguised = dir.join("disguised.json");
        std::fs::write(&disguised, b"\x89PNG\r\n\x1a\n").unwrap();
        assert_eq!(target(&state, Kind::State), Ok(Target::Replaces));
        assert_eq!(target(&png, Kind::Png), Ok(Target::Replaces));
        assert_eq!(target(&dir.join("new.json"), Kind::State), Ok(Target::New));
        let refused = target(&png, Kind::State).unwrap_err().to_string();
        assert!(refused.contains("ending in .json"), "{refused}");
        let refused = target(&disguised, Kind::State).unwrap_err().to_string();
        assert!(refused.contains("holds a PNG image"), "{refused}");
        let refused = target(&dir.join("state.png"), Kind::Png);
        assert_eq!(refused, Ok(Target::New));
        std::fs::write(dir.join("state.png"), b"{}").unwrap();
        assert!(target(&dir.join("state.png"), Kind::Png).is_err());
        assert!(target(&dir, Kind::State).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_long_file_is_told_by_its_start_even_with_a_character_cut_there() {
        let dir = scratch("long");
        let scene = dir.join("long.toml");
        // 'é' is two bytes: one of them falls on each side of the bytes read.
        let mut text = format!("title = \"{}", "a".repeat(64 * 1024 - 10));
        text.push_str("é\"\n[source]\n");
        text.push_str(&"# comment\n".repeat(20_000));
        std::fs::write(&scene, &text).unwrap();
        assert_eq!(first_bytes(&scene).map(|b| b.len()), Some(64 * 1024));
        assert_eq!(target(&scene, Kind::Scene), Ok(Target::Replaces));
        assert_eq!(utf8_prefix(b"ab\xc3"), Some("ab"));
        assert_eq!(utf8_prefix(b"a\xffb"), None);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn scenes_and_animations_are_told_from_states_and_images() {
        assert_eq!(Kind::of_contents(b"GIF89a\x01"), Some(Kind::Gif));
        let scene = b"# A lesson\n\ntitle = \"Slab\"\n[source]\n";
        assert_eq!(Kind::of_contents(scene), Some(Kind::Scene));
        assert_eq!(
            Kind::of_contents(b"[media.glass]\nindex = 1.5\n"),
            Some(Kind::Scene)
        );
        assert_eq!(Kind::of_contents(b"just some words"), None);
        let deck = b"[deck]\nversion = 1\n\n[[step]]\ntitle = \"One\"\n";
        assert_eq!(Kind::of_contents(deck), Some(Kind::Deck));
        assert_eq!(Kind::of_contents(b"\xff\xfe = binary"), None);
        let dir = scratch("scenes");
        let state = dir.join("lesson.toml");
        std::fs::write(&state, b"{\"w\":[0,-1,0]}").unwrap();
        let refused = target(&state, Kind::Scene).unwrap_err().to_string();
        assert!(
            refused.contains("holds a saved state (JSON), not a scene (TOML)"),
            "{refused}"
        );
        let scene_file = dir.join("slab.toml");
        std::fs::write(&scene_file, scene).unwrap();
        assert_eq!(target(&scene_file, Kind::Scene), Ok(Target::Replaces));
        let refused = target(&scene_file, Kind::Deck).unwrap_err().to_string();
        assert!(
            refused.contains("holds a scene (TOML), not a lesson deck (TOML)"),
            "{refused}"
        );
        let deck_file = dir.join("lesson.toml");
        std::fs::write(&deck_file, deck).unwrap();
        assert_eq!(target(&deck_file, Kind::Deck), Ok(Target::Replaces));
        assert!(
            target(&deck_file, Kind::Scene).is_err(),
            "no scene over a deck"
        );
        assert!(
            target(&scene_file, Kind::Gif)
                .unwrap_err()
                .to_string()
                .contains("ending in .gif")
        );
        // A picture is a PNG or an SVG: any other name is refused as not being a .png.
        assert_eq!(picture_target(&dir.join("new.svg")), Ok(Target::New));
        assert!(
            picture_target(&scene_file)
                .unwrap_err()
                .to_string()
                .contains("ending in .png")
        );
        // No name, or a folder: the next free number there.
        assert_eq!(
            or_numbered("  ", "scene", "svg"),
            PathBuf::from("scene-001.svg")
        );
        let typed = dir.display().to_string();
        assert_eq!(
            or_numbered(&typed, "scene", "svg"),
            dir.join("scene-001.svg")
        );
        assert_eq!(
            or_numbered(" a.png ", "scene", "svg"),
            PathBuf::from("a.png")
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_refusal_names_both_kinds_in_the_language_of_the_window() {
        let dir = scratch("german");
        let disguised = dir.join("disguised.json");
        std::fs::write(&disguised, b"\x89PNG\r\n\x1a\n").unwrap();
        refraction_i18n::set_locale(refraction_i18n::Locale::De);
        let refused = target(&disguised, Kind::State).unwrap_err().to_string();
        let named = target(&dir.join("picture.svg"), Kind::Png)
            .unwrap_err()
            .to_string();
        refraction_i18n::set_locale(refraction_i18n::Locale::En);
        assert!(
            refused.ends_with("enthält ein PNG-Bild, keinen gespeicherten Zustand (JSON): Die Datei bleibt unverändert; bitte einen anderen Namen wählen"),
            "{refused}"
        );
        assert!(
            named.contains(": Ein PNG-Bild wird als .png-Datei"),
            "{named}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn exports_are_numbered_from_the_first_free_number() {
        let dir = scratch("numbers");
        assert_eq!(
            numbered(&dir, "diagram", "png"),
            dir.join("diagram-001.png")
        );
        std::fs::write(dir.join("diagram-001.png"), b"").unwrap();
        std::fs::write(dir.join("diagram-002.png"), b"").unwrap();
        assert_eq!(
            numbered(&dir, "diagram", "png"),
            dir.join("diagram-003.png")
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_listing_shows_folders_and_the_wanted_files_only() {
        let dir = scratch("listing");
        std::fs::create_dir_all(dir.join("lessons")).unwrap();
        for name in ["b.json", "a.json", "c.png", ".hidden.json"] {
            std::fs::write(dir.join(name), b"{}").unwrap();
        }
        let mut dialog = FileDialog::new(
            Purpose::Open,
            &["json"],
            dir.join("a.json").to_str().unwrap(),
        );
        dialog.list();
        let names: Vec<&str> = dialog.entries.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["lessons", "a.json", "b.json"]);
        assert_eq!(dialog.choose(), Some(dir.join("a.json")));
        dialog.enter("lessons");
        dialog.list();
        assert!(dialog.entries.is_empty());
        assert_eq!(dialog.choose(), None, "no a.json in lessons");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

//! The deck file (TOML, described in the repository's guide, `docs/decks.md`): a `[deck]`
//! table with the format's version and a title, then one `[[step]]` table per step. It is read
//! with the scene format's machinery ([`refraction_scene::parse_toml`]), so that every error
//! names the file, the line and column of the value at fault, and what was expected; and
//! written back from the same structures, so that reading what is written gives an equal deck.

use core::ops::Range;
use std::path::{Path, PathBuf};

use glam::DVec3;
use serde::{Deserialize, Serialize};
use toml::Spanned;

use refraction_kernel::{Convention, IndexName, InputError, VectorName};
use refraction_model::ExplorerState;
use refraction_scene::{Invalid, LoadError, Numbers, Scene, invalid, parse_toml, toml_text};

use super::step::{Effect, Step, StepTool, StepView};
use super::{Deck, builtin};
use refraction_model::Polarisation;

/// The version of the deck format this explorer reads and writes.
pub const VERSION: u32 = 1;

/// The largest deck file read: 1 MiB (a deck of 100 steps with long notes is under 100 KiB).
pub const MAX_DECK_FILE_BYTES: u64 = 1 << 20;

/// The most steps a deck may have.
pub const MAX_STEPS: usize = 500;

/// The `[deck]` table.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct Header {
    version: Spanned<i64>,
    #[serde(default)]
    title: String,
}

/// A `[[step]]` table.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct StepSpec {
    title: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    question: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    notes: String,
    #[serde(default)]
    view: StepView,
    w: Spanned<Numbers<3>>,
    n: Spanned<Numbers<3>>,
    mu_i: Spanned<f64>,
    mu_t: Spanned<f64>,
    #[serde(default)]
    convention: Convention,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    scene: Option<Spanned<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    tool: Option<StepTool>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    effects: Vec<Spanned<Effect>>,
    #[serde(default)]
    light: Polarisation,
}

/// A deck file as written.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
struct DeckFile {
    deck: Spanned<Header>,
    #[serde(default)]
    step: Vec<Spanned<StepSpec>>,
}

/// The value a kernel's refusal is about, so that the message points at it.
fn refused_at(error: &InputError, spec: &StepSpec) -> Range<usize> {
    match error {
        InputError::NonFiniteComponent {
            vector: VectorName::W,
            ..
        }
        | InputError::ZeroVector(VectorName::W) => spec.w.span(),
        InputError::NonFiniteComponent { .. } | InputError::ZeroVector(_) => spec.n.span(),
        InputError::BadIndex {
            index: IndexName::MuI,
            ..
        } => spec.mu_i.span(),
        InputError::BadIndex { .. } | InputError::RatioOutOfRange { .. } => spec.mu_t.span(),
    }
}

/// The state a step gives, as the kernel takes it.
fn state(spec: &StepSpec) -> Result<ExplorerState, Invalid> {
    ExplorerState::new(
        DVec3::from_array(spec.w.get_ref().0),
        DVec3::from_array(spec.n.get_ref().0),
        *spec.mu_i.get_ref(),
        *spec.mu_t.get_ref(),
        spec.convention,
    )
    .or_else(|e| invalid(refused_at(&e, spec), e.to_string()))
}

/// The effects, each once.
fn effects(specs: &[Spanned<Effect>]) -> Result<Vec<Effect>, Invalid> {
    let mut effects: Vec<Effect> = Vec::new();
    for spec in specs {
        let effect = *spec.get_ref();
        if effects.contains(&effect) {
            return invalid(
                spec.span(),
                "this effect is named twice: name each effect once",
            );
        }
        effects.push(effect);
    }
    Ok(Effect::ALL
        .into_iter()
        .filter(|e| effects.contains(e))
        .collect())
}

/// The scene named, which must load (a path relative to `folder`).
fn scene(spec: &Spanned<String>, folder: Option<&Path>) -> Result<String, Invalid> {
    let name = spec.get_ref();
    resolve_scene(name, folder).map_err(|e| Invalid {
        span: spec.span(),
        message: format!("the step's scene cannot be opened: {e}"),
    })?;
    Ok(name.clone())
}

/// The scene `name`: a built-in scene, or a scene file whose relative path starts from
/// `folder`.
///
/// # Errors
/// As [`Scene::load`].
pub fn resolve_scene(name: &str, folder: Option<&Path>) -> Result<Scene, LoadError> {
    match scene_file(name, folder) {
        None => Scene::embedded(name),
        Some(path) => Scene::load(&path.to_string_lossy()),
    }
}

/// The file the scene `name` is read from (relative to `folder`); `None` for a built-in scene.
#[must_use]
pub fn scene_file(name: &str, folder: Option<&Path>) -> Option<PathBuf> {
    if Scene::embedded(name).is_ok() {
        return None;
    }
    Some(folder.map_or_else(|| PathBuf::from(name), |f| f.join(name)))
}

fn step(spec: &StepSpec, folder: Option<&Path>) -> Result<Step, Invalid> {
    let question = match &spec.question {
        Some(q) if q.get_ref().trim().is_empty() => {
            return invalid(
                q.span(),
                "the question is empty: give it words, or leave `question` out for a step that \
                 shows its answer at once",
            );
        }
        q => q.as_ref().map(|q| q.get_ref().clone()),
    };
    Ok(Step {
        title: spec.title.clone(),
        notes: spec.notes.clone(),
        question,
        state: state(spec)?,
        view: spec.view,
        scene: spec.scene.as_ref().map(|s| scene(s, folder)).transpose()?,
        tool: spec.tool,
        effects: effects(&spec.effects)?,
        light: spec.light,
    })
}

fn build(file: &DeckFile, folder: Option<&Path>) -> Result<Deck, Invalid> {
    let header = file.deck.get_ref();
    let version = *header.version.get_ref();
    if version != i64::from(VERSION) {
        let newer = if version > i64::from(VERSION) {
            " (a newer explorer wrote it)"
        } else {
            ""
        };
        return invalid(
            header.version.span(),
            format!(
                "version {version}: this explorer reads deck files of version {VERSION}{newer}"
            ),
        );
    }
    if file.step.is_empty() {
        return invalid(
            file.deck.span(),
            "the deck has no step: add at least one [[step]] table",
        );
    }
    if let Some(extra) = file.step.get(MAX_STEPS) {
        return invalid(
            extra.span(),
            format!("more than {MAX_STEPS} steps: a deck has at most {MAX_STEPS}"),
        );
    }
    let steps = file
        .step
        .iter()
        .map(|s| step(s.get_ref(), folder))
        .collect::<Result<_, _>>()?;
    Ok(Deck {
        title: header.title.clone(),
        steps,
        folder: folder.map(Path::to_path_buf),
    })
}

/// A value with no place in a file: written values carry no span.
fn unplaced<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn step_spec(step: &Step) -> StepSpec {
    let state = &step.state;
    StepSpec {
        title: step.title.clone(),
        question: step.question.clone().map(unplaced),
        notes: step.notes.clone(),
        view: step.view,
        w: unplaced(Numbers(state.w().to_array())),
        n: unplaced(Numbers(state.n().to_array())),
        mu_i: unplaced(state.mu_i()),
        mu_t: unplaced(state.mu_t()),
        convention: state.convention(),
        scene: step.scene.clone().map(unplaced),
        tool: step.tool,
        effects: step.effects.iter().copied().map(unplaced).collect(),
        light: step.light,
    }
}

impl Deck {
    /// Reads a deck from TOML text. `file` names it in errors; a step's scene file is found
    /// from `folder` (the deck file's folder; `None`: the working folder).
    ///
    /// # Errors
    /// A [`LoadError`] at the line and column of the first problem: malformed TOML, a missing
    /// or unknown field, a value of the wrong type or name, a version other than [`VERSION`],
    /// no step or more than [`MAX_STEPS`], a state the kernel refuses, an effect named twice,
    /// an empty question, or a scene that cannot be opened.
    pub fn from_toml(text: &str, file: &str, folder: Option<&Path>) -> Result<Self, LoadError> {
        let at = |e: Invalid| LoadError::in_text(text, file, Some(e.span), e.message);
        one_deck_table(text).map_err(at)?;
        let parsed: DeckFile = parse_toml(text, file)?;
        build(&parsed, folder).map_err(at)
    }

    /// A built-in deck by name ([`builtin::names`]), or else a deck file by path (at most
    /// [`MAX_DECK_FILE_BYTES`] long), its steps' scene files found from its folder.
    ///
    /// # Errors
    /// The file cannot be read, is too long, is not UTF-8, or fails to load
    /// ([`Deck::from_toml`]).
    pub fn load(name_or_path: &str) -> Result<Self, LoadError> {
        if let Some(deck) = builtin::deck(name_or_path) {
            return Ok(deck);
        }
        let path = Path::new(name_or_path);
        let bytes = refraction_files::read_capped_bytes(path, MAX_DECK_FILE_BYTES, "a deck file")
            .map_err(|e| LoadError {
            file: name_or_path.to_owned(),
            position: None,
            message: format!(
                "cannot read: {e} (expected a deck file or one of {})",
                builtin::names().join(", ")
            ),
        })?;
        let text = toml_text(&bytes, name_or_path, "a deck file")?;
        Self::from_toml(text, name_or_path, path.parent())
    }

    /// The deck as a deck file: reading it back ([`Deck::from_toml`]) gives an equal deck.
    ///
    /// # Errors
    /// The TOML writer's error (a deck's values always have a form in TOML, so only a broken
    /// build meets one).
    pub fn to_toml(&self) -> Result<String, toml::ser::Error> {
        let file = DeckFile {
            deck: unplaced(Header {
                version: unplaced(i64::from(VERSION)),
                title: self.title.clone(),
            }),
            step: self.steps.iter().map(|s| unplaced(step_spec(s))).collect(),
        };
        toml::to_string_pretty(&file)
    }
}

/// Refuses `[[deck]]`, an array of tables where the format has one table (the TOML reader would
/// only say that a table is not a number).
fn one_deck_table(text: &str) -> Result<(), Invalid> {
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim();
        if trimmed.replace(' ', "") == "[[deck]]" {
            let at = start + line.find('[').unwrap_or(0);
            return invalid(
                at..at + trimmed.len(),
                "`[deck]` is one table: write `[deck]`, not `[[deck]]` (each step is a `[[step]]`)",
            );
        }
        start += line.len();
    }
    Ok(())
}

/// Whether `text` is a deck file rather than a scene: it has a `[deck]` table.
#[must_use]
pub fn looks_like_deck(text: &str) -> bool {
    text.lines().any(|line| line.trim() == "[deck]")
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = "[deck]\nversion = 1\n\n[[step]]\ntitle = \"One\"\nw = [0.6, -0.8, 0]\nn = [0, 1, 0]\nmu_i = 1\nmu_t = 1.5\n";

    fn error(text: &str) -> String {
        Deck::from_toml(text, "lesson.toml", None)
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn a_minimal_deck_loads_with_the_defaults() {
        let deck = Deck::from_toml(MINIMAL, "lesson.toml", None).unwrap();
        let step = &deck.steps[0];
        assert_eq!(step.title, "One");
        assert_eq!(step.view, StepView::One);
        assert_eq!(step.question, None);
        assert_eq!(step.state.mu_t(), 1.5);
        assert!(looks_like_deck(MINIMAL));
        assert!(!looks_like_deck("title = \"Slab\"\n[source]\n"));
    }

    #[test]
    fn bad_values_are_refused_where_they_stand() {
        let at = |from: &str, to: &str| error(&MINIMAL.replace(from, to));
        assert_eq!(
            at("mu_t = 1.5", "mu_t = -1"),
            "lesson.toml:9:8: mu_t is -1: an index of refraction must be a finite number > 0"
        );
        assert!(
            at("w = [0.6, -0.8, 0]", "w = [0, 0, 0]")
                .starts_with("lesson.toml:6:5: w is the zero vector"),
        );
        let unknown = at("title = \"One\"", "title = \"One\"\ncolour = \"red\"");
        assert!(
            unknown.starts_with("lesson.toml:6:1: unknown field `colour`, expected one of"),
            "{unknown}"
        );
        let view = at("mu_t = 1.5", "mu_t = 1.5\nview = \"accuracy\"");
        assert!(
            view.starts_with(
                "lesson.toml:10:8: unknown variant `accuracy`, expected `one` or `scenes`"
            ),
            "{view}"
        );
        let twice = at(
            "mu_t = 1.5",
            "mu_t = 1.5\neffects = [\"wavefronts\", \"wavefronts\"]",
        );
        assert!(
            twice.starts_with("lesson.toml:10:26: this effect is named twice"),
            "{twice}"
        );
        let newer = at("version = 1", "version = 2");
        assert_eq!(
            newer,
            "lesson.toml:2:11: version 2: this explorer reads deck files of version 1 (a newer \
             explorer wrote it)"
        );
        let scene = at("mu_t = 1.5", "mu_t = 1.5\nscene = \"no-such-scene.toml\"");
        assert!(
            scene.starts_with("lesson.toml:10:9: the step's scene cannot be opened: no-such-scene.toml: cannot read"),
            "{scene}"
        );
        let empty = at("title = \"One\"", "title = \"One\"\nquestion = \" \"");
        assert!(
            empty.starts_with("lesson.toml:6:12: the question is empty"),
            "{empty}"
        );
        assert!(error("[deck]\nversion = 1\n").contains("the deck has no step"));
        assert!(error("[deck]\nversion = \"one\"\n").starts_with("lesson.toml:2:11: invalid type"));
    }

    #[test]
    fn a_vector_holds_exactly_three_numbers() {
        // Issue 31: a fourth entry (even a string or a table) was read and dropped.
        let at = |from: &str, to: &str| error(&MINIMAL.replace(from, to));
        for (w, column) in [
            ("[0.6, -0.8, 0, 1]", 5),
            ("[0.6, -0.8, 0, \"x\", {a = 1}]", 5),
        ] {
            let e = at("w = [0.6, -0.8, 0]", &format!("w = {w}"));
            assert!(
                e.starts_with(&format!(
                    "lesson.toml:6:{column}: expected three numbers [x, y, z], found"
                )),
                "{e}"
            );
        }
        let two = at("n = [0, 1, 0]", "n = [0, 1]");
        assert!(
            two.starts_with("lesson.toml:7:5: invalid length 2"),
            "{two}"
        );
    }

    #[test]
    fn odd_tables_are_refused_with_their_place() {
        let deep = format!("[deck]\nversion = 1\n{}b = 1\n", "a.".repeat(200));
        let e = error(&deep);
        assert!(e.starts_with("lesson.toml:3:"), "{e}");
        let array = error("[[deck]]\nversion = 1\n");
        assert!(
            array.starts_with("lesson.toml:1:1: `[deck]` is one table"),
            "{array}"
        );
    }
}

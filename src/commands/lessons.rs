//! `lessons` and `render --lesson`: the built-in lesson decks listed, and a deck drawn as a
//! handout (PDF, one page per step) or as one SVG per step.

use std::io::{self, Write as _};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use glam::Vec2;
use refraction_deck::{Deck, builtin};
use refraction_explorer::app::handout::{Drawn, HandoutError, picture, write};
use refraction_render::{ImageFormat, RenderError, check_size, handout::Sheet, svg};
use refraction_scene::LoadError;

use super::inputs::{Input, OtherKind, OutputIsInput, refuse_inputs, refuse_other_kinds};
use super::output::printable;
use super::{fail, output_error};

/// Runs `lessons`: each built-in deck as `NAME<TAB>TITLE<TAB>STEPS`, in the language asked for.
pub(crate) fn list() -> ExitCode {
    let mut out = io::stdout().lock();
    builtin::catalogue()
        .iter()
        .try_for_each(|info| {
            writeln!(
                out,
                "{}\t{}\t{}",
                info.name,
                printable(&info.title),
                info.steps
            )
        })
        .and_then(|()| out.flush())
        .map_or_else(|e| output_error("lessons", &e), |()| ExitCode::SUCCESS)
}

/// Where `render --lesson` writes: a handout, or a folder of pictures.
enum Out {
    /// A PDF handout at this path.
    Handout(PathBuf),
    /// `step-01.svg`, `step-02.svg`, … in this folder.
    Folder(PathBuf),
}

/// Why `render --lesson` wrote nothing: each worded once, in the commands' English (the
/// deck's, the renderer's and the file system's own messages as they came).
#[derive(Debug, thiserror::Error)]
enum LessonFailure {
    /// `--out` names neither a handout nor a folder.
    #[error(
        "--out {0}: with --lesson, give a handout's name ending in .pdf, or a folder ending in / \
         for one SVG per step (step-01.svg, step-02.svg, …)"
    )]
    NeitherHandoutNorFolder(String),
    /// The size is outside the limits, or a picture cannot be drawn.
    #[error(transparent)]
    Render(#[from] RenderError),
    /// The deck, or a step's scene, cannot be opened.
    #[error(transparent)]
    Deck(#[from] LoadError),
    /// The handout cannot be made or written.
    #[error(transparent)]
    Handout(#[from] HandoutError),
    /// The pictures' folder cannot be made.
    #[error("cannot make the folder {}: {source}", folder.display())]
    Folder {
        /// The folder.
        folder: PathBuf,
        /// Why.
        source: io::Error,
    },
    /// A file cannot be written (its own message names it).
    #[error(transparent)]
    Unwritable(io::Error),
    /// `--out` names the deck or one of its scene files.
    #[error(transparent)]
    OutputIsInput(#[from] OutputIsInput),
    /// `--out` (or a picture in its folder) holds a file of another kind.
    #[error(transparent)]
    OtherKind(#[from] OtherKind),
    /// `--web-base` cannot start a link.
    #[error(transparent)]
    WebBase(#[from] super::WebBaseRefused),
}

/// What `--out` asks for: a folder when it ends in `/` or is one, a handout when it ends in
/// `.pdf`.
fn out_of(out: &Path) -> Result<Out, LessonFailure> {
    let text = out.to_string_lossy();
    if text.ends_with('/') || out.is_dir() {
        return Ok(Out::Folder(out.to_path_buf()));
    }
    let pdf = out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("pdf"));
    if pdf {
        refraction_files::check_writable(out).map_err(LessonFailure::Unwritable)?;
        return Ok(Out::Handout(out.to_path_buf()));
    }
    Err(LessonFailure::NeitherHandoutNorFolder(text.into_owned()))
}

/// The name of step `number`'s picture (`step-01.svg`).
fn step_file(number: usize) -> String {
    format!("step-{number:02}.{}", ImageFormat::Svg.extension())
}

/// Writes each step of `deck` as `step-01.svg`, `step-02.svg`, … in `folder` (made if it is
/// missing), at `size` pixels: every picture is drawn before any is written, then all are
/// written or none, and none if one would replace a file the deck reads (`inputs`). Pictures
/// of later steps that a longer deck left there (ours: our SVG's
/// first line) are removed, so that the folder holds this deck's steps only.
fn pictures(
    deck: &Deck,
    folder: &Path,
    (width, height): (u32, u32),
    inputs: &[Input],
) -> Result<(), LessonFailure> {
    let paths: Vec<PathBuf> = (1..=deck.steps.len())
        .map(|i| folder.join(step_file(i)))
        .collect();
    refuse_inputs(paths.iter().map(PathBuf::as_path), "--out", inputs)?;
    refuse_other_kinds(
        paths.iter().map(PathBuf::as_path),
        "--out",
        "an SVG picture",
    )?;
    let size = Vec2::new(width as f32, height as f32);
    let texts = deck
        .steps
        .iter()
        .map(|step| {
            let primitives = picture(deck, step, size, Drawn::default())?;
            svg::document(width, height, svg::Labels::default(), |_, _| primitives)
                .map_err(LessonFailure::from)
        })
        .collect::<Result<Vec<String>, LessonFailure>>()?;
    std::fs::create_dir_all(folder).map_err(|source| LessonFailure::Folder {
        folder: folder.to_path_buf(),
        source,
    })?;
    let files: Vec<(&Path, &[u8])> = paths
        .iter()
        .zip(&texts)
        .map(|(path, text)| (path.as_path(), text.as_bytes()))
        .collect();
    refraction_files::write_all_atomically(&files).map_err(LessonFailure::Unwritable)?;
    remove_stale_steps(folder, texts.len());
    Ok(())
}

/// Removes `step-NN.svg` for every step after `count` while one is there and ours (it starts
/// as [`svg::document`] writes it). What cannot be removed stays: the new steps are written.
fn remove_stale_steps(folder: &Path, count: usize) {
    let header = svg::document_header();
    for number in count + 1.. {
        let path = folder.join(step_file(number));
        match refraction_files::first_bytes(&path, header.len() as u64) {
            Ok(Some(start)) if start == header.as_bytes() => {
                std::fs::remove_file(&path).ok();
            }
            _ => break,
        }
    }
}

/// The files `deck`, opened as `lesson`, was read from: its own (unless it is a built-in
/// deck) and its steps' scene files.
fn inputs_of(lesson: &str, deck: &Deck) -> Vec<Input> {
    let own = (!builtin::names().contains(&lesson)).then(|| Input {
        path: PathBuf::from(lesson),
        what: "the deck",
    });
    let scenes = deck.scene_files().into_iter().map(|path| Input {
        path,
        what: "a scene of the deck",
    });
    own.into_iter().chain(scenes).collect()
}

/// Runs `render --lesson NAME|FILE --out OUT`: the deck's handout (`OUT` ending in `.pdf`) or
/// its steps as SVG pictures of `size` (`OUT` a folder). The output is checked before the deck
/// is drawn, and never replaces the deck or a scene file it reads: the teacher's handout or the class's sheet (`sheet`); with `web_base`, each page
/// of a handout carries its step's link and QR code.
pub(crate) fn render(
    lesson: &str,
    out: &Path,
    size: (u32, u32),
    (sheet, web_base): (Sheet, Option<&str>),
) -> ExitCode {
    let checked = check_size(size.0, size.1).map_err(LessonFailure::from);
    let base = checked.and_then(|()| Ok(super::web_base(web_base)?));
    let drawn = base
        .and_then(|base| Ok((base, out_of(out)?)))
        .and_then(|(base, to)| {
            let web_base = base.as_deref();
            let deck = Deck::load(lesson)?;
            let inputs = inputs_of(lesson, &deck);
            match to {
                Out::Handout(path) => {
                    refuse_inputs([path.as_path()], "--out", &inputs)?;
                    refuse_other_kinds([path.as_path()], "--out", "a PDF")?;
                    Ok(write(&deck, sheet, web_base, &path)?)
                }
                Out::Folder(folder) => pictures(&deck, &folder, size, &inputs),
            }
        });
    match drawn {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => fail("render", &message),
    }
}

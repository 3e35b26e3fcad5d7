//! A deck's handout (PDF, one page per step) and each step's picture and link: what
//! `render --lesson` writes and the *Lesson deck* tool exports, drawn the same way.

use std::path::Path;

use glam::Vec2;
use refraction_deck::{Deck, Step, StepView, builtin};
use refraction_diagram::palette::Palette;
use refraction_diagram::{Diagram, Overlay, Primitive, SceneLayout, ScenePicture};
use refraction_i18n::t;
use refraction_render::RenderError;
use refraction_render::handout::{self, Page, Sheet};
use refraction_scene::LoadError;
use refraction_tools::link::{self, Link};

use super::overlay_of;
use crate::app::status;

/// Why a deck's handout could not be made or written: each error as it came, worded by its
/// own `Display`.
#[derive(Debug, thiserror::Error)]
pub enum HandoutError {
    /// A step's scene cannot be opened.
    #[error(transparent)]
    Scene(#[from] LoadError),
    /// A page cannot be converted to PDF.
    #[error(transparent)]
    Pdf(#[from] RenderError),
    /// The handout's file cannot be written (its own message names it).
    #[error(transparent)]
    Write(std::io::Error),
}

/// How a step's picture is drawn: with its answer hidden or not, for paper or a screen.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Drawn {
    /// The answer is hidden, as before the reveal.
    pub hidden: bool,
    /// On paper: no handle, no index scale ([`Overlay::paper`]).
    pub paper: bool,
}

/// The picture of `step` of `deck` on a canvas of `size` pixels, drawn as `drawn` says: the
/// one interface with the step's effects, or its scene traced (up to the first surface while
/// the answer is hidden).
///
/// # Errors
/// The step's scene cannot be opened.
pub fn picture(
    deck: &Deck,
    step: &Step,
    size: Vec2,
    drawn: Drawn,
) -> Result<Vec<Primitive>, LoadError> {
    let hidden = drawn.hidden;
    match step.view {
        StepView::One => {
            let overlay = Overlay {
                hide_answer: hidden,
                paper: drawn.paper,
                ..overlay_of(step)
            };
            Ok(Diagram::with_overlay(&step.state, size, &overlay).primitives())
        }
        StepView::Scenes => {
            let scene = deck.scene(step)?;
            let trace = scene.trace();
            let layout = SceneLayout::new(trace.bounds, size);
            let picture = if hidden {
                let shown = refraction_deck::answer::up_to_first_surface(&trace);
                ScenePicture::asking(&scene, &shown, &layout, &Palette::STANDARD)
            } else {
                ScenePicture::new(&scene, &trace, &layout)
            };
            Ok(picture.primitives)
        }
    }
}

/// The name of the built-in deck `deck` is, if it is one: the same steps with the same states
/// (in whatever language it was opened).
#[must_use]
pub fn builtin_name(deck: &Deck) -> Option<&'static str> {
    builtin::names().into_iter().find(|name| {
        builtin::deck(name).is_some_and(|known| {
            known.steps.len() == deck.steps.len()
                && known
                    .steps
                    .iter()
                    .zip(&deck.steps)
                    .all(|(a, b)| a.state == b.state && a.view == b.view)
        })
    })
}

/// What opens step `index` of `deck` in the web build: the built-in deck at that step, else
/// the step's state when it shows one interface; `None` for a scene of a deck file (a link
/// cannot carry a scene).
#[must_use]
pub fn step_link(deck: &Deck, index: usize) -> Option<Link> {
    if let Some(name) = builtin_name(deck) {
        return Some(Link::Lesson {
            name: name.to_owned(),
            step: index + 1,
        });
    }
    let step = deck.steps.get(index)?;
    (step.view == StepView::One).then(|| Link::State(Box::new(step.state.clone())))
}

/// Whether the student sheet draws step `index` of `deck` with its answer hidden: a step
/// that asks a question, and a step that explains one (no question of its own) with the same
/// ray or scene as a step that asks: on paper a student can turn the page to it.
fn hidden_on_sheet(deck: &Deck, index: usize) -> bool {
    let Some(step) = deck.steps.get(index) else {
        return false;
    };
    step.hides_answer()
        || deck
            .steps
            .iter()
            .filter(|other| other.hides_answer())
            .any(|other| same_picture(step, other))
}

/// Whether two steps show the same light: the same scene, or the same ray meeting the same
/// surface between the same media (whichever way W is written).
fn same_picture(a: &Step, b: &Step) -> bool {
    match (a.view, b.view) {
        (StepView::Scenes, StepView::Scenes) => a.scene == b.scene,
        (StepView::One, StepView::One) => {
            let (ra, rb) = (a.state.refraction(), b.state.refraction());
            let close = |u: glam::DVec3, v: glam::DVec3| u.distance(v) < 1e-9;
            close(ra.travel, rb.travel)
                && close(ra.facing_normal, rb.facing_normal)
                && (a.state.mu_i() - b.state.mu_i()).abs() < 1e-12
                && (a.state.mu_t() - b.state.mu_t()).abs() < 1e-12
        }
        _ => false,
    }
}

/// The handout's page for step `index` of `deck`, on the teacher's handout or the student
/// sheet, with the step's link at `web_base` if given. The step's scene is opened first, so
/// that a page that cannot be drawn is an error.
fn page<'a>(
    deck: &'a Deck,
    index: usize,
    (sheet, web_base): (Sheet, Option<&str>),
) -> Result<Page<'a>, LoadError> {
    let step = &deck.steps[index];
    if step.view == StepView::Scenes {
        deck.scene(step)?;
    }
    let number = t!(
        "deck-step-number",
        number = (index + 1).to_string(),
        count = deck.steps.len().to_string()
    );
    let students = sheet == Sheet::Students;
    let drawn = Drawn {
        hidden: students && hidden_on_sheet(deck, index),
        paper: true,
    };
    Ok(Page {
        deck: deck.title.clone(),
        heading: number,
        title: step.title.clone(),
        question: step
            .question
            .clone()
            .map(|q| (t!("deck-handout-question"), q)),
        notes: (!students).then(|| (t!("deck-handout-notes"), step.notes.clone())),
        writing_lines: students && step.question.is_some(),
        // The scene opened above: drawing it again cannot fail.
        diagram: Box::new(move |size| picture(deck, step, size, drawn).unwrap_or_default()),
        link: web_base.and_then(|base| Some(link::url(base, &step_link(deck, index)?))),
    })
}

/// The handout of `deck` as PDF bytes, one page per step: the teacher's or the class's
/// (`sheet`), each page with its link and QR code when `web_base` (the web build's address)
/// is given.
///
/// # Errors
/// A step's scene cannot be opened, or a page cannot be converted.
pub fn pdf(deck: &Deck, sheet: Sheet, web_base: Option<&str>) -> Result<Vec<u8>, HandoutError> {
    let pages = (0..deck.steps.len())
        .map(|i| page(deck, i, (sheet, web_base)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(handout::pdf(&deck.title, &pages)?)
}

/// Writes the handout of `deck` ([`pdf`]) at `path`, all of it or nothing.
///
/// # Errors
/// A step's scene cannot be opened, a page cannot be converted, or the file cannot be written.
pub fn write(
    deck: &Deck,
    sheet: Sheet,
    web_base: Option<&str>,
    path: &Path,
) -> Result<(), HandoutError> {
    let bytes = pdf(deck, sheet, web_base)?;
    refraction_files::write_atomically(path, &bytes).map_err(HandoutError::Write)
}

impl crate::app::Explorer {
    /// Writes the open deck's handout as the next free `handout-NNN.pdf` (in a browser, a
    /// download), with each step's link when a web address is set; the deck tool says what
    /// happened.
    pub(crate) fn write_handout(&mut self) {
        let Some(deck) = &self.lesson.deck else {
            return;
        };
        // An address that cannot start a link is said, not left off the pages in silence.
        let base = match self.web_base().trim() {
            "" => None,
            typed => match link::web_base(typed) {
                Ok(base) => Some(base),
                Err(refused) => {
                    self.lesson.panel.status = Some(status::Status::Refused(refused.message()));
                    return;
                }
            },
        };
        let path = crate::app::file_dialog::numbered(Path::new(""), "handout", "pdf");
        let written = write(deck, Sheet::Teacher, base.as_deref(), &path);
        self.lesson.panel.status = Some(status::exported(written, &path));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_built_in_deck_links_its_steps_by_name_and_a_file_s_by_state() {
        let snell = builtin::deck("snell").unwrap();
        assert_eq!(builtin_name(&snell), Some("snell"));
        assert_eq!(
            step_link(&snell, 1),
            Some(Link::Lesson {
                name: "snell".to_owned(),
                step: 2
            })
        );
        let mut own = snell.clone();
        own.steps.truncate(1);
        assert_eq!(builtin_name(&own), None);
        assert_eq!(
            step_link(&own, 0),
            Some(Link::State(Box::new(own.steps[0].state.clone())))
        );
    }
}

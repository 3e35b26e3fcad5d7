//! A deck's handout (PDF, one page per step) and each step's picture and link: what
//! `render --lesson` writes and the *Lesson deck* tool exports, drawn the same way.

use std::path::Path;

use glam::Vec2;
use refraction_deck::{Deck, Step, StepView, builtin};
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

/// The picture of `step` of `deck` on a canvas of `size` pixels, its answer shown unless
/// `hidden` (and the step asks a question): the one interface with the step's effects, or its
/// scene traced (up to the first surface while the answer is hidden).
///
/// # Errors
/// The step's scene cannot be opened.
pub fn picture(
    deck: &Deck,
    step: &Step,
    size: Vec2,
    hidden: bool,
) -> Result<Vec<Primitive>, LoadError> {
    let hidden = hidden && step.hides_answer();
    match step.view {
        StepView::One => {
            let overlay = Overlay {
                hide_answer: hidden,
                ..overlay_of(step)
            };
            Ok(Diagram::with_overlay(&step.state, size, &overlay).primitives())
        }
        StepView::Scenes => {
            let scene = deck.scene(step)?;
            let trace = scene.trace();
            let layout = SceneLayout::new(trace.bounds, size);
            let shown = if hidden {
                refraction_deck::answer::up_to_first_surface(&trace)
            } else {
                trace
            };
            Ok(ScenePicture::new(&scene, &shown, &layout).primitives)
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
        diagram: Box::new(move |size| picture(deck, step, size, students).unwrap_or_default()),
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

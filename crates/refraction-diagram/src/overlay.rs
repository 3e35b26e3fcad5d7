//! What is drawn over the interface diagram besides the state itself: the palette, the pan and
//! zoom of the view, a student's T beside the right one, and the parts a walk-through step is
//! about. Kept in the diagram model, not in the window, so that the PNG export shows them too.

use glam::DVec3;
use refraction_model::Polarisation;

use super::layout::PanZoom;
use super::palette::Palette;
use super::wavefronts::WaveOptions;
use refraction_kernel::Rejection;

/// A student's T to draw beside the right one.
#[derive(Clone, Debug, PartialEq)]
pub struct StudentRay {
    /// Their T, as they gave it (any length; drawn with its length, so that a T that is not
    /// unit length looks it).
    pub t: DVec3,
    /// What it is, e.g. `your T: wrong side`.
    pub label: String,
    /// What the student's API calls W and N, drawn instead of those names while their case is
    /// shown (`None`: this project's own W and N).
    pub names: Option<VectorNames>,
}

/// The labels of the incident vector and the normal in a student's API, such as
/// `wi (back toward the origin)` and `n` for pbrt.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VectorNames {
    /// The label of W's arrow.
    pub incident: String,
    /// The label of N's arrow.
    pub normal: String,
}

/// A part of the diagram that a walk-through step can highlight.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part {
    /// The incoming ray.
    Incoming,
    /// W.
    W,
    /// N.
    N,
    /// The chosen T.
    T,
    /// The angle of incidence θi.
    AngleI,
    /// The angle of refraction θt.
    AngleT,
    /// T drawn as a·W then b·N.
    Decomposition,
    /// A rejected candidate.
    Candidate(Rejection),
}

/// What a walk-through step is about, as the set of parts it highlights.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    /// Snell's law: the two angles.
    Angles,
    /// T = a·W + b·N and the cosines as dot products.
    Decomposition,
    /// The squared constraints: all four candidates satisfy them.
    SquaredConstraints,
    /// The two roots a = ±μ: T and its mirror across the normal.
    RootsOfA,
    /// The choice of a by the μ → 1 argument: the incoming ray, T and the wrong bend.
    ChoiceOfA,
    /// The two roots for b: T and its mirror across the surface.
    RootsOfB,
    /// The choice of b: T, the wrong side.
    ChoiceOfB,
}

impl Focus {
    /// The parts this focus highlights.
    #[must_use]
    pub(crate) fn parts(self) -> &'static [Part] {
        use Part::{AngleI, AngleT, Candidate, Decomposition, Incoming, N, T, W};
        use Rejection::{Reversed, WrongBend, WrongSide};
        match self {
            Self::Angles => &[AngleI, AngleT],
            Self::Decomposition => &[W, N, Decomposition],
            Self::SquaredConstraints => &[
                T,
                Candidate(WrongSide),
                Candidate(WrongBend),
                Candidate(Reversed),
            ],
            Self::RootsOfA => &[W, T, Candidate(WrongBend)],
            Self::ChoiceOfA => &[Incoming, T, Candidate(WrongBend)],
            Self::RootsOfB => &[N, T, Candidate(WrongSide)],
            Self::ChoiceOfB => &[T, Candidate(WrongSide)],
        }
    }
}

/// Everything drawn on top of the state.
#[derive(Clone, Debug, PartialEq)]
pub struct Overlay {
    /// The colours and ray dashes.
    pub palette: Palette,
    /// How the view is panned and zoomed.
    pub pan_zoom: PanZoom,
    /// A student's T, if one is being checked.
    pub student: Option<StudentRay>,
    /// What a walk-through step highlights.
    pub focus: Option<Focus>,
    /// The *Intensities* switch: the reflected and transmitted rays drawn by their share of
    /// this light, with percentages; `None` when off.
    pub intensities: Option<Polarisation>,
    /// The *Wavefronts* switch: the fronts (at their phase) and, if asked, Huygens's
    /// construction; `None` when off.
    pub waves: Option<WaveOptions>,
    /// A lesson step's question is being asked: T, the reflected ray, the rejected candidates,
    /// the angle of refraction and the banner's verdict are left out until it is revealed.
    pub hide_answer: bool,
    /// The index scale is drawn (folded away by presentation's diagram-only key).
    pub index_scale: bool,
    /// The simple view, for a class that has not met the four candidates yet: the three
    /// rejected candidates and their (a, b) labels are left out, and so is the outward-normal
    /// bug's wrong T (the paper's formula with N as given), which is one of them.
    pub simple: bool,
    /// Drawn for paper (a handout): no handle is drawn and the index scale is left out (the
    /// media's labels give both indices), and a hidden answer's banner names only the
    /// convention, where the window says how to reveal it.
    pub paper: bool,
    /// Handles sized for a finger (a phone's student view): each handle's grab area is at least
    /// [`TOUCH_TARGET`](super::picture::TOUCH_TARGET) pixels across, as WCAG's target size asks.
    pub touch: bool,
}

impl Default for Overlay {
    fn default() -> Self {
        Self {
            palette: Palette::STANDARD,
            pan_zoom: PanZoom::default(),
            student: None,
            focus: None,
            intensities: None,
            waves: None,
            hide_answer: false,
            index_scale: true,
            simple: false,
            paper: false,
            touch: false,
        }
    }
}

impl Overlay {
    /// Whether `part` is highlighted.
    #[must_use]
    pub(crate) fn highlights(&self, part: Part) -> bool {
        self.focus.is_some_and(|f| f.parts().contains(&part))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_focus_highlights_something_and_none_highlights_nothing() {
        let mut overlay = Overlay::default();
        assert!(!overlay.highlights(Part::T));
        overlay.focus = Some(Focus::ChoiceOfA);
        assert!(overlay.highlights(Part::Candidate(Rejection::WrongBend)));
        assert!(!overlay.highlights(Part::Candidate(Rejection::WrongSide)));
    }
}

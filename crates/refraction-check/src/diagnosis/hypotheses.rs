//! The hypotheses the diagnosis of a whole log ranks: every single-line mistake of the
//! refraction formula (the ratio, in the whole formula or in one of its parts, on one side or
//! both; the normal's orientation; the incident vector's sign; the root's sign; the term along
//! N; pbrt's flip left out) and every pair of them, each as the [`Variant`] of the formula it
//! computes on a ray arriving from outside and on one from inside.
//!
//! A mistake in the caller's arguments is the same mistake: GLSL's eta passed upside down and
//! a ratio inverted inside the student's own `refract` give the same T. What the arguments
//! show (the readings of a call, as codes) only says where the mistake is, and must be one a
//! hypothesis can make: a line whose logged eta is inverted is explained by a hypothesis with
//! the ratio inverted, not by one with the root's sign flipped, even where both give its T.

use std::sync::OnceLock;

use refraction_kernel::api::Api;

use super::Code;
use super::formula::{self, Outcome, Situation, Variant};
use refraction_model::log_map::Side;

/// A set of mistake codes (the argument mistakes a reading of a call assumes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Codes(u16);

impl Codes {
    /// The set of `codes`.
    #[must_use]
    pub fn of(codes: &[Code]) -> Self {
        Self(codes.iter().fold(0, |set, code| set | code.bit()))
    }

    /// Whether every code of `self` is in `other`.
    #[must_use]
    pub fn within(self, other: Self) -> bool {
        self.0 & !other.0 == 0
    }

    /// Whether the set is empty.
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// Whether the two sets share a code.
    #[must_use]
    pub fn meets(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }
}

/// What one reading of a line says: the argument mistakes it assumes, and the formula's
/// variants that reproduce what came back in the situation it makes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct View {
    /// The argument mistakes the reading assumes (none for any renderer's own refraction).
    pub arguments: Codes,
    /// The variants that reproduce the line, as [`Variant::bit`]s.
    pub variants: u64,
}

/// What a line's views are made from, kept by its verdict so that the formula's variants are
/// worked out only for the diagnosis of the whole log: each reading's argument mistakes and
/// situation, what came back, and whether it is the right answer.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Readings {
    /// Each reading's argument mistakes and the situation it makes.
    pub situations: Vec<(Codes, Situation)>,
    /// What the code sent the ray along.
    pub outcome: Outcome,
    /// Whether the line is right: its views are the variants that agree with the right answer
    /// (not those that reproduce what was logged, within its rounding).
    pub right: bool,
    /// How closely a variant must match, in radians.
    pub tolerance: f64,
}

impl Readings {
    /// The views: for each reading, its argument mistakes and the variants that reproduce the
    /// line (or agree with it, for a right line).
    #[must_use]
    pub fn views(&self) -> Vec<View> {
        self.situations
            .iter()
            .map(|(arguments, situation)| View {
                arguments: *arguments,
                variants: if self.right {
                    formula::agreeing(situation, self.tolerance)
                } else {
                    formula::reproducing(situation, self.outcome, self.tolerance)
                },
            })
            .collect()
    }
}

/// How an API takes its arguments, which decides what an argument mistake does to the formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Family {
    /// The incident vector along the ray and a normal that must face it: GLSL, the book.
    Along,
    /// `wi` back along the ray and a ratio relative to the normal given (either side): pbrt,
    /// Mitsuba. An inward normal there is an inverted ratio, and a reversed `wi` refracts as
    /// if from the other side.
    Back,
    /// Any renderer's own refraction (`check` without `--api`): as [`Family::Along`], but
    /// no argument is logged as the API's, so a normal or an incident vector is wrong in the
    /// code itself.
    Own,
}

impl Family {
    /// The family of `api` (`None`: any renderer's own refraction).
    #[must_use]
    pub(crate) fn of(api: Option<Api>) -> Self {
        match api {
            Some(Api::Pbrt | Api::Mitsuba) => Self::Back,
            Some(Api::Glsl | Api::Rtiow) => Self::Along,
            None => Self::Own,
        }
    }
}

/// One line of code a student gets wrong, as the search tries it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Slip {
    /// The ratio upside down: μ → 1/μ in the whole formula.
    Ratio,
    /// The ratio upside down in the part across N only (the scale of d⊥).
    RatioAcross,
    /// The ratio upside down in cosθt only (k, and the test for total internal reflection).
    RatioAlong,
    /// The normal not turned to face the ray: the other root, in GLSL's form.
    Normal,
    /// The incident vector the wrong way round.
    Incident,
    /// The sign of the part across N in the code's own formula (Mitsuba's `-eta_ti * wi.x()`
    /// written without its minus).
    AcrossSign,
    /// The square root's sign: cosθt on the ray's own side.
    Root,
    /// The term along N subtracted instead of added.
    Term,
    /// pbrt's `if (cosTheta_i < 0)` flip left out: neither the normal turned nor the ratio
    /// inverted, for rays from the normal's far side.
    NoFlip,
}

impl Slip {
    /// Every slip.
    pub(crate) const ALL: [Self; 9] = [
        Self::Ratio,
        Self::RatioAcross,
        Self::RatioAlong,
        Self::Normal,
        Self::Incident,
        Self::AcrossSign,
        Self::Root,
        Self::Term,
        Self::NoFlip,
    ];

    /// The sides the slip may be confined to by a line of code (a ratio chosen by a ternary
    /// on the side; a normal turned, or not, on one side). A reversed incident vector or a
    /// root's sign on one side only is not one line of code.
    fn sides(self) -> &'static [Sides] {
        match self {
            Self::Ratio | Self::RatioAcross | Self::RatioAlong | Self::Normal | Self::Term => {
                &[Sides::Both, Sides::Entering, Sides::Leaving]
            }
            Self::Incident | Self::AcrossSign | Self::Root => &[Sides::Both],
            Self::NoFlip => &[Sides::Leaving],
        }
    }

    /// What the slip changes in the formula, for an API of `family`.
    #[must_use]
    pub(crate) fn variant(self, family: Family) -> Variant {
        let ratio = Variant::ACROSS.with(Variant::ALONG);
        match (self, family) {
            (Self::Ratio, _) | (Self::Normal, Family::Back) => ratio,
            (Self::RatioAcross, _) => Variant::ACROSS,
            (Self::RatioAlong, _) => Variant::ALONG,
            (Self::Normal, Family::Along | Family::Own) | (Self::Root, _) => Variant::ROOT,
            (Self::Incident, Family::Along | Family::Own) | (Self::AcrossSign, _) => {
                Variant::INCIDENT
            }
            (Self::Incident, Family::Back) => ratio.with(Variant::REVERSED),
            (Self::Term, _) => Variant::TERM,
            (Self::NoFlip, _) => ratio.with(Variant::ROOT),
        }
    }

    /// The argument mistakes (of a call's readings) this slip may show as.
    #[must_use]
    pub(crate) fn arguments(self, family: Family) -> Codes {
        match (self, family) {
            (Self::Ratio, Family::Along | Family::Own) => Codes::of(&[Code::EtaInverted]),
            (Self::Ratio, Family::Back) => Codes::of(&[Code::EtaInverted, Code::NormalNotFacing]),
            (Self::Normal, _) => Codes::of(&[Code::NormalNotFacing]),
            (Self::Incident, _) => Codes::of(&[Code::IncidentReversed]),
            _ => Codes::default(),
        }
    }

    /// Whether the slip can only be in the arguments a call passes (an API's normal or
    /// incident vector): where the log has them, the line must show it there; the same change
    /// made inside the code is another slip (the root's sign, the sign across N).
    #[must_use]
    pub(crate) fn argument_only(self, family: Family) -> bool {
        family != Family::Own && matches!(self, Self::Normal | Self::Incident)
    }

    /// The code a finding of this slip is reported as.
    #[must_use]
    pub(crate) fn code(self, sides: Sides) -> Code {
        match (self, sides) {
            (Self::Ratio | Self::RatioAcross | Self::RatioAlong, _) => Code::EtaInverted,
            // The term along N with its sign wrong on one side only: a normal that does not
            // face the ray there, used in that term (smallpt's `nl` for `n`).
            (Self::Normal, _) | (Self::Term, Sides::Entering | Sides::Leaving) => {
                Code::NormalNotFacing
            }
            (Self::Incident, _) => Code::IncidentReversed,
            (Self::AcrossSign, _) => Code::AcrossSign,
            (Self::Root, _) => Code::OtherRoot,
            (Self::Term, Sides::Both) => Code::NormalTermSign,
            (Self::NoFlip, _) => Code::NoFlipInside,
        }
    }
}

/// The rays a mistake touches.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) enum Sides {
    /// Every ray.
    Both,
    /// Rays arriving from outside (entering the object).
    Entering,
    /// Rays arriving from inside (leaving it).
    Leaving,
}

impl Sides {
    fn touches(self, entering: bool) -> bool {
        match self {
            Self::Both => true,
            Self::Entering => entering,
            Self::Leaving => !entering,
        }
    }
}

/// One mistake: a slip, on the rays of some side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct Mistake {
    /// What is wrong.
    pub slip: Slip,
    /// Where.
    pub sides: Sides,
}

/// A hypothesis: one mistake, or two in different parts.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct Hypothesis {
    /// The mistakes, the one the finding is named by first.
    pub mistakes: Vec<Mistake>,
}

/// Every hypothesis: each mistake alone, then each pair of mistakes in different parts.
#[must_use]
pub(crate) fn all() -> &'static [Hypothesis] {
    static ALL: OnceLock<Vec<Hypothesis>> = OnceLock::new();
    ALL.get_or_init(|| {
        let singles: Vec<Mistake> = Slip::ALL
            .iter()
            .flat_map(|&slip| {
                slip.sides()
                    .iter()
                    .map(move |&sides| Mistake { slip, sides })
            })
            .collect();
        let mut out: Vec<Hypothesis> = singles
            .iter()
            .map(|&m| Hypothesis { mistakes: vec![m] })
            .collect();
        for (i, a) in singles.iter().enumerate() {
            for b in &singles[i + 1..] {
                if a.slip != b.slip {
                    out.push(Hypothesis {
                        mistakes: vec![*a, *b],
                    });
                }
            }
        }
        out
    })
}

impl Hypothesis {
    /// The formula this hypothesis computes for a ray entering (or leaving) the object.
    #[must_use]
    pub(crate) fn variant(&self, family: Family, entering: bool) -> Variant {
        self.mistakes
            .iter()
            .filter(|m| m.sides.touches(entering))
            .fold(Variant::RIGHT, |v, m| v.with(m.slip.variant(family)))
    }

    /// The argument mistakes this hypothesis may show as.
    #[must_use]
    pub(crate) fn arguments(&self, family: Family) -> Codes {
        Codes(
            self.mistakes
                .iter()
                .fold(0, |set, m| set | m.slip.arguments(family).0),
        )
    }

    /// Whether the hypothesis reproduces a line read as `views`, on `side` (`None`: either).
    #[must_use]
    pub(crate) fn explains(&self, family: Family, views: &[View], side: Option<Side>) -> bool {
        self.reading(family, views, side, |view, variant| {
            view.variants & variant.bit() != 0
        })
    }

    /// Whether the hypothesis allows the arguments of one of `views` (a sampled reflection
    /// shows nothing else: whatever the code would have transmitted, it reflected).
    #[must_use]
    pub(crate) fn allows(&self, family: Family, views: &[View], side: Option<Side>) -> bool {
        self.reading(family, views, side, |_, _| true)
    }

    /// Whether one of `views`, on a side `side` allows, has arguments the hypothesis allows
    /// (and shows its mistakes that can only be in arguments) and passes `outcome` with the
    /// variant it computes there.
    fn reading(
        &self,
        family: Family,
        views: &[View],
        side: Option<Side>,
        outcome: impl Fn(&View, Variant) -> bool,
    ) -> bool {
        let allowed = self.arguments(family);
        let sides: &[bool] = match side {
            Some(Side::Outside) => &[true],
            Some(Side::Inside) => &[false],
            None => &[true, false],
        };
        views.iter().any(|view| {
            view.arguments.within(allowed)
                && sides.iter().any(|&entering| {
                    let shown = self
                        .mistakes
                        .iter()
                        .filter(|m| m.sides.touches(entering) && m.slip.argument_only(family))
                        .all(|m| view.arguments.meets(m.slip.arguments(family)));
                    shown && outcome(view, self.variant(family, entering))
                })
        })
    }

    /// Whether a line that `views` explain shows this hypothesis in its arguments (the caller
    /// passed the mistake) rather than in what the code computed.
    #[must_use]
    pub(crate) fn in_arguments(&self, family: Family, views: &[View]) -> bool {
        let allowed = self.arguments(family);
        views
            .iter()
            .any(|v| !v.arguments.is_empty() && v.arguments.within(allowed))
    }

    /// The code the finding is named by, and the second mistake's of a pair.
    #[must_use]
    pub(crate) fn codes(&self) -> Vec<Code> {
        let mut codes: Vec<Code> = Vec::new();
        for m in &self.mistakes {
            let code = m.slip.code(m.sides);
            if !codes.contains(&code) {
                codes.push(code);
            }
        }
        // pbrt's missing flip is one block: the ratio and the normal on the leaving rays.
        if self.is_no_flip() {
            return vec![Code::NoFlipInside];
        }
        codes
    }

    /// Whether this is the ratio and the normal both left as they are for rays from inside:
    /// pbrt's missing flip, whichever way it is written.
    fn is_no_flip(&self) -> bool {
        let leaving = |slip: Slip| {
            self.mistakes
                .iter()
                .any(|m| m.slip == slip && m.sides == Sides::Leaving)
        };
        leaving(Slip::Ratio) && leaving(Slip::Normal)
    }

    /// The mistake the finding is named by.
    #[must_use]
    pub(crate) fn first(&self) -> Mistake {
        self.mistakes[0]
    }

    /// How many conditions the hypothesis has: a mistake on one side counts one more than on
    /// both (a ternary more), a pair the sum.
    #[must_use]
    pub(crate) fn conditions(&self) -> usize {
        self.mistakes
            .iter()
            .map(|m| if m.sides == Sides::Both { 1 } else { 2 })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn single(slip: Slip, sides: Sides) -> Hypothesis {
        Hypothesis {
            mistakes: vec![Mistake { slip, sides }],
        }
    }

    #[test]
    fn the_space_holds_each_mistake_and_each_pair_once() {
        let all = all();
        let singles = all.iter().filter(|h| h.mistakes.len() == 1).count();
        assert_eq!(singles, 3 * 5 + 3 + 1);
        assert!(all.len() > 150, "{}", all.len());
        let distinct: std::collections::HashSet<&Hypothesis> = all.iter().collect();
        assert_eq!(distinct.len(), all.len());
    }

    #[test]
    fn each_hypothesis_is_named_by_its_code() {
        let cases = [
            (Slip::Ratio, Sides::Leaving, Code::EtaInverted),
            (Slip::RatioAcross, Sides::Both, Code::EtaInverted),
            (Slip::RatioAlong, Sides::Leaving, Code::EtaInverted),
            (Slip::Normal, Sides::Leaving, Code::NormalNotFacing),
            (Slip::Incident, Sides::Both, Code::IncidentReversed),
            (Slip::AcrossSign, Sides::Both, Code::AcrossSign),
            (Slip::Root, Sides::Both, Code::OtherRoot),
            (Slip::Term, Sides::Both, Code::NormalTermSign),
            (Slip::Term, Sides::Leaving, Code::NormalNotFacing),
            (Slip::NoFlip, Sides::Leaving, Code::NoFlipInside),
        ];
        for (slip, sides, code) in cases {
            assert_eq!(single(slip, sides).codes(), [code], "{slip:?} {sides:?}");
        }
        let pair = Hypothesis {
            mistakes: vec![
                Mistake {
                    slip: Slip::Ratio,
                    sides: Sides::Leaving,
                },
                Mistake {
                    slip: Slip::Normal,
                    sides: Sides::Leaving,
                },
            ],
        };
        assert_eq!(pair.codes(), [Code::NoFlipInside]);
    }

    #[test]
    fn a_mistake_on_one_side_leaves_the_other_side_right() {
        let h = single(Slip::Ratio, Sides::Leaving);
        let ratio = Variant::ACROSS.with(Variant::ALONG);
        assert_eq!(h.variant(Family::Along, true), Variant::RIGHT);
        assert_eq!(h.variant(Family::Along, false), ratio);
        let right = View {
            arguments: Codes::default(),
            variants: Variant::RIGHT.bit(),
        };
        let inverted = View {
            arguments: Codes::of(&[Code::EtaInverted]),
            variants: ratio.bit(),
        };
        assert!(h.explains(Family::Along, &[right], Some(Side::Outside)));
        assert!(!h.explains(Family::Along, &[right], Some(Side::Inside)));
        assert!(h.explains(Family::Along, &[inverted], Some(Side::Inside)));
        assert!(h.in_arguments(Family::Along, &[inverted]));
        // An argument the hypothesis cannot pass wrong: not explained, whatever T is.
        let root = single(Slip::Root, Sides::Both);
        let reversed = View {
            arguments: Codes::of(&[Code::IncidentReversed]),
            variants: Variant::ROOT.bit(),
        };
        assert!(!root.explains(Family::Along, &[reversed], None));
    }

    #[test]
    fn an_argument_mistake_changes_the_formula_as_its_api_reads_it() {
        // GLSL's normal against the ray not given: the other root. pbrt's inward normal: the
        // ratio inverted. pbrt's wi reversed: refracted as if from the other side.
        let ratio = Variant::ACROSS.with(Variant::ALONG);
        assert_eq!(Slip::Normal.variant(Family::Along), Variant::ROOT);
        assert_eq!(Slip::Normal.variant(Family::Back), ratio);
        assert_eq!(
            Slip::Incident.variant(Family::Back),
            ratio.with(Variant::REVERSED)
        );
        assert!(
            Slip::Ratio
                .arguments(Family::Back)
                .meets(Codes::of(&[Code::NormalNotFacing]))
        );
    }
}

//! The ranked search: every hypothesis scored on the log's kinds of line, the best taken as a
//! finding, the lines it leaves ranked again.

use refraction_i18n::t;
use refraction_kernel::api::Api;

use super::fixes::{self, Fix, Location};
use super::hypotheses::{self, Family, Hypothesis, Sides, Slip};
use super::{Band, Census, Finding, Kind, LogTally, Missing, NONE, TOO_FEW_DIGITS, UNCHECKED};
use super::{Code, Renderer, SMALL_ANGLE_BANDS, Side};

/// What is ranked: a hypothesis of the formula's mistakes, or a set of mistakes some lines
/// were given on their own (a missed total internal reflection, inputs not unit length...).
#[derive(Clone, Debug)]
enum Candidate<'a> {
    Formula(&'a Hypothesis),
    Line(Vec<Code>),
}

/// A candidate scored on the failing lines left.
#[derive(Clone, Debug)]
struct Scored<'a> {
    candidate: Candidate<'a>,
    /// The failing kinds it explains (indices into the log's kinds).
    kinds: Vec<usize>,
    explained: Census,
    /// Right lines it would have made wrong.
    contradicted: usize,
    /// What only many lines show against it (see [`penalty`]).
    penalty: u32,
    /// How unlikely its mistakes are in the API's code (lower is likelier).
    prior: u32,
    /// Mistakes and one-sided conditions it assumes.
    conditions: usize,
    /// The codes it is reported by, the finding's first.
    codes: Vec<Code>,
}

impl Scored<'_> {
    fn score(&self) -> i64 {
        let explained = i64::try_from(self.explained.total()).unwrap_or(i64::MAX);
        explained - i64::try_from(self.contradicted).unwrap_or(i64::MAX)
    }

    /// The order of candidates: the best first.
    fn rank(&self, other: &Self) -> core::cmp::Ordering {
        other
            .score()
            .cmp(&self.score())
            .then(other.explained.total().cmp(&self.explained.total()))
            .then(self.is_line().cmp(&other.is_line()))
            .then(self.conditions.cmp(&other.conditions))
            .then(self.penalty.cmp(&other.penalty))
            .then(self.prior.cmp(&other.prior))
    }

    fn is_line(&self) -> bool {
        matches!(self.candidate, Candidate::Line(_))
    }
}

/// The log's kinds of line, in a fixed order.
struct Lines<'t> {
    tally: &'t LogTally,
    kinds: Vec<(&'t Kind, usize)>,
    family: Family,
    api: Option<Api>,
}

/// The most findings ranked: each ranks every hypothesis on the kinds of line left, so a log
/// of K kinds each explained by a finding of its own would cost K rankings of K kinds (issue
/// 45). The failing lines left after them are one finding of lines no single cause explains.
pub(super) const MAX_FINDINGS: usize = 8;

/// The findings, the verdict first; none when no line was judged.
pub(super) fn findings(
    tally: &LogTally,
    api: Option<Api>,
    renderer: Option<Renderer>,
) -> Vec<Finding> {
    if tally.judged.total() == 0 {
        return Vec::new();
    }
    let kinds: Vec<(&Kind, usize)> = tally.kinds.iter().map(|(k, n)| (k, *n)).collect();
    let lines = Lines {
        tally,
        kinds,
        family: Family::of(api),
        api,
    };
    let mut left: Vec<usize> = (0..lines.kinds.len())
        .filter(|&i| tally.failing(lines.kinds[i].0))
        .collect();
    let contradicted = lines.contradictions();
    let mut findings = Vec::new();
    while !left.is_empty() {
        if findings.len() == MAX_FINDINGS {
            findings.push(lines.unexplained(&left));
            break;
        }
        let ranked = lines.ranked(&left, &contradicted);
        let Some(best) = ranked.first().filter(|b| !b.kinds.is_empty()) else {
            findings.push(lines.unexplained(&left));
            break;
        };
        findings.push(lines.finding(best, &ranked, renderer));
        left.retain(|i| !best.kinds.contains(i));
    }
    findings.extend(lines.undecided());
    findings.extend(lines.unchecked());
    if findings.is_empty() {
        findings.push(Finding {
            code: NONE,
            lines: tally.judged.total(),
            place: tally.place(&tally.judged),
            fix: String::new(),
            with: Vec::new(),
            alike: Vec::new(),
            tell_apart: Vec::new(),
        });
    }
    findings
}

impl Lines<'_> {
    /// Whether kind `i` is a reflection read as sampled: right, and no evidence either way.
    fn neutral(&self, i: usize) -> bool {
        let kind = self.kinds[i].0;
        kind.sample.is_some() && !self.tally.failing(kind)
    }

    /// Whether `h` reproduces kind `i`: its views; for a reflection in a band where the log
    /// samples reflection, only its arguments (the reflection was drawn, whatever T was).
    fn explains(&self, h: &Hypothesis, i: usize) -> bool {
        let kind = self.kinds[i].0;
        let sampled = kind.sample.is_some_and(|band| {
            self.tally
                .bands
                .get(&(kind.side, band))
                .is_some_and(Band::sampling)
        });
        if sampled {
            h.allows(self.family, &kind.views, kind.side)
        } else {
            h.explains(self.family, &kind.views, kind.side)
        }
    }

    /// For every hypothesis, the right lines it would have made wrong.
    fn contradictions(&self) -> Vec<usize> {
        hypotheses::all()
            .iter()
            .map(|h| {
                self.kinds
                    .iter()
                    .enumerate()
                    .filter(|(i, (kind, _))| {
                        !self.tally.failing(kind) && !self.neutral(*i) && !self.explains(h, *i)
                    })
                    .map(|(_, (_, count))| count)
                    .sum()
            })
            .collect()
    }

    /// Every candidate scored on the failing kinds `left`, best first.
    fn ranked<'h>(&self, left: &[usize], contradicted: &[usize]) -> Vec<Scored<'h>> {
        let mut scored: Vec<Scored<'h>> = hypotheses::all()
            .iter()
            .zip(contradicted)
            .filter_map(|(h, &contradicted)| {
                let kinds: Vec<usize> = left
                    .iter()
                    .copied()
                    .filter(|&i| self.explains(h, i))
                    .collect();
                (!kinds.is_empty()).then(|| self.scored(Candidate::Formula(h), kinds, contradicted))
            })
            .collect();
        // Each set once, in the order first met (a set is looked up, not searched for).
        let mut seen = std::collections::HashSet::new();
        let mut sets: Vec<&Vec<Code>> = Vec::new();
        for &i in left {
            for set in &self.kinds[i].0.alternatives {
                if !set.is_empty() && seen.insert(set) {
                    sets.push(set);
                }
            }
        }
        for set in sets {
            let kinds: Vec<usize> = left
                .iter()
                .copied()
                .filter(|&i| self.kinds[i].0.alternatives.contains(set))
                .collect();
            scored.push(self.scored(Candidate::Line(set.clone()), kinds, 0));
        }
        scored.sort_by(Scored::rank);
        scored
    }

    /// `candidate` scored on `kinds`.
    fn scored<'h>(
        &self,
        candidate: Candidate<'h>,
        kinds: Vec<usize>,
        contradicted: usize,
    ) -> Scored<'h> {
        let mut explained = Census::default();
        for &i in &kinds {
            let (kind, count) = self.kinds[i];
            explained.add(kind.side, kind.past_critical, count);
        }
        let one_side = self.tally.confined_to_one_side(&explained);
        let (codes, conditions) = match &candidate {
            Candidate::Formula(h) => (h.codes(), h.conditions()),
            Candidate::Line(set) => (line_codes(self.api, set, one_side), set.len()),
        };
        let codes = self.renamed(codes, &explained);
        let mut scored = Scored {
            candidate,
            kinds,
            explained,
            contradicted,
            penalty: 0,
            prior: codes.iter().map(|&c| prior(self.api, c)).sum(),
            conditions,
            codes,
        };
        scored.penalty = self.penalty(&scored);
        scored
    }

    /// `codes` named by the compound cause the log shows, where it shows one: lines that never
    /// transmit, down to small angles where no ratio makes k negative, are the cosine's sign
    /// lost in the Fresnel term, not the test for total internal reflection; a normal that
    /// does not face the ray on a few lines of both sides, where the code turns it on all the
    /// others, was turned by a side decided with another normal.
    fn renamed(&self, codes: Vec<Code>, explained: &Census) -> Vec<Code> {
        match codes.as_slice() {
            [Code::FalseTir] if self.tally.never_transmits(explained) => {
                vec![Code::FresnelCosSign]
            }
            [Code::NormalNotFacing]
                if self.family == Family::Along && self.tally.normals_mixed(explained) =>
            {
                vec![Code::NormalsMixed]
            }
            _ => codes,
        }
    }

    /// The fix of `best`, with what to print where the log cannot tell a normal that does not
    /// face the ray from one turned by a side decided with another normal (`entering`).
    fn fix_text(&self, best: &Scored<'_>, renderer: Option<Renderer>) -> String {
        let fix = fixes::fix(renderer, self.api, &self.fix_of(best));
        let [against, facing] = self.tally.normal_faces;
        let unsided = self.tally.told[0] < self.tally.judged.total();
        if best.codes[0] == Code::NormalNotFacing && unsided && 2 * against < facing {
            return format!("{fix} {}", t!("check-fix-normals-print"));
        }
        fix
    }

    /// What only many lines show against a candidate: a mistake that cannot depend on the
    /// side the ray comes from, seen on one side only; a normal said to face the wrong way,
    /// or an incident vector said to be reversed (which would make the normal point inward),
    /// where the normal is the outward one on every line.
    /// And a normal that does not face rays entering the object (an inward normal) is less
    /// likely than the root's sign, where lines entering show it.
    fn penalty(&self, scored: &Scored<'_>) -> u32 {
        let one_side = self.tally.confined_to_one_side(&scored.explained);
        let outward = self.tally.normal_always_outward();
        let codes: u32 = scored
            .codes
            .iter()
            .map(|code| match code {
                Code::IncidentReversed if one_side => 2,
                Code::IncidentReversed | Code::NormalNotFacing if outward => 1,
                _ => 0,
            })
            .sum();
        let inward = match &scored.candidate {
            Candidate::Formula(h) => {
                self.family != Family::Back
                    && scored.explained.outside > 0
                    && h.mistakes
                        .iter()
                        .any(|m| m.slip == Slip::Normal && m.sides != Sides::Leaving)
            }
            Candidate::Line(_) => false,
        };
        codes + u32::from(inward)
    }

    /// The finding for `best`, with the candidates the log cannot tell from it.
    fn finding(
        &self,
        best: &Scored<'_>,
        ranked: &[Scored<'_>],
        renderer: Option<Renderer>,
    ) -> Finding {
        let mut alike: Vec<&'static str> = Vec::new();
        let mut tell_apart: Vec<&'static str> = Vec::new();
        for other in ranked.iter().skip(1) {
            // Alike: the same lines, as simply (a pair whose second mistake touches no line
            // of the log is not another reading of it).
            let same = other.kinds == best.kinds
                && other.score() == best.score()
                && other.conditions == best.conditions
                && other.penalty == best.penalty;
            let name = other.codes[0].name();
            // A line's own name for what a mistake of the formula explains is its symptom.
            let symptom = other.is_line() && !best.is_line();
            if !same || symptom || other.codes.contains(&best.codes[0]) || alike.contains(&name) {
                continue;
            }
            alike.push(name);
            for field in self.telling_fields(&best.codes, &other.codes) {
                if !tell_apart.contains(&field) {
                    tell_apart.push(field);
                }
            }
        }
        Finding {
            code: best.codes[0].name(),
            lines: best.explained.total(),
            place: self.tally.place(&best.explained),
            fix: self.fix_text(best, renderer),
            with: best.codes[1..].iter().map(|c| c.name()).collect(),
            alike,
            tell_apart,
        }
    }

    /// What the fix of `best` is about.
    fn fix_of(&self, best: &Scored<'_>) -> Fix {
        match &best.candidate {
            Candidate::Formula(h) => {
                let shown = best
                    .kinds
                    .iter()
                    .filter(|&&i| h.in_arguments(self.family, &self.kinds[i].0.views))
                    .map(|&i| self.kinds[i].1)
                    .sum::<usize>();
                let location = if 2 * shown > best.explained.total() {
                    Location::Arguments
                } else {
                    Location::Code
                };
                let first = h.first();
                Fix {
                    code: best.codes[0],
                    slip: Some(first.slip),
                    sides: first.sides,
                    location,
                }
            }
            Candidate::Line(_) => {
                // A call's own explanations name its arguments' mistakes as they were passed.
                let argument = matches!(
                    best.codes[0],
                    Code::EtaInverted | Code::IncidentReversed | Code::NormalNotFacing
                );
                Fix {
                    code: best.codes[0],
                    slip: None,
                    sides: self.sides_of(&best.explained),
                    location: if argument && self.api.is_some() {
                        Location::Arguments
                    } else {
                        Location::Code
                    },
                }
            }
        }
    }

    /// The side lines are confined to, if they are.
    fn sides_of(&self, lines: &Census) -> Sides {
        match (lines.outside, lines.inside, lines.unknown_side) {
            (0, 1.., 0) if self.tally.judged.outside > 0 => Sides::Leaving,
            (1.., 0, 0) if self.tally.judged.inside > 0 => Sides::Entering,
            _ => Sides::Both,
        }
    }

    /// The logged fields that would tell the mistakes `a` from `b`, of those not logged on
    /// every line already: the ray's direction of travel shows which way the incident vector
    /// points; whether the ray enters shows which mistakes depend on the side.
    fn telling_fields(&self, a: &[Code], b: &[Code]) -> Vec<&'static str> {
        let differ = |code: Code| a.contains(&code) != b.contains(&code);
        let all = self.tally.judged.total();
        let mut fields = Vec::new();
        if differ(Code::IncidentReversed) && self.tally.told[1] < all {
            fields.push("travel");
        }
        let sided = [
            Code::EtaInverted,
            Code::NoFlipInside,
            Code::OtherRoot,
            Code::NormalNotFacing,
        ];
        if sided.into_iter().any(differ) && self.tally.told[0] < all {
            fields.push("entering");
        }
        fields
    }

    /// The finding for failing lines nothing explains.
    fn unexplained(&self, left: &[usize]) -> Finding {
        let mut lines = Census::default();
        for &i in left {
            let (kind, count) = self.kinds[i];
            lines.add(kind.side, kind.past_critical, count);
        }
        let fix = Fix {
            code: Code::NotTheApiResult,
            slip: None,
            sides: self.sides_of(&lines),
            location: Location::Code,
        };
        Finding {
            code: Code::NotTheApiResult.name(),
            lines: lines.total(),
            place: self.tally.place(&lines),
            fix: fixes::fix(None, self.api, &fix),
            with: Vec::new(),
            alike: Vec::new(),
            tell_apart: Vec::new(),
        }
    }

    /// The finding for lines whose printed digits cannot tell them right or wrong, if there
    /// are: the log's precision is too low.
    fn undecided(&self) -> Option<Finding> {
        let mut lines = Census::default();
        for (kind, count) in &self.kinds {
            if kind.unchecked == Some(Missing::Digits) {
                lines.add(kind.side, kind.past_critical, *count);
            }
        }
        (lines.total() > 0).then(|| Finding {
            code: TOO_FEW_DIGITS,
            lines: lines.total(),
            place: self.tally.place(&lines),
            fix: t!("check-too-few-digits-fix"),
            with: Vec::new(),
            alike: Vec::new(),
            tell_apart: Vec::new(),
        })
    }

    /// The finding for right lines whose ratio cannot be told right or wrong, if there are.
    fn unchecked(&self) -> Option<Finding> {
        let mut lines = Census::default();
        let mut entering = 0;
        for (kind, count) in &self.kinds {
            if let (Some(missing @ (Missing::Entering | Missing::Indices)), true) =
                (kind.unchecked, kind.ok)
            {
                lines.add(kind.side, kind.past_critical, *count);
                entering += if missing == Missing::Entering {
                    *count
                } else {
                    0
                };
            }
        }
        (lines.total() > 0).then(|| {
            let fix = if 2 * entering > lines.total() {
                t!("check-unchecked-log-entering")
            } else {
                t!("check-unchecked-pass-indices")
            };
            Finding {
                code: UNCHECKED,
                lines: lines.total(),
                place: self.tally.place(&lines),
                fix,
                with: Vec::new(),
                alike: Vec::new(),
                tell_apart: Vec::new(),
            }
        })
    }
}

impl LogTally {
    /// Whether the code transmits nothing, at any angle, on the sides of `lines`, lines at
    /// small angles (where no ratio makes k negative) among them.
    fn never_transmits(&self, lines: &Census) -> bool {
        let sides = [
            (lines.outside, Some(Side::Outside)),
            (lines.inside, Some(Side::Inside)),
            (lines.unknown_side, None),
        ];
        let mut touched = sides
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(_, s)| *s)
            .peekable();
        touched.peek().is_some()
            && touched.all(|side| {
                let mut bands = self.bands.iter().filter(|((s, _), _)| *s == side);
                let none = bands.clone().all(|(_, b)| b.transmitted == 0);
                none && bands.any(|((_, band), b)| *band < SMALL_ANGLE_BANDS && b.refused > 0)
            })
    }

    /// Whether the normal passed does not face the ray on `lines`, from both sides, while it
    /// faces it on most lines: the code turns it, by a side decided with another normal.
    fn normals_mixed(&self, lines: &Census) -> bool {
        let [against, facing] = self.normal_faces;
        lines.outside > 0 && lines.inside > 0 && against > 0 && 2 * against < facing
    }

    /// Whether the normal is the outward one on every line that says which way the ray goes.
    fn normal_always_outward(&self) -> bool {
        self.normal_outward[1] > 0 && self.normal_outward[0] == 0
    }

    /// Whether `lines` are all on one side while lines on the other side were judged.
    fn confined_to_one_side(&self, lines: &Census) -> bool {
        let only_inside = lines.outside == 0 && lines.inside > 0 && self.judged.outside > 0;
        let only_outside = lines.inside == 0 && lines.outside > 0 && self.judged.inside > 0;
        lines.unknown_side == 0 && (only_inside || only_outside)
    }

    /// On which kind of line `lines` are, in words.
    fn place(&self, lines: &Census) -> String {
        let (count, all) = (lines.total(), self.judged.total());
        if count == all {
            return t!("check-where-every", count = count);
        }
        let every_on = |part: usize, of: usize| part == count && part == of;
        if every_on(lines.inside, self.judged.inside) {
            return t!("check-where-inside", count = count);
        }
        if every_on(lines.outside, self.judged.outside) {
            return t!("check-where-outside", count = count);
        }
        if every_on(lines.past_critical, self.judged.past_critical) {
            return t!("check-where-past-critical", count = count);
        }
        if lines.unknown_side == 0 {
            let (inside, outside) = (lines.inside, lines.outside);
            return t!(
                "check-where-some-sides",
                count = count,
                all = all,
                inside = inside,
                outside = outside
            );
        }
        t!("check-where-some", count = count, all = all)
    }
}

/// The codes a line's own explanation is reported by: a term along the normal with the
/// wrong sign on the rays from inside only is a normal that does not face the ray there (the
/// outward normal used in that term where the ray leaves).
fn line_codes(api: Option<Api>, codes: &[Code], one_side: bool) -> Vec<Code> {
    match codes {
        [Code::NormalTermSign] if api.is_none() && one_side => vec![Code::NormalNotFacing],
        [] => vec![Code::NotTheApiResult],
        codes => codes.to_vec(),
    }
}

/// How unlikely a mistake is in `api`'s code (lower is likelier), for hypotheses that explain
/// the same lines: eta upside down and an unflipped normal lead in GLSL and the book; the
/// sign of wi leads in pbrt and Mitsuba.
fn prior(api: Option<Api>, code: Code) -> u32 {
    match (api, code) {
        (Some(Api::Glsl | Api::Rtiow) | None, Code::EtaInverted) => 0,
        (Some(Api::Glsl | Api::Rtiow) | None, Code::NormalNotFacing | Code::NormalsMixed) => 1,
        (Some(Api::Pbrt | Api::Mitsuba), Code::EtaInverted) => 0,
        (Some(Api::Pbrt | Api::Mitsuba), Code::IncidentReversed) => 1,
        (_, Code::NoFlipInside | Code::NormalTermSign | Code::OtherRoot | Code::AcrossSign) => 2,
        (_, Code::IncidentReversed) => 3,
        (Some(Api::Pbrt | Api::Mitsuba), Code::NormalNotFacing) => 3,
        _ => 4,
    }
}

//! The diagnosis of a whole log: which one mistake in the student's code explains the lines
//! that went wrong, on which kind of line it shows, and the fix in their renderer's own code.
//!
//! A bug is one line of code, wrong the same way on every call it touches. So the diagnosis
//! is one ranked search over hypotheses ([`hypotheses`]): every single-line mistake of the
//! refraction formula (the ratio, whole or in one of its parts, on one side or both; the
//! normal's orientation; the incident vector's sign; the root's sign; the term along N) and
//! every pair of them, each reproducing some lines ([`formula`]), beside the mistakes each line
//! was given on its own (a missed or false total internal reflection, inputs that are not
//! unit length...). A hypothesis scores the failing lines it reproduces less the right lines
//! it would have made wrong, so a cause that explains false total internal reflections, missed
//! ones and wrong directions together (the ratio inverted) beats each of its symptoms, and a
//! mistake confined to the side it shows on beats the same mistake everywhere. Ties go to
//! fewer mistakes and conditions, then to what only many lines show (a normal that is the
//! outward one on every line), then to how often students make that mistake. The best is the
//! verdict; lines it leaves get the next best, and so on. A log whose judged lines are all
//! right says `none`; one whose lines cannot be told right from wrong says `unchecked`.
//!
//! Renderers that sample reflection with probability F (Mitsuba, Tungsten, Cycles) may log
//! nothing where the ray refracts: such a line is a sampled reflection when the log transmits
//! at the same angles on the same side, or when F makes that many reflections likely enough;
//! otherwise the code never transmits there, and the line is wrong.
//!
//! Lines are counted, not kept: a million-line log costs a counter per kind of line.

pub(crate) mod code;
mod fixes;
pub(crate) mod formula;
pub(crate) mod hypotheses;
mod rank;
pub(crate) mod renderer;

use std::collections::BTreeMap;

use refraction_i18n::t;
use refraction_kernel::api::Api;
use serde::Serialize;

pub use code::Code;
pub(crate) use hypotheses::{Codes, Readings, View};
pub(crate) use refraction_model::log_map::Side;
pub use renderer::Renderer;

/// How wide a band of angles of incidence the sampling of reflection is judged in, degrees.
pub(crate) const BIN_DEG: f64 = 5.0;

/// The bands of angles of incidence (below 15°) where no ratio of real glass, upside down or
/// squared, makes k = 1 − μ²·sin²θi negative (μ < 3.8): a code that transmits nothing there
/// is not wrong in its test for total internal reflection.
pub(crate) const SMALL_ANGLE_BANDS: u8 = 3;

/// Below this probability, reflections at every line of a band of angles are not sampling:
/// the code never transmits there.
const SAMPLING_UNLIKELY: f64 = 1e-3;

/// Why a line's ratio cannot be told right or wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Missing {
    /// The indices are given (`--inside`, `--outside`) but not the side the ray comes from.
    Entering,
    /// Neither the indices nor `from` and `to`.
    Indices,
    /// The printed digits cannot decide a sign the verdict rests on (of N·I, of k, of a
    /// root): the line is wrong as printed but right for numbers within their rounding.
    Digits,
}

/// Which truth fields a line logged (so that the diagnosis does not ask for them).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Told {
    /// `entering` (or what gives it: `--normal`, pbrt's or Mitsuba's normal with the indices).
    pub entering: bool,
    /// `travel`.
    pub travel: bool,
}

/// What one judged line tells the diagnosis of the whole log.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Evidence {
    /// Whether the line is right.
    pub ok: bool,
    /// The line's own explanations, each a set of mistakes, the likeliest first (empty when
    /// the line is right, or when nothing explains it).
    pub alternatives: Vec<Vec<Code>>,
    /// Its readings: the argument mistakes each assumes and the formula's variants that
    /// reproduce what came back.
    pub views: Vec<View>,
    /// The side the ray arrives from, when the line or the API's convention says.
    pub side: Option<Side>,
    /// Whether the right answer is total internal reflection.
    pub past_critical: bool,
    /// Whether the logged normal points back toward where the ray comes from, on a line that
    /// says whether the ray enters: `Some(true)` when it does exactly when the ray enters
    /// (an outward normal), `Some(false)` when it does exactly when the ray leaves.
    pub normal_outward: Option<bool>,
    /// Whether the normal passed to the API faces the ray (against GLSL's `I`, the book's
    /// `uv`), for an API that needs it to; `None` for one that turns it itself.
    pub normal_faces: Option<bool>,
    /// The band of angles of incidence the line is in ([`BIN_DEG`] wide).
    pub band: u8,
    /// Whether the code sent the ray along a direction (it transmitted).
    pub transmitted: bool,
    /// For a line that logged nothing where the ray refracts, in a renderer that samples
    /// reflection: ln F, the log of the probability of that reflection. The line is right
    /// if the log shows sampling at these angles.
    pub sample: Option<f64>,
    /// Why the line, right as far as its API goes, cannot be told right or wrong.
    pub unchecked: Option<Missing>,
    /// The truth fields the line logged.
    pub told: Told,
}

/// The explanations of a reflection read as sampled, should the log show that the code never
/// transmits at its angles: a false total internal reflection, or (`twice`, where the ratio
/// squared is past its critical angle) a refraction done twice.
#[must_use]
pub(crate) fn sampled_alternatives(twice: bool) -> Vec<Vec<Code>> {
    let mut sets = vec![vec![Code::FalseTir]];
    if twice {
        sets.push(vec![Code::RefractedTwice]);
    }
    sets
}

/// The band of `incidence_deg` for [`Evidence::band`].
#[must_use]
pub(crate) fn band(incidence_deg: f64) -> u8 {
    // Within [0, 90]: 18 bands.
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let band = (incidence_deg.clamp(0.0, 89.999) / BIN_DEG) as u8;
    band
}

/// The kind of a line: everything the ranking looks at, so that lines of one kind are counted
/// together.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Kind {
    ok: bool,
    alternatives: Vec<Vec<Code>>,
    views: Vec<View>,
    side: Option<Side>,
    past_critical: bool,
    /// The band of a sampled reflection (the line's verdict waits for its band's).
    sample: Option<u8>,
    unchecked: Option<Missing>,
}

/// Lines of one side and whether they are past the critical angle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Census {
    outside: usize,
    inside: usize,
    unknown_side: usize,
    past_critical: usize,
}

impl Census {
    fn add(&mut self, side: Option<Side>, past_critical: bool, count: usize) {
        match side {
            Some(Side::Outside) => self.outside += count,
            Some(Side::Inside) => self.inside += count,
            None => self.unknown_side += count,
        }
        if past_critical {
            self.past_critical += count;
        }
    }

    fn total(&self) -> usize {
        self.outside + self.inside + self.unknown_side
    }
}

/// The lines of one side and band of angles: whether the code transmits there, and how
/// likely its reflections are as samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Band {
    transmitted: usize,
    /// Lines that transmitted nothing where the ray refracts.
    refused: usize,
    log_f: f64,
}

impl Band {
    /// Whether the reflections of this band are sampled: the code transmits here too, or
    /// F makes that many reflections likely enough.
    fn sampling(&self) -> bool {
        self.transmitted > 0 || self.log_f > SAMPLING_UNLIKELY.ln()
    }
}

/// The counts a log's diagnosis is made from, added to line by line.
#[derive(Clone, Debug, Default)]
pub struct LogTally {
    kinds: BTreeMap<Kind, usize>,
    bands: BTreeMap<(Option<Side>, u8), Band>,
    judged: Census,
    skipped: usize,
    unreadable: usize,
    /// Lines with the normal outward (true) or inward (false) as the ray's side tells.
    normal_outward: [usize; 2],
    /// Lines that told `entering`, and `travel`.
    told: [usize; 2],
    /// Lines whose normal passed does not face the ray (0), and does (1), for APIs that
    /// need it to.
    normal_faces: [usize; 2],
    /// Why the first line that could not be read as a call could not.
    first_unreadable: Option<String>,
}

/// One finding of the diagnosis: a mistake (or none), the lines it explains and the fix.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Finding {
    /// The mistake's code; `none` for a log without one, `unchecked` for one whose lines
    /// cannot be told right or wrong, `too_few_digits` for lines whose printed digits cannot.
    pub code: &'static str,
    /// How many judged lines it explains (every judged line for `none`).
    pub lines: usize,
    /// On which kind of line it shows, in words.
    #[serde(rename = "where")]
    pub place: String,
    /// The fix, in the renderer's own words and code (empty for `none`); for `unchecked`,
    /// what to log or pass; for `unreadable` where no line was judged, why the first line
    /// could not be.
    pub fix: String,
    /// The other mistake of a pair, when one mistake alone does not explain the lines.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub with: Vec<&'static str>,
    /// Other mistakes that explain exactly these lines as well, when the log cannot tell.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub alike: Vec<&'static str>,
    /// The logged fields that would tell them apart.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tell_apart: Vec<&'static str>,
}

/// The `--summary` file: the counts and the ranked diagnosis, the verdict first.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Summary {
    /// Lines read (the non-empty ones).
    pub lines: usize,
    /// Lines judged: calls read and checked.
    pub judged: usize,
    /// Judged lines that are right (sampled reflections included).
    pub ok: usize,
    /// Lines left out: not matching the pattern, or unreadable.
    pub skipped: usize,
    /// Lines that logged nothing where the ray refracts, read as sampled reflections.
    pub sampled: usize,
    /// The findings, the verdict first.
    pub diagnosis: Vec<Finding>,
}

/// The code of a log whose judged lines are all right.
pub(crate) const NONE: &str = "none";

/// The code of a log whose lines cannot be told right or wrong (see [`Missing`]).
pub(crate) const UNCHECKED: &str = "unchecked";

/// The code of a log some of whose lines cannot be told right or wrong from their printed
/// digits (see [`Missing::Digits`]): no line is wrong, but its print is too coarse.
pub(crate) const TOO_FEW_DIGITS: &str = "too_few_digits";

/// The code of a log whose judged lines are all right but some of whose lines could not be read
/// (issue 40: the summary said `none` while the status said a failure).
pub(crate) const UNREADABLE: &str = "unreadable";

/// What the verdict says, for the exit status.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// No line was judged.
    NothingJudged,
    /// Every judged line is right.
    None,
    /// No line is wrong, but the log cannot tell right from wrong.
    Unchecked,
    /// No judged line is wrong, but some lines could not be read.
    Unreadable,
    /// A mistake.
    Mistake,
}

impl Finding {
    /// The finding in a sentence: the verdict's (`first`) or a later one's.
    #[must_use]
    pub fn sentence(&self, first: bool) -> String {
        if self.code == UNREADABLE && self.fix.is_empty() {
            return t!("check-diagnosis-unreadable", lines = self.lines);
        }
        if self.code == UNREADABLE {
            return t!(
                "check-diagnosis-none-judged",
                lines = self.lines,
                error = &self.fix
            );
        }
        if self.code == TOO_FEW_DIGITS {
            return t!(
                "check-diagnosis-too-few-digits",
                place = &self.place,
                fix = &self.fix
            );
        }
        if self.code == UNCHECKED {
            return t!(
                "check-diagnosis-unchecked",
                place = &self.place,
                fix = &self.fix
            );
        }
        let Some(code) = Code::named(self.code) else {
            return t!("check-diagnosis-none", place = &self.place);
        };
        let meaning = match self.with.first() {
            Some(&other) => format!("{}; {other}", code.meaning()),
            None => code.meaning(),
        };
        let (name, place, fix) = (self.code, &self.place, &self.fix);
        let mut text = if first {
            t!(
                "check-diagnosis-verdict",
                code = name,
                meaning = meaning,
                place = place,
                fix = fix
            )
        } else {
            t!(
                "check-diagnosis-also",
                code = name,
                meaning = meaning,
                place = place,
                fix = fix
            )
        };
        if !self.alike.is_empty() {
            let alike = self.alike.join(", ");
            let said = if self.tell_apart.is_empty() {
                t!("check-diagnosis-alike-no-field", alike = alike)
            } else {
                let fields = self.tell_apart.join(", ");
                t!("check-diagnosis-alike", alike = alike, fields = fields)
            };
            text = format!("{text} {said}");
        }
        text
    }
}

/// The most bytes of a file read to tell whether it is a summary: one holds a few findings of
/// a few hundred bytes each, so a larger file is something else.
pub const MAX_SUMMARY_BYTES: u64 = 1 << 16;

/// Whether `bytes`, a whole file, is a summary `check --summary` wrote: one JSON object with
/// exactly a [`Summary`]'s keys, in any order (another program may have written it back with its
/// keys sorted or reordered), so that it may be replaced by the next.
#[must_use]
pub fn looks_like_summary(bytes: &[u8]) -> bool {
    const KEYS: [&str; 6] = ["diagnosis", "judged", "lines", "ok", "sampled", "skipped"];
    serde_json::from_slice::<serde_json::Map<String, serde_json::Value>>(bytes).is_ok_and(|map| {
        map.len() == KEYS.len()
            && KEYS.iter().all(|key| map.contains_key(*key))
            && map["diagnosis"].is_array()
    })
}

impl Summary {
    /// The diagnosis in sentences, the verdict first (one saying so when no line was judged).
    #[must_use]
    pub fn sentences(&self) -> Vec<String> {
        if self.diagnosis.is_empty() {
            return vec![t!("check-diagnosis-no-lines", lines = self.lines)];
        }
        self.diagnosis
            .iter()
            .enumerate()
            .map(|(i, finding)| finding.sentence(i == 0))
            .collect()
    }

    /// What the verdict is, for the exit status.
    #[must_use]
    pub fn verdict(&self) -> Verdict {
        match self.diagnosis.first().map(|f| f.code) {
            None => Verdict::NothingJudged,
            Some(NONE) => Verdict::None,
            Some(UNCHECKED | TOO_FEW_DIGITS) => Verdict::Unchecked,
            Some(UNREADABLE) => Verdict::Unreadable,
            Some(_) => Verdict::Mistake,
        }
    }
}

impl LogTally {
    /// Counts one judged line.
    pub fn add(&mut self, evidence: Evidence) {
        self.judged.add(evidence.side, evidence.past_critical, 1);
        if let Some(outward) = evidence.normal_outward {
            self.normal_outward[usize::from(outward)] += 1;
        }
        self.told[0] += usize::from(evidence.told.entering);
        self.told[1] += usize::from(evidence.told.travel);
        if let Some(faces) = evidence.normal_faces {
            self.normal_faces[usize::from(faces)] += 1;
        }
        let band = self
            .bands
            .entry((evidence.side, evidence.band))
            .or_default();
        band.transmitted += usize::from(evidence.transmitted);
        band.refused += usize::from(!evidence.transmitted && !evidence.past_critical);
        band.log_f += evidence.sample.unwrap_or(0.0);
        let kind = Kind {
            ok: evidence.ok,
            alternatives: evidence.alternatives,
            views: evidence.views,
            side: evidence.side,
            past_critical: evidence.past_critical,
            sample: evidence.sample.map(|_| evidence.band),
            unchecked: evidence.unchecked.filter(|_| evidence.ok),
        };
        *self.kinds.entry(kind).or_default() += 1;
    }

    /// Counts a line that was not judged: not matching the pattern.
    pub fn skip(&mut self) {
        self.skipped += 1;
    }

    /// Counts a line that could not be read as a call.
    pub fn unreadable(&mut self) {
        self.unreadable += 1;
    }

    /// Counts a line that could not be read as a call for the reason `why` gives (kept for
    /// the first such line: a log none of whose lines is judged says why).
    pub fn unreadable_for(&mut self, why: impl FnOnce() -> String) {
        self.unreadable();
        if self.first_unreadable.is_none() {
            self.first_unreadable = Some(why());
        }
    }

    /// Whether a kind's lines are wrong: judged so, or reflections where the log shows no
    /// sampling.
    fn failing(&self, kind: &Kind) -> bool {
        !kind.ok
            || kind
                .sample
                .is_some_and(|band| !self.sampling(kind.side, band))
    }

    /// Whether the reflections logged on `side` in `band` are sampled (see [`Band::sampling`]).
    fn sampling(&self, side: Option<Side>, band: u8) -> bool {
        self.bands.get(&(side, band)).is_some_and(Band::sampling)
    }

    /// Whether the diagnosis of the whole log counts a judged line with `evidence` wrong:
    /// judged wrong on its own, or a reflection logged where the code never transmits (the
    /// line's own verdict waits for its band's). For a caller that reports each call once
    /// the log is whole (`check_records`).
    #[must_use]
    pub(crate) fn counts_wrong(&self, evidence: &Evidence) -> bool {
        !evidence.ok || (evidence.sample.is_some() && !self.sampling(evidence.side, evidence.band))
    }

    /// The ranked diagnosis for a log of `api`'s calls (`None`: any renderer's own), whose
    /// fixes quote `renderer`'s code where it is one the docs name.
    #[must_use]
    pub fn summary(&self, api: Option<Api>, renderer: Option<Renderer>) -> Summary {
        let (mut ok, mut sampled) = (0, 0);
        for (kind, &count) in &self.kinds {
            // A line its digits cannot decide is neither right nor wrong.
            if !self.failing(kind) && kind.unchecked != Some(Missing::Digits) {
                ok += count;
                sampled += if kind.sample.is_some() { count } else { 0 };
            }
        }
        Summary {
            lines: self.judged.total() + self.skipped + self.unreadable,
            judged: self.judged.total(),
            ok,
            skipped: self.skipped + self.unreadable,
            sampled,
            diagnosis: self.with_unreadable(rank::findings(self, api, renderer)),
        }
    }

    /// `findings` with the lines that could not be read as the verdict where nothing else is
    /// wrong: a log with unread lines is not passed, and its summary says so as its status does.
    /// A log none of whose lines is judged, although some were read by the pattern, says why
    /// the first could not be judged (issue 43: not "check the pattern" when it is right).
    fn with_unreadable(&self, mut findings: Vec<Finding>) -> Vec<Finding> {
        let clean = findings
            .first()
            .is_none_or(|f| [NONE, UNCHECKED, TOO_FEW_DIGITS].contains(&f.code));
        if self.unreadable > 0 && clean {
            let why = if findings.is_empty() {
                self.first_unreadable.clone().unwrap_or_default()
            } else {
                String::new()
            };
            findings.retain(|f| f.code != NONE);
            findings.insert(
                0,
                Finding {
                    code: UNREADABLE,
                    lines: self.unreadable,
                    place: String::new(),
                    fix: why,
                    with: Vec::new(),
                    alike: Vec::new(),
                    tell_apart: Vec::new(),
                },
            );
        }
        findings
    }
}

#[cfg(test)]
mod tests;

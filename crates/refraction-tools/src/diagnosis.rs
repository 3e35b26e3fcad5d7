//! The diagnosis of a whole log: which one mistake in the student's code explains the lines
//! that went wrong, on which kind of line it shows, and the fix in their API's own code.
//!
//! A bug is one line of code, wrong the same way on every call it touches. So each judged
//! line's explanations (the sets of mistakes that reproduce what it logged) are counted, and
//! each explanation is ranked as a hypothesis for the whole log: first by how many failing
//! lines it explains, then by what only many lines show: which lines fail (from inside only,
//! past the critical angle only, all of them), what stays the same (a normal always on the side
//! the ray comes from when it enters is the outward one), and, last, how often students make
//! that mistake in that API. The best hypothesis is the verdict; lines it leaves unexplained
//! get the next best, and so on. A log whose judged lines are all right says `none`.
//!
//! Lines are counted, not kept: a million-line log costs a handful of counters per kind of
//! line.

use std::collections::BTreeMap;

use refraction_i18n::t;
use refraction_kernel::api::Api;
use serde::Serialize;

use crate::api_check::Code;
pub use refraction_model::log_map::Side;

/// What one judged line tells the diagnosis of the whole log.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Evidence {
    /// Whether the line is right.
    pub ok: bool,
    /// The line's explanations, each a set of mistakes, the likeliest first (empty when the
    /// line is right, or when nothing explains it).
    pub alternatives: Vec<Vec<Code>>,
    /// The side the ray arrives from, when the line or the API's convention says.
    pub side: Option<Side>,
    /// Whether the right answer is total internal reflection.
    pub past_critical: bool,
    /// Whether the logged normal points back toward where the ray comes from, on a line that
    /// says whether the ray enters: `Some(true)` when it does exactly when the ray enters
    /// (an outward normal), `Some(false)` when it does exactly when the ray leaves.
    pub normal_outward: Option<bool>,
}

/// The kind of a failing line: everything the ranking looks at, so that lines of one kind are
/// counted together.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Kind {
    alternatives: Vec<Vec<Code>>,
    side: Option<Side>,
    past_critical: bool,
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

/// The counts a log's diagnosis is made from, added to line by line.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LogTally {
    failing: BTreeMap<Kind, usize>,
    judged: Census,
    ok: usize,
    skipped: usize,
    unreadable: usize,
    /// Lines with the normal outward (true) or inward (false) as the ray's side tells.
    normal_outward: [usize; 2],
}

/// One finding of the diagnosis: a mistake (or none), the lines it explains and the fix.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Finding {
    /// The mistake's code, `none` for a log without one.
    pub code: &'static str,
    /// How many judged lines it explains (every judged line for `none`).
    pub lines: usize,
    /// On which kind of line it shows, in words.
    #[serde(rename = "where")]
    pub place: String,
    /// The fix, in the API's own words and code (empty for `none`).
    pub fix: String,
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
    /// Judged lines that are right.
    pub ok: usize,
    /// Lines left out: not matching the pattern, or unreadable.
    pub skipped: usize,
    /// The findings, the verdict first.
    pub diagnosis: Vec<Finding>,
}

impl Finding {
    /// The finding in a sentence: the verdict's (`first`) or a later one's.
    #[must_use]
    pub fn sentence(&self, first: bool) -> String {
        let Some(code) = Code::named(self.code) else {
            return t!("check-diagnosis-none", place = &self.place);
        };
        let (name, meaning, place, fix) = (self.code, code.meaning(), &self.place, &self.fix);
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
            let (alike, fields) = (self.alike.join(", "), self.tell_apart.join(", "));
            text = format!(
                "{text} {}",
                t!("check-diagnosis-alike", alike = alike, fields = fields)
            );
        }
        text
    }
}

/// Whether a file that starts with `bytes` is a summary `check --summary` wrote (its JSON's
/// first key, in the order it is written, is `diagnosis`): one that may be replaced by the next.
#[must_use]
pub fn looks_like_summary(bytes: &[u8]) -> bool {
    bytes.trim_ascii_start().starts_with(br#"{"diagnosis":"#)
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
}

/// A hypothesis being ranked: a set of mistakes and the failing lines it explains.
#[derive(Clone, Debug)]
struct Hypothesis {
    codes: Vec<Code>,
    explained: Census,
    penalty: u32,
    prior: u32,
}

impl LogTally {
    /// Counts one judged line.
    pub fn add(&mut self, evidence: &Evidence) {
        self.judged.add(evidence.side, evidence.past_critical, 1);
        if let Some(outward) = evidence.normal_outward {
            self.normal_outward[usize::from(outward)] += 1;
        }
        if evidence.ok {
            self.ok += 1;
            return;
        }
        let kind = Kind {
            alternatives: evidence.alternatives.clone(),
            side: evidence.side,
            past_critical: evidence.past_critical,
        };
        *self.failing.entry(kind).or_default() += 1;
    }

    /// Counts a line that was not judged: not matching the pattern.
    pub fn skip(&mut self) {
        self.skipped += 1;
    }

    /// Counts a line that could not be read as a call.
    pub fn unreadable(&mut self) {
        self.unreadable += 1;
    }

    /// The ranked diagnosis for a log of `api`'s calls (`None`: the generic `check`).
    #[must_use]
    pub fn summary(&self, api: Option<Api>) -> Summary {
        Summary {
            lines: self.judged.total() + self.skipped + self.unreadable,
            judged: self.judged.total(),
            ok: self.ok,
            skipped: self.skipped + self.unreadable,
            diagnosis: self.findings(api),
        }
    }

    /// Whether the normal is the outward one on every line that says which way the ray goes.
    fn normal_always_outward(&self) -> bool {
        self.normal_outward[1] > 0 && self.normal_outward[0] == 0
    }

    /// The findings, the verdict first; none when no line was judged.
    fn findings(&self, api: Option<Api>) -> Vec<Finding> {
        if self.judged.total() == 0 {
            return Vec::new();
        }
        if self.failing.is_empty() {
            return vec![Finding {
                code: "none",
                lines: self.judged.total(),
                place: self.place(&self.judged),
                fix: String::new(),
                alike: Vec::new(),
                tell_apart: Vec::new(),
            }];
        }
        let mut left: Vec<(&Kind, usize)> = self.failing.iter().map(|(k, n)| (k, *n)).collect();
        let mut findings = Vec::new();
        while !left.is_empty() {
            let ranked = self.ranked(api, &left);
            let Some(best) = ranked.first() else {
                findings.push(self.unexplained(api, &left));
                break;
            };
            findings.push(self.finding(api, best, &ranked));
            left.retain(|(kind, _)| !kind.alternatives.contains(&best.codes));
        }
        findings
    }

    /// The hypotheses the kinds of line `left` offer, best first.
    fn ranked(&self, api: Option<Api>, left: &[(&Kind, usize)]) -> Vec<Hypothesis> {
        let mut hypotheses: Vec<Hypothesis> = Vec::new();
        for (kind, count) in left {
            for codes in &kind.alternatives {
                let found = hypotheses.iter().position(|h| &h.codes == codes);
                let index = found.unwrap_or_else(|| {
                    hypotheses.push(Hypothesis {
                        codes: codes.clone(),
                        explained: Census::default(),
                        penalty: 0,
                        prior: codes.iter().map(|&c| prior(api, c)).sum(),
                    });
                    hypotheses.len() - 1
                });
                hypotheses[index]
                    .explained
                    .add(kind.side, kind.past_critical, *count);
            }
        }
        for h in &mut hypotheses {
            h.penalty = self.penalty(h);
        }
        hypotheses.sort_by(|a, b| {
            b.explained
                .total()
                .cmp(&a.explained.total())
                .then(a.penalty.cmp(&b.penalty))
                .then(a.prior.cmp(&b.prior))
        });
        hypotheses
    }

    /// What only many lines show against a hypothesis: a mistake that cannot depend on the
    /// side the ray comes from, seen on one side only; a normal said to face the wrong way,
    /// or an incident vector said to be reversed (which would make the normal point inward),
    /// where the normal is the outward one on every line.
    fn penalty(&self, h: &Hypothesis) -> u32 {
        let one_side = self.confined_to_one_side(&h.explained);
        let outward = self.normal_always_outward();
        h.codes
            .iter()
            .map(|code| match code {
                Code::IncidentReversed if one_side => 2,
                Code::IncidentReversed | Code::NormalNotFacing if outward => 1,
                _ => 0,
            })
            .sum()
    }

    /// Whether `lines` are all on one side while lines on the other side were judged.
    fn confined_to_one_side(&self, lines: &Census) -> bool {
        let only_inside = lines.outside == 0 && lines.inside > 0 && self.judged.outside > 0;
        let only_outside = lines.inside == 0 && lines.outside > 0 && self.judged.inside > 0;
        lines.unknown_side == 0 && (only_inside || only_outside)
    }

    /// The finding for hypothesis `best`, with the ones the log cannot tell from it.
    fn finding(&self, api: Option<Api>, best: &Hypothesis, ranked: &[Hypothesis]) -> Finding {
        let code = reported_code(api, &best.codes, self.confined_to_one_side(&best.explained));
        let alike: Vec<&Hypothesis> = ranked[1..]
            .iter()
            .filter(|h| h.explained == best.explained && h.penalty == best.penalty)
            .collect();
        let mut tell_apart: Vec<&'static str> = Vec::new();
        for other in &alike {
            for field in telling_fields(&best.codes, &other.codes) {
                if !tell_apart.contains(&field) {
                    tell_apart.push(field);
                }
            }
        }
        Finding {
            code: code.name(),
            lines: best.explained.total(),
            place: self.place(&best.explained),
            fix: fix(api, code),
            alike: alike
                .iter()
                .flat_map(|h| h.codes.iter().map(|c| c.name()))
                .collect(),
            tell_apart,
        }
    }

    /// The finding for failing lines nothing explains.
    fn unexplained(&self, api: Option<Api>, left: &[(&Kind, usize)]) -> Finding {
        let mut lines = Census::default();
        for (kind, count) in left {
            lines.add(kind.side, kind.past_critical, *count);
        }
        Finding {
            code: Code::NotTheApiResult.name(),
            lines: lines.total(),
            place: self.place(&lines),
            fix: fix(api, Code::NotTheApiResult),
            alike: Vec::new(),
            tell_apart: Vec::new(),
        }
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

/// The code a hypothesis is reported as: a term along the normal with the wrong sign on the
/// rays from inside only is a normal that does not face the ray there (the outward normal used
/// in that term where the ray leaves); a single code as it is; a pair as its first.
fn reported_code(api: Option<Api>, codes: &[Code], one_side: bool) -> Code {
    match codes {
        [Code::NormalTermSign] if api.is_none() && one_side => Code::NormalNotFacing,
        [first, ..] => *first,
        [] => Code::NotTheApiResult,
    }
}

/// How unlikely a mistake is in `api`'s code (lower is likelier), for hypotheses that explain
/// the same lines: eta upside down and an unflipped normal lead in GLSL and the book; the
/// sign of wi leads in pbrt and Mitsuba.
fn prior(api: Option<Api>, code: Code) -> u32 {
    match (api, code) {
        (Some(Api::Glsl | Api::Rtiow) | None, Code::EtaInverted) => 0,
        (Some(Api::Glsl | Api::Rtiow) | None, Code::NormalNotFacing) => 1,
        (Some(Api::Pbrt | Api::Mitsuba), Code::EtaInverted) => 0,
        (Some(Api::Pbrt | Api::Mitsuba), Code::IncidentReversed) => 1,
        (_, Code::NoFlipInside | Code::NormalTermSign | Code::OtherRoot) => 2,
        (_, Code::IncidentReversed) => 3,
        (Some(Api::Pbrt | Api::Mitsuba), Code::NormalNotFacing) => 3,
        _ => 4,
    }
}

/// The logged fields that would tell the mistakes `a` from `b`: the ray's direction of travel
/// shows which way the incident vector points; whether the ray enters shows which mistakes
/// depend on the side (the ratio, the normal's side, the flip, the root where only leaving rays
/// fail).
fn telling_fields(a: &[Code], b: &[Code]) -> Vec<&'static str> {
    let differ = |code: Code| a.contains(&code) != b.contains(&code);
    let mut fields = Vec::new();
    if differ(Code::IncidentReversed) {
        fields.push("travel");
    }
    let sided = [
        Code::EtaInverted,
        Code::NoFlipInside,
        Code::OtherRoot,
        Code::NormalNotFacing,
    ];
    if sided.into_iter().any(differ) {
        fields.push("entering");
    }
    fields
}

/// The fix for `code` in `api`'s own code (`None`: any renderer's).
fn fix(api: Option<Api>, code: Code) -> String {
    match (api, code) {
        (Some(api), code) => api_fix(api, code).unwrap_or_else(|| generic_fix(code)),
        (None, code) => generic_fix(code),
    }
}

/// The fix for `code` in pbrt-v4's, GLSL's, the book's or Mitsuba's code, where it has one.
#[rustfmt::skip] // the t! keys stay where the translation tests find them
fn api_fix(api: Api, code: Code) -> Option<String> {
    let (key, text) = match (api, code) {
        // untranslated: code of each API, quoted in the sentences around it
        (Api::Pbrt, Code::EtaInverted) => ("pass", "Refract(wo, n, eta, &etap, &wi); // eta = n_inside / n_outside as the material gives it, not 1 / eta"),
        (Api::Pbrt, Code::NoFlipInside) => ("restore", "if (cosTheta_i < 0) { eta = 1 / eta; cosTheta_i = -cosTheta_i; n = -n; }"),
        (Api::Pbrt, Code::NormalTermSign) => ("write", "*wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);"),
        (Api::Pbrt, Code::OtherRoot) => ("write", "Float cosTheta_t = SafeSqrt(1 - sin2Theta_t); *wt = -wi / eta + (cosTheta_i / eta - cosTheta_t) * Vector3f(n);"),
        (Api::Pbrt, Code::IncidentReversed) => ("pass", "Refract(-ray.d, n, eta, &etap, &wt); // wi points back where the ray came from"),
        (Api::Pbrt, Code::NormalNotFacing) => ("pass", "Refract(wo, n, eta, &etap, &wi); // n: the shape's outward normal, which Refract turns itself"),
        (Api::Pbrt, Code::MissedTir | Code::FalseTir) => ("write", "Float sin2Theta_t = sin2Theta_i / Sqr(eta); if (sin2Theta_t >= 1) return false;"),
        (Api::Glsl, Code::EtaInverted) => ("pass", "refract(I, N, entering ? 1.0 / ior : ior)"),
        (Api::Glsl, Code::NormalNotFacing) => ("pass", "refract(I, faceforward(N, I, N), eta)"),
        (Api::Glsl, Code::IncidentReversed) => ("pass", "refract(rd, N, eta)"),
        (Api::Glsl, Code::NormalTermSign | Code::OtherRoot) => ("write", "eta * I - (eta * dot(N, I) + sqrt(k)) * N"),
        (Api::Glsl, Code::MissedTir | Code::FalseTir) => ("write", "float k = 1.0 - eta * eta * (1.0 - dot(N, I) * dot(N, I)); if (k < 0.0) return vec3(0.0);"),
        (Api::Rtiow, Code::EtaInverted) => ("write", "double ri = rec.front_face ? (1.0/refraction_index) : refraction_index;"),
        (Api::Rtiow, Code::NormalNotFacing) => ("write", "normal = front_face ? outward_normal : -outward_normal; // set_face_normal"),
        (Api::Rtiow, Code::IncidentReversed) => ("pass", "vec3 unit_direction = unit_vector(r_in.direction());"),
        (Api::Rtiow, Code::NormalTermSign | Code::OtherRoot) => ("write", "vec3 r_out_parallel = -std::sqrt(std::fabs(1.0 - r_out_perp.length_squared())) * n;"),
        (Api::Rtiow, Code::MissedTir | Code::FalseTir) => ("write", "bool cannot_refract = ri * sin_theta > 1.0; // then reflect"),
        (Api::Mitsuba, Code::EtaInverted) => ("pass", "fresnel(cos_theta_i, eta) // eta = int_ior / ext_ior; fresnel inverts it itself"),
        (Api::Mitsuba, Code::IncidentReversed) => ("pass", "Frame3f::cos_theta(wi) // wi in the local frame, pointing away from the surface"),
        (Api::Mitsuba, Code::NormalNotFacing) => ("pass", "refract(wi, cos_theta_t, eta_ti) // about the shading frame's z axis: fresnel turns it"),
        _ => return None,
    };
    Some(match key {
        "pass" => t!("check-fix-pass", code = text),
        "restore" => t!("check-fix-restore", code = text),
        _ => t!("check-fix-write", code = text),
    })
}

/// The fix for `code` in any renderer's own refraction.
fn generic_fix(code: Code) -> String {
    match code {
        Code::EtaInverted => t!("check-fix-generic-eta-inverted"),
        Code::IncidentReversed => t!("check-fix-generic-incident-reversed"),
        Code::NormalNotFacing => t!("check-fix-generic-normal-not-facing"),
        Code::NoFlipInside => t!("check-fix-generic-no-flip-inside"),
        Code::NormalTermSign => t!("check-fix-generic-normal-term-sign"),
        Code::OtherRoot => t!("check-fix-generic-other-root"),
        Code::MissedTir => t!("check-fix-generic-missed-tir"),
        Code::FalseTir => t!("check-fix-generic-false-tir"),
        Code::NotUnitInput => t!("check-fix-generic-not-unit-input"),
        Code::NotTheApiResult => t!("check-fix-generic-not-the-api-result"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(codes: &[&[Code]], side: Side) -> Evidence {
        Evidence {
            ok: codes.is_empty(),
            alternatives: codes.iter().map(|c| c.to_vec()).collect(),
            side: Some(side),
            past_critical: false,
            normal_outward: None,
        }
    }

    fn tally(lines: &[(Evidence, usize)]) -> LogTally {
        let mut tally = LogTally::default();
        for (evidence, count) in lines {
            for _ in 0..*count {
                tally.add(evidence);
            }
        }
        tally
    }

    fn codes(summary: &Summary) -> Vec<&'static str> {
        summary.diagnosis.iter().map(|f| f.code).collect()
    }

    #[test]
    fn a_log_with_no_mistake_says_none() {
        let t = tally(&[(line(&[], Side::Outside), 5), (line(&[], Side::Inside), 3)]);
        let s = t.summary(Some(Api::Glsl));
        assert_eq!(codes(&s), ["none"]);
        assert_eq!(
            (s.lines, s.judged, s.ok, s.diagnosis[0].lines),
            (8, 8, 8, 8)
        );
        assert!(s.diagnosis[0].fix.is_empty(), "no fix for no mistake");
    }

    #[test]
    fn the_hypothesis_that_explains_most_lines_is_the_verdict() {
        let eta = [Code::EtaInverted];
        let t = tally(&[
            (line(&[&eta, &[Code::IncidentReversed]], Side::Outside), 4),
            (line(&[&eta], Side::Inside), 4),
            (line(&[], Side::Inside), 1),
        ]);
        let s = t.summary(Some(Api::Rtiow));
        assert_eq!(codes(&s), ["eta_inverted"]);
        assert_eq!(s.diagnosis[0].lines, 8);
        assert!(
            s.diagnosis[0].fix.contains("front_face"),
            "{:?}",
            s.diagnosis[0]
        );
    }

    #[test]
    fn a_reversed_incident_vector_on_one_side_only_is_not_one_line_of_code() {
        // The book's outward normal: each leaving line ties normal_not_facing and
        // incident_reversed; only leaving lines fail.
        let tie: &[&[Code]] = &[&[Code::IncidentReversed], &[Code::NormalNotFacing]];
        let t = tally(&[(line(tie, Side::Inside), 6), (line(&[], Side::Outside), 6)]);
        let s = t.summary(Some(Api::Rtiow));
        assert_eq!(codes(&s), ["normal_not_facing"]);
        assert_eq!(s.diagnosis[0].lines, 6);
        assert!(s.diagnosis[0].alike.is_empty(), "{:?}", s.diagnosis[0]);
        assert!(
            s.diagnosis[0].place.contains("inside"),
            "{}",
            s.diagnosis[0].place
        );
    }

    #[test]
    fn an_outward_normal_on_every_line_leaves_eta_as_the_cause() {
        // pbrt, 1/eta passed: every line ties three readings; the normal is outward on all.
        let tie: &[&[Code]] = &[
            &[Code::IncidentReversed],
            &[Code::EtaInverted],
            &[Code::NormalNotFacing],
        ];
        let mut outward = line(tie, Side::Outside);
        outward.normal_outward = Some(true);
        let mut leaving = line(tie, Side::Inside);
        leaving.normal_outward = Some(true);
        let s = tally(&[(outward, 3), (leaving, 3)]).summary(Some(Api::Pbrt));
        assert_eq!(codes(&s), ["eta_inverted"]);
        assert!(
            s.diagnosis[0].fix.contains("not 1 / eta"),
            "{:?}",
            s.diagnosis[0]
        );
    }

    #[test]
    fn hypotheses_the_log_cannot_tell_apart_name_the_field_that_would() {
        let tie: &[&[Code]] = &[&[Code::EtaInverted], &[Code::IncidentReversed]];
        let mut unknown = line(tie, Side::Outside);
        unknown.side = None;
        let s = tally(&[(unknown, 4)]).summary(Some(Api::Glsl));
        assert_eq!(codes(&s), ["eta_inverted"]);
        assert_eq!(s.diagnosis[0].alike, ["incident_reversed"]);
        assert_eq!(s.diagnosis[0].tell_apart, ["travel", "entering"]);
    }

    #[test]
    fn lines_the_verdict_leaves_get_the_next_finding() {
        let t = tally(&[
            (line(&[&[Code::NoFlipInside]], Side::Inside), 5),
            (line(&[&[Code::NotUnitInput]], Side::Outside), 2),
            (line(&[], Side::Outside), 3),
            (line(&[], Side::Inside), 0),
        ]);
        let s = t.summary(Some(Api::Pbrt));
        assert_eq!(codes(&s), ["no_flip_inside", "not_unit_input"]);
        assert_eq!(s.diagnosis[0].lines, 5);
        assert!(
            s.diagnosis[0].fix.contains("cosTheta_i < 0"),
            "{:?}",
            s.diagnosis[0]
        );
    }

    #[test]
    fn a_normal_term_from_inside_only_is_a_normal_that_does_not_face_the_ray() {
        let t = tally(&[
            (line(&[&[Code::NormalTermSign]], Side::Inside), 5),
            (line(&[], Side::Outside), 5),
        ]);
        assert_eq!(codes(&t.summary(None)), ["normal_not_facing"]);
        let everywhere = tally(&[
            (line(&[&[Code::NormalTermSign]], Side::Inside), 5),
            (line(&[&[Code::NormalTermSign]], Side::Outside), 5),
        ]);
        assert_eq!(codes(&everywhere.summary(None)), ["normal_term_sign"]);
    }

    #[test]
    fn lines_nothing_explains_are_not_the_api_result() {
        let mut bad = line(&[], Side::Inside);
        bad.ok = false;
        let s = tally(&[(line(&[], Side::Outside), 2), (bad, 1)]).summary(Some(Api::Glsl));
        assert_eq!(codes(&s), ["not_the_api_result"]);
        assert_eq!(s.diagnosis[0].lines, 1);
        assert_eq!(s.ok, 2);
    }

    #[test]
    fn a_log_with_no_judged_line_has_no_diagnosis_and_says_so() {
        let mut t = LogTally::default();
        t.skip();
        t.skip();
        let s = t.summary(Some(Api::Glsl));
        assert!(s.diagnosis.is_empty());
        assert_eq!((s.lines, s.skipped, s.judged), (2, 2, 0));
        assert!(
            s.sentences()[0].contains("No line was judged"),
            "{:?}",
            s.sentences()
        );
    }

    #[test]
    fn the_place_names_the_kind_of_line() {
        let mut past = line(&[&[Code::MissedTir]], Side::Inside);
        past.past_critical = true;
        let t = tally(&[
            (past, 3),
            (line(&[], Side::Inside), 2),
            (line(&[], Side::Outside), 4),
        ]);
        let s = t.summary(Some(Api::Glsl));
        assert!(
            s.diagnosis[0].place.contains("critical angle"),
            "{}",
            s.diagnosis[0].place
        );
    }
}

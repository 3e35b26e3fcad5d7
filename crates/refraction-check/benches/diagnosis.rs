//! What the diagnosis of a whole log costs beside judging its lines: the per-line work `check`
//! does (read a log line with a pattern, judge it) on one thread, without and with what the
//! diagnosis adds (each line's evidence: the formula's variants that reproduce it; counting it;
//! the ranked search at the end), and that part alone on lines judged beforehand, for calls of
//! an API and for any renderer's own refraction; a
//! line that almost matches the pattern against one that does; and the ranking of a
//! million-line log's counts into findings. `cargo bench -p refraction-check --bench diagnosis`.
//!
//! The figures are in docs/check.md ("Find the bug").

use core::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use refraction_check::LogTally;
use refraction_check::{
    Dialect, Format, MAX_PLACEHOLDERS, Options, Pattern, Record, Session, judge_record,
};
use refraction_kernel::api::Api;

/// Lines the book's `dielectric::scatter` prints, right and with an outward normal from inside.
const LINES: [&str; 2] = [
    "uv=0.642788 -0.766044 0 n=0 1 0 ratio=0.666667 front_face=1 refracted=0.428525 -0.903530 0",
    "uv=0.342020 0.939693 0 n=0 1 0 ratio=1.5 front_face=0 refracted=0.513030 -0.858370 0",
];

const PATTERN: &str =
    "uv={uv} n={n} ratio={etai_over_etat} front_face={entering} refracted={refracted}";

/// smallpt's lines (docs/examples/smallpt.log, whose rays from inside use `nl` in `tdir`): any
/// renderer's own refraction, right and wrong.
const SMALLPT: [&str; 2] = [
    "REFR d=(0.814060 -0.533213 -0.230197) nl=(-0.201798 0.646311 -0.735907) into=1 tdir=(0.654226 -0.712648 0.253221)",
    "REFR d=(-0.413051 -0.568748 -0.711277) nl=(0.565556 0.347137 0.748093) into=0 tdir=(-0.456107 -0.514582 -0.726066)",
];

const SMALLPT_PATTERN: &str = "REFR d={w} nl={n} into={entering} tdir={t_yours}";

/// A log of `lines` repeated to 2,000 lines.
fn log_of(lines: &[&str]) -> String {
    lines
        .iter()
        .cycle()
        .take(2000)
        .flat_map(|l| [*l, "\n"])
        .collect()
}

/// The per-line work of a log in `dialect` read with `pattern`: judged only, and judged with
/// the diagnosis of the whole log (each line's evidence counted, the ranking at the end).
fn bench_dialect(c: &mut Criterion, name: &str, dialect: Dialect, pattern: &str, lines: &[&str]) {
    let log = log_of(lines);
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(dialect)
    };
    let parsed = Pattern::parse(dialect, pattern).expect("the pattern reads");
    let mut group = c.benchmark_group(name);
    group.bench_function("judge_2000_lines", |b| {
        b.iter(|| {
            let mut ok = 0;
            for line in log.lines() {
                let texts = parsed.capture(black_box(line)).expect("every line matches");
                let record = Record::from_texts(dialect, texts).expect("the fields read");
                ok += usize::from(judge_record(&record, &options).is_ok_and(|j| j.ok()));
            }
            black_box(ok)
        });
    });
    group.bench_function("judge_and_diagnose_2000_lines", |b| {
        b.iter(|| {
            let mut tally = LogTally::default();
            for line in log.lines() {
                let texts = parsed.capture(black_box(line)).expect("every line matches");
                let record = Record::from_texts(dialect, texts).expect("the fields read");
                if let Ok(judged) = judge_record(&record, &options) {
                    tally.add(judged.evidence());
                }
            }
            black_box(tally.summary(dialect.api(), None))
        });
    });
    // The diagnosis alone: the lines judged beforehand, their evidence counted and ranked.
    let judged: Vec<_> = log
        .lines()
        .filter_map(|line| {
            let texts = parsed.capture(line)?;
            let record = Record::from_texts(dialect, texts).ok()?;
            judge_record(&record, &options).ok()
        })
        .collect();
    group.bench_function("diagnose_only_2000_judged_lines", |b| {
        b.iter(|| {
            let mut tally = LogTally::default();
            for judgement in &judged {
                tally.add(black_box(judgement).evidence());
            }
            black_box(tally.summary(dialect.api(), None))
        });
    });
    group.bench_function("check_2000_lines_one_thread", |b| {
        b.iter(|| {
            let format = Format::Pattern(parsed.clone());
            let mut session = Session::new(options, format, false, false);
            let mut out = Vec::new();
            let answered = session.run(black_box(log.as_bytes()), &mut out, 1);
            black_box((answered.is_ok(), session.summary()))
        });
    });
    group.finish();
}

fn lines(c: &mut Criterion) {
    bench_dialect(c, "rtiow", Dialect::Api(Api::Rtiow), PATTERN, &LINES);
    bench_dialect(c, "smallpt", Dialect::Physics, SMALLPT_PATTERN, &SMALLPT);
}

/// A log line that matches the pattern, and one of the same length that almost does (its last
/// literal differs): a renderer's log is mostly lines of its other kinds.
fn near_misses(c: &mut Criterion) {
    let pattern = Pattern::parse(Api::Rtiow, PATTERN).expect("the pattern reads");
    let matching = LINES[0];
    let near = matching.replace("refracted=", "reflected=");
    let mut group = c.benchmark_group("pattern_line");
    group.bench_function("matching", |b| {
        b.iter(|| black_box(pattern.capture(black_box(matching))));
    });
    group.bench_function("near_miss", |b| {
        b.iter(|| black_box(pattern.capture(black_box(&near))));
    });
    // The pattern's literals over and over, never completed (345 bytes): per byte, within
    // three times a matching line's cost.
    let repeated = "uv=0.642788 -0.766044 0 n=0 1 0 ratio=0.666667 front_face=1 ".repeat(6);
    let repeated = &repeated[..345];
    group.bench_function("repeated_literals_345_bytes", |b| {
        b.iter(|| black_box(pattern.capture(black_box(repeated))));
    });
    // The largest pattern a user may give, on a 59 KB line that never completes it.
    let placeholders: String = (0..MAX_PLACEHOLDERS - 5).map(|_| "{_} | ").collect();
    let large =
        format!("{placeholders}{{uv}} | {{n}} | {{etai_over_etat}} | {{refracted}} | {{entering}}");
    let large = Pattern::parse(Api::Rtiow, &large).expect("the pattern reads");
    let long = "1 | 0.5 0.5 | x | ".repeat(3_500);
    group.bench_function("largest_pattern_59_kb_near_miss", |b| {
        b.iter(|| black_box(large.capture(black_box(&long))));
    });
    // A run of 80,000 spaces between two fields (issue 40: 64 s when each place of the run
    // scanned it again), matching and almost matching: linear in the line, as the near miss.
    let gap = " ".repeat(80_000);
    let spaced = matching.replacen(" n=", &format!("{gap}n="), 1);
    let spaced_near = near.replacen(" n=", &format!("{gap}n="), 1);
    group.bench_function("spaces_80000_matching", |b| {
        b.iter(|| black_box(pattern.capture(black_box(&spaced))));
    });
    group.bench_function("spaces_80000_near_miss", |b| {
        b.iter(|| black_box(pattern.capture(black_box(&spaced_near))));
    });
    group.finish();
}

/// Counting a million lines' evidence (the book's log: right lines, and lines from inside
/// with an outward normal) and ranking every hypothesis on the counts.
fn ranking(c: &mut Criterion) {
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Api::Rtiow)
    };
    let parsed = Pattern::parse(Api::Rtiow, PATTERN).expect("the pattern reads");
    let evidence: Vec<_> = LINES
        .iter()
        .map(|line| {
            let texts = parsed.capture(line).expect("the line matches");
            let record = Record::from_texts(Api::Rtiow, texts).expect("the fields read");
            judge_record(&record, &options)
                .expect("the line is judged")
                .evidence()
        })
        .collect();
    c.bench_function("count_1000000_lines_and_rank", |b| {
        b.iter(|| {
            let mut tally = LogTally::default();
            for e in evidence.iter().cycle().take(1_000_000) {
                tally.add(black_box(e.clone()));
            }
            black_box(tally.summary(Some(Api::Rtiow), None))
        });
    });
}

/// The ranked search on a log of many kinds of line (issue 45: its cost grew with the square
/// of the kinds): the book's calls at 180 angles from both sides, each logged with one of
/// several wrong results, so that the kinds are many and each explained alone.
fn ranking_many_kinds(c: &mut Criterion) {
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Api::Rtiow)
    };
    let mut evidence = Vec::new();
    for step in 0..180_u32 {
        let angle = f64::from(step) * 0.5_f64.to_radians();
        let (s, c) = angle.sin_cos();
        for (entering, wrong) in [(true, 0.0), (true, 0.3), (false, 0.7), (false, -0.2)] {
            let (uv, ratio) = if entering {
                ([s, -c, 0.0], 1.0 / 1.5)
            } else {
                ([s, -c, 0.0], 1.5)
            };
            let refracted = [s * 0.5 + wrong, -c, wrong];
            let line = format!(
                r#"{{"uv":{uv:?},"n":[0,1,0],"etai_over_etat":{ratio},"refracted":{refracted:?},"entering":{entering}}}"#
            );
            let record = Record::from_json_line(Api::Rtiow, &line).expect("the fields read");
            if let Ok(judged) = judge_record(&record, &options) {
                evidence.push(judged.evidence());
            }
        }
    }
    c.bench_function("rank_720_lines_of_many_kinds", |b| {
        b.iter(|| {
            let mut tally = LogTally::default();
            for e in &evidence {
                tally.add(black_box(e.clone()));
            }
            black_box(tally.summary(Some(Api::Rtiow), None))
        });
    });
}

criterion_group!(benches, lines, near_misses, ranking, ranking_many_kinds);
criterion_main!(benches);

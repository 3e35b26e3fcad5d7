//! What the diagnosis of a whole log costs: the per-line work `check --api` does (read a log
//! line with a pattern, judge the call, count its evidence) on one thread, a line that almost
//! matches the pattern against one that does, and the ranking of a log's counts into findings. `cargo bench -p refraction-tools --bench diagnosis`.
//!
//! Measured whole, a 1,000,000-line log of the book's calls takes as long with the diagnosis
//! as without it (`check --summary` against `check` before it, release build, 2 cores).

use core::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use refraction_kernel::api::Api;
use refraction_tools::api_check::{Code, Format, MAX_PLACEHOLDERS, Options, Pattern, Session};
use refraction_tools::diagnosis::{Evidence, LogTally, Side};

/// Lines the book's `dielectric::scatter` prints, right and with an outward normal from inside.
const LINES: [&str; 2] = [
    "uv=0.642788 -0.766044 0 n=0 1 0 ratio=0.666667 front_face=1 refracted=0.428525 -0.903530 0",
    "uv=0.342020 0.939693 0 n=0 1 0 ratio=1.5 front_face=0 refracted=0.513030 -0.858370 0",
];

const PATTERN: &str =
    "uv={uv} n={n} ratio={etai_over_etat} front_face={entering} refracted={refracted}";

fn lines(c: &mut Criterion) {
    let log: String = LINES
        .iter()
        .cycle()
        .take(2000)
        .flat_map(|l| [*l, "\n"])
        .collect();
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(Api::Rtiow)
    };
    c.bench_function("check_2000_pattern_lines_one_thread", |b| {
        b.iter(|| {
            let pattern = Pattern::parse(Api::Rtiow, PATTERN).expect("the pattern reads");
            let mut session = Session::new(options, Format::Pattern(pattern), false, false);
            let mut out = Vec::new();
            let answered = session.run(black_box(log.as_bytes()), &mut out, 1);
            black_box((answered.is_ok(), session.summary()))
        });
    });
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
    group.finish();
}

fn ranking(c: &mut Criterion) {
    let kinds = [
        Evidence {
            ok: true,
            side: Some(Side::Outside),
            ..Evidence::default()
        },
        Evidence {
            alternatives: vec![vec![Code::NormalNotFacing], vec![Code::IncidentReversed]],
            side: Some(Side::Inside),
            ..Evidence::default()
        },
        Evidence {
            alternatives: vec![vec![Code::MissedTir]],
            side: Some(Side::Inside),
            past_critical: true,
            ..Evidence::default()
        },
    ];
    c.bench_function("count_1000000_lines_and_rank", |b| {
        b.iter(|| {
            let mut tally = LogTally::default();
            for evidence in kinds.iter().cycle().take(1_000_000) {
                tally.add(black_box(evidence.clone()));
            }
            black_box(tally.summary(Some(Api::Rtiow), None))
        });
    });
}

criterion_group!(benches, lines, near_misses, ranking);
criterion_main!(benches);

//! Fuzzing the parsers of hostile input: a `solve` line, a `check` line, a vector string, the
//! JSON Lines loop, a state file, a share string, and `check --api`'s readers (its JSON lines,
//! a `--pattern` and the log lines it reads, CSV). `cargo fuzz` needs a nightly toolchain and
//! the cargo-fuzz tool, so these are proptest runs over arbitrary bytes and strings and over
//! structured mutations of valid inputs, a few hundred cases each in the ordinary test run.
//! None may panic, and every answer must be JSON whose numbers are all there: `serde_json` writes
//! a NaN or an infinity as `null`, so a `null` where a number belongs is a non-finite number.

use std::io::Write as _;

use glam::DVec3;
use proptest::prelude::*;
use refraction_check::{Format, Options, Pattern, Session};
use refraction_kernel::Convention;
use refraction_kernel::api::Api;
use refraction_model::ExplorerState;
use refraction_tools::{
    check_line, open_state_file, parse_state, parse_t, solve_line, solve_lines, state_to_json,
};
use serde_json::Value;

const CASES: u32 = 384;

/// Numbers as a hostile or careless log writes them: ordinary, extreme, out of range, long.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (-2.0..2.0_f64).prop_map(|x| x.to_string()),
        any::<f64>()
            .prop_filter("finite", |x| x.is_finite())
            .prop_map(|x| format!("{x:e}")),
        prop::sample::select(vec![
            "0",
            "-0",
            "1",
            "-1",
            "1.5",
            "1e308",
            "-1.7e308",
            "1e309",
            "5e-324",
            "1e-320",
            "1e-160",
            "1e16",
            "1e30",
            "2e7",
            "3.4e38",
            "1e39",
            "18446744073709551616",
            "-9223372036854775809",
            "0.000000000000000000000000000000000000000000001",
        ])
        .prop_map(str::to_owned),
    ]
}

/// A JSON value other than a number, as a wrong or unknown field holds.
fn other_value() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "true",
            "null",
            "\"along_ray\"",
            "\"toward_origin\"",
            "\"f32\"",
            "\"f64\"",
            "\"vec3(0.1, -0.9, 0)\"",
            "\"inf, 0, 0\"",
            "\"nan nan nan\"",
            "[]",
            "{}",
            "[[1, 2], [3]]",
            "{\"w\": [1, 0, 0]}",
        ])
        .prop_map(str::to_owned),
        any::<String>().prop_map(|s| Value::String(s).to_string()),
    ]
}

/// An array of numbers, usually three.
fn vector() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => prop::collection::vec(number(), 3),
        1 => prop::collection::vec(prop_oneof![number(), other_value()], 0..6),
    ]
    .prop_map(|items| format!("[{}]", items.join(",")))
}

/// A line with the fields of `solve` (and often `t_yours` and an unknown field), mostly valid.
fn valid_line() -> impl Strategy<Value = String> {
    let optional = |key: &'static str, value: BoxedStrategy<String>| {
        prop::option::weighted(0.5, value).prop_map(move |v| v.map(|v| format!("\"{key}\":{v}")))
    };
    (
        vector(),
        vector(),
        prop_oneof![4 => number(), 1 => other_value()],
        prop_oneof![4 => number(), 1 => other_value()],
        optional("convention", other_value().boxed()),
        optional("precision", other_value().boxed()),
        optional("t_yours", prop_oneof![vector(), other_value()].boxed()),
        optional("junk", prop_oneof![vector(), other_value()].boxed()),
    )
        .prop_map(|(w, n, mu_i, mu_t, convention, precision, yours, junk)| {
            let mut fields = vec![
                format!("\"w\":{w}"),
                format!("\"n\":{n}"),
                format!("\"mu_i\":{mu_i}"),
                format!("\"mu_t\":{mu_t}"),
            ];
            fields.extend([convention, precision, yours, junk].into_iter().flatten());
            format!("{{{}}}", fields.join(","))
        })
}

/// One mutation of a valid line: cut short, a character put in, a stretch taken out.
fn mutated(line: impl Strategy<Value = String>) -> impl Strategy<Value = String> {
    (
        line,
        any::<prop::sample::Index>(),
        any::<char>(),
        0..8_usize,
    )
        .prop_map(|(line, at, c, how)| {
            let chars: Vec<char> = line.chars().collect();
            let i = at.index(chars.len() + 1);
            let mut out: Vec<char> = chars.clone();
            match how {
                0 => out.truncate(i),
                1 => out.insert(i, c),
                2 => {
                    out.drain(i..(i + 5).min(chars.len()));
                }
                _ => return line,
            }
            out.into_iter().collect()
        })
}

/// Lines as they come: arbitrary text, valid lines and their mutations.
fn any_line() -> impl Strategy<Value = String> {
    prop_oneof![
        1 => any::<String>(),
        1 => "[ -~]{0,120}",
        4 => mutated(valid_line()),
    ]
}

/// Asserts that `value` at `field` is a number, or an array of numbers.
fn assert_numbers(value: &Value, field: &str, context: &str) {
    let present = match &value[field] {
        Value::Number(_) => true,
        Value::Array(items) => items.iter().all(Value::is_number),
        _ => false,
    };
    assert!(
        present,
        "`{field}` is not all numbers in {value} (from {context})"
    );
}

/// Asserts that a `solve` answer is JSON with every number there.
fn assert_finite_solve_answer(text: &str, line: &str) {
    let answer: Value = serde_json::from_str(text).expect("the answer is JSON");
    for field in ["reflected", "k", "cos_i"] {
        assert_numbers(&answer, field, line);
    }
    if answer["tir"] == false {
        for field in ["t", "a", "b", "cos_t"] {
            assert_numbers(&answer, field, line);
        }
    }
    for candidate in answer["candidates"].as_array().expect("candidates") {
        for field in ["a", "b", "t"] {
            assert_numbers(candidate, field, line);
        }
    }
}

/// Asserts that no non-finite number is written in `text` (the one fixed sentence that names
/// NaN and infinity aside).
fn assert_no_non_finite_words(text: &str, context: &str) {
    let cleaned = text.replace("NaN or infinite", "");
    assert!(
        !cleaned.contains("NaN") && !cleaned.contains("inf"),
        "{text} (from {context})"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn a_solve_line_is_answered_with_finite_json_or_an_error(line in any_line()) {
        match solve_line(&line) {
            Ok(text) => assert_finite_solve_answer(&text, &line),
            // Not checked for words: an error message quotes what it refuses (`"inf, 0, 0"`).
            Err(message) => prop_assert!(!message.to_string().is_empty()),
        }
    }

    #[test]
    fn a_check_line_is_judged_with_finite_json_or_an_error(line in any_line()) {
        match check_line(&line) {
            Ok((text, verdict)) => {
                let answer: Value = serde_json::from_str(&text).expect("the answer is JSON");
                if !answer["t"].is_null() {
                    assert_numbers(&answer, "t", &line);
                }
                prop_assert_eq!(answer["ok"].as_bool(), Some(verdict.ok));
                assert_no_non_finite_words(&verdict.explanation, &line);
            }
            Err(message) => prop_assert!(!message.to_string().is_empty()),
        }
    }

    #[test]
    fn a_vector_string_is_read_or_refused_without_panicking(
        text in prop_oneof![
            any::<String>(),
            "[a-zA-Z0-9_:(\\[ ,.+\\-eE\\])f;]{0,40}",
            prop::collection::vec(number(), 0..5).prop_map(|v| format!("vec3({})", v.join(", "))),
        ]
    ) {
        if let Err(message) = parse_t(&text) {
            prop_assert!(!message.to_string().is_empty());
        }
    }

    #[test]
    fn the_line_loop_answers_every_non_blank_line_once_in_json(
        pieces in prop::collection::vec(
            prop_oneof![
                any_line().prop_map(String::into_bytes),
                prop::collection::vec(any::<u8>(), 0..40),
                Just(Vec::new()),
            ],
            0..12,
        )
    ) {
        let input = pieces.join(&b'\n');
        let lines: Vec<&[u8]> = input.split(|&b| b == b'\n').collect();
        let expected = lines
            .iter()
            .filter(|line| core::str::from_utf8(line).map_or(true, |t| !t.trim().is_empty()))
            .count();
        let mut output = Vec::new();
        solve_lines(&input[..], &mut output).expect("writing to memory cannot fail");
        let text = String::from_utf8(output).expect("the output is UTF-8");
        prop_assert_eq!(text.lines().count(), expected);
        for line in text.lines() {
            let answer: Value = serde_json::from_str(line).expect("every line is JSON");
            if let Some(k) = answer["line"].as_u64() {
                prop_assert!(k >= 1 && k as usize <= lines.len());
            }
        }
    }

    #[test]
    fn a_share_string_reads_back_exactly_or_is_refused(
        w in prop::array::uniform3(-1e3..1e3_f64),
        n in prop::array::uniform3(-1e3..1e3_f64),
        mu in (1e-3..1e3_f64, 1e-3..1e3_f64),
        toward in any::<bool>(),
        mutation in (any::<prop::sample::Index>(), any::<char>(), 0..4_usize),
    ) {
        let convention = if toward { Convention::TowardOrigin } else { Convention::AlongRay };
        let Ok(state) = ExplorerState::new(
            DVec3::from_array(w), DVec3::from_array(n), mu.0, mu.1, convention,
        ) else {
            return Ok(());
        };
        let share = state_to_json(&state);
        prop_assert!(parse_state(&share) == Ok(state.clone()));
        let (at, c, how) = mutation;
        let mut chars: Vec<char> = share.chars().collect();
        let i = at.index(chars.len());
        match how {
            0 => chars.truncate(i),
            1 => chars.insert(i, c),
            _ => chars[i] = c,
        }
        let pasted: String = chars.into_iter().collect();
        if let Ok(back) = parse_state(&pasted) {
            prop_assert!(parse_state(&state_to_json(&back)) == Ok(back));
        }
    }
}

proptest! {
    // Each case writes a file: fewer of them.
    #![proptest_config(ProptestConfig::with_cases(CASES / 4))]

    #[test]
    fn a_state_file_of_any_bytes_loads_or_is_refused_naming_it(
        bytes in prop_oneof![
            prop::collection::vec(any::<u8>(), 0..300),
            mutated(valid_line()).prop_map(|l| l.replace(',', ",\n  ").into_bytes()),
        ]
    ) {
        let path = std::env::temp_dir()
            .join(format!("parsers-fuzz-{}-{:?}.json", std::process::id(), std::thread::current().id()));
        std::fs::File::create(&path).and_then(|mut f| f.write_all(&bytes)).unwrap();
        let loaded = open_state_file(&path).map_err(|e| e.to_string());
        std::fs::remove_file(&path).unwrap();
        match loaded {
            Ok(state) => prop_assert!(parse_state(&state_to_json(&state)) == Ok(state)),
            Err(message) => prop_assert!(message.contains(&path.display().to_string()), "{}", message),
        }
    }
}

/// Any of the four APIs.
fn api() -> impl Strategy<Value = Api> {
    prop_oneof![
        Just(Api::Glsl),
        Just(Api::Pbrt),
        Just(Api::Rtiow),
        Just(Api::Mitsuba),
    ]
}

/// A vector as a log prints it, in one of the forms `--pattern` reads, or something else.
fn logged_vector() -> impl Strategy<Value = String> {
    (prop::collection::vec(number(), 3), 0..7_usize).prop_map(|(v, form)| match form {
        0 => v.join(" "),
        1 => v.join(", "),
        2 => format!("[ {} ]", v.join(", ")),
        3 => format!("({})", v.join(", ")),
        4 => format!("vec3({})", v.join(", ")),
        5 => format!("Vec3 {{ x: {}, y: {}, z: {} }}", v[0], v[1], v[2]),
        _ => format!("{}f {}f", v[0], v[1]),
    })
}

/// Checks one `check --api` answer: JSON whose `t`, when there, is all numbers, and whose
/// explanation writes no non-finite number.
fn assert_api_answer(reply: &str, context: &str) {
    for text in reply.lines() {
        let answer: Value = serde_json::from_str(text).expect("the answer is JSON");
        if !answer["t"].is_null() {
            assert_numbers(&answer, "t", context);
        }
        if let Some(explanation) = answer["explanation"].as_str() {
            assert_no_non_finite_words(explanation, context);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn a_check_api_json_line_is_judged_or_refused(api in api(), line in any_line(), swap in any::<bool>()) {
        // The solve fields renamed to the API's own, so that mutations hit its reader.
        let names = refraction_check::fields::names(api);
        let line = if swap {
            line.replace("\"w\"", &format!("\"{}\"", names.incident))
                .replace("\"n\"", &format!("\"{}\"", names.normal))
                .replace("\"mu_t\"", &format!("\"{}\"", names.eta))
                .replace("\"t_yours\"", &format!("\"{}\"", names.result))
        } else {
            line
        };
        let mut session = Session::new(Options::new(api), Format::JsonLines, false, false);
        match session.answer(1, &line) {
            Ok(reply) => assert_api_answer(&reply, &line),
            Err(message) => prop_assert!(!message.to_string().is_empty()),
        }
    }

    #[test]
    fn a_pattern_and_the_log_lines_it_reads_never_panic(
        api in api(),
        literal in "[ -~]{0,12}",
        values in prop::collection::vec(prop_oneof![logged_vector(), number(), "[ -~]{0,20}"], 4),
        noise in any::<String>(),
        pattern_noise in "[ -~{}]{0,30}",
    ) {
        let names = refraction_check::fields::names(api);
        let fields = [names.incident, names.normal, names.eta, names.result];
        let pattern = format!(
            "LOG{literal}{{{}}} | {{{}}} | {{{}}} | {{{}}}",
            fields[0], fields[1], fields[2], fields[3]
        );
        let line = format!(
            "LOG{literal}{} | {} | {} | {}",
            values[0], values[1], values[2], values[3]
        );
        for text in [pattern.as_str(), pattern_noise.as_str()] {
            let Ok(parsed) = Pattern::parse(api, text) else { continue };
            let mut session = Session::new(Options::new(api), Format::Pattern(parsed), false, true);
            for log_line in [line.as_str(), noise.as_str()] {
                match session.answer(1, log_line) {
                    Ok(reply) => assert_api_answer(&reply, log_line),
                    Err(message) => prop_assert!(!message.to_string().is_empty()),
                }
            }
            if let Some(summary) = session.finish() {
                let _: Value = serde_json::from_str(&summary).expect("the summary is JSON");
            }
        }
    }

    #[test]
    fn a_csv_log_of_any_text_is_answered_line_by_line(
        api in api(),
        header in prop_oneof!["[ -~]{0,60}", Just("I,N,eta,result".to_owned()), Just("uv,n,etai_over_etat,refracted".to_owned())],
        rows in prop::collection::vec(prop_oneof![
            "[ -~]{0,60}",
            prop::collection::vec(prop_oneof![logged_vector().prop_map(|v| format!("\"{v}\"")), number()], 4)
                .prop_map(|cells| cells.join(",")),
        ], 0..6),
    ) {
        let text = core::iter::once(header).chain(rows).collect::<Vec<_>>().join("\n");
        let mut session = Session::new(Options::new(api), Format::Csv, false, false);
        let mut out = Vec::new();
        session.run(text.as_bytes(), &mut out, 2).expect("memory cannot fail");
        for line in String::from_utf8(out).expect("UTF-8").lines() {
            assert_api_answer(line, &text);
        }
    }
}

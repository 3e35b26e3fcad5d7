//! A log read by `check`: the first byte picks the dialect (an API or any renderer's) and the
//! format (JSON Lines, CSV, or a pattern taken from the first line), the rest is the log.
//! Every line gets an answer in finite JSON or an error line, and the diagnosis is built.
#![no_main]

#[path = "answer.rs"]
mod answer;
#[path = "message.rs"]
mod message;

use refraction_check::{Dialect, Format, Options, Pattern, Session};
use refraction_kernel::api::Api;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let dialect = match pick % 5 {
        0 => Dialect::Api(Api::Glsl),
        1 => Dialect::Api(Api::Pbrt),
        2 => Dialect::Api(Api::Rtiow),
        3 => Dialect::Api(Api::Mitsuba),
        _ => Dialect::Physics,
    };
    let (format, log) = match (pick / 5) % 3 {
        0 => (Format::JsonLines, rest),
        1 => (Format::Csv, rest),
        _ => {
            let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
            let Ok(text) = std::str::from_utf8(&rest[..end]) else {
                return;
            };
            match Pattern::parse(dialect, text) {
                Ok(pattern) => (Format::Pattern(pattern), &rest[end..]),
                Err(e) => return message::assert_message(&e.to_string(), data),
            }
        }
    };
    let options = Options {
        inside: Some(1.5),
        outside: Some(1.0),
        ..Options::new(dialect)
    };
    let mut session = Session::new(options, format, false, pick & 0x80 != 0);
    let mut out = Vec::new();
    if session.run(log, &mut out, 1).is_ok() {
        answer::assert_json(std::str::from_utf8(&out).expect("answers are UTF-8"));
        let summary = session.summary();
        assert!(summary.judged <= summary.lines, "{summary:?}");
        summary
            .sentences()
            .iter()
            .for_each(|s| message::assert_message(s, data));
    }
});

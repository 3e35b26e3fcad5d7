//! A `--pattern` of up to thousands of placeholders and a line to match: the first two bytes
//! give how many times the pattern's middle repeats (up to 65,535), the rest up to the first
//! newline is that middle, and what follows is the line, each tab of it widened to a run of
//! 100,000 spaces (issue 40: a long run of spaces made matching quadratic). Parsing answers
//! with a pattern or a message, and matching a line ends (the fuzzer's timeout catches a
//! super-linear match).
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_check::Pattern;
use refraction_kernel::api::Api;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let [high, low, rest @ ..] = data else {
        return;
    };
    let repeats = usize::from(u16::from_be_bytes([*high, *low]));
    let end = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
    let (Ok(middle), Ok(line)) = (
        std::str::from_utf8(&rest[..end]),
        std::str::from_utf8(rest.get(end + 1..).unwrap_or_default()),
    ) else {
        return;
    };
    let line = line.replacen('\t', &" ".repeat(100_000), 10);
    // Placeholders in the thousands: a middle of `{_} | ` repeated 2,000 times and more.
    let text = format!(
        "uv={{uv}} {} n={{n}} r={{refracted}}",
        middle.repeat(repeats.min(4_000))
    );
    match Pattern::parse(Api::Rtiow, &text) {
        Ok(pattern) => {
            if let Some(captured) = pattern.capture(&line) {
                assert!(captured.iter().all(|(_, t)| line.contains(t)));
            }
        }
        Err(e) => message::assert_message(&e.to_string(), data),
    }
});

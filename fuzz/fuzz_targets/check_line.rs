//! `check`'s JSON line (the `solve` fields and `t_yours`): a verdict in finite JSON with an
//! explanation, or an error in words.
#![no_main]

#[path = "answer.rs"]
mod answer;
#[path = "message.rs"]
mod message;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(line) = std::str::from_utf8(data) {
        match refraction_tools::check_line(line) {
            Ok((text, verdict)) => {
                answer::assert_json(&text);
                message::assert_message(&verdict.explanation, data);
            }
            Err(e) => message::assert_message(&e.to_string(), data),
        }
    }
});

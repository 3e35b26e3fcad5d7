//! `solve`'s JSON line: an answer in finite JSON, or an error in words.
#![no_main]

#[path = "answer.rs"]
mod answer;
#[path = "message.rs"]
mod message;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(line) = std::str::from_utf8(data) {
        match refraction_tools::solve_line(line) {
            Ok(text) => answer::assert_json(&text),
            Err(e) => message::assert_message(&e.to_string(), data),
        }
    }
});

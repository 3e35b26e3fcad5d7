//! A state file: a state that writes back as the same line, or an error in words.
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_tools::state_file;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        match state_file::parse(text) {
            Ok(state) => {
                let line = state_file::to_json(&state);
                assert_eq!(state_file::parse(&line).ok(), Some(state), "{line}");
            }
            Err(e) => message::assert_message(&e.to_string(), data),
        }
    }
});

//! A state file: a state that writes back as the same line, or an error in words.
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_tools::{parse_state, state_to_json};

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        match parse_state(text) {
            Ok(state) => {
                let line = state_to_json(&state);
                assert_eq!(parse_state(&line).ok(), Some(state), "{line}");
            }
            Err(e) => message::assert_message(&e.to_string(), data),
        }
    }
});

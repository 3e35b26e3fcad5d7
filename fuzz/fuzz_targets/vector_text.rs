//! A vector as programs print it: three numbers and their digits, or an error in words.
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_tools::vector_text::parse_vector;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        match parse_vector(text) {
            Ok(v) => assert!(v.digits <= 17, "{v:?}"),
            Err(e) => message::assert_message(&e.to_string(), data),
        }
    }
});

//! A lesson deck file: a deck whose every step the kernel accepts, that writes back to a file
//! that loads as the same deck, or one error naming the file, the line and the column.
#![no_main]

#[path = "message.rs"]
mod message;

use refraction_deck::Deck;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match Deck::from_toml(text, "fuzz.toml", None) {
        Ok(deck) => {
            let written = deck.to_toml().expect("a deck writes");
            let again = Deck::from_toml(&written, "again.toml", None)
                .unwrap_or_else(|e| panic!("written back, it does not load: {e}\n{written}"));
            assert_eq!(again, deck, "{written}");
        }
        Err(e) => {
            let message = e.to_string();
            assert!(message.starts_with("fuzz.toml"), "{message}");
            assert_eq!(message.lines().count(), 1, "one line: {message}");
            message::assert_message(&message, data);
        }
    }
});

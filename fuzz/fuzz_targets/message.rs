//! What every target checks of a message.

/// Panics unless an error message about `input` has words in it and is no caught panic's
/// text. A message may quote the input, so "panicked" counts only where the input lacks it.
pub fn assert_message(message: &str, input: &[u8]) {
    assert!(!message.trim().is_empty(), "an empty message");
    let quoted = String::from_utf8_lossy(input).contains("panicked");
    assert!(quoted || !message.contains("panicked"), "{message}");
}

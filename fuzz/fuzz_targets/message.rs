//! What every target checks of a message.

/// Panics unless an error message is one line of words of a sensible length.
pub fn assert_message(message: &str) {
    assert!(!message.trim().is_empty(), "an empty message");
    assert!(!message.contains("panicked"), "{message}");
}

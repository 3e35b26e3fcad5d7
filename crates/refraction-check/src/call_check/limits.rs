//! How large a `--pattern` may be: it is user input, so it is bounded. The pattern's parser
//! enforces these ([`super::pattern`]) and its errors quote them ([`super::error`]).

/// The most placeholders (`{field}` and `{_}`) a pattern may hold: each of a dialect's fields
/// once, and a few `{_}` for what the renderer prints between them.
pub const MAX_PLACEHOLDERS: usize = 32;

/// The longest pattern, in bytes: a printf line is a few hundred.
pub const MAX_PATTERN_BYTES: usize = 4096;

/// The most lines a record may be printed over: one vector a line, and a few lines between.
pub const MAX_PATTERN_LINES: usize = 16;

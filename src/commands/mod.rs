//! The subcommands' bodies: each reads its input, calls the library and turns the outcome into
//! output and an exit status. A failure prints one line naming the command and exits non-zero.

pub mod bench;
pub mod lines;
pub mod render;
pub mod trace;

use std::io::ErrorKind;
use std::process::ExitCode;

/// Prints `refraction-explorer COMMAND: MESSAGE` on stderr and returns exit status 2.
pub fn fail(command: &str, message: &dyn std::fmt::Display) -> ExitCode {
    let space = if command.is_empty() { "" } else { " " };
    eprintln!("refraction-explorer{space}{command}: {message}");
    ExitCode::from(2)
}

/// The exit status for an output error: a closed pipe (`| head`) is not a failure.
pub fn output_error(command: &str, error: &std::io::Error) -> ExitCode {
    if error.kind() == ErrorKind::BrokenPipe {
        ExitCode::SUCCESS
    } else {
        fail(command, error)
    }
}

//! The subcommands' bodies: each reads its input, calls the library and turns the outcome into
//! output and an exit status. A failure prints one line naming the command and exits non-zero.
//! Nothing here prints with `println!` or `eprintln!`, which panic when the stream cannot be
//! written: every write goes through [`output`] and a failed one sets the exit status.

pub(crate) mod bench;
pub(crate) mod inputs;
pub(crate) mod lessons;
pub(crate) mod lines;
pub(crate) mod output;
pub(crate) mod render;
pub(crate) mod trace;
pub(crate) mod window;

use std::io::ErrorKind;
use std::process::ExitCode;

/// The exit status when stdout is a closed pipe (`| head`): the output was cut short, so not
/// 0, and no message (the reader chose to stop). 141 is what a shell reports for a program
/// killed by SIGPIPE, as `cat` or `grep` would be.
pub(crate) const CLOSED_PIPE: u8 = 141;

/// Prints `refraction-explorer COMMAND: MESSAGE` on stderr, with characters that would act on
/// a terminal escaped (see [`output::printable`]), and returns exit status 2.
pub(crate) fn fail(command: &str, message: &dyn core::fmt::Display) -> ExitCode {
    let space = if command.is_empty() { "" } else { " " };
    let message = message.to_string();
    let message = refraction_tools::brief(&message);
    let line = format!("refraction-explorer{space}{command}: {message}");
    // The exit status says it failed even when stderr cannot say why.
    output::to_stderr(&output::printable(&line)).ok();
    ExitCode::from(2)
}

/// The exit status for a failed write to stdout: [`CLOSED_PIPE`] quietly for a closed pipe,
/// otherwise the error on stderr and status 2.
pub(crate) fn output_error(command: &str, error: &std::io::Error) -> ExitCode {
    if error.kind() == ErrorKind::BrokenPipe {
        ExitCode::from(CLOSED_PIPE)
    } else {
        fail(command, &format!("cannot write the output: {error}"))
    }
}

/// `--web-base` that cannot start a link ([`refraction_tools::link::web_base`], the one check
/// the window and the page use too), quoting the address (cut, its control characters
/// escaped) before the reason, so that the reason is never cut from the message.
#[derive(Debug, thiserror::Error)]
#[error(
    "--web-base `{shown}` cannot start a link: {reason}; give the address where the web build's \
     folder is hosted, such as https://school.example/explorer/"
)]
pub(crate) struct WebBaseRefused {
    /// The address as given, quoted.
    shown: String,
    /// Why it is refused.
    reason: refraction_tools::link::WebBaseError,
}

/// The web build's address `--web-base` gives, checked and written as links start with it.
///
/// # Errors
/// The address cannot start a link.
pub(crate) fn web_base(given: Option<&str>) -> Result<Option<String>, WebBaseRefused> {
    use refraction_tools::link;
    given
        .map(|url| {
            link::web_base(url).map_err(|reason| WebBaseRefused {
                shown: link::echo(url, link::ECHO_CHARS),
                reason,
            })
        })
        .transpose()
}

//! `repro`: parses the command line and dispatches (`cli/`); all work lives in the library.

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    end_quietly_on_a_closed_pipe();
    match cli::run(cli::args::parse()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// A closed standard output (`repro all | head -3`) ends the program quietly, as it ends any
/// Unix filter, instead of the next `println!` panicking on the broken pipe with a backtrace:
/// Rust starts a program with SIGPIPE ignored, so its default action is restored first.
/// Progress and errors go to standard error; the solves are in the cache by the time the
/// summary lines are printed.
fn end_quietly_on_a_closed_pipe() {
    #[cfg(unix)]
    // SAFETY: sets the disposition of one signal to its default, at the start of `main`,
    // before any other thread exists.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

//! `repro`: parses the command line and dispatches (`cli/`); all work lives in the library.

mod cli;

use std::process::ExitCode;

fn main() -> ExitCode {
    match cli::run(cli::args::parse()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

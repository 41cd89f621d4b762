//! `repro`: parses the command line and dispatches; all work lives in the library.

mod cli;
mod report;

use clap::Parser;
use cli::{Cli, Command};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Solve(args) => report::solve(&args),
        Command::Table4(args) => report::table4(&args),
        Command::List => {
            for t in repro::artefacts::TARGETS {
                println!("{:<8} {}", t.name, t.description);
            }
            Ok(true)
        }
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

//! `repro`: parses the command line and dispatches; each command lives in `cli/`, all work
//! in the library.

mod cli;

use cli::args::{Cli, Command};
use std::process::ExitCode;

fn main() -> ExitCode {
    let result = match Cli::parse_args().command {
        Command::Solve(a) => cli::solve::run(&a),
        Command::Table4(a) => cli::target::table4(&a),
        Command::Table1(a) => cli::target::one("table1", &a),
        Command::Table2(a) => cli::target::one("table2", &a),
        Command::Table3(a) => cli::target::one("table3", &a),
        Command::Fig1(a) => cli::target::one("fig1", &a),
        Command::Fig2(a) => cli::target::one("fig2", &a),
        Command::Fig3(a) => cli::target::one("fig3", &a),
        Command::Fig4(a) => cli::target::one("fig4", &a),
        Command::Fig5(a) => cli::target::one("fig5", &a),
        Command::Fig6(a) => cli::target::one("fig6", &a),
        Command::Fig7(a) => cli::target::one("fig7", &a),
        Command::Fig8(a) => cli::target::one("fig8", &a),
        Command::Mastercurve(a) => cli::target::one("mastercurve", &a),
        Command::Thermal(a) => cli::target::one("thermal", &a),
        Command::Lss(a) => cli::target::one("lss", &a),
        Command::All(a) => cli::target::all(&a),
        Command::Run(a) => cli::target::study(&a),
        Command::List => cli::target::list(),
        Command::Predict(a) => cli::predict::run(&a),
        Command::Check(a) => cli::check::run(&a),
        Command::Accuracy(a) => cli::accuracy::run(&a),
        Command::Cache(a) => cli::cache::run(&a),
        Command::Slurm(a) => cli::slurm::run(&a),
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

//! `repro`: parses the command line and dispatches; all work lives in the library.

mod accuracy_cmd;
mod check;
mod cli;
mod predict;
mod report;
mod solve_line;

use clap::Parser;
use cli::{Cli, Command};
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Solve(args) => report::solve(&args),
        Command::Table4(args) => report::table4(&args),
        Command::Table1(a) => report::target("table1", &a),
        Command::Table2(a) => report::target("table2", &a),
        Command::Table3(a) => report::target("table3", &a),
        Command::Fig1(a) => report::target("fig1", &a),
        Command::Fig2(a) => report::target("fig2", &a),
        Command::Fig3(a) => report::target("fig3", &a),
        Command::Fig4(a) => report::target("fig4", &a),
        Command::Fig5(a) => report::target("fig5", &a),
        Command::Fig6(a) => report::target("fig6", &a),
        Command::Fig7(a) => report::target("fig7", &a),
        Command::Fig8(a) => report::target("fig8", &a),
        Command::Predict(a) => predict::predict(&a),
        Command::All(a) => report::all(&a),
        Command::Run(a) => report::run_study(&a),
        Command::Check(a) => check::check(&a),
        Command::Accuracy(a) => accuracy_cmd::run(&a),
        Command::List => {
            for t in repro::artefacts::targets::TARGETS {
                let level = t
                    .default_level
                    .map(|l| format!("[level {l}]"))
                    .unwrap_or_default();
                println!("{:<8} {:<10} {}", t.name, level, t.description);
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

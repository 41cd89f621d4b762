//! The command line, in layers: `args` (every flag; the only file that knows clap; the
//! targets' subcommands come from the registry, `repro::paper::REGISTRY`) and `config` (flags
//! turned once into cases, solver parameters and the pipeline's context) at the bottom;
//! `print` and `progress` (what the commands share on stdout and stderr) above them; one
//! file per command on top. Commands call the library and print; the library knows nothing
//! of the command line.

pub mod accuracy;
pub mod args;
pub mod cache;
pub mod check;
pub mod config;
pub mod predict;
pub mod print;
pub mod progress;
pub mod shard;
pub mod slurm;
pub mod solve;
pub mod target;
pub mod thermal;

use anyhow::Result;
use args::{Command, Invocation};

/// Runs what the command line asked for: `Ok(false)` when it ran and found a failure (a
/// solve that did not converge, a snapshot that differs), an error when it could not run.
pub fn run(invocation: Invocation) -> Result<bool> {
    let command = match invocation {
        Invocation::Target(target, a) => return target::one(target, &a),
        Invocation::Command(c) => c,
    };
    match command {
        Command::Solve(a) => solve::run(&a),
        Command::Table4(a) => target::table4(&a),
        Command::Predict(a) => predict::run(&a),
        Command::All(a) => target::all(&a),
        Command::Run(a) => target::study(&a),
        Command::Check(a) => check::run(&a),
        Command::Accuracy(a) => accuracy::run(&a),
        Command::List => target::list(),
        Command::Cache(a) => cache::run(&a),
        Command::Slurm(a) => slurm::run(&a),
    }
}

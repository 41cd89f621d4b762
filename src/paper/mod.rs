//! The paper's targets: one module per table or figure (or study beyond the paper), each
//! with its cases, its computation and its picture, and the registry every command reads.
//!
//! A target is a [`Target`] (`target.rs`); [`REGISTRY`] lists them in the paper's
//! order. `repro list`, the subcommands `repro <target>`, `repro all` (`make figures`),
//! `repro check`, `repro slurm`, `--shard` and `--offline` all read it: adding a target is
//! adding its module and one line here.
//!
//! Below the targets: [`eq13`] (Eq. (13), the mastercurve, and its fit to a set of points),
//! which the figures, the tables, the report and `repro predict` measure against. Beside
//! them: [`prediction`] (the mastercurve as a tool, `repro predict`) and [`accuracy`]
//! (`repro accuracy`, the level study behind each target's default level).

pub mod accuracy;
pub mod cases;
pub mod eq13;
pub mod fig8;
pub mod figures;
pub mod lss;
pub mod mastercurve;
pub mod picture;
pub mod prediction;
pub mod table4;
pub mod tables;
pub mod target;
pub mod thermal;

use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::job::Job;
use crate::pipeline::provenance::{Provenance, SUFFIX};
use std::time::Instant;
pub use target::{Target, TargetReport};

/// Every target, in the paper's order.
pub static REGISTRY: &[&dyn Target] = &[
    &tables::Table1,
    &tables::Table2,
    &tables::Table3,
    &table4::Table4,
    &figures::FIG1,
    &figures::FIG2,
    &figures::FIG3,
    &figures::FIG4,
    &figures::FIG5,
    &figures::FIG6,
    &figures::FIG7,
    &fig8::Fig8,
    &mastercurve::Mastercurve,
    &thermal::ShearHeating,
    &lss::Lss,
];

/// The target named `name`.
pub fn find(name: &str) -> Option<&'static dyn Target> {
    REGISTRY.iter().copied().find(|a| a.name() == name)
}

/// The target named `name`, or an error that says which targets there are.
pub fn known(name: &str) -> Result<&'static dyn Target, PipelineError> {
    find(name).ok_or_else(|| {
        let known: Vec<&str> = REGISTRY.iter().map(|a| a.name()).collect();
        PipelineError::UnknownTarget {
            name: name.to_string(),
            known: known.join(", "),
        }
    })
}

/// Every solve of the targets `names` in the context, each with its target: what a run of
/// them shards and what `--offline` must find in the cache.
pub fn jobs_of(names: &[&str], ctx: &Context) -> Result<Vec<(String, Job)>, PipelineError> {
    let mut out = Vec::new();
    for n in names {
        let jobs = known(n)?.jobs(ctx)?;
        out.extend(jobs.into_iter().map(|j| (n.to_string(), j)));
    }
    Ok(out)
}

/// Builds `target`, timed, with its provenance sidecar (the targets that solve nothing get
/// one that says so).
pub fn build(target: &dyn Target, ctx: &Context) -> Result<TargetReport, PipelineError> {
    let start = Instant::now();
    let mut report = target.build(ctx)?;
    if !report.files.iter().any(|f| f.ends_with(SUFFIX)) {
        let name = target.name();
        let sidecar = Provenance::new(name, &report.files).to_json();
        report
            .files
            .push(ctx.write(&format!("{name}{SUFFIX}"), &sidecar)?);
    }
    report.seconds = start.elapsed().as_secs_f64();
    Ok(report)
}

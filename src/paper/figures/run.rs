//! The cases of a sweep a context runs ([`selection`]), as solves ([`study_jobs`]) and run
//! through the cache ([`run_sweep`]): what every sweep figure, a study and the targets built
//! on the figures' sweeps share.

use crate::paper::target::WORKING_LEVEL;
use crate::physics::case::Case;
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::{run_cases_in, PointRun, RunProgress};
use crate::pipeline::job::{point_jobs, Job, Setup};
use crate::pipeline::sweep::Sweep;

/// The cases of a sweep that a context runs (a sample of the large sweeps at the snapshot
/// profile) and their level: the context's, else the sweep's own, else the target's
/// `default_level`, else the working level.
pub(super) fn selection(
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> (Vec<Case>, u32) {
    let level = ctx
        .level
        .or(sweep.level)
        .or(default_level)
        .unwrap_or(WORKING_LEVEL);
    let stride = ctx.stride_for(sweep.cases.len());
    let cases: Vec<_> = sweep.cases.iter().step_by(stride).cloned().collect();
    (cases, level)
}

/// Runs a sweep's cases of the context (see [`selection`]) through the cache.
pub fn run_sweep(
    label: &str,
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<(Vec<PointRun>, u32), PipelineError> {
    let (cases, level) = selection(sweep, default_level, ctx);
    let progress = |p: RunProgress| (ctx.progress)(label, p);
    let runs = run_cases_in(
        label,
        (&cases, level, Setup::Rule),
        ctx.cache_policy(),
        &progress,
        ctx.warn,
        ctx.stop,
    )?;
    Ok((runs, level))
}

/// Every solve of a sweep in the context (a study of `repro run`, or a figure's sweep).
pub fn study_jobs(
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<Vec<Job>, PipelineError> {
    let (cases, level) = selection(sweep, default_level, ctx);
    Ok(point_jobs(&cases, level)?
        .into_iter()
        .map(|p| p.job)
        .collect())
}

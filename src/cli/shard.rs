//! Sharded and offline runs of targets: `--shard I/N` (or a Slurm array task's variables)
//! solves a share of the targets' cases into the cache and writes nothing else; `--offline`
//! first checks that the cache holds every case of the targets, naming all that it lacks.

use super::args::TargetArgs;
use super::progress::in_context_writing;
use anyhow::{bail, Context as _, Result};
use repro::pipeline::context::Context;
use repro::pipeline::executor::{run_jobs, RunProgress};
use repro::pipeline::job::Job;
use repro::pipeline::offline::{check_complete, missing};
use repro::pipeline::outcome::CaseOutcome;
use repro::pipeline::shard::Shard;
use std::time::Instant;

/// The solves of a run, each with the target that needs it.
pub type TargetJobs = Vec<(String, Job)>;

/// The shard this run solves: `--shard`, else a Slurm array task's (said on stderr), else
/// none. `--offline` never shards.
pub fn detect(args: &TargetArgs) -> Result<Option<Shard>> {
    if let Some(text) = &args.shard {
        return Ok(Some(Shard::parse(text).context("--shard")?));
    }
    if args.offline {
        return Ok(None);
    }
    let var = |name: &str| std::env::var(name).ok();
    let (Some(id), Some(count)) = (var("SLURM_ARRAY_TASK_ID"), var("SLURM_ARRAY_TASK_COUNT"))
    else {
        return Ok(None);
    };
    let min = var("SLURM_ARRAY_TASK_MIN");
    let step = var("SLURM_ARRAY_TASK_STEP");
    let shard = Shard::from_slurm(&id, &count, min.as_deref(), step.as_deref())
        .context("Slurm array task")?;
    eprintln!(
        "Slurm array task {id} of {count} (from {}): solving shard {shard} of the cases (no --shard given)",
        min.as_deref().unwrap_or("?")
    );
    Ok(Some(shard))
}

/// Solves `shard` of the jobs `list` gives in the context of `args`, into the cache: one
/// line per solve and a summary on stdout (the task's log), no figures. Errors when an
/// entry could not be written (the shard's work would be lost).
pub fn run(
    args: &TargetArgs,
    shard: Shard,
    list: impl FnOnce(&Context) -> Result<TargetJobs>,
) -> Result<bool> {
    let start = Instant::now();
    in_context_writing(args, false, true, |ctx| {
        let all = list(ctx)?;
        // Targets share cases (Figs. 1-3 draw one sweep): count each solve once.
        let total = all
            .iter()
            .map(|(_, j)| j.key.as_str())
            .collect::<std::collections::BTreeSet<_>>()
            .len();
        let targets: Vec<String> = all.iter().map(|(t, _)| t.clone()).collect();
        let jobs: Vec<Job> = shard.select(all.iter().map(|(_, j)| j.clone()).collect());
        let target_of = |key: &str| {
            all.iter()
                .find(|(_, j)| j.key == key)
                .map(|(t, _)| t.as_str())
                .unwrap_or("?")
        };
        let Some(cache) = ctx.cache.as_ref() else {
            bail!("--shard: a shard writes cache entries only; drop --no-cache");
        };
        let mut names = targets.clone();
        names.dedup();
        println!(
            "shard {shard} of {}: {} of {total} solves, into the cache {}",
            names.join(" "),
            jobs.len(),
            cache.dir().display()
        );
        let label = format!("shard {shard}");
        let progress = |p: RunProgress| (ctx.progress)(&label, p);
        let done = run_jobs(&label, &jobs, ctx.cache_policy(), &progress, ctx.warn)?;
        let (mut solved, mut cached, mut failed) = (0, 0, 0);
        for (job, d) in jobs.iter().zip(&done) {
            let status = match (&d.outcome, d.cached) {
                (_, true) => {
                    cached += 1;
                    "cached".to_string()
                }
                (CaseOutcome::Solved(_), false) => {
                    solved += 1;
                    "solved".to_string()
                }
                (CaseOutcome::Failed(f), false) => {
                    failed += 1;
                    f.status()
                }
            };
            let seconds = d
                .stamp
                .as_ref()
                .filter(|_| !d.cached)
                .map(|s| format!(" in {:.2} s", s.seconds))
                .unwrap_or_default();
            println!(
                "  {status}{seconds}: {}: {} [key {}]",
                target_of(&job.key),
                job.label,
                job.key
            );
        }
        let unwritten = missing(&jobs, cache);
        if !unwritten.is_empty() {
            bail!(
                "shard {shard}: {} of its results are not in the cache {} (see the warnings above); the shard must be run again",
                unwritten.len(),
                cache.dir().display()
            );
        }
        println!(
            "shard {shard}: {} solves ({solved} solved, {cached} already cached, {failed} failed, failures cached as results) in {:.1} s; wrote cache entries only",
            jobs.len(),
            start.elapsed().as_secs_f64()
        );
        Ok(true)
    })
}

/// For `--offline`: an error listing every job of `list` the cache lacks, across targets.
pub fn check_offline(ctx: &Context, list: &TargetJobs) -> Result<()> {
    let Some(cache) = ctx.cache.as_ref() else {
        bail!("--offline needs the cache; drop --no-cache");
    };
    Ok(check_complete(cache, list)?)
}

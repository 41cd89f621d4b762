//! The paper as targets: `repro list`, `repro <target>`, `repro all`, `repro run` (a user's
//! sweep) and `repro table4` (with its own levels and per-cycle progress).

use super::args::{RunArgs, Table4Args, TargetArgs};
use super::config::check_level;
use super::print::{solve_progress, summary_line};
use super::progress::in_context;
use super::shard::{self, TargetJobs};
use anyhow::{Context as _, Result};
use repro::paper::eq13::FIT_TAU_C_MIN;
use repro::paper::table4;
use repro::paper::{self, Target, REGISTRY};
use repro::pipeline::cache::GIT_REVISION;
use repro::pipeline::context::Context;
use repro::pipeline::csv::write_atomic;
use repro::pipeline::executor::{run_jobs, RunProgress};
use repro::pipeline::job::Job;
use repro::pipeline::sweep::Sweep;
use repro::report;
use std::time::Instant;

/// Every solve of the targets `names` in the context, with its target.
fn target_jobs(names: &[&str], ctx: &Context) -> Result<TargetJobs> {
    Ok(paper::jobs_of(names, ctx)?)
}

/// Before an offline build: every case of `names` must be in the cache.
fn check_offline(names: &[&str], ctx: &Context) -> Result<()> {
    if ctx.offline {
        shard::check_offline(ctx, &target_jobs(names, ctx)?)?;
    }
    Ok(())
}

/// `repro list`: one line per target.
pub fn list() -> Result<bool> {
    let width = REGISTRY.iter().map(|a| a.name().len()).max().unwrap_or(0);
    for a in REGISTRY {
        let level = a
            .default_level()
            .map(|l| format!("[level {l}]"))
            .unwrap_or_default();
        println!("{:<width$} {:<10} {}", a.name(), level, a.describe());
    }
    Ok(true)
}

/// `repro <target>`.
pub fn one(target: &dyn Target, args: &TargetArgs) -> Result<bool> {
    let name = target.name();
    if let Some(s) = shard::detect(args)? {
        return shard::run(args, s, |ctx| target_jobs(&[name], ctx));
    }
    let built = in_context(args, true, |ctx| {
        check_offline(&[name], ctx)?;
        Ok(paper::build(target, ctx)?)
    })?;
    println!("{}", summary_line(&built));
    Ok(true)
}

/// `repro all`: every target, then `summary.csv` and `index.html`.
pub fn all(args: &TargetArgs) -> Result<bool> {
    let names: Vec<&str> = REGISTRY.iter().map(|a| a.name()).collect();
    if let Some(s) = shard::detect(args)? {
        return shard::run(args, s, |ctx| target_jobs(&names, ctx));
    }
    if GIT_REVISION.ends_with("-dirty") {
        eprintln!(
            "warning: this build ({GIT_REVISION}) has uncommitted source changes: index.html \
             will say at its top that no commit reproduces it (make figures refuses such a build)"
        );
    }
    let mut solved = None;
    let built = in_context(args, true, |ctx| {
        check_offline(&names, ctx)?;
        solved = solve_together(&names, ctx)?;
        Ok(report::build_all(REGISTRY, ctx)?)
    })?;
    if let Some((cases, solved, seconds)) = solved {
        println!(
            "all: {cases} cases of every target, {solved} solved in one pool in {seconds:.1} s"
        );
    }
    for b in &built {
        println!("{}", summary_line(b));
    }
    println!("wrote {}", args.out.join("summary.csv").display());
    Ok(true)
}

/// Solves the missing cases of the targets `names` in one pool into the cache, before the
/// targets are assembled from it: the heaviest trees of every target first, so that no
/// target's last solves leave a core idle (one target after another, the cold run of every
/// target at level 7 took about 1 % longer wall). The number of distinct cases, of those
/// solved (not found in the cache), and the wall time; nothing where there is no cache to
/// fill or nothing may be solved.
fn solve_together(names: &[&str], ctx: &Context) -> Result<Option<(usize, usize, f64)>> {
    if ctx.offline || ctx.cache.is_none() {
        return Ok(None);
    }
    let start = Instant::now();
    let mut seen = std::collections::BTreeSet::new();
    let jobs: Vec<Job> = target_jobs(names, ctx)?
        .into_iter()
        .map(|(_, j)| j)
        .filter(|j| seen.insert(j.key.clone()))
        .collect();
    let progress = |p: RunProgress| (ctx.progress)("all", p);
    let finished = run_jobs("all", &jobs, ctx.cache_policy(), &progress, ctx.warn)?;
    let solved = finished.iter().filter(|f| !f.cached).count();
    Ok(Some((jobs.len(), solved, start.elapsed().as_secs_f64())))
}

/// `repro run my-study.toml`: the same pipeline as a figure target.
pub fn study(args: &RunArgs) -> Result<bool> {
    let sweep = Sweep::read(&args.file)?;
    let stem = args
        .file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "study".into());
    let study_jobs = |ctx: &Context| -> Result<TargetJobs> {
        let jobs = paper::figures::study_jobs(&sweep, None, ctx)
            .with_context(|| args.file.display().to_string())?;
        Ok(jobs.into_iter().map(|j| (stem.clone(), j)).collect())
    };
    if let Some(s) = shard::detect(&args.target)? {
        return shard::run(&args.target, s, study_jobs);
    }
    let t = Instant::now();
    let mut built = in_context(&args.target, true, |ctx| {
        if ctx.offline {
            shard::check_offline(ctx, &study_jobs(ctx)?)?;
        }
        paper::figures::study(&stem, &sweep, ctx).with_context(|| args.file.display().to_string())
    })?;
    built.seconds = t.elapsed().as_secs_f64();
    println!("{}", summary_line(&built));
    if let Some(fit) = built.eq13() {
        println!(
            "mastercurve (paper: c = 5): {} points with tau_c >= {FIT_TAU_C_MIN}: {}; c = {:.2} over all solved",
            fit.points,
            fit.describe(),
            built.eq13_c_all().unwrap_or(f64::NAN)
        );
    } else {
        println!("mastercurve (paper: c = 5): {}", built.ours);
    }
    Ok(built.solved == Some(built.cases))
}

/// `repro table4`: false when a level failed.
pub fn table4(args: &Table4Args) -> Result<bool> {
    let spec = table4::Table4Case::shipped()?;
    let levels = match &args.levels {
        Some(l) => l
            .iter()
            .map(|&v| check_level("levels", v))
            .collect::<Result<Vec<_>>>()?,
        None => spec.levels.clone(),
    };
    let mut printer = solve_progress(args.quiet);
    let rows = table4::compute(&spec, &levels, |p| printer(p))?;
    let path = args.out.join("table4.csv");
    write_atomic(&path, &table4::to_csv(&rows))
        .with_context(|| format!("--out: cannot write {}", path.display()))?;
    print!("{}", table4::to_text(&rows));
    println!("wrote {}", path.display());
    Ok(rows.iter().all(|r| r.outcome.solved().is_some()))
}

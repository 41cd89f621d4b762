//! `repro slurm TARGET... --tasks N`: writes the sbatch scripts of a sharded run and prints
//! how to submit them.

use super::args::{SlurmArgs, TargetArgs};
use super::config::context;
use anyhow::{bail, Context as _, Result};
use repro::paper::{self, REGISTRY};
use repro::pipeline::csv::write_atomic;
use repro::pipeline::slurm::{sh_quote, SlurmPlan};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Typical wall time of one solve on one core, s, by level: the development machine's
/// benchmarks (docs/RESULTS.md, "What accuracy costs"), rounded up. For the estimate printed only.
fn typical_seconds(level: u32) -> f64 {
    match level {
        0..=5 => 0.5,
        6 => 1.0,
        7 => 2.5,
        _ => 10.0,
    }
}

/// `path` made absolute against the current directory.
fn absolute(path: &Path) -> Result<PathBuf> {
    std::path::absolute(path)
        .with_context(|| format!("{}: cannot make it absolute", path.display()))
}

/// `repro slurm`.
pub fn run(args: &SlurmArgs) -> Result<bool> {
    let names: Vec<&str> = if args.targets.iter().any(|t| t == "all") {
        REGISTRY.iter().map(|a| a.name()).collect()
    } else {
        args.targets.iter().map(String::as_str).collect()
    };
    if args.tasks == 0 {
        bail!("--tasks: at least 1");
    }
    if args.cpus == 0 {
        bail!("--cpus: at least 1");
    }
    // The solves of the run, counted as a shard counts them (distinct cache keys).
    let listing = TargetArgs {
        level: args.level,
        out: args.out.clone(),
        cache: args.cache.clone(),
        no_cache: true,
        shard: None,
        offline: false,
        quiet: true,
    };
    let (progress, warn) = (|_: &str, _| {}, |_: String| {});
    let ctx = context(&listing, false, &progress, &warn)?;
    let mut keys = BTreeSet::new();
    // Shards take whole families (the cases that start from one base).
    let mut families = BTreeSet::new();
    for n in &names {
        for j in paper::known(n).and_then(|a| a.jobs(&ctx))? {
            families.insert(j.family().to_string());
            keys.insert(j.key);
        }
    }
    let solves = keys.len();
    if solves == 0 {
        bail!(
            "{}: nothing to solve (emitted targets need no cluster)",
            args.targets.join(" ")
        );
    }
    let tasks = args.tasks.min(families.len());
    let repro = match &args.repro {
        Some(p) => absolute(p)?,
        None => std::env::current_exe().context("cannot find this repro binary; pass --repro")?,
    };
    let plan = SlurmPlan {
        name: args
            .name
            .clone()
            .unwrap_or_else(|| format!("repro-{}", args.targets[0])),
        targets: args.targets.clone(),
        tasks,
        level: args.level,
        partition: args.partition.clone(),
        time: args.time.clone(),
        cpus: args.cpus,
        dir: absolute(&args.dir)?,
        cache: absolute(&args.cache)?,
        out: absolute(&args.out)?,
        repro,
        workdir: absolute(Path::new("."))?,
        solves,
    };
    for dir in [plan.dir.join("logs"), plan.dir.join("caches")] {
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("--dir: cannot create {}", dir.display()))?;
    }
    for (path, text) in [
        (plan.array_path(), plan.array_script()),
        (plan.assemble_path(), plan.assemble_script()),
        (plan.submit_path(), plan.submit_script()),
    ] {
        write_atomic(&path, &text)
            .with_context(|| format!("--dir: cannot write {}", path.display()))?;
    }
    if tasks < args.tasks {
        println!(
            "--tasks {} lowered to {tasks}: there are {solves} solves in {} families (a task takes whole families)",
            args.tasks,
            families.len()
        );
    }
    let per_task = solves.div_ceil(families.len()) * families.len().div_ceil(tasks);
    let level = args.level.unwrap_or(7);
    let seconds = per_task as f64 * typical_seconds(level) / args.cpus as f64;
    let minutes = seconds / 60.0;
    let took = if minutes < 1.0 {
        format!("{seconds:.0} s")
    } else {
        format!("{minutes:.0} min")
    };
    println!(
        "{solves} solves in {tasks} array tasks: up to {per_task} per task, about {took} each on {} CPU(s) at level {level}{} (typical solves; heavy cases take several times longer)",
        args.cpus,
        if args.level.is_none() { " (the estimate's level; each target runs at its own)" } else { "" }
    );
    if minutes < 1.0 && tasks > 1 {
        let whole = solves as f64 * typical_seconds(level) / args.cpus as f64;
        let fewer = ((whole / 300.0).ceil() as usize).max(1);
        if fewer == 1 {
            println!(
                "note: tasks this short spend more time being scheduled than solving; the whole run is about {whole:.0} s of solves, one task (--tasks 1) is enough"
            );
        } else {
            println!(
                "note: tasks this short spend more time being scheduled than solving; --tasks {fewer} gives each about 5 minutes"
            );
        }
    }
    println!(
        "wrote {}, {} and {}",
        plan.array_path().display(),
        plan.assemble_path().display(),
        plan.submit_path().display()
    );
    println!(
        "submit with:\n  sh {}\nor by hand:\n  jid=$(sbatch --parsable {})\n  sbatch --dependency=afterok:$jid {}",
        sh_quote(&plan.submit_path().to_string_lossy()),
        sh_quote(&plan.array_path().to_string_lossy()),
        sh_quote(&plan.assemble_path().to_string_lossy())
    );
    Ok(true)
}

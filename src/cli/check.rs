//! `repro check`: recompute targets at the snapshot profile and compare with the baselines.

use super::args::{CheckArgs, TargetArgs};
use super::print::summary_line;
use super::progress::in_context;
use anyhow::Result;
use repro::paper::{self, known, Target, REGISTRY};
use repro::pipeline::snapshot::{self, PROFILE_LEVEL, PROFILE_STRIDE};
use repro::report;

/// Differences printed before the rest are only counted.
const SHOWN: usize = 40;

/// `repro check`: false when a result differs from its baseline.
pub fn run(args: &CheckArgs) -> Result<bool> {
    let all = args.targets.is_empty();
    let targets: Vec<&dyn Target> = if all {
        REGISTRY.to_vec()
    } else {
        args.targets
            .iter()
            .map(|n| known(n))
            .collect::<Result<_, _>>()?
    };
    let work = std::env::temp_dir().join(format!("repro-check-{}", std::process::id()));
    let target_args = TargetArgs {
        level: Some(PROFILE_LEVEL),
        out: work.join("out"),
        cache: work.join("cache"),
        no_cache: false,
        shard: None,
        offline: false,
        quiet: args.quiet,
    };
    // Failed cases are part of the baselines, not news: no warnings.
    let result = in_context(&target_args, false, |ctx| {
        ctx.stride = PROFILE_STRIDE;
        let ctx = &*ctx;
        let built = if all {
            report::build_all(&targets, ctx)?
        } else {
            targets
                .iter()
                .map(|a| paper::build(*a, ctx))
                .collect::<Result<Vec<_>, _>>()?
        };
        if !args.quiet {
            for b in &built {
                eprintln!("  {}", summary_line(b));
            }
        }
        let files = snapshot::csv_files(built.iter().flat_map(|b| &b.files), all);
        let diffs = snapshot::check_files(&args.snapshots, &ctx.out, &files)?;
        for d in diffs.iter().take(SHOWN) {
            eprintln!("{}", d);
        }
        if diffs.len() > SHOWN {
            eprintln!("... and {} more differences", diffs.len() - SHOWN);
        }
        if args.accept {
            snapshot::accept(&args.snapshots, &ctx.out, &files)?;
            println!(
                "accepted {} files into {} ({} differences above)",
                files.len(),
                args.snapshots.display(),
                diffs.len()
            );
            return Ok(true);
        }
        if diffs.is_empty() {
            println!(
                "check: {} files of {} targets agree with {} (level {PROFILE_LEVEL}, every {PROFILE_STRIDE}th case of the large sweeps)",
                files.len(),
                built.len(),
                args.snapshots.display()
            );
            Ok(true)
        } else {
            println!(
                "check: {} differences from {}; if intended, run `make snapshots`",
                diffs.len(),
                args.snapshots.display()
            );
            Ok(false)
        }
    });
    let _ = std::fs::remove_dir_all(&work);
    result
}

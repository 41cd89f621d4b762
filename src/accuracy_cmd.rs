//! `repro accuracy`: the level study of [`repro::artefacts::accuracy`], its files and summary.

use anyhow::{bail, Context as _, Result};
use clap::Args;
use repro::artefacts::accuracy::{self, MU_TOLERANCE};
use repro::artefacts::csv::write_atomic;
use std::path::PathBuf;

/// Flags of `repro accuracy`.
#[derive(Debug, Args)]
pub struct AccuracyArgs {
    /// Point-contact levels, `A..B` (inclusive) or a comma list (the line contact runs 2
    /// levels finer).
    #[arg(long, default_value = "4..8", value_parser = parse_levels)]
    pub levels: Levels,
    /// Solves per level; the median wall time is kept.
    #[arg(long, default_value_t = 1)]
    pub repeats: usize,
    /// Leave out the line contact of Fig. 7 (studied 2 levels finer than the point
    /// contacts; its level 10 takes about 1.5 s, its dense Newton solve is O(n^3)).
    #[arg(long = "no-line")]
    pub no_line: bool,
    /// Output folder.
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// No per-level progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

/// A list of grid levels.
#[derive(Debug, Clone)]
pub struct Levels(pub Vec<u32>);

fn parse_levels(s: &str) -> std::result::Result<Levels, String> {
    let levels: Vec<u32> = if let Some((a, b)) = s.split_once("..") {
        let a: u32 = a.trim().parse().map_err(|e| format!("'{a}': {e}"))?;
        let b: u32 = b.trim().parse().map_err(|e| format!("'{b}': {e}"))?;
        (a..=b).collect()
    } else {
        s.split(',')
            .map(|v| v.trim().parse().map_err(|e| format!("'{v}': {e}")))
            .collect::<std::result::Result<_, _>>()?
    };
    if levels.is_empty() || levels.windows(2).any(|w| w[0] >= w[1]) {
        return Err(format!("'{s}': give increasing levels, e.g. 4..8 or 5,6,7"));
    }
    Ok(Levels(levels))
}

/// Runs the study; false when a case converged at none of its levels.
pub fn run(args: &AccuracyArgs) -> Result<bool> {
    for &l in &args.levels.0 {
        crate::cli::check_level("--levels", l)?;
    }
    if args.repeats == 0 {
        bail!("--repeats: must be at least 1");
    }
    let cases = accuracy::study_cases(!args.no_line).map_err(anyhow::Error::msg)?;
    let quiet = args.quiet;
    let mut progress = |c: &accuracy::StudyCase, r: &accuracy::LevelRun| {
        if quiet {
            return;
        }
        match &r.outcome {
            Ok(m) => eprintln!(
                "  {} level {}: Hc {:.5e}, mu-bar {:.4}, {} cycles, {:.3} s",
                c.name, r.level, m.h_central, m.mu_bar, m.cycles, r.seconds
            ),
            Err(e) => eprintln!(
                "  {} level {}: failed ({:.3} s): {e}",
                c.name, r.level, r.seconds
            ),
        }
    };
    let studies = accuracy::run(&cases, &args.levels.0, args.repeats, &mut progress);
    let recs = accuracy::recommend(&studies, MU_TOLERANCE);
    let files = [
        ("accuracy.csv", accuracy::to_csv(&studies)),
        ("accuracy_levels.csv", accuracy::recommendations_csv(&recs)),
        (
            "accuracy.svg",
            accuracy::svg(&studies).map_err(anyhow::Error::msg)?,
        ),
    ];
    for (name, text) in &files {
        let path = args.out.join(name);
        write_atomic(&path, text)
            .with_context(|| format!("--out: cannot write {}", path.display()))?;
    }
    print!("{}", accuracy::to_text(&studies, &recs));
    println!(
        "wrote {}",
        files
            .iter()
            .map(|f| args.out.join(f.0).display().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
    // A level that fails (a film that collapses on a coarse grid) is a result of the study,
    // not a failure of the command; a case with no converged level at all is.
    Ok(studies.iter().all(|s| s.reference.is_some()))
}

//! `repro accuracy`: the level study of [`repro::paper::accuracy`], its files and summary.

use super::args::AccuracyArgs;
use super::config::check_level;
use anyhow::{bail, Context as _, Result};
use repro::paper::accuracy::{self, MU_TOLERANCE};
use repro::pipeline::csv::write_atomic;

/// Runs the study; false when a case converged at none of its levels.
pub fn run(args: &AccuracyArgs) -> Result<bool> {
    for &l in &args.levels.0 {
        check_level("levels", l)?;
    }
    if args.repeats == 0 {
        bail!("--repeats: must be at least 1");
    }
    let cases = accuracy::cases::accuracy_cases(!args.no_line)?;
    let quiet = args.quiet;
    let mut progress = |c: &accuracy::AccuracyCase, r: &accuracy::LevelRun| {
        if quiet {
            return;
        }
        match &r.outcome {
            Ok(m) => eprintln!(
                "  {} level {}: ended on {}, Hc {:.5e}, Hmin {:.5e}, mu-bar {:.4}, {} cycles, {:.3} s",
                c.name,
                r.level,
                c.contact.points(m.level, m.across),
                m.h_central,
                m.h_min,
                m.mu_bar,
                m.cycles,
                r.seconds
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
        ("accuracy.csv", accuracy::files::to_csv(&studies)),
        (
            "accuracy_levels.csv",
            accuracy::files::recommendations_csv(&recs),
        ),
        ("accuracy.svg", accuracy::picture::svg(&studies)?),
        ("accuracy_film.svg", accuracy::picture::film_svg(&studies)?),
        ("accuracy_hmin.svg", accuracy::picture::h_min_svg(&studies)?),
    ];
    for (name, text) in &files {
        let path = args.out.join(name);
        write_atomic(&path, text)
            .with_context(|| format!("--out: cannot write {}", path.display()))?;
    }
    print!("{}", accuracy::files::to_text(&studies, &recs));
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

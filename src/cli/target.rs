//! The paper as targets: `repro list`, `repro <target>`, `repro all`, `repro run` (a user's
//! sweep) and `repro table4` (with its own levels and per-cycle progress).

use super::args::{RunArgs, Table4Args, TargetArgs};
use super::config::check_level;
use super::print::{point_progress, summary_line};
use super::progress::in_context;
use anyhow::{anyhow, Context as _, Result};
use repro::artefacts::csv::write_atomic;
use repro::artefacts::sweep::Sweep;
use repro::artefacts::table4;
use repro::artefacts::{report, targets};
use std::time::Instant;

/// `repro list`: one line per target.
pub fn list() -> Result<bool> {
    let width = targets::TARGETS
        .iter()
        .map(|t| t.name.len())
        .max()
        .unwrap_or(0);
    for t in targets::TARGETS {
        let level = t
            .default_level
            .map(|l| format!("[level {l}]"))
            .unwrap_or_default();
        println!("{:<width$} {:<10} {}", t.name, level, t.description);
    }
    Ok(true)
}

/// `repro <target>`.
pub fn one(name: &str, args: &TargetArgs) -> Result<bool> {
    let built = in_context(args, true, |ctx| {
        targets::build(name, ctx).map_err(anyhow::Error::msg)
    })?;
    println!("{}", summary_line(&built));
    Ok(true)
}

/// `repro all`: every target, then `summary.csv` and `index.html`.
pub fn all(args: &TargetArgs) -> Result<bool> {
    let names: Vec<&str> = targets::TARGETS.iter().map(|t| t.name).collect();
    let built = in_context(args, true, |ctx| {
        report::build_all(&names, ctx).map_err(anyhow::Error::msg)
    })?;
    for b in &built {
        println!("{}", summary_line(b));
    }
    println!("wrote {}", args.out.join("summary.csv").display());
    Ok(true)
}

/// `repro run my-study.toml`: the same pipeline as a figure target.
pub fn study(args: &RunArgs) -> Result<bool> {
    let sweep = Sweep::read(&args.file)?;
    let stem = args
        .file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "study".into());
    let t = Instant::now();
    let mut built = in_context(&args.target, true, |ctx| {
        targets::figure::study(&stem, &sweep, ctx)
            .map_err(|e| anyhow!("{}: {e}", args.file.display()))
    })?;
    built.seconds = t.elapsed().as_secs_f64();
    println!("{}", summary_line(&built).replacen("study", &stem, 1));
    println!("mastercurve (paper: c = 5): {}", built.ours);
    Ok(built.solved == Some(built.cases))
}

/// `repro table4`: false when a level failed.
pub fn table4(args: &Table4Args) -> Result<bool> {
    let spec = table4::Table4Case::shipped().map_err(anyhow::Error::msg)?;
    let levels = match &args.levels {
        Some(l) => l
            .iter()
            .map(|&v| check_level("--levels", v))
            .collect::<Result<Vec<_>>>()?,
        None => spec.levels.clone(),
    };
    let mut printer = point_progress(args.quiet);
    let rows = table4::compute(&spec, &levels, |p| printer(p)).map_err(anyhow::Error::msg)?;
    let path = args.out.join("table4.csv");
    write_atomic(&path, &table4::to_csv(&rows))
        .with_context(|| format!("--out: cannot write {}", path.display()))?;
    print!("{}", table4::to_text(&rows));
    println!("wrote {}", path.display());
    Ok(rows.iter().all(|r| r.outcome.is_ok()))
}

//! `repro cache`: what a cache holds per solver revision (`list`, the default), the pruning
//! of what the present revisions cannot reach (`prune`), and caches combined by content hash
//! (`merge SRC... --into DST`).

use super::args::{CacheArgs, CacheCommand, CacheDirArgs, MergeArgs, PruneArgs};
use anyhow::{anyhow, Result};
use repro::pipeline::cache::Cache;
use repro::pipeline::merge::merge;
use repro::pipeline::prune::{inventory, prune, Inventory, Share};
use std::path::Path;

/// `repro cache ...`.
pub fn run(args: &CacheArgs) -> Result<bool> {
    match &args.command {
        None => run_list(&CacheDirArgs {
            cache: ".repro-cache".into(),
        }),
        Some(CacheCommand::List(a)) => run_list(a),
        Some(CacheCommand::Prune(a)) => run_prune(a),
        Some(CacheCommand::Merge(m)) => run_merge(m),
    }
}

/// `bytes` in MB (10^6), one decimal.
fn megabytes(bytes: u64) -> String {
    format!("{:.1} MB", bytes as f64 / 1e6)
}

/// The cache folder of `args`, which must exist.
fn existing(dir: &Path) -> Result<Cache> {
    if !dir.is_dir() {
        return Err(anyhow!("{}: no cache folder here", dir.display()));
    }
    Ok(Cache::new(dir))
}

/// One line per set of revisions: entries, size, whether the present build reaches them.
fn run_list(args: &CacheDirArgs) -> Result<bool> {
    let cache = existing(&args.cache)?;
    let inv = inventory(&cache)?;
    println!("{}:", args.cache.display());
    println!(
        "  {:<24} {:>8} {:>11}  reached",
        "revisions", "entries", "size"
    );
    for (revisions, share) in &inv.by_revisions {
        let (name, reached) = match revisions {
            Some(r) if Inventory::reachable(revisions) => (r.as_str(), "yes"),
            Some(r) => (r.as_str(), "no: an older revision"),
            None => ("(unrecorded)", "no: older than the revisions' record"),
        };
        println!(
            "  {name:<24} {:>8} {:>11}  {reached}",
            share.entries,
            megabytes(share.bytes)
        );
    }
    if !inv.corrupt.is_empty() {
        let bytes = inv.corrupt.iter().map(|c| c.1).sum();
        println!(
            "  {:<24} {:>8} {:>11}  no: fails verification",
            "(corrupt)",
            inv.corrupt.len(),
            megabytes(bytes)
        );
    }
    if !inv.abandoned.is_empty() {
        let bytes = inv.abandoned.iter().map(|a| a.1).sum();
        println!(
            "  {:<24} {:>8} {:>11}  no: a write that never finished",
            "(temporary files)",
            inv.abandoned.len(),
            megabytes(bytes)
        );
    }
    let gone = inv.unreachable();
    if gone.entries > 0 {
        println!(
            "{} files ({}) are never answered again: `repro cache prune{}` removes them",
            gone.entries,
            megabytes(gone.bytes),
            cache_flag(&args.cache)
        );
    }
    Ok(true)
}

/// ` --cache DIR` where `dir` is not the default.
fn cache_flag(dir: &Path) -> String {
    if dir == Path::new(".repro-cache") {
        String::new()
    } else {
        format!(" --cache {}", dir.display())
    }
}

/// Removes (or with `--dry-run` counts) what the present revisions cannot reach.
fn run_prune(args: &PruneArgs) -> Result<bool> {
    let cache = existing(&args.dir.cache)?;
    let Share { entries, bytes } = if args.dry_run {
        inventory(&cache)?.unreachable()
    } else {
        prune(&cache)?
    };
    let verb = if args.dry_run {
        "would remove"
    } else {
        "removed"
    };
    println!(
        "{}: {verb} {entries} files ({}) the present revisions cannot reach",
        args.dir.cache.display(),
        megabytes(bytes)
    );
    Ok(true)
}

/// Merges each source in turn, one line of counts per source and one per refused entry;
/// false when an entry was refused.
fn run_merge(args: &MergeArgs) -> Result<bool> {
    let dst = Cache::new(&args.into);
    let (mut copied, mut identical, mut refused) = (0, 0, 0);
    for src in &args.sources {
        if !src.is_dir() {
            return Err(anyhow!("{}: not a cache folder", src.display()));
        }
        let r = merge(&Cache::new(src), &dst)?;
        println!(
            "{}: {} copied, {} already there with the same result, {} refused",
            src.display(),
            r.copied,
            r.identical,
            r.refused.len()
        );
        for (key, why) in &r.refused {
            eprintln!("refused {key}: {why}");
        }
        copied += r.copied;
        identical += r.identical;
        refused += r.refused.len();
    }
    println!(
        "merged {} caches into {}: {copied} copied, {identical} already there, {refused} refused",
        args.sources.len(),
        args.into.display()
    );
    Ok(refused == 0)
}

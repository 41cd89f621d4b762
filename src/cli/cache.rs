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
    let row = |name: &str, entries: usize, bytes: u64, reached: &str| {
        println!(
            "  {name:<24} {entries:>8} {:>11}  {reached}",
            megabytes(bytes)
        )
    };
    for (revisions, share) in &inv.by_revisions {
        let (name, reached) = match revisions {
            Some(r) if Inventory::reachable(revisions) => (r.as_str(), "yes"),
            Some(r) => (r.as_str(), "no: an older revision"),
            None => ("(unrecorded)", "no: older than the revisions' record"),
        };
        row(name, share.entries, share.bytes, reached);
    }
    let others = [
        ("(corrupt)", &inv.corrupt, "no: fails verification"),
        (
            "(temporary files)",
            &inv.abandoned
                .iter()
                .map(|(p, b)| (p.display().to_string(), *b))
                .collect(),
            "no: a write that never finished",
        ),
    ];
    for (name, files, reached) in others {
        if !files.is_empty() {
            row(name, files.len(), files.iter().map(|f| f.1).sum(), reached);
        }
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

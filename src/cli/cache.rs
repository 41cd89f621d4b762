//! `repro cache merge SRC... --into DST`: caches combined by content hash.

use super::args::{CacheArgs, CacheCommand, MergeArgs};
use anyhow::{anyhow, Result};
use repro::pipeline::cache::Cache;
use repro::pipeline::merge::merge;

/// `repro cache ...`.
pub fn run(args: &CacheArgs) -> Result<bool> {
    match &args.command {
        CacheCommand::Merge(m) => run_merge(m),
    }
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

//! What a cache holds, per solver revision, and the pruning of what the present revisions can
//! no longer reach (`repro cache`, `repro cache prune`).
//!
//! A key holds the revisions of the numerics that made its result ([`super::keys`]), so an
//! entry made under an older revision is never answered again: a raised revision leaves the
//! old entries behind, unreachable. Each entry's stamp records the revisions its key holds;
//! entries written before stamps recorded them are counted as unrecorded, and are older than
//! the present point revision (the first to be recorded), so a point entry among them is
//! unreachable; a line contact's may still be reached, and costs a second to solve again.

use super::cache::Cache;
use super::error::PipelineError;
use super::keys::present_revisions;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// A temporary file older than this is a write that never finished (a live write renames its
/// file within milliseconds of creating it).
pub const ABANDONED_WRITE_AGE: Duration = Duration::from_secs(3600);

/// The entries of one set of revisions.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Share {
    /// Entries.
    pub entries: usize,
    /// Their files' size, bytes.
    pub bytes: u64,
}

impl Share {
    fn add(&mut self, bytes: u64) {
        self.entries += 1;
        self.bytes += bytes;
    }
}

/// What a cache folder holds.
#[derive(Debug, Clone, Default)]
pub struct Inventory {
    /// Verified entries by the revisions their stamps record (`None`: unrecorded).
    pub by_revisions: BTreeMap<Option<String>, Share>,
    /// Entries that fail verification (recomputed on use): their keys and sizes.
    pub corrupt: Vec<(String, u64)>,
    /// Temporary files of writes that never finished (older than [`ABANDONED_WRITE_AGE`]).
    pub abandoned: Vec<(PathBuf, u64)>,
    /// Every file the present revisions cannot reach, with its size: the entries of other
    /// revisions, unrecorded and corrupt ones, and the abandoned writes.
    unreachable_files: Vec<(PathBuf, u64)>,
}

impl Inventory {
    /// Whether the present build can answer with an entry of `revisions`.
    pub fn reachable(revisions: &Option<String>) -> bool {
        revisions
            .as_ref()
            .is_some_and(|r| present_revisions().contains(r))
    }

    /// The entries and files the present revisions cannot reach: unreachable revisions,
    /// corrupt entries and abandoned writes.
    pub fn unreachable(&self) -> Share {
        let mut out = Share::default();
        for (_, bytes) in &self.unreachable_files {
            out.add(*bytes);
        }
        out
    }
}

fn size(path: &Path) -> u64 {
    std::fs::metadata(path).map_or(0, |m| m.len())
}

/// Whether `name` is a temporary file of [`Cache::put_raw`].
fn is_temporary(name: &str) -> bool {
    name.len() > 64
        && name[..64].bytes().all(|b| b.is_ascii_hexdigit())
        && name[64..].starts_with(".tmp")
}

/// The temporary files under the cache folder older than `age`.
fn abandoned_writes(cache: &Cache, age: Duration) -> Vec<(PathBuf, u64)> {
    let now = SystemTime::now();
    let mut out = Vec::new();
    let Ok(top) = std::fs::read_dir(cache.dir()) else {
        return out;
    };
    for sub in top.flatten() {
        let Ok(files) = std::fs::read_dir(sub.path()) else {
            continue;
        };
        for f in files.flatten() {
            let old = f
                .metadata()
                .and_then(|m| m.modified())
                .ok()
                .and_then(|t| now.duration_since(t).ok())
                .is_some_and(|d| d >= age);
            if old && is_temporary(&f.file_name().to_string_lossy()) {
                out.push((f.path(), size(&f.path())));
            }
        }
    }
    out.sort();
    out
}

/// What `cache` holds (an error names a folder that cannot be read).
pub fn inventory(cache: &Cache) -> Result<Inventory, PipelineError> {
    inventory_aged(cache, ABANDONED_WRITE_AGE)
}

fn inventory_aged(cache: &Cache, age: Duration) -> Result<Inventory, PipelineError> {
    let mut inv = Inventory {
        abandoned: abandoned_writes(cache, age),
        ..Inventory::default()
    };
    inv.unreachable_files.clone_from(&inv.abandoned);
    for key in cache.keys()? {
        let path = cache.path(&key);
        let bytes = size(&path);
        let reachable = match cache.get_raw(&key) {
            Ok(Some(entry)) => {
                let revisions = entry.stamp.and_then(|s| s.revisions);
                let reachable = Inventory::reachable(&revisions);
                inv.by_revisions.entry(revisions).or_default().add(bytes);
                reachable
            }
            Ok(None) => true,
            Err(_) => {
                inv.corrupt.push((key, bytes));
                false
            }
        };
        if !reachable {
            inv.unreachable_files.push((path, bytes));
        }
    }
    Ok(inv)
}

/// Removes from `cache` what the present revisions cannot reach ([`Inventory::unreachable`])
/// and returns what was removed; an error names the file that could not be removed.
pub fn prune(cache: &Cache) -> Result<Share, PipelineError> {
    prune_aged(cache, ABANDONED_WRITE_AGE)
}

fn prune_aged(cache: &Cache, age: Duration) -> Result<Share, PipelineError> {
    let mut removed = Share::default();
    let mut remove = |path: &Path, bytes: u64| match std::fs::remove_file(path) {
        Ok(()) => {
            removed.add(bytes);
            Ok(())
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
        Err(e) => Err(PipelineError::io(
            format!("cannot remove {}", path.display()),
            path,
            e,
        )),
    };
    for (path, bytes) in inventory_aged(cache, age)?.unreachable_files {
        remove(&path, bytes)?;
    }
    Ok(removed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::cache::{key_of, Stamp};
    use crate::pipeline::keys::{line_revisions, point_revisions};

    fn stamp(revisions: Option<String>) -> Stamp {
        Stamp {
            repro_version: "0.1.0".into(),
            git_revision: "abc".into(),
            host: "node".into(),
            seconds: 1.0,
            revisions,
        }
    }

    /// Entries of the present revisions stay; an older revision's, an unrecorded one, a
    /// corrupt one and an abandoned write go; a second prune finds nothing.
    #[test]
    fn prune_keeps_what_the_present_revisions_reach() {
        let dir = std::env::temp_dir().join(format!("repro-prune-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let cache = Cache::new(&dir);
        let keys: Vec<String> = (0..5).map(|i| key_of(&i)).collect();
        let put = |k: &str, r: Option<String>| cache.put(k, &vec![1.0], &stamp(r)).unwrap();
        put(&keys[0], Some(point_revisions()));
        put(&keys[1], Some(line_revisions()));
        put(&keys[2], Some("point-1 thermal-1".into()));
        put(&keys[3], None);
        cache.put_raw(&keys[4], "{ truncated").unwrap();
        let tmp = cache.path(&keys[0]).with_extension("tmp42-ThreadId1");
        std::fs::write(&tmp, "half").unwrap();
        // Age 0: every temporary file counts as abandoned.
        let inv = inventory_aged(&cache, Duration::ZERO).unwrap();
        assert_eq!(inv.by_revisions.len(), 4);
        assert_eq!(inv.by_revisions[&Some(point_revisions())].entries, 1);
        assert_eq!(inv.corrupt.len(), 1);
        assert_eq!(inv.abandoned.len(), 1);
        assert_eq!(inv.unreachable().entries, 4);
        // A live write (younger than the age) is left alone.
        assert!(inventory(&cache).unwrap().abandoned.is_empty());
        let removed = prune_aged(&cache, Duration::ZERO).unwrap();
        assert_eq!(removed, inv.unreachable());
        assert_eq!(cache.keys().unwrap(), {
            let mut k = vec![keys[0].clone(), keys[1].clone()];
            k.sort();
            k
        });
        assert!(!tmp.exists());
        assert_eq!(prune_aged(&cache, Duration::ZERO).unwrap().entries, 0);
        let _ = std::fs::remove_dir_all(&dir);
    }
}

//! The result cache: one JSON file per solved case, keyed by the SHA-256 of the canonical case,
//! the level, the domain and the solver revision. An entry holds the result (the payload, the
//! same bytes wherever the case was solved) and its [`Stamp`] (which build solved it, where,
//! how long it took). Entries are written atomically (temporary file, then rename) and carry
//! the SHA-256 of payload and stamp, checked on read: a corrupt entry is reported and
//! recomputed, never trusted.

use crate::pipeline::error::PipelineError;
use crate::solver::point::Start;
use serde::{de::DeserializeOwned, Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Lower-case hex SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The key of anything serialisable: SHA-256 of its canonical JSON (struct fields in
/// declaration order, floats in shortest round-trip form).
pub fn key_of<T: Serialize>(value: &T) -> String {
    // Serialising plain data structs cannot fail.
    sha256_hex(
        serde_json::to_string(value)
            .expect("serialisable key")
            .as_bytes(),
    )
}

/// How an entry was made: which build of `repro` solved the case, where, and how long it
/// took. Kept beside the result, not in it: two runs of the same case on the same kind of
/// machine give the same result bytes but never the same wall time.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Stamp {
    /// `repro`'s crate version.
    pub repro_version: String,
    /// Git revision of the build (`-dirty` when the work tree had changes; `unknown` outside
    /// a git checkout).
    pub git_revision: String,
    /// Host name of the machine that solved it.
    pub host: String,
    /// Wall time of the solve, s.
    pub seconds: f64,
    /// The solver revisions its key holds (`point-25 thermal-3`, `line-4`): what `repro
    /// cache` sorts entries by (`None` in entries written before they were recorded).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub revisions: Option<String>,
}

impl Stamp {
    /// The stamp of a solve of `seconds` under `revisions` by this build on this machine.
    pub fn now(seconds: f64, revisions: String) -> Self {
        Stamp {
            repro_version: env!("CARGO_PKG_VERSION").to_string(),
            git_revision: GIT_REVISION.to_string(),
            host: host_name(),
            seconds,
            revisions: Some(revisions),
        }
    }
}

/// Git revision of this build (set by `build.rs`).
pub const GIT_REVISION: &str = env!("REPRO_GIT_REVISION");

/// This machine's host name (Linux), else `HOSTNAME`, else `unknown`.
fn host_name() -> String {
    std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .map(|h| h.trim().to_string())
        .filter(|h| !h.is_empty())
        .unwrap_or_else(|| "unknown".into())
}

/// An entry as stored. `sha256` covers the payload followed by the stamp's text (the payload
/// alone in entries written before stamps, which still read).
#[derive(Serialize, Deserialize)]
struct EntryFile {
    key: String,
    sha256: String,
    payload: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    stamp: Option<String>,
}

impl EntryFile {
    fn checksum(payload: &str, stamp: Option<&str>) -> String {
        match stamp {
            Some(s) => sha256_hex(format!("{payload}\n{s}").as_bytes()),
            None => sha256_hex(payload.as_bytes()),
        }
    }
}

/// A verified entry as stored: what `repro cache merge` compares and copies.
#[derive(Debug, Clone)]
pub struct RawEntry {
    /// The key.
    pub key: String,
    /// The result's canonical JSON: the content that must agree wherever it was computed.
    pub payload: String,
    /// How it was made (`None` in entries written before stamps).
    pub stamp: Option<Stamp>,
    /// The file's bytes, copied as they are.
    pub text: String,
}

/// What a read found.
#[derive(Debug)]
pub enum Lookup<T> {
    /// A verified entry and how it was made (`None` for entries written before stamps).
    Hit(T, Option<Stamp>),
    /// No entry.
    Miss,
    /// An entry that failed verification (the reason: the file and field), to be recomputed.
    Corrupt(PipelineError),
}

/// A cache folder, and in memory the solutions its process solved, for the cases that start
/// from them (continuation: [`crate::pipeline::base`]).
#[derive(Debug, Clone)]
pub struct Cache {
    dir: PathBuf,
    starts: Arc<Mutex<Starts>>,
}

/// The solutions kept in memory, by cache key, within [`STARTS_MEMORY`].
#[derive(Debug, Default)]
struct Starts {
    by_key: HashMap<String, Arc<Start>>,
    bytes: usize,
}

/// Memory the kept solutions may take: 2 GiB, the pressure fields of about 4 000 level-7
/// solves (a run of every target holds about 1 500).
const STARTS_MEMORY: usize = 2 << 30;

impl Cache {
    /// A cache in `dir` (created on first write).
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Cache {
            dir: dir.into(),
            starts: Arc::default(),
        }
    }

    /// The solution of `key` solved by this process, if kept. A solution solves to the same
    /// bits whoever solves it, so a kept one and a fresh one are the same start.
    pub fn start(&self, key: &str) -> Option<Arc<Start>> {
        let starts = self.starts.lock().unwrap_or_else(|e| e.into_inner());
        starts.by_key.get(key).cloned()
    }

    /// Keeps the solution of `key` for the cases that start from it, while the memory allows.
    /// A start that hands a Newton-Krylov factor on ([`Start::factor`], level 8) is not kept:
    /// the factor is hundreds of megabytes (the cold paper peaked at 13.6 GB with them kept), and kept
    /// without it the start would solve its members to other bits than their tree's start
    /// does; such a member's base is solved again with it.
    pub fn keep_start(&self, key: &str, start: Arc<Start>) {
        if start.factor.is_some() {
            return;
        }
        let mut starts = self.starts.lock().unwrap_or_else(|e| e.into_inner());
        let bytes = start.p.len() * std::mem::size_of::<f64>();
        if starts.bytes + bytes <= STARTS_MEMORY && !starts.by_key.contains_key(key) {
            starts.bytes += bytes;
            starts.by_key.insert(key.to_string(), start);
        }
    }

    /// The folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The file of `key`.
    pub fn path(&self, key: &str) -> PathBuf {
        self.dir.join(&key[..2]).join(format!("{key}.json"))
    }

    /// Reads and verifies the entry of `key` as stored (`Ok(None)` when there is none; the
    /// error names the file and what is wrong).
    pub fn get_raw(&self, key: &str) -> Result<Option<RawEntry>, PipelineError> {
        let path = self.path(key);
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(PipelineError::io(path.display().to_string(), &path, e)),
        };
        let entry: EntryFile = serde_json::from_str(&text).map_err(|e| {
            PipelineError::parse(
                path.display().to_string(),
                None,
                format!("not a cache entry: {e}"),
            )
        })?;
        if entry.key != key {
            return Err(PipelineError::parse(
                path.display().to_string(),
                Some("key"),
                format!("{} does not match the file name", entry.key),
            ));
        }
        if EntryFile::checksum(&entry.payload, entry.stamp.as_deref()) != entry.sha256 {
            return Err(PipelineError::parse(
                path.display().to_string(),
                Some("sha256"),
                "hash mismatch",
            ));
        }
        let stamp =
            match &entry.stamp {
                Some(s) => Some(serde_json::from_str(s).map_err(|e| {
                    PipelineError::parse(path.display().to_string(), Some("stamp"), e)
                })?),
                None => None,
            };
        Ok(Some(RawEntry {
            key: entry.key,
            payload: entry.payload,
            stamp,
            text,
        }))
    }

    /// Reads and verifies the entry of `key`.
    pub fn get<T: DeserializeOwned>(&self, key: &str) -> Lookup<T> {
        match self.get_raw(key) {
            Ok(None) => Lookup::Miss,
            Err(why) => Lookup::Corrupt(why),
            Ok(Some(raw)) => match serde_json::from_str(&raw.payload) {
                Ok(v) => Lookup::Hit(v, raw.stamp),
                Err(e) => Lookup::Corrupt(PipelineError::parse(
                    self.path(key).display().to_string(),
                    Some("payload"),
                    e,
                )),
            },
        }
    }

    /// Writes the entry of `key` atomically, with how it was made.
    pub fn put<T: Serialize>(&self, key: &str, value: &T, stamp: &Stamp) -> std::io::Result<()> {
        let payload = serde_json::to_string(value).map_err(std::io::Error::other)?;
        let stamp = serde_json::to_string(stamp).map_err(std::io::Error::other)?;
        let entry = EntryFile {
            key: key.to_string(),
            sha256: EntryFile::checksum(&payload, Some(&stamp)),
            payload,
            stamp: Some(stamp),
        };
        let text = serde_json::to_string(&entry).map_err(std::io::Error::other)?;
        self.put_raw(key, &text)
    }

    /// Writes the bytes of an entry for `key` atomically (temporary file, then rename).
    pub fn put_raw(&self, key: &str, text: &str) -> std::io::Result<()> {
        let path = self.path(key);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        // A temporary name per process and thread: writers of the same key, in this process
        // or in another on a shared file system, never share one.
        let tmp = path.with_extension(
            format!(
                "tmp{}-{:?}",
                std::process::id(),
                std::thread::current().id()
            )
            .replace(['(', ')'], ""),
        );
        std::fs::write(&tmp, text)?;
        std::fs::rename(&tmp, &path)
    }

    /// Every key with an entry file, sorted (temporary files and anything else left out).
    pub fn keys(&self) -> Result<Vec<String>, PipelineError> {
        let mut keys = Vec::new();
        let top = match std::fs::read_dir(&self.dir) {
            Ok(t) => t,
            Err(e) => {
                return Err(PipelineError::io(
                    self.dir.display().to_string(),
                    &self.dir,
                    e,
                ))
            }
        };
        for sub in top.flatten() {
            let Ok(files) = std::fs::read_dir(sub.path()) else {
                continue;
            };
            for f in files.flatten() {
                let name = f.file_name().to_string_lossy().into_owned();
                if let Some(key) = name.strip_suffix(".json") {
                    if key.len() == 64 && key.bytes().all(|b| b.is_ascii_hexdigit()) {
                        keys.push(key.to_string());
                    }
                }
            }
        }
        keys.sort();
        Ok(keys)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("repro-cache-test-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    #[test]
    fn round_trip_and_corruption_is_detected() {
        let cache = Cache::new(temp_dir("rt"));
        let key = key_of(&("case", 7u32));
        assert!(matches!(cache.get::<Vec<f64>>(&key), Lookup::Miss));
        let stamp = Stamp::now(0.25, "point-0".into());
        cache.put(&key, &vec![1.5, -2.0], &stamp).unwrap();
        match cache.get::<Vec<f64>>(&key) {
            Lookup::Hit(v, s) => assert_eq!((v, s), (vec![1.5, -2.0], Some(stamp.clone()))),
            other => panic!("{other:?}"),
        }
        assert_eq!(cache.keys().unwrap(), vec![key.clone()]);
        // Flip one digit of the payload: the hash no longer matches.
        let path = cache.path(&key);
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("1.5", "1.6");
        std::fs::write(&path, text).unwrap();
        assert!(matches!(cache.get::<Vec<f64>>(&key), Lookup::Corrupt(_)));
        std::fs::write(&path, "{ truncated").unwrap();
        assert!(matches!(cache.get::<Vec<f64>>(&key), Lookup::Corrupt(_)));
        // The stamp is covered by the hash too: a changed wall time is caught.
        cache.put(&key, &vec![1.5], &stamp).unwrap();
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("0.25", "0.5");
        std::fs::write(&path, text).unwrap();
        match cache.get::<Vec<f64>>(&key) {
            Lookup::Corrupt(why) => assert!(why.to_string().contains("sha256"), "{why}"),
            other => panic!("{other:?}"),
        }
        let _ = std::fs::remove_dir_all(cache.dir());
    }

    /// Entries written before stamps (the SHA-256 of the payload alone) still read.
    #[test]
    fn entries_without_a_stamp_still_read() {
        let cache = Cache::new(temp_dir("legacy"));
        let key = key_of(&"legacy");
        let payload = "[2.5]";
        let text = format!(
            "{{\"key\":\"{key}\",\"sha256\":\"{}\",\"payload\":\"{payload}\"}}",
            sha256_hex(payload.as_bytes())
        );
        cache.put_raw(&key, &text).unwrap();
        match cache.get::<Vec<f64>>(&key) {
            Lookup::Hit(v, None) => assert_eq!(v, vec![2.5]),
            other => panic!("{other:?}"),
        }
        let _ = std::fs::remove_dir_all(cache.dir());
    }

    #[test]
    fn keys_change_with_any_field() {
        assert_ne!(key_of(&("a", 1.0)), key_of(&("a", 1.0000001)));
        assert_eq!(key_of(&("a", 1.0)), key_of(&("a", 1.0)));
        assert_eq!(key_of(&"x").len(), 64);
    }
}

//! The result cache: one JSON file per solved case, keyed by the SHA-256 of the canonical case,
//! the level, the domain and the solver revision. Entries are written atomically (temporary
//! file, then rename) and carry the SHA-256 of their payload, checked on read: a corrupt entry
//! is reported and recomputed, never trusted.

use serde::{de::DeserializeOwned, Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

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

#[derive(Serialize, Deserialize)]
struct Entry {
    key: String,
    sha256: String,
    payload: String,
}

/// What a read found.
#[derive(Debug)]
pub enum Lookup<T> {
    /// A verified entry.
    Hit(T),
    /// No entry.
    Miss,
    /// An entry that failed verification (the reason), to be recomputed.
    Corrupt(String),
}

/// A cache folder.
#[derive(Debug, Clone)]
pub struct Cache {
    dir: PathBuf,
}

impl Cache {
    /// A cache in `dir` (created on first write).
    pub fn new(dir: impl Into<PathBuf>) -> Self {
        Cache { dir: dir.into() }
    }

    /// The folder.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    fn path(&self, key: &str) -> PathBuf {
        self.dir.join(&key[..2]).join(format!("{key}.json"))
    }

    /// Reads and verifies the entry of `key`.
    pub fn get<T: DeserializeOwned>(&self, key: &str) -> Lookup<T> {
        let path = self.path(key);
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Lookup::Miss,
            Err(e) => return Lookup::Corrupt(format!("{}: {e}", path.display())),
        };
        let entry: Entry = match serde_json::from_str(&text) {
            Ok(e) => e,
            Err(e) => {
                return Lookup::Corrupt(format!("{}: not a cache entry: {e}", path.display()))
            }
        };
        if entry.key != key || sha256_hex(entry.payload.as_bytes()) != entry.sha256 {
            return Lookup::Corrupt(format!("{}: hash mismatch", path.display()));
        }
        match serde_json::from_str(&entry.payload) {
            Ok(v) => Lookup::Hit(v),
            Err(e) => Lookup::Corrupt(format!("{}: payload: {e}", path.display())),
        }
    }

    /// Writes the entry of `key` atomically.
    pub fn put<T: Serialize>(&self, key: &str, value: &T) -> std::io::Result<()> {
        let payload = serde_json::to_string(value).map_err(std::io::Error::other)?;
        let entry = Entry {
            key: key.to_string(),
            sha256: sha256_hex(payload.as_bytes()),
            payload,
        };
        let text = serde_json::to_string(&entry).map_err(std::io::Error::other)?;
        let path = self.path(key);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        // A per-thread temporary name: parallel writers of the same key never share one.
        let tmp = path.with_extension(
            format!("tmp{:?}", std::thread::current().id()).replace(['(', ')'], ""),
        );
        std::fs::write(&tmp, text)?;
        std::fs::rename(&tmp, &path)
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
        cache.put(&key, &vec![1.5, -2.0]).unwrap();
        match cache.get::<Vec<f64>>(&key) {
            Lookup::Hit(v) => assert_eq!(v, vec![1.5, -2.0]),
            other => panic!("{other:?}"),
        }
        // Flip one digit of the payload: the hash no longer matches.
        let path = cache.path(&key);
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("1.5", "1.6");
        std::fs::write(&path, text).unwrap();
        assert!(matches!(cache.get::<Vec<f64>>(&key), Lookup::Corrupt(_)));
        std::fs::write(&path, "{ truncated").unwrap();
        assert!(matches!(cache.get::<Vec<f64>>(&key), Lookup::Corrupt(_)));
        let _ = std::fs::remove_dir_all(cache.dir());
    }

    #[test]
    fn keys_change_with_any_field() {
        assert_ne!(key_of(&("a", 1.0)), key_of(&("a", 1.0000001)));
        assert_eq!(key_of(&("a", 1.0)), key_of(&("a", 1.0)));
        assert_eq!(key_of(&"x").len(), 64);
    }
}

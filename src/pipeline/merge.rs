//! `repro cache merge`: caches combined by content hash. An entry is the same result bytes
//! wherever its case was solved; an entry of a source is copied when the destination has none,
//! counted when the destination has the same result, and refused (named by its key) when the
//! destination's result differs. Stamps (which build solved it, where, how long) may differ:
//! the destination's is kept.

use super::cache::{Cache, RawEntry};
use crate::pipeline::error::PipelineError;

/// What a merge did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct MergeReport {
    /// Entries copied into the destination.
    pub copied: usize,
    /// Entries the destination already had, with the same result.
    pub identical: usize,
    /// Entries refused: the key and why (a different result, or a source entry that fails
    /// verification).
    pub refused: Vec<(String, String)>,
}

/// Keys of the result fields that entries written before stamps carried in their payload and
/// that are not part of the result (the solve's wall time): left out when two payloads are
/// compared, so that an old entry and a new one of the same result agree.
const NOT_RESULT: &[&str] = &["seconds"];

/// The payload without the [`NOT_RESULT`] fields (wall times), keys sorted: the result a
/// payload holds, the same wherever and however fast it was computed.
pub fn result_of(payload: &str) -> Option<serde_json::Value> {
    fn strip(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Object(m) => {
                m.retain(|k, _| !NOT_RESULT.contains(&k.as_str()));
                m.values_mut().for_each(strip);
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    let mut v: serde_json::Value = serde_json::from_str(payload).ok()?;
    strip(&mut v);
    Some(v)
}

/// Whether two entries hold the same result.
fn same_result(a: &RawEntry, b: &RawEntry) -> bool {
    a.payload == b.payload
        || matches!((result_of(&a.payload), result_of(&b.payload)), (Some(x), Some(y)) if x == y)
}

/// Merges every verified entry of `src` into `dst`. A destination file that cannot be
/// written ends the merge with an error naming it.
pub fn merge(src: &Cache, dst: &Cache) -> Result<MergeReport, PipelineError> {
    let mut report = MergeReport::default();
    for key in src.keys()? {
        let entry = match src.get_raw(&key) {
            Ok(Some(e)) => e,
            Ok(None) => continue,
            Err(why) => {
                report
                    .refused
                    .push((key, format!("source entry fails verification: {why}")));
                continue;
            }
        };
        match dst.get_raw(&key) {
            Ok(Some(there)) if same_result(&there, &entry) => report.identical += 1,
            Ok(Some(there)) => report.refused.push((
                key,
                format!(
                    "{} holds a different result than {} (solved by {} and {})",
                    dst.path(&there.key).display(),
                    src.path(&entry.key).display(),
                    who(&there),
                    who(&entry)
                ),
            )),
            // A destination entry that fails verification is replaced by a verified one.
            Ok(None) | Err(_) => {
                dst.put_raw(&key, &entry.text).map_err(|e| {
                    let path = dst.path(&key);
                    PipelineError::io(format!("cannot write {}", path.display()), path, e)
                })?;
                report.copied += 1;
            }
        }
    }
    Ok(report)
}

/// Which build solved an entry, in words.
fn who(e: &RawEntry) -> String {
    match &e.stamp {
        Some(s) => format!(
            "repro {} at {} on {}",
            s.repro_version, s.git_revision, s.host
        ),
        None => "a build before stamps".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::cache::{key_of, sha256_hex, Stamp};

    fn temp_cache(name: &str) -> Cache {
        let d = std::env::temp_dir().join(format!("repro-merge-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        Cache::new(d)
    }

    fn stamp(host: &str, seconds: f64) -> Stamp {
        Stamp {
            repro_version: "0.1.0".into(),
            git_revision: "abc".into(),
            host: host.into(),
            seconds,
            revisions: None,
        }
    }

    #[test]
    fn copies_counts_and_refuses_naming_the_key() {
        let (a, b, dst) = (temp_cache("a"), temp_cache("b"), temp_cache("dst"));
        let (k1, k2, k3) = (key_of(&1), key_of(&2), key_of(&3));
        a.put(&k1, &vec![1.0], &stamp("n1", 1.0)).unwrap();
        a.put(&k2, &vec![2.0], &stamp("n1", 2.0)).unwrap();
        // The same result solved elsewhere, in another time: the same content.
        b.put(&k2, &vec![2.0], &stamp("n2", 9.0)).unwrap();
        // A different result under the same key: refused.
        b.put(&k3, &vec![3.0], &stamp("n2", 1.0)).unwrap();
        dst.put(&k3, &vec![3.5], &stamp("n0", 1.0)).unwrap();
        let ra = merge(&a, &dst).unwrap();
        assert_eq!((ra.copied, ra.identical, ra.refused.len()), (2, 0, 0));
        let rb = merge(&b, &dst).unwrap();
        assert_eq!((rb.copied, rb.identical), (0, 1));
        assert_eq!(rb.refused.len(), 1);
        assert_eq!(rb.refused[0].0, k3);
        assert!(rb.refused[0].1.contains("different result"), "{rb:?}");
        // The refused entry is left as it was; the copied one is the source's bytes.
        assert!(matches!(
            dst.get::<Vec<f64>>(&k3),
            crate::pipeline::cache::Lookup::Hit(v, _) if v == vec![3.5]
        ));
        assert_eq!(
            std::fs::read(dst.path(&k1)).unwrap(),
            std::fs::read(a.path(&k1)).unwrap()
        );
        // A corrupt source entry is refused, not copied.
        let text = std::fs::read_to_string(a.path(&k1))
            .unwrap()
            .replace("[1.0]", "[1.5]");
        std::fs::write(a.path(&k1), text).unwrap();
        let dst2 = temp_cache("dst2");
        let r = merge(&a, &dst2).unwrap();
        assert_eq!((r.copied, r.refused.len()), (1, 1));
        assert!(r.refused[0].1.contains("verification"), "{r:?}");
        for c in [a, b, dst, dst2] {
            let _ = std::fs::remove_dir_all(c.dir());
        }
    }

    /// An entry written before stamps kept the solve's time in its payload: it agrees with a
    /// new entry of the same result.
    #[test]
    fn an_old_entry_and_a_new_one_of_the_same_result_agree() {
        let (old, new) = (temp_cache("old"), temp_cache("new"));
        let key = key_of(&"case");
        let payload = r#"{"Solved":{"h":0.5,"seconds":1.25}}"#;
        let text = serde_json::json!({"key": key, "sha256": sha256_hex(payload.as_bytes()), "payload": payload})
            .to_string();
        old.put_raw(&key, &text).unwrap();
        new.put(
            &key,
            &serde_json::json!({"Solved": {"h": 0.5}}),
            &stamp("n", 3.0),
        )
        .unwrap();
        let r = merge(&new, &old).unwrap();
        assert_eq!((r.identical, r.refused.len()), (1, 0), "{r:?}");
        // But a different film is a different result.
        let other = temp_cache("other");
        other
            .put(
                &key,
                &serde_json::json!({"Solved": {"h": 0.6}}),
                &stamp("n", 3.0),
            )
            .unwrap();
        assert_eq!(merge(&other, &old).unwrap().refused.len(), 1);
        for c in [old, new, other] {
            let _ = std::fs::remove_dir_all(c.dir());
        }
    }
}

//! Sweeps beyond one machine, with shards run as separate local processes: three shards of
//! Fig. 7 in separate caches, merged and assembled offline, give the bytes of the unsharded
//! run; an offline build of a partial cache names every missing case; merges refuse a
//! different result; `repro slurm` writes the scripts of the same run.

use crate::support::{repro, scratch};
use repro::paper::cases::shipped_sweep;
use repro::pipeline::cache::{key_of, Cache, Stamp};
use repro::pipeline::job::{point_jobs, Job};
use repro::pipeline::keys::{line_revisions, point_revisions};
use repro::pipeline::outcome::{CaseOutcome, Failure, FailureKind};
use repro::pipeline::shard::Shard;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Level of the round trip: the point contacts' coarsest working level, so that the four
/// runs of Fig. 7 take seconds; byte identity does not depend on the level.
const LEVEL: &str = "4";

fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

/// Runs `repro fig7` at [`LEVEL`] with `flags`, in `env` (every Slurm variable removed first,
/// so that a test run inside a Slurm job is not sharded by it).
fn fig7(flags: &[&str], env: &[(&str, &str)]) -> (i32, String, String) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_repro"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["fig7", "--level", LEVEL, "-q"])
        .args(flags);
    for v in [
        "SLURM_ARRAY_TASK_ID",
        "SLURM_ARRAY_TASK_COUNT",
        "SLURM_ARRAY_TASK_MIN",
        "SLURM_ARRAY_TASK_STEP",
    ] {
        cmd.env_remove(v);
    }
    cmd.envs(env.iter().copied());
    let out = cmd.output().expect("run repro");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// How a shard is handed its index: flags and environment variables.
type Handed<'a> = (&'a [&'a str], &'a [(&'a str, &'a str)]);

fn keys(cache: &Path) -> Vec<String> {
    Cache::new(cache).keys().expect("cache folder")
}

#[test]
fn three_shards_merged_and_assembled_offline_equal_the_one_machine_run() {
    let dir = scratch("shards", "fig7");
    let (one_cache, one_out) = (dir.join("one-cache"), dir.join("one-out"));
    let (code, _, err) = fig7(&["--cache", s(&one_cache), "--out", s(&one_out)], &[]);
    assert_eq!(code, 0, "{err}");

    // Three shards, each its own process and cache, handed its index three ways: a Slurm
    // array from 0, a Slurm array from 1, the flag.
    let shards: Vec<PathBuf> = (1..=3).map(|i| dir.join(format!("shard-{i}"))).collect();
    let no_figures = dir.join("shard-out");
    let handed: [Handed; 3] = [
        (
            &[],
            &[
                ("SLURM_ARRAY_TASK_ID", "0"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
                ("SLURM_ARRAY_TASK_MIN", "0"),
            ],
        ),
        (
            &[],
            &[
                ("SLURM_ARRAY_TASK_ID", "2"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
                ("SLURM_ARRAY_TASK_MIN", "1"),
            ],
        ),
        (&["--shard", "3/3"], &[]),
    ];
    for (i, (flags, env)) in handed.iter().enumerate() {
        let mut all = vec!["--cache", s(&shards[i]), "--out", s(&no_figures)];
        all.extend_from_slice(flags);
        let (code, out, err) = fig7(&all, env);
        assert_eq!(code, 0, "shard {}: {err}", i + 1);
        assert!(
            out.starts_with(&format!("shard {}/3 of fig7: 5 of 15 solves", i + 1)),
            "15 distinct solves (10 point, 5 line contacts) split 5/5/5: {out}"
        );
        if !env.is_empty() {
            assert!(err.contains("Slurm array task"), "says so: {err}");
        }
    }
    assert!(!no_figures.exists(), "a shard writes cache entries only");
    let mut union: Vec<String> = shards.iter().flat_map(|c| keys(c)).collect();
    union.sort();
    assert_eq!(
        union,
        keys(&one_cache),
        "the shards partition the run's cases"
    );

    let merged = dir.join("merged");
    let mut merge = vec!["cache", "merge"];
    merge.extend(shards.iter().map(|p| s(p)));
    merge.extend(["--into", s(&merged)]);
    let (code, out, err) = repro(&merge);
    assert_eq!(code, 0, "{err}");
    // The 15 solves and the bases their 10 point contacts start from (Fig. 7's ellipses are
    // not Table 2's family bases).
    assert!(
        out.contains("25 copied, 0 already there, 0 refused"),
        "{out}"
    );

    // `repro cache` counts the merged entries by the revisions their keys hold, every one
    // reached by the present build: 20 point contacts (10 and their bases), 5 line contacts.
    let (code, out, err) = repro(&["cache", "list", "--cache", s(&merged)]);
    assert_eq!(code, 0, "{err}");
    let row = |revisions: &str, n: usize| {
        out.lines().any(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            l.trim_start().starts_with(revisions)
                && w.contains(&n.to_string().as_str())
                && l.ends_with("yes")
        })
    };
    assert!(
        row(&point_revisions(), 20) && row(&line_revisions(), 5),
        "{out}"
    );

    let offline_out = dir.join("offline-out");
    let (code, out, err) = fig7(
        &["--offline", "--cache", s(&merged), "--out", s(&offline_out)],
        &[],
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("15 cases, ") && out.contains("15 cached"),
        "{out}"
    );
    for f in ["fig7.csv", "fig7-line.csv", "fig7.svg"] {
        let (a, b) = (one_out.join(f), offline_out.join(f));
        assert!(
            std::fs::read(&a).expect("one-machine file")
                == std::fs::read(&b).expect("offline file"),
            "{f}: the offline assembly differs from the one-machine run"
        );
    }
    // The sidecars name the same keys; only the stamps (who solved, how long) differ.
    let sidecar = |d: &Path| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(d.join("fig7.provenance.json")).unwrap())
            .unwrap()
    };
    let key_list = |v: &serde_json::Value| -> Vec<String> {
        v["cases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["key"].as_str().unwrap().to_string())
            .collect()
    };
    let (a, b) = (sidecar(&one_out), sidecar(&offline_out));
    assert_eq!(key_list(&a).len(), 15);
    assert_eq!(key_list(&a), key_list(&b));

    // Merging a shard again adds nothing.
    let (code, out, _) = repro(&["cache", "merge", s(&shards[0]), "--into", s(&merged)]);
    assert_eq!(code, 0);
    // (Its five solves and the bases of its point contacts: how many of those it has depends
    // on which families fall to it.)
    let entries = keys(&shards[0]).len();
    assert!(
        out.contains(&format!("0 copied, {entries} already there")),
        "{out}"
    );

    // A different result under a key the merged cache has: refused, named, exit 1.
    let key = keys(&shards[0])[0].clone();
    let other = CaseOutcome::Failed(Failure {
        kind: FailureKind::NotConverged,
        error: "not converged (edited)".into(),
        residual_history: vec![1.0],
    });
    Cache::new(&shards[0])
        .put(&key, &other, &Stamp::now(0.0, point_revisions()))
        .expect("write");
    let (code, _, err) = repro(&["cache", "merge", s(&shards[0]), "--into", s(&merged)]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains(&format!("refused {key}")), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn offline_on_a_partial_cache_names_every_missing_case() {
    let dir = scratch("shards", "partial");
    let (shard, out) = (dir.join("shard-1"), dir.join("out"));
    let (code, _, err) = fig7(&["--shard", "1/3", "--cache", s(&shard)], &[]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = fig7(&["--offline", "--cache", s(&shard), "--out", s(&out)], &[]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("10 case(s) missing from the cache"), "{err}");
    let have = keys(&shard);
    let listed: Vec<&str> = err.lines().filter(|l| l.contains("[key ")).collect();
    assert_eq!(listed.len(), 10, "{err}");
    assert!(
        listed
            .iter()
            .all(|l| have.iter().all(|k| !l.contains(k.as_str()))),
        "only cases the cache lacks are listed: {err}"
    );
    assert!(
        err.contains("fig7: case ") && err.contains("fig7: line contact "),
        "by target and case, point and line contacts: {err}"
    );
    assert!(
        !out.join("fig7.csv").exists(),
        "no partial figure is written"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn slurm_writes_an_array_a_dependent_assembly_and_says_how_to_submit() {
    let dir = scratch("shards", "slurm");
    let (code, out, err) = repro(&[
        "slurm",
        "fig7",
        "--tasks",
        "40",
        "--level",
        LEVEL,
        "--dir",
        s(&dir),
        "--partition",
        "short",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("--tasks 40 lowered to 15"), "{out}");
    assert!(
        out.contains("sh ") && out.contains("--dependency=afterok"),
        "{out}"
    );
    let array = std::fs::read_to_string(dir.join("repro-fig7.array.sbatch")).unwrap();
    assert!(array.contains("#SBATCH --array=1-15\n"), "{array}");
    assert!(array.contains("#SBATCH --partition=short\n"), "{array}");
    let assemble = std::fs::read_to_string(dir.join("repro-fig7.assemble.sbatch")).unwrap();
    assert!(assemble.contains("cache merge ") && assemble.contains("fig7 --offline"));
    assert!(dir.join("repro-fig7.submit.sh").exists());
    let (code, _, err) = repro(&["slurm", "nofig", "--tasks", "2", "--dir", s(&dir)]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown target 'nofig'"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Fig. 4's jobs at level 5.
fn fig4_jobs() -> Vec<Job> {
    let sweep = shipped_sweep("fig4").unwrap();
    point_jobs(&sweep.cases, 5)
        .unwrap()
        .into_iter()
        .map(|p| p.job)
        .collect()
}

#[test]
fn shards_partition_the_families_evenly() {
    let jobs = fig4_jobs();
    let mut doubled = jobs.clone();
    doubled.extend(jobs.iter().cloned()); // a case listed twice is solved once
    for count in [1, 3, 7] {
        let mut all: Vec<String> = Vec::new();
        let mut families = Vec::new();
        let mut owner: BTreeSet<(String, usize)> = BTreeSet::new();
        for index in 1..=count {
            let share = Shard::new(index, count).unwrap().select(doubled.clone());
            let mine: BTreeSet<String> = share.iter().map(|j| j.family().to_string()).collect();
            families.push(mine.len());
            owner.extend(mine.into_iter().map(|f| (f, index)));
            all.extend(share.into_iter().map(|j| j.key));
        }
        all.sort();
        let mut expect: Vec<String> = jobs.iter().map(|j| j.key.clone()).collect();
        expect.sort();
        assert_eq!(all, expect, "{count} shards: every case once");
        // Fig. 4's 27 families of nine, each in one shard, the shards within one family.
        assert_eq!(owner.len(), 27, "{count} shards: a family split");
        let (lo, hi) = (
            families.iter().min().unwrap(),
            families.iter().max().unwrap(),
        );
        assert!(hi - lo <= 1, "{count} shards: families {families:?}");
    }
    // The same list gives the same share in any order.
    let mut reversed = jobs.clone();
    reversed.reverse();
    let keys = |v: Vec<Job>| {
        let mut k: Vec<String> = v.into_iter().map(|j| j.key).collect();
        k.sort();
        k
    };
    let s = Shard::new(2, 5).unwrap();
    assert_eq!(keys(s.select(jobs)), keys(s.select(reversed)));
}

/// `repro cache prune` removes the entries an older revision made and keeps the present
/// build's; `--dry-run` only counts them.
#[test]
fn pruning_removes_what_the_present_revisions_cannot_reach() {
    let dir = scratch("shards", "prune");
    let cache = Cache::new(dir.join("cache"));
    let stamp = |revisions: &str| Stamp {
        revisions: Some(revisions.into()),
        ..Stamp::now(1.0, String::new())
    };
    let (present, old) = (key_of(&"present"), key_of(&"old"));
    cache
        .put(&present, &vec![1.0], &stamp(&point_revisions()))
        .unwrap();
    cache
        .put(&old, &vec![1.0], &stamp("point-24 thermal-3"))
        .unwrap();
    let at = s(cache.dir());
    let (code, out, err) = repro(&["cache", "prune", "--dry-run", "--cache", at]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("would remove 1 files"), "{out}");
    assert_eq!(cache.keys().unwrap().len(), 2);
    let (code, out, err) = repro(&["cache", "prune", "--cache", at]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("removed 1 files"), "{out}");
    assert_eq!(cache.keys().unwrap(), vec![present]);
    let (code, _, err) = repro(&["cache", "list", "--cache", s(&dir.join("none"))]);
    assert_eq!(code, 2, "a folder that is not there: {err}");
    assert!(err.contains("no cache folder"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

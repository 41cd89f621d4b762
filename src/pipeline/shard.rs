//! Shards of a run: `--shard I/N` takes the I-th of N equal shares of the run's distinct
//! solves (1-based), so that N processes (a Slurm job array, GNU parallel, HyperQueue) each
//! solve their share into a cache, and the caches merge.
//!
//! The share is decided by the cache keys alone: the run's cases go by family (the cases that
//! start from one base, [`Job::family`], keyed by the root base's key, so that each base is
//! solved once), the families' keys sorted, the one of rank r (from 0) to shard `r mod N +
//! 1`. Every process of the run lists the same cases, so they agree on the split without
//! talking to each other; the shares differ by at most one family (a split by hash ranges
//! would leave them unequal by the square root of their size); and a key's place in the
//! sorted list is unrelated to where its case is in the sweep, so heavy and light regions of
//! a grid spread over the shards.

use super::job::Job;
use crate::pipeline::error::PipelineError;
use std::collections::BTreeSet;
use std::fmt;

/// Shard `index` of `count` (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which shard, 1..=count.
    pub index: usize,
    /// How many shards.
    pub count: usize,
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// Parses `I/N` with `1 <= I <= N`.
    pub fn parse(text: &str) -> Result<Self, PipelineError> {
        let (i, n) = text
            .split_once('/')
            .ok_or_else(|| PipelineError::Shard(format!("'{text}': expected I/N, e.g. 2/8")))?;
        let index: usize = i
            .trim()
            .parse()
            .map_err(|e| PipelineError::Shard(format!("'{text}': shard index '{i}': {e}")))?;
        let count: usize = n
            .trim()
            .parse()
            .map_err(|e| PipelineError::Shard(format!("'{text}': shard count '{n}': {e}")))?;
        Self::new(index, count).map_err(|e| PipelineError::Shard(format!("'{text}': {e}")))
    }

    /// Shard `index` of `count`, checked.
    pub fn new(index: usize, count: usize) -> Result<Self, PipelineError> {
        if count == 0 {
            return Err(PipelineError::Shard(
                "the number of shards must be at least 1".into(),
            ));
        }
        if !(1..=count).contains(&index) {
            return Err(PipelineError::Shard(format!(
                "shard index {index} outside 1..={count} (shards are numbered from 1)"
            )));
        }
        Ok(Shard { index, count })
    }

    /// The shard of a Slurm array task, from `SLURM_ARRAY_TASK_ID`, `SLURM_ARRAY_TASK_COUNT`,
    /// `SLURM_ARRAY_TASK_MIN` and `SLURM_ARRAY_TASK_STEP` (given as read; absent ones `None`).
    /// Arrays may start at 0 or 1 (or anywhere) and step by more than 1: the task's shard is
    /// its place in the array, `(ID - MIN) / STEP + 1` of COUNT.
    pub fn from_slurm(
        id: &str,
        count: &str,
        min: Option<&str>,
        step: Option<&str>,
    ) -> Result<Self, PipelineError> {
        let num = |name: &str, v: &str| -> Result<usize, PipelineError> {
            v.trim()
                .parse()
                .map_err(|e| PipelineError::Shard(format!("{name}={v}: not a task number ({e})")))
        };
        let id = num("SLURM_ARRAY_TASK_ID", id)?;
        let count = num("SLURM_ARRAY_TASK_COUNT", count)?;
        let Some(min) = min else {
            return Err(PipelineError::Shard(
                "SLURM_ARRAY_TASK_MIN is not set, so whether the array starts at 0 or 1 is unknown; pass --shard I/N"
                    .into(),
            ));
        };
        let min = num("SLURM_ARRAY_TASK_MIN", min)?;
        let step = match step {
            Some(s) => num("SLURM_ARRAY_TASK_STEP", s)?.max(1),
            None => 1,
        };
        if id < min || (id - min) % step != 0 {
            return Err(PipelineError::Shard(format!(
                "SLURM_ARRAY_TASK_ID={id} is not on the array's range (from {min} by {step}); an array given as a list needs --shard I/N"
            )));
        }
        Self::new((id - min) / step + 1, count).map_err(|e| {
            PipelineError::Shard(format!("SLURM_ARRAY_TASK_ID={id} with MIN={min}, STEP={step}, COUNT={count}: {e}; an array given as a list needs --shard I/N"))
        })
    }

    /// This shard's share of `jobs`: whole families ([`Job::family`], the cases that start
    /// from one base, so that each base is solved by one shard), the distinct family keys in
    /// sorted order, every `count`-th from the `index`-th (see the module documentation).
    /// Jobs keep their order; a job listed twice is kept once.
    pub fn select(&self, jobs: Vec<Job>) -> Vec<Job> {
        let families: BTreeSet<&str> = jobs.iter().map(|j| j.family()).collect();
        let mine: BTreeSet<String> = families
            .into_iter()
            .enumerate()
            .filter(|(rank, _)| rank % self.count + 1 == self.index)
            .map(|(_, k)| k.to_string())
            .collect();
        let mut seen = BTreeSet::new();
        jobs.into_iter()
            .filter(|j| mine.contains(j.family()) && seen.insert(j.key.clone()))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shard_flags_and_slurm_arrays_from_0_or_1() {
        assert_eq!(Shard::parse("2/3").unwrap(), Shard { index: 2, count: 3 });
        for bad in ["0/3", "4/3", "1/0", "2", "a/3", "1/b"] {
            assert!(Shard::parse(bad).is_err(), "{bad}");
        }
        // --array=0-2: tasks 0, 1, 2 are shards 1, 2, 3.
        assert_eq!(
            Shard::from_slurm("0", "3", Some("0"), Some("1")).unwrap(),
            Shard { index: 1, count: 3 }
        );
        // --array=1-3: task 3 is shard 3.
        assert_eq!(
            Shard::from_slurm("3", "3", Some("1"), None).unwrap(),
            Shard { index: 3, count: 3 }
        );
        // --array=10-30:10: task 20 is shard 2.
        assert_eq!(
            Shard::from_slurm("20", "3", Some("10"), Some("10")).unwrap(),
            Shard { index: 2, count: 3 }
        );
        let e = Shard::from_slurm("2", "3", None, None)
            .unwrap_err()
            .to_string();
        assert!(e.contains("SLURM_ARRAY_TASK_MIN"), "{e}");
        // --array=1,5,9 (a list): not a range, refused with the way out.
        let e = Shard::from_slurm("9", "3", Some("1"), Some("1"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("--shard"), "{e}");
        assert!(Shard::from_slurm("x", "3", Some("0"), None).is_err());
    }
}

//! The engine under the paper's targets: solves as jobs with cache keys, run in parallel
//! through the result cache, and the files they become.
//!
//! - [`job`]: each solve as a job, [`keys`]: its cache key, [`label`]: its case in words,
//!   [`base`]: the case a solve starts from; [`outcome`]: what a solve yields;
//! - [`executor`]: jobs run in parallel through the cache; [`offline`]: assembly from the
//!   cache alone; [`cache`], [`merge`], [`prune`]: the result cache, the merge of caches and
//!   what a cache holds per revision;
//! - [`shard`], [`slurm`]: scale-out; [`provenance`]: what made an output;
//! - [`sweep`]: sweep files (the cases of `cases/` and users' studies);
//! - [`context`]: where and how targets are built; [`error`]: why a target failed; [`csv`]: deterministic CSV files;
//!   [`snapshot`]: the comparison with the committed baselines.

pub mod base;
pub mod cache;
pub mod context;
pub mod csv;
pub mod error;
pub mod executor;
pub mod job;
pub mod keys;
pub mod label;
pub mod merge;
pub mod offline;
pub mod outcome;
pub mod provenance;
pub mod prune;
pub mod shard;
pub mod slurm;
pub mod snapshot;
pub mod sweep;

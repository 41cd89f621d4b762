//! The engine under the paper's artefacts: solves as jobs with cache keys, run in parallel
//! through the result cache, and the files they become.
//!
//! - [`run`]: jobs, their keys and the parallel executor; [`base`]: the case a solve starts
//!   from; [`cache`], [`merge`]: the result cache and the merge of caches;
//! - [`shard`], [`slurm`]: scale-out; [`provenance`]: what made an output;
//! - [`sweep`]: sweep files (the cases of `cases/` and users' studies);
//! - [`context`]: where and how targets are built; [`csv`]: deterministic CSV files;
//!   [`snapshot`]: the comparison with the committed baselines.

pub mod base;
pub mod cache;
pub mod context;
pub mod csv;
pub mod merge;
pub mod provenance;
pub mod run;
pub mod shard;
pub mod slurm;
pub mod snapshot;
pub mod sweep;

//! The artefact pipeline: the paper's tables and figures as named targets, their case
//! definitions (from `cases/`), and the files they write.
//!
//! Layers, each on those below it: the computations (`run`, `cache`, `sweep`, `table4`,
//! `line_cases`, `accuracy`, `measured`, `fit`) and the files (`csv`, `plot`); [`target`],
//! what every target shares; the targets and their registry ([`targets`]); the [`report`] of
//! a run of them all and the [`snapshot`] comparison.

pub mod accuracy;
pub mod base;
pub mod cache;
pub mod csv;
pub mod fit;
pub mod html;
pub mod line_cases;
pub mod lss_curve;
pub mod measured;
pub mod merge;
pub mod oracle;
pub mod plot;
pub mod prediction;
pub mod provenance;
pub mod refined;
pub mod report;
pub mod run;
pub mod shard;
pub mod slurm;
pub mod snapshot;
pub mod sweep;
pub mod table4;
pub mod target;
pub mod targets;

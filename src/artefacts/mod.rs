//! The artefact pipeline: the paper's tables and figures as named targets, their case
//! definitions (from `cases/`), and the files they write.

pub mod accuracy;
pub mod cache;
pub mod csv;
pub mod fig8;
pub mod figures;
pub mod fit;
pub mod html;
pub mod line_cases;
pub mod measured;
pub mod plot;
pub mod run;
pub mod snapshot;
pub mod sweep;
pub mod table4;
pub mod tables;
pub mod targets;

//! The artefact pipeline: the paper's tables and figures as named targets, their case
//! definitions (from `cases/`), and the files they write.

pub mod cache;
pub mod csv;
pub mod fit;
pub mod run;
pub mod sweep;
pub mod table4;

/// A target of `repro list`.
#[derive(Debug, Clone, Copy)]
pub struct Target {
    /// Name on the command line.
    pub name: &'static str,
    /// One line for `repro list`.
    pub description: &'static str,
}

/// Every target, in the paper's order.
pub const TARGETS: &[Target] = &[Target {
    name: "table4",
    description: "Grid convergence of Hc and sliding mu-bar for the Appendix case, levels 5-8, with wall times",
}];

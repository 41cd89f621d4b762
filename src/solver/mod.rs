//! Solvers: grids, the deformation integral and the EHL multigrid solvers.
//! No I/O: progress goes through a callback the caller passes in.

pub mod banded;
pub(crate) mod bordered_lu;
pub mod deformation;
pub(crate) mod dense;
pub(crate) mod gmres;
pub mod grid;
pub mod line;
pub(crate) mod line_search;
pub mod output;
pub mod point;

//! Solvers: grids, the deformation integral and the point-contact EHL multigrid solver.
//! No I/O: progress goes through a callback the caller passes in.

pub mod deformation;
pub mod grid;

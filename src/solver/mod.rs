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
pub mod thermal;

/// Fixes the parallelism of faer's factorisations (the Newton-Krylov preconditioner's sparse
/// LU, the line contact's dense LU) at a degree of 2, whatever the number of threads. faer
/// splits its work by the degree it is given; at its default (rayon's current thread count)
/// the last bits of a factorisation, and so of every Newton iterate after it, depend on the
/// machine's or the job's thread count: a Slurm task on one CPU and a two-core workstation
/// gave the same case different last digits. With a fixed degree a case gives the same bits
/// everywhere; the two halves still run on whatever threads rayon has (in turn, on one).
/// Degree 2 is what every result computed so far used (this machine's thread count), so
/// cached results stay valid.
pub(crate) fn fix_factorisation_parallelism() {
    static FIXED: std::sync::Once = std::sync::Once::new();
    FIXED.call_once(|| faer::set_global_parallelism(faer::Par::rayon(2)));
}

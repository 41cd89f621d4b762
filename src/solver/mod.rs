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
pub mod richardson;
pub mod subnormal;
pub mod thermal;

/// Fixes faer's factorisations (the Newton-Krylov preconditioner's sparse LU, the line
/// contact's dense LU) to run on one thread, whatever the number of threads. faer splits its
/// work by the degree of parallelism it is given, so the last bits of a factorisation, and of
/// every Newton iterate after it, depend on that degree: at faer's default (rayon's thread
/// count) a Slurm task on one CPU and a two-core workstation gave a case different digits.
/// One thread gives the same bits everywhere, and it is also the faster choice: with a
/// degree of 2 the split's scheduling (threads spinning in `sched_yield`, freshly mapped
/// buffers) cost more than the second core saved (docs/ACCURACY_NOTES.md, "The Newton-Krylov
/// step"), and a sweep runs cases side by side on every core anyway.
pub(crate) fn fix_factorisation_parallelism() {
    static FIXED: std::sync::Once = std::sync::Once::new();
    FIXED.call_once(|| faer::set_global_parallelism(faer::Par::Seq));
}

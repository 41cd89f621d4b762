//! `repro`: regenerates "A Generalized Traction Curve for EHL Contacts" (Jacod, Venner and
//! Lugt, ASME J. Tribology 2001) from first principles.
//!
//! Layers, with one-way dependencies: `cli` (binary) -> [`report`] -> [`paper`] (one module
//! per target of the paper, and their registry) -> [`pipeline`] (jobs, cache, executor,
//! files) and [`plot`] (the SVG kit) -> [`solver`] -> [`physics`]. The numerical kernel does
//! no I/O.

// Numerical kernels index several arrays by the same grid index; iterator rewrites of those
// loops obscure the stencils they implement.
#![allow(clippy::needless_range_loop)]

pub mod paper;
pub mod physics;
pub mod pipeline;
pub mod plot;
pub mod report;
pub mod solver;

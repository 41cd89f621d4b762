//! The driver: which strategy covers the contact, then its solve, each through the one loop
//! of [`super::covering`] (converge, check the film, read the outputs and their error, refine
//! where they miss). A uniform grid ([`super::uniform`]) converges its top level warm or cold,
//! settles its edge, estimates by the ladder of coarser levels and refines. The nested chain
//! ([`super::chain`]) solves a uniform grid on each of its domains, the case-sized one first,
//! and estimates over whole chains at coarser levels; the composite grid
//! ([`super::composite`]) solves one on its patch inside rounds that couple the patch with the
//! whole domain, and estimates over whole composites. The chain refines by being solved again
//! one level finer; the composite does not refine.

use super::composite::PatchSet;
use super::{chain, composite, uniform, Params, PointSolution, Start};
use crate::physics::case::Problem;
use crate::solver::output::{Progress, SolveError};

/// How a solve covers the contact ([`Params::patch`], [`Params::nested`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Strategy<'a> {
    /// One grid over the domain at a uniform mesh.
    Uniform,
    /// The domain and rectangles nested inside it down to the contact's core, each at the
    /// same level inside the solution around it.
    Nested,
    /// The domain and patches at half its mesh, coupled both ways.
    Composite(&'a PatchSet),
}

impl<'a> Strategy<'a> {
    /// The strategy `params` ask for: a patch where they give one, else the chain where they
    /// ask for nesting and the domain has rectangles inside it ([`chain::rectangles`]), else
    /// the uniform grid.
    pub(super) fn of(params: &'a Params) -> Self {
        match &params.patch {
            Some(spec) => Strategy::Composite(spec),
            None if params.nested && !chain::rectangles(&params.domain).is_empty() => {
                Strategy::Nested
            }
            None => Strategy::Uniform,
        }
    }
}

/// Solves `problem` with `params` by their strategy, from `start` where given and the
/// strategy uses one (the composite solves cold).
pub(super) fn solve(
    problem: &Problem,
    params: &Params,
    start: Option<&Start>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    match Strategy::of(params) {
        Strategy::Composite(spec) => composite::solve_point(problem, params, spec, observer),
        Strategy::Nested => chain::solve_point(problem, params, start, observer),
        Strategy::Uniform => uniform::solve(problem, (params, None), start, observer),
    }
}

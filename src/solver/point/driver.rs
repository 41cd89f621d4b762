//! The driver: which strategy covers the contact, then its solve. A uniform grid
//! ([`super::uniform`]) is the solver's own loop: converge the top level warm or cold, settle
//! its edge, check the film, estimate the outputs' error by the ladder of coarser levels, and
//! refine where the film closes or the estimate misses the target. The nested chain
//! ([`super::chain`]) runs that loop on each of its domains, the case-sized one first, and
//! estimates over whole chains at coarser levels; the composite grid ([`super::composite`])
//! runs it on its patch inside rounds that couple the patch with the whole domain.

use super::composite::PatchSpec;
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
    /// The domain and a patch at half its mesh, coupled both ways.
    Composite(&'a PatchSpec),
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

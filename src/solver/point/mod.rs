//! The isothermal elliptical EHL contact with Eyring rheology (Sec. II of the paper), solved
//! by full-approximation-scheme multigrid with a full-multigrid start from the Hertzian
//! pressure (Venner and Lubrecht, "Multilevel Methods in Lubrication", 2000):
//!
//! - Reynolds, Eq. (1), second-order central Poiseuille terms and a second-order upstream
//!   wedge term; cavitation by `P = max(P, 0)`;
//! - film, Eq. (6), with the deformation evaluated exactly on each grid by zero-padded FFT
//!   ([`crate::solver::deformation`]);
//! - line relaxation switching between Gauss-Seidel and Jacobi distributive ([`relax`]);
//! - the force balance, Eq. (7), relaxed on the coarsest grid through `Delta`.
//!
//! The domain defaults to the paper's `-2.5 <= X <= 1.5`, `-2 <= Y <= 2`
//! ([`crate::solver::grid::Domain::default`]); level `n` has `2^(n+1)` intervals per direction.

pub mod chain;
mod cold;
pub mod composite;
mod converge;
mod covering;
mod cycles;
mod driver;
mod edge;
mod far_field;
mod finish;
mod friction;
mod jacobian;
mod ladder;
mod level;
mod model;
mod multigrid;
pub mod nested;
mod newton;
mod params;
mod patch;
mod rectangles;
mod refine;
mod relax;
mod sequence;
mod stopping;
mod tau;
mod transfer;
mod uniform;
mod warm;

use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{Film, Friction, Info, OutputErrors, Progress, SolveError};
pub use covering::level_to_resolve;
pub use friction::{mean_shear_stress, FrictionRegion, LOADED_FILM_FACTOR};
pub use ladder::CoarseSolution;
/// The applied load in `P` and `X, Y` units, `2 pi / 3` (Eq. 7).
pub(crate) use level::LOAD;
pub use model::HalfPointMean;
use nested::Surround;
pub use newton::HandedFactor;
pub use params::{
    AccuracyParams, Edge, FrictionParams, KrylovParams, MultigridParams, NewtonParams, Params,
    StoppingParams,
};
pub use refine::AccuracyTarget;
use std::sync::Arc;
pub use tau::{CoarseChange, TauExtrapolated};
pub use warm::Start;

/// Revision of the point-contact numerics: part of every cache key, raised whenever a change
/// can move a result (the revision guard, tests/revision.rs, fails when a result moves and it
/// is not).
pub const SOLVER_REVISION: &str = "point-44";

/// Highest level the solver accepts (1024 x 1024: 8.4 M nodes of working arrays).
pub const MAX_LEVEL: u32 = 9;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// A converged point-contact solution.
#[derive(Debug, Clone)]
pub struct PointSolution {
    /// The finest grid.
    pub grid: Grid,
    /// Pressure `P = p/p_H` at the nodes.
    pub p: Vec<f64>,
    /// Film `H = h/c` at the nodes.
    pub h: Vec<f64>,
    /// The film constant `Delta` of Eq. (6).
    pub delta: f64,
    /// Central and minimum film.
    pub film: Film,
    /// Reduced friction.
    pub friction: Friction,
    /// The region the friction was integrated over ([`FrictionParams::region`]).
    pub friction_region: FrictionRegion,
    /// Convergence information.
    pub info: Info,
    /// The outputs' discretisation error ([`AccuracyParams::error_levels`]; `None` where it is 0).
    pub errors: Option<OutputErrors>,
    /// The coarser levels' solutions behind `errors`, finest first: a member's ladder starts
    /// from them ([`Start::coarser`]).
    pub coarser: Vec<CoarseSolution>,
    /// The case-sized domain's solution around a chain of nested domains ([`chain`]), whose
    /// innermost grid this is; a related case starts from it.
    pub surroundings: Option<Box<PointSolution>>,
    /// The patches of a composite grid ([`Params::patch`]): each one's rectangle and mesh;
    /// the fields above are the whole domain's. Empty on other grids.
    pub patches: Vec<(Domain, f64)>,
    /// The final level's outputs tau-extrapolated ([`AccuracyParams::tau_extrapolation`]).
    pub tau: Option<TauExtrapolated>,
    /// The final level's last Newton-Krylov factor, on level 8 (`newton::HANDED_LEVELS`): a
    /// related case started from this solution preconditions its first step with it.
    pub factor: Option<HandedFactor>,
    /// Under a top refined across the rolling direction, the level under it refined the same
    /// way, as it converged for the estimate: a member's start of the same
    /// ([`Start::across`]).
    pub across_rung: Option<CoarseSolution>,
}

impl PointSolution {
    /// The grid's own central film, `H` at X = Y = 0 of [`PointSolution::h`] (what the level's
    /// film reads, [`Grid::at_centre`]) where the solve reported it tau-extrapolated
    /// ([`OutputErrors::tau_central`]); elsewhere the reported [`PointSolution::film`]'s (a
    /// composite grid's comes from its patch, finer than these whole-domain fields).
    pub fn grid_h_central(&self) -> f64 {
        match self.errors.as_ref().and_then(|e| e.tau_central) {
            Some(_) => self.grid.at_centre(&self.h),
            None => self.film.h_central,
        }
    }
}

/// Solves `problem` with `params` from the Hertzian pressure (full multigrid); `observer` (if
/// any) hears of every cycle and Newton step.
pub fn solve(
    problem: &Problem,
    params: &Params,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    driver::solve(problem, params, None, observer)
}

/// Solves `problem` with `params` from `start`, the converged solution of a related case (its
/// base: the same contact at another slip or Eyring stress, [`warm`]); where the warm solve
/// fails, or `start` does not fit the grid, from the Hertzian pressure as [`solve`] does
/// ([`Info::start`] says which).
pub fn solve_from(
    problem: &Problem,
    params: &Params,
    start: &Start,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    driver::solve(problem, params, Some(start), observer)
}

/// Solves `problem` with `params` on a nested domain (`params.domain`, its edges on grid lines
/// of the solution around it, [`chain::snap`]) inside `surround` ([`nested`]), cold from the
/// surroundings' pressure: the prototypes' probe (`examples/nested_probe.rs`), which nests
/// at levels of its own.
pub fn solve_nested(
    problem: &Problem,
    params: &Params,
    surround: &Arc<Surround>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    uniform::solve(problem, (params, Some(surround)), None, observer)
}

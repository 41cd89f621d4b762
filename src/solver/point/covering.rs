//! The one loop of a solve, whatever covers the contact ([`super::driver`]'s strategies): the
//! covering converged at its level, its film checked, its outputs and their discretisation
//! error read, and a finer level added where the film closes or the estimate misses the
//! accuracy target ([`super::AccuracyParams`]), within the refinements it has left.
//!
//! A uniform grid ([`super::uniform`]) refines; the nested chain ([`super::chain`]) and the
//! composite grid ([`super::composite`]) do not (their estimate solves the whole strategy
//! again at coarser levels, and a finer one would cost four times their level).

use super::converge::Tally;
use super::tau::TauExtrapolated;
use super::{AccuracyParams, CoarseSolution, PointSolution, MAX_LEVEL};
use crate::physics::case::Problem;
use crate::physics::film::hc_nijenbanning;
use crate::solver::output::{Film, Friction, OutputErrors, Progress, SolveError};

/// A converged covering's outputs.
pub(super) struct Outputs {
    pub(super) friction: Friction,
    /// The tau-extrapolated outputs, where asked for ([`AccuracyParams::tau_extrapolation`]).
    pub(super) tau: Option<TauExtrapolated>,
    /// The discretisation error, where asked for ([`AccuracyParams::error_levels`]).
    pub(super) errors: Option<OutputErrors>,
    /// The coarser levels' solutions behind `errors`: a refined level's ladder starts from
    /// them, and a member's ([`super::Start::coarser`]).
    pub(super) coarser: Vec<CoarseSolution>,
}

/// What the loop asks of a strategy's solve, converged at its present level. A covering
/// that refines overrides the three methods that say so; the others are solved at the
/// level given.
pub(super) trait Covering {
    /// The film (central and minimum) the outputs are read from.
    fn film(&self) -> Film;
    /// The present level.
    fn level(&self) -> u32;
    /// The outputs and their error estimate.
    fn outputs(&mut self, observe: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError>;
    /// The residuals and cycles so far: a closed film's error carries them.
    fn into_tally(self) -> Tally;
    /// The solution, with `film` and `outputs`.
    fn into_solution(self, film: Film, outputs: Outputs) -> PointSolution;

    /// Whether a finer level may still be added.
    fn may_refine(&self) -> bool {
        false
    }
    /// Whether the accuracy target is read at this level.
    fn reads_target(&self) -> bool {
        false
    }
    /// A finer level added and converged: after `outputs` where the estimate missed the
    /// target (the levels it read start the refined level's), without where the film closed.
    /// Called only where [`Covering::may_refine`].
    fn refine(
        &mut self,
        _after: Option<Outputs>,
        _observe: &mut dyn FnMut(&Progress),
    ) -> Result<(), SolveError> {
        Err(SolveError::InvalidParams(format!(
            "this grid is solved at level {} alone",
            self.level()
        )))
    }
}

/// The loop (the module's documentation) on `covering` of `problem`, converged at its first
/// level, with the accuracy `accuracy` asks for.
pub(super) fn run(
    mut covering: impl Covering,
    problem: &Problem,
    accuracy: &AccuracyParams,
    observe: &mut dyn FnMut(&Progress),
) -> Result<PointSolution, SolveError> {
    loop {
        let film = covering.film();
        if accuracy.require_positive_film && film.h_min <= 0.0 {
            if !covering.may_refine() {
                let level = covering.level();
                return Err(film_collapse(
                    problem,
                    level,
                    film.h_min,
                    covering.into_tally(),
                ));
            }
            covering.refine(None, observe)?;
            continue;
        }
        let outputs = covering.outputs(observe)?;
        let missed = match (&accuracy.target, &outputs.errors) {
            (Some(target), Some(e)) => {
                covering.reads_target() && !target.met_by(e, problem.groups.m)
            }
            _ => false,
        };
        if !(missed && covering.may_refine()) {
            return Ok(covering.into_solution(film, outputs));
        }
        covering.refine(Some(outputs), observe)?;
    }
}

/// The level estimated to resolve the film of `problem` whose minimum film came out as
/// `h_min <= 0` (in `h/c`) at `level`: the film's grid error (the expected minimum film less
/// `h_min`) falls like `4^-level` (second order), and the level is the first where it is
/// below half the expected minimum film, taken as half the Nijenbanning-Venner-Moes central
/// film (the heavily loaded contacts' minimum film is 0.5-0.7 of the central one).
pub fn level_to_resolve(problem: &Problem, level: u32, h_min: f64) -> u32 {
    let g = &problem.groups;
    let expected = 0.5 * hc_nijenbanning(g.m, g.l, g.d) / g.moes_film_scale;
    let error = expected - h_min;
    let halvings = ((2.0 * error / expected).ln() / 4f64.ln()).ceil().max(1.0);
    level + halvings as u32
}

/// The error of a film that closed at `level` (its minimum film `h_min <= 0`) with no finer
/// level left to the solve: the level estimated to resolve it, and the residuals so far.
fn film_collapse(problem: &Problem, level: u32, h_min: f64, tally: Tally) -> SolveError {
    SolveError::FilmCollapse {
        h_min,
        level,
        level_needed: Some(level_to_resolve(problem, level, h_min)),
        finest_level: MAX_LEVEL,
        cycle: tally.cycles,
        residual_history: tally.history,
    }
}

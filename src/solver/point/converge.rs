//! One way to converge a level as the top of the hierarchy: its multigrid cycles, and where
//! they fail, the Newton-Krylov finish. Every path of the point solver converges its levels
//! here: the cold solve's finest level after full multigrid ([`super::cold`]), a warm start
//! ([`super::warm`]), the far field's settling ([`super::edge`]), a refined level
//! ([`super::refine`]), the coarser levels of the error estimate ([`super::ladder`]) and the
//! levels of the grid sequence ([`super::sequence`]).
//!
//! What follows cycles that did not converge depends on where the level started
//! ([`AfterStall`]): from a converged solution, or one interpolated from it, the finish starts
//! from the better of the cycles' best state and the start, with a second try where it stalls
//! (the cycles relax the finish's state, then Newton again); from full multigrid, the finish
//! starts on the level only where the cycles crept close to the solution, and otherwise the
//! cold solve hands their best state to the grid sequence.

use super::cycles::{converge_by_cycles, Cycles, StallWindows, State};
use super::finish::finish;
use super::multigrid::Hierarchy;
use super::newton;
use super::stopping::Known;
use super::Params;
use crate::solver::output::{Method, Progress, SolveError};

/// The running tallies of a solve: the cycles of its levels' first tries, every residual
/// (cycles and Newton steps, in order), the Newton-Krylov work.
#[derive(Default)]
pub(super) struct Tally {
    pub(super) cycles: usize,
    pub(super) history: Vec<f64>,
    pub(super) work: Work,
}

impl Tally {
    /// The solve's failure to converge, with its history.
    pub(super) fn not_converged(&self, params: &Params) -> SolveError {
        SolveError::NotConverged {
            cycles: self.cycles,
            tolerance: params.stopping.tolerance,
            residual_history: self.history.clone(),
        }
    }
}

/// Newton-Krylov steps and GMRES iterations over the levels of a finish.
#[derive(Default)]
pub(super) struct Work {
    pub(super) newton_steps: usize,
    pub(super) krylov_iterations: usize,
}

impl Work {
    /// Counts a level's outcome; whether it converged.
    pub(super) fn add(&mut self, outcome: &newton::NewtonKrylovRun) -> bool {
        self.newton_steps += outcome.iterations;
        self.krylov_iterations += outcome.krylov_iterations;
        outcome.converged
    }
}

/// How a level is converged by [`converge_level`].
pub(super) struct How<'a> {
    /// Cycles first (the level, or the one it came from, converged by them); `false` goes
    /// straight to the Newton-Krylov finish.
    pub(super) cycles: bool,
    /// When the cycles count as stalled.
    pub(super) windows: StallWindows,
    /// What stops them besides the residual ([`Known`]: a warm start's outputs, a finer
    /// level's).
    pub(super) known: &'a Known,
    /// What follows cycles that did not converge.
    pub(super) after_stall: AfterStall,
}

/// What [`converge_level`] does after cycles that did not converge.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum AfterStall {
    /// The Newton-Krylov finish from the better of the cycles' best state (where they stayed
    /// finite) and the level's start; where that stalls, [`polish_and_finish`]. For a level
    /// that starts from a converged solution or one interpolated from it.
    BetterOfStart,
    /// The finish from the cycles' best state where its residual is below this, once; else
    /// (or where it fails) the level is left to its caller with that state
    /// ([`Stalled::best`]). For the cold solve's finest level after full multigrid
    /// ([`super::cold`]), whose cycles far from the solution stall at 1e-2 or diverge.
    FinishBelow(f64),
}

/// A level that did not converge: the best state of its cycles, where [`AfterStall::FinishBelow`]
/// hands it on, and the cycle at which a non-finite value appeared, where one did.
pub(super) struct Stalled {
    pub(super) best: Option<State>,
    pub(super) non_finite: Option<usize>,
}

impl<'a> How<'a> {
    /// Cycles with the ordinary stall window and no early rule (a start that is already
    /// converged, or nearly, need not halve its residual early), stopped also by `known`;
    /// where they alternate, with a weighted correction (`StallWindows::weigh_alternation`).
    pub(super) fn from_converged(params: &Params, known: &'a Known) -> Self {
        How {
            cycles: true,
            windows: StallWindows {
                stall: params.multigrid.stall_cycles,
                early: 0,
                weigh_alternation: true,
            },
            known,
            after_stall: AfterStall::BetterOfStart,
        }
    }

    /// Cycles where `method` says the level converged by them, else the finish alone.
    pub(super) fn as_by(method: Method, params: &Params, known: &'a Known) -> Self {
        How {
            cycles: method == Method::Cycles,
            ..How::from_converged(params, known)
        }
    }
}

/// Converges level `k` (the top) from its current state as `how` says, counting into
/// `tally`: the cycles; where they fail, Newton-Krylov (if [`super::NewtonParams::steps`]
/// allows) as [`How::after_stall`] says. How it converged, or how it did not.
pub(super) fn converge_level(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    how: &How,
    tally: &mut Tally,
    observe: &mut dyn FnMut(&Progress),
) -> Result<Method, Stalled> {
    let mut non_finite = None;
    if how.cycles {
        let start = State::of(mg, k);
        let run = converge_by_cycles(mg, k, params, how.windows, how.known, observe);
        tally.cycles += run.history.len();
        tally.history.extend(&run.history);
        if run.converged {
            return Ok(Method::Cycles);
        }
        if let AfterStall::FinishBelow(limit) = how.after_stall {
            return finish_from_best(mg, k, params, (run, limit), tally, observe);
        }
        // The start's residual is measured only here, where it is needed.
        start.restore(mg, k);
        let (start_residual, _) = mg.residual_norm(k);
        if run.non_finite.is_none() && run.best_residual < start_residual {
            run.best.restore(mg, k);
        }
        non_finite = run.non_finite;
    }
    let converged = params.newton.steps > 0
        && (tally
            .work
            .add(&finish(mg, k, params, observe, &mut tally.history))
            || polish_and_finish(mg, k, params, observe, tally));
    if converged {
        Ok(Method::NewtonKrylov)
    } else {
        Err(Stalled {
            best: None,
            non_finite,
        })
    }
}

/// [`AfterStall::FinishBelow`]: the finish on level `k` from the best state of `run` where its
/// residual is below `limit`; where it is not, or the finish fails, that state handed back.
fn finish_from_best(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    (run, limit): (Cycles, f64),
    tally: &mut Tally,
    observe: &mut dyn FnMut(&Progress),
) -> Result<Method, Stalled> {
    if params.newton.steps > 0 && run.best_residual < limit {
        run.best.restore(mg, k);
        if tally
            .work
            .add(&finish(mg, k, params, observe, &mut tally.history))
        {
            return Ok(Method::NewtonKrylov);
        }
    }
    Err(Stalled {
        best: Some(run.best),
        non_finite: run.non_finite,
    })
}

/// A second try on level `k` after its Newton-Krylov finish stalled: the cycles relax its
/// state (their projection `P = max(P, 0)` settles the cavitation boundary where the
/// semi-smooth Newton steps cycle between active sets) and, unless they converge, Newton
/// starts again from their best state. M 0.13, L 47 (lambda 170) at level 6: one cycle and
/// two Newton steps to 6e-11, after 30 steps stalled at 0.11. Its cycles go in the history,
/// not in the first tries' count.
fn polish_and_finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    tally: &mut Tally,
) -> bool {
    let windows = StallWindows {
        stall: params.multigrid.sequence_stall_cycles,
        early: params.multigrid.early_stall_cycles,
        weigh_alternation: false,
    };
    let run = converge_by_cycles(mg, k, params, windows, &Known::default(), observe);
    tally.history.extend(&run.history);
    if run.converged {
        return true;
    }
    run.best.restore(mg, k);
    tally
        .work
        .add(&finish(mg, k, params, observe, &mut tally.history))
}

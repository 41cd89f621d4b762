//! The cold solve's way out where its finest level's cycles fail: the Newton-Krylov finish
//! grid-sequenced from a coarser level's full-multigrid state.

use super::converge::{converge_level, AfterStall, How, Tally};
use super::cycles::{StallWindows, State};
use super::ladder::CoarseSolution;
use super::multigrid::Hierarchy;
use super::stopping::Known;
use super::Params;
use crate::solver::output::Progress;

/// The Newton-Krylov finish, grid-sequenced: level [`super::NewtonParams::start_level`] converged
/// from its state in `starts` (its cycles, then Newton where they stall), then Newton on each finer
/// level from the interpolated solution of the one below ([`converge_level`]), counted in `tally`.
/// Each level below the finest that converges replaces its entry of `coarser` (the error
/// ladder's starts, [`super::ladder`]) with its solution: the full-multigrid state of a case
/// whose cycles fail can be far from it (5P4E, 40 C, 2 GPa, 7 m/s: level 6's ladder rung took
/// 65 Newton-Krylov steps from that state and, where it failed, the injected finer solution).
/// Whether the finest level converged.
pub(super) fn grid_sequence(
    mg: &mut Hierarchy,
    (starts, coarser): (&[State], &mut [CoarseSolution]),
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    tally: &mut Tally,
) -> bool {
    let top = mg.levels.len() - 1;
    let first = (params
        .newton
        .start_level
        .clamp(params.multigrid.coarsest_level, params.level)
        - params.multigrid.coarsest_level) as usize;
    // The saved state first, then its level made the top: the far-field edge follows the
    // restored film constant.
    starts[first].restore(mg, first);
    mg.make_top(first);
    let known = Known::default();
    // Its residuals and Newton work go in the solve's tally, its cycles not: the solve counts
    // the cycles of its finest level's first try.
    let cycles = tally.cycles;
    let mut converged = true;
    for k in first..=top {
        if k > first {
            mg.make_top(k);
            mg.interpolate(k);
        }
        let how = How {
            cycles: k == first && first < top,
            windows: StallWindows {
                stall: params.multigrid.sequence_stall_cycles,
                early: params.multigrid.early_stall_cycles,
                weigh_alternation: false,
            },
            known: &known,
            after_stall: AfterStall::BetterOfStart,
        };
        if converge_level(mg, k, params, &how, tally, observe).is_err() {
            converged = false;
            break;
        }
        if let Some(entry) = coarser.get_mut(k) {
            *entry = CoarseSolution::converged(mg, k);
        }
    }
    tally.cycles = cycles;
    converged
}

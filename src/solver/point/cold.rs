//! The cold solve: full multigrid from the Hertzian pressure (or a nested domain's
//! surroundings), the finest level's cycles, and where they stall the Newton-Krylov finish,
//! directly or grid-sequenced ([`super::sequence`]).

use super::converge::Tally;
use super::cycles::{converge_by_cycles, cycle_progress, level_number, StallWindows, State};
use super::finish::finish;
use super::ladder::CoarseSolution;
use super::multigrid::Hierarchy;
use super::nested::Surround;
use super::sequence::grid_sequence;
use super::stopping::Known;
use super::{Converged, Params};
use crate::physics::case::Problem;
use crate::physics::film::hc_eq10;
use crate::solver::output::{Method, Progress, SolveError, StartKind};
use std::sync::Arc;

/// The best residual of stalled finest-level cycles below which the Newton-Krylov finish
/// starts on the finest level from their best state rather than from a coarse level: the
/// most heavily loaded Table 2 cases creep at ~0.97 per cycle below 1e-4 (mineral oil A,
/// 60 C, 3 GPa, 2 m/s at level 8), while the cycles of the very viscous cases stall at
/// 1e-2 or diverge.
const DIRECT_FINISH_RESIDUAL: f64 = 1e-3;

/// The cold solve's convergence on the top level: full multigrid from the Hertzian
/// pressure, the finest level's cycles, and where they stall the Newton-Krylov finish
/// (directly, or grid-sequenced); `history` holds what came before (a failed warm start).
pub(super) fn converge(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    observe: &mut dyn FnMut(&Progress),
    history: Vec<f64>,
) -> Result<(Hierarchy, Converged), SolveError> {
    let g = &problem.groups;
    // Initial Delta: the Eq. (10) central film minus the Hertzian approach (W(0) = 1).
    // A nested domain starts from its surroundings: their pressure and film constant.
    let delta = surround
        .as_ref()
        .map_or(hc_eq10(g.m, g.l) / g.moes_film_scale - 1.0, |s| s.delta());
    let mut mg = Hierarchy::for_problem(problem, params, surround, delta);
    let top = mg.levels.len() - 1;
    // Full multigrid: Hertzian pressure on the coarsest grid, then each finer level starts
    // from the interpolated solution of the one below; each level's state after its cycles
    // is kept as a start for the finish's grid sequence.
    {
        let l0 = &mut mg.levels[0];
        let grid = l0.grid;
        l0.p = match surround {
            Some(s) => grid.sample(|x, y| s.pressure(x, y)),
            None => grid.sample(crate::physics::hertz::Hertz::pressure),
        };
    }
    let mut starts = Vec::with_capacity(top);
    // The same states, as the starts of the coarser levels' solves for the error estimate
    // ([`ladder`]): closer to their own solutions than the finest one injected.
    let mut fmg = Vec::with_capacity(top);
    for k in 0..top {
        mg.make_top(k);
        if k > 0 {
            mg.interpolate(k);
        }
        // The coarsest level alone is solved once (its "cycle" is a full solve).
        let cycles = if k == 0 {
            1
        } else {
            params.multigrid.fmg_cycles
        };
        for cycle in 1..=cycles {
            let before = mg.levels[k].p.clone();
            mg.cycle(k);
            observe(&cycle_progress(&mut mg, k, cycle, &before));
        }
        starts.push(State::of(&mg, k));
        fmg.push(CoarseSolution {
            level: level_number(&mg.levels[k]),
            p: mg.levels[k].p.clone(),
            delta: mg.delta,
            residual: None,
        });
    }
    mg.make_top(top);
    if top > 0 {
        mg.interpolate(top);
    }
    let windows = StallWindows {
        stall: params.multigrid.stall_cycles,
        early: params.multigrid.early_stall_cycles,
        weigh_alternation: false,
    };
    let finest = converge_by_cycles(&mut mg, top, params, windows, &Known::default(), observe);
    let mut tally = Tally {
        cycles: finest.history.len(),
        history,
        ..Tally::default()
    };
    tally.history.extend(&finest.history);
    let mut method = Method::Cycles;
    let mut converged = finest.converged;
    if !converged && params.newton.steps == 0 {
        if let Some(cycle) = finest.non_finite {
            return Err(SolveError::NonFinite {
                what: "pressure or residual",
                cycle,
                residual_history: tally.history,
            });
        }
    }
    if !converged && params.newton.steps > 0 {
        method = Method::NewtonKrylov;
        // Cycles that crept close to the solution (a heavily loaded case converging too
        // slowly) hand their best state to Newton on the finest level; otherwise, or where
        // that fails, the grid sequence.
        if finest.best_residual < DIRECT_FINISH_RESIDUAL {
            finest.best.restore(&mut mg, top);
            converged = tally
                .work
                .add(&finish(&mut mg, top, params, observe, &mut tally.history));
        }
        if !converged {
            starts.push(finest.best);
            converged = grid_sequence(&mut mg, (&starts, &mut fmg), params, observe, &mut tally);
        }
    }
    if !converged {
        return Err(tally.not_converged(params));
    }
    Ok((
        mg,
        Converged {
            tally,
            method,
            start: StartKind::Cold,
            coarser: fmg,
        },
    ))
}

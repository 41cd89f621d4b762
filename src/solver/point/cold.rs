//! The cold solve: full multigrid from the Hertzian pressure (or a nested domain's
//! surroundings), then the finest level converged as every level is
//! ([`super::converge::converge_level`]): its cycles, and where they stall the Newton-Krylov
//! finish, directly or grid-sequenced ([`super::sequence`]).

use super::converge::{converge_level, AfterStall, How, Stalled, Tally};
use super::cycles::{cycle_progress, StallWindows, State};
use super::ladder::CoarseSolution;
use super::multigrid::Hierarchy;
use super::nested::Surround;
use super::sequence::grid_sequence;
use super::stopping::Known;
use super::Params;
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

/// What converged the top level, cold here or warm ([`super::warm`]): its cycles, history
/// and Newton work, its method and start.
pub(super) struct Converged {
    pub(super) tally: Tally,
    pub(super) method: Method,
    pub(super) start: StartKind,
    /// Starts of the coarser levels' solves for the error estimate ([`super::ladder`]).
    pub(super) coarser: Vec<CoarseSolution>,
}

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
            level: mg.levels[k].grid.level_number(),
            p: mg.levels[k].p.clone(),
            delta: mg.delta,
            residual: None,
        });
    }
    mg.make_top(top);
    if top > 0 {
        mg.interpolate(top);
    }
    // The finest level's cycles, through the finish directly where they crept close to the
    // solution (a heavily loaded case converging too slowly), else the grid sequence from
    // the full multigrid's states and the cycles' best.
    let known = Known::default();
    let how = How {
        cycles: true,
        windows: StallWindows {
            stall: params.multigrid.stall_cycles,
            early: params.multigrid.early_stall_cycles,
            weigh_alternation: false,
        },
        known: &known,
        after_stall: AfterStall::FinishBelow(DIRECT_FINISH_RESIDUAL),
    };
    let mut tally = Tally {
        history,
        ..Tally::default()
    };
    let method = match converge_level(&mut mg, top, params, &how, &mut tally, observe) {
        Ok(method) => method,
        Err(Stalled { non_finite, best }) => {
            if params.newton.steps == 0 {
                return Err(match non_finite {
                    Some(cycle) => SolveError::NonFinite {
                        what: "pressure or residual",
                        cycle,
                        residual_history: tally.history,
                    },
                    None => tally.not_converged(params),
                });
            }
            starts.extend(best);
            if !grid_sequence(&mut mg, (&starts, &mut fmg), params, observe, &mut tally) {
                return Err(tally.not_converged(params));
            }
            Method::NewtonKrylov
        }
    };
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

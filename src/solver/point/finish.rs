//! The Newton-Krylov finish: on the top level directly, grid-sequenced from a coarser one,
//! or after the cycles relaxed a stalled state; the far field refitted between solves.

use super::cycles::{
    converge_by_cycles, edge_outputs, level_number, outputs_settled, StallWindows, State,
};
use super::multigrid::Hierarchy;
use super::stopping::Known;
use super::{level, newton, Edge, Params, FAR_FIELD_ROUNDS, FAR_FIELD_SETTLED};
use crate::solver::output::{mean_change, Progress, Step};

/// The Newton-Krylov finish on level `k` (the top of the hierarchy) from its current
/// state; each step is reported and its residual appended to `history`.
pub(super) fn finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
) -> newton::Outcome {
    let mut outcome = newton_solve(mg, k, params, observe, history);
    if params.edge != Edge::FittedFarField {
        return outcome;
    }
    // A fitted far field: Newton with the edge frozen, the amplitude refitted to its
    // solution, until the amplitude or the outputs settle (a few rounds; each a warm Newton
    // solve).
    let mut last = edge_outputs(mg, k, params);
    for _ in 0..FAR_FIELD_ROUNDS {
        if !outcome.converged || mg.fit_far_field(k) < FAR_FIELD_SETTLED {
            break;
        }
        let next = newton_solve(mg, k, params, observe, history);
        outcome = newton::Outcome {
            converged: next.converged,
            iterations: outcome.iterations + next.iterations,
            krylov_iterations: outcome.krylov_iterations + next.krylov_iterations,
        };
        let now = edge_outputs(mg, k, params);
        if outputs_settled(&last, &now) {
            break;
        }
        last = now;
    }
    outcome
}

/// One Newton-Krylov solve on level `k` with its edge as it stands.
fn newton_solve(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
) -> newton::Outcome {
    let model = mg.model;
    let mut h0 = mg.h0;
    let level = &mut mg.levels[k];
    let mut before = level.p.clone();
    let mut steps = 0;
    let outcome = newton::iterate(
        level,
        &model,
        &mut h0,
        &newton::Limits {
            steps: params.newton_steps,
            tolerance: params.tolerance,
            load_tolerance: params.load_tolerance,
            box_radius: params.box_radius,
            krylov_restart: KRYLOV_RESTART,
            krylov_iterations: params.krylov_iterations,
            first_forcing: if mg.warm {
                newton::warm_first_forcing(level_number(level))
            } else {
                newton::FIRST_FORCING
            },
        },
        &mut |level: &level::Level, step: &newton::Step| {
            steps += 1;
            history.push(step.residual);
            observe(&Progress {
                level: level_number(level),
                count: steps,
                step: Step::NewtonKrylov {
                    krylov_iterations: step.krylov_iterations,
                },
                residual: step.residual,
                load_error: step.load_error,
                pressure_change: mean_change(&level.p, &before),
                h_central: level.h_central(),
                worst_at: step.worst_at,
            });
            before.copy_from_slice(&level.p);
        },
    );
    mg.h0 = h0;
    outcome
}

/// The Newton-Krylov finish, grid-sequenced: level `newton_start_level` converged from
/// its state in `starts` (its cycles, then Newton where they stall), then Newton on each
/// finer level from the interpolated solution of the one below; `work` counts the steps.
/// Whether the finest level converged.
pub(super) fn grid_sequence(
    mg: &mut Hierarchy,
    starts: &[State],
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
    work: &mut Work,
) -> bool {
    let top = mg.levels.len() - 1;
    let first = (params
        .newton_start_level
        .clamp(params.coarsest_level, params.level)
        - params.coarsest_level) as usize;
    // The saved state first, then its level made the top: the far-field edge follows the
    // restored film constant.
    starts[first].restore(mg, first);
    mg.make_top(first);
    let mut converged = false;
    if first < top {
        let windows = StallWindows {
            stall: params.sequence_stall_cycles,
            early: params.early_stall_cycles,
        };
        let run = converge_by_cycles(mg, first, params, windows, &Known::default(), observe);
        converged = run.converged;
        if !converged {
            run.best.restore(mg, first);
        }
    }
    for k in first..=top {
        if k > first {
            mg.make_top(k);
            mg.interpolate(k);
            converged = false;
        }
        if !converged {
            converged = work.add(&finish(mg, k, params, observe, history));
        }
        if !converged {
            converged = polish_and_finish(mg, k, params, observe, history, work);
        }
        if !converged {
            return false;
        }
    }
    converged
}

/// A second try on level `k` after its Newton-Krylov finish stalled: the cycles relax its
/// state (their projection `P = max(P, 0)` settles the cavitation boundary where the
/// semi-smooth Newton steps cycle between active sets) and, unless they converge, Newton
/// starts again from their best state. M 0.13, L 47 (lambda 170) at level 6: one cycle and
/// two Newton steps to 6e-11, after 30 steps stalled at 0.11.
pub(super) fn polish_and_finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
    work: &mut Work,
) -> bool {
    let windows = StallWindows {
        stall: params.sequence_stall_cycles,
        early: params.early_stall_cycles,
    };
    let run = converge_by_cycles(mg, k, params, windows, &Known::default(), observe);
    history.extend(&run.history);
    if run.converged {
        return true;
    }
    run.best.restore(mg, k);
    work.add(&finish(mg, k, params, observe, history))
}

/// Newton-Krylov steps and GMRES iterations over the levels of a finish.
#[derive(Default)]
pub(super) struct Work {
    pub(super) newton_steps: usize,
    pub(super) krylov_iterations: usize,
}

impl Work {
    /// Counts a level's outcome; whether it converged.
    pub(super) fn add(&mut self, outcome: &newton::Outcome) -> bool {
        self.newton_steps += outcome.iterations;
        self.krylov_iterations += outcome.krylov_iterations;
        outcome.converged
    }
}

/// GMRES vectors kept before a restart: more than the preconditioned systems need (the
/// feasibility study: 20 iterations to 1e-6 at level 7), so restarts are rare.
const KRYLOV_RESTART: usize = 60;

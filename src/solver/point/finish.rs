//! The Newton-Krylov finish on the top level from its current state, the far field refitted
//! between solves where it is fitted.

use super::cycles::{edge_outputs, outputs_settled};
use super::far_field::{FAR_FIELD_ROUNDS, FAR_FIELD_SETTLED};
use super::multigrid::Hierarchy;
use super::{level, newton, Edge, Params};
use crate::solver::output::{mean_change, Progress, Step};

/// The Newton-Krylov finish on level `k` (the top of the hierarchy) from its current
/// state; each step is reported and its residual appended to `history`.
pub(super) fn finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
) -> newton::NewtonKrylovRun {
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
        outcome = newton::NewtonKrylovRun {
            converged: next.converged,
            iterations: outcome.iterations + next.iterations,
            factorisations: outcome.factorisations + next.factorisations,
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
) -> newton::NewtonKrylovRun {
    let model = mg.model;
    let mut delta = mg.delta;
    let handed = mg.take_factor(k);
    let level = &mut mg.levels[k];
    let number = level.grid.level_number();
    let mut before = level.p.clone();
    let mut steps = 0;
    let (outcome, factor) = newton::iterate(
        level,
        &model,
        &mut delta,
        (&params.newton, &params.stopping),
        if mg.warm {
            newton::warm_first_forcing(number)
        } else {
            newton::FIRST_FORCING
        },
        handed,
        &mut |level: &level::LevelFields, step: &newton::NewtonStep| {
            steps += 1;
            history.push(step.residual);
            observe(&Progress {
                level: level.grid.level_number(),
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
    mg.delta = delta;
    if newton::HANDED_LEVELS.contains(&number) {
        mg.keep_factor(k, factor);
    }
    outcome
}

//! The uniform grid's solve, the loop every strategy runs on each of its grids
//! ([`super::driver`]): the top level converged warm (from a related case's solution) or cold
//! (full multigrid from the Hertzian pressure), then, level by level, its edge settled, the
//! film checked, the outputs' error estimated by the ladder of coarser levels, and a finer
//! level added where the film closes or the estimate misses the accuracy target
//! ([`super::AccuracyParams`]). The nested chain ([`super::chain`]) runs it on each of its
//! domains, the composite grid ([`super::composite`]) on its patch.

use super::cold::Converged;
use super::converge::Tally;
use super::cycles::level_number;
use super::edge::settle_top;
use super::level::LOAD;
use super::multigrid::Hierarchy;
use super::nested::Surround;
use super::tau::{self, TauExtrapolated};
use super::{
    cold, friction, ladder, refine, warm, CoarseSolution, Params, PointSolution, Start, MAX_LEVEL,
    MIN_LEVEL,
};
use crate::physics::case::Problem;
use crate::physics::film::hc_nijenbanning;
use crate::solver::output::{
    Friction, Info, LadderStop, Method, OutputErrors, Progress, SolveError, StartKind,
};
use std::sync::Arc;
use std::time::Instant;

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
pub(super) fn film_collapse(problem: &Problem, level: u32, h_min: f64, tally: Tally) -> SolveError {
    SolveError::FilmCollapse {
        h_min,
        level,
        level_needed: Some(level_to_resolve(problem, level, h_min)),
        finest_level: MAX_LEVEL,
        cycle: tally.cycles,
        residual_history: tally.history,
    }
}

/// `observer` as a closure that hears every step, or none where there is no observer.
pub(super) fn observing<'a>(
    mut observer: Option<&'a mut dyn FnMut(&Progress)>,
) -> impl FnMut(&Progress) + 'a {
    move |p| {
        if let Some(o) = observer.as_mut() {
            o(p)
        }
    }
}

/// Solves `problem` on one grid (inside `surround`, where given) from `warm_start` where it
/// fits and converges, else cold; then settles, checks, estimates and refines (the module's
/// documentation).
pub(super) fn solve(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    warm_start: Option<&Start>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let start = Instant::now();
    SolveError::check_level(params.level, MIN_LEVEL..=MAX_LEVEL)?;
    if params.multigrid.coarsest_level < 2 || params.multigrid.gamma == 0 {
        return Err(SolveError::InvalidParams(format!(
            "coarsest level {} must be at least 2, gamma {} positive",
            params.multigrid.coarsest_level, params.multigrid.gamma
        )));
    }
    let params = &{
        let mut clamped = params.clone();
        clamped.multigrid.coarsest_level = params.multigrid.coarsest_level.min(params.level);
        clamped
    };
    let g = &problem.groups;
    let mut observe = observing(observer);
    // A warm start that fits converges on its own level (a base refined to a finer level
    // takes the member there, with the refinements it has left); where it fails, the cold
    // solve from the Hertzian pressure, its attempt kept in the history.
    let warm_params = warm_start
        .filter(|s| s.fits(params))
        .map(|s| (s, warm::params_at(params, s.level)));
    let mut tried = Vec::new();
    let warm_run = warm_params
        .as_ref()
        .and_then(|(s, p)| warm::converge(problem, (p, surround), s, &mut observe, &mut tried));
    let (params, mut mg, run) = match (warm_run, &warm_params) {
        (Some((mg, run)), Some((_, p))) => (p, mg, run),
        _ => {
            let (mg, mut run) = cold::converge(problem, (params, surround), &mut observe, tried)?;
            if warm_params.is_some() {
                run.start = StartKind::Fallback;
            }
            (params, mg, run)
        }
    };
    let Converged {
        mut tally,
        mut method,
        start: start_kind,
        coarser: run_coarser,
    } = run;
    // Whether a round of the edge needed Newton-Krylov: reported, while the refinement
    // below goes by how the level converged in the first place.
    let mut newton_used = false;

    // Each level, once converged, has its edge settled ([`edge::settle_edge`]). A film that closes
    // somewhere (the side lobes of the most heavily loaded contacts, M above ~5000, where the
    // film is a thousandth of the Hertzian approach and the grid's error in the deformation
    // at the contact edge exceeds it), or outputs whose estimated discretisation error misses
    // the accuracy target ([`AccuracyParams::target`]), then ask for a finer grid ([`refine`]),
    // within [`AccuracyParams::refinement_levels`]. The refined level's ladder starts from the
    // levels below as they converged.
    let mut refinements = 0;
    let (mut warm_coarser, outside_at_base) = match (start_kind, warm_start) {
        // The coarser levels start from the base's where the member started from it, and
        // stop where the base's did outside the asymptotic range; else they start from the
        // full-multigrid states of the cold solve.
        (StartKind::Warm, Some(s)) => (s.coarser.clone(), s.outside),
        _ => (run_coarser, None),
    };
    let (film, outputs) = loop {
        settle_top(
            &mut mg,
            params,
            (method, &mut newton_used),
            &mut tally,
            &mut observe,
        )?;
        let may_refine = refinements < params.accuracy.refinement_levels
            && level_number(mg.finest()) < MAX_LEVEL;
        let film = friction::film(mg.finest(), g.moes_film_scale);
        if params.accuracy.require_positive_film && film.h_min <= 0.0 {
            if !may_refine {
                let level = level_number(mg.finest());
                return Err(film_collapse(problem, level, film.h_min, tally));
            }
        } else {
            // The ladder converges its levels the way the top one finally converged.
            let used = if newton_used {
                Method::NewtonKrylov
            } else {
                method
            };
            let warm = (warm_coarser.as_slice(), outside_at_base);
            let outputs =
                top_outputs(&mut mg, problem, params, (used, warm), &tally, &mut observe)?;
            // Only a level its cycles converged: a refined level's Newton-Krylov finish costs
            // 4-5 s a step at level 8 and converges linearly there (docs/SOLVER.md).
            let missed = match (&params.accuracy.target, &outputs.errors) {
                (Some(target), Some(e)) => method == Method::Cycles && !target.met_by(e, g.m),
                _ => false,
            };
            if !(missed && may_refine) {
                break (film, outputs);
            }
            // The refined level's ladder starts from this level and the ones below it.
            let top = mg.levels.len() - 1;
            let finest = CoarseSolution::converged(&mut mg, top);
            warm_coarser = std::iter::once(finest).chain(outputs.coarser).collect();
        }
        refinements += 1;
        method = refine::refine(&mut mg, params, method, &mut tally, &mut observe)?;
    };
    let TopOutputs {
        friction,
        tau,
        errors,
        coarser,
    } = outputs;
    if newton_used {
        method = Method::NewtonKrylov;
    }
    let fine = mg.finest();
    let load_error = (fine.load_defect() / LOAD).abs();
    let (grid, p, h, delta) = (fine.grid, fine.p.clone(), fine.h.clone(), mg.delta);
    let level = level_number(fine);
    Ok(PointSolution {
        grid,
        p,
        h,
        delta,
        film,
        friction,
        friction_region: params.friction.region,
        info: Info {
            level,
            method,
            cycles: tally.cycles,
            newton_steps: tally.work.newton_steps,
            krylov_iterations: tally.work.krylov_iterations,
            residual_history: tally.history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
            start: start_kind,
        },
        errors,
        coarser,
        surroundings: None,
        patch: None,
        tau,
    })
}

/// The converged top level's friction, tau-extrapolated outputs and discretisation error.
struct TopOutputs {
    friction: Friction,
    tau: Option<TauExtrapolated>,
    errors: Option<OutputErrors>,
    /// The coarser levels' solutions behind `errors` ([`ladder`]).
    coarser: Vec<CoarseSolution>,
}

/// The outputs of `mg`'s converged top level: its friction, the tau-extrapolated outputs
/// (before the ladder, which makes the coarser levels tops of their own) and the error
/// estimate by the ladder, whose levels converge as `used` says from the `warm` starts.
fn top_outputs(
    mg: &mut Hierarchy,
    problem: &Problem,
    params: &Params,
    (used, warm): (Method, (&[CoarseSolution], Option<LadderStop>)),
    tally: &Tally,
    observe: &mut dyn FnMut(&Progress),
) -> Result<TopOutputs, SolveError> {
    let friction = friction::friction(
        mg.finest(),
        &mg.model,
        mg.rolling_scale,
        params.friction.region,
    );
    if !friction.sliding.is_finite() || !friction.total().is_finite() {
        return Err(SolveError::NonFinite {
            what: "friction",
            cycle: tally.cycles,
            residual_history: tally.history.clone(),
        });
    }
    let scale = problem.groups.moes_film_scale;
    let tau = params
        .accuracy
        .tau_extrapolation
        .then(|| tau::extrapolated_outputs(mg, params, scale));
    let (errors, coarser) = if params.accuracy.error_levels > 0 {
        let (e, c) = ladder::output_errors(mg, params, used, warm, observe);
        (Some(e), c)
    } else {
        (None, Vec::new())
    };
    Ok(TopOutputs {
        friction,
        tau,
        errors,
        coarser,
    })
}

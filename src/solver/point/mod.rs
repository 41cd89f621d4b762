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
mod cycles;
mod edge;
mod far_field;
mod finish;
mod friction;
mod jacobian;
mod ladder;
mod level;
mod multigrid;
pub mod nested;
mod newton;
mod params;
mod refine;
mod relax;
mod stopping;
mod transfer;
mod warm;

use crate::physics::case::Problem;
use crate::physics::film::{hc_eq10, hc_nijenbanning};
use crate::solver::grid::Grid;
use crate::solver::output::{
    Film, Friction, Info, Method, OutputErrors, Progress, SolveError, StartKind,
};
use cycles::{converge_by_cycles, cycle_progress, level_number, StallWindows, State};
use edge::settle_top;
use far_field::FarField;
use finish::{finish, grid_sequence, Work};
pub use friction::{mean_shear_stress, FrictionRegion, LOADED_FILM_FACTOR};
pub use ladder::CoarseSolution;
use level::Model;
/// The applied load in `P` and `X, Y` units, `2 pi / 3` (Eq. 7).
pub(crate) use level::LOAD;
use multigrid::Hierarchy;
use nested::Surround;
pub use params::{Edge, Params};
pub use refine::AccuracyTarget;
use std::sync::Arc;
use std::time::Instant;
use stopping::Known;
pub use warm::Start;

/// Revision of the point-contact numerics: part of every cache key, bumped whenever a change
/// can move a result.
pub const SOLVER_REVISION: &str = "point-21";

/// Highest level the solver accepts (1024 x 1024: 8.4 M nodes of working arrays).
pub const MAX_LEVEL: u32 = 9;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// Most refits of a fitted far field ([`Edge::FittedFarField`]) per level, each followed by
/// the cycles or a Newton-Krylov solve with the new edge.
const FAR_FIELD_ROUNDS: usize = 8;
/// A fitted far field counts as settled when its fit moves the amplitude by less than this,
/// relative ...
const FAR_FIELD_SETTLED: f64 = 1e-4;

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
    /// The region the friction was integrated over ([`Params::friction_region`]).
    pub friction_region: FrictionRegion,
    /// Convergence information.
    pub info: Info,
    /// The outputs' discretisation error ([`Params::error_levels`]; `None` where it is 0).
    pub errors: Option<OutputErrors>,
    /// The coarser levels' solutions behind `errors`, finest first: a member's ladder starts
    /// from them ([`Start::coarser`]).
    pub coarser: Vec<CoarseSolution>,
    /// The case-sized domain's solution around a chain of nested domains ([`chain`]), whose
    /// innermost grid this is; a related case starts from it.
    pub surroundings: Option<Box<PointSolution>>,
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

/// The best residual of stalled finest-level cycles below which the Newton-Krylov finish
/// starts on the finest level from their best state rather than from a coarse level: the
/// most heavily loaded Table 2 cases creep at ~0.97 per cycle below 1e-4 (mineral oil A,
/// 60 C, 3 GPa, 2 m/s at level 8), while the cycles of the very viscous cases stall at
/// 1e-2 or diverge.
const DIRECT_FINISH_RESIDUAL: f64 = 1e-3;

/// The cold solve's convergence on the top level: full multigrid from the Hertzian
/// pressure, the finest level's cycles, and where they stall the Newton-Krylov finish
/// (directly, or grid-sequenced); `history` holds what came before (a failed warm start).
fn converge_cold(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    observe: &mut dyn FnMut(&Progress),
    mut history: Vec<f64>,
) -> Result<(Hierarchy, Converged), SolveError> {
    let g = &problem.groups;
    // Initial Delta: the Eq. (10) central film minus the Hertzian approach (W(0) = 1).
    // A nested domain starts from its surroundings: their pressure and film constant.
    let h0 = surround
        .as_ref()
        .map_or(hc_eq10(g.m, g.l) / g.moes_film_scale - 1.0, |s| s.delta());
    let mut mg = hierarchy(problem, params, surround, h0);
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
        let cycles = if k == 0 { 1 } else { params.fmg_cycles };
        for cycle in 1..=cycles {
            let before = mg.levels[k].p.clone();
            mg.cycle(k);
            observe(&cycle_progress(&mut mg, k, cycle, &before));
        }
        starts.push(State::of(&mg, k));
        fmg.push(CoarseSolution {
            level: level_number(&mg.levels[k]),
            p: mg.levels[k].p.clone(),
            delta: mg.h0,
            residual: None,
        });
    }
    mg.make_top(top);
    if top > 0 {
        mg.interpolate(top);
    }
    let windows = StallWindows {
        stall: params.stall_cycles,
        early: params.early_stall_cycles,
    };
    let finest = converge_by_cycles(&mut mg, top, params, windows, &Known::default(), observe);
    let cycles = finest.history.len();
    history.extend(&finest.history);
    let mut method = Method::Cycles;
    let mut work = Work::default();
    let mut converged = finest.converged;
    if !converged && params.newton_steps == 0 {
        if let Some(cycle) = finest.non_finite {
            return Err(SolveError::NonFinite {
                what: "pressure or residual",
                cycle,
                residual_history: history,
            });
        }
    }
    if !converged && params.newton_steps > 0 {
        method = Method::NewtonKrylov;
        // Cycles that crept close to the solution (a heavily loaded case converging too
        // slowly) hand their best state to Newton on the finest level; otherwise, or where
        // that fails, the grid sequence.
        if finest.best_residual < DIRECT_FINISH_RESIDUAL {
            finest.best.restore(&mut mg, top);
            converged = work.add(&finish(&mut mg, top, params, observe, &mut history));
        }
        if !converged {
            starts.push(finest.best);
            converged = grid_sequence(&mut mg, &starts, params, observe, &mut history, &mut work);
        }
    }
    if !converged {
        return Err(SolveError::NotConverged {
            cycles,
            tolerance: params.tolerance,
            residual_history: history,
        });
    }
    Ok((
        mg,
        Converged {
            cycles,
            history,
            method,
            work,
            start: StartKind::Cold,
            coarser: fmg,
        },
    ))
}

/// Solves `problem` with `params` from the Hertzian pressure (full multigrid); `observer` (if
/// any) hears of every cycle and Newton step.
pub fn solve(
    problem: &Problem,
    params: &Params,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    solve_any(problem, params, None, observer)
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
    solve_any(problem, params, Some(start), observer)
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
    solve_with(problem, (params, Some(surround)), None, observer)
}

/// [`solve`] and [`solve_from`]: on the chain of nested domains where the parameters ask
/// for it and the domain has rectangles ([`Params::nested`]), else on the one domain.
fn solve_any(
    problem: &Problem,
    params: &Params,
    start: Option<&Start>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    if params.nested && !chain::rectangles(&params.domain).is_empty() {
        return chain::solve_point(problem, params, start, observer);
    }
    solve_with(problem, (params, None), start, observer)
}

/// What converged the top level: its cycles, history, method and Newton work.
struct Converged {
    cycles: usize,
    history: Vec<f64>,
    method: Method,
    work: Work,
    start: StartKind,
    /// Starts of the coarser levels' solves for the error estimate ([`ladder`]).
    coarser: Vec<CoarseSolution>,
}

/// A hierarchy for `problem` on `params`' levels and domain, the far field of its edge (or
/// the surroundings `surround` of a nested domain), and the film constant `h0`.
fn hierarchy(
    problem: &Problem,
    params: &Params,
    surround: Option<&Arc<Surround>>,
    h0: f64,
) -> Hierarchy {
    let model = Model::new(problem);
    let g = &problem.groups;
    // Without the far field: its lambda-0 form, zero everywhere.
    let far_lambda = if params.edge == Edge::Zero {
        0.0
    } else {
        g.lambda
    };
    let far = FarField::new(problem.shape, g.kappa, far_lambda, problem.viscosity)
        .with_surround(surround.cloned());
    let mut mg = Hierarchy::new(model, far, &params.domain, params, h0);
    mg.rolling_scale = params.rolling_friction.then(|| g.rolling_stress_scale());
    mg
}

fn solve_with(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    warm_start: Option<&Start>,
    mut observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let start = Instant::now();
    if !(MIN_LEVEL..=MAX_LEVEL).contains(&params.level) {
        return Err(SolveError::InvalidParams(format!(
            "level {} outside {MIN_LEVEL}..={MAX_LEVEL}",
            params.level
        )));
    }
    if params.coarsest_level < 2 || params.gamma == 0 {
        return Err(SolveError::InvalidParams(format!(
            "coarsest level {} must be at least 2, gamma {} positive",
            params.coarsest_level, params.gamma
        )));
    }
    let params = &Params {
        coarsest_level: params.coarsest_level.min(params.level),
        ..params.clone()
    };
    let g = &problem.groups;
    let mut observe = |p: &Progress| {
        if let Some(obs) = observer.as_mut() {
            obs(p)
        }
    };
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
            let (mg, mut run) = converge_cold(problem, (params, surround), &mut observe, tried)?;
            if warm_params.is_some() {
                run.start = StartKind::Fallback;
            }
            (params, mg, run)
        }
    };
    let Converged {
        mut cycles,
        mut history,
        mut method,
        mut work,
        start: start_kind,
        coarser: run_coarser,
    } = run;
    // Whether a round of the edge needed Newton-Krylov: reported, while the refinement
    // below goes by how the level converged in the first place.
    let mut newton_used = false;

    // Each level, once converged, has its edge settled ([`settle_edge`]). A film that closes
    // somewhere (the side lobes of the most heavily loaded contacts, M above ~5000, where the
    // film is a thousandth of the Hertzian approach and the grid's error in the deformation
    // at the contact edge exceeds it), or outputs whose estimated discretisation error misses
    // the accuracy target ([`Params::accuracy`]), then ask for a finer grid ([`refine`]),
    // within [`Params::refinement_levels`]. The refined level's ladder starts from the
    // levels below as they converged.
    let mut refinements = 0;
    let mut warm_coarser: Vec<CoarseSolution> = match (start_kind, warm_start) {
        // The coarser levels start from the base's where the member started from it, else
        // from the full-multigrid states of the cold solve.
        (StartKind::Warm, Some(s)) => s.coarser.clone(),
        _ => run_coarser,
    };
    let (film, friction, errors, coarser) = loop {
        settle_top(
            &mut mg,
            params,
            (method, &mut newton_used),
            (&mut cycles, &mut history, &mut work),
            &mut observe,
        )?;
        let may_refine =
            refinements < params.refinement_levels && level_number(mg.finest()) < MAX_LEVEL;
        let film = friction::film(mg.finest(), g.moes_film_scale);
        let closed = film.h_min <= 0.0;
        if !(params.require_positive_film && closed && may_refine) {
            let fine = mg.finest();
            if params.require_positive_film && closed {
                let level = level_number(fine);
                return Err(SolveError::FilmCollapse {
                    h_min: film.h_min,
                    level,
                    level_needed: Some(level_to_resolve(problem, level, film.h_min)),
                    finest_level: MAX_LEVEL,
                    cycle: cycles,
                    residual_history: history,
                });
            }
            let friction =
                friction::friction(fine, &mg.model, mg.rolling_scale, params.friction_region);
            if !friction.sliding.is_finite() || !friction.total().is_finite() {
                return Err(SolveError::NonFinite {
                    what: "friction",
                    cycle: cycles,
                    residual_history: history,
                });
            }
            // The ladder converges its levels the way the top one finally converged.
            let used = if newton_used {
                Method::NewtonKrylov
            } else {
                method
            };
            let (errors, coarser) = if params.error_levels > 0 {
                let (e, c) =
                    ladder::output_errors(&mut mg, params, used, &warm_coarser, &mut observe);
                (Some(e), c)
            } else {
                (None, Vec::new())
            };
            // Only a level its cycles converged: a refined level's Newton-Krylov finish costs
            // 4-5 s a step at level 8 and converges linearly there (docs/SOLVER.md).
            let missed = match (&params.accuracy, &errors) {
                (Some(target), Some(e)) => method == Method::Cycles && !target.met_by(e, g.m),
                _ => false,
            };
            if !(missed && may_refine) {
                break (film, friction, errors, coarser);
            }
            // The refined level's ladder starts from this level and the ones below it.
            let top = mg.levels.len() - 1;
            let finest = CoarseSolution {
                level: level_number(&mg.levels[top]),
                p: mg.levels[top].p.clone(),
                delta: mg.h0,
                residual: Some(mg.residual_norm(top).0),
            };
            warm_coarser = std::iter::once(finest).chain(coarser).collect();
        }
        refinements += 1;
        let tally = refine::Tally {
            cycles: &mut cycles,
            history: &mut history,
            work: &mut work,
        };
        method = refine::refine(&mut mg, params, method, tally, &mut observe)?;
    };
    if newton_used {
        method = Method::NewtonKrylov;
    }
    let fine = mg.finest();
    let load_error = (fine.load_defect() / LOAD).abs();
    let (grid, p, h, delta) = (fine.grid, fine.p.clone(), fine.h.clone(), mg.h0);
    let level = level_number(fine);
    Ok(PointSolution {
        grid,
        p,
        h,
        delta,
        film,
        friction,
        friction_region: params.friction_region,
        info: Info {
            level,
            method,
            cycles,
            newton_steps: work.newton_steps,
            krylov_iterations: work.krylov_iterations,
            residual_history: history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
            start: start_kind,
        },
        errors,
        coarser,
        surroundings: None,
    })
}

#[cfg(test)]
mod tests {
    use super::StallWindows;

    const WINDOWS: StallWindows = StallWindows {
        stall: 15,
        early: 6,
    };

    #[test]
    fn cycles_that_never_get_going_stall_at_the_early_cycle() {
        // The first finest-level cycles of the 5P4E case (60 C, 3 GPa, 12 m/s, level 7): no
        // cycle halves the first residual, nor the first pressure change (0.53 at best).
        let residuals = [2.573e-2, 2.023e-2, 1.893e-2, 1.807e-2, 1.883e-2, 2.708e-2];
        let changes = [1.483e-3, 1.038e-3, 9.278e-4, 7.883e-4, 9.454e-4, 1.108e-3];
        assert!(!WINDOWS.stalled(&residuals[..5], &changes[..5]));
        assert!(WINDOWS.stalled(&residuals, &changes));
        // Off: they run on.
        let off = StallWindows {
            early: 0,
            ..WINDOWS
        };
        assert!(!off.stalled(&residuals, &changes));
    }

    #[test]
    fn cycles_that_halve_either_measure_early_run_on() {
        // The heaviest converging case (mineral oil A, 60 C, 3 GPa, 2 m/s, level 7) halves
        // its residual at the third cycle; one measure that halves is enough.
        let residuals = [3.723e-2, 2.542e-2, 1.561e-2, 9.010e-3, 5.060e-3, 2.817e-3];
        let flat = [1.0; 6];
        assert!(!WINDOWS.stalled(&residuals, &flat));
        assert!(!WINDOWS.stalled(&flat, &residuals));
        // The early rule looks at the early cycle only, not at later ones.
        let mut long = vec![1.0; 10];
        long[2] = 0.4;
        assert!(!WINDOWS.stalled(&long, &long));
    }

    #[test]
    fn cycles_that_stop_converging_stall_after_the_window() {
        // Halving for five cycles, then fifteen without a new half: stalled.
        let mut residuals: Vec<f64> = (0..5).map(|i| 0.5f64.powi(i + 1)).collect();
        residuals.extend(std::iter::repeat_n(0.03, 15));
        assert!(WINDOWS.stalled(&residuals, &residuals));
        assert!(!WINDOWS.stalled(&residuals[..19], &residuals[..19]));
    }
}

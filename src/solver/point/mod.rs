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
//! ([`Domain::default`]); level `n` has `2^(n+1)` intervals per direction.

mod friction;
mod level;
mod multigrid;
mod newton;
mod relax;
mod transfer;

use crate::physics::case::Problem;
use crate::physics::film::hc_eq10;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{Film, Friction, Info, SolveError};
use level::{Model, LOAD};
use multigrid::Hierarchy;
use std::time::Instant;

/// Revision of the point-contact numerics: part of every cache key, bumped whenever a change
/// can move a result.
pub const SOLVER_REVISION: &str = "point-2";

/// Highest level the solver accepts (1024 x 1024: 8.4 M nodes of working arrays).
pub const MAX_LEVEL: u32 = 9;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// Residual growth over the best cycle that stops the solve as diverged.
const DIVERGENCE_FACTOR: f64 = 1e3;

/// Solver parameters, with the defaults of the paper's working resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// Finest level: `2^(level+1)` intervals per direction. Default 7 (256 x 256).
    pub level: u32,
    /// Coarsest level of the hierarchy (lowered to `level` if above it). Default 4
    /// (32 x 32): at the paper's heaviest loads a 16 x 16 grid no longer represents the smooth
    /// error and the cycles slow down (Table 4 case, level 7: 33 V-cycles from level 3, 20
    /// from level 4).
    pub coarsest_level: u32,
    /// Computational domain.
    pub domain: Domain,
    /// Relaxations before coarsening. Default 2.
    pub pre_sweeps: usize,
    /// Relaxations after the correction. Default 1.
    pub post_sweeps: usize,
    /// Relaxations on the coarsest grid per visit. Default 100.
    pub coarsest_sweeps: usize,
    /// Force-balance updates of `Delta` per visit of the coarsest grid, evenly among its
    /// sweeps. Default 10.
    pub coarsest_force_updates: usize,
    /// Gain of the force-balance update `Delta += gain * (int P - 2 pi / 3)`. Default 0.1.
    pub force_balance_gain: f64,
    /// Cycle index: 1 for V-cycles, 2 for W-cycles. Default 1.
    pub gamma: usize,
    /// Cycles on each intermediate level of the full-multigrid start. Default 2.
    pub fmg_cycles: usize,
    /// Most cycles on the finest level. Default 80: the Table 4 case converges in about 20,
    /// but the most heavily loaded cases of Table 2 (M ~ 1e4) converge at about 0.85 per
    /// cycle and need 50-70.
    pub max_cycles: usize,
    /// Convergence: the mean absolute Reynolds residual on the finest level. Default 1e-6.
    pub tolerance: f64,
    /// Convergence, alternatively: the mean absolute change of `P` over one finest cycle.
    /// On fine grids the residual can stall at a few nodes of tiny pressure on the
    /// cavitation boundary that flip in and out of it every cycle, with no effect on any
    /// output; the pressure change still measures the iteration error. Default 3e-7, which
    /// leaves the Table 4 film within 1e-4 (level 7) and 2e-5 (level 8) of its converged value.
    pub pressure_tolerance: f64,
    /// Convergence: relative force-balance error. Default 1e-4.
    pub load_tolerance: f64,
    /// Most Newton steps that finish a solve on the finest level when its cycles stall or
    /// run out ([`newton`]); 0 turns the finish off. Default 20: from a stalled cycle
    /// (residual ~5e-2) the 5P4E hard case at level 5 converges in 8.
    pub newton_steps: usize,
    /// Largest Newton system (pressurised nodes + 1) the finish will factorise. Default 8000:
    /// the dense Jacobian takes `8 n^2` bytes (0.5 GB) and ~7 s per factorisation on two
    /// cores, so the finish serves level 5 (~3000 nodes in contact) and light loads at level
    /// 6, not the level-7 sweeps.
    pub newton_max_unknowns: usize,
    /// Cycles without the residual halving after which the cycles are taken as stalled and
    /// the Newton finish starts. Default 15.
    pub stall_cycles: usize,
    /// Compute the rolling (Poiseuille) part of the friction. Default true.
    pub rolling_friction: bool,
    /// Fail with [`SolveError::FilmCollapse`] when the minimum film is not positive. Default
    /// true; Table 4 turns it off at level 5, where the paper itself reports a film an
    /// order of magnitude too thin.
    pub require_positive_film: bool,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            level: 7,
            coarsest_level: 4,
            domain: Domain::default(),
            pre_sweeps: 2,
            post_sweeps: 1,
            coarsest_sweeps: 100,
            coarsest_force_updates: 10,
            force_balance_gain: 0.1,
            gamma: 1,
            fmg_cycles: 2,
            max_cycles: 80,
            tolerance: 1e-6,
            pressure_tolerance: 3e-7,
            load_tolerance: 1e-4,
            newton_steps: 20,
            newton_max_unknowns: 8000,
            stall_cycles: 15,
            rolling_friction: true,
            require_positive_film: true,
        }
    }
}

impl Params {
    /// Default parameters at `level`.
    pub fn at_level(level: u32) -> Self {
        Params {
            level,
            ..Params::default()
        }
    }
}

/// What the observer is told after each cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// Level the cycle ran on.
    pub level: u32,
    /// Cycle number on that level (from 1).
    pub cycle: usize,
    /// Mean absolute residual after the cycle.
    pub residual: f64,
    /// Relative force-balance error after the cycle.
    pub load_error: f64,
    /// Mean absolute change of `P` over the cycle.
    pub pressure_change: f64,
    /// Central film `H` after the cycle.
    pub h_central: f64,
    /// `(X, Y)` of the largest residual.
    pub worst_at: (f64, f64),
    /// Whether this was a step of the Newton finish (its `cycle` counts on from the
    /// cycles').
    pub newton: bool,
}

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
    /// Convergence information.
    pub info: Info,
}

/// Whether the last `window` cycles brought a convergence measure (the residual, or the
/// pressure change) no lower than half its best value before them: the cycles no longer
/// converge (a slowly converging heavy case still halves both every four or five cycles).
fn stalled(history: &[f64], window: usize) -> bool {
    if window == 0 || history.len() <= window {
        return false;
    }
    let (before, recent) = history.split_at(history.len() - window);
    let best = |v: &[f64]| v.iter().cloned().fold(f64::INFINITY, f64::min);
    best(recent) > 0.5 * best(before)
}

/// Mean absolute difference of two pressure fields.
fn mean_change(p: &[f64], before: &[f64]) -> f64 {
    p.iter()
        .zip(before)
        .map(|(a, b)| (a - b).abs())
        .sum::<f64>()
        / p.len() as f64
}

/// Whether the Newton finish would take `level` on: it is enabled and the pressurised nodes
/// fit its system.
fn newton_fits(level: &level::Level, params: &Params) -> bool {
    params.newton_steps > 0
        && level.p.iter().filter(|&&p| p > 0.0).count() < params.newton_max_unknowns
}

/// Solves `problem` with `params`; `observer` (if any) hears of every cycle and Newton step.
pub fn solve(
    problem: &Problem,
    params: &Params,
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
    let model = Model::new(problem);
    let g = &problem.groups;
    // Initial Delta: the Eq. (10) central film minus the Hertzian approach (W(0) = 1).
    let h0 = hc_eq10(g.m, g.l) / g.moes_film_scale - 1.0;
    let mut mg = Hierarchy::new(model, &params.domain, params, h0);
    let top = mg.levels.len() - 1;

    // Full multigrid: Hertzian pressure on the coarsest grid, then each finer level starts
    // from the interpolated solution of the one below.
    {
        let l0 = &mut mg.levels[0];
        let grid = l0.grid;
        l0.p = grid.sample(crate::physics::hertz::Hertz::pressure);
    }
    let mut history = Vec::new();
    // The mean pressure change of each finest cycle: the other measure of convergence.
    let mut changes = Vec::new();
    let mut converged = false;
    for k in 0..=top {
        mg.make_top(k);
        if k > 0 {
            mg.interpolate(k);
        }
        // The coarsest level alone is solved once (its "cycle" is a full solve) unless it is
        // the only level.
        let cycles = match (k == top, k == 0) {
            (true, _) => params.max_cycles,
            (false, true) => 1,
            (false, false) => params.fmg_cycles,
        };
        for cycle in 1..=cycles {
            let before = mg.levels[k].p.clone();
            mg.cycle(k);
            let (residual, worst_at) = mg.residual_norm(k);
            let level = &mg.levels[k];
            let load_error = (level.load_defect() / LOAD).abs();
            let dp = mean_change(&level.p, &before);
            if let Some(obs) = observer.as_mut() {
                obs(&Progress {
                    level: params.coarsest_level + k as u32,
                    cycle,
                    residual,
                    load_error,
                    pressure_change: dp,
                    h_central: level.h_central(),
                    worst_at,
                    newton: false,
                });
            }
            if k < top {
                continue;
            }
            history.push(residual);
            if !residual.is_finite() || !mg.h0.is_finite() || level.p.iter().any(|v| !v.is_finite())
            {
                return Err(SolveError::NonFinite {
                    what: "pressure or residual",
                    cycle,
                    residual_history: history,
                });
            }
            // A residual a thousand times above the best one seen is divergence, not noise.
            let best = history.iter().cloned().fold(f64::INFINITY, f64::min);
            changes.push(dp);
            // A stall ends the cycles only where the Newton finish can take over; elsewhere
            // they run on (some cases converge after a long noisy stretch).
            let stall = stalled(&history, params.stall_cycles)
                && stalled(&changes, params.stall_cycles)
                && newton_fits(level, params);
            if residual > DIVERGENCE_FACTOR * best || stall {
                break;
            }
            if (residual < params.tolerance || dp < params.pressure_tolerance)
                && load_error < params.load_tolerance
            {
                converged = true;
                break;
            }
        }
    }
    // The cycles stalled or ran out: finish on the finest level by Newton when its system
    // is small enough.
    let cycles = history.len();
    let mut newton_steps = 0;
    if !converged && params.newton_steps > 0 {
        let model = mg.model;
        let mut h0 = mg.h0;
        let fine = mg.levels.last_mut().expect("a hierarchy has a level");
        let mut before = fine.p.clone();
        let outcome = newton::iterate(
            fine,
            &model,
            &mut h0,
            &newton::Limits {
                steps: params.newton_steps,
                unknowns: params.newton_max_unknowns,
                tolerance: params.tolerance,
                load_tolerance: params.load_tolerance,
            },
            &mut |level: &level::Level, step: &newton::Step| {
                history.push(step.residual);
                if let Some(obs) = observer.as_mut() {
                    obs(&Progress {
                        level: params.level,
                        cycle: history.len(),
                        residual: step.residual,
                        load_error: step.load_error,
                        pressure_change: mean_change(&level.p, &before),
                        h_central: level.h_central(),
                        worst_at: step.worst_at,
                        newton: true,
                    });
                }
                before.copy_from_slice(&level.p);
            },
        );
        mg.h0 = h0;
        newton_steps = outcome.iterations;
        converged = outcome.converged;
    }
    let fine = mg.finest();
    let load_error = (fine.load_defect() / LOAD).abs();
    if !converged {
        return Err(SolveError::NotConverged {
            cycles,
            tolerance: params.tolerance,
            residual_history: history,
        });
    }
    let film = friction::film(fine, g.moes_film_scale);
    if params.require_positive_film && film.h_min <= 0.0 {
        return Err(SolveError::FilmCollapse {
            h_min: film.h_min,
            cycle: cycles,
            residual_history: history,
        });
    }
    let rolling = params.rolling_friction.then(|| g.rolling_stress_scale());
    let friction = friction::friction(fine, &mg.model, rolling);
    if !friction.sliding.is_finite() || !friction.total().is_finite() {
        return Err(SolveError::NonFinite {
            what: "friction",
            cycle: cycles,
            residual_history: history,
        });
    }
    Ok(PointSolution {
        grid: fine.grid,
        p: fine.p.clone(),
        h: fine.h.clone(),
        delta: mg.h0,
        film,
        friction,
        info: Info {
            cycles,
            newton_steps,
            residual_history: history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
        },
    })
}

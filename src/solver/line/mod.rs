//! The isothermal line contact with Eyring rheology (Fig. 7 of the paper), solved by
//! full-approximation-scheme multigrid with a full-multigrid start from the Hertzian pressure,
//! as Venner and Lubrecht ("Multilevel Methods in Lubrication", 2000) solve the line contact:
//!
//! - dimensionless `X = x/a`, `P = p/p_H`, `H = h Rx / a^2`
//!   ([`crate::physics::line_contact`]);
//! - Reynolds `d/dX (eps dP/dX) - d(rho H)/dX = 0`, `eps = rho H^3 / (eta_eff lambda)`, with
//!   second-order central Poiseuille terms and a second-order upstream wedge term; `P = 0` at
//!   both ends; cavitation by `P = max(P, 0)`;
//! - the Eyring flow in its exact 1-D form by default (effective viscosity
//!   `eta / (cosh(tau_m) F(G))`, `sinh(tau_m) = x G / sinh G`,
//!   [`crate::physics::line_contact::LineEyringFlow::Exact`]), or the perturbation form of the
//!   point contact ([`crate::physics::line_contact::LineEyringFlow::Perturbation`]), selected
//!   on the problem. The exact form is the default because in one dimension it costs nothing
//!   more and removes the perturbation assumption; the two differ little where it matters for
//!   friction (see the test `exact_and_perturbation_eyring_differ_little`: on the heavy
//!   Table 3 case the sliding `mu-bar` moves by a fraction of a per cent);
//! - film `H = H0 + X^2/2 - (1/pi) int P ln|X - X'| dX'`, the pressure piecewise constant on
//!   the cells, evaluated exactly on each grid (direct sum or zero-padded FFT, [`kernel`]);
//! - relaxation switching between Gauss-Seidel and Jacobi distributive on `eps/h^2`, all
//!   nodes' changes solved together in a band ([`relax`]);
//! - force balance `int P dX = pi/2` relaxed on the coarsest grid through `H0`.
//!
//! Why multigrid rather than Newton: a damped Newton method with the dense elastic Jacobian is
//! robust but costs `O(n^3)` per step, which rules out the level-12 grid (8193 nodes) the grid
//! convergence study needs; FAS multigrid costs `O(n log n)` per cycle here and is the method
//! the paper's authors use. The hard cases the tests solve (the 3 GPa Table 3 case with
//! Roelands, Dowson-Higginson and Eyring) converge in a few tens of V-cycles.
//!
//! The domain defaults to `-4.5 <= X <= 1.5` ([`LineDomain::default`]); level `n` has
//! `2^(n+1)` intervals, so `X = 0` is a node of every level.

mod friction;
mod kernel;
mod level;
mod multigrid;
mod relax;
mod transfer;

use crate::physics::line_contact::{LineFilmFormula, LineProblem};
use crate::solver::output::{Film, Friction, Info, SolveError};
use level::{Model, LOAD};
use multigrid::Hierarchy;
use std::time::Instant;

/// Highest level the solver accepts (32768 intervals).
pub const MAX_LEVEL: u32 = 14;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// Residual growth over the best cycle that stops the solve as diverged.
const DIVERGENCE_FACTOR: f64 = 1e3;
/// `1/4 + ln(2)/2`: the deformation plus `X^2/2` of the dry Hertzian pressure, flat inside
/// the contact (so that `H(0) = H0 + 0.5966` for the Hertzian start).
const HERTZ_APPROACH: f64 = 0.25 + 0.5 * std::f64::consts::LN_2;

/// The computational domain in `X = x/a`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineDomain {
    /// Inlet boundary.
    pub x_start: f64,
    /// Outlet boundary.
    pub x_end: f64,
}

impl Default for LineDomain {
    /// `-4.5 <= X <= 1.5`: an inlet long enough for fully flooded moderately and heavily
    /// loaded contacts (M >~ 10), an outlet past the cavitation point, and a length of 6 so
    /// that `X = 0` is a node of every level.
    fn default() -> Self {
        LineDomain {
            x_start: -4.5,
            x_end: 1.5,
        }
    }
}

/// Solver parameters with documented defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// Finest level: `2^(level+1)` intervals. Default 10 (2048 intervals, `h = 0.0029`).
    pub level: u32,
    /// Coarsest level of the hierarchy (lowered to `level` if above it). Default 4
    /// (32 intervals).
    pub coarsest_level: u32,
    /// Computational domain.
    pub domain: LineDomain,
    /// Relaxations before coarsening. Default 2.
    pub pre_sweeps: usize,
    /// Relaxations after the correction. Default 1.
    pub post_sweeps: usize,
    /// Relaxations on the coarsest grid per visit. Default 200.
    pub coarsest_sweeps: usize,
    /// Force-balance updates of `H0` per visit of the coarsest grid, evenly among its sweeps.
    /// Default 20.
    pub coarsest_force_updates: usize,
    /// Gain of the force-balance update `H0 += gain * (int P - pi/2)`. Default 0.1.
    pub force_balance_gain: f64,
    /// Cycle index: 1 for V-cycles, 2 for W-cycles. Default 1.
    pub gamma: usize,
    /// Cycles on each intermediate level of the full-multigrid start. Default 2.
    pub fmg_cycles: usize,
    /// Most cycles on the finest level. Default 60.
    pub max_cycles: usize,
    /// Convergence: the mean absolute Reynolds residual on the finest level. Default 1e-8.
    pub tolerance: f64,
    /// Convergence: relative force-balance error. Default 1e-5.
    pub load_tolerance: f64,
    /// Compute the rolling (Poiseuille) part of the friction. Default false (Fig. 7 needs
    /// only the sliding part).
    pub rolling_friction: bool,
    /// Fail with [`SolveError::FilmCollapse`] when the minimum film is not positive.
    /// Default true.
    pub require_positive_film: bool,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            level: 10,
            coarsest_level: 4,
            domain: LineDomain::default(),
            pre_sweeps: 2,
            post_sweeps: 1,
            coarsest_sweeps: 200,
            coarsest_force_updates: 20,
            force_balance_gain: 0.1,
            gamma: 1,
            fmg_cycles: 2,
            max_cycles: 60,
            tolerance: 1e-8,
            load_tolerance: 1e-5,
            rolling_friction: false,
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
    /// Central film `H` after the cycle.
    pub h_central: f64,
}

/// A converged line-contact solution.
#[derive(Debug, Clone)]
pub struct LineSolution {
    /// Node coordinates `X = x/a` of the finest grid.
    pub x: Vec<f64>,
    /// Pressure `P = p/p_H` at the nodes.
    pub p: Vec<f64>,
    /// Film `H = h Rx / a^2` at the nodes.
    pub h: Vec<f64>,
    /// The film constant `H0`.
    pub h0: f64,
    /// Central and minimum film (`H` and Moes units).
    pub film: Film,
    /// Reduced friction `mu-bar = mu p_H / tau0`.
    pub friction: Friction,
    /// Convergence information.
    pub info: Info,
}

/// The starting film constant: the central film of Moes' formula minus the Hertzian
/// deformation at the centre.
fn initial_h0(problem: &LineProblem) -> f64 {
    let g = &problem.groups;
    LineFilmFormula::Moes.hc(g.m, g.l) / g.moes_film_scale - HERTZ_APPROACH
}

/// Solves `problem` with `params`; `observer` (if any) hears of every cycle.
pub fn solve(
    problem: &LineProblem,
    params: &Params,
    mut observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<LineSolution, SolveError> {
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
    let d = params.domain;
    if !(d.x_start < -1.0 && d.x_end > 1.0 && d.x_start.is_finite() && d.x_end.is_finite()) {
        return Err(SolveError::InvalidParams(format!(
            "domain {}..{} must contain the Hertzian contact -1..1",
            d.x_start, d.x_end
        )));
    }
    let params = &Params {
        coarsest_level: params.coarsest_level.min(params.level),
        ..params.clone()
    };
    let model = Model::new(problem);
    let mut mg = Hierarchy::new(model, params, initial_h0(problem));
    let top = mg.levels.len() - 1;

    // Full multigrid: Hertzian pressure on the coarsest grid, then each finer level starts
    // from the interpolated solution of the one below.
    {
        let l0 = &mut mg.levels[0];
        for i in 0..=l0.n {
            l0.p[i] = crate::physics::line_contact::LineHertz::pressure(l0.x(i));
        }
    }
    mg.make_top(0);
    mg.cycle(0);
    let mut history = Vec::new();
    for k in 1..=top {
        mg.make_top(k);
        mg.interpolate(k);
        let cycles = if k == top {
            params.max_cycles
        } else {
            params.fmg_cycles
        };
        for cycle in 1..=cycles {
            mg.cycle(k);
            let residual = mg.residual_norm(k);
            let level = &mg.levels[k];
            let load_error = (level.load_defect() / LOAD).abs();
            if k == top {
                history.push(residual);
            }
            if let Some(obs) = observer.as_mut() {
                obs(&Progress {
                    level: params.coarsest_level + k as u32,
                    cycle,
                    residual,
                    load_error,
                    h_central: friction::film(level, 1.0).h_central,
                });
            }
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
            if k == top && residual > DIVERGENCE_FACTOR * best {
                return Err(SolveError::NotConverged {
                    cycles: cycle,
                    tolerance: params.tolerance,
                    residual_history: history,
                });
            }
            if k == top && residual < params.tolerance && load_error < params.load_tolerance {
                break;
            }
        }
    }
    let fine = mg.finest();
    let load_error = (fine.load_defect() / LOAD).abs();
    let residual = history.last().copied().unwrap_or(f64::INFINITY);
    let cycles = history.len();
    if !(residual < params.tolerance && load_error < params.load_tolerance) {
        return Err(SolveError::NotConverged {
            cycles,
            tolerance: params.tolerance,
            residual_history: history,
        });
    }
    let film = friction::film(fine, problem.groups.moes_film_scale);
    if params.require_positive_film && film.h_min <= 0.0 {
        return Err(SolveError::FilmCollapse {
            h_min: film.h_min,
            cycle: cycles,
            residual_history: history,
        });
    }
    let friction = friction::friction(fine, &mg.model, params.rolling_friction);
    if !friction.sliding.is_finite() || !friction.total().is_finite() {
        return Err(SolveError::NonFinite {
            what: "friction",
            cycle: cycles,
            residual_history: history,
        });
    }
    Ok(LineSolution {
        x: (0..=fine.n).map(|i| fine.x(i)).collect(),
        p: fine.p.clone(),
        h: fine.h.clone(),
        h0: mg.h0,
        film,
        friction,
        info: Info {
            cycles,
            residual_history: history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
        },
    })
}

#[cfg(test)]
mod tests;

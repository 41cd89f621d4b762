//! The isothermal line contact with Eyring rheology (Fig. 7 of the paper; "a separate
//! approach based on the equations presented in Ref. [11]", Conry, Wang and Cusano 1987):
//!
//! - dimensionless `X = x/a`, `P = p/p_H`, `H = h Rx / a^2`
//!   ([`crate::physics::line_contact`]);
//! - Reynolds `d/dX (eps dP/dX) - d(rho H)/dX = 0`, `eps = rho H^3 / (eta_eff lambda)`, with
//!   second-order central Poiseuille terms and a second-order upstream wedge term; `P = 0` at
//!   both ends; cavitation `P >= 0` as a complementarity condition ([`newton`]);
//! - the Eyring flow in its exact 1-D form by default (effective viscosity
//!   `eta / (cosh(tau_m) F(G))`, `sinh(tau_m) = x G / sinh G`,
//!   [`crate::physics::line_contact::LineEyringFlow::Exact`]), or the perturbation form of
//!   Eqs. (2)-(4) that the point contact uses
//!   ([`crate::physics::line_contact::LineEyringFlow::Perturbation`]), selected on the
//!   problem;
//! - film `H = Delta + X^2/2 - (1/pi) int P ln|X - X'| dX'`, the pressure piecewise constant on
//!   the cells, evaluated exactly on each grid (direct sum or zero-padded FFT, [`kernel`]);
//! - force balance `int P dX = pi/2` solved together with Reynolds, `Delta` an unknown.
//!
//! Method: damped semi-smooth Newton with the full (dense) Jacobian on each grid of a nested
//! iteration: the Hertzian pressure on the start level, then each finer level starts from the
//! cubic interpolation of the converged coarser solution. Why not FAS multigrid (which the
//! paper's authors use): a FAS solver with Gauss-Seidel / Jacobi distributive relaxation was
//! written first and stalled or blew up on every heavily loaded case we tried (and on some
//! light Newtonian ones); Newton with the full Jacobian is the method of Houpert and Hamrock
//! (1986), known to be robust up to several GPa. Its price is the dense `O(n^3)` factorisation:
//! level 9 (1024 intervals) costs about a second, so the working level is 8 and level 11 is
//! the finest that tests afford.
//!
//! The domain defaults to `-4.5 <= X <= 1.5` ([`LineDomain::default`]); level `n` has
//! `2^(n+1)` intervals, so `X = 0` is a node of every level.

mod friction;
mod kernel;
mod ladder;
mod level;
mod newton;
mod transfer;

use crate::physics::line_contact::{LineFilmFormula, LineHertz, LineProblem};
use crate::solver::output::{
    mean_change, Film, Friction, Info, LevelValues, Method, OutputErrors, Progress, SolveError,
    Step,
};
use crate::solver::richardson::ERROR_LEVELS;
use level::{LineLevelFields, LineModel, LOAD};
use std::time::Instant;

/// Revision of the line-contact numerics: part of every line-contact cache key, bumped
/// whenever a change can move a result.
pub const SOLVER_REVISION: &str = "line-5";

/// Highest level the solver accepts (8192 intervals: a dense Jacobian of 0.5 GB).
pub const MAX_LEVEL: u32 = 12;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// Residual growth over the best iteration that stops the solve as diverged.
const DIVERGENCE_FACTOR: f64 = 1e3;
/// `1/4 + ln(2)/2`: the deformation plus `X^2/2` of the dry Hertzian pressure, flat inside
/// the contact (so that `H(0) = Delta + 0.5966` for the Hertzian start).
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
    /// Finest level: `2^(level+1)` intervals. Default 8 (512 intervals, `h = 0.0117`).
    pub level: u32,
    /// Level of the nested iteration's Hertzian start (lowered to `level` if above it).
    /// Default 6 (128 intervals).
    pub start_level: u32,
    /// Computational domain.
    pub domain: LineDomain,
    /// Most Newton iterations per level. Default 60.
    pub max_iterations: usize,
    /// Convergence: the mean absolute Reynolds residual on the finest level. Default 1e-9.
    pub tolerance: f64,
    /// Convergence: relative force-balance error. Default 1e-8.
    pub load_tolerance: f64,
    /// Compute the rolling (Poiseuille) part of the friction. Default true.
    pub rolling_friction: bool,
    /// Fail with [`SolveError::FilmCollapse`] when the minimum film is not positive.
    /// Default true.
    pub require_positive_film: bool,
    /// Finer levels the solve may add, one at a time, while its error estimate reads fewer
    /// than three levels inside the asymptotic range ([`ladder`]). The level solved on is
    /// reported in [`Info::level`]. Default 0 (studies of the numerics solve the level they
    /// are given); the rule sets [`RULE_REFINEMENT_LEVELS`].
    pub refinement_levels: u32,
}

/// The rule's [`Params::refinement_levels`]: two, which Fig. 7's line contact 2 needs at
/// level 8 (its levels 6 and 7 are outside the asymptotic range, level 8 is the first of
/// three inside it); a level costs four times the one below (level 10: 2-3 s).
pub const RULE_REFINEMENT_LEVELS: u32 = 2;

impl Default for Params {
    fn default() -> Self {
        Params {
            level: 8,
            start_level: 6,
            domain: LineDomain::default(),
            max_iterations: 60,
            tolerance: 1e-9,
            load_tolerance: 1e-8,
            rolling_friction: true,
            require_positive_film: true,
            refinement_levels: 0,
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

    /// The rule from a line contact to its solver parameters, which every command and
    /// pipeline uses (`repro solve --line`, Fig. 7's line contacts, the accuracy study), as
    /// [`crate::solver::point::Params::for_problem`] is for the elliptical contact. Nothing
    /// depends on the case yet (the domain is [`LineDomain::default`] for all): the defaults
    /// at `level`.
    ///
    /// The nested iteration starts [`ERROR_LEVELS`] below `level` where the default start is
    /// closer: the levels it converges on the way are the error estimate's; where fewer than
    /// three of them are inside the asymptotic range the solve goes on to finer levels, up to
    /// [`RULE_REFINEMENT_LEVELS`] ([`ladder`]).
    pub fn for_problem(_problem: &LineProblem, level: u32) -> Self {
        let defaults = Params::at_level(level);
        Params {
            start_level: defaults
                .start_level
                .min(level.saturating_sub(ERROR_LEVELS))
                .max(MIN_LEVEL),
            refinement_levels: RULE_REFINEMENT_LEVELS,
            ..defaults
        }
    }
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
    /// The film constant `Delta`.
    pub delta: f64,
    /// Central and minimum film (`H` and Moes units).
    pub film: Film,
    /// Reduced friction `mu-bar = mu p_H / tau0`.
    pub friction: Friction,
    /// The mean shear stress `tau_m / tau0` at the nodes (Eq. 8's integrand; 0 where
    /// `P <= 0`: [`friction::mean_shear_stress`]).
    pub tau_m: Vec<f64>,
    /// Convergence information.
    pub info: Info,
    /// The outputs' discretisation error, from the finest level and the two below it, which
    /// the grid sequence converges on the way, where they are inside the asymptotic range
    /// ([`ladder`], [`crate::solver::richardson`]); `None` where the sequence started less
    /// than two levels below.
    pub errors: Option<OutputErrors>,
}

/// The outputs of a converged line-contact level.
fn values(level: &LineLevelFields, model: &LineModel, lv: u32) -> LevelValues {
    let film = friction::film(level, 1.0);
    let mu = friction::friction(level, model, true);
    LevelValues {
        level: lv,
        h_central: film.h_central,
        h_min: film.h_min,
        mu_bar_sliding: mu.sliding,
        mu_bar_total: mu.total(),
    }
}

/// The starting film constant: the central film of Moes' formula minus the Hertzian
/// deformation at the centre.
fn initial_delta(problem: &LineProblem) -> f64 {
    let g = &problem.groups;
    LineFilmFormula::Moes.hc(g.m, g.l) / g.moes_film_scale - HERTZ_APPROACH
}

/// Solves `problem` with `params`; `observer` (if any) hears of every Newton iteration on
/// every level. Failure is a typed [`SolveError`] carrying the finest level's residual
/// history (or the level that failed).
pub fn solve(
    problem: &LineProblem,
    params: &Params,
    mut observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<LineSolution, SolveError> {
    let start = Instant::now();
    SolveError::check_level(params.level, MIN_LEVEL..=MAX_LEVEL)?;
    if params.start_level < MIN_LEVEL || params.max_iterations == 0 {
        return Err(SolveError::InvalidParams(format!(
            "start level {} must be at least {MIN_LEVEL}, max_iterations positive",
            params.start_level
        )));
    }
    let d = params.domain;
    if !(d.x_start < -1.0 && d.x_end > 1.0 && d.x_start.is_finite() && d.x_end.is_finite()) {
        return Err(SolveError::InvalidParams(format!(
            "domain {}..{} must contain the Hertzian contact -1..1",
            d.x_start, d.x_end
        )));
    }
    let model = LineModel::new(problem);
    let first = params.start_level.min(params.level);
    let mut delta = initial_delta(problem);
    let mut level = LineLevelFields::new(1usize << (first + 1), d.x_start, d.x_end);
    for i in 0..=level.n {
        level.p[i] = LineHertz::pressure(level.x(i));
    }
    let mut history: Vec<f64>;
    // Every converged level's outputs, for the error estimate.
    let mut ladder = Vec::new();
    let last = (params.level + params.refinement_levels).min(MAX_LEVEL);
    let mut lv = first;
    let errors = loop {
        if lv > first {
            let mut fine = LineLevelFields::new(1usize << (lv + 1), d.x_start, d.x_end);
            transfer::interpolate_solution(&level, &mut fine);
            level = fine;
        }
        let mut level_history = Vec::new();
        let mut non_finite = false;
        let mut diverged = false;
        let mut before = level.p.clone();
        let mut report = |l: &LineLevelFields, residual: f64, load_error: f64, _h0: f64| -> bool {
            level_history.push(residual);
            if let Some(obs) = observer.as_mut() {
                obs(&Progress {
                    level: lv,
                    count: level_history.len(),
                    step: Step::Newton,
                    residual,
                    load_error,
                    pressure_change: mean_change(&l.p, &before),
                    h_central: friction::film(l, 1.0).h_central,
                    worst_at: (l.x(l.worst_residual_node()), 0.0),
                });
            }
            before.copy_from_slice(&l.p);
            if !residual.is_finite() || l.p.iter().any(|v| !v.is_finite()) {
                non_finite = true;
                return false;
            }
            let best = level_history.iter().cloned().fold(f64::INFINITY, f64::min);
            if residual > DIVERGENCE_FACTOR * best {
                diverged = true;
                return false;
            }
            true
        };
        let outcome = newton::iterate(
            &mut level,
            &model,
            &mut delta,
            params.max_iterations,
            params.tolerance,
            params.load_tolerance,
            &mut report,
        );
        history = level_history;
        if non_finite || !delta.is_finite() {
            return Err(SolveError::NonFinite {
                what: "pressure or residual",
                cycle: outcome.iterations,
                residual_history: history,
            });
        }
        if !outcome.converged || diverged {
            return Err(SolveError::NotConverged {
                cycles: outcome.iterations,
                tolerance: params.tolerance,
                residual_history: history,
            });
        }
        ladder.push(values(&level, &model, lv));
        if lv >= params.level {
            let errors = ladder::errors(&ladder, 0.0);
            if lv == last || ladder::complete(errors.as_ref()) {
                break errors;
            }
        }
        lv += 1;
    };
    let fine = &level;
    let load_error = ((fine.load() - LOAD) / LOAD).abs();
    let cycles = history.len();
    let film = friction::film(fine, problem.groups.moes_film_scale);
    if params.require_positive_film && film.h_min <= 0.0 {
        return Err(SolveError::FilmCollapse {
            h_min: film.h_min,
            level: lv,
            level_needed: None,
            finest_level: MAX_LEVEL,
            cycle: cycles,
            residual_history: history,
        });
    }
    let friction = friction::friction(fine, &model, params.rolling_friction);
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
        delta,
        film,
        friction,
        tau_m: friction::mean_shear_stress(fine, &model),
        info: Info {
            level: lv,
            method: Method::Newton,
            newton_steps: 0,
            krylov_iterations: 0,
            cycles,
            residual_history: history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
            start: crate::solver::output::StartKind::Cold,
        },
        errors,
    })
}

#[cfg(test)]
mod tests;

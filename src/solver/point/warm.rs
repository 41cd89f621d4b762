//! Continuation: a solve that starts from the converged solution of a related case, its base
//! (the same contact at another slip or Eyring stress, or the Eyring twin of a limited
//! case), instead of from the Hertzian pressure.
//!
//! At the small slips of the paper the pressure and the film hardly depend on the slip and
//! the Eyring stress: over Figs. 4-6 the central film of the nine cases of a family spreads
//! by 1e-4 (median; 7e-3 at most). So the finest level starts from the base's pressure and
//! `Delta`, on the base's level (a base the film made refine takes its members there too);
//! by cycles if the base converged by cycles, else by the Newton-Krylov finish directly.
//! Where that fails the solve starts again from the Hertzian pressure
//! ([`StartKind::Fallback`]).
//!
//! Two stopping details make the warm start pay: the start's own outputs are the first entry
//! of the output history (a converged state is a point of the sequence the estimate reads,
//! so two cycles can end the solve instead of five:
//! [`super::stopping::OutputHistory::new`]), and settled outputs are accepted
//! while the residual is at most a few times the base's accepted one even
//! where it no longer falls ([`super::stopping::WarmStop`]: a warm start begins near its fixed point; without it the
//! heaviest members, M 11 070, took a Newton-Krylov detour and were slower than cold).

use super::cold::Converged;
use super::converge::{converge_level, How, Tally};
use super::cycles::from_converged;
use super::multigrid::Hierarchy;
use super::nested::Surround;
use super::stopping::Known;
use super::{Params, MAX_LEVEL};
use crate::physics::case::Problem;
use crate::solver::grid::Grid;
use crate::solver::output::{LadderStop, Method, Progress, StartKind};
use std::sync::Arc;

/// A converged solution that a related case starts from: its finest grid and level, the
/// pressure there, the film constant, how it converged and the residual it was accepted at.
#[derive(Debug, Clone, PartialEq)]
pub struct Start {
    /// The grid of `p`.
    pub grid: Grid,
    /// The level of that grid.
    pub level: u32,
    /// Pressure `P` at the nodes.
    pub p: Vec<f64>,
    /// The film constant `Delta`.
    pub delta: f64,
    /// What converged it.
    pub method: Method,
    /// Its coarser levels' solutions (finest first), where its discretisation error was
    /// estimated: the starts of the member's own.
    pub coarser: Vec<super::CoarseSolution>,
    /// The coarser level its ladder found outside the asymptotic range, where it did: a
    /// member's ladder stops there too ([`super::ladder`]).
    pub outside: Option<LadderStop>,
    /// Its last residual.
    pub residual: f64,
    /// Its final level's last Newton-Krylov factor, where it hands one on
    /// ([`super::PointSolution::factor`]).
    pub factor: Option<super::HandedFactor>,
    /// Its tau-extrapolation's coarse problem, where it was extrapolated: the start of the
    /// member's on the same grid ([`super::tau::CoarseChange`]).
    pub tau: Option<super::CoarseChange>,
    /// The top refined across the rolling direction above `grid`, where the solve added one
    /// ([`super::AccuracyTarget::h_min`]): the start of the member's.
    pub across: Option<AcrossStart>,
}

/// A converged top refined across the rolling direction ([`Start::across`]).
#[derive(Debug, Clone, PartialEq)]
pub struct AcrossStart {
    /// Its grid.
    pub grid: Grid,
    /// Pressure `P` at its nodes.
    pub p: Vec<f64>,
    /// Its film constant.
    pub delta: f64,
    /// Its last residual.
    pub residual: f64,
    /// The level under it refined the same way, as it converged for the estimate
    /// ([`crate::solver::output::AcrossValues::below`]), where it did.
    pub below: Option<super::CoarseSolution>,
}

impl Start {
    /// The start a solution gives: a chain's case-sized domain ([`super::chain`]). A solution
    /// on a top refined across the rolling direction starts a member on the square level
    /// under it (its first coarser solution) and that top from its own.
    pub fn of(s: &super::PointSolution) -> Self {
        let s = s.surroundings.as_deref().unwrap_or(s);
        if let (true, [square, coarser @ ..]) = (s.grid.is_refined_y(), s.coarser.as_slice()) {
            return Start {
                grid: s.grid.unrefined_y(),
                p: square.p.clone(),
                delta: square.delta,
                residual: square.residual.unwrap_or(s.info.residual()),
                coarser: coarser.to_vec(),
                factor: None,
                across: Some(AcrossStart {
                    grid: s.grid,
                    p: s.p.clone(),
                    delta: s.delta,
                    residual: s.info.residual(),
                    below: s.across_rung.clone(),
                }),
                ..Start::of_grid(s)
            };
        }
        Start::of_grid(s)
    }

    /// The start of `s`'s own grid.
    fn of_grid(s: &super::PointSolution) -> Self {
        Start {
            grid: s.grid,
            level: s.info.level,
            p: s.p.clone(),
            delta: s.delta,
            method: s.info.method,
            residual: s.info.residual(),
            coarser: s.coarser.clone(),
            outside: s
                .errors
                .as_ref()
                .and_then(|e| e.stopped)
                .filter(|stop| stop.is_outside()),
            factor: s.factor.clone(),
            tau: s.tau.as_ref().map(|t| t.coarse.clone()),
            across: None,
        }
    }

    /// Whether a solve with `params` can start from it: the same domain, on a level no
    /// coarser than asked.
    pub(super) fn fits(&self, params: &Params) -> bool {
        self.level >= params.level
            && self.level <= MAX_LEVEL
            && Grid::level(&params.domain, self.level) == self.grid
            && self.p.len() == self.grid.len()
            && self.delta.is_finite()
    }
}

/// `params` on `level` (a base refined to a finer level than asked), with the refinements
/// left to it.
pub(super) fn params_at(params: &Params, level: u32) -> Params {
    let mut at = params.clone();
    at.level = level;
    at.multigrid.coarsest_level = params.multigrid.coarsest_level.min(level);
    at.accuracy.refinement_levels = params
        .accuracy
        .refinement_levels
        .saturating_sub(level - params.level);
    at
}

/// Converges `problem` on `start`'s level from it (module documentation); `None` where it
/// fails, its residuals appended to `tried`.
pub(super) fn converge(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    start: &Start,
    observe: &mut dyn FnMut(&Progress),
    tried: &mut Vec<f64>,
) -> Option<(Hierarchy, Converged)> {
    let mut mg = Hierarchy::for_problem(problem, params, surround, start.delta);
    mg.warm = true;
    let top = mg.levels.len() - 1;
    // The start's factor (its grid is the top level's: `Start::fits`) preconditions the
    // first Newton step where one is taken.
    mg.keep_factor(top, start.factor.as_ref().map(|f| f.copy()));
    let stop = from_converged(
        &mut mg,
        top,
        (&start.p, start.delta),
        Some(start.residual),
        params,
    );
    let known = Known {
        start: stop,
        finer: None,
    };
    let mut tally = Tally::default();
    let how = How::as_by(start.method, params, &known);
    let Ok(method) = converge_level(&mut mg, top, params, &how, &mut tally, observe) else {
        tried.extend(tally.history);
        return None;
    };
    Some((
        mg,
        Converged {
            tally,
            method,
            start: StartKind::Warm,
            coarser: Vec::new(),
        },
    ))
}

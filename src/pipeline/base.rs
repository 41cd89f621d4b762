//! The base of a case: the related case whose converged solution it starts from
//! (continuation, [`crate::solver::point::solve_from`]), a pure function of the case, so
//! that a result stays a function of its case and its cache key whichever path solves it.
//!
//! A family is the cases that differ only in the slip and the Eyring stress: at the paper's
//! slips their pressure and film hardly differ (the central film of a Figs. 4-6 family
//! spreads by 1e-4, median), so each starts from one member, the base:
//! - a physical case (Newtonian or Eyring): the same contact at `S` = 0.5 % and `tau0` =
//!   6 MPa, the middle of Table 2's slip and Eyring-stress ranges (for Figs. 4-6 a member of
//!   every family; for a user's study the same rule, so its families share a base with
//!   Table 2's where they meet it);
//! - a case in Moes groups (Figs. 1-3): the same `M`, `L` and `D` at `S-bar` = 0.1, the
//!   middle of the paper's two decades, with the same dimensionless Eyring stress
//!   `S / S-bar`;
//! - a case with a limiting shear stress: its Eyring twin (which has its own base).
//!
//! A case that is its own base solves cold, from the Hertzian pressure.

use super::error::PipelineError;
use crate::physics::case::{Case, CaseForm, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::physics::rheology::Rheology;
use crate::solver::output::Progress;
use crate::solver::point::{self, Params, PointSolution, Start};

/// The base's slide-to-roll ratio for a physical case.
pub const BASE_SLIP: f64 = 0.005;
/// The base's Eyring stress for a physical case, Pa.
pub const BASE_TAU0_PA: f64 = 6e6;
/// The base's dimensionless slip for a case in Moes groups.
pub const BASE_S_BAR: f64 = 0.1;

/// The base of `case` (module documentation), or `None` where the case is its own base (or
/// has no dimensionless Eyring stress to keep: pure rolling in Moes groups).
pub fn base_of(case: &Case) -> Option<Case> {
    if let Rheology::EyringLss(_) = case.physics.rheology {
        let mut twin = case.clone();
        twin.physics.rheology = Rheology::Eyring;
        return Some(twin);
    }
    let mut base = case.clone();
    match &mut base.spec {
        CaseForm::Physical(p) => {
            if p.slip == BASE_SLIP && p.tau0_pa == BASE_TAU0_PA {
                return None;
            }
            p.slip = BASE_SLIP;
            p.tau0_pa = BASE_TAU0_PA;
        }
        CaseForm::Dimensionless(d) => {
            if d.s_bar == BASE_S_BAR || d.s_bar <= 0.0 {
                return None;
            }
            d.slip = d.slip / d.s_bar * BASE_S_BAR;
            d.s_bar = BASE_S_BAR;
        }
    }
    Some(base)
}

/// Solves a point case as every command and pipeline does: the chain of its bases first,
/// the deepest cold and each from the one below, at the same parameters, then `problem`
/// (the case's) from its base; `observer` hears of the case's own solve, `on_base` of each
/// base before it is solved; a base that does not resolve into a problem is
/// [`PipelineError::Case`], the case's own failure [`PipelineError::Solve`]. The same arithmetic as a sweep's ([`super::executor::run_jobs`]).
pub fn solve_case(
    case: &Case,
    problem: &Problem,
    params: &Params,
    lubricants: &LubricantTable,
    on_base: &mut dyn FnMut(&Case),
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, PipelineError> {
    let chain: Vec<Case> = std::iter::successors(base_of(case), base_of).collect();
    let mut start: Option<Start> = None;
    for base in chain.iter().rev() {
        on_base(base);
        let bp = Problem::from_case(base, lubricants)
            .map_err(|e| PipelineError::case("the case's base", e))?;
        // A base that fails leaves its members to start cold, as in a sweep.
        start = match &start {
            Some(s) => point::solve_from(&bp, params, s, None),
            None => point::solve(&bp, params, None),
        }
        .ok()
        .map(|s| Start::of(&s));
    }
    Ok(match &start {
        Some(s) => point::solve_from(problem, params, s, observer),
        None => point::solve(problem, params, observer),
    }?)
}

//! A chain of nested domains (the rule's for the light contacts, [`Params::for_problem`]): the
//! case-sized domain, then rectangles each about a third of the one around it, down to the
//! contact's core, every one solved at the same level inside the solution around it
//! ([`super::nested`]). The outputs are the innermost grid's film and the friction summed over
//! the chain; their error is estimated by Richardson over the whole chain at two coarser
//! levels, whose meshes halve together, so that the surroundings' own error is part of it
//! (docs/ACCURACY_NOTES.md, "Resolution where the contact needs it"). Where that estimate
//! misses the accuracy target, the chain is solved again, cold, one level finer (no case of the
//! figures does at level 7; Fig. 6 case 19 asked at level 5 or 6 does).

use super::converge::Tally;
use super::covering::{self, Covering, Outputs};
use super::ladder;
use super::nested::Surround;
pub use super::rectangles::{rectangles, snap, CORE, SHRINK};
use super::uniform::{self, observing};
use super::{Params, PointSolution, Start, LOADED_FILM_FACTOR};
use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{
    Film, Friction, LevelValues, Method, OutputErrors, Progress, SolveError,
};
use std::sync::Arc;
use std::time::Instant;

/// A solved chain at one level.
#[derive(Debug)]
pub struct Chain {
    /// The case-sized domain's solution, then each rectangle's, outermost first.
    pub solutions: Vec<PointSolution>,
    /// The surroundings of each rectangle.
    pub surrounds: Vec<Arc<Surround>>,
}

impl Chain {
    /// The innermost solution: the film's.
    pub fn innermost(&self) -> &PointSolution {
        self.solutions
            .last()
            .expect("a chain has its case-sized domain")
    }

    /// Central film, minimum film (Moes) and sliding `mu-bar` of the chain: the innermost
    /// grid's film, its friction plus each surroundings' outside it (Eq. 8, loaded film).
    pub fn outputs(&self, problem: &Problem) -> [f64; 3] {
        let inner = self.innermost();
        [
            inner.film.hc_moes,
            inner.film.hmin_moes,
            self.friction(problem).sliding,
        ]
    }

    /// The chain's friction: the innermost grid's plus each surroundings' outside it.
    pub fn friction(&self, problem: &Problem) -> Friction {
        let inner = self.innermost();
        let limit = LOADED_FILM_FACTOR * inner.film.h_central;
        self.surrounds
            .iter()
            .fold(inner.friction, |f, s| s.plus_outside(problem, limit, f))
    }

    /// The chain's values for the error estimate, in the solver's units.
    fn level_values(&self, problem: &Problem) -> LevelValues {
        let inner = self.innermost();
        let friction = self.friction(problem);
        LevelValues {
            level: inner.info.level,
            h_central: inner.film.h_central,
            h_min: inner.film.h_min,
            mu_bar_sliding: friction.sliding,
            mu_bar_total: friction.total(),
        }
    }
}

/// Solves `problem`'s chain at `params.level` on `params.domain` (the case-sized domain with
/// its far field, [`Params::for_problem`]); no error estimate of its own.
pub fn solve_chain(problem: &Problem, params: &Params) -> Result<Chain, SolveError> {
    chain_from(
        problem,
        params,
        &rectangles(&params.domain),
        None,
        &mut |_| {},
    )
}

/// The chain of `rects` inside `params.domain`, the case-sized domain from `start` where
/// given (a related case's surroundings, [`Start`]), every solve heard by `observe`.
fn chain_from(
    problem: &Problem,
    params: &Params,
    rects: &[Domain],
    start: Option<&Start>,
    observe: &mut dyn FnMut(&Progress),
) -> Result<Chain, SolveError> {
    let mut params = params.clone();
    params.accuracy.error_levels = 0;
    params.nested = false;
    let wide = uniform::solve(problem, (&params, None), start, Some(&mut *observe))?;
    let mut chain = Chain {
        solutions: vec![wide],
        surrounds: Vec::new(),
    };
    for rect in rects {
        let outer = chain.innermost();
        let inner = snap(rect, &outer.grid);
        let fine = Grid::level(&inner, params.level);
        let surround = Arc::new(Surround::new(
            problem,
            &outer.grid,
            (&outer.p, &outer.h, outer.delta),
            &inner,
            (fine.hx, fine.hy),
        ));
        // The rectangle starts on its own level from the surroundings' pressure and film
        // constant (from the coarsest grid, the light members at S 0.1 % of Fig. 6 diverged);
        // where that fails, cold from the same.
        let start = Start {
            grid: fine,
            level: params.level,
            p: fine.sample(|x, y| surround.pressure(x, y)),
            delta: outer.delta,
            method: outer.info.method,
            coarser: Vec::new(),
            outside: None,
            residual: outer.info.residual(),
            factor: None,
            tau: None,
            across: None,
        };
        let nested = uniform::solve(
            problem,
            (
                &Params {
                    domain: inner,
                    ..params.clone()
                },
                Some(&surround),
            ),
            Some(&start),
            Some(&mut *observe),
        )?;
        chain.surrounds.push(surround);
        chain.solutions.push(nested);
    }
    Ok(chain)
}

/// The solve of a case whose parameters ask for nested domains ([`Params::nested`]): its
/// chain at `params.level`, the case-sized domain from `start` where it fits, and the chains
/// at the `params.accuracy.error_levels` levels below for the error estimate (cold; a level that
/// fails ends the estimate there); the chain one level finer where that estimate misses the
/// accuracy target ([`covering`]). The solution is the innermost grid's, with the chain's
/// friction, the whole time and the case-sized domain's solution at the level asked as its
/// surroundings (a related case's start).
pub(super) fn solve_point(
    problem: &Problem,
    params: &Params,
    start: Option<&Start>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let clock = Instant::now();
    let mut observe = observing(observer);
    // Where a rectangle does not converge (Fig. 6's lightest members at S 0.1 %: their
    // Newton-Krylov finish on the rectangle stalls), the case is solved on its one
    // case-sized domain, as without the chain, with that domain's own error estimate.
    let rects = rectangles(&params.domain);
    match chain_from(problem, params, &rects, start, &mut observe) {
        Ok(chain) => {
            let nested = Nested {
                problem,
                params: params.clone(),
                chain,
                refinements: 0,
                handed: None,
                read: None,
                kept: None,
                clock,
            };
            covering::run(nested, problem, &params.accuracy, &mut observe)
        }
        Err(_) => {
            let single = Params {
                nested: false,
                ..params.clone()
            };
            let mut s = uniform::solve(problem, (&single, None), start, Some(&mut observe))?;
            s.info.seconds = clock.elapsed().as_secs_f64();
            Ok(s)
        }
    }
}

/// A converged chain, for the loop of [`covering`].
struct Nested<'a> {
    problem: &'a Problem,
    /// The parameters at the chain's present level.
    params: Params,
    chain: Chain,
    refinements: u32,
    /// The case-sized domain's solution at the level asked, where the chain was refined: the
    /// related cases start from it, so that a member's result does not depend on whether its
    /// base refined.
    handed: Option<PointSolution>,
    /// The estimate of the level the chain was refined from: its levels are the refined
    /// chain's ladder below it.
    read: Option<OutputErrors>,
    /// The outputs of the level below where the refined chain did not converge: they stand.
    kept: Option<Outputs>,
    clock: Instant,
}

impl Covering for Nested<'_> {
    /// The innermost grid's (whose solve refused a closed film).
    fn film(&self) -> Film {
        self.chain.innermost().film
    }

    fn level(&self) -> u32 {
        self.params.level
    }

    fn may_refine(&self) -> bool {
        self.params
            .accuracy
            .may_refine(self.refinements, self.level())
    }

    /// The chain's friction and the estimate by the chains at the levels below (those the
    /// level it was refined from read, and that level).
    fn outputs(&mut self, _: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError> {
        if let Some(kept) = self.kept.take() {
            return Ok(kept);
        }
        let levels = self.params.accuracy.error_levels;
        let top = self.chain.level_values(self.problem);
        let errors = (levels > 0).then(|| match &self.read {
            Some(below) => below.refined_to(top, levels),
            None => chain_errors(self.problem, &self.params, top, levels),
        });
        Ok(Outputs {
            friction: self.chain.friction(self.problem),
            tau: None,
            errors,
            coarser: Vec::new(),
        })
    }

    /// The chain one level finer, solved cold (a related case's start is on the level asked);
    /// where it does not converge, the level below stands with its outputs.
    fn refine(
        &mut self,
        after: Option<Outputs>,
        observe: &mut dyn FnMut(&Progress),
    ) -> Result<(), SolveError> {
        self.refinements += 1;
        let finer = Params {
            level: self.params.level + 1,
            ..self.params.clone()
        };
        match chain_from(
            self.problem,
            &finer,
            &rectangles(&finer.domain),
            None,
            observe,
        ) {
            Ok(chain) => {
                let mut coarser = std::mem::replace(&mut self.chain, chain);
                if self.handed.is_none() {
                    self.handed = Some(coarser.solutions.swap_remove(0));
                }
                self.read = after.and_then(|o| o.errors);
                self.params = finer;
            }
            Err(_) => self.kept = after,
        }
        Ok(())
    }

    fn into_tally(self) -> Tally {
        let inner = self.chain.innermost();
        Tally {
            cycles: inner.info.cycles,
            history: inner.info.residual_history.clone(),
            ..Tally::default()
        }
    }

    fn into_solution(self, _: Film, outputs: Outputs) -> PointSolution {
        let mut solutions = self.chain.solutions;
        let mut solution = solutions.pop().expect("a chain has its case-sized domain");
        solution.friction = outputs.friction;
        solution.errors = outputs.errors;
        solution.info.seconds = self.clock.elapsed().as_secs_f64();
        if solutions
            .iter()
            .any(|s| s.info.method == Method::NewtonKrylov)
        {
            solution.info.method = Method::NewtonKrylov;
        }
        if !solutions.is_empty() {
            let wide = solutions.swap_remove(0);
            solution.info.start = wide.info.start;
            solution.surroundings = Some(Box::new(self.handed.unwrap_or(wide)));
        }
        solution
    }
}

/// The discretisation error of a chain whose values at `params.level` are `top`: the chains
/// at the `levels` levels below, each solved cold on its own, and `top` ([`ladder::by_solving_again`]).
fn chain_errors(problem: &Problem, params: &Params, top: LevelValues, levels: u32) -> OutputErrors {
    let below = params.level.saturating_sub(levels)..params.level;
    ladder::by_solving_again(below, top, |level| {
        let at = Params {
            level,
            ..params.clone()
        };
        solve_chain(problem, &at)
            .ok()
            .map(|c| c.level_values(problem))
    })
}

/// [`solve_chain`] at `params.level` and its error estimate over the chains at the `levels`
/// levels below it ([`OutputErrors::estimate`], in the solver's units).
pub fn solve_chain_estimated(
    problem: &Problem,
    params: &Params,
    levels: u32,
) -> Result<(Chain, OutputErrors), SolveError> {
    let chain = solve_chain(problem, params)?;
    let errors = chain_errors(problem, params, chain.level_values(problem), levels);
    Ok((chain, errors))
}

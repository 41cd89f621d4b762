//! The uniform grid: the strategy that refines ([`super::covering`]), and the solve the nested
//! chain ([`super::chain`]) runs on each of its domains and the composite grid
//! ([`super::composite`]) on its patch. Its top level converges warm (from a related case's
//! solution) or cold (full multigrid from the Hertzian pressure) and, like each finer level
//! added, has its edge settled ([`super::edge`]); the outputs' error is estimated by the ladder
//! of coarser levels ([`ladder`]).
//!
//! A finer level ([`refine`]) is added where the film closes somewhere (the side lobes of the
//! most heavily loaded contacts, M above ~5000, where the film is a thousandth of the
//! Hertzian approach and the grid's error in the deformation at the contact edge exceeds it),
//! or where the estimate misses the accuracy target, whether the level converged by cycles or by
//! the Newton-Krylov finish (the refined level converges the way the level below did: Fig. 6's
//! light contacts at M 12-18, L 28-32, 1.0-1.8 % at level 7, take four Newton-Krylov steps and
//! 7-8 s at level 8 to 0.6-0.8 %). The refined level's ladder starts from the levels below as
//! they converged.

use super::cold::Converged;
use super::converge::Tally;
use super::converge::{converge_level, How};
use super::covering::{self, Covering, Outputs};
use super::cycles::from_converged;
use super::edge::settle_top;
use super::level::LOAD;
use super::multigrid::Hierarchy;
use super::nested::Surround;
use super::newton::HandedFactor;
use super::refine::{ACROSS_LEVELS, ACROSS_UNESTIMATED_LEVEL};
use super::stopping::Known;
use super::tau::TauExtrapolated;
use super::warm::AcrossStart;
use super::{
    cold, friction, ladder, refine, tau, warm, CoarseSolution, Params, PointSolution, Start,
    MAX_LEVEL, MIN_LEVEL,
};
use crate::physics::case::Problem;
use crate::solver::output::{
    AcrossValues, Film, Friction, Info, LadderStop, Method, Output, OutputErrors, Progress,
    SolveError, StartKind,
};
use std::sync::Arc;
use std::time::Instant;

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
/// fits and converges, else cold, through the loop of [`covering`].
pub(super) fn solve(
    problem: &Problem,
    (params, surround): (&Params, Option<&Arc<Surround>>),
    warm_start: Option<&Start>,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let mut observe = observing(observer);
    let uniform = Uniform::converge(problem, (params, surround), warm_start, &mut observe)?;
    covering::run(uniform, problem, &params.accuracy, &mut observe)
}

/// A uniform grid's solve, its top level converged and its edge settled.
struct Uniform<'a> {
    problem: &'a Problem,
    /// The parameters at the level it converged on (a warm start's may be finer than asked).
    params: Params,
    mg: Hierarchy,
    tally: Tally,
    /// How the top level converged in the first place: the refinement goes by it.
    method: Method,
    /// Whether a round of the edge needed Newton-Krylov: reported.
    newton_used: bool,
    start: StartKind,
    refinements: u32,
    /// The starts of the ladder's levels and where it stops at the base
    /// ([`ladder::output_errors`]).
    coarser: Vec<CoarseSolution>,
    outside_at_base: Option<LadderStop>,
    /// The start of the tau-extrapolation's coarse problem: the base's, where the member
    /// started from it ([`tau::CoarseChange`]).
    tau_start: Option<tau::CoarseChange>,
    /// The start of a top refined across the rolling direction: the base's, where the member
    /// started from it.
    across_start: Option<AcrossStart>,
    /// The level under the top refined across, refined the same way, as it converged.
    across_rung: Option<CoarseSolution>,
    clock: Instant,
}

impl<'a> Uniform<'a> {
    /// The top level converged: from `warm_start` where it fits and converges on its own level
    /// (a base refined to a finer level takes the member there, with the refinements it has
    /// left), else cold from the Hertzian pressure, the warm attempt kept in the history; its
    /// edge settled.
    fn converge(
        problem: &'a Problem,
        (params, surround): (&Params, Option<&Arc<Surround>>),
        warm_start: Option<&Start>,
        observe: &mut dyn FnMut(&Progress),
    ) -> Result<Self, SolveError> {
        let clock = Instant::now();
        SolveError::check_level(params.level, MIN_LEVEL..=MAX_LEVEL)?;
        if params.multigrid.coarsest_level < 2 || params.multigrid.gamma == 0 {
            return Err(SolveError::InvalidParams(format!(
                "coarsest level {} must be at least 2, gamma {} positive",
                params.multigrid.coarsest_level, params.multigrid.gamma
            )));
        }
        let mut clamped = params.clone();
        clamped.multigrid.coarsest_level = params.multigrid.coarsest_level.min(params.level);
        let warm_params = warm_start
            .filter(|s| s.fits(&clamped))
            .map(|s| (s, warm::params_at(&clamped, s.level)));
        let mut tried = Vec::new();
        let warm_run = warm_params
            .as_ref()
            .and_then(|(s, p)| warm::converge(problem, (p, surround), s, observe, &mut tried));
        let (params, mg, run) = match (warm_run, warm_params) {
            (Some((mg, run)), Some((_, p))) => (p, mg, run),
            (_, warm_params) => {
                let (mg, mut run) = cold::converge(problem, (&clamped, surround), observe, tried)?;
                if warm_params.is_some() {
                    run.start = StartKind::Fallback;
                }
                (clamped, mg, run)
            }
        };
        let Converged {
            tally,
            method,
            start,
            coarser,
        } = run;
        // The coarser levels start from the base's where the member started from it, and
        // stop where the base's did outside the asymptotic range; else they start from the
        // cold solve's states.
        let (coarser, outside_at_base, tau_start, across_start) = match (start, warm_start) {
            (StartKind::Warm, Some(s)) => (
                s.coarser.clone(),
                s.outside,
                s.tau.clone(),
                s.across.clone(),
            ),
            _ => (coarser, None, None, None),
        };
        let mut uniform = Uniform {
            problem,
            params,
            mg,
            tally,
            method,
            newton_used: false,
            start,
            refinements: 0,
            coarser,
            outside_at_base,
            tau_start,
            across_start,
            across_rung: None,
            clock,
        };
        uniform.settle(observe)?;
        Ok(uniform)
    }

    /// How the top level converged: Newton-Krylov where the solve needed it or its base did.
    fn method_used(&self) -> Method {
        if self.newton_used {
            Method::NewtonKrylov
        } else {
            self.method
        }
    }

    /// The top level's friction; a non-finite one is the solve's error.
    fn friction(&self) -> Result<Friction, SolveError> {
        let mg = &self.mg;
        let friction = friction::friction(
            mg.finest(),
            &mg.model,
            mg.rolling_scale,
            self.params.friction.region,
        );
        if !friction.sliding.is_finite() || !friction.total().is_finite() {
            return Err(SolveError::NonFinite {
                what: "friction",
                cycle: self.tally.cycles,
                residual_history: self.tally.history.clone(),
            });
        }
        Ok(friction)
    }

    /// The top level's edge settled ([`super::edge`]).
    fn settle(&mut self, observe: &mut dyn FnMut(&Progress)) -> Result<(), SolveError> {
        settle_top(
            &mut self.mg,
            &self.params,
            (self.method, &mut self.newton_used),
            &mut self.tally,
            observe,
        )
    }
}

impl Covering for Uniform<'_> {
    fn film(&self) -> Film {
        friction::film(self.mg.finest(), self.problem.groups.moes_film_scale)
    }

    fn level(&self) -> u32 {
        self.mg.finest().grid.level_number()
    }

    fn may_refine(&self) -> bool {
        self.params
            .accuracy
            .may_refine(self.refinements, self.level())
    }

    /// The friction and the ladder's estimate, its levels converged the way the top one
    /// finally converged.
    fn outputs(&mut self, observe: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError> {
        let used = self.method_used();
        let friction = self.friction()?;
        let (mg, params) = (&mut self.mg, &self.params);
        let (errors, coarser) = if params.accuracy.error_levels > 0 {
            let warm = (self.coarser.as_slice(), self.outside_at_base);
            let (e, c) = ladder::output_errors(mg, params, used, warm, observe);
            (Some(e), c)
        } else {
            (None, Vec::new())
        };
        Ok(Outputs {
            friction,
            tau: None,
            errors,
            coarser,
        })
    }

    /// After the ladder, which made the coarser levels tops of their own and the top a coarse
    /// level of theirs in its half points' means (the rest of the top's equations it left
    /// alone): those means set back, then extrapolated. Not where the level needed
    /// Newton-Krylov: the coarse problem is solved by cycles, which stall on such a contact.
    /// The 5P4E family at 40 C, 3 GPa, 12 m/s (tests/continuation.rs) at level 6 gave a
    /// central film 6.4 % apart warm and cold after 23 coarse cycles each, on level-6
    /// solutions 1e-7 apart.
    fn tau_extrapolated(&mut self) -> Option<TauExtrapolated> {
        if !self.params.accuracy.tau_extrapolation || self.method_used() == Method::NewtonKrylov {
            return None;
        }
        let top = self.mg.levels.len() - 1;
        if top == 0 {
            // A grid alone in its hierarchy has no coarse problem to extrapolate with.
            return None;
        }
        self.mg.set_half_points(top);
        self.mg.refresh(top);
        let scale = self.problem.groups.moes_film_scale;
        Some(tau::extrapolated_outputs(
            &mut self.mg,
            &self.params,
            scale,
            self.tau_start.as_ref(),
        ))
    }

    /// On a level of [`ACROSS_LEVELS`], whatever refinement budget is left: the target
    /// asks for it (none on an exact level, [`super::Params::exact_level`], which the level
    /// study's points are too).
    /// Above [`ACROSS_UNESTIMATED_LEVEL`], only where the square levels estimate the
    /// minimum film.
    fn may_refine_across(&self, errors: &OutputErrors) -> bool {
        let level = self.level();
        !self.mg.finest().grid.is_refined_y()
            && ACROSS_LEVELS.contains(&level)
            && (level <= ACROSS_UNESTIMATED_LEVEL || errors.level_estimate(Output::HMin).is_some())
    }

    /// The top starts from the base's where the member started from it, else from the level
    /// below interpolated (cubic along `Y`), and converges by cycles, finished by
    /// Newton-Krylov where they stall: coarsened in `Y` alone, its cycles contract by 0.38
    /// where the square levels' do by 0.48 (docs/ACCURACY_NOTES.md, "Semi-coarsening in `Y`").
    /// Its estimate reads the level under it refined the same way ([`ladder::across_rung`]).
    /// The level below, as it converged, leads the coarser solutions: a member's start.
    fn refine_across(
        &mut self,
        mut outputs: Outputs,
        observe: &mut dyn FnMut(&Progress),
    ) -> Result<Outputs, SolveError> {
        let below = self.mg.levels.len() - 1;
        let square = CoarseSolution::converged(&mut self.mg, below);
        let k = self.mg.add_across_level();
        let start = self
            .across_start
            .as_ref()
            .filter(|s| s.grid == self.mg.levels[k].grid);
        let (mg, params) = (&mut self.mg, &self.params);
        let known = match start {
            Some(s) => Known {
                start: from_converged(mg, k, (&s.p, s.delta), Some(s.residual), params),
                finer: None,
            },
            None => {
                mg.make_top(k);
                mg.interpolate(k);
                Known::default()
            }
        };
        let how = How::from_converged(params, &known);
        let method = converge_level(mg, k, params, &how, &mut self.tally, observe)
            .map_err(|_| self.tally.not_converged(params))?;
        self.newton_used |= method != Method::Cycles;
        self.settle(observe)?;
        outputs.friction = self.friction()?;
        let top = ladder::values(&self.mg, k, &self.params);
        let warm = self.across_start.as_ref().and_then(|s| s.below.as_ref());
        let rung = ladder::across_rung(&mut self.mg, k, &self.params, method, warm, observe);
        let (below, rung) = rung.unzip();
        self.across_rung = rung;
        outputs.errors = outputs
            .errors
            .map(|e| e.with_across(AcrossValues { top, below }));
        outputs.coarser.insert(0, square);
        Ok(outputs)
    }

    fn refine(
        &mut self,
        after: Option<Outputs>,
        observe: &mut dyn FnMut(&Progress),
    ) -> Result<(), SolveError> {
        if let Some(outputs) = after {
            // The refined level's ladder starts from this level and the ones below it.
            let top = self.mg.levels.len() - 1;
            let finest = CoarseSolution::converged(&mut self.mg, top);
            self.coarser = std::iter::once(finest).chain(outputs.coarser).collect();
        }
        self.refinements += 1;
        self.method = refine::refine(
            &mut self.mg,
            &self.params,
            self.method,
            &mut self.tally,
            observe,
        )?;
        self.settle(observe)
    }

    fn into_tally(self) -> Tally {
        self.tally
    }

    fn into_solution(mut self, film: Film, outputs: Outputs) -> PointSolution {
        let top = self.mg.levels.len() - 1;
        let factor = self.mg.take_factor(top).map(HandedFactor::new);
        let method = self.method_used();
        let fine = self.mg.finest();
        PointSolution {
            grid: fine.grid,
            p: fine.p.clone(),
            h: fine.h.clone(),
            delta: self.mg.delta,
            film,
            friction: outputs.friction,
            friction_region: self.params.friction.region,
            info: Info {
                level: fine.grid.level_number(),
                method,
                cycles: self.tally.cycles,
                newton_steps: self.tally.work.newton_steps,
                krylov_iterations: self.tally.work.krylov_iterations,
                residual_history: self.tally.history,
                load_error: (fine.load_defect() / LOAD).abs(),
                seconds: self.clock.elapsed().as_secs_f64(),
                start: self.start,
            },
            errors: outputs.errors,
            coarser: outputs.coarser,
            surroundings: None,
            patches: Vec::new(),
            tau: outputs.tau,
            factor,
            across_rung: self.across_rung,
        }
    }
}

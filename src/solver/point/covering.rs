//! The one loop of a solve, whatever covers the contact ([`super::driver`]'s strategies): the
//! covering converged at its level, its film checked, its outputs and their discretisation
//! error read, and a finer level added where the film closes or the estimate misses the
//! accuracy target ([`super::AccuracyParams`]), within the refinements it has left.
//!
//! A uniform grid ([`super::uniform`]) refines by a level added to its hierarchy; the nested
//! chain ([`super::chain`]) by the whole chain solved one level finer, its estimate reading the
//! chains the level below read; the composite grid ([`super::composite`]) is solved at the
//! level given (its estimate solves the whole composite again at coarser levels, and an
//! estimate that misses the target is reported with the solution).
//!
//! Where the solve ends on a uniform level of [`super::refine::ACROSS_LEVELS`] whose minimum
//! film misses its target, a top refined across the rolling direction is added last
//! ([`Covering::refine_across`]); the central film keeps the level's tau-extrapolation.

use super::converge::Tally;
use super::tau::TauExtrapolated;
use super::{AccuracyParams, AccuracyTarget, CoarseSolution, PointSolution, MAX_LEVEL};
use crate::physics::case::Problem;
use crate::physics::film::hc_nijenbanning;
use crate::solver::output::{Film, Friction, Output, OutputErrors, Progress, SolveError};

/// A converged covering's outputs.
pub(super) struct Outputs {
    pub(super) friction: Friction,
    /// The tau-extrapolated outputs of the level the solve ends on, where asked for
    /// ([`AccuracyParams::tau_extrapolation`]; [`Covering::tau_extrapolated`]).
    pub(super) tau: Option<TauExtrapolated>,
    /// The discretisation error, where asked for ([`AccuracyParams::error_levels`]).
    pub(super) errors: Option<OutputErrors>,
    /// The coarser levels' solutions behind `errors`: a refined level's ladder starts from
    /// them, and a member's ([`super::Start::coarser`]).
    pub(super) coarser: Vec<CoarseSolution>,
}

/// What the loop asks of a strategy's solve, converged at its present level. A covering
/// that refines overrides the three methods that say so; the others are solved at the
/// level given.
pub(super) trait Covering {
    /// The film (central and minimum) the outputs are read from.
    fn film(&self) -> Film;
    /// The present level.
    fn level(&self) -> u32;
    /// The outputs and their error estimate.
    fn outputs(&mut self, observe: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError>;
    /// The residuals and cycles so far: a closed film's error carries them.
    fn into_tally(self) -> Tally;
    /// The solution, with `film` and `outputs`.
    fn into_solution(self, film: Film, outputs: Outputs) -> PointSolution;

    /// Whether a finer level may still be added.
    fn may_refine(&self) -> bool {
        false
    }
    /// The present level's outputs tau-extrapolated, where the parameters ask for them and
    /// the covering gives them: read once the solve ends on this level.
    fn tau_extrapolated(&mut self) -> Option<TauExtrapolated> {
        None
    }
    /// Whether a top refined across the rolling direction may still be added
    /// ([`Covering::refine_across`]), given the level's estimate `errors`.
    fn may_refine_across(&self, _errors: &OutputErrors) -> bool {
        false
    }
    /// A top refined across the rolling direction added above the level the solve ends on
    /// and converged, where the minimum film misses its target ([`AccuracyTarget::h_min`]):
    /// `outputs` with the top's friction, and its values in their estimate
    /// ([`OutputErrors::across`](crate::solver::output::OutputErrors::across)). Called only
    /// where [`Covering::may_refine_across`].
    fn refine_across(
        &mut self,
        outputs: Outputs,
        _observe: &mut dyn FnMut(&Progress),
    ) -> Result<Outputs, SolveError> {
        Ok(outputs)
    }
    /// A finer level added and converged: after `outputs` where the estimate missed the
    /// target (the levels it read start the refined level's), without where the film closed.
    /// Called only where [`Covering::may_refine`].
    fn refine(
        &mut self,
        _after: Option<Outputs>,
        _observe: &mut dyn FnMut(&Progress),
    ) -> Result<(), SolveError> {
        Err(SolveError::InvalidParams(format!(
            "this grid is solved at level {} alone",
            self.level()
        )))
    }
}

/// The loop (the module's documentation) on `covering` of `problem`, converged at its first
/// level, with the accuracy `accuracy` asks for.
pub(super) fn run(
    mut covering: impl Covering,
    problem: &Problem,
    accuracy: &AccuracyParams,
    observe: &mut dyn FnMut(&Progress),
) -> Result<PointSolution, SolveError> {
    loop {
        let film = covering.film();
        if accuracy.require_positive_film && film.h_min <= 0.0 {
            if !covering.may_refine() {
                let level = covering.level();
                return Err(film_collapse(
                    problem,
                    level,
                    film.h_min,
                    covering.into_tally(),
                ));
            }
            covering.refine(None, observe)?;
            continue;
        }
        let outputs = covering.outputs(observe)?;
        let missed = match (&accuracy.target, &outputs.errors) {
            (Some(target), Some(e)) => !target.met_by(e, problem.groups.m),
            _ => false,
        };
        if !(missed && covering.may_refine()) {
            let tau = extrapolates(accuracy, &outputs, covering.level(), problem.groups.m)
                .then(|| covering.tau_extrapolated())
                .flatten();
            let outputs = Outputs { tau, ..outputs };
            let across = match (&accuracy.target, &outputs.errors) {
                (Some(target), Some(e)) => {
                    target.h_min_missed_by(e) && covering.may_refine_across(e)
                }
                _ => false,
            };
            let outputs = if across {
                covering.refine_across(outputs, observe)?
            } else {
                outputs
            };
            let outputs = tau_central(outputs);
            let film = reported_film(covering.film(), &outputs);
            return Ok(covering.into_solution(film, outputs));
        }
        covering.refine(Some(outputs), observe)?;
    }
}

/// The coarsest level whose central film is tau-extrapolated: its coarse problem, a level
/// below, must lie in the asymptotic range. A level-5 member of the 5P4E Newton-Krylov family
/// (tests/continuation.rs), extrapolated from level 4, came out 6.4 % apart warm and cold;
/// the estimate study measured levels 6-8.
const TAU_LEAST_LEVEL: u32 = 6;

/// Whether the level a solve ends on is tau-extrapolated: where `accuracy` asks for it, and
/// where the level's own estimate of its central film misses issue 39's film bound (2 %, 5 %
/// from M 5 000 up, [`AccuracyTarget::ISSUE_39`]) or there is no estimate to read (the
/// studies of the numerics). Within the bound the level's central film is reported: the
/// extrapolation's coarse cycles cost as much as a warm member's whole solve (0.23 s against
/// 0.50 s on the Table 4 case's family at level 7), and on the paper's sweeps extrapolating
/// every level took the cold paper from 1 838 s to 2 891 s of CPU. Nor below
/// [`TAU_LEAST_LEVEL`].
fn extrapolates(accuracy: &AccuracyParams, outputs: &Outputs, level: u32, m: f64) -> bool {
    if !accuracy.tau_extrapolation || level < TAU_LEAST_LEVEL {
        return false;
    }
    let Some(errors) = &outputs.errors else {
        return true;
    };
    let bound = AccuracyTarget::ISSUE_39.h_central_bound(m);
    match (errors.level_estimate(Output::HCentral), bound) {
        (Some(e), Some(bound)) => e.relative(errors.value(Output::HCentral)) > bound,
        _ => false,
    }
}

/// `outputs` with the tau-extrapolated central film in their estimate's record, where both
/// were computed and the levels estimate it: the central film reported
/// ([`OutputErrors::tau_central`]).
fn tau_central(mut outputs: Outputs) -> Outputs {
    if let (Some(tau), Some(errors)) = (&outputs.tau, &mut outputs.errors) {
        if errors.level_estimate(Output::HCentral).is_some() {
            errors.tau_central = Some(tau.film.h_central);
        }
    }
    outputs
}

/// The film the solution reports: the level's `film`, with the tau-extrapolated central film
/// where [`tau_central`] put it in the estimate.
fn reported_film(film: Film, outputs: &Outputs) -> Film {
    match (
        &outputs.tau,
        outputs.errors.as_ref().and_then(|e| e.tau_central),
    ) {
        (Some(tau), Some(_)) => Film {
            h_central: tau.film.h_central,
            hc_moes: tau.film.hc_moes,
            ..film
        },
        _ => film,
    }
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

/// The error of a film that closed at `level` (its minimum film `h_min <= 0`) with no finer
/// level left to the solve: the level estimated to resolve it, and the residuals so far.
fn film_collapse(problem: &Problem, level: u32, h_min: f64, tally: Tally) -> SolveError {
    SolveError::FilmCollapse {
        h_min,
        level,
        level_needed: Some(level_to_resolve(problem, level, h_min)),
        finest_level: MAX_LEVEL,
        cycle: tally.cycles,
        residual_history: tally.history,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::grid::{Domain, Grid};
    use crate::solver::output::{Info, LevelValues, Method, StartKind};
    use crate::solver::point::{AccuracyTarget, FrictionRegion};

    /// A covering whose film and estimate are scripted by level: its film closed below
    /// `closed_below`, its friction estimate missing 1 % below `missed_below` (levels converging
    /// at 10 % a level) and within it from there (0.1 % a level); it may refine up to `last`.
    struct Scripted {
        level: u32,
        last: u32,
        closed_below: u32,
        missed_below: u32,
        /// Each refinement: the level it left and whether outputs came with it.
        refined: Vec<(u32, bool)>,
    }

    impl Scripted {
        fn at(level: u32, last: u32) -> Self {
            Scripted {
                level,
                last,
                closed_below: 0,
                missed_below: 0,
                refined: Vec::new(),
            }
        }
    }

    impl Covering for Scripted {
        fn film(&self) -> Film {
            let h_min = if self.level < self.closed_below {
                -1e-4
            } else {
                1e-3
            };
            Film {
                h_central: 2e-3,
                h_min,
                hc_moes: 2.0,
                hmin_moes: h_min * 1e3,
            }
        }

        fn level(&self) -> u32 {
            self.level
        }

        fn outputs(&mut self, _: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError> {
            let step = if self.level < self.missed_below {
                1.0
            } else {
                0.01
            };
            let levels = (0..3)
                .map(|i| {
                    let mu = 10.0 - step * (2 - i) as f64 / (i + 1) as f64;
                    LevelValues {
                        level: self.level - 2 + i,
                        h_central: 2e-3,
                        h_min: 1e-3,
                        mu_bar_sliding: mu,
                        mu_bar_total: mu,
                    }
                })
                .collect();
            Ok(Outputs {
                friction: Friction {
                    sliding: 10.0,
                    rolling: None,
                },
                tau: None,
                errors: Some(OutputErrors::of(levels, 0.0)),
                coarser: Vec::new(),
            })
        }

        fn into_tally(self) -> Tally {
            Tally {
                cycles: 7,
                history: vec![1e-3, 1e-5],
                ..Tally::default()
            }
        }

        fn into_solution(self, film: Film, outputs: Outputs) -> PointSolution {
            let grid = Grid::level(&Domain::default(), 3);
            PointSolution {
                grid,
                p: Vec::new(),
                h: Vec::new(),
                delta: 0.0,
                film,
                friction: outputs.friction,
                friction_region: FrictionRegion::Domain,
                info: Info {
                    level: self.level,
                    method: Method::Cycles,
                    // The refinements, and those that came after outputs.
                    cycles: self.refined.len(),
                    newton_steps: self.refined.iter().filter(|(_, after)| *after).count(),
                    krylov_iterations: 0,
                    residual_history: Vec::new(),
                    load_error: 0.0,
                    seconds: 0.0,
                    start: StartKind::Cold,
                },
                errors: outputs.errors,
                coarser: Vec::new(),
                surroundings: None,
                patches: Vec::new(),
                tau: None,
                factor: None,
                across_rung: None,
            }
        }

        fn may_refine(&self) -> bool {
            self.level < self.last
        }

        fn refine(
            &mut self,
            after: Option<Outputs>,
            _: &mut dyn FnMut(&Progress),
        ) -> Result<(), SolveError> {
            self.refined.push((self.level, after.is_some()));
            self.level += 1;
            Ok(())
        }
    }

    fn solve(covering: Scripted) -> Result<PointSolution, SolveError> {
        let accuracy = AccuracyParams {
            error_levels: 2,
            target: Some(AccuracyTarget::FRICTION),
            ..AccuracyParams::default()
        };
        run(
            covering,
            &Problem::circular(1000.0, 10.0, 0.1),
            &accuracy,
            &mut |_| {},
        )
    }

    #[test]
    fn a_closed_film_refines_without_outputs_and_fails_where_no_level_is_left() {
        let closed = Scripted {
            closed_below: 8,
            ..Scripted::at(7, 8)
        };
        let s = solve(closed).unwrap();
        assert_eq!(s.info.level, 8);
        assert_eq!(
            (s.info.cycles, s.info.newton_steps),
            (1, 0),
            "one refinement, before any outputs were read"
        );
        let still_closed = Scripted {
            closed_below: 9,
            ..Scripted::at(7, 8)
        };
        match solve(still_closed) {
            Err(SolveError::FilmCollapse {
                level,
                level_needed,
                cycle,
                residual_history,
                ..
            }) => {
                assert_eq!(level, 8);
                assert!(level_needed.is_some_and(|l| l > 8));
                assert_eq!((cycle, residual_history.len()), (7, 2), "the tally's");
            }
            other => panic!("expected a closed film's error, got {other:?}"),
        }
    }

    #[test]
    fn a_missed_target_refines_where_a_level_is_left() {
        let missed = Scripted {
            missed_below: 8,
            ..Scripted::at(7, 8)
        };
        let s = solve(missed).unwrap();
        assert_eq!(s.info.level, 8, "refined once, the target met there");
        assert_eq!(
            (s.info.cycles, s.info.newton_steps),
            (1, 1),
            "after its outputs"
        );
        let met = solve(Scripted::at(7, 8)).unwrap();
        assert_eq!(met.info.level, 7, "met at once: no refinement");
        let exhausted = Scripted {
            missed_below: 9,
            ..Scripted::at(7, 8)
        };
        let s = solve(exhausted).unwrap();
        assert_eq!(
            s.info.level, 8,
            "missed again at the last level: its outputs"
        );
    }
}

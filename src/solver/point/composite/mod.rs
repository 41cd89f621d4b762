//! A composite grid (issue 39; [`Params::patch`], an expert's option, not the rule's, whose
//! cost budget it would exceed): the whole domain at level `L` and patches of it at half its
//! mesh (over the inlet, over the side lobes: [`PatchSet`]), coupled both ways as in Brandt's multilevel adaptive technique and the fast adaptive
//! composite-grid method (docs/ACCURACY_NOTES.md, "Composite grid").
//!
//! A round solves each patch inside the whole-domain level (its edge pressure, by bicubic
//! interpolation, and the deformation by the pressure outside it, [`Surround::banded`]) with
//! the film constant `Delta` held at the whole-domain level's, then carries the patches back:
//! at the coarse nodes inside a patch the whole-domain level takes the restricted patch
//! pressure, the FAS forcing of its Reynolds equation (`f = R(r_P) + L_L(R P_P)`, the relative
//! truncation error), the film-equation offset that reproduces the patch's film there, and
//! the patch's load less its own over the patch in its force balance; then it takes one
//! cycle (where its cycles converged it) or a converged solve (where they did not, and once
//! the outputs settle). At the fixed point the whole-domain solution carries the patch's
//! accuracy outside the patch too: a patch over the inlet, where a heavy contact's central
//! film is formed, gives the central film of the uniform grid one level finer; patches over
//! the side lobes, where its minimum film is, that film.
//!
//! The whole-domain level keeps its edge (the fitted far field refits its amplitude in its
//! converged rounds; the patch's load correction survives it, [`LevelFields::load_correction`]).
//! The study: `examples/composite_probe.rs`.

mod round;

use super::cold;
use super::converge::{converge_level, How, Tally};
use super::covering::{self, Covering, Outputs};
use super::ladder;
use super::level::{LevelFields, Model, LOAD};
use super::nested::Surround;
use super::patch::{carry_into, Carried};
pub use super::patch::{Patch, PatchSet, PatchSpec};
use super::stopping::{Known, OUTPUT_TOLERANCE};
use super::uniform::{self, observing};
use super::{Params, PointSolution, Start, MAX_LEVEL, MIN_LEVEL};
use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{Film, Info, LevelValues, Method, Progress, SolveError, StartKind};
pub use round::CompositeRound;
use round::{round_outputs, settled, Solved};
use std::sync::Arc;
use std::time::Instant;

/// Solves `problem` on `params`' domain and level with the patches `set`, round after round
/// until the central film and the friction change by less than the output tolerance between
/// two rounds of converged whole-domain solves, or for `max_rounds`; the outputs of every
/// round.
pub fn solve_composite(
    problem: &Problem,
    params: &Params,
    set: &PatchSet,
    max_rounds: usize,
) -> Result<Vec<CompositeRound>, SolveError> {
    set.check(params)?;
    let mut place = |h: &[f64]| set.place(&params.domain, params.level, h);
    Ok(run(problem, params, &mut place, max_rounds, &mut |_| {})?.rounds)
}

/// A composite solve: its rounds, whether they settled, the whole-domain level's last state,
/// the last patch solutions, and the whole-domain level's tallies.
struct Run {
    rounds: Vec<CompositeRound>,
    settled: bool,
    grid: Grid,
    p: Vec<f64>,
    h: Vec<f64>,
    delta: f64,
    load_error: f64,
    patches: Vec<PointSolution>,
    tally: Tally,
    method: Method,
}

/// One patch of a composite solve: its rectangle and corner node on the whole-domain level,
/// its grid, its parameters, its coupling and its last solution.
struct OnePatch {
    rect: Domain,
    corner: [usize; 2],
    grid: Grid,
    params: Params,
    spec: PatchSpec,
    last: Option<PointSolution>,
}

/// Places a composite's patches from the whole-domain level's cold film.
type Place<'a> = dyn FnMut(&[f64]) -> Result<Vec<PatchSpec>, SolveError> + 'a;

/// The composite solve of `problem` at `params`, its patches placed by `place` from the
/// whole-domain level's cold film.
fn run(
    problem: &Problem,
    params: &Params,
    place: &mut Place,
    max_rounds: usize,
    observe: &mut dyn FnMut(&Progress),
) -> Result<Run, SolveError> {
    let began = Instant::now();
    if params.level > MAX_LEVEL || max_rounds == 0 {
        return Err(SolveError::InvalidParams(format!(
            "the composite grid takes a level up to {MAX_LEVEL} and a round (level {})",
            params.level
        )));
    }
    let mut wide = params.clone().level_alone();
    wide.multigrid.coarsest_level = params.multigrid.coarsest_level.min(params.level);
    let tolerance = if params.stopping.output_tolerance > 0.0 {
        params.stopping.output_tolerance
    } else {
        OUTPUT_TOLERANCE
    };
    let (mut mg, converged) = cold::converge(problem, (&wide, None), observe, Vec::new())?;
    let top = mg.levels.len() - 1;
    let specs = place(&mg.levels[top].h)?;
    let mut patches = Vec::with_capacity(specs.len());
    for spec in specs {
        spec.check(params)?;
        let (rect, corner) = spec.rectangle(&params.domain, params.level);
        // `Delta` is the whole domain's: the patch relaxes no force balance of its own (with
        // its own balance and its edge in a heavy contact, the patch moved `Delta` by twice
        // the film) and its load goes to the whole-domain level. Cycles only: the
        // Newton-Krylov finish solves for `Delta`.
        let mut patch_params = Params {
            level: spec.cells_level,
            domain: rect,
            ..wide.clone()
        };
        patch_params.multigrid.force_balance_gain = 0.0;
        patch_params.stopping.load_tolerance = f64::INFINITY;
        patch_params.newton.steps = 0;
        patches.push(OnePatch {
            rect,
            corner,
            grid: Grid::level(&rect, spec.cells_level),
            params: patch_params,
            spec,
            last: None,
        });
    }
    if patches.is_empty() {
        return Err(SolveError::InvalidParams(
            "the composite grid takes at least one patch".into(),
        ));
    }
    let mut tally: Tally = converged.tally;
    let method = converged.method;
    // One cycle of the whole-domain level per round where it converged by cycles (the fast
    // adaptive composite-grid method's outer iteration) until the outputs settle, then
    // converged solves (polishing) until they settle again; converged solves throughout
    // where it needed the Newton-Krylov finish (M 19 205: single cycles diverged within ten
    // rounds).
    let mut polishing = method != Method::Cycles;
    let model = mg.model;
    // The film equation's right-hand side of the top level as it is, outside the patches.
    let geometry = mg.levels[top].hrhs.clone();
    let mut rounds: Vec<CompositeRound> = Vec::with_capacity(max_rounds);
    let mut settled_rounds = false;
    for _ in 0..max_rounds {
        let (residual, _) = mg.residual_norm(top);
        let coarse = &mg.levels[top];
        let state = (&coarse.p[..], &coarse.h[..], mg.delta);
        let mut solved: Vec<PatchSolved> = Vec::with_capacity(patches.len());
        for patch in &patches {
            // The split of the friction and film outside the patch; without a band also the
            // patch's surroundings.
            let outside = Arc::new(Surround::new(
                problem,
                &coarse.grid,
                state,
                &patch.rect,
                (patch.grid.hx, patch.grid.hy),
            ));
            let surround = match patch.spec.band {
                0 => Arc::clone(&outside),
                b => Arc::new(Surround::banded(
                    problem,
                    &coarse.grid,
                    state,
                    (&patch.grid, patch.corner),
                    b,
                )),
            };
            let start = Start {
                grid: patch.grid,
                level: patch.spec.cells_level,
                p: patch.last.as_ref().map_or_else(
                    || patch.grid.sample(|x, y| surround.pressure(x, y)),
                    |s| s.p.clone(),
                ),
                delta: mg.delta,
                method: Method::Cycles,
                coarser: Vec::new(),
                outside: None,
                residual: params.stopping.tolerance,
                factor: None,
                tau: None,
                across: None,
            };
            let sol = uniform::solve(
                problem,
                (&patch.params, Some(&surround)),
                Some(&start),
                Some(&mut *observe),
            )?;
            solved.push((sol, outside, surround));
        }
        let views: Vec<Solved> = patches
            .iter()
            .zip(&solved)
            .map(|(patch, (sol, outside, _))| Solved {
                corner: patch.corner,
                sol,
                outside,
                previous: patch.last.as_ref(),
            })
            .collect();
        let round = round_outputs(problem, coarse, &views);
        rounds.push(CompositeRound {
            delta: mg.delta,
            residual,
            seconds: began.elapsed().as_secs_f64(),
            ..round
        });
        let now_settled = settled(&rounds, tolerance);
        settled_rounds = now_settled && polishing;
        polishing |= now_settled;
        if !settled_rounds {
            carry(&mut mg.levels[top], &patches, &solved, (&model, &geometry));
        }
        for (patch, (sol, ..)) in patches.iter_mut().zip(solved) {
            patch.last = Some(sol);
        }
        if settled_rounds {
            break;
        }
        if !polishing {
            mg.cycle(top);
        } else {
            let known = Known::default();
            let how = How::from_converged(&wide, &known);
            if converge_level(&mut mg, top, &wide, &how, &mut tally, observe).is_err() {
                return Err(tally.not_converged(&wide));
            }
        }
    }
    mg.refresh(top);
    let level = &mg.levels[top];
    Ok(Run {
        rounds,
        settled: settled_rounds,
        grid: level.grid,
        p: level.p.clone(),
        h: level.h.clone(),
        delta: mg.delta,
        load_error: (level.load_defect() / LOAD).abs(),
        patches: patches
            .into_iter()
            .map(|p| p.last.expect("at least one round"))
            .collect(),
        tally,
        method,
    })
}

/// A round's patch solutions with their surroundings: the split of the friction
/// ([`Surround::new`]) and the surroundings the patch was solved in.
type PatchSolved = (PointSolution, Arc<Surround>, Arc<Surround>);

/// The round's patches `solved` as levels (each film from its own pressure and its
/// surroundings'), restricted and carried into the whole-domain level `level`, whose film
/// right-hand side outside the patches is `geometry`.
fn carry(
    level: &mut LevelFields,
    patches: &[OnePatch],
    solved: &[PatchSolved],
    (model, geometry): (&Model, &[f64]),
) {
    let fine: Vec<LevelFields> = solved
        .iter()
        .map(|(sol, _, surround)| {
            let pg = sol.grid;
            let mut fine = LevelFields::new(pg, model);
            fine.hrhs = pg.sample(|x, y| model.geometry(x, y) + surround.film_offset(x, y));
            fine.p.clone_from(&sol.p);
            fine.refresh(sol.delta, model);
            fine
        })
        .collect();
    let carried: Vec<Carried> = patches
        .iter()
        .zip(&fine)
        .zip(solved)
        .map(|((patch, fine), (sol, ..))| Carried {
            fine,
            delta: sol.delta,
            corner: patch.corner,
            margin: patch.spec.margin,
        })
        .collect();
    carry_into(level, &carried, (model, geometry));
}

/// The product's composite solve (`Params::patch`; `repro solve --patch inlet`): the
/// composite at `params.level`, cold, and its error estimate over the composites at the
/// [`super::AccuracyParams::error_levels`] levels below, on the same rectangles (on the
/// coarsest's grid lines, placed once, at the top level) whose patches are one level coarser
/// with each, so that the meshes halve together (case 150's composites converge at order
/// 1.96, docs/ACCURACY_NOTES.md). The solution's fields are the whole-domain level's; its
/// film and friction the composite's; no refinement. Not converged where the rounds do not
/// settle.
pub(super) fn solve_point(
    problem: &Problem,
    params: &Params,
    set: &PatchSet,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let clock = Instant::now();
    set.check(params)?;
    let mut observe = observing(observer);
    // The levels below as far as every patch keeps a grid of its own (level 3).
    let smallest = set.cells_levels().min().unwrap_or(MIN_LEVEL);
    let levels = params
        .accuracy
        .error_levels
        .min(smallest.saturating_sub(MIN_LEVEL));
    let coarsest = params.level - levels;
    let mut placed: Vec<(PatchSpec, Domain)> = Vec::new();
    let top = {
        let mut place = |h: &[f64]| {
            let specs = set.place(&params.domain, params.level, h)?;
            placed = specs
                .iter()
                .map(|s| {
                    let coarse = PatchSpec {
                        cells_level: s.cells_level - levels,
                        ..*s
                    };
                    (*s, coarse.rectangle(&params.domain, coarsest).0)
                })
                .collect();
            Ok(placed
                .iter()
                .map(|(s, r)| at(s, params.level, r, params.level))
                .collect())
        };
        run(problem, params, &mut place, MAX_ROUNDS, &mut observe)?
    };
    if !top.settled {
        return Err(top.tally.not_converged(params));
    }
    let composite = Composite {
        problem,
        params,
        placed,
        below: coarsest..params.level,
        top,
        clock,
    };
    covering::run(composite, problem, &params.accuracy, &mut observe)
}

/// `spec` on the estimate's rectangle `rect` at `level`, for a composite whose own level is
/// `top`: its patch one level coarser with each level below.
fn at(spec: &PatchSpec, level: u32, rect: &Domain, top: u32) -> PatchSpec {
    PatchSpec {
        x_start: rect.x_start,
        y_centre: rect.y_centre,
        cells_level: spec.cells_level + level - top,
        ..*spec
    }
}

/// A composite solve whose rounds settled, for the loop of [`covering`].
struct Composite<'a> {
    problem: &'a Problem,
    params: &'a Params,
    /// Its patches at its own level, each with its rectangle for the estimate.
    placed: Vec<(PatchSpec, Domain)>,
    /// The levels of its estimate.
    below: std::ops::Range<u32>,
    top: Run,
    clock: Instant,
}

impl Run {
    /// The last round's values at `level`.
    fn values(&self, level: u32) -> LevelValues {
        let last = self.last();
        LevelValues {
            level,
            h_central: last.h_central,
            h_min: last.h_min,
            mu_bar_sliding: last.friction.sliding,
            mu_bar_total: last.friction.total(),
        }
    }

    fn last(&self) -> &CompositeRound {
        self.rounds.last().expect("a round")
    }
}

impl Covering for Composite<'_> {
    fn film(&self) -> Film {
        let last = self.top.last();
        Film {
            h_central: last.h_central,
            h_min: last.h_min,
            hc_moes: last.hc_moes,
            hmin_moes: last.hmin_moes,
        }
    }

    fn level(&self) -> u32 {
        self.params.level
    }

    /// The last round's friction, and the estimate by the composites at the levels below.
    fn outputs(&mut self, observe: &mut dyn FnMut(&Progress)) -> Result<Outputs, SolveError> {
        let (problem, params, top_level) = (self.problem, self.params, self.params.level);
        let placed = &self.placed;
        let errors = (!self.below.is_empty()).then(|| {
            let top = self.top.values(top_level);
            ladder::by_solving_again(self.below.clone(), top, |level| {
                let coarser = Params {
                    level,
                    ..params.clone()
                };
                let specs: Vec<PatchSpec> = placed
                    .iter()
                    .map(|(s, r)| at(s, level, r, top_level))
                    .collect();
                let mut place = |_: &[f64]| Ok(specs.clone());
                match run(problem, &coarser, &mut place, MAX_ROUNDS, observe) {
                    Ok(r) if r.settled => Some(r.values(level)),
                    _ => None,
                }
            })
        });
        Ok(Outputs {
            friction: self.top.last().friction,
            tau: None,
            errors,
            coarser: Vec::new(),
        })
    }

    fn into_tally(self) -> Tally {
        self.top.tally
    }

    fn into_solution(self, film: Film, outputs: Outputs) -> PointSolution {
        let top = self.top;
        PointSolution {
            grid: top.grid,
            p: top.p,
            h: top.h,
            delta: top.delta,
            film,
            friction: outputs.friction,
            friction_region: self.params.friction.region,
            info: Info {
                level: self.params.level,
                method: top.method,
                cycles: top.tally.cycles,
                newton_steps: top.tally.work.newton_steps,
                krylov_iterations: top.tally.work.krylov_iterations,
                residual_history: top.tally.history,
                load_error: top.load_error,
                seconds: self.clock.elapsed().as_secs_f64(),
                start: StartKind::Cold,
            },
            errors: outputs.errors,
            coarser: Vec::new(),
            surroundings: None,
            tau: None,
            patches: top
                .patches
                .iter()
                .map(|p| (p.grid.domain(), p.grid.hx))
                .collect(),
            factor: None,
            across_rung: None,
        }
    }
}

/// Most rounds of a composite solve: case 150 settled in 3-9 (level 6: 7 of single cycles
/// and 2 converged), M 5 000, L 1 in 7.
const MAX_ROUNDS: usize = 16;

//! A composite grid (issue 39; [`Params::patch`], an expert's option, not the rule's, whose
//! cost budget it would exceed): the whole domain at level `L` and one patch of it at half its
//! mesh, coupled both ways as in Brandt's multilevel adaptive technique and the fast adaptive
//! composite-grid method (docs/ACCURACY_NOTES.md, "Composite grid").
//!
//! A round solves the patch inside the whole-domain level (its edge pressure, by bicubic
//! interpolation, and the deformation by the pressure outside it, [`Surround::banded`]) with
//! the film constant `Delta` held at the whole-domain level's, then carries the patch back:
//! at the coarse nodes inside the patch the whole-domain level takes the restricted patch
//! pressure, the FAS forcing of its Reynolds equation (`f = R(r_P) + L_L(R P_P)`, the relative
//! truncation error), the film-equation offset that reproduces the patch's film there, and
//! the patch's load less its own over the patch in its force balance; then it takes one
//! cycle (where its cycles converged it) or a converged solve (where they did not, and once
//! the outputs settle). At the fixed point the whole-domain solution carries the patch's
//! accuracy outside the patch too: a patch over the inlet, where a heavy contact's central
//! film is formed, gives the central film of the uniform grid one level finer.
//!
//! The whole-domain level keeps its edge (the fitted far field refits its amplitude in its
//! converged rounds; the patch's load correction survives it, [`LevelFields::load_correction`]).
//! The study: `examples/composite_probe.rs`.

use super::cold;
use super::converge::{converge_level, How, Tally};
use super::covering::{self, Covering, Outputs};
use super::ladder;
use super::level::{LevelFields, LOAD};
use super::nested::Surround;
use super::patch::carry_into;
pub use super::patch::{Patch, PatchSpec};
use super::stopping::{Known, OUTPUT_TOLERANCE};
use super::uniform::{self, observing};
use super::{Params, PointSolution, Start, LOADED_FILM_FACTOR, MAX_LEVEL, MIN_LEVEL};
use crate::physics::case::Problem;
use crate::solver::grid::Grid;
use crate::solver::output::{
    Film, Friction, Info, LevelValues, Method, Progress, SolveError, StartKind,
};
use std::sync::Arc;
use std::time::Instant;

/// The outputs after one round of the composite iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeRound {
    /// Central film (Moes), on the patch where the centre is inside it, else on the
    /// whole-domain level.
    pub hc_moes: f64,
    /// The same in `h/c`.
    pub h_central: f64,
    /// The minimum film below in `h/c`.
    pub h_min: f64,
    /// The smaller of the patch's minimum film and the whole-domain level's outside it (Moes).
    pub hmin_moes: f64,
    /// `mu-bar`: the patch's loaded film plus the whole-domain level's outside it (rolling
    /// where it is computed).
    pub friction: Friction,
    /// The film constant.
    pub delta: f64,
    /// The largest change of the patch pressure from the round before (0 in the first).
    pub patch_change: f64,
    /// The whole-domain level's mean residual at the round's start (with the forcing of the
    /// round before).
    pub residual: f64,
    /// Seconds since the start of the composite solve.
    pub seconds: f64,
}

/// Solves `problem` on `params`' domain and level with the patch `spec`, round after round
/// until the central film and the friction change by less than the output tolerance between
/// two rounds of converged whole-domain solves, or for `max_rounds`; the outputs of every
/// round.
pub fn solve_composite(
    problem: &Problem,
    params: &Params,
    spec: &PatchSpec,
    max_rounds: usize,
) -> Result<Vec<CompositeRound>, SolveError> {
    Ok(run(problem, params, spec, max_rounds, &mut |_| {})?.rounds)
}

/// A composite solve: its rounds, whether they settled, the whole-domain level's last state,
/// the last patch solution, and the whole-domain level's tallies.
struct Run {
    rounds: Vec<CompositeRound>,
    settled: bool,
    grid: Grid,
    p: Vec<f64>,
    h: Vec<f64>,
    delta: f64,
    load_error: f64,
    patch: PointSolution,
    tally: Tally,
    method: Method,
}

fn run(
    problem: &Problem,
    params: &Params,
    spec: &PatchSpec,
    max_rounds: usize,
    observe: &mut dyn FnMut(&Progress),
) -> Result<Run, SolveError> {
    let began = Instant::now();
    if spec.cells_level > params.level
        || spec.cells_level < MIN_LEVEL
        || params.level > MAX_LEVEL
        || spec.margin == 0
        || max_rounds == 0
    {
        return Err(SolveError::InvalidParams(format!(
            "the composite grid takes a level up to {MAX_LEVEL}, a patch within the domain \
             of level {MIN_LEVEL} or finer, a margin of at least one cell and a round \
             (level {}, patch level {}, margin {})",
            params.level, spec.cells_level, spec.margin
        )));
    }
    let mut wide = params.clone().level_alone();
    wide.multigrid.coarsest_level = params.multigrid.coarsest_level.min(params.level);
    let (patch, corner) = spec.rectangle(&params.domain, params.level);
    // `Delta` is the whole domain's: the patch relaxes no force balance of its own (with its
    // own balance and its edge in a heavy contact, the patch moved `Delta` by twice the film)
    // and its load goes to the whole-domain level. Cycles only: the Newton-Krylov finish
    // solves for `Delta`.
    let mut patch_params = Params {
        level: spec.cells_level,
        domain: patch,
        ..wide.clone()
    };
    patch_params.multigrid.force_balance_gain = 0.0;
    patch_params.stopping.load_tolerance = f64::INFINITY;
    patch_params.newton.steps = 0;
    let pg = Grid::level(&patch, spec.cells_level);
    let tolerance = if params.stopping.output_tolerance > 0.0 {
        params.stopping.output_tolerance
    } else {
        OUTPUT_TOLERANCE
    };
    let (mut mg, converged) = cold::converge(problem, (&wide, None), observe, Vec::new())?;
    let mut tally: Tally = converged.tally;
    let method = converged.method;
    // One cycle of the whole-domain level per round where it converged by cycles (the fast
    // adaptive composite-grid method's outer iteration) until the outputs settle, then
    // converged solves (polishing) until they settle again; converged solves throughout
    // where it needed the Newton-Krylov finish (M 19 205: single cycles diverged within ten
    // rounds).
    let mut polishing = method != Method::Cycles;
    let top = mg.levels.len() - 1;
    let model = mg.model;
    // The film equation's right-hand side of the top level as it is, outside the patch.
    let geometry = mg.levels[top].hrhs.clone();
    let mut last: Option<PointSolution> = None;
    let mut rounds: Vec<CompositeRound> = Vec::with_capacity(max_rounds);
    let mut settled_rounds = false;
    for _ in 0..max_rounds {
        let (residual, _) = mg.residual_norm(top);
        let coarse = &mg.levels[top];
        let state = (&coarse.p[..], &coarse.h[..], mg.delta);
        // The split of the friction and film outside the patch; without a band also the
        // patch's surroundings.
        let outside = Arc::new(Surround::new(
            problem,
            &coarse.grid,
            state,
            &patch,
            (pg.hx, pg.hy),
        ));
        let surround = match spec.band {
            0 => Arc::clone(&outside),
            b => Arc::new(Surround::banded(
                problem,
                &coarse.grid,
                state,
                (&pg, corner),
                b,
            )),
        };
        let previous = last.as_ref();
        let start = Start {
            grid: pg,
            level: spec.cells_level,
            p: previous.map_or_else(
                || pg.sample(|x, y| surround.pressure(x, y)),
                |s| s.p.clone(),
            ),
            delta: mg.delta,
            method: Method::Cycles,
            coarser: Vec::new(),
            outside: None,
            residual: params.stopping.tolerance,
            factor: None,
        };
        let sol = uniform::solve(
            problem,
            (&patch_params, Some(&surround)),
            Some(&start),
            Some(&mut *observe),
        )?;
        let round = round_outputs(problem, (coarse, corner), (&sol, &outside), previous);
        rounds.push(CompositeRound {
            delta: mg.delta,
            residual,
            seconds: began.elapsed().as_secs_f64(),
            ..round
        });
        let done = settled(&rounds, tolerance) && polishing;
        if settled(&rounds, tolerance) {
            polishing = true;
        }
        if done {
            last = Some(sol);
            settled_rounds = true;
            break;
        }
        // The patch as a level (its film from its own pressure and the surroundings'),
        // restricted, and carried into the whole-domain level.
        let mut fine = LevelFields::new(pg, &model);
        fine.hrhs = pg.sample(|x, y| model.geometry(x, y) + surround.film_offset(x, y));
        fine.p.clone_from(&sol.p);
        fine.refresh(sol.delta, &model);
        let level = &mut mg.levels[top];
        carry_into(
            level,
            (&fine, sol.delta),
            (corner, spec.margin),
            (&model, &geometry),
        );
        last = Some(sol);
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
    let patch_solution = last.expect("at least one round");
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
        patch: patch_solution,
        tally,
        method,
    })
}

/// The product's composite solve (`Params::patch`; `repro solve --patch inlet`): the
/// composite at `params.level`, cold, and its error estimate over the composites at the
/// [`super::AccuracyParams::error_levels`] levels below, on one rectangle (on the coarsest's
/// grid lines) whose patch is one level coarser with each, so that the meshes halve together
/// (case 150's composites converge at order 1.96, docs/ACCURACY_NOTES.md). The solution's
/// fields are the whole-domain level's; its film and friction the composite's; no
/// refinement. Not converged where the rounds do not settle.
pub(super) fn solve_point(
    problem: &Problem,
    params: &Params,
    spec: &PatchSpec,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let clock = Instant::now();
    let mut observe = observing(observer);
    // The levels below as far as the patch keeps a grid of its own (level 3).
    let levels = params
        .accuracy
        .error_levels
        .min(spec.cells_level.saturating_sub(MIN_LEVEL));
    let coarsest = params.level - levels;
    let (rect, _) = PatchSpec {
        cells_level: spec.cells_level - levels,
        ..*spec
    }
    .rectangle(&params.domain, coarsest);
    let rect_start = rect.x_start;
    let top = run(
        problem,
        params,
        &at(spec, params.level, rect_start, params.level),
        MAX_ROUNDS,
        &mut observe,
    )?;
    if !top.settled {
        return Err(top.tally.not_converged(params));
    }
    let composite = Composite {
        problem,
        params,
        spec,
        below: coarsest..params.level,
        rect_start,
        top,
        clock,
    };
    covering::run(composite, problem, &params.accuracy, &mut observe)
}

/// `spec` on the estimate's rectangle (its inlet at `x_start`) at `level`, for a composite
/// whose own level is `top`: its patch one level coarser with each level below.
fn at(spec: &PatchSpec, level: u32, x_start: f64, top: u32) -> PatchSpec {
    PatchSpec {
        x_start,
        cells_level: spec.cells_level + level - top,
        ..*spec
    }
}

/// A composite solve whose rounds settled, for the loop of [`covering`].
struct Composite<'a> {
    problem: &'a Problem,
    params: &'a Params,
    spec: &'a PatchSpec,
    /// The levels of its estimate.
    below: std::ops::Range<u32>,
    /// The inlet of the estimate's rectangle.
    rect_start: f64,
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
        let (problem, params, spec, top_level) =
            (self.problem, self.params, self.spec, self.params.level);
        let errors = (!self.below.is_empty()).then(|| {
            let top = self.top.values(top_level);
            ladder::by_solving_again(self.below.clone(), top, |level| {
                let coarser = Params {
                    level,
                    ..params.clone()
                };
                let patch = at(spec, level, self.rect_start, top_level);
                match run(problem, &coarser, &patch, MAX_ROUNDS, observe) {
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
            patch: Some((top.patch.grid.domain(), top.patch.grid.hx)),
            factor: None,
        }
    }
}

/// Most rounds of a composite solve: case 150 settled in 3-9 (level 6: 7 of single cycles
/// and 2 converged), M 5 000, L 1 in 7.
const MAX_ROUNDS: usize = 16;

/// Whether the last two rounds' central film and friction agree within `tolerance`.
fn settled(rounds: &[CompositeRound], tolerance: f64) -> bool {
    let [.., a, b] = rounds else {
        return false;
    };
    let close = |x: f64, y: f64| (x - y).abs() <= tolerance * y.abs();
    close(a.hc_moes, b.hc_moes) && close(a.friction.sliding, b.friction.sliding)
}

/// A round's central and minimum film and friction from the whole-domain level `coarse`, the
/// patch's solution `sol` and its surroundings `outside` ([`Surround::new`], the split of the
/// friction), and the largest change of the patch pressure from `previous`.
fn round_outputs(
    problem: &Problem,
    (coarse, [i0, j0]): (&LevelFields, [usize; 2]),
    (sol, outside): (&PointSolution, &Surround),
    previous: Option<&PointSolution>,
) -> CompositeRound {
    let inner = outside.inner();
    let hc = if inner.x_start < 0.0 && inner.x_end > 0.0 {
        sol.film.h_central
    } else {
        coarse.h_central()
    };
    let g = coarse.grid;
    let cells = sol.grid.nx / 2;
    let under =
        |i: usize, j: usize| (i0..=i0 + cells).contains(&i) && (j0..=j0 + cells).contains(&j);
    let outside_min = (0..g.len())
        .filter(|&k| !under(k % g.px(), k / g.px()))
        .map(|k| coarse.h[k])
        .fold(f64::INFINITY, f64::min);
    let scale = problem.groups.moes_film_scale;
    let friction = outside.plus_outside(problem, LOADED_FILM_FACTOR * hc, sol.friction);
    let h_min = sol.film.h_min.min(outside_min);
    CompositeRound {
        hc_moes: hc * scale,
        h_central: hc,
        h_min,
        hmin_moes: h_min * scale,
        friction,
        delta: sol.delta,
        patch_change: previous.map_or(0.0, |q| {
            q.p.iter()
                .zip(&sol.p)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
        }),
        residual: 0.0,
        seconds: 0.0,
    }
}

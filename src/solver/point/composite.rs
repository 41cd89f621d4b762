//! A composite grid (issue 39, prototype; not the rule's): the whole domain at level `L` and
//! one patch of it at half its mesh, coupled both ways as in Brandt's multilevel adaptive
//! technique and the fast adaptive composite-grid method (docs/ACCURACY_NOTES.md, "Composite
//! grid").
//!
//! A round solves the patch inside the whole-domain level (its edge pressure, by bicubic
//! interpolation, and the deformation by the pressure outside it, [`Surround::banded`]) with
//! the film constant `Delta` held at the whole-domain level's, then carries the patch back:
//! at the coarse nodes inside the patch the whole-domain level takes the restricted patch
//! pressure, the FAS forcing of its Reynolds equation (`f = R(r_P) + L_L(R P_P)`, the relative
//! truncation error), the film-equation offset that reproduces the patch's film there, and
//! the patch's load less its own over the patch in its force balance; then it is converged
//! again. At the fixed point the whole-domain solution carries the patch's accuracy outside
//! the patch too: a patch over the inlet, where a heavy contact's central film is formed,
//! gives the central film of the uniform grid one level finer.
//!
//! The whole-domain level keeps its edge (the fitted far field refits its amplitude in its
//! converged rounds; the patch's load correction survives it, [`LevelFields::load_correction`]).
//! The study: `examples/composite_probe.rs`.

use super::cold;
use super::converge::{converge_level, How, Tally};
use super::level::{LevelFields, Model};
use super::nested::Surround;
use super::stopping::{Known, OUTPUT_TOLERANCE};
use super::transfer::coarsen;
use super::{solve_with, Params, PointSolution, Start, LOADED_FILM_FACTOR};
use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{Method, SolveError};
use crate::solver::richardson::{self, ErrorEstimate};
use std::sync::Arc;
use std::time::Instant;

/// Where a patch lies and how it is coupled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchSpec {
    /// Its inlet: the whole-domain level's grid line nearest this `X`.
    pub x_start: f64,
    /// It spans `2^cells_level` cells of the whole-domain level in each direction,
    /// symmetric about `Y = 0`: its own grid is level `cells_level` on its rectangle.
    pub cells_level: u32,
    /// The whole-domain nodes that take the patch's forcing: those at least this many cells
    /// inside its edge (1: every interior node; with 2 a ring of coarse equations under the
    /// patch made the rounds alternate).
    pub margin: usize,
    /// Width in whole-domain cells of the band around the patch over which the deformation
    /// by the outside pressure is taken at the patch's mesh ([`Surround::banded`]; 0: the
    /// wide cells split at the edge, [`Surround::new`]).
    pub band: usize,
}

impl PatchSpec {
    /// The heavy contact's inlet patch of the study: `-1.2` to about `-0.45` Hertzian radii on
    /// the heavy-load domain at any level (a quarter of the domain in each direction),
    /// interior forcing, a band of eight cells.
    pub fn inlet(level: u32) -> Self {
        PatchSpec {
            x_start: -1.2,
            cells_level: level - 1,
            margin: 1,
            band: 8,
        }
    }

    /// The patch's rectangle on `level`'s grid of `domain`, and its corner node there.
    pub fn rectangle(&self, domain: &Domain, level: u32) -> (Domain, [usize; 2]) {
        let coarse = Grid::level(domain, level);
        let cells = 1usize << self.cells_level;
        let i0 = ((self.x_start - coarse.x0) / coarse.hx).round() as usize;
        let j0 = (coarse.ny - cells) / 2;
        let patch = Domain {
            x_start: coarse.x(i0),
            x_end: coarse.x(i0 + cells),
            y_half: -coarse.y(j0),
        };
        (patch, [i0, j0])
    }
}

/// The outputs after one round of the composite iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeRound {
    /// Central film (Moes), on the patch where the centre is inside it, else on the
    /// whole-domain level.
    pub hc_moes: f64,
    /// The smaller of the patch's minimum film and the whole-domain level's outside it (Moes).
    pub hmin_moes: f64,
    /// Sliding `mu-bar`: the patch's loaded film plus the whole-domain level's outside it.
    pub mu_bar_sliding: f64,
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
    let began = Instant::now();
    if spec.cells_level > params.level || spec.margin == 0 {
        return Err(SolveError::InvalidParams(
            "the composite prototype takes a patch within the domain and a margin of at least \
             one cell"
                .into(),
        ));
    }
    let mut wide = params.clone();
    wide.nested = false;
    wide.accuracy.error_levels = 0;
    wide.accuracy.target = None;
    wide.accuracy.refinement_levels = 0;
    wide.accuracy.require_positive_film = false;
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
    let mut observe = |_: &crate::solver::output::Progress| {};
    let (mut mg, converged) = cold::converge(problem, (&wide, None), &mut observe, Vec::new())?;
    let mut tally: Tally = converged.tally;
    // One cycle of the whole-domain level per round where it converged by cycles (the fast
    // adaptive composite-grid method's outer iteration) until the outputs settle, then
    // converged solves (polishing) until they settle again; converged solves throughout
    // where it needed the Newton-Krylov finish (M 19 205: single cycles diverged within ten
    // rounds).
    let mut polishing = converged.method != Method::Cycles;
    let top = mg.levels.len() - 1;
    let model = mg.model;
    // The film equation's right-hand side of the top level as it is, outside the patch.
    let geometry = mg.levels[top].hrhs.clone();
    let mut previous: Option<PointSolution> = None;
    let mut out: Vec<CompositeRound> = Vec::with_capacity(max_rounds);
    for _ in 0..max_rounds {
        let (residual, _) = mg.residual_norm(top);
        let coarse = &mg.levels[top];
        let state = (&coarse.p[..], &coarse.h[..], mg.delta);
        let outside = Surround::new(problem, &coarse.grid, state, &patch, (pg.hx, pg.hy));
        let surround = Arc::new(match spec.band {
            0 => Surround::new(problem, &coarse.grid, state, &patch, (pg.hx, pg.hy)),
            b => Surround::banded(problem, &coarse.grid, state, (&pg, corner), b),
        });
        let start = Start {
            grid: pg,
            level: spec.cells_level,
            p: previous.as_ref().map_or_else(
                || pg.sample(|x, y| surround.pressure(x, y)),
                |s| s.p.clone(),
            ),
            delta: mg.delta,
            method: Method::Cycles,
            coarser: Vec::new(),
            residual: params.stopping.tolerance,
        };
        let sol = solve_with(
            problem,
            (&patch_params, Some(&surround)),
            Some(&start),
            None,
        )?;
        let round = round_outputs(
            problem,
            (coarse, corner),
            (&sol, &outside),
            previous.as_ref(),
        );
        out.push(CompositeRound {
            delta: mg.delta,
            residual,
            seconds: began.elapsed().as_secs_f64(),
            ..round
        });
        if settled(&out, tolerance) {
            if polishing {
                break;
            }
            polishing = true;
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
        previous = Some(sol);
        if !polishing {
            mg.cycle(top);
        } else {
            let known = Known::default();
            let how = How::from_converged(&wide, &known);
            if converge_level(&mut mg, top, &wide, &how, &mut tally, &mut observe).is_none() {
                return Err(tally.not_converged(&wide));
            }
        }
    }
    Ok(out)
}

/// Whether the last two rounds' central film and friction agree within `tolerance`.
fn settled(rounds: &[CompositeRound], tolerance: f64) -> bool {
    let [.., a, b] = rounds else {
        return false;
    };
    let close = |x: f64, y: f64| (x - y).abs() <= tolerance * y.abs();
    close(a.hc_moes, b.hc_moes) && close(a.mu_bar_sliding, b.mu_bar_sliding)
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
    let limit = LOADED_FILM_FACTOR * hc;
    CompositeRound {
        hc_moes: hc * scale,
        hmin_moes: sol.film.h_min.min(outside_min) * scale,
        mu_bar_sliding: sol.friction.sliding + outside.outside_sliding(problem, limit),
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

/// Carries the converged patch `fine` (film constant `delta`) into the whole-domain level
/// `level`, its corner at node `[i0, j0]`: at the level's nodes at least `margin` cells inside
/// the patch, the restricted pressure and the FAS forcing (`f`, and the film-equation offset
/// that reproduces the patch's film; elsewhere the film's right-hand side is `geometry`); in
/// the force balance, the patch's load less the level's own over the patch.
fn carry_into(
    level: &mut LevelFields,
    (fine, delta): (&LevelFields, f64),
    ([i0, j0], margin): ([usize; 2], usize),
    (model, geometry): (&Model, &[f64]),
) {
    let mut sub = LevelFields::new(fine.grid.coarser(), model);
    coarsen(fine, &mut sub, model, delta);
    let (g, sg) = (level.grid, sub.grid);
    let at = |ic: usize, jc: usize| g.idx(i0 + ic, j0 + jc);
    let forced = || {
        (margin..=sg.ny - margin)
            .flat_map(move |jc| (margin..=sg.nx - margin).map(move |ic| (ic, jc)))
    };
    level.f.iter_mut().for_each(|v| *v = 0.0);
    for (ic, jc) in forced() {
        level.p[at(ic, jc)] = sub.p[sg.idx(ic, jc)];
        level.f[at(ic, jc)] = sub.f[sg.idx(ic, jc)];
    }
    let mut w = g.zeros();
    level.deformation.apply(&level.p, &mut w);
    level.hrhs.copy_from_slice(geometry);
    for (ic, jc) in forced() {
        let k = at(ic, jc);
        level.hrhs[k] = sub.h[sg.idx(ic, jc)] - delta - w[k];
    }
    let mut under = sg.zeros();
    for jc in 0..=sg.ny {
        for ic in 0..=sg.nx {
            under[sg.idx(ic, jc)] = level.p[at(ic, jc)];
        }
    }
    level.load_correction = fine.grid.integrate(&fine.p) - sg.integrate(&under);
    level.rg = -(level.load - level.load_correction);
    level.invalidate();
}

/// The composite's outputs at `params.level` (its last round) and the Richardson estimates
/// of its central film and sliding friction ([`richardson::estimate`], Moes units and
/// `mu-bar`) over the composites at the `levels` levels below: the same rectangle (on the
/// coarsest one's grid lines), its patch one level coarser with each, so that the meshes
/// halve together (docs/ACCURACY_NOTES.md: case 150's composites converge at order 1.96).
pub fn solve_composite_estimated(
    problem: &Problem,
    params: &Params,
    spec: &PatchSpec,
    (levels, max_rounds): (u32, usize),
) -> Result<(CompositeRound, [Option<ErrorEstimate>; 2]), SolveError> {
    let coarsest = params.level.saturating_sub(levels);
    let drop = params.level - coarsest;
    if spec.cells_level < drop {
        return Err(SolveError::InvalidParams(
            "the patch must have cells at the coarsest level of the estimate".into(),
        ));
    }
    let (rect, _) = PatchSpec {
        cells_level: spec.cells_level - drop,
        ..*spec
    }
    .rectangle(&params.domain, coarsest);
    let mut runs = Vec::new();
    for level in coarsest..=params.level {
        let at = PatchSpec {
            x_start: rect.x_start,
            cells_level: spec.cells_level + level - params.level,
            ..*spec
        };
        let rounds = solve_composite(
            problem,
            &Params {
                level,
                ..params.clone()
            },
            &at,
            max_rounds,
        )?;
        runs.push(rounds.last().cloned().expect("at least one round"));
    }
    let hc: Vec<f64> = runs.iter().map(|r| r.hc_moes).collect();
    let mu: Vec<f64> = runs.iter().map(|r| r.mu_bar_sliding).collect();
    let last = runs.pop().expect("the composite at the level itself");
    Ok((last, [richardson::estimate(&hc), richardson::estimate(&mu)]))
}

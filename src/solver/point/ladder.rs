//! The discretisation error of the outputs: the converged finest level restricted to each of
//! [`super::AccuracyParams::error_levels`] coarser levels in turn, converged there as that level's
//! own problem (its own equations and far field, not the coarse-grid problem of a cycle), and the
//! central film, minimum film and sliding friction of all of them extrapolated
//! ([`crate::solver::richardson`]).
//!
//! A coarser level starts from the same level's solution of the warm start's base where there
//! is one ([`CoarseSolution`], kept with every solution): a member differs from its base by
//! its slip or Eyring stress, and its coarser levels converge from the base's in as few
//! cycles as its finest level does from the base's finest. Otherwise (a cold solve) it starts
//! from the finer solution injected onto its nodes, which is within the two levels'
//! discretisation difference of its own solution (on the Table 4 case 20 % in the central
//! film between levels 6 and 7, 24 cycles); where it does not converge from that state, it is
//! converged again from injection. A level that does not converge, or whose film is outside
//! the asymptotic range (closed at the centre, or under half the finest's: the heavy
//! contacts' coarsest levels, M above ~1 000 at small L), ends the ladder ([`LadderStop`]);
//! the estimate reads the levels above it: with two, at the scheme's second order, with one,
//! none ([`crate::solver::richardson`]). A member's ladder ends where its base's found a level
//! outside the asymptotic range ([`LadderStop::OutsideAtBase`]): a family's films differ by
//! 1e-4, and the member would converge that level from injection only to find the same (Fig.
//! 4's M = 19 205 members each spent 1.1-2.5 s on their level 7, 44 level-8 members on their
//! level 6; docs/ACCURACY_NOTES.md, "Where a solve's time goes").

use super::converge::{converge_level, How, Tally};
use super::cycles::{from_converged, stop_outputs};
use super::edge::settle_edge;
use super::level::LevelFields;
use super::multigrid::Hierarchy;
use super::stopping::{Finer, Known};
use super::{Params, MIN_LEVEL};
use crate::solver::output::{LadderStop, LevelValues, Method, Output, OutputErrors, Progress};
use std::time::Instant;

/// A coarser level's converged solution: the start of the same level of a member's ladder.
#[derive(Debug, Clone, PartialEq)]
pub struct CoarseSolution {
    /// Its level.
    pub level: u32,
    /// Pressure `P` at its nodes.
    pub p: Vec<f64>,
    /// Its film constant `Delta`.
    pub delta: f64,
    /// The residual it converged to; `None` for a state that is only a start (the cold
    /// solve's full-multigrid state of the level).
    pub residual: Option<f64>,
}

impl CoarseSolution {
    /// Level `k` of `mg` as it converged, with its own residual: a refined level's or a grid
    /// sequence's start of the same level of the ladder.
    pub(super) fn converged(mg: &mut Hierarchy, k: usize) -> Self {
        let residual = mg.residual_norm(k).0;
        CoarseSolution::at(mg, k, residual)
    }

    /// Level `k` of `mg` as a rung left it, converged to `residual`.
    fn at(mg: &Hierarchy, k: usize, residual: f64) -> Self {
        CoarseSolution {
            level: mg.levels[k].grid.level_number(),
            p: mg.levels[k].p.clone(),
            delta: mg.delta,
            residual: Some(residual),
        }
    }
}

/// The outputs of level `k` as it stands (those the stopping rule reads, the total friction
/// in place of its rolling part).
pub(super) fn values(mg: &Hierarchy, k: usize, params: &Params) -> LevelValues {
    let [h_central, h_min, sliding, rolling] = stop_outputs(mg, k, params);
    LevelValues {
        level: mg.levels[k].grid.level_number(),
        h_central,
        h_min,
        mu_bar_sliding: sliding,
        mu_bar_total: sliding + rolling,
    }
}

/// `v`'s outputs in the order the stopping rule reads them ([`stop_outputs`]): a rung's
/// [`Known::finer`].
fn stop_values(v: &LevelValues) -> [f64; 4] {
    [
        Output::HCentral,
        Output::HMin,
        Output::MuBarSliding,
        Output::MuBarTotal,
    ]
    .map(|o| v.get(o))
}

/// Injects level `k + 1`'s pressure onto level `k`'s nodes.
fn inject(mg: &mut Hierarchy, k: usize) {
    let (lo, hi) = mg.levels.split_at_mut(k + 1);
    let (coarse, fine) = (&mut lo[k], &hi[0]);
    let (gc, gf) = (coarse.grid, fine.grid);
    let (rx, ry) = gf.ratio_to(&gc);
    for jc in 0..gc.py() {
        for ic in 0..gc.px() {
            coarse.p[gc.idx(ic, jc)] = fine.p[gf.idx(rx * ic, ry * jc)];
        }
    }
}

/// Relaxations per visit of the coarsest grid when a coarser level of the ladder is the top (the
/// top level's cycles keep [`super::MultigridParams::coarsest_sweeps`], 50). The coarsest visit is
/// a fixed cost per cycle, 50 sweeps of 33 x 33 nodes: about 11 % of a level-7 cycle, but 36 % of a
/// level-6 and 80 % of a level-5 one (node counts); 20 cut the ladder's time by a quarter for half
/// a cycle more per level (docs/ACCURACY_NOTES.md, "Fewer coarsest sweeps on a coarser top").
const LADDER_COARSEST_SWEEPS: usize = 20;

/// Converges level `k` as the top, the way the top level converged (`method`: cycles, with
/// the finish where they stall, or the Newton-Krylov finish directly), from `warm` (the base's
/// solution on this level, or the cold solve's full-multigrid state) where it fits, else from
/// the injected finer solution; its cycles stop where the outputs' algebraic error is a small
/// share of their distance to `finer`, the next finer level's outputs
/// ([`super::stopping::Known::finer`]). Where it fails from `warm`, it is converged again from
/// the injected finer solution: Fig. 6's cases 41 and 50 in the paper's setup (5P4E, 40 C,
/// 2 GPa, 7 and 12 m/s), cold bases finished by Newton-Krylov, did not converge level 6 from
/// its full-multigrid state and did from injection (a cold solve's grid sequence now hands
/// the ladder its converged levels instead, [`super::sequence::grid_sequence`]). Returns the
/// residual it converged to, `None` where it failed.
fn converge_rung(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    (method, finer): (Method, Finer),
    warm: Option<&CoarseSolution>,
    observe: &mut dyn FnMut(&Progress),
) -> Option<f64> {
    let warm = warm.filter(|w| w.p.len() == mg.levels[k].p.len());
    let delta = mg.delta;
    let starts = if warm.is_some() {
        vec![warm, None]
    } else {
        vec![None]
    };
    starts.into_iter().find_map(|start| {
        // A converged start's outputs and residual stop its cycles as a warm start's do.
        let stop = match start {
            Some(w) => from_converged(mg, k, (&w.p, w.delta), w.residual, params),
            None => {
                inject(mg, k);
                mg.delta = delta;
                mg.make_top(k);
                mg.refresh(k);
                None
            }
        };
        let known = Known {
            start: stop,
            finer: Some(finer),
        };
        // Its tallies are not the solve's: the ladder reports its time, not its cycles.
        let mut tally = Tally::default();
        let how = How::as_by(method, params, &known);
        let used = converge_level(mg, k, params, &how, &mut tally, observe).ok()?;
        let mut newton_used = false;
        settle_edge(mg, k, params, (used, &mut newton_used), &mut tally, observe)
            .then(|| mg.residual_norm(k).0)
    })
}

/// The outputs of the converged top level of `mg` and of up to `params.accuracy.error_levels`
/// coarser levels converged on their own (from `warm`'s solutions, the base's, where they are
/// of the same levels; not below the level `warm`'s stop found outside the asymptotic range),
/// their estimates, and the coarser solutions. The film constant is restored after.
pub(super) fn output_errors(
    mg: &mut Hierarchy,
    params: &Params,
    method: Method,
    (warm, outside_at_base): (&[CoarseSolution], Option<LadderStop>),
    observe: &mut dyn FnMut(&Progress),
) -> (OutputErrors, Vec<CoarseSolution>) {
    let clock = Instant::now();
    let top = mg.levels.len() - 1;
    let mut levels = vec![values(mg, top, params)];
    let mut solutions = Vec::new();
    let mut stopped = None;
    let delta = mg.delta;
    let sweeps = mg.set_coarsest_sweeps(LADDER_COARSEST_SWEEPS);
    for step in 1..=params.accuracy.error_levels as usize {
        // The hierarchy's coarsest level is solved by relaxation alone: never a top.
        let Some(k) = top.checked_sub(step).filter(|&k| k >= 1) else {
            break;
        };
        let level = mg.levels[k].grid.level_number();
        let start = warm.iter().find(|w| w.level == level);
        if level < MIN_LEVEL {
            break;
        }
        // The base found this level (or a finer one) outside the asymptotic range: a member
        // would converge it from injection only to find the same (Fig. 4's M = 19 205
        // members' level 7, 1.1-2.5 s each; 44 level-8 members' level 6).
        if outside_at_base.is_some_and(|stop| level <= stop.level()) {
            stopped = Some(LadderStop::OutsideAtBase { level });
            break;
        }
        let finer = Finer {
            outputs: stop_values(&levels[0]),
            rolling_of_total: false,
        };
        let Some(residual) = converge_rung(mg, k, params, (method, finer), start, observe) else {
            stopped = Some(LadderStop::NotConverged { level });
            break;
        };
        let v = values(mg, k, params);
        // A film closed at the centre, or open under half the finest's, is outside the range
        // the estimate can read ([`LadderStop::outside`]): a closed central film is negative
        // and its friction meaningless (0 on Fig. 1's M 1 000, L 1 at level 5). A film closed
        // only in the side lobes (the heaviest contacts' levels below the one they were
        // refined to) keeps a central film and a friction that converge with the levels above
        // (M 11 070's level 7 under levels 8-9: order 2.1 in friction), and is read (its
        // minimum film's estimate says how unresolved the side lobes are).
        if let Some(stop) = LadderStop::outside(&v, &levels[levels.len() - 1]) {
            stopped = Some(stop);
            break;
        }
        levels.insert(0, v);
        solutions.push(CoarseSolution::at(mg, k, residual));
    }
    mg.delta = delta;
    mg.set_coarsest_sweeps(sweeps);
    (
        OutputErrors {
            stopped,
            ..OutputErrors::of(levels, clock.elapsed().as_secs_f64())
        },
        solutions,
    )
}

/// The level under the converged top `k`, a top refined across the rolling direction, refined
/// the same way (`6y` under `7y`): converged on its own as a rung of the ladder is (from
/// `warm`, the base's, where it fits, else the top injected), in place of the square level
/// below the top, which is put back after with the film constant. Its values and solution;
/// `None` where it did not converge or lies outside the asymptotic range ([`LadderStop::outside`]).
pub(super) fn across_rung(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    method: Method,
    warm: Option<&CoarseSolution>,
    observe: &mut dyn FnMut(&Progress),
) -> Option<(LevelValues, CoarseSolution)> {
    let grid = mg.levels[k].grid.coarser();
    let square = std::mem::replace(&mut mg.levels[k - 1], LevelFields::new(grid, &mg.model));
    let (delta, sweeps) = (mg.delta, mg.set_coarsest_sweeps(LADDER_COARSEST_SWEEPS));
    let top = values(mg, k, params);
    let finer = Finer {
        outputs: stop_values(&top),
        rolling_of_total: true,
    };
    let rung = converge_rung(mg, k - 1, params, (method, finer), warm, observe).and_then(|r| {
        let v = values(mg, k - 1, params);
        LadderStop::outside(&v, &top)
            .is_none()
            .then(|| (v, CoarseSolution::at(mg, k - 1, r)))
    });
    mg.levels[k - 1] = square;
    mg.delta = delta;
    mg.set_coarsest_sweeps(sweeps);
    rung
}

/// The error estimate of a solve whose strategy cannot restrict its solution (the nested
/// chain, [`super::chain`]; the composite grid, [`super::composite`]): the same strategy
/// solved afresh at each level of `below` by `solve_at` (its values, `None` where it does not
/// converge, which ends the estimate there: [`LadderStop::NotConverged`]), then `top`'s.
pub(super) fn by_solving_again(
    below: std::ops::Range<u32>,
    top: LevelValues,
    mut solve_at: impl FnMut(u32) -> Option<LevelValues>,
) -> OutputErrors {
    let clock = Instant::now();
    let mut levels = Vec::new();
    let mut stopped = None;
    for level in below {
        match solve_at(level) {
            Some(values) => levels.push(values),
            None => {
                levels.clear();
                stopped = Some(LadderStop::NotConverged { level });
            }
        }
    }
    levels.push(top);
    OutputErrors {
        levels,
        seconds: clock.elapsed().as_secs_f64(),
        stopped,
        tau_central: None,
        across: None,
    }
}

//! The finest level's multigrid cycles: when they converge, stall or diverge, and the
//! state they leave.

use super::far_field::{FAR_FIELD_ROUNDS, FAR_FIELD_SETTLED};
use super::level::LOAD;
use super::multigrid::Hierarchy;
use super::stopping::{self, Known, WarmStop};
use super::{friction, Edge, Params};
use crate::solver::output::{mean_change, Progress, Step};

/// When a run of cycles counts as stalled (see [`super::MultigridParams::stall_cycles`],
/// [`super::MultigridParams::early_stall_cycles`]), and whether cycles that alternate get a
/// weighted correction first ([`DAMPED_CORRECTION`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct StallWindows {
    pub(super) stall: usize,
    pub(super) early: usize,
    /// On for a level started from a converged solution (a refined level, a warm start, the
    /// edge's rounds, the error ladder's levels: `converge::How::from_converged`), where the
    /// three families of [`DAMPED_CORRECTION`] alternated. Off for the cold solve's finest
    /// cycles and the grid sequence, where weighting made a nested chain slower
    /// (docs/ACCURACY_NOTES.md, "Why the new level-8 solves needed Newton-Krylov").
    pub(super) weigh_alternation: bool,
}

impl StallWindows {
    /// Whether cycles with these residuals and pressure changes (one per cycle so far) have
    /// stalled: both measures no lower than half their best for `stall` cycles, or, at
    /// cycle `early`, neither below half its first cycle's value.
    pub(super) fn stalled(&self, residuals: &[f64], changes: &[f64]) -> bool {
        let early = self.early;
        let never_got_going = early > 0
            && residuals.len() == early
            && stalled(residuals, early - 1)
            && stalled(changes, early - 1);
        never_got_going || stalled(residuals, self.stall) && stalled(changes, self.stall)
    }
}

/// Whether the last `window` cycles brought a convergence measure (the residual, or the
/// pressure change) no lower than half its best value before them: the cycles no longer
/// converge (a slowly converging heavy case still halves both every four or five cycles).
pub(super) fn stalled(history: &[f64], window: usize) -> bool {
    if window == 0 || history.len() <= window {
        return false;
    }
    let (before, recent) = history.split_at(history.len() - window);
    let best = |v: &[f64]| v.iter().cloned().fold(f64::INFINITY, f64::min);
    best(recent) > 0.5 * best(before)
}

/// A level's pressure and the film constant `Delta`: a start of the finish.
pub(super) struct State {
    pub(super) p: Vec<f64>,
    delta: f64,
}

impl State {
    pub(super) fn of(mg: &Hierarchy, k: usize) -> Self {
        State {
            p: mg.levels[k].p.clone(),
            delta: mg.delta,
        }
    }

    pub(super) fn restore(&self, mg: &mut Hierarchy, k: usize) {
        mg.levels[k].p.copy_from_slice(&self.p);
        mg.delta = self.delta;
    }
}

/// What the cycles on the top level reached.
pub(super) struct Cycles {
    pub(super) converged: bool,
    /// Residual after each cycle.
    pub(super) history: Vec<f64>,
    /// The state of the lowest residual.
    pub(super) best: State,
    /// That residual.
    pub(super) best_residual: f64,
    /// The cycle at which a non-finite value appeared, if one did.
    pub(super) non_finite: Option<usize>,
}

/// The observer's view of level `k` after a cycle that started from pressure `before`.
pub(super) fn cycle_progress(
    mg: &mut Hierarchy,
    k: usize,
    cycle: usize,
    before: &[f64],
) -> Progress {
    let (residual, worst_at) = mg.residual_norm(k);
    let level = &mg.levels[k];
    Progress {
        level: level.grid.level_number(),
        count: cycle,
        step: Step::Cycle,
        residual,
        load_error: (level.load_defect() / LOAD).abs(),
        pressure_change: mean_change(&level.p, before),
        h_central: level.h_central(),
        worst_at,
    }
}

/// V-cycles on level `k` as the top of the hierarchy until they converge, diverge, stall
/// (when the Newton-Krylov finish can take over) or run out.
pub(super) fn converge_by_cycles(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    windows: StallWindows,
    known: &Known,
    observe: &mut dyn FnMut(&Progress),
) -> Cycles {
    let mut history = Vec::new();
    // The mean pressure change of each cycle: the other measure of convergence.
    let mut changes = Vec::new();
    let mut best = State::of(mg, k);
    let mut best_residual = f64::INFINITY;
    let mut alternation = Alternation::default();
    // A warm start's own outputs count as the first entry of their history ([`super::warm`]).
    let mut outputs = stopping::OutputHistory::new(known);
    // A fitted far field is refitted once at the start and then each time the cycles have
    // converged with the edge as it stands, until its amplitude settles (refitting before
    // every cycle moved the edge under the cycles: the Table 4 case stalled at a residual
    // of 6e-2 at the inlet corner and took 56 Newton steps, 34 s, against 17 cycles).
    let fitted = params.edge == Edge::FittedFarField;
    let mut refits = 0;
    let mut last_outputs: Option<[f64; 3]> = None;
    if fitted {
        mg.fit_far_field(k);
    }
    for cycle in 1..=params.multigrid.max_cycles {
        let before = mg.levels[k].p.clone();
        mg.cycle(k);
        let progress = cycle_progress(mg, k, cycle, &before);
        observe(&progress);
        let residual = progress.residual;
        history.push(residual);
        let level = &mg.levels[k];
        if !residual.is_finite() || !mg.delta.is_finite() || level.p.iter().any(|v| !v.is_finite())
        {
            return Cycles {
                converged: false,
                history,
                best,
                best_residual,
                non_finite: Some(cycle),
            };
        }
        if residual < best_residual {
            best_residual = residual;
            best = State::of(mg, k);
        }
        changes.push(progress.pressure_change);
        if windows.weigh_alternation
            && alternation.push(&level.p, &before)
            && !stopping::residual_falls(&history)
        {
            mg.levels[k].correction_weight = DAMPED_CORRECTION;
        }
        // A residual a thousand times above the best one seen is divergence, not noise. A
        // stall ends the cycles only where the Newton-Krylov finish can take over;
        // otherwise they run on (some cases converge after a long noisy stretch).
        let stall = params.newton.steps > 0 && windows.stalled(&history, &changes);
        if residual > DIVERGENCE_FACTOR * best_residual || stall {
            break;
        }
        if params.stopping.output_tolerance > 0.0 {
            outputs.push(stop_outputs(mg, k, params), residual);
        }
        // With the outputs' rule on, only settled outputs end the cycles: a residual below
        // its tolerance, or a pressure change below its own, can come while an output is
        // still far off (a side-lobe minimum film of a heavy contact).
        let rule = params.stopping.output_tolerance > 0.0;
        let settled = rule && outputs.settled(params.stopping.output_tolerance);
        let still = if rule {
            settled
        } else {
            progress.pressure_change < params.stopping.pressure_tolerance
        };
        let residual_done = residual < params.stopping.tolerance && (settled || !rule);
        if still
            && residual >= params.stopping.tolerance
            && params.newton.steps > 0
            && !stopping::residual_falls(&history)
            && !known.start.is_some_and(|w| w.accepts(residual))
        {
            if history.len() < stopping::FALL_WINDOW {
                // Too few cycles to tell a fixed point from a start (the first cycles after
                // an edge is put anew change the pressure little while its residual falls):
                // cycle on.
                continue;
            }
            // Settled on a fixed point of the cycle that is not a solution: the Newton-Krylov
            // finish takes over ([`stopping::residual_falls`]).
            break;
        }
        if (residual_done || still) && progress.load_error < params.stopping.load_tolerance {
            if fitted && refits < FAR_FIELD_ROUNDS {
                let now = edge_outputs(mg, k, params);
                let settled_outputs = last_outputs.is_some_and(|o| outputs_settled(&o, &now));
                last_outputs = Some(now);
                if !settled_outputs && mg.fit_far_field(k) >= FAR_FIELD_SETTLED {
                    // The edge moved: the outputs' history and the residual's best start
                    // again (the residual at the inlet corner jumps with the edge).
                    refits += 1;
                    outputs = stopping::OutputHistory::new(&Known {
                        start: None,
                        ..*known
                    });
                    best_residual = f64::INFINITY;
                    continue;
                }
            }
            return Cycles {
                converged: true,
                history,
                best,
                best_residual,
                non_finite: None,
            };
        }
    }
    Cycles {
        converged: false,
        history,
        best,
        best_residual,
        non_finite: None,
    }
}

/// The weight of the coarse-grid correction into a level whose cycles alternate
/// ([`Alternation`]). Where a sharp pressure front (the side of a high-`L` contact's
/// horseshoe-shaped spike) is resolved on the top level but not on the one below, the
/// coarse-grid correction moves the front by a cell and the relaxation moves it back: the
/// cycle has an eigenvalue at or below -1 and locks into a period-two oscillation. A weight
/// `w` takes an eigenvalue `l` to `1 - w (1 - l)`; 0.5-0.7 cured the measured families, 0.8
/// did not, and only an alternating level is weighted, since the weight slows healthy cycles
/// (docs/ACCURACY_NOTES.md, "Why the new level-8 solves needed Newton-Krylov, and the
/// weighted correction").
pub(super) const DAMPED_CORRECTION: f64 = 0.6;

/// Cosine between two successive cycles' pressure changes below which they alternate.
const ALTERNATING_COSINE: f64 = -0.9;

/// Successive cycles whose changes must alternate ([`ALTERNATING_COSINE`]) before the
/// correction is weighted: the three families above alternate at cosines below -0.95 from
/// their fourth or fifth cycle at level 8 on.
const ALTERNATING_CYCLES: usize = 3;

/// Watches a level's cycles for a period-two oscillation ([`DAMPED_CORRECTION`]).
#[derive(Default)]
struct Alternation {
    /// The last cycle's pressure change.
    last: Vec<f64>,
    /// The Euclidean norm of every cycle's pressure change.
    norms: Vec<f64>,
    /// Successive cycles so far whose changes alternate.
    run: usize,
}

impl Alternation {
    /// Records the cycle that took the pressure from `before` to `p`; whether the cycles
    /// now alternate without the pressure change (its Euclidean norm) falling by the
    /// residual's factor over two cycles ([`stopping::residual_falls`]; the caller also reads
    /// the residual's fall). Cycles whose changes alternate while either still falls
    /// converge, and their results are not touched; the three families' changes and
    /// residuals stood still or grew.
    fn push(&mut self, p: &[f64], before: &[f64]) -> bool {
        let first = self.last.is_empty();
        if first {
            self.last.resize(p.len(), 0.0);
        }
        // The change and its products with the last one in one pass, kept in place of it.
        let (mut dot, mut squares) = (0.0, 0.0);
        for ((last, a), b) in self.last.iter_mut().zip(p).zip(before) {
            let change = a - b;
            dot += change * *last;
            squares += change * change;
            *last = change;
        }
        let norm: f64 = squares.sqrt();
        let last_norm = self.norms.last().copied().unwrap_or(0.0);
        let alternates = !first && dot < ALTERNATING_COSINE * norm * last_norm && norm > 0.0;
        self.run = if alternates { self.run + 1 } else { 0 };
        self.norms.push(norm);
        self.run >= ALTERNATING_CYCLES && !stopping::residual_falls(&self.norms)
    }
}

/// Residual growth over the best cycle that stops the solve as diverged.
const DIVERGENCE_FACTOR: f64 = 1e3;

/// Level `k` of `mg` made its top from a converged pressure `p` and film constant `delta`: the
/// pressure first, then the edge (the far field is put on the boundary for `delta`), and the
/// film and coefficients of `p` (those of the level's last visit as a coarse grid, or none, are
/// not its own). Returns the warm stop its cycles compare with, its outputs read from that
/// film, where the solution's last `residual` is known ([`WarmStop`]): a member's finest
/// level from its base's, a ladder's rung from the base's same level, a top refined across
/// the rolling direction from the base's.
pub(super) fn from_converged(
    mg: &mut Hierarchy,
    k: usize,
    (p, delta): (&[f64], f64),
    residual: Option<f64>,
    params: &Params,
) -> Option<WarmStop> {
    mg.levels[k].p.copy_from_slice(p);
    mg.delta = delta;
    mg.make_top(k);
    mg.refresh(k);
    residual.map(|residual| WarmStop {
        outputs: stop_outputs(mg, k, params),
        residual,
    })
}

/// Central and minimum film, sliding and rolling `mu-bar` (0 where it is not computed) of
/// level `k`: what the outputs' stopping rule reads ([`stopping::OutputHistory`]).
pub(super) fn stop_outputs(mg: &Hierarchy, k: usize, params: &Params) -> [f64; 4] {
    let level = &mg.levels[k];
    let film = friction::film(level, 1.0);
    let mu = friction::friction(level, &mg.model, mg.rolling_scale, params.friction.region);
    [
        film.h_central,
        film.h_min,
        mu.sliding,
        mu.rolling.unwrap_or(0.0),
    ]
}

/// The outputs a far field's refits are judged by: central and minimum film and sliding
/// friction of level `k`.
pub(super) fn edge_outputs(mg: &Hierarchy, k: usize, params: &Params) -> [f64; 3] {
    let level = &mg.levels[k];
    let film = friction::film(level, 1.0);
    let mu = friction::friction(level, &mg.model, None, params.friction.region);
    [film.h_central, film.h_min, mu.sliding]
}

/// Whether every output moved by less than [`FAR_FIELD_OUTPUTS_SETTLED`], relative.
pub(super) fn outputs_settled(before: &[f64; 3], after: &[f64; 3]) -> bool {
    before
        .iter()
        .zip(after)
        .all(|(b, a)| (a - b).abs() <= FAR_FIELD_OUTPUTS_SETTLED * a.abs())
}

/// A fitted far field also counts as settled when the last refit moved the outputs (central and
/// minimum film, sliding friction) by less than this, relative: a tenth of the solver's output
/// tolerance ([`stopping::OUTPUT_TOLERANCE`]), so that with the refits' measured contraction (about
/// 0.9 per round where the fit ring is slaved to the edge: M 20, L 30 at level 7 drifts 1e-5 per
/// round) the drift left is below that tolerance.
const FAR_FIELD_OUTPUTS_SETTLED: f64 = 5e-5;

#[cfg(test)]
mod tests {
    use super::{Alternation, StallWindows, ALTERNATING_CYCLES};

    const WINDOWS: StallWindows = StallWindows {
        stall: 15,
        early: 6,
        weigh_alternation: false,
    };

    #[test]
    fn cycles_that_never_get_going_stall_at_the_early_cycle() {
        // The first finest-level cycles of the 5P4E case (60 C, 3 GPa, 12 m/s, level 7): no
        // cycle halves the first residual, nor the first pressure change (0.53 at best).
        let residuals = [2.573e-2, 2.023e-2, 1.893e-2, 1.807e-2, 1.883e-2, 2.708e-2];
        let changes = [1.483e-3, 1.038e-3, 9.278e-4, 7.883e-4, 9.454e-4, 1.108e-3];
        assert!(!WINDOWS.stalled(&residuals[..5], &changes[..5]));
        assert!(WINDOWS.stalled(&residuals, &changes));
        // Off: they run on.
        let off = StallWindows {
            early: 0,
            ..WINDOWS
        };
        assert!(!off.stalled(&residuals, &changes));
    }

    #[test]
    fn cycles_that_halve_either_measure_early_run_on() {
        // The heaviest converging case (mineral oil A, 60 C, 3 GPa, 2 m/s, level 7) halves
        // its residual at the third cycle; one measure that halves is enough.
        let residuals = [3.723e-2, 2.542e-2, 1.561e-2, 9.010e-3, 5.060e-3, 2.817e-3];
        let flat = [1.0; 6];
        assert!(!WINDOWS.stalled(&residuals, &flat));
        assert!(!WINDOWS.stalled(&flat, &residuals));
        // The early rule looks at the early cycle only, not at later ones.
        let mut long = vec![1.0; 10];
        long[2] = 0.4;
        assert!(!WINDOWS.stalled(&long, &long));
    }

    #[test]
    fn cycles_that_stop_converging_stall_after_the_window() {
        // Halving for five cycles, then fifteen without a new half: stalled.
        let mut residuals: Vec<f64> = (0..5).map(|i| 0.5f64.powi(i + 1)).collect();
        residuals.extend(std::iter::repeat_n(0.03, 15));
        assert!(WINDOWS.stalled(&residuals, &residuals));
        assert!(!WINDOWS.stalled(&residuals[..19], &residuals[..19]));
    }

    /// Pressures `p_n = base + a_n mode` for the amplitudes `a_n` of a mode: what
    /// [`Alternation`] sees of cycles dominated by it.
    fn alternation_of(amplitudes: &[f64]) -> Vec<bool> {
        let mode = [0.3, -1.0, 0.5, 0.0, 2.0];
        let at = |a: f64| mode.iter().map(|m| 1.0 + a * m).collect::<Vec<_>>();
        let mut watch = Alternation::default();
        amplitudes
            .windows(2)
            .map(|w| watch.push(&at(w[1]), &at(w[0])))
            .collect()
    }

    #[test]
    fn cycles_locked_in_a_period_two_oscillation_alternate() {
        // Fig. 5 case 5's level 8: the same state every other cycle (cosine -1.000 between
        // successive changes, the change standing at 3.1e-5). Weighted once three changes
        // alternate (the fourth cycle: the first has no change before it) and the change no
        // longer falls.
        let locked: Vec<f64> = (0..8)
            .map(|n| if n % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let seen = alternation_of(&locked);
        let first = seen.iter().position(|&s| s).expect("it alternates");
        assert_eq!(first, ALTERNATING_CYCLES, "{seen:?}");
        // A growing oscillation (Fig. 6 case 82's level 8) too.
        let growing: Vec<f64> = (0..8).map(|n| (-1.1f64).powi(n)).collect();
        assert!(alternation_of(&growing).iter().any(|&s| s));
    }

    #[test]
    fn cycles_that_converge_are_left_alone() {
        // An alternating mode that decays at 0.6 a cycle (0.36 over two) converges: no
        // weight. Nor a mode that decays without alternating, however slowly.
        let decaying: Vec<f64> = (0..12).map(|n| (-0.6f64).powi(n)).collect();
        assert!(alternation_of(&decaying).iter().all(|&s| !s));
        let creeping: Vec<f64> = (0..12).map(|n| 0.99f64.powi(n)).collect();
        assert!(alternation_of(&creeping).iter().all(|&s| !s));
    }
}

//! The isothermal elliptical EHL contact with Eyring rheology (Sec. II of the paper), solved
//! by full-approximation-scheme multigrid with a full-multigrid start from the Hertzian
//! pressure (Venner and Lubrecht, "Multilevel Methods in Lubrication", 2000):
//!
//! - Reynolds, Eq. (1), second-order central Poiseuille terms and a second-order upstream
//!   wedge term; cavitation by `P = max(P, 0)`;
//! - film, Eq. (6), with the deformation evaluated exactly on each grid by zero-padded FFT
//!   ([`crate::solver::deformation`]);
//! - line relaxation switching between Gauss-Seidel and Jacobi distributive ([`relax`]);
//! - the force balance, Eq. (7), relaxed on the coarsest grid through `Delta`.
//!
//! The domain defaults to the paper's `-2.5 <= X <= 1.5`, `-2 <= Y <= 2`
//! ([`Domain::default`]); level `n` has `2^(n+1)` intervals per direction.

mod far_field;
mod friction;
mod jacobian;
mod level;
mod multigrid;
mod newton;
mod relax;
mod stopping;
mod transfer;
mod warm;

use crate::physics::case::Problem;
use crate::physics::film::{hc_eq10, hc_nijenbanning};
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::{
    mean_change, Film, Friction, Info, Method, Progress, SolveError, StartKind, Step,
};
use far_field::FarField;
pub use friction::{FrictionRegion, LOADED_FILM_FACTOR};
use level::Model;
/// The applied load in `P` and `X, Y` units, `2 pi / 3` (Eq. 7).
pub(crate) use level::LOAD;
use multigrid::Hierarchy;
use std::time::Instant;
pub use warm::Start;

/// Revision of the point-contact numerics: part of every cache key, bumped whenever a change
/// can move a result.
pub const SOLVER_REVISION: &str = "point-16";

/// Highest level the solver accepts (1024 x 1024: 8.4 M nodes of working arrays).
pub const MAX_LEVEL: u32 = 9;
/// Lowest level the solver accepts as the finest.
pub const MIN_LEVEL: u32 = 3;
/// Most refits of a fitted far field ([`Edge::FittedFarField`]) per level, each followed by
/// the cycles or a Newton-Krylov solve with the new edge.
const FAR_FIELD_ROUNDS: usize = 8;
/// A fitted far field counts as settled when its fit moves the amplitude by less than this,
/// relative ...
const FAR_FIELD_SETTLED: f64 = 1e-4;
/// ... or when the last refit moved the outputs (central and minimum film, sliding
/// friction) by less than this, relative: a tenth of the solver's output tolerance
/// ([`stopping::OUTPUT_TOLERANCE`]), so that with the refits' measured contraction (about
/// 0.9 per round where the fit ring is slaved to the edge: M 20, L 30 at level 7 drifts
/// 1e-5 per round) the drift left is below that tolerance.
const FAR_FIELD_OUTPUTS_SETTLED: f64 = 5e-5;
/// Residual growth over the best cycle that stops the solve as diverged.
const DIVERGENCE_FACTOR: f64 = 1e3;

/// The condition on the domain's edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    /// `P = 0`, the paper's.
    Zero,
    /// The flooded inlet's asymptote, its amplitude fixed a priori from `lambda`, and the
    /// load it carries outside taken off the force balance ([`far_field`]).
    FarField,
    /// [`Edge::FarField`] with its amplitude fitted to the solution a few cells inside the
    /// edge, before each finest cycle and between Newton-Krylov solves.
    FittedFarField,
}

/// Solver parameters, with the defaults of the paper's working resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// Finest level: `2^(level+1)` intervals per direction. Default 7 (256 x 256).
    pub level: u32,
    /// Coarsest level of the hierarchy (lowered to `level` if above it). Default 4
    /// (32 x 32): at the paper's heaviest loads a 16 x 16 grid no longer represents the smooth
    /// error and the cycles slow down (Table 4 case, level 7: 33 V-cycles from level 3, 20
    /// from level 4).
    pub coarsest_level: u32,
    /// Computational domain.
    pub domain: Domain,
    /// The condition on the domain's edge ([`Edge`]). Default [`Edge::Zero`], the paper's
    /// `P = 0`, for studies of the numerics on a fixed domain; a case is solved with the
    /// fitted far field ([`Params::for_problem`]).
    pub edge: Edge,
    /// Relaxations before coarsening. Default 2.
    pub pre_sweeps: usize,
    /// Relaxations after the correction. Default 1.
    pub post_sweeps: usize,
    /// Relaxations on the coarsest grid per visit. Default 50. The coarsest sweeps converge
    /// at about 0.975 each, so a visit's 50 reduce its error fourfold, below the cycle's own
    /// factor (0.6-0.68), and more are not repaid: on 25 cases (Table 4, five lubricants
    /// and temperatures at two loads and two speeds from their bases, four Moes cases) 50
    /// sweeps instead of 100 solved the same cases at levels 5, 6 and 7 in 32 %, 17 % and
    /// 11 % less time, the outputs within 1.3e-4, 2.1e-4 and 6.3e-5 of each other and the
    /// cycle counts the same but in five of the 66 solves that converged; the CI profile's
    /// snapshots moved by 1.9e-3 at most (a level-5 minimum film, M 1000, L 15).
    pub coarsest_sweeps: usize,
    /// Force-balance updates of `Delta` per visit of the coarsest grid, evenly among its
    /// sweeps. Default 10.
    pub coarsest_force_updates: usize,
    /// Gain of the force-balance update `Delta += gain * (int P - 2 pi / 3)`. Default 0.1.
    pub force_balance_gain: f64,
    /// Cycle index: 1 for V-cycles, 2 for W-cycles. Default 1.
    pub gamma: usize,
    /// Cycles on each intermediate level of the full-multigrid start. Default 2.
    pub fmg_cycles: usize,
    /// Most cycles on the finest level. Default 80: the Table 4 case converges in about 20,
    /// but the most heavily loaded cases of Table 2 (M ~ 1e4) converge at about 0.85 per
    /// cycle and need 50-70.
    pub max_cycles: usize,
    /// Convergence: the mean absolute Reynolds residual on the finest level. Default 1e-6.
    /// The Newton-Krylov finish stops on it; the cycles, where the outputs' rule is on
    /// ([`Params::output_tolerance`]), only with settled outputs: a heavy contact's
    /// side-lobe minimum film converges far more slowly than the mean residual falls (Fig. 4,
    /// mineral oil A at 100 C, 3 GPa, 7 m/s, M 7 506, level 7: residual 8e-7 after 22 cycles
    /// with `Hmin` 2 % off, its estimated error 17 %).
    pub tolerance: f64,
    /// Convergence, alternatively, where the outputs' rule is off: the mean absolute change
    /// of `P` over one finest cycle. On fine grids the residual can stall at a few nodes of
    /// tiny pressure on the cavitation boundary that flip in and out of it every cycle, with
    /// no effect on any output; the pressure change still measures the iteration error.
    /// Default 3e-7, which leaves the Table 4 film within 1e-4 (level 7) and 2e-5 (level 8)
    /// of its converged value.
    pub pressure_tolerance: f64,
    /// Convergence: relative force-balance error. Default 1e-4.
    pub load_tolerance: f64,
    /// Convergence, alternatively: the estimated relative algebraic error of the central
    /// film, the minimum film and the sliding and rolling friction ([`stopping`]). Default 5e-4, a
    /// hundredth of level 7's discretisation error in the film; 0 stops on the residual
    /// or the pressure change alone.
    pub output_tolerance: f64,
    /// Most Newton steps on each level of the Newton-Krylov finish ([`newton`]) that takes
    /// over when the cycles stall, diverge or run out; 0 turns the finish off. Default 30:
    /// the 5P4E hard case converges in 8-15 per level.
    pub newton_steps: usize,
    /// Level at which the finish's grid sequence starts (clamped to the hierarchy): the
    /// finish converges there, from that level's own cycles, then on each finer level from
    /// the interpolated solution of the one below, never from the stalled or diverged
    /// state of the finest cycles. Default 5 (64 x 64): there the cycles of the hardest
    /// cases stall rather than diverge, and a Newton step costs milliseconds.
    pub newton_start_level: u32,
    /// Half-width in cells of the box of elastic-kernel entries the finish's sparse
    /// preconditioner keeps. Default 2 (5 x 5): the feasibility study of the 5P4E Newton
    /// systems measured 8 GMRES iterations to 1e-2 at level 7 with it, none converging with
    /// a 3 x 3 box.
    pub box_radius: usize,
    /// Most GMRES iterations per Newton step. Default 200.
    pub krylov_iterations: usize,
    /// Cycles without the residual halving after which the cycles are taken as stalled and
    /// the Newton-Krylov finish starts. Default 15.
    pub stall_cycles: usize,
    /// Cycles after which the first cycles on the finest level (and on the grid sequence's
    /// first level) are taken as stalled when neither the residual nor the pressure change
    /// has fallen below half its first cycle's value; 0 turns the rule off. Default 6: every
    /// case the cycles converge halves both within three cycles on the 16-case battery
    /// (the heaviest, M = 11 070, by its third), while the cycles of the very viscous cases
    /// hover for 15 more cycles before the rule above ends them.
    pub early_stall_cycles: usize,
    /// The stall window of the grid sequence's first level (level 5), whose cycles only
    /// give Newton-Krylov a start and a Newton step costs about what a cycle does. Default 5:
    /// on the 5P4E cases they stall after about 8 cycles and ran 30 more at 15 ms with 15.
    pub sequence_stall_cycles: usize,
    /// Where the friction is integrated ([`FrictionRegion`]). Default the whole domain (the
    /// paper's Eq. 8), for studies of the numerics; a case is solved with the loaded film,
    /// which goes with the far field ([`Params::for_problem`]).
    pub friction_region: FrictionRegion,
    /// Compute the rolling (Poiseuille) part of the friction. Default true.
    pub rolling_friction: bool,
    /// Fail with [`SolveError::FilmCollapse`] when the minimum film is not positive (after
    /// the refinements below). Default true; Table 4 turns it off at level 5, where the
    /// paper itself reports a film an order of magnitude too thin.
    pub require_positive_film: bool,
    /// Finer levels the solver may add, one at a time, while the converged film is not
    /// positive: friction is never computed on a closed gap. Default 1: level 8 opens the
    /// film of the heaviest Table 2 loads that close at level 7 (M up to ~11 000). The
    /// level solved on is reported in [`Info::level`].
    pub film_refinement_levels: u32,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            level: 7,
            coarsest_level: 4,
            domain: Domain::default(),
            edge: Edge::Zero,
            pre_sweeps: 2,
            post_sweeps: 1,
            coarsest_sweeps: 50,
            coarsest_force_updates: 10,
            force_balance_gain: 0.1,
            gamma: 1,
            fmg_cycles: 2,
            max_cycles: 80,
            tolerance: 1e-6,
            pressure_tolerance: 3e-7,
            load_tolerance: 1e-4,
            output_tolerance: stopping::OUTPUT_TOLERANCE,
            newton_steps: 30,
            newton_start_level: 5,
            box_radius: 2,
            krylov_iterations: 200,
            stall_cycles: 15,
            early_stall_cycles: 6,
            sequence_stall_cycles: 5,
            friction_region: FrictionRegion::Domain,
            rolling_friction: true,
            require_positive_film: true,
            film_refinement_levels: 1,
        }
    }
}

impl Params {
    /// Default parameters at `level`, on the paper's domain whatever the case: for tests and
    /// studies of the numerics. A case is solved with [`Params::for_problem`].
    pub fn at_level(level: u32) -> Self {
        Params {
            level,
            ..Params::default()
        }
    }

    /// THE rule from a case to its solver parameters, which every command and pipeline uses
    /// (`repro solve`, `repro predict --solve`, the figure sweeps and studies, Table 4, the
    /// accuracy study, shards and benchmarks): the defaults at `level` on the domain the
    /// problem calls for ([`Domain::for_problem`]), with the flooded inlet's far field on its
    /// edge ([`Edge::FarField`]) and the friction of the loaded film
    /// ([`FrictionRegion::LoadedFilm`]), so that neither the film nor the friction depends on
    /// where the domain ends (`docs/DOMAIN_NOTES.md`). The far field's amplitude is the
    /// a-priori one: the domain keeps the load outside below 8 %, where fitting it moved
    /// film and friction by 0.05 % or less at level 7 on M 1, 5 and 50 and on Fig. 6 case 23;
    /// at M 20, L 30 by 0.4 % and 0.7 %, and there the a-priori edge is the better converged
    /// in the domain (doubling it moves film and friction 0.15 % and 0.17 %, the fitted
    /// 0.21 % and 0.49 %); the refits cost up to three times the solve. A path that needs a different
    /// parameter (Table 4's film check at level 5, an expert's `--domain`) sets it on top of
    /// this.
    pub fn for_problem(problem: &Problem, level: u32) -> Self {
        Params {
            level,
            domain: Domain::for_problem(problem),
            edge: Edge::FarField,
            friction_region: FrictionRegion::LoadedFilm,
            ..Params::default()
        }
    }
}

/// A converged point-contact solution.
#[derive(Debug, Clone)]
pub struct PointSolution {
    /// The finest grid.
    pub grid: Grid,
    /// Pressure `P = p/p_H` at the nodes.
    pub p: Vec<f64>,
    /// Film `H = h/c` at the nodes.
    pub h: Vec<f64>,
    /// The film constant `Delta` of Eq. (6).
    pub delta: f64,
    /// Central and minimum film.
    pub film: Film,
    /// Reduced friction.
    pub friction: Friction,
    /// The region the friction was integrated over ([`Params::friction_region`]).
    pub friction_region: FrictionRegion,
    /// Convergence information.
    pub info: Info,
}

/// When a run of cycles counts as stalled (see [`Params::stall_cycles`],
/// [`Params::early_stall_cycles`]).
#[derive(Debug, Clone, Copy)]
struct StallWindows {
    stall: usize,
    early: usize,
}

impl StallWindows {
    /// Whether cycles with these residuals and pressure changes (one per cycle so far) have
    /// stalled: both measures no lower than half their best for `stall` cycles, or, at
    /// cycle `early`, neither below half its first cycle's value.
    fn stalled(&self, residuals: &[f64], changes: &[f64]) -> bool {
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
fn stalled(history: &[f64], window: usize) -> bool {
    if window == 0 || history.len() <= window {
        return false;
    }
    let (before, recent) = history.split_at(history.len() - window);
    let best = |v: &[f64]| v.iter().cloned().fold(f64::INFINITY, f64::min);
    best(recent) > 0.5 * best(before)
}

/// A level's pressure and the film constant `Delta`: a start of the finish.
struct State {
    p: Vec<f64>,
    h0: f64,
}

impl State {
    fn of(mg: &Hierarchy, k: usize) -> Self {
        State {
            p: mg.levels[k].p.clone(),
            h0: mg.h0,
        }
    }

    fn restore(&self, mg: &mut Hierarchy, k: usize) {
        mg.levels[k].p.copy_from_slice(&self.p);
        mg.h0 = self.h0;
    }
}

/// What the cycles on the top level reached.
struct Cycles {
    converged: bool,
    /// Residual after each cycle.
    history: Vec<f64>,
    /// The state of the lowest residual.
    best: State,
    /// That residual.
    best_residual: f64,
    /// The cycle at which a non-finite value appeared, if one did.
    non_finite: Option<usize>,
}

/// The observer's view of level `k` after a cycle that started from pressure `before`.
fn cycle_progress(mg: &mut Hierarchy, k: usize, cycle: usize, before: &[f64]) -> Progress {
    let (residual, worst_at) = mg.residual_norm(k);
    let level = &mg.levels[k];
    Progress {
        level: level_number(level),
        count: cycle,
        step: Step::Cycle,
        residual,
        load_error: (level.load_defect() / LOAD).abs(),
        pressure_change: mean_change(&level.p, before),
        h_central: level.h_central(),
        worst_at,
    }
}

/// The level number of a grid (`2^(level+1)` intervals along `X`).
fn level_number(level: &level::Level) -> u32 {
    level.grid.nx.trailing_zeros() - 1
}

/// V-cycles on level `k` as the top of the hierarchy until they converge, diverge, stall
/// (when the Newton-Krylov finish can take over) or run out.
fn converge_by_cycles(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    windows: StallWindows,
    warm_stop: Option<&warm::WarmStop>,
    observe: &mut dyn FnMut(&Progress),
) -> Cycles {
    let mut history = Vec::new();
    // The mean pressure change of each cycle: the other measure of convergence.
    let mut changes = Vec::new();
    let mut best = State::of(mg, k);
    let mut best_residual = f64::INFINITY;
    // A warm start's own outputs count as the first entry of their history ([`warm`]).
    let mut outputs = match warm_stop {
        Some(w) => stopping::OutputHistory::from_start(w.outputs),
        None => stopping::OutputHistory::default(),
    };
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
    for cycle in 1..=params.max_cycles {
        let before = mg.levels[k].p.clone();
        mg.cycle(k);
        let progress = cycle_progress(mg, k, cycle, &before);
        observe(&progress);
        let residual = progress.residual;
        history.push(residual);
        let level = &mg.levels[k];
        if !residual.is_finite() || !mg.h0.is_finite() || level.p.iter().any(|v| !v.is_finite()) {
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
        // A residual a thousand times above the best one seen is divergence, not noise. A
        // stall ends the cycles only where the Newton-Krylov finish can take over;
        // otherwise they run on (some cases converge after a long noisy stretch).
        let stall = params.newton_steps > 0 && windows.stalled(&history, &changes);
        if residual > DIVERGENCE_FACTOR * best_residual || stall {
            break;
        }
        if params.output_tolerance > 0.0 {
            let film = friction::film(level, 1.0);
            let mu_bar =
                friction::friction(level, &mg.model, mg.rolling_scale, params.friction_region);
            outputs.push(
                film.h_central,
                film.h_min,
                mu_bar.sliding,
                mu_bar.rolling.unwrap_or(0.0),
            );
        }
        // With the outputs' rule on, only settled outputs end the cycles: a residual below
        // its tolerance, or a pressure change below its own, can come while an output is
        // still far off (a side-lobe minimum film of a heavy contact).
        let rule = params.output_tolerance > 0.0;
        let settled = rule && outputs.relative_error() < params.output_tolerance;
        let still = if rule {
            settled
        } else {
            progress.pressure_change < params.pressure_tolerance
        };
        let residual_done = residual < params.tolerance && (settled || !rule);
        if still
            && residual >= params.tolerance
            && params.newton_steps > 0
            && !stopping::residual_falls(&history)
            && !warm_stop.is_some_and(|w| w.accepts(residual))
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
        if (residual_done || still) && progress.load_error < params.load_tolerance {
            if fitted && refits < FAR_FIELD_ROUNDS {
                let now = edge_outputs(mg, k, params);
                let settled_outputs = last_outputs.is_some_and(|o| outputs_settled(&o, &now));
                last_outputs = Some(now);
                if !settled_outputs && mg.fit_far_field(k) >= FAR_FIELD_SETTLED {
                    // The edge moved: the outputs' history and the residual's best start
                    // again (the residual at the inlet corner jumps with the edge).
                    refits += 1;
                    outputs = stopping::OutputHistory::default();
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

/// The Newton-Krylov finish on level `k` (the top of the hierarchy) from its current
/// state; each step is reported and its residual appended to `history`.
fn finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
) -> newton::Outcome {
    let mut outcome = newton_solve(mg, k, params, observe, history);
    if params.edge != Edge::FittedFarField {
        return outcome;
    }
    // A fitted far field: Newton with the edge frozen, the amplitude refitted to its
    // solution, until the amplitude or the outputs settle (a few rounds; each a warm Newton
    // solve).
    let mut last = edge_outputs(mg, k, params);
    for _ in 0..FAR_FIELD_ROUNDS {
        if !outcome.converged || mg.fit_far_field(k) < FAR_FIELD_SETTLED {
            break;
        }
        let next = newton_solve(mg, k, params, observe, history);
        outcome = newton::Outcome {
            converged: next.converged,
            iterations: outcome.iterations + next.iterations,
            krylov_iterations: outcome.krylov_iterations + next.krylov_iterations,
        };
        let now = edge_outputs(mg, k, params);
        if outputs_settled(&last, &now) {
            break;
        }
        last = now;
    }
    outcome
}

/// The outputs a far field's refits are judged by: central and minimum film and sliding
/// friction of level `k`.
fn edge_outputs(mg: &Hierarchy, k: usize, params: &Params) -> [f64; 3] {
    let level = &mg.levels[k];
    let film = friction::film(level, 1.0);
    let mu = friction::friction(level, &mg.model, None, params.friction_region);
    [film.h_central, film.h_min, mu.sliding]
}

/// Whether every output moved by less than [`FAR_FIELD_OUTPUTS_SETTLED`], relative.
fn outputs_settled(before: &[f64; 3], after: &[f64; 3]) -> bool {
    before
        .iter()
        .zip(after)
        .all(|(b, a)| (a - b).abs() <= FAR_FIELD_OUTPUTS_SETTLED * a.abs())
}

/// One Newton-Krylov solve on level `k` with its edge as it stands.
fn newton_solve(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
) -> newton::Outcome {
    let model = mg.model;
    let mut h0 = mg.h0;
    let level = &mut mg.levels[k];
    let mut before = level.p.clone();
    let mut steps = 0;
    let outcome = newton::iterate(
        level,
        &model,
        &mut h0,
        &newton::Limits {
            steps: params.newton_steps,
            tolerance: params.tolerance,
            load_tolerance: params.load_tolerance,
            box_radius: params.box_radius,
            krylov_restart: KRYLOV_RESTART,
            krylov_iterations: params.krylov_iterations,
            first_forcing: if mg.warm {
                newton::warm_first_forcing(level_number(level))
            } else {
                newton::FIRST_FORCING
            },
        },
        &mut |level: &level::Level, step: &newton::Step| {
            steps += 1;
            history.push(step.residual);
            observe(&Progress {
                level: level_number(level),
                count: steps,
                step: Step::NewtonKrylov {
                    krylov_iterations: step.krylov_iterations,
                },
                residual: step.residual,
                load_error: step.load_error,
                pressure_change: mean_change(&level.p, &before),
                h_central: level.h_central(),
                worst_at: step.worst_at,
            });
            before.copy_from_slice(&level.p);
        },
    );
    mg.h0 = h0;
    outcome
}

/// The Newton-Krylov finish, grid-sequenced: level `newton_start_level` converged from
/// its state in `starts` (its cycles, then Newton where they stall), then Newton on each
/// finer level from the interpolated solution of the one below; `work` counts the steps.
/// Whether the finest level converged.
fn grid_sequence(
    mg: &mut Hierarchy,
    starts: &[State],
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
    work: &mut Work,
) -> bool {
    let top = mg.levels.len() - 1;
    let first = (params
        .newton_start_level
        .clamp(params.coarsest_level, params.level)
        - params.coarsest_level) as usize;
    // The saved state first, then its level made the top: the far-field edge follows the
    // restored film constant.
    starts[first].restore(mg, first);
    mg.make_top(first);
    let mut converged = false;
    if first < top {
        let windows = StallWindows {
            stall: params.sequence_stall_cycles,
            early: params.early_stall_cycles,
        };
        let run = converge_by_cycles(mg, first, params, windows, None, observe);
        converged = run.converged;
        if !converged {
            run.best.restore(mg, first);
        }
    }
    for k in first..=top {
        if k > first {
            mg.make_top(k);
            mg.interpolate(k);
            converged = false;
        }
        if !converged {
            converged = work.add(&finish(mg, k, params, observe, history));
        }
        if !converged {
            converged = polish_and_finish(mg, k, params, observe, history, work);
        }
        if !converged {
            return false;
        }
    }
    converged
}

/// A second try on level `k` after its Newton-Krylov finish stalled: the cycles relax its
/// state (their projection `P = max(P, 0)` settles the cavitation boundary where the
/// semi-smooth Newton steps cycle between active sets) and, unless they converge, Newton
/// starts again from their best state. M 0.13, L 47 (lambda 170) at level 6: one cycle and
/// two Newton steps to 6e-11, after 30 steps stalled at 0.11.
fn polish_and_finish(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    history: &mut Vec<f64>,
    work: &mut Work,
) -> bool {
    let windows = StallWindows {
        stall: params.sequence_stall_cycles,
        early: params.early_stall_cycles,
    };
    let run = converge_by_cycles(mg, k, params, windows, None, observe);
    history.extend(&run.history);
    if run.converged {
        return true;
    }
    run.best.restore(mg, k);
    work.add(&finish(mg, k, params, observe, history))
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

/// Newton-Krylov steps and GMRES iterations over the levels of a finish.
#[derive(Default)]
struct Work {
    newton_steps: usize,
    krylov_iterations: usize,
}

impl Work {
    /// Counts a level's outcome; whether it converged.
    fn add(&mut self, outcome: &newton::Outcome) -> bool {
        self.newton_steps += outcome.iterations;
        self.krylov_iterations += outcome.krylov_iterations;
        outcome.converged
    }
}

/// The best residual of stalled finest-level cycles below which the Newton-Krylov finish
/// starts on the finest level from their best state rather than from a coarse level: the
/// most heavily loaded Table 2 cases creep at ~0.97 per cycle below 1e-4 (mineral oil A,
/// 60 C, 3 GPa, 2 m/s at level 8), while the cycles of the very viscous cases stall at
/// 1e-2 or diverge.
const DIRECT_FINISH_RESIDUAL: f64 = 1e-3;

/// GMRES vectors kept before a restart: more than the preconditioned systems need (the
/// feasibility study: 20 iterations to 1e-6 at level 7), so restarts are rare.
const KRYLOV_RESTART: usize = 60;

/// Rounds of the far field's self-consistency on level `k` (the top, converged by
/// `method`). The edge takes the asymptote for the film constant of the moment its level
/// became the top (the coarser level's `Delta`, or a warm start's base's), and the converged
/// `Delta` differs; so the edge is put anew for the converged `Delta` and the solve
/// converged again from where it stands (cycles that stop on settled outputs, or Newton), until
/// the edge moves by less than [`EDGE_SETTLED`]. Without it the answer depended on the path
/// that reached it: Fig. 6's 5P4E at 1 GPa, 7 m/s, S 0.5 %, tau0 4 MPa at level 5 gave a
/// sliding `mu-bar` 0.8 % apart from a cold and from a warm start, both converged. Where
/// there is no far field, or it is fitted to the solution, nothing is done. False where a
/// reconvergence failed; the cycles and Newton work are counted.
#[allow(clippy::too_many_arguments)]
fn settle_edge(
    mg: &mut Hierarchy,
    k: usize,
    params: &Params,
    method: Method,
    newton_used: &mut bool,
    cycles: &mut usize,
    history: &mut Vec<f64>,
    work: &mut Work,
    observe: &mut dyn FnMut(&Progress),
) -> bool {
    if params.edge != Edge::FarField {
        return true;
    }
    for _ in 0..EDGE_ROUNDS {
        let (pressure, load) = mg.edge_drift(k);
        if pressure < EDGE_SETTLED && load < OUTSIDE_LOAD_SETTLED {
            return true;
        }
        let (residual, _) = mg.residual_norm(k);
        let level = &mg.levels[k];
        let film = friction::film(level, 1.0);
        let mu = friction::friction(level, &mg.model, mg.rolling_scale, params.friction_region);
        let stop = warm::WarmStop {
            outputs: [
                film.h_central,
                film.h_min,
                mu.sliding,
                mu.rolling.unwrap_or(0.0),
            ],
            residual,
        };
        mg.make_top(k);
        if method == Method::Cycles {
            let windows = StallWindows {
                stall: params.stall_cycles,
                early: 0,
            };
            let run = converge_by_cycles(mg, k, params, windows, Some(&stop), observe);
            *cycles += run.history.len();
            history.extend(&run.history);
            if run.converged {
                continue;
            }
            run.best.restore(mg, k);
        }
        *newton_used = true;
        if params.newton_steps == 0
            || !(work.add(&finish(mg, k, params, observe, history))
                || polish_and_finish(mg, k, params, observe, history, work))
        {
            return false;
        }
    }
    true
}

/// [`settle_edge`] on the top level, a failed reconvergence as the solve's error.
fn settle_top(
    mg: &mut Hierarchy,
    params: &Params,
    (method, newton_used): (Method, &mut bool),
    (cycles, history, work): (&mut usize, &mut Vec<f64>, &mut Work),
    observe: &mut dyn FnMut(&Progress),
) -> Result<(), SolveError> {
    let k = mg.levels.len() - 1;
    if settle_edge(
        mg,
        k,
        params,
        method,
        newton_used,
        cycles,
        history,
        work,
        observe,
    ) {
        Ok(())
    } else {
        Err(SolveError::NotConverged {
            cycles: *cycles,
            tolerance: params.tolerance,
            residual_history: history.clone(),
        })
    }
}

/// Most rounds of [`settle_edge`]: each changes the edge by the change of `Delta` that the
/// last edge change caused, a small fraction of it, so one or two suffice.
const EDGE_ROUNDS: usize = 4;

/// The largest change of an edge pressure, relative to the largest pressure, at which the
/// edge counts as settled. Measured (levels 5 and 7): where the edge moved by 6e-5 of the
/// largest pressure (the 5P4E case above) the sliding `mu-bar` moved by 0.8 %, about 130
/// times as much; 1e-7 keeps that below a hundredth of the output tolerance. The Appendix
/// case's edge moves by 9e-8 and is left alone; light cases take one round, rarely two.
const EDGE_SETTLED: f64 = 1e-7;

/// The outside load's change, relative to the applied load, at which the edge counts as
/// settled: a hundredth of the output tolerance, for the load the contact carries changes
/// by as much and the film responds to it with a factor below one.
const OUTSIDE_LOAD_SETTLED: f64 = 5e-6;

/// The cold solve's convergence on the top level: full multigrid from the Hertzian
/// pressure, the finest level's cycles, and where they stall the Newton-Krylov finish
/// (directly, or grid-sequenced); `history` holds what came before (a failed warm start).
fn converge_cold(
    problem: &Problem,
    params: &Params,
    observe: &mut dyn FnMut(&Progress),
    mut history: Vec<f64>,
) -> Result<(Hierarchy, Converged), SolveError> {
    let g = &problem.groups;
    // Initial Delta: the Eq. (10) central film minus the Hertzian approach (W(0) = 1).
    let h0 = hc_eq10(g.m, g.l) / g.moes_film_scale - 1.0;
    let mut mg = hierarchy(problem, params, h0);
    let top = mg.levels.len() - 1;
    // Full multigrid: Hertzian pressure on the coarsest grid, then each finer level starts
    // from the interpolated solution of the one below; each level's state after its cycles
    // is kept as a start for the finish's grid sequence.
    {
        let l0 = &mut mg.levels[0];
        let grid = l0.grid;
        l0.p = grid.sample(crate::physics::hertz::Hertz::pressure);
    }
    let mut starts = Vec::with_capacity(top);
    for k in 0..top {
        mg.make_top(k);
        if k > 0 {
            mg.interpolate(k);
        }
        // The coarsest level alone is solved once (its "cycle" is a full solve).
        let cycles = if k == 0 { 1 } else { params.fmg_cycles };
        for cycle in 1..=cycles {
            let before = mg.levels[k].p.clone();
            mg.cycle(k);
            observe(&cycle_progress(&mut mg, k, cycle, &before));
        }
        starts.push(State::of(&mg, k));
    }
    mg.make_top(top);
    if top > 0 {
        mg.interpolate(top);
    }
    let windows = StallWindows {
        stall: params.stall_cycles,
        early: params.early_stall_cycles,
    };
    let finest = converge_by_cycles(&mut mg, top, params, windows, None, observe);
    let cycles = finest.history.len();
    history.extend(&finest.history);
    let mut method = Method::Cycles;
    let mut work = Work::default();
    let mut converged = finest.converged;
    if !converged && params.newton_steps == 0 {
        if let Some(cycle) = finest.non_finite {
            return Err(SolveError::NonFinite {
                what: "pressure or residual",
                cycle,
                residual_history: history,
            });
        }
    }
    if !converged && params.newton_steps > 0 {
        method = Method::NewtonKrylov;
        // Cycles that crept close to the solution (a heavily loaded case converging too
        // slowly) hand their best state to Newton on the finest level; otherwise, or where
        // that fails, the grid sequence.
        if finest.best_residual < DIRECT_FINISH_RESIDUAL {
            finest.best.restore(&mut mg, top);
            converged = work.add(&finish(&mut mg, top, params, observe, &mut history));
        }
        if !converged {
            starts.push(finest.best);
            converged = grid_sequence(&mut mg, &starts, params, observe, &mut history, &mut work);
        }
    }
    if !converged {
        return Err(SolveError::NotConverged {
            cycles,
            tolerance: params.tolerance,
            residual_history: history,
        });
    }
    Ok((
        mg,
        Converged {
            cycles,
            history,
            method,
            work,
            start: StartKind::Cold,
        },
    ))
}

/// Solves `problem` with `params` from the Hertzian pressure (full multigrid); `observer` (if
/// any) hears of every cycle and Newton step.
pub fn solve(
    problem: &Problem,
    params: &Params,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    solve_with(problem, params, None, observer)
}

/// Solves `problem` with `params` from `start`, the converged solution of a related case (its
/// base: the same contact at another slip or Eyring stress, [`warm`]); where the warm solve
/// fails, or `start` does not fit the grid, from the Hertzian pressure as [`solve`] does
/// ([`Info::start`] says which).
pub fn solve_from(
    problem: &Problem,
    params: &Params,
    start: &Start,
    observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    solve_with(problem, params, Some(start), observer)
}

/// What converged the top level: its cycles, history, method and Newton work.
struct Converged {
    cycles: usize,
    history: Vec<f64>,
    method: Method,
    work: Work,
    start: StartKind,
}

/// A hierarchy for `problem` on `params`' levels and domain, the far field of its edge, and
/// the film constant `h0`.
fn hierarchy(problem: &Problem, params: &Params, h0: f64) -> Hierarchy {
    let model = Model::new(problem);
    let g = &problem.groups;
    // Without the far field: its lambda-0 form, zero everywhere.
    let far_lambda = if params.edge == Edge::Zero {
        0.0
    } else {
        g.lambda
    };
    let far = FarField::new(problem.shape, g.kappa, far_lambda, problem.viscosity);
    let mut mg = Hierarchy::new(model, far, &params.domain, params, h0);
    mg.rolling_scale = params.rolling_friction.then(|| g.rolling_stress_scale());
    mg
}

fn solve_with(
    problem: &Problem,
    params: &Params,
    warm_start: Option<&Start>,
    mut observer: Option<&mut dyn FnMut(&Progress)>,
) -> Result<PointSolution, SolveError> {
    let start = Instant::now();
    if !(MIN_LEVEL..=MAX_LEVEL).contains(&params.level) {
        return Err(SolveError::InvalidParams(format!(
            "level {} outside {MIN_LEVEL}..={MAX_LEVEL}",
            params.level
        )));
    }
    if params.coarsest_level < 2 || params.gamma == 0 {
        return Err(SolveError::InvalidParams(format!(
            "coarsest level {} must be at least 2, gamma {} positive",
            params.coarsest_level, params.gamma
        )));
    }
    let params = &Params {
        coarsest_level: params.coarsest_level.min(params.level),
        ..params.clone()
    };
    let g = &problem.groups;
    let mut observe = |p: &Progress| {
        if let Some(obs) = observer.as_mut() {
            obs(p)
        }
    };
    // A warm start that fits converges on its own level (a base refined to a finer level
    // takes the member there, with the refinements it has left); where it fails, the cold
    // solve from the Hertzian pressure, its attempt kept in the history.
    let warm_params = warm_start
        .filter(|s| s.fits(params))
        .map(|s| (s, warm::params_at(params, s.level)));
    let mut tried = Vec::new();
    let warm_run = warm_params
        .as_ref()
        .and_then(|(s, p)| warm::converge(problem, p, s, &mut observe, &mut tried));
    let (params, mut mg, run) = match (warm_run, &warm_params) {
        (Some((mg, run)), Some((_, p))) => (p, mg, run),
        _ => {
            let (mg, mut run) = converge_cold(problem, params, &mut observe, tried)?;
            if warm_params.is_some() {
                run.start = StartKind::Fallback;
            }
            (params, mg, run)
        }
    };
    let Converged {
        mut cycles,
        mut history,
        mut method,
        mut work,
        start: start_kind,
    } = run;
    // Whether a round of the edge needed Newton-Krylov: reported, while the refinement
    // below goes by how the level converged in the first place.
    let mut newton_used = false;

    // Each level, once converged, has its edge settled ([`settle_edge`]). A film that closes
    // somewhere (the side lobes of the most heavily loaded contacts, M above ~5000, where the
    // film is a thousandth of the Hertzian approach and the grid's error in the deformation
    // at the contact edge exceeds it) then asks for a finer grid: the converged solution
    // interpolated up, cycled there (where the cycles converged the level below), and
    // finished by Newton-Krylov from the better of the interpolated start and the cycles'
    // best state where they do not converge. (Newton-Krylov alone takes 7 steps of 4-5 s
    // each at level 8 on these cases; the cycles converge in about 20 of 0.2 s.)
    let mut refinements = 0;
    loop {
        settle_top(
            &mut mg,
            params,
            (method, &mut newton_used),
            (&mut cycles, &mut history, &mut work),
            &mut observe,
        )?;
        let closed = friction::film(mg.finest(), g.moes_film_scale).h_min <= 0.0;
        if !(params.require_positive_film
            && closed
            && refinements < params.film_refinement_levels
            && params.level + refinements < MAX_LEVEL)
        {
            break;
        }
        refinements += 1;
        let k = mg.add_finer_level(&params.domain);
        mg.make_top(k);
        mg.interpolate(k);
        if method == Method::Cycles {
            let start = State::of(&mg, k);
            let (start_residual, _) = mg.residual_norm(k);
            // A refined level starts from a converged solution: no early rule there (its
            // cycles may start slowly, and Newton-Krylov costs 4 s a step at level 8).
            let windows = StallWindows {
                stall: params.stall_cycles,
                early: 0,
            };
            let run = converge_by_cycles(&mut mg, k, params, windows, None, &mut observe);
            cycles += run.history.len();
            history.extend(&run.history);
            if run.converged {
                continue;
            }
            if run.best_residual < start_residual {
                run.best.restore(&mut mg, k);
            } else {
                start.restore(&mut mg, k);
            }
        }
        method = Method::NewtonKrylov;
        if !work.add(&finish(&mut mg, k, params, &mut observe, &mut history)) {
            return Err(SolveError::NotConverged {
                cycles,
                tolerance: params.tolerance,
                residual_history: history,
            });
        }
    }
    if newton_used {
        method = Method::NewtonKrylov;
    }
    let fine = mg.finest();
    let load_error = (fine.load_defect() / LOAD).abs();
    let film = friction::film(fine, g.moes_film_scale);
    if params.require_positive_film && film.h_min <= 0.0 {
        let level = level_number(fine);
        return Err(SolveError::FilmCollapse {
            h_min: film.h_min,
            level,
            level_needed: Some(level_to_resolve(problem, level, film.h_min)),
            finest_level: MAX_LEVEL,
            cycle: cycles,
            residual_history: history,
        });
    }
    let friction = friction::friction(fine, &mg.model, mg.rolling_scale, params.friction_region);
    if !friction.sliding.is_finite() || !friction.total().is_finite() {
        return Err(SolveError::NonFinite {
            what: "friction",
            cycle: cycles,
            residual_history: history,
        });
    }
    Ok(PointSolution {
        grid: fine.grid,
        p: fine.p.clone(),
        h: fine.h.clone(),
        delta: mg.h0,
        film,
        friction,
        friction_region: params.friction_region,
        info: Info {
            level: level_number(fine),
            method,
            cycles,
            newton_steps: work.newton_steps,
            krylov_iterations: work.krylov_iterations,
            residual_history: history,
            load_error,
            seconds: start.elapsed().as_secs_f64(),
            start: start_kind,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::StallWindows;

    const WINDOWS: StallWindows = StallWindows {
        stall: 15,
        early: 6,
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
}

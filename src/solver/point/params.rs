//! The solver's parameters and THE rule from a case to them ([`Params::for_problem`]).

use super::{stopping, FrictionRegion};
use crate::physics::case::Problem;
pub use crate::solver::gmres::KrylovParams;
use crate::solver::grid::Domain;
use crate::solver::richardson::ERROR_LEVELS;

/// The condition on the domain's edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    /// `P = 0`, the paper's.
    Zero,
    /// The flooded inlet's asymptote, its amplitude fixed a priori from `lambda`, and the
    /// load it carries outside taken off the force balance (the `far_field` module).
    FarField,
    /// [`Edge::FarField`] with its amplitude fitted to the solution a few cells inside the
    /// edge, before each finest cycle and between Newton-Krylov solves.
    FittedFarField,
}

/// Solver parameters, nested by stage, with the defaults of the paper's working resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    /// Finest level: `2^(level+1)` intervals per direction. Default 7 (256 x 256).
    pub level: u32,
    /// Computational domain.
    pub domain: Domain,
    /// The condition on the domain's edge ([`Edge`]). Default [`Edge::Zero`], the paper's
    /// `P = 0`, for studies of the numerics on a fixed domain; a case is solved with the
    /// far field of the a-priori amplitude, [`Edge::FarField`] ([`Params::for_problem`]).
    pub edge: Edge,
    /// Solve on a chain of nested domains inside `domain` ([`super::chain`]): the case-sized
    /// domain, then rectangles each a third of the one around it down to the contact's core,
    /// every one at `level`. Default false; the rule sets it where the domain has rectangles
    /// ([`Params::for_problem`]); a domain without any (an expert's `--domain`, Fig. 6's
    /// paper setup) is solved alone.
    pub nested: bool,
    /// Solve on a composite grid: the domain at `level` and these patches of it at half its
    /// mesh, coupled both ways (`composite`; `repro solve --patch inlet`, an expert's
    /// option: not the rule's, which stays within issue 39's cost). Default none.
    pub patch: Option<super::patch::PatchSet>,
    /// How the conductances meet at the half points of Eq. (1) on every level
    /// ([`super::HalfPointMean`]). Default the arithmetic mean.
    pub half_point: super::HalfPointMean,
    /// The multigrid cycles (`cycles`, `multigrid`).
    pub multigrid: MultigridParams,
    /// When a level is converged (`stopping`, and the Newton-Krylov finish).
    pub stopping: StoppingParams,
    /// The Newton-Krylov finish (`finish`, `newton`) where the cycles stall, diverge or run
    /// out.
    pub newton: NewtonParams,
    /// How the friction is integrated (`friction`).
    pub friction: FrictionParams,
    /// The discretisation error: its estimate, the refinement that meets a target, and the
    /// film check (`ladder`, `refine`).
    pub accuracy: AccuracyParams,
}

impl Default for Params {
    fn default() -> Self {
        Params {
            level: 7,
            domain: Domain::default(),
            edge: Edge::Zero,
            nested: false,
            patch: None,
            half_point: super::HalfPointMean::Arithmetic,
            multigrid: MultigridParams::default(),
            stopping: StoppingParams::default(),
            newton: NewtonParams::default(),
            friction: FrictionParams::default(),
            accuracy: AccuracyParams::default(),
        }
    }
}

/// The multigrid cycles (`cycles`, `multigrid`).
#[derive(Debug, Clone, PartialEq)]
pub struct MultigridParams {
    /// Coarsest level of the hierarchy (lowered to `level` if above it). Default 4
    /// (32 x 32): at the paper's heaviest loads a 16 x 16 grid no longer represents the smooth
    /// error and the cycles slow down (Table 4 case, level 7: 33 V-cycles from level 3, 20
    /// from level 4).
    pub coarsest_level: u32,
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
}

impl Default for MultigridParams {
    fn default() -> Self {
        MultigridParams {
            coarsest_level: 4,
            pre_sweeps: 2,
            post_sweeps: 1,
            coarsest_sweeps: 50,
            coarsest_force_updates: 10,
            force_balance_gain: 0.1,
            gamma: 1,
            fmg_cycles: 2,
            max_cycles: 80,
            stall_cycles: 15,
            early_stall_cycles: 6,
            sequence_stall_cycles: 5,
        }
    }
}

/// When a level is converged (`stopping`, and the Newton-Krylov finish).
#[derive(Debug, Clone, PartialEq)]
pub struct StoppingParams {
    /// Convergence: the mean absolute Reynolds residual on the finest level. Default 1e-6.
    /// The Newton-Krylov finish stops on it; the cycles, where the outputs' rule is on
    /// ([`StoppingParams::output_tolerance`]), only with settled outputs: a heavy contact's
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
    /// Convergence, alternatively: the estimated relative algebraic error of the central film, the
    /// minimum film and the sliding and rolling friction (the `stopping` module). Default 5e-4, a
    /// hundredth of level 7's discretisation error in the film; 0 stops on the residual or the
    /// pressure change alone.
    pub output_tolerance: f64,
}

impl Default for StoppingParams {
    fn default() -> Self {
        StoppingParams {
            tolerance: 1e-6,
            pressure_tolerance: 3e-7,
            load_tolerance: 1e-4,
            output_tolerance: stopping::OUTPUT_TOLERANCE,
        }
    }
}

/// The Newton-Krylov finish (`finish`, `newton`) where the cycles stall, diverge or run out.
#[derive(Debug, Clone, PartialEq)]
pub struct NewtonParams {
    /// Most Newton steps on each level of the Newton-Krylov finish (the `newton` module) that takes
    /// over when the cycles stall, diverge or run out; 0 turns the finish off. Default 30:
    /// the 5P4E hard case converges in 8-15 per level.
    pub steps: usize,
    /// Level at which the finish's grid sequence starts (clamped to the hierarchy): the
    /// finish converges there, from that level's own cycles, then on each finer level from
    /// the interpolated solution of the one below, never from the stalled or diverged
    /// state of the finest cycles. Default 5 (64 x 64): there the cycles of the hardest
    /// cases stall rather than diverge, and a Newton step costs milliseconds.
    pub start_level: u32,
    /// Half-width in cells of the box of elastic-kernel entries the finish's sparse
    /// preconditioner keeps, on levels up to 8. Default 2 (5 x 5): the feasibility study of
    /// the 5P4E Newton systems measured 8 GMRES iterations to 1e-2 at level 7 with it, none
    /// converging with a 3 x 3 box.
    pub box_radius: usize,
    /// The same on level 9 ([`super::MAX_LEVEL`]), where a box of `box_radius` cells reaches
    /// half as far as on level 8. Default 3 (7 x 7): on the M 35 900, L 2.55 thin film the
    /// 5 x 5 box left GMRES at its 200-iteration cap every Newton step and the residual at
    /// 1.5e-2; with 7 x 7 one step of 33 iterations converged level 9 (13 GB). A 9 x 9 box,
    /// level 8's reach, passed 21 GB before its first step (docs/hard-cases.md).
    pub finest_box_radius: usize,
    /// The GMRES solves of its linear systems.
    pub krylov: KrylovParams,
}

impl Default for NewtonParams {
    fn default() -> Self {
        NewtonParams {
            steps: 30,
            start_level: 5,
            box_radius: 2,
            finest_box_radius: 3,
            krylov: KrylovParams {
                restart: KRYLOV_RESTART,
                max_iterations: 200,
            },
        }
    }
}

impl NewtonParams {
    /// The preconditioner's box half-width on `level` ([`NewtonParams::box_radius`],
    /// [`NewtonParams::finest_box_radius`]).
    pub fn box_radius_on(&self, level: u32) -> usize {
        if level >= super::MAX_LEVEL {
            self.finest_box_radius
        } else {
            self.box_radius
        }
    }
}

/// How the friction is integrated (`friction`).
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionParams {
    /// Where the friction is integrated ([`FrictionRegion`]). Default the whole domain (the
    /// paper's Eq. 8), for studies of the numerics; a case is solved with the loaded film,
    /// which goes with the far field ([`Params::for_problem`]).
    pub region: FrictionRegion,
    /// Compute the rolling (Poiseuille) part of the friction. Default true.
    pub rolling: bool,
}

impl Default for FrictionParams {
    fn default() -> Self {
        FrictionParams {
            region: FrictionRegion::Domain,
            rolling: true,
        }
    }
}

/// The discretisation error: its estimate, the refinement that meets a target, and the film
/// check (`ladder`, `refine`).
#[derive(Debug, Clone, PartialEq)]
pub struct AccuracyParams {
    /// Coarser levels solved on their own after the finest, for the outputs' discretisation error
    /// ([`crate::solver::richardson`], the `ladder` module); 0 for none. Default 0 (studies of the
    /// numerics solve their levels themselves); a case is solved with 2, the three levels an
    /// observed order needs ([`Params::for_problem`]).
    pub error_levels: u32,
    /// The estimated discretisation errors the solve refines its grid to meet, within
    /// [`AccuracyParams::refinement_levels`] ([`super::AccuracyTarget`]; needs
    /// [`AccuracyParams::error_levels`]).
    /// Default none (studies of the numerics solve the level they are given); the rule sets 1 %
    /// in friction ([`super::AccuracyTarget::FRICTION`]): at `point-35` 334 of the paper's 1 369
    /// solves end on level 8 and 972 of the 989 rows of Figs. 1 and 3-7 are within 1 %
    /// (docs/ACCURACY_NOTES.md, "Refinement to a target", has what it cost).
    pub target: Option<super::AccuracyTarget>,
    /// Finer levels the solver may add, one at a time, while the converged film is not
    /// positive (friction is never computed on a closed gap) or the outputs' estimated error
    /// misses [`AccuracyParams::target`]. Default 1: level 8 opens the film of the heaviest
    /// Table 2 loads that close at level 7 (M up to ~11 000). The level solved on is reported in
    /// [`super::Info::level`].
    pub refinement_levels: u32,
    /// Fail with [`SolveError::FilmCollapse`] when the minimum film is not positive (after
    /// the refinements above). Default true; Table 4 turns it off at level 5, where the
    /// paper itself reports a film an order of magnitude too thin.
    pub require_positive_film: bool,
    /// Also give the final level's outputs tau-extrapolated ([`super::TauExtrapolated`],
    /// [`PointSolution::tau`](super::PointSolution::tau)). Where the ladder estimates the
    /// central film ([`AccuracyParams::error_levels`]), the solution reports the extrapolated
    /// central film, estimated by its distance to the levels' extrapolation
    /// ([`OutputErrors::tau_central`](crate::solver::output::OutputErrors::tau_central)); the
    /// other outputs and the refinement are the level's. Default false; the rule's true
    /// (docs/ACCURACY_NOTES.md, "The central film tau-extrapolated"). The uniform grid gives
    /// it; the nested chain and the composite grid give none.
    pub tau_extrapolation: bool,
}

impl AccuracyParams {
    /// Whether a solve on `level` that has added `refinements` finer levels may add one more:
    /// within [`AccuracyParams::refinement_levels`] and [`super::MAX_LEVEL`] (the uniform grid's
    /// and the nested chain's rule alike).
    pub(super) fn may_refine(&self, refinements: u32, level: u32) -> bool {
        refinements < self.refinement_levels && level < super::MAX_LEVEL
    }
}

impl Default for AccuracyParams {
    fn default() -> Self {
        AccuracyParams {
            error_levels: 0,
            target: None,
            refinement_levels: 1,
            require_positive_film: true,
            tau_extrapolation: false,
        }
    }
}

/// GMRES vectors kept before a restart: more than the preconditioned systems need (the
/// feasibility study: 20 iterations to 1e-6 at level 7), so restarts are rare.
const KRYLOV_RESTART: usize = 60;

impl Params {
    /// These parameters solving the level asked for and no other: no finer level for the
    /// accuracy target or a closed film, and no top refined across the rolling direction (the
    /// target dropped). `repro solve --exact-level` and the level study's points.
    pub fn exact_level(mut self) -> Self {
        self.accuracy.target = None;
        self.accuracy.refinement_levels = 0;
        self
    }

    /// These parameters solving their level alone, on one grid: [`Params::exact_level`]
    /// without nested domains, patch, error estimate, film check or tau-extrapolation. The
    /// composite grid's levels, and the studies that compare it with uniform levels.
    pub fn level_alone(self) -> Self {
        let mut this = self.exact_level();
        this.nested = false;
        this.patch = None;
        this.accuracy.error_levels = 0;
        this.accuracy.require_positive_film = false;
        this.accuracy.tau_extrapolation = false;
        this
    }

    /// Default parameters at `level`, on the paper's domain whatever the case: for tests and
    /// studies of the numerics. A case is solved with [`Params::for_problem`].
    pub fn at_level(level: u32) -> Self {
        Params {
            level,
            ..Params::default()
        }
    }

    /// THE rule from a case to its solver parameters, which every command and pipeline uses (`repro
    /// solve`, `repro predict --solve`, the figure sweeps and studies, Table 4, the accuracy study,
    /// shards and benchmarks): the defaults at `level` on the domain the problem calls for
    /// ([`Domain::for_problem`]), with the flooded inlet's far field on its edge
    /// ([`Edge::FarField`]) and the friction of the loaded film ([`FrictionRegion::LoadedFilm`]),
    /// so that neither the film nor the friction depends on where the domain ends
    /// (`docs/DOMAIN_NOTES.md`), and on a chain of nested domains where the case-sized domain
    /// reaches far beyond the contact ([`Params::nested`]: the light contacts, whose uniform grid
    /// is 3-5 times coarser in the contact than the paper's), refined one level where the sliding
    /// friction's estimated error misses 1 % ([`AccuracyParams::target`]). The far field's
    /// amplitude is the a-priori one: the domain keeps the load outside below 8 %, where fitting it
    /// moved film and friction by 0.05 % or less at level 7 on M 1, 5 and 50 and on Fig. 6 case 23;
    /// at M 20, L 30 by 0.4 % and 0.7 %, and there the a-priori edge is the better converged in the
    /// domain (doubling it moves film and friction 0.15 % and 0.17 %, the fitted 0.21 % and 0.49
    /// %); the refits cost up to three times the solve. A path that needs a different parameter
    /// (Table 4's film check at level 5, an expert's `--domain`) sets it on top of this.
    pub fn for_problem(problem: &Problem, level: u32) -> Self {
        let domain = Domain::for_problem(problem);
        Params {
            level,
            domain,
            edge: Edge::FarField,
            nested: !super::rectangles::rectangles(&domain).is_empty(),
            friction: FrictionParams {
                region: FrictionRegion::LoadedFilm,
                ..FrictionParams::default()
            },
            accuracy: AccuracyParams {
                error_levels: ERROR_LEVELS,
                target: Some(super::AccuracyTarget::RULE),
                tau_extrapolation: true,
                ..AccuracyParams::default()
            },
            ..Params::default()
        }
    }
}

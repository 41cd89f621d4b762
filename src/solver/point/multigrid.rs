//! The multigrid hierarchy and the FAS cycle with the force balance relaxed on the coarsest
//! grid (Venner and Lubrecht 2000).

use super::far_field::FarField;
use super::level::{LevelFields, Model, LOAD};
use super::nested::Surround;
use super::newton::KeptFactor;
use super::relax::{relax, LineScratch};
use super::transfer::{coarsen, correct, interpolate_solution, scale_tau};
use super::{Edge, Params};
use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use std::sync::Arc;

/// Levels from coarsest (index 0) to finest, the global film constant `Delta` (`delta`), and
/// the relaxation parameters.
#[derive(Debug)]
pub(crate) struct Hierarchy {
    pub levels: Vec<LevelFields>,
    pub model: Model,
    /// The flooded inlet beyond the domain.
    far: FarField,
    pub delta: f64,
    /// The scale of the rolling friction (`Problem`'s), where it is computed: the cycles'
    /// stopping rule watches it.
    pub rolling_scale: Option<f64>,
    /// The state started from a converged related solution ([`super::warm`]): the
    /// Newton-Krylov finish solves its first linear system tightly.
    pub warm: bool,
    /// Current gain of the force-balance update (adapted, see `relax_force_balance`).
    gain: f64,
    /// The load defect at the previous update.
    last_defect: f64,
    scratch: LineScratch,
    params: Params,
    /// The last converged Newton-Krylov factor of a level and that level's index: the next
    /// finish on the level (its edge round), or a member started from this solution, starts
    /// from it ([`super::newton::HANDED_ITERATIONS`]).
    factor: Option<(usize, KeptFactor)>,
}

impl Hierarchy {
    /// A hierarchy for `problem` on `params`' levels and domain, the far field of its edge
    /// (or the surroundings `surround` of a nested domain), and the film constant `delta`.
    pub fn for_problem(
        problem: &Problem,
        params: &Params,
        surround: Option<&Arc<Surround>>,
        delta: f64,
    ) -> Self {
        let model = Model::new(problem).with_half_point(params.half_point);
        let g = &problem.groups;
        // Without the far field: its lambda-0 form, zero everywhere.
        let far_lambda = if params.edge == Edge::Zero {
            0.0
        } else {
            g.lambda
        };
        let far = FarField::new(problem.shape, g.kappa, far_lambda, problem.viscosity)
            .with_surround(surround.cloned());
        let mut mg = Hierarchy::new(model, far, &params.domain, params, delta);
        mg.rolling_scale = params.friction.rolling.then(|| g.rolling_stress_scale());
        mg
    }

    /// Builds every level from `params.multigrid.coarsest_level` to `params.level` on `domain`.
    pub fn new(model: Model, far: FarField, domain: &Domain, params: &Params, delta: f64) -> Self {
        let levels = (params.multigrid.coarsest_level..=params.level)
            .map(|l| LevelFields::new(Grid::level(domain, l), &model))
            .collect();
        Hierarchy {
            levels,
            model,
            far,
            delta,
            rolling_scale: None,
            warm: false,
            gain: params.multigrid.force_balance_gain,
            last_defect: 0.0,
            scratch: LineScratch::new(),
            params: params.clone(),
            factor: None,
        }
    }

    /// The kept Newton-Krylov factor of level `k`, where there is one (taken: the finish
    /// that uses it keeps its own last one).
    pub fn take_factor(&mut self, k: usize) -> Option<KeptFactor> {
        match self.factor.take() {
            Some((level, factor)) if level == k => Some(factor),
            other => {
                self.factor = other;
                None
            }
        }
    }

    /// Keeps `factor` (a converged finish's last, or none) as level `k`'s.
    pub fn keep_factor(&mut self, k: usize, factor: Option<KeptFactor>) {
        self.factor = factor.map(|f| (k, f));
    }

    /// Adds a level twice as fine as the finest on `domain` and returns its index.
    pub fn add_finer_level(&mut self, domain: &Domain) -> usize {
        let level = self.finest().grid.nx.trailing_zeros();
        let grid = Grid::level(domain, level);
        self.levels.push(LevelFields::new(grid, &self.model));
        self.levels.len() - 1
    }

    /// Adds a top refined across the rolling direction above the finest level
    /// ([`Grid::refined_y`]: coarsened to it in `Y` alone, the transfers reading the ratio) and
    /// returns its index.
    pub fn add_across_level(&mut self) -> usize {
        let grid = self.finest().grid.refined_y();
        self.levels.push(LevelFields::new(grid, &self.model));
        self.levels.len() - 1
    }

    /// Sets the relaxations per visit of the coarsest grid; returns the previous number.
    pub fn set_coarsest_sweeps(&mut self, sweeps: usize) -> usize {
        std::mem::replace(&mut self.params.multigrid.coarsest_sweeps, sweeps)
    }

    pub fn finest(&self) -> &LevelFields {
        self.levels
            .last()
            .expect("a hierarchy has at least one level")
    }

    pub fn relax(&mut self, k: usize) {
        relax(
            &mut self.levels[k],
            &self.model,
            self.delta,
            &mut self.scratch,
        );
    }

    /// `Delta += gain * (sum P hx hy + rg)`: too much load lifts the surfaces. The load of a
    /// heavily loaded, highly viscous contact is very stiff in `Delta`; where the defect changes
    /// sign between updates the gain overshot and is halved, where it keeps its sign the gain
    /// grows back by 10 % towards `force_balance_gain`.
    fn relax_force_balance(&mut self, k: usize) {
        let defect = self.levels[k].load_defect();
        if defect * self.last_defect < 0.0 {
            self.gain *= 0.5;
        } else {
            self.gain = (self.gain * 1.1).min(self.params.multigrid.force_balance_gain);
        }
        self.last_defect = defect;
        self.delta += self.gain * defect;
    }

    /// Solves the coarsest level by many sweeps, with a force-balance update after each
    /// group of sweeps.
    fn solve_coarsest(&mut self) {
        let groups = self.params.multigrid.coarsest_force_updates.max(1);
        let per_group = self.params.multigrid.coarsest_sweeps.div_ceil(groups);
        for _ in 0..groups {
            for _ in 0..per_group {
                self.relax(0);
            }
            self.relax_force_balance(0);
        }
    }

    /// One FAS coarse-grid correction cycle on level `k` (`gamma = 1`: V, `2`: W).
    pub fn cycle(&mut self, k: usize) {
        if k == 0 {
            self.solve_coarsest();
            return;
        }
        for _ in 0..self.params.multigrid.pre_sweeps {
            self.relax(k);
        }
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            let fine = &mut hi[0];
            fine.refresh(self.delta, &self.model);
            coarsen(fine, &mut lo[k - 1], &self.model, self.delta);
        }
        for _ in 0..self.params.multigrid.gamma {
            self.cycle(k - 1);
        }
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            correct(&lo[k - 1], &mut hi[0]);
        }
        for _ in 0..self.params.multigrid.post_sweeps {
            self.relax(k);
        }
    }

    /// Tau-extrapolation of the converged top `k` ([`super::tau`]): its FAS coarse problem
    /// with the relative truncation error scaled by `factor`, solved by cycles until `done`
    /// says so (it sees the coarse level after each cycle, its film refreshed), its change
    /// added to the top without relaxing after it.
    ///
    /// The coarse problem's cycles start from the restricted top, or, where `start` gives a
    /// change from it of the coarse level's size (a related case's, [`super::tau`]), from the
    /// restricted top plus that change. Returns the coarse problem's solution as a change
    /// from the restricted top: its pressure at the coarse nodes and its film constant's.
    /// The coarser levels and the force balance's adaptation are put back as they were (the
    /// extrapolation works on fresh coarse levels), so that what the solve does next with
    /// them (its error ladder) is what it would have done without it.
    pub fn tau_extrapolate(
        &mut self,
        k: usize,
        factor: f64,
        start: Option<(&[f64], f64)>,
        mut done: impl FnMut(&LevelFields) -> bool,
    ) -> (Vec<f64>, f64) {
        let model = self.model;
        let fresh: Vec<LevelFields> = self.levels[..k]
            .iter()
            .map(|level| LevelFields::new(level.grid, &model))
            .collect();
        let kept: Vec<LevelFields> = self.levels.splice(..k, fresh).collect();
        let adaptation = (self.gain, self.last_defect);
        let natural = self.natural_film_rhs(&self.levels[k - 1].grid);
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            let fine = &mut hi[0];
            fine.refresh(self.delta, &model);
            coarsen(fine, &mut lo[k - 1], &model, self.delta);
            scale_tau(fine, &mut lo[k - 1], &natural, factor);
        }
        let delta = self.delta;
        let coarse = &mut self.levels[k - 1];
        if let Some((change, delta_change)) = start.filter(|(c, _)| c.len() == coarse.p.len()) {
            // The edge keeps the restricted far field.
            let g = coarse.grid;
            for j in 1..g.ny {
                for i in 1..g.nx {
                    let c = g.idx(i, j);
                    coarse.p[c] = (coarse.pold[c] + change[c]).max(0.0);
                }
            }
            self.delta += delta_change;
        }
        loop {
            self.cycle(k - 1);
            self.levels[k - 1].refresh(self.delta, &model);
            if done(&self.levels[k - 1]) {
                break;
            }
        }
        let coarse = &self.levels[k - 1];
        let change = coarse
            .p
            .iter()
            .zip(&coarse.pold)
            .map(|(p, r)| p - r)
            .collect();
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            correct(&lo[k - 1], &mut hi[0]);
        }
        self.levels[k].refresh(self.delta, &model);
        self.levels.splice(..k, kept);
        (self.gain, self.last_defect) = adaptation;
        (change, self.delta - delta)
    }

    /// Starts level `k` from the converged level `k - 1` (full multigrid).
    pub fn interpolate(&mut self, k: usize) {
        let (lo, hi) = self.levels.split_at_mut(k);
        interpolate_solution(&lo[k - 1], &mut hi[0]);
    }

    /// Makes level `k` the top of the hierarchy: its own equations, not a coarse-grid
    /// problem, with the far field of the present film constant on its boundary.
    pub fn make_top(&mut self, k: usize) {
        self.set_half_points(k);
        let hrhs = self.natural_film_rhs(&self.levels[k].grid);
        let level = &mut self.levels[k];
        level.hrhs = hrhs;
        level.f.iter_mut().for_each(|v| *v = 0.0);
        level.set_far_field(&self.far, self.delta);
    }

    /// The half points' means of a hierarchy topped by level `k`: the model's on `k`, the
    /// arithmetic mean on the levels below (and above, which are not part of its cycles).
    pub fn set_half_points(&mut self, k: usize) {
        let model = self.model;
        for (i, level) in self.levels.iter_mut().enumerate() {
            let mean = if i == k {
                model.half_point
            } else {
                super::HalfPointMean::Arithmetic
            };
            if level.half_point != mean {
                level.half_point = mean;
                level.invalidate();
            }
        }
    }

    /// The film equation's right-hand side of a top level on `grid`: the geometry and the far
    /// field's film offset.
    fn natural_film_rhs(&self, grid: &Grid) -> Vec<f64> {
        let (model, far) = (&self.model, &self.far);
        grid.sample(|x, y| model.geometry(x, y) + far.film_offset(x, y))
    }

    /// How far the far field on level `k`'s edge is from the one of the film constant as it
    /// is now: the largest change of an edge pressure, relative to the level's largest
    /// pressure, and the change of the load outside, relative to the applied load (both 0
    /// without a far field).
    pub fn edge_drift(&self, k: usize) -> (f64, f64) {
        let level = &self.levels[k];
        let g = level.grid;
        let now = g.sample_boundary(|x, y| self.far.pressure(x, y, self.delta));
        let largest = level.p.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let change = g
            .boundary()
            .map(|i| (now[i] - level.edge[i]).abs())
            .fold(0.0f64, f64::max);
        let outside = LOAD - self.far.outside_load(&g.domain(), self.delta);
        let pressure = if largest > 0.0 {
            change / largest
        } else {
            change
        };
        (pressure, (outside - level.load).abs() / LOAD)
    }

    /// Refits the far field's amplitude to level `k`'s pressure and puts the result on its
    /// edge and in its force balance; returns the amplitude's relative change.
    pub fn fit_far_field(&mut self, k: usize) -> f64 {
        let level = &mut self.levels[k];
        let change = self.far.fit(&level.grid, &level.p, self.delta);
        level.set_far_field(&self.far, self.delta);
        change
    }

    /// Film, coefficients and residual norm of level `k` for its current pressure, and where
    /// the largest residual is.
    pub fn residual_norm(&mut self, k: usize) -> (f64, (f64, f64)) {
        let level = &mut self.levels[k];
        level.refresh(self.delta, &self.model);
        level.residual_norm()
    }

    /// Brings level `k`'s film and coefficients up to its pressure and the film constant.
    pub fn refresh(&mut self, k: usize) {
        self.levels[k].refresh(self.delta, &self.model);
    }
}

//! The multigrid hierarchy of the line contact and the FAS cycle, with the force balance
//! relaxed on the coarsest grid (Venner and Lubrecht 2000).

use super::level::{Level, Model};
use super::relax::{relax, Scratch};
use super::transfer::{coarsen, correct, interpolate_solution};
use super::Params;

/// Levels from coarsest (index 0) to finest, the film constant `H0`, the model and the
/// cycle parameters.
#[derive(Debug)]
pub(crate) struct Hierarchy {
    pub levels: Vec<Level>,
    pub model: Model,
    pub h0: f64,
    scratch: Scratch,
    params: Params,
}

impl Hierarchy {
    /// Builds every level from `params.coarsest_level` to `params.level`.
    pub fn new(model: Model, params: &Params, h0: f64) -> Self {
        let d = params.domain;
        let levels = (params.coarsest_level..=params.level)
            .map(|l| Level::new(1usize << (l + 1), d.x_start, d.x_end))
            .collect();
        Hierarchy {
            levels,
            model,
            h0,
            scratch: Scratch::new(),
            params: params.clone(),
        }
    }

    pub fn finest(&self) -> &Level {
        self.levels
            .last()
            .expect("a hierarchy has at least one level")
    }

    /// Film and coefficients of level `k` for its current pressure.
    pub fn prepare(&mut self, k: usize) {
        let level = &mut self.levels[k];
        level.update_film(self.h0);
        level.update_coefficients(&self.model);
    }

    /// One relaxation sweep on level `k`.
    pub fn relax(&mut self, k: usize) {
        self.prepare(k);
        let before = self.levels[k].p.iter().cloned().fold(0.0, f64::max);
        relax(&mut self.levels[k], &mut self.scratch);
        let after = self.levels[k].p.iter().cloned().fold(0.0, f64::max);
        if std::env::var("LINE_TRACE").is_ok() && after > 3.0 * before.max(1.0) {
            let l = &self.levels[k];
            let i = (0..=l.n)
                .max_by(|&a, &b| l.p[a].partial_cmp(&l.p[b]).unwrap())
                .unwrap();
            eprintln!(
                "relax blowup level n={} max {before} -> {after} at X={} h={} xi={:?} h0={}",
                l.n,
                l.x(i),
                l.h[i],
                l.xi(i.clamp(1, l.n - 1)),
                self.h0
            );
        }
    }

    /// `H0 += gain * (sum P h + rg)`: too much load lifts the surfaces.
    fn relax_force_balance(&mut self, k: usize) {
        self.h0 += self.params.force_balance_gain * self.levels[k].load_defect();
    }

    /// Solves the coarsest level by many sweeps, with a force-balance update after each group
    /// of sweeps.
    fn solve_coarsest(&mut self) {
        let groups = self.params.coarsest_force_updates.max(1);
        let per_group = self.params.coarsest_sweeps.div_ceil(groups);
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
        for _ in 0..self.params.pre_sweeps {
            self.relax(k);
        }
        self.prepare(k);
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            coarsen(&hi[0], &mut lo[k - 1], &self.model, self.h0);
        }
        for _ in 0..self.params.gamma {
            self.cycle(k - 1);
        }
        {
            let (lo, hi) = self.levels.split_at_mut(k);
            correct(&lo[k - 1], &mut hi[0]);
        }
        for _ in 0..self.params.post_sweeps {
            self.relax(k);
        }
    }

    /// Starts level `k` from the converged level `k - 1` (full multigrid).
    pub fn interpolate(&mut self, k: usize) {
        let (lo, hi) = self.levels.split_at_mut(k);
        interpolate_solution(&lo[k - 1], &mut hi[0]);
    }

    /// Makes level `k` the top of the hierarchy: its own equations, not a coarse-grid problem.
    pub fn make_top(&mut self, k: usize) {
        let level = &mut self.levels[k];
        level.reset_geometry();
        level.f.iter_mut().for_each(|v| *v = 0.0);
        level.rg = -super::level::LOAD;
    }

    /// Residual norm of level `k` for its current pressure (film and coefficients updated).
    pub fn residual_norm(&mut self, k: usize) -> f64 {
        self.prepare(k);
        self.levels[k].residual_norm()
    }
}

//! One grid level of the point-contact problem: its fields, the film thickness equation
//! (Eq. 6), the coefficients and the discrete Reynolds operator (Eq. 1).

use super::far_field::FarField;
pub(crate) use super::model::{HalfPointMean, Model};
use crate::solver::deformation::Deformation;
use crate::solver::grid::Grid;

/// The dimensionless load of the force balance, Eq. (7): `int P dX dY = 2 pi / 3`.
pub(crate) use crate::physics::hertz::DIMENSIONLESS_LOAD as LOAD;

/// Fields of one level.
#[derive(Debug)]
pub(crate) struct LevelFields {
    pub grid: Grid,
    pub deformation: Deformation,
    /// Pressure `P`.
    pub p: Vec<f64>,
    /// Right-hand side of the Reynolds equation (zero on the finest level; FAS on coarser).
    pub f: Vec<f64>,
    /// Film thickness `H = Delta + hrhs + W`.
    pub h: Vec<f64>,
    /// The film equation's right-hand side: geometry on the finest level, FAS on coarser.
    pub hrhs: Vec<f64>,
    /// Elastic deformation `W`.
    pub w: Vec<f64>,
    /// The coarse-grid pressure as restricted, before the coarse cycle (for the correction).
    pub pold: Vec<f64>,
    /// Right-hand side of the force balance: `sum P hx hy + rg = 0`.
    pub rg: f64,
    /// The far-field pressure at the boundary nodes (zero inside): the domain's Dirichlet
    /// condition ([`super::far_field`]).
    pub edge: Vec<f64>,
    /// The load the domain carries: [`LOAD`] less the far field's outside the domain.
    pub load: f64,
    /// What a composite grid's patch carries beyond this level's own pressure over it, taken
    /// off the force balance with the far field's ([`super::composite`]; 0 elsewhere).
    pub load_correction: f64,
    /// `rho H^3 / (eta_x lambda)` at the nodes.
    pub ex: Vec<f64>,
    /// `kappa^2 rho H^3 / (eta_y lambda)` at the nodes.
    pub ey: Vec<f64>,
    /// Twice the half-point conductance between node `k` and `k + 1` (along `X`) and
    /// between `k` and `k + px` (along `Y`): the sum of the two nodes' for the arithmetic
    /// mean ([`super::model::HalfPointMean`]).
    pub ex_half: Vec<f64>,
    pub ey_half: Vec<f64>,
    /// Where the mean is not the arithmetic one: the derivatives of `ex_half[k]` in
    /// `ex[k]` and in `ex[k + 1]` (and of `ey_half`), for the Newton-Krylov Jacobian; empty
    /// for the arithmetic mean (both 1).
    pub ex_half_d: Vec<[f64; 2]>,
    pub ey_half_d: Vec<[f64; 2]>,
    /// The half-point mean of this level: the model's on the top level, the arithmetic one
    /// on the coarser levels of its cycles.
    pub half_point: HalfPointMean,
    /// `rho` at the nodes (all ones when incompressible).
    pub rho: Vec<f64>,
    /// `rho H` at the nodes.
    pub rh: Vec<f64>,
    /// `Delta` of the last [`LevelFields::refresh`] while film and coefficients are still those
    /// of [`LevelFields::refreshed_p`] (any other update clears it).
    refreshed_delta: Option<u64>,
    /// The pressure of the last [`LevelFields::refresh`].
    refreshed_p: Vec<f64>,
    /// The weight the coarse-grid correction into this level is added with: 1, or
    /// [`super::cycles::DAMPED_CORRECTION`] once its cycles as the top alternated
    /// ([`super::cycles`]).
    pub correction_weight: f64,
}

impl LevelFields {
    /// A level on `grid` with `P = 0` on its boundary and the whole load: the far field, if
    /// any, is put on it when it becomes the top ([`LevelFields::set_far_field`]).
    pub fn new(grid: Grid, model: &Model) -> Self {
        let n = grid.len();
        LevelFields {
            deformation: Deformation::new(&grid, model.kappa, model.ell_k),
            p: vec![0.0; n],
            f: vec![0.0; n],
            h: vec![0.0; n],
            hrhs: grid.sample(|x, y| model.geometry(x, y)),
            w: vec![0.0; n],
            pold: vec![0.0; n],
            rg: -LOAD,
            edge: vec![0.0; n],
            load: LOAD,
            load_correction: 0.0,
            ex: vec![0.0; n],
            ey: vec![0.0; n],
            ex_half: vec![0.0; n],
            ey_half: vec![0.0; n],
            ex_half_d: Vec::new(),
            ey_half_d: Vec::new(),
            half_point: HalfPointMean::Arithmetic,
            rho: vec![1.0; n],
            rh: vec![0.0; n],
            refreshed_delta: None,
            refreshed_p: Vec::new(),
            correction_weight: 1.0,
            grid,
        }
    }

    /// Film and coefficients for the current `P` and `delta`, recomputed only where either
    /// changed since the last refresh (bit for bit): a cycle's first sweep follows the
    /// residual evaluation of the same state, and one of the five updates of a V(2,1)
    /// cycle is saved.
    pub fn refresh(&mut self, delta: f64, model: &Model) {
        if self.refreshed_delta == Some(delta.to_bits()) && self.refreshed_p == self.p {
            return;
        }
        self.update_film(delta);
        self.update_coefficients(model);
        self.refreshed_p.clone_from(&self.p);
        self.refreshed_delta = Some(delta.to_bits());
    }

    /// Marks film and coefficients as stale for [`LevelFields::refresh`]: the film equation's
    /// right-hand side changed.
    pub fn invalidate(&mut self) {
        self.refreshed_delta = None;
    }

    /// Eq. (6): `H = Delta + hrhs + W(P)`.
    pub fn update_film(&mut self, delta: f64) {
        self.refreshed_delta = None;
        self.deformation.apply(&self.p, &mut self.w);
        for ((h, r), w) in self.h.iter_mut().zip(&self.hrhs).zip(&self.w) {
            *h = delta + r + w;
        }
    }

    /// Coefficients of Eq. (1) from the current `P` and `H`.
    pub fn update_coefficients(&mut self, m: &Model) {
        self.refreshed_delta = None;
        for k in 0..self.p.len() {
            let h = self.h[k];
            let (ex, ey, rho) = m.coefficients(self.p[k], h);
            self.ex[k] = ex;
            self.ey[k] = ey;
            self.rho[k] = rho;
            self.rh[k] = rho * h;
        }
        self.update_half_points(self.half_point);
    }

    /// The half-point conductances of the nodes' present ones ([`LevelFields::ex_half`]).
    fn update_half_points(&mut self, mean: HalfPointMean) {
        let (n, px) = (self.p.len(), self.grid.px());
        let arithmetic = mean == HalfPointMean::Arithmetic;
        for (half, d, node, step) in [
            (&mut self.ex_half, &mut self.ex_half_d, &self.ex, 1),
            (&mut self.ey_half, &mut self.ey_half_d, &self.ey, px),
        ] {
            // The arithmetic mean (every solve of the product) as a plain sum of neighbours,
            // no per-node dispatch; the others with their derivatives.
            if arithmetic {
                d.clear();
                for (h, (a, b)) in half.iter_mut().zip(node.iter().zip(&node[step..])) {
                    *h = a + b;
                }
                continue;
            }
            d.resize(n, [1.0, 1.0]);
            for k in 0..n - step {
                let (sum, da, db) = mean.twice(node[k], node[k + step]);
                half[k] = sum;
                d[k] = [da, db];
            }
        }
    }

    /// The derivatives of the half-point sums `(w, e, s, n)` of node `c` in the conductance
    /// of `c` itself and of the neighbour across each; `None` for the arithmetic mean (every
    /// one 1).
    #[inline]
    pub fn half_derivatives(&self, c: usize) -> Option<[[f64; 2]; 4]> {
        if self.ex_half_d.is_empty() {
            return None;
        }
        let px = self.grid.px();
        let (w, e) = (self.ex_half_d[c - 1], self.ex_half_d[c]);
        let (s, n) = (self.ey_half_d[c - px], self.ey_half_d[c]);
        Some([[w[1], w[0]], [e[0], e[1]], [s[1], s[0]], [n[0], n[1]]])
    }

    /// Half-point coefficients `(xi_w, xi_e, xi_s, xi_n)` at `(i, j)`, divided by `h^2`.
    #[inline]
    pub fn xi(&self, i: usize, j: usize) -> [f64; 4] {
        let g = &self.grid;
        let c = g.idx(i, j);
        let (rx2, ry2) = (0.5 / (g.hx * g.hx), 0.5 / (g.hy * g.hy));
        [
            self.ex_half[c - 1] * rx2,
            self.ex_half[c] * rx2,
            self.ey_half[c - g.px()] * ry2,
            self.ey_half[c] * ry2,
        ]
    }

    /// The wedge term `d(rho H)/dX` at `(i, j)`: second-order upstream, first order at `i = 1`.
    #[inline]
    pub fn wedge(&self, i: usize, j: usize) -> f64 {
        let g = &self.grid;
        let c = g.idx(i, j);
        if i >= 2 {
            (1.5 * self.rh[c] - 2.0 * self.rh[c - 1] + 0.5 * self.rh[c - 2]) / g.hx
        } else {
            (self.rh[c] - self.rh[c - 1]) / g.hx
        }
    }

    /// The discrete Reynolds operator `L(P)` at interior node `(i, j)` for pressure `p`, with
    /// the coefficients and film of the last update.
    #[inline]
    pub fn operator(&self, p: &[f64], i: usize, j: usize) -> f64 {
        let g = &self.grid;
        let c = g.idx(i, j);
        let [xw, xe, xs, xn] = self.xi(i, j);
        let pc = p[c];
        xw * (p[c - 1] - pc)
            + xe * (p[c + 1] - pc)
            + xs * (p[c - g.px()] - pc)
            + xn * (p[c + g.px()] - pc)
            - self.wedge(i, j)
    }

    /// Residual `f - L(P)` at interior node `(i, j)`.
    #[inline]
    pub fn residual(&self, i: usize, j: usize) -> f64 {
        self.f[self.grid.idx(i, j)] - self.operator(&self.p, i, j)
    }

    /// Mean absolute residual over the pressurised interior nodes (film and coefficients
    /// must be current), and where the largest one is.
    pub fn residual_norm(&self) -> (f64, (f64, f64)) {
        let g = &self.grid;
        let mut sum = 0.0;
        let (mut max, mut at) = (-1.0, (0.0, 0.0));
        for j in 1..g.ny {
            for i in 1..g.nx {
                if self.p[g.idx(i, j)] > 0.0 {
                    let r = self.residual(i, j).abs();
                    sum += r;
                    if r > max {
                        max = r;
                        at = (g.x(i), g.y(j));
                    }
                }
            }
        }
        (sum / ((g.nx - 1) * (g.ny - 1)) as f64, at)
    }

    /// Film `H` at the contact centre `X = Y = 0`: the node there on the paper's and the
    /// wide domain; on a domain where `X = 0` falls between two nodes (the heavy-load one),
    /// linear in `X` between them (`Y = 0` is a node of every symmetric grid).
    pub fn h_central(&self) -> f64 {
        self.grid.at_centre(&self.h)
    }

    /// The far field `far` for the film constant `delta` as this level's top-level boundary
    /// condition: its pressure on the boundary nodes ([`LevelFields::edge`], copied into `P`) and
    /// its outside load taken off the force balance ([`LevelFields::load`], `rg`).
    pub fn set_far_field(&mut self, far: &FarField, delta: f64) {
        self.edge = self.grid.sample_boundary(|x, y| far.pressure(x, y, delta));
        self.load = LOAD - far.outside_load(&self.grid.domain(), delta);
        self.rg = -(self.load - self.load_correction);
        for k in self.grid.boundary() {
            self.p[k] = self.edge[k];
        }
        self.invalidate();
    }

    /// Force-balance defect `sum P hx hy + rg`.
    pub fn load_defect(&self) -> f64 {
        self.grid.integrate(&self.p) + self.rg
    }
}

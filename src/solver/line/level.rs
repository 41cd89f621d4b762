//! One grid level of the line-contact problem: its fields, the film equation, the
//! coefficients of the Reynolds equation and its discrete operator.
//!
//! Reynolds, with `eps = rho H^3 / (eta_eff lambda)`:
//! `d/dX (eps dP/dX) - d(rho H)/dX = 0`, discretised as
//! `[eps_{i-1/2} (P_{i-1} - P_i) + eps_{i+1/2} (P_{i+1} - P_i)] / h^2
//!  - (1.5 rho H_i - 2 rho H_{i-1} + 0.5 rho H_{i-2}) / h`
//! (half-point coefficients the mean of the nodal ones; second-order upstream wedge, first
//! order at `i = 1`), as the point contact does along `X`.

use super::kernel::LineDeformation;
use crate::physics::density::Density;
use crate::physics::line_contact::{LineEyringFlow, LineProblem};
use crate::physics::rheology::ShearLaw;
use crate::physics::viscosity::Viscosity;

/// The parts of the dimensionless problem the discrete equations use.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LineModel {
    pub viscosity: Viscosity,
    pub density: Density,
    pub rheology: ShearLaw,
    pub flow: LineEyringFlow,
    /// `N S`: the Couette argument is `N S eta / H`.
    pub n_s: f64,
    /// `1 / lambda`.
    pub inv_lambda: f64,
    /// `G = g_scale H dP/dX`, the Poiseuille stress on the surface over `tau0`.
    pub g_scale: f64,
}

impl LineModel {
    pub fn new(problem: &LineProblem) -> Self {
        let g = &problem.groups;
        LineModel {
            viscosity: problem.viscosity,
            density: problem.density,
            rheology: problem.shear,
            flow: problem.eyring_flow,
            n_s: problem.eyring_n_s(),
            inv_lambda: 1.0 / g.lambda,
            g_scale: g.poiseuille_stress_scale,
        }
    }

    /// `eta_bar(P)`.
    #[inline]
    pub fn eta(&self, p: f64) -> f64 {
        self.viscosity.eta_bar_capped(p)
    }

    /// Whether the flow depends on the pressure gradient (the exact Eyring flow does).
    pub fn uses_gradient(&self) -> bool {
        self.rheology.is_plain_eyring() && self.flow == LineEyringFlow::Exact
    }
}

/// Fields of one level.
#[derive(Debug)]
pub(crate) struct LineLevelFields {
    /// Intervals (nodes `0..=n`).
    pub n: usize,
    /// `X` of node 0.
    pub x0: f64,
    /// Mesh size.
    pub dx: f64,
    pub deformation: LineDeformation,
    /// Pressure `P`.
    pub p: Vec<f64>,
    /// Film `H = Delta + X^2/2 + W`.
    pub h: Vec<f64>,
    /// The undeformed gap `X^2/2`.
    pub hrhs: Vec<f64>,
    /// Elastic deformation `W`.
    pub w: Vec<f64>,
    /// `rho H^3 / (eta_eff lambda)` at the nodes.
    pub eps: Vec<f64>,
    /// `rho` at the nodes (all ones and never touched when incompressible).
    pub rho: Vec<f64>,
    /// `rho H` at the nodes.
    pub rh: Vec<f64>,
}

/// The force-balance target `int P dX = pi/2`.
pub(crate) const LOAD: f64 = std::f64::consts::FRAC_PI_2;

impl LineLevelFields {
    pub fn new(n: usize, x0: f64, x1: f64) -> Self {
        let dx = (x1 - x0) / n as f64;
        let hrhs = (0..=n)
            .map(|i| {
                let x = x0 + i as f64 * dx;
                0.5 * x * x
            })
            .collect();
        LineLevelFields {
            n,
            x0,
            dx,
            deformation: LineDeformation::new(dx, n),
            p: vec![0.0; n + 1],
            h: vec![0.0; n + 1],
            hrhs,
            w: vec![0.0; n + 1],
            eps: vec![0.0; n + 1],
            rho: vec![1.0; n + 1],
            rh: vec![0.0; n + 1],
        }
    }

    /// `X` of node `i`.
    #[inline]
    pub fn x(&self, i: usize) -> f64 {
        self.x0 + i as f64 * self.dx
    }

    /// The node nearest to `x`.
    pub fn nearest(&self, x: f64) -> usize {
        ((x - self.x0) / self.dx).round().clamp(0.0, self.n as f64) as usize
    }

    /// Film equation: `H = Delta + hrhs + W(P)`.
    pub fn update_film(&mut self, delta: f64) {
        self.deformation.apply(&self.p, &mut self.w);
        for ((h, r), w) in self.h.iter_mut().zip(&self.hrhs).zip(&self.w) {
            *h = delta + r + w;
        }
    }

    /// `dP/dX` at node `i` (central; one-sided at the ends).
    #[inline]
    pub fn slope(&self, p: &[f64], i: usize) -> f64 {
        if i == 0 {
            (p[1] - p[0]) / self.dx
        } else if i == self.n {
            (p[i] - p[i - 1]) / self.dx
        } else {
            (p[i + 1] - p[i - 1]) / (2.0 * self.dx)
        }
    }

    /// `G = (h/2)(dp/dx)/tau0` at node `i`.
    #[inline]
    pub fn g(&self, m: &LineModel, i: usize) -> f64 {
        m.g_scale * self.h[i] * self.slope(&self.p, i)
    }

    /// Coefficients of the Reynolds equation from the current `P` and `H`.
    pub fn update_coefficients(&mut self, m: &LineModel) {
        let compressible = !m.density.is_incompressible();
        let gradient = m.uses_gradient();
        for k in 0..=self.n {
            let p = self.p[k];
            let h = self.h[k];
            let eta = m.eta(p);
            let rho = if compressible {
                let r = m.density.rho_bar(p);
                self.rho[k] = r;
                r
            } else {
                1.0
            };
            let g = if gradient { self.g(m, k) } else { 0.0 };
            self.eps[k] = rho * m.inv_lambda * m.flow.conductance(m.rheology, h, eta, m.n_s, g, p);
            self.rh[k] = rho * h;
        }
    }

    /// Half-point coefficients `(xi_w, xi_e)` at `i`, divided by `h^2`.
    #[inline]
    pub fn xi(&self, i: usize) -> [f64; 2] {
        let r = 0.5 / (self.dx * self.dx);
        [
            (self.eps[i] + self.eps[i - 1]) * r,
            (self.eps[i] + self.eps[i + 1]) * r,
        ]
    }

    /// The wedge term `d(rho H)/dX` at `i`: second-order upstream, first order at `i = 1`.
    #[inline]
    pub fn wedge(&self, i: usize) -> f64 {
        if i >= 2 {
            (1.5 * self.rh[i] - 2.0 * self.rh[i - 1] + 0.5 * self.rh[i - 2]) / self.dx
        } else {
            (self.rh[i] - self.rh[i - 1]) / self.dx
        }
    }

    /// The discrete Reynolds operator `L(P)` at interior node `i` for pressure `p`, with the
    /// coefficients and film of the last update.
    #[inline]
    pub fn operator(&self, p: &[f64], i: usize) -> f64 {
        let [xw, xe] = self.xi(i);
        xw * (p[i - 1] - p[i]) + xe * (p[i + 1] - p[i]) - self.wedge(i)
    }

    /// Residual `-L(P)` at interior node `i`.
    #[inline]
    pub fn residual(&self, i: usize) -> f64 {
        -self.operator(&self.p, i)
    }

    /// Mean absolute residual over the pressurised interior nodes (film and coefficients
    /// must be current), divided by the number of interior nodes.
    pub fn residual_norm(&self) -> f64 {
        let mut sum = 0.0;
        for i in 1..self.n {
            if self.p[i] > 0.0 {
                sum += self.residual(i).abs();
            }
        }
        sum / (self.n - 1) as f64
    }

    /// The pressurised interior node of the largest absolute residual (the first node when
    /// none is pressurised).
    pub fn worst_residual_node(&self) -> usize {
        (1..self.n)
            .filter(|&i| self.p[i] > 0.0)
            .max_by(|&a, &b| self.residual(a).abs().total_cmp(&self.residual(b).abs()))
            .unwrap_or(0)
    }

    /// `int P dX` by the rectangle rule (the end values are zero).
    pub fn load(&self) -> f64 {
        self.p.iter().sum::<f64>() * self.dx
    }
}

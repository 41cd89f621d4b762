//! The case's physics at a node, as the discrete equations use it: the viscosity, density
//! and shear laws of the dimensionless problem and its groups.

use crate::physics::case::Problem;
use crate::physics::density::Density;
use crate::physics::rheology::ShearLaw;
use crate::physics::viscosity::Viscosity;

/// The parts of the dimensionless problem the discrete equations use.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Model {
    pub viscosity: Viscosity,
    pub density: Density,
    pub rheology: ShearLaw,
    /// `N S` of Eq. (4).
    pub n_s: f64,
    /// `1 / lambda`.
    pub inv_lambda: f64,
    /// `kappa^2`, the weight of the `Y` derivative in Eq. (1).
    pub kappa2: f64,
    /// Shape factor `S(kappa)` of Eq. (6).
    pub shape: f64,
    pub kappa: f64,
    pub ell_k: f64,
}

impl Model {
    pub fn new(problem: &Problem) -> Self {
        let g = &problem.groups;
        Model {
            viscosity: problem.viscosity,
            density: problem.density,
            rheology: problem.shear,
            n_s: problem.eyring_n_s(),
            inv_lambda: 1.0 / g.lambda,
            kappa2: g.kappa * g.kappa,
            shape: problem.shape,
            kappa: g.kappa,
            ell_k: problem.ell_k,
        }
    }

    /// `eta_bar(P)`. Where `P <= 0` (most of the domain: outside the contact and in the
    /// cavitated outlet) every law gives exactly `exp(0) = 1`, returned without evaluating it
    /// (the same bits, a third of the coefficient update saved).
    #[inline]
    pub fn eta(&self, p: f64) -> f64 {
        if p <= 0.0 {
            return 1.0;
        }
        self.viscosity.eta_bar_capped(p)
    }

    /// The mean shear stress `tau_m / tau0` at a node of pressure `p > 0` and film `h`: the
    /// case's shear law (Eq. 4 for Eyring) at the Couette argument `N S eta_bar(P) / H`. The
    /// one formula of the friction (Eq. 8) and of the stress field
    /// ([`super::friction::mean_shear_stress`]).
    #[inline]
    pub fn mean_shear_stress(&self, p: f64, h: f64) -> f64 {
        self.rheology
            .mean_shear_stress(self.n_s * self.eta(p) / h, p)
    }

    /// The coefficients of Eq. (1) at one node of pressure `p` and film `h`:
    /// `(rho H^3 / (eta_x lambda), kappa^2 rho H^3 / (eta_y lambda), rho)`.
    #[inline]
    pub fn coefficients(&self, p: f64, h: f64) -> (f64, f64, f64) {
        // rho_bar(P <= 0) = 1 exactly: not evaluated there, like the viscosity.
        let rho = if self.density.is_incompressible() || p <= 0.0 {
            1.0
        } else {
            self.density.rho_bar(p)
        };
        let eta = self.eta(p);
        let scale = rho * self.inv_lambda;
        (
            scale * self.rheology.conductance_x(h, eta, self.n_s, p),
            scale * self.kappa2 * self.rheology.conductance_y(h, eta, self.n_s, p),
            rho,
        )
    }

    /// Gap geometry `S X^2 + (1 - S) Y^2` of Eq. (6).
    pub fn geometry(&self, x: f64, y: f64) -> f64 {
        self.shape * x * x + (1.0 - self.shape) * y * y
    }
}

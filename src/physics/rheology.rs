//! Lubricant rheology: Newtonian or Eyring, through the perturbation approach of Eqs. (2)-(4)
//! (Ehret, Dowson and Taylor 1998).
//!
//! Every quantity is written in terms of the local Couette stress argument
//! `x = N eta_bar S / H` (the Newtonian mean shear stress over `tau0`), so that
//! `tau_m = asinh(x)` (Eq. 4), `cosh(tau_m) = sqrt(1 + x^2)` and `sinh(tau_m) = x`.
//! Written this way nothing overflows even where `eta_bar` is 1e25.

use super::evaluations::{record, Effect};
use serde::{Deserialize, Serialize};

/// Which rheology a case asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Rheology {
    /// Linear viscous: the mean shear stress is `x` and the effective viscosities are `eta`.
    Newtonian,
    /// Eyring: `gamma_dot = (tau0 / eta) sinh(tau / tau0)`.
    #[default]
    Eyring,
}

impl Rheology {
    /// Dimensionless mean shear stress `tau_m / tau0` for the Couette argument `x`:
    /// Eq. (4) for Eyring, `x` itself for a Newtonian fluid.
    #[inline]
    pub fn mean_shear_stress(self, x: f64) -> f64 {
        match self {
            Rheology::Newtonian => x,
            Rheology::Eyring => {
                record(Effect::Eyring);
                x.asinh()
            }
        }
    }

    /// `eta / eta_x`: Eq. (2), `cosh(tau_m) = sqrt(1 + x^2)`.
    #[inline]
    pub fn flow_factor_x(self, x: f64) -> f64 {
        match self {
            Rheology::Newtonian => 1.0,
            Rheology::Eyring => {
                record(Effect::Eyring);
                x.hypot(1.0)
            }
        }
    }

    /// `eta / eta_y`: Eq. (3) as corrected in SPEC.md, `eta_y = eta tau_m / sinh(tau_m)`,
    /// so `eta / eta_y = x / asinh(x)`, which tends to 1 as `x -> 0`.
    #[inline]
    pub fn flow_factor_y(self, x: f64) -> f64 {
        match self {
            Rheology::Newtonian => 1.0,
            Rheology::Eyring => {
                record(Effect::Eyring);
                if x.abs() < 1e-4 {
                    1.0 + x * x / 6.0
                } else {
                    x / x.asinh()
                }
            }
        }
    }
}

impl Rheology {
    /// Poiseuille conductance along the sliding direction, `H^3 / eta_x_bar` (Eqs. 1-2), for
    /// film `h`, viscosity `eta` and `n_s = N S`. For Eyring it is written
    /// `H^2 hypot(H / eta, N S)`, finite however large `eta` is; zero where `h <= 0`.
    #[inline]
    pub fn conductance_x(self, h: f64, eta: f64, n_s: f64) -> f64 {
        if h <= 0.0 {
            return 0.0;
        }
        match self {
            Rheology::Newtonian => h * h * h / eta,
            // sqrt(a^2 + b^2) rather than hypot: a = H/eta <= H and b = N S are far from
            // overflow, and hypot's extra care costs a tenth of a solve.
            Rheology::Eyring => {
                record(Effect::Eyring);
                let a = h / eta;
                h * h * (a * a + n_s * n_s).sqrt()
            }
        }
    }

    /// Poiseuille conductance across the sliding direction, `H^3 / eta_y_bar` (Eqs. 1, 3).
    /// For Eyring, with `x = N S eta / H`: `(H^3 / eta) x / asinh(x) = H^2 N S / asinh(x)`.
    #[inline]
    pub fn conductance_y(self, h: f64, eta: f64, n_s: f64) -> f64 {
        if h <= 0.0 {
            return 0.0;
        }
        match self {
            Rheology::Newtonian => h * h * h / eta,
            Rheology::Eyring => {
                record(Effect::Eyring);
                let x = n_s * eta / h;
                if x < 1e-4 {
                    h * h * h / eta * (1.0 + x * x / 6.0)
                } else {
                    h * h * n_s / x.asinh()
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eyring_tends_to_newtonian_at_low_stress() {
        let e = Rheology::Eyring;
        for x in [0.0, 1e-8, 1e-5] {
            assert!((e.mean_shear_stress(x) - x).abs() <= 1e-15);
            assert!((e.flow_factor_x(x) - 1.0).abs() < 1e-9);
            assert!((e.flow_factor_y(x) - 1.0).abs() < 1e-9);
        }
        // Continuity across the series switch (error of the series ~ x^4/... < 1e-17).
        let below = e.flow_factor_y(0.99999e-4);
        let above = e.flow_factor_y(1.00001e-4);
        assert!((below - above).abs() < 1e-12);
    }

    #[test]
    fn eyring_factors_are_cosh_and_sinh_over_tau() {
        let e = Rheology::Eyring;
        for tau in [0.5_f64, 3.0, 40.0] {
            let x = tau.sinh();
            assert!((e.mean_shear_stress(x) - tau).abs() < 1e-12 * tau.max(1.0));
            assert!((e.flow_factor_x(x) / tau.cosh() - 1.0).abs() < 1e-12);
            assert!((e.flow_factor_y(x) / (tau.sinh() / tau) - 1.0).abs() < 1e-12);
        }
        // Huge arguments stay finite.
        assert!(e.flow_factor_x(1e200).is_finite());
    }

    #[test]
    fn conductances_are_h_cubed_over_the_effective_viscosities() {
        let e = Rheology::Eyring;
        for (h, eta, ns) in [(0.02, 1e20, 1e-5), (0.5, 3.0, 0.01), (1.0, 1.0, 0.0)] {
            let x = ns * eta / h;
            let cx = h * h * h / eta * e.flow_factor_x(x);
            let cy = h * h * h / eta * e.flow_factor_y(x);
            assert!((e.conductance_x(h, eta, ns) / cx - 1.0).abs() < 1e-12);
            assert!((e.conductance_y(h, eta, ns) / cy - 1.0).abs() < 1e-12);
        }
        assert_eq!(e.conductance_x(-1e-3, 1.0, 0.1), 0.0);
        // Where eta overflows to infinity the conductance stays finite.
        assert!(e.conductance_x(0.02, f64::INFINITY, 1e-5).is_finite());
    }

    #[test]
    fn newtonian_is_linear() {
        let n = Rheology::Newtonian;
        assert_eq!(n.mean_shear_stress(3.0), 3.0);
        assert_eq!(n.flow_factor_x(3.0), 1.0);
        assert_eq!(n.flow_factor_y(3.0), 1.0);
    }
}

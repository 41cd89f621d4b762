//! Viscosity-pressure laws, dimensionless: `eta_bar = eta / eta0` as a function of `P = p / p_H`.

use super::evaluations::{record, Effect};
use serde::{Deserialize, Serialize};

/// Reference pressure of the Roelands equation, Pa.
pub const ROELANDS_P0: f64 = 1.96e8;
/// The constant `9.67` of the Roelands equation (`ln` of 1/(6.31e-5 Pa s)).
pub const ROELANDS_LN_ETA_INF: f64 = 9.67;

/// Which viscosity-pressure law a case asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum ViscosityLaw {
    /// Eq. (5).
    #[default]
    Barus,
    /// Roelands (1966), the law of Figs. 4-7.
    Roelands,
}

/// A viscosity law with its parameters, evaluated in the solver's dimensionless pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Viscosity {
    /// Barus, Eq. (5): `eta_bar = exp(alpha_bar P)`.
    Barus {
        /// `alpha_bar = alpha p_H`.
        alpha_bar: f64,
    },
    /// Roelands: `eta_bar = exp((ln eta0 + 9.67)((1 + p/p0)^z - 1))`,
    /// `z = alpha p0 / (ln eta0 + 9.67)`, so that the slope at `p = 0` is `alpha`.
    Roelands {
        /// `ln(eta0 [Pa s]) + 9.67`.
        ln_ratio: f64,
        /// Roelands pressure-viscosity index.
        z: f64,
        /// `p_H / p0`.
        ph_over_p0: f64,
    },
}

/// The cap on `ln(eta/eta0)` in [`Viscosity::eta_bar_capped`]; no converged EHL solution
/// comes near it (it would need `alpha-bar P > 700`).
pub const LN_ETA_BAR_MAX: f64 = 700.0;

impl Viscosity {
    /// Barus with `alpha_bar = alpha p_H`.
    pub fn barus(alpha_bar: f64) -> Self {
        Viscosity::Barus { alpha_bar }
    }

    /// Roelands from the ambient viscosity `eta0_pa_s`, the pressure-viscosity coefficient
    /// `alpha_per_pa` and the maximum Hertzian pressure `ph_pa` (the dimensionless scale).
    pub fn roelands(eta0_pa_s: f64, alpha_per_pa: f64, ph_pa: f64) -> Self {
        let ln_ratio = eta0_pa_s.ln() + ROELANDS_LN_ETA_INF;
        Viscosity::Roelands {
            ln_ratio,
            z: alpha_per_pa * ROELANDS_P0 / ln_ratio,
            ph_over_p0: ph_pa / ROELANDS_P0,
        }
    }

    /// Builds the law a case asks for.
    pub fn new(law: ViscosityLaw, eta0_pa_s: f64, alpha_per_pa: f64, ph_pa: f64) -> Self {
        match law {
            ViscosityLaw::Barus => Self::barus(alpha_per_pa * ph_pa),
            ViscosityLaw::Roelands => Self::roelands(eta0_pa_s, alpha_per_pa, ph_pa),
        }
    }

    /// `ln(eta / eta0)` at dimensionless pressure `p` (clamped at 0: no tension).
    pub fn ln_eta_bar(&self, p: f64) -> f64 {
        let p = p.max(0.0);
        match *self {
            Viscosity::Barus { alpha_bar } => alpha_bar * p,
            Viscosity::Roelands {
                ln_ratio,
                z,
                ph_over_p0,
            } => {
                record(Effect::Roelands);
                ln_ratio * ((1.0 + ph_over_p0 * p).powf(z) - 1.0)
            }
        }
    }

    /// `eta / eta0` at dimensionless pressure `p`.
    pub fn eta_bar(&self, p: f64) -> f64 {
        self.ln_eta_bar(p).exp()
    }

    /// `eta / eta0` as the discrete equations evaluate it (point and line contacts, and the
    /// thermal post-process's Couette argument): `ln eta_bar` capped at [`LN_ETA_BAR_MAX`]
    /// so that `exp` stays finite.
    #[inline]
    pub fn eta_bar_capped(&self, p: f64) -> f64 {
        self.ln_eta_bar(p).min(LN_ETA_BAR_MAX).exp()
    }

    /// Which law this is.
    pub fn law(&self) -> ViscosityLaw {
        match self {
            Viscosity::Barus { .. } => ViscosityLaw::Barus,
            Viscosity::Roelands { .. } => ViscosityLaw::Roelands,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn barus_is_exponential() {
        let v = Viscosity::barus(20.0);
        assert!((v.eta_bar(0.5) - 10f64.exp()).abs() < 1e-9 * 10f64.exp());
        assert_eq!(v.eta_bar(0.0), 1.0);
    }

    #[test]
    fn roelands_matches_barus_slope_at_ambient_and_is_below_it_at_high_pressure() {
        // Mineral oil A at 40 C: eta0 = 8.24 mPa s, alpha = 21.6 /GPa, p_H = 3 GPa.
        let v = Viscosity::roelands(8.24e-3, 21.6e-9, 3e9);
        let b = Viscosity::barus(21.6e-9 * 3e9);
        let dp = 1e-7;
        let slope = v.ln_eta_bar(dp) / dp;
        // Initial slopes agree to first order in dp (relative error ~ (z-1) p/p0 ~ 1e-5).
        assert!(
            (slope / (21.6e-9 * 3e9) - 1.0).abs() < 1e-4,
            "slope {slope}"
        );
        assert!(v.eta_bar(1.0) < b.eta_bar(1.0) * 1e-3);
        // Hand evaluation of the formula at p = p_H:
        // ln_ratio = ln(8.24e-3) + 9.67, z = alpha p0 / ln_ratio.
        let ln_ratio = (8.24e-3_f64).ln() + 9.67;
        let z = 21.6e-9 * 1.96e8 / ln_ratio;
        let expect = ln_ratio * ((1.0 + 3e9 / 1.96e8_f64).powf(z) - 1.0);
        assert!((v.ln_eta_bar(1.0) - expect).abs() < 1e-12);
    }

    #[test]
    fn negative_pressure_is_clamped() {
        let v = Viscosity::roelands(8.24e-3, 21.6e-9, 3e9);
        assert_eq!(v.eta_bar(-0.1), 1.0);
    }
}

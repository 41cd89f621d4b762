//! Density-pressure laws, dimensionless: `rho_bar = rho / rho0` as a function of `P = p / p_H`.

use super::evaluations::{record, Effect};
use serde::{Deserialize, Serialize};

/// Which density law a case asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum DensityLaw {
    /// `rho_bar = 1`.
    #[default]
    Incompressible,
    /// Dowson and Higginson (1966).
    DowsonHigginson,
}

/// A density law with its parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Density {
    /// `rho_bar = 1`: never evaluates anything.
    Incompressible,
    /// Dowson-Higginson: `rho/rho0 = (5.9e8 + 1.34 p) / (5.9e8 + p)`, `p` in Pa.
    DowsonHigginson {
        /// `p_H`, Pa: the scale of the dimensionless pressure.
        ph_pa: f64,
    },
}

impl Density {
    /// Builds the law a case asks for at the contact's `p_H`.
    pub fn new(law: DensityLaw, ph_pa: f64) -> Self {
        match law {
            DensityLaw::Incompressible => Density::Incompressible,
            DensityLaw::DowsonHigginson => Density::DowsonHigginson { ph_pa },
        }
    }

    /// `rho / rho0` at dimensionless pressure `p` (clamped at 0).
    #[inline]
    pub fn rho_bar(&self, p: f64) -> f64 {
        match *self {
            Density::Incompressible => 1.0,
            Density::DowsonHigginson { ph_pa } => {
                record(Effect::DowsonHigginson);
                let p = ph_pa * p.max(0.0);
                (5.9e8 + 1.34 * p) / (5.9e8 + p)
            }
        }
    }

    /// True when the density is constant (the solver may skip it).
    pub fn is_incompressible(&self) -> bool {
        matches!(self, Density::Incompressible)
    }

    /// Which law this is.
    pub fn law(&self) -> DensityLaw {
        match self {
            Density::Incompressible => DensityLaw::Incompressible,
            Density::DowsonHigginson { .. } => DensityLaw::DowsonHigginson,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dowson_higginson_limits() {
        let d = Density::new(DensityLaw::DowsonHigginson, 3e9);
        assert_eq!(d.rho_bar(0.0), 1.0);
        // At 3 GPa: (5.9e8 + 4.02e9) / (3.59e9) = 1.28412...
        assert!((d.rho_bar(1.0) - 4.61e9 / 3.59e9).abs() < 1e-14);
        // The asymptote is 1.34.
        assert!(d.rho_bar(1e6) < 1.34 && d.rho_bar(1e6) > 1.3399);
        assert_eq!(Density::Incompressible.rho_bar(0.7), 1.0);
    }
}

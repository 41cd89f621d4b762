//! The viscosity's temperature dependence, `eta(p, T) = eta(p, T0) exp(Delta(p, T))`, on top
//! of the case's isothermal law at its temperature `T0`.
//!
//! Roelands (1966), the law of Figs. 4-7, with temperature:
//! `ln eta(p, T) + 9.67 = (ln eta0(T0) + 9.67) (1 + p/p0)^z ((T0 - 138 K)/(T - 138 K))^S0`,
//! so `Delta = (ln eta(p, T0) + 9.67) (((T0 - 138)/(T - 138))^S0 - 1)`: the temperature
//! coefficient `-d ln eta/dT = S0 (ln eta(p, T0) + 9.67)/(T0 - 138 K)` grows with pressure as
//! the isothermal Roelands viscosity does (`beta0 (1 + p/p0)^z`). The index `S0` is fitted to
//! the lubricant's own `eta0` at the ends of the Table 1 interval the film heats into (from
//! `T0` up; the last interval at the table's top): the law passes through both.
//!
//! Barus: `Delta = -beta0 (T - T0)` with `beta0` the slope of `ln eta0` over that interval,
//! the same at every pressure.

use super::ThermalError;
use crate::physics::lubricant::Lubricant;
use crate::physics::viscosity::{Viscosity, ROELANDS_LN_ETA_INF};

/// The temperature `T_inf` of the Roelands temperature law, K.
pub const ROELANDS_T_INF_K: f64 = 138.0;
/// Celsius to kelvin.
pub const KELVIN: f64 = 273.15;

/// How the viscosity falls with the film's temperature rise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ThermalViscosity {
    /// Roelands' temperature-pressure law (module doc).
    Roelands {
        /// The isothermal law at `T0` (dimensionless pressure).
        viscosity: Viscosity,
        /// `ln eta0(T0) + 9.67`, `eta0` in Pa s.
        ln_ratio: f64,
        /// `T0 - 138 K`.
        t0_minus_inf_k: f64,
        /// The temperature index `S0`.
        s0: f64,
    },
    /// `exp(-beta0 (T - T0))` at every pressure.
    Exponential {
        /// `beta0`, 1/K.
        beta0: f64,
    },
}

impl ThermalViscosity {
    /// The law of `lubricant` (named `name`, for messages) at `temperature_c` over the case's
    /// isothermal `viscosity` (its `eta0` must be the table's at that temperature).
    pub fn of_lubricant(
        name: &str,
        lubricant: &Lubricant,
        temperature_c: f64,
        viscosity: &Viscosity,
    ) -> Result<Self, ThermalError> {
        let t = &lubricant.temperature_c;
        if t.len() < 2 {
            return Err(ThermalError::Input {
                what: "lubricant",
                message: format!(
                    "'{name}' has eta0 at one temperature: no temperature coefficient"
                ),
            });
        }
        // The interval the film heats into: [t_i, t_i+1] with t_i <= T0 < t_i+1.
        let i = t
            .iter()
            .rposition(|&ti| ti <= temperature_c)
            .unwrap_or(0)
            .min(t.len() - 2);
        let ln_eta = |j: usize| (lubricant.eta0_mpa_s[j] * 1e-3).ln();
        Ok(match *viscosity {
            Viscosity::Roelands { ln_ratio, .. } => {
                let t_inf = |c: f64| c + KELVIN - ROELANDS_T_INF_K;
                let s0 = ((ln_eta(i) + ROELANDS_LN_ETA_INF)
                    / (ln_eta(i + 1) + ROELANDS_LN_ETA_INF))
                    .ln()
                    / (t_inf(t[i + 1]) / t_inf(t[i])).ln();
                ThermalViscosity::Roelands {
                    viscosity: *viscosity,
                    ln_ratio,
                    t0_minus_inf_k: t_inf(temperature_c),
                    s0,
                }
            }
            Viscosity::Barus { .. } => ThermalViscosity::Exponential {
                beta0: (ln_eta(i) - ln_eta(i + 1)) / (t[i + 1] - t[i]),
            },
        })
    }

    /// `Delta = ln(eta(p, T0 + theta) / eta(p, T0))` at dimensionless pressure `p` and a
    /// temperature rise `theta` (K). Exactly 0 at `theta = 0` and for a zero coefficient.
    pub fn delta_ln_eta(&self, p: f64, theta: f64) -> f64 {
        self.delta_ln_eta_with(self.pressure_part(p), theta)
    }

    /// What [`ThermalViscosity::delta_ln_eta`] takes from the pressure alone: made once for
    /// the temperatures a node's root tries (a Roelands power of the pressure each).
    pub fn pressure_part(&self, p: f64) -> f64 {
        match *self {
            ThermalViscosity::Roelands {
                viscosity,
                ln_ratio,
                ..
            } => ln_ratio + viscosity.ln_eta_bar(p),
            ThermalViscosity::Exponential { .. } => 0.0,
        }
    }

    /// [`ThermalViscosity::delta_ln_eta`] from its [`ThermalViscosity::pressure_part`] (the
    /// same arithmetic, so the same bits).
    pub fn delta_ln_eta_with(&self, pressure_part: f64, theta: f64) -> f64 {
        match *self {
            ThermalViscosity::Roelands {
                t0_minus_inf_k, s0, ..
            } => {
                let r = t0_minus_inf_k / (t0_minus_inf_k + theta);
                pressure_part * (r.powf(s0) - 1.0)
            }
            ThermalViscosity::Exponential { beta0 } => -beta0 * theta,
        }
    }

    /// The temperature-viscosity coefficient `beta = -d ln eta/dT` at ambient pressure and
    /// `T0`, 1/K.
    pub fn beta0(&self) -> f64 {
        match *self {
            ThermalViscosity::Roelands {
                ln_ratio,
                t0_minus_inf_k,
                s0,
                ..
            } => s0 * ln_ratio / t0_minus_inf_k,
            ThermalViscosity::Exponential { beta0 } => beta0,
        }
    }

    /// `beta` at dimensionless pressure `p` (at `T0`).
    pub fn beta_at(&self, p: f64) -> f64 {
        match *self {
            ThermalViscosity::Roelands {
                viscosity,
                ln_ratio,
                ..
            } => self.beta0() * (ln_ratio + viscosity.ln_eta_bar(p)) / ln_ratio,
            ThermalViscosity::Exponential { beta0 } => beta0,
        }
    }

    /// The same law with its temperature coefficient scaled by `factor` (0: isothermal).
    pub fn scaled(&self, factor: f64) -> Self {
        match *self {
            ThermalViscosity::Roelands {
                viscosity,
                ln_ratio,
                t0_minus_inf_k,
                s0,
            } => ThermalViscosity::Roelands {
                viscosity,
                ln_ratio,
                t0_minus_inf_k,
                s0: s0 * factor,
            },
            ThermalViscosity::Exponential { beta0 } => ThermalViscosity::Exponential {
                beta0: beta0 * factor,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::lubricant::LubricantTable;

    fn law(name: &str, temperature_c: f64) -> (ThermalViscosity, Viscosity) {
        let table = LubricantTable::table1();
        let s = table.state(name, temperature_c).unwrap();
        let v = Viscosity::roelands(s.eta0_pa_s, s.alpha_per_pa, 3e9);
        let lub = table.get(name).unwrap();
        (
            ThermalViscosity::of_lubricant(name, lub, temperature_c, &v).unwrap(),
            v,
        )
    }

    #[test]
    fn the_law_passes_through_the_tables_eta0_and_mineral_oil_as_alpha() {
        // At ambient pressure from 40 C, a 20 K rise gives the table's eta0 at 60 C (the fit's
        // own point: round-off only).
        let table = LubricantTable::table1();
        for name in ["mineral-oil-a", "traction-fluid", "5p4e"] {
            let (th, _) = law(name, 40.0);
            let e40 = table.state(name, 40.0).unwrap().eta0_pa_s;
            let e60 = table.state(name, 60.0).unwrap().eta0_pa_s;
            assert!(
                (th.delta_ln_eta(0.0, 20.0) - (e60 / e40).ln()).abs() < 1e-12,
                "{name}"
            );
        }
        // Its pressure dependence, the Roelands z fixed, predicts alpha(T) = alpha(T0) (ln eta0(T)
        // + 9.67)/(ln eta0(T0) + 9.67): for mineral oil A the table's 18.6 /GPa at 60 C within
        // 0.5 % (the table's rounding is 0.3 %). The slope is taken at 1 kPa (first-order
        // error ~1e-5).
        let (th, v) = law("mineral-oil-a", 40.0);
        let dp = 1e3 / 3e9;
        let slope = (v.ln_eta_bar(dp) + th.delta_ln_eta(dp, 20.0) - th.delta_ln_eta(0.0, 20.0))
            / (dp * 3e9);
        assert!(
            (slope / 18.6e-9 - 1.0).abs() < 5e-3,
            "alpha(60 C) = {slope}"
        );
    }

    #[test]
    fn no_rise_or_no_coefficient_is_exactly_isothermal() {
        let (th, _) = law("5p4e", 40.0);
        assert_eq!(th.delta_ln_eta(1.0, 0.0), 0.0);
        assert_eq!(th.scaled(0.0).delta_ln_eta(1.0, 35.0), 0.0);
        let e = ThermalViscosity::Exponential { beta0: 0.03 };
        assert_eq!(e.scaled(0.0).delta_ln_eta(1.0, 35.0), 0.0);
        assert!((e.delta_ln_eta(0.3, 10.0) + 0.3).abs() < 1e-15);
    }

    #[test]
    fn the_coefficient_grows_with_pressure() {
        // beta at p_H = 3 GPa is beta0 (ln eta(p_H) + 9.67)/(ln eta0 + 9.67); for mineral oil
        // A at 40 C beta0 is 0.03-0.05 /K (a mineral oil's range) and several times that at
        // p_H. Checked against a central difference of Delta in T (step 1e-3 K: error 1e-6).
        let (th, _) = law("mineral-oil-a", 40.0);
        let b0 = th.beta0();
        assert!((0.03..0.05).contains(&b0), "beta0 = {b0}");
        let numeric = -(th.delta_ln_eta(1.0, 1e-3) - th.delta_ln_eta(1.0, -1e-3)) / 2e-3;
        assert!((numeric / th.beta_at(1.0) - 1.0).abs() < 1e-6);
        assert!(th.beta_at(1.0) > 3.0 * b0);
    }
}

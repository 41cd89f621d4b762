//! A datasheet lubricant's density against temperature: ASTM D1250 Table 54D.

use super::{check_positive, DatasheetError};
use crate::physics::walther::WALTHER_TEMPERATURE_RANGE_C;

/// ASTM D1250 (API MPMS 11.1, ISO 91-1) Table 54D, lubricating oils: `K0` in
/// `alpha15 = K0 / rho15^2 + K1 / rho15`, (kg/m^3)^2/K.
pub const D1250_TABLE_54D_K0: f64 = 0.0;
/// Table 54D `K1`, kg/(m^3 K).
pub const D1250_TABLE_54D_K1: f64 = 0.6278;
/// Densities at 15 C Table 54D covers, kg/m^3.
pub const D1250_TABLE_54D_RHO15_KG_M3: (f64, f64) = (800.0, 1164.0);

/// Density against temperature in the form of ASTM D1250 (API MPMS 11.1, ISO 91-1),
///
/// ```text
/// rho(T) = rho15 exp(-a15 dT (1 + 0.8 a15 dT)),   dT = T - 15 C,
/// ```
///
/// with the expansion coefficient `a15` (1/K) either given or from Table 54D (lubricating
/// oils), `a15 = K0 / rho15^2 + K1 / rho15`, `K0 = 0`, `K1 = 0.6278 kg/(m^3 K)` (about
/// 7.2e-4 1/K at 870 kg/m^3). The 54D constants and its 800-1164 kg/m^3 density range were
/// read from a third-party implementation of ISO 91-1; D1250's own temperature limits for
/// Table 54D were not confirmed, so the D341 line's window
/// ([`WALTHER_TEMPERATURE_RANGE_C`]) is used.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DatasheetDensity {
    rho15_kg_m3: f64,
    expansion15_per_k: f64,
}

impl DatasheetDensity {
    /// Density at 15 C `rho15_kg_m3` with the Table 54D expansion coefficient.
    pub fn d1250_table_54d(rho15_kg_m3: f64) -> Result<Self, DatasheetError> {
        check_positive("rho15_kg_m3", rho15_kg_m3)?;
        let (lo, hi) = D1250_TABLE_54D_RHO15_KG_M3;
        if !(lo..=hi).contains(&rho15_kg_m3) {
            return Err(DatasheetError::Rho15OutsideTable54D {
                rho15_kg_m3,
                lo,
                hi,
            });
        }
        let expansion15_per_k =
            D1250_TABLE_54D_K0 / (rho15_kg_m3 * rho15_kg_m3) + D1250_TABLE_54D_K1 / rho15_kg_m3;
        Ok(DatasheetDensity {
            rho15_kg_m3,
            expansion15_per_k,
        })
    }

    /// Density at 15 C `rho15_kg_m3` with a given expansion coefficient at 15 C.
    pub fn with_expansion(
        rho15_kg_m3: f64,
        expansion15_per_k: f64,
    ) -> Result<Self, DatasheetError> {
        check_positive("rho15_kg_m3", rho15_kg_m3)?;
        check_positive("expansion15_per_k", expansion15_per_k)?;
        Ok(DatasheetDensity {
            rho15_kg_m3,
            expansion15_per_k,
        })
    }

    /// Density at 15 C, kg/m^3.
    pub fn rho15_kg_m3(&self) -> f64 {
        self.rho15_kg_m3
    }

    /// Expansion coefficient at 15 C, 1/K.
    pub fn expansion15_per_k(&self) -> f64 {
        self.expansion15_per_k
    }

    /// Density at `temperature_c`, kg/m^3.
    pub fn rho_kg_m3(&self, temperature_c: f64) -> Result<f64, DatasheetError> {
        let (lo_c, hi_c) = WALTHER_TEMPERATURE_RANGE_C;
        if !(lo_c..=hi_c).contains(&temperature_c) {
            return Err(DatasheetError::TemperatureOutOfRange {
                temperature_c,
                lo_c,
                hi_c,
            });
        }
        let a_dt = self.expansion15_per_k * (temperature_c - 15.0);
        Ok(self.rho15_kg_m3 * (-a_dt * (1.0 + 0.8 * a_dt)).exp())
    }
}

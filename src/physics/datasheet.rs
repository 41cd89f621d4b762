//! A lubricant as its datasheet gives it: kinematic viscosity at 40 C (measured, or an ISO VG
//! grade), kinematic viscosity at 100 C (measured, or a viscosity index), density at 15 C and
//! the base-oil type. From these: kinematic viscosity at any temperature (ASTM D341,
//! [`super::walther`]), density (ASTM D1250 Table 54D), dynamic viscosity `eta = nu rho`, and
//! the pressure-viscosity coefficient with its band (AGMA 925, [`super::pressure_viscosity`]).
//!
//! A datasheet in a case file reads, for example,
//!
//! ```toml
//! iso_vg = 46               # or nu40_mm2_s = 46.0
//! viscosity_index = 100     # or nu100_mm2_s = 6.8
//! rho15_kg_m3 = 870
//! base_oil = "mineral"      # "polyalphaolefin" ("pao") or "polyglycol" ("pag")
//! ```

use serde::{Deserialize, Serialize};

mod density;
pub use density::{
    DatasheetDensity, D1250_TABLE_54D_K0, D1250_TABLE_54D_K1, D1250_TABLE_54D_RHO15_KG_M3,
};

use super::lubricant::LubricantState;
use super::pressure_viscosity::{
    alpha_agma925, BaseOil, PressureViscosityError, PressureViscosityEstimate,
};
use super::viscosity_index::{nu100_from_viscosity_index, viscosity_index, ViscosityIndexError};
use super::walther::{WaltherError, WaltherLine};

/// ISO 3448 viscosity grades: `(grade, midpoint kinematic viscosity at 40 C in mm^2/s)`. A
/// grade's limits are the midpoint +-10 %.
pub const ISO_3448_GRADES: [(u32, f64); 20] = [
    (2, 2.2),
    (3, 3.2),
    (5, 4.6),
    (7, 6.8),
    (10, 10.0),
    (15, 15.0),
    (22, 22.0),
    (32, 32.0),
    (46, 46.0),
    (68, 68.0),
    (100, 100.0),
    (150, 150.0),
    (220, 220.0),
    (320, 320.0),
    (460, 460.0),
    (680, 680.0),
    (1000, 1000.0),
    (1500, 1500.0),
    (2200, 2200.0),
    (3200, 3200.0),
];

/// Errors of a datasheet.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DatasheetError {
    /// Neither of two fields that give a quantity.
    #[error("give {field} or {alternative}")]
    Missing {
        /// One field.
        field: &'static str,
        /// The field that can replace it.
        alternative: &'static str,
    },
    /// Both of two fields that give the same quantity.
    #[error("give {field} or {other}, not both")]
    Conflicting {
        /// One field.
        field: &'static str,
        /// The other.
        other: &'static str,
    },
    /// A grade not in ISO 3448.
    #[error("iso_vg = {grade} is not an ISO 3448 grade (grades: {known})")]
    UnknownIsoVg {
        /// The grade given.
        grade: u32,
        /// The ISO 3448 grades.
        known: String,
    },
    /// A density or expansion coefficient that is zero, negative or not finite.
    #[error("{field} = {value}: must be a positive finite number")]
    NotPositive {
        /// The input's name.
        field: &'static str,
        /// Its value.
        value: f64,
    },
    /// A density outside ASTM D1250 Table 54D, when its expansion coefficient is used.
    #[error(
        "rho15_kg_m3 = {rho15_kg_m3} is outside ASTM D1250 Table 54D ({lo}..{hi} kg/m^3); \
         give expansion15_per_k to use another density"
    )]
    Rho15OutsideTable54D {
        /// The density given, kg/m^3.
        rho15_kg_m3: f64,
        /// Lowest density of the table, kg/m^3.
        lo: f64,
        /// Highest density of the table, kg/m^3.
        hi: f64,
    },
    /// A temperature outside the density law's range.
    #[error(
        "temperature_c = {temperature_c} C is outside the density law's range ({lo_c}..{hi_c} C)"
    )]
    TemperatureOutOfRange {
        /// The temperature asked for, C.
        temperature_c: f64,
        /// Lowest accepted temperature, C.
        lo_c: f64,
        /// Highest accepted temperature, C.
        hi_c: f64,
    },
    /// The viscosity-temperature line (ASTM D341).
    #[error(transparent)]
    Walther(#[from] WaltherError),
    /// The viscosity index (ASTM D2270).
    #[error(transparent)]
    ViscosityIndex(#[from] ViscosityIndexError),
    /// The pressure-viscosity correlation (AGMA 925).
    #[error(transparent)]
    PressureViscosity(#[from] PressureViscosityError),
}

impl DatasheetError {
    /// The case-file key the error is about (a key of [`Datasheet`], `temperature_c` or
    /// `alpha_per_gpa`), so that a command line can name its flag and a study its field.
    pub fn field(&self) -> &'static str {
        match self {
            DatasheetError::Missing { field, .. } => field,
            DatasheetError::Conflicting { other, .. } => other,
            DatasheetError::UnknownIsoVg { .. } => "iso_vg",
            DatasheetError::NotPositive { field, .. } => field,
            DatasheetError::Rho15OutsideTable54D { .. } => "rho15_kg_m3",
            DatasheetError::TemperatureOutOfRange { .. } => "temperature_c",
            DatasheetError::Walther(e) => match e {
                // The line is built through (40 C, nu40) and (100 C, nu100).
                WaltherError::NotPositive { field, .. }
                | WaltherError::ViscosityBelowRange { field, .. } => match *field {
                    "nu1_mm2_s" => "nu40_mm2_s",
                    "nu2_mm2_s" => "nu100_mm2_s",
                    // A predicted viscosity below the line's floor: the temperature is too
                    // high for this oil.
                    _ => "temperature_c",
                },
                WaltherError::TemperatureOutOfRange { .. } => "temperature_c",
                WaltherError::NotFalling { .. } => "nu100_mm2_s",
            },
            DatasheetError::ViscosityIndex(e) => match e {
                ViscosityIndexError::NotPositive { field, .. } => field,
                ViscosityIndexError::Nu100NotBelowNu40 { .. }
                | ViscosityIndexError::Nu100BelowD2270 { .. } => "nu100_mm2_s",
                ViscosityIndexError::ViscosityIndexOutOfRange { .. } => "viscosity_index",
            },
            // Unreachable from a datasheet (eta = nu rho > 0); the viscosity at the
            // temperature is what it was computed from.
            DatasheetError::PressureViscosity(_) => "temperature_c",
        }
    }
}

/// An ISO 3448 viscosity grade.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoVg {
    grade: u32,
    nu40_mm2_s: f64,
}

impl IsoVg {
    /// The ISO 3448 grade `grade` (2, 3, 5, 7, 10, 15, ..., 3200).
    pub fn new(grade: u32) -> Result<Self, DatasheetError> {
        ISO_3448_GRADES
            .iter()
            .find(|(g, _)| *g == grade)
            .map(|&(grade, nu40_mm2_s)| IsoVg { grade, nu40_mm2_s })
            .ok_or_else(|| DatasheetError::UnknownIsoVg {
                grade,
                known: ISO_3448_GRADES
                    .iter()
                    .map(|(g, _)| g.to_string())
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }

    /// The grade number.
    pub fn grade(&self) -> u32 {
        self.grade
    }

    /// Midpoint kinematic viscosity at 40 C, mm^2/s.
    pub fn nu40_mm2_s(&self) -> f64 {
        self.nu40_mm2_s
    }

    /// The grade's limits at 40 C, midpoint -10 % and +10 %, mm^2/s.
    pub fn nu40_limits_mm2_s(&self) -> (f64, f64) {
        (0.9 * self.nu40_mm2_s, 1.1 * self.nu40_mm2_s)
    }
}

/// A lubricant's datasheet, as a case file gives it. The 40 C viscosity comes from
/// `nu40_mm2_s` or `iso_vg`, the 100 C one from `nu100_mm2_s` or `viscosity_index`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Datasheet {
    /// Kinematic viscosity at 40 C (ASTM D445), mm^2/s.
    pub nu40_mm2_s: Option<f64>,
    /// ISO 3448 grade: the 40 C viscosity is its midpoint.
    pub iso_vg: Option<u32>,
    /// Kinematic viscosity at 100 C (ASTM D445), mm^2/s.
    pub nu100_mm2_s: Option<f64>,
    /// Viscosity index (ASTM D2270): the 100 C viscosity follows from it.
    pub viscosity_index: Option<f64>,
    /// Density at 15 C, kg/m^3.
    pub rho15_kg_m3: f64,
    /// Thermal expansion coefficient at 15 C, 1/K; ASTM D1250 Table 54D's when absent.
    pub expansion15_per_k: Option<f64>,
    /// Base-oil type.
    pub base_oil: BaseOil,
}

impl Datasheet {
    /// A short description for tables and listings (no commas, so a CSV cell needs no
    /// quotes), e.g. `ISO VG 68 VI 97 mineral`.
    pub fn label(&self) -> String {
        let g = |x: f64| format!("{:.4e}", x).parse::<f64>().unwrap_or(x);
        let nu40 = match (self.iso_vg, self.nu40_mm2_s) {
            (Some(vg), _) => format!("ISO VG {vg}"),
            (None, Some(nu)) => format!("nu40 {} mm^2/s", g(nu)),
            (None, None) => "nu40 ?".into(),
        };
        let nu100 = match (self.viscosity_index, self.nu100_mm2_s) {
            (Some(vi), _) => format!("VI {}", g(vi)),
            (None, Some(nu)) => format!("nu100 {} mm^2/s", g(nu)),
            (None, None) => "nu100 ?".into(),
        };
        let oil = match self.base_oil {
            BaseOil::Mineral => "mineral",
            BaseOil::Polyalphaolefin => "PAO",
            BaseOil::Polyglycol => "PAG",
        };
        format!("{nu40} {nu100} {oil}")
    }

    /// Checks the datasheet and derives the lubricant's laws.
    pub fn resolve(&self) -> Result<DatasheetLubricant, DatasheetError> {
        let nu40_mm2_s = match (self.nu40_mm2_s, self.iso_vg) {
            (Some(nu), None) => nu,
            (None, Some(grade)) => IsoVg::new(grade)?.nu40_mm2_s(),
            (Some(_), Some(_)) => {
                return Err(DatasheetError::Conflicting {
                    field: "nu40_mm2_s",
                    other: "iso_vg",
                })
            }
            (None, None) => {
                return Err(DatasheetError::Missing {
                    field: "nu40_mm2_s",
                    alternative: "iso_vg",
                })
            }
        };
        let (nu100_mm2_s, vi) = match (self.nu100_mm2_s, self.viscosity_index) {
            (Some(nu100), None) => match viscosity_index(nu40_mm2_s, nu100) {
                Ok(vi) => (nu100, Some(vi)),
                // A 100 C viscosity below 2 mm^2/s has no VI, but still makes a D341 line.
                Err(ViscosityIndexError::Nu100BelowD2270 { .. }) => (nu100, None),
                Err(e) => return Err(e.into()),
            },
            (None, Some(vi)) => (nu100_from_viscosity_index(nu40_mm2_s, vi)?, Some(vi)),
            (Some(_), Some(_)) => {
                return Err(DatasheetError::Conflicting {
                    field: "nu100_mm2_s",
                    other: "viscosity_index",
                })
            }
            (None, None) => {
                return Err(DatasheetError::Missing {
                    field: "nu100_mm2_s",
                    alternative: "viscosity_index",
                })
            }
        };
        let walther = WaltherLine::through(40.0, nu40_mm2_s, 100.0, nu100_mm2_s)?;
        let density = match self.expansion15_per_k {
            Some(a15) => DatasheetDensity::with_expansion(self.rho15_kg_m3, a15)?,
            None => DatasheetDensity::d1250_table_54d(self.rho15_kg_m3)?,
        };
        Ok(DatasheetLubricant {
            nu40_mm2_s,
            nu100_mm2_s,
            viscosity_index: vi,
            walther,
            density,
            base_oil: self.base_oil,
        })
    }
}

/// A lubricant derived from its datasheet: viscosity, density and pressure-viscosity
/// coefficient at any temperature in the laws' range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DatasheetLubricant {
    nu40_mm2_s: f64,
    nu100_mm2_s: f64,
    viscosity_index: Option<f64>,
    walther: WaltherLine,
    density: DatasheetDensity,
    base_oil: BaseOil,
}

impl DatasheetLubricant {
    /// Kinematic viscosity at 40 C, mm^2/s.
    pub fn nu40_mm2_s(&self) -> f64 {
        self.nu40_mm2_s
    }

    /// Kinematic viscosity at 100 C, mm^2/s.
    pub fn nu100_mm2_s(&self) -> f64 {
        self.nu100_mm2_s
    }

    /// Viscosity index (unrounded); `None` when the 100 C viscosity is below 2 mm^2/s.
    pub fn viscosity_index(&self) -> Option<f64> {
        self.viscosity_index
    }

    /// The ASTM D341 line.
    pub fn walther(&self) -> &WaltherLine {
        &self.walther
    }

    /// The density law.
    pub fn density(&self) -> &DatasheetDensity {
        &self.density
    }

    /// Base-oil type.
    pub fn base_oil(&self) -> BaseOil {
        self.base_oil
    }

    /// Kinematic viscosity at `temperature_c`, mm^2/s (ASTM D341).
    pub fn nu_mm2_s(&self, temperature_c: f64) -> Result<f64, DatasheetError> {
        Ok(self.walther.nu_mm2_s(temperature_c)?)
    }

    /// Density at `temperature_c`, kg/m^3.
    pub fn rho_kg_m3(&self, temperature_c: f64) -> Result<f64, DatasheetError> {
        self.density.rho_kg_m3(temperature_c)
    }

    /// Dynamic viscosity at `temperature_c`, `eta = nu rho`, Pa s.
    pub fn eta_pa_s(&self, temperature_c: f64) -> Result<f64, DatasheetError> {
        Ok(self.nu_mm2_s(temperature_c)? * 1e-6 * self.rho_kg_m3(temperature_c)?)
    }

    /// Pressure-viscosity coefficient at `temperature_c` with its band (AGMA 925).
    pub fn alpha(&self, temperature_c: f64) -> Result<PressureViscosityEstimate, DatasheetError> {
        Ok(alpha_agma925(self.base_oil, self.eta_pa_s(temperature_c)?)?)
    }

    /// `alpha` (central value) and `eta0` at `temperature_c`, the same state Table 1 gives.
    pub fn state(&self, temperature_c: f64) -> Result<LubricantState, DatasheetError> {
        Ok(LubricantState {
            alpha_per_pa: self.alpha(temperature_c)?.alpha_per_pa,
            eta0_pa_s: self.eta_pa_s(temperature_c)?,
        })
    }
}

/// A datasheet lubricant at one temperature: the state the solver takes (`alpha`, `eta0`) and
/// what a report shows beside it (the viscosity and density it came from, and the
/// correlation's estimate of `alpha` with its band when the user gave none).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DatasheetState {
    /// Temperature, C.
    pub temperature_c: f64,
    /// Kinematic viscosity at the temperature (ASTM D341), mm^2/s.
    pub nu_mm2_s: f64,
    /// Density at the temperature (ASTM D1250), kg/m^3.
    pub rho_kg_m3: f64,
    /// `alpha` (given, or the correlation's central value) and `eta0 = nu rho`.
    pub state: LubricantState,
    /// The correlation's estimate and band; `None` when `alpha` was given.
    pub correlated: Option<PressureViscosityEstimate>,
}

impl DatasheetLubricant {
    /// The lubricant at `temperature_c`: `eta0 = nu rho` (D341, D1250) and `alpha`, the
    /// user's `alpha_per_gpa` when given (it replaces the correlation), else AGMA 925's.
    pub fn at(
        &self,
        temperature_c: f64,
        alpha_per_gpa: Option<f64>,
    ) -> Result<DatasheetState, DatasheetError> {
        let nu_mm2_s = self.nu_mm2_s(temperature_c)?;
        let rho_kg_m3 = self.rho_kg_m3(temperature_c)?;
        // The same product as [`DatasheetLubricant::eta_pa_s`], so both give the same bits.
        let eta0_pa_s = nu_mm2_s * 1e-6 * rho_kg_m3;
        let (alpha_per_pa, correlated) = match alpha_per_gpa {
            Some(a) => {
                check_positive("alpha_per_gpa", a)?;
                (a * 1e-9, None)
            }
            None => {
                let e = alpha_agma925(self.base_oil, eta0_pa_s)?;
                (e.alpha_per_pa, Some(e))
            }
        };
        Ok(DatasheetState {
            temperature_c,
            nu_mm2_s,
            rho_kg_m3,
            state: LubricantState {
                alpha_per_pa,
                eta0_pa_s,
            },
            correlated,
        })
    }
}

fn check_positive(field: &'static str, value: f64) -> Result<(), DatasheetError> {
    if !(value > 0.0 && value.is_finite()) {
        return Err(DatasheetError::NotPositive { field, value });
    }
    Ok(())
}

#[cfg(test)]
mod tests;

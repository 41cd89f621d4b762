//! The lubricant and physics inputs: a lubricant of Table 1, `alpha` and `eta0` given, or a
//! datasheet; the rheology and its parameters; the laws over a form's defaults. Which inputs
//! go together is checked here.

use super::error::{need, need_with, InputError};
use crate::physics::case::{LubricantSpec, Physics};
use crate::physics::datasheet::Datasheet;
use crate::physics::density::DensityLaw;
use crate::physics::pressure_viscosity::BaseOil;
use crate::physics::rheology::{LimitingShearStress, Rheology};
use crate::physics::viscosity::ViscosityLaw;

/// A lubricant's datasheet as given: eta0 = nu rho at the temperature by ASTM D341 and
/// D1250, alpha from AGMA 925 for the base oil unless alpha is given.
#[derive(Debug, Clone, Default)]
pub struct DatasheetInputs {
    /// Kinematic viscosity at 40 C, mm^2/s (or `iso_vg`).
    pub nu40: Option<f64>,
    /// ISO 3448 viscosity grade (or `nu40`).
    pub iso_vg: Option<u32>,
    /// Kinematic viscosity at 100 C, mm^2/s (or `vi`).
    pub nu100: Option<f64>,
    /// Viscosity index, ASTM D2270 (or `nu100`).
    pub vi: Option<f64>,
    /// Density at 15 C, kg/m^3.
    pub rho15: Option<f64>,
    /// Thermal expansion coefficient at 15 C, 1/K.
    pub expansion15: Option<f64>,
    /// Base-oil type, for the pressure-viscosity correlation.
    pub base_oil: Option<BaseOil>,
}

impl DatasheetInputs {
    /// Whether any datasheet input was given.
    pub fn any(&self) -> bool {
        self.nu40.is_some()
            || self.iso_vg.is_some()
            || self.nu100.is_some()
            || self.vi.is_some()
            || self.rho15.is_some()
            || self.expansion15.is_some()
            || self.base_oil.is_some()
    }
}

/// The rheology asked for; the limiting shear stress's parameters are inputs of their own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RheologyChoice {
    /// Eyring, the paper's.
    Eyring,
    /// Newtonian.
    Newtonian,
    /// Eyring with a limiting shear stress tau_L = tau_L0 + Lambda p (beyond the paper).
    EyringLss,
}

/// The lubricant of the physical form: a lubricant of Table 1 at `temperature`, `alpha` and
/// `eta0` given directly, or a datasheet at `temperature` (with `alpha` when the user knows
/// it). Which inputs go together is checked here; the datasheet's values are checked when
/// the case is resolved.
pub fn lubricant_spec(
    lubricant: Option<&str>,
    temperature: Option<f64>,
    alpha: Option<f64>,
    eta0: Option<f64>,
    sheet: &DatasheetInputs,
) -> Result<LubricantSpec, InputError> {
    if sheet.any() {
        if lubricant.is_some() {
            return Err(InputError::invalid("lubricant", "a lubricant of Table 1 and datasheet flags (--nu40, --iso-vg, --nu100, --vi, --rho15, --expansion15, --base-oil) cannot be mixed"));
        }
        if eta0.is_some() {
            return Err(InputError::invalid(
                "eta0",
                "a datasheet gives eta0 (nu rho at --temperature); drop --eta0",
            ));
        }
        // One of two flags that give the same property: `(flag, other, what to write when
        // neither is given)`.
        let one_of =
            |a: bool, b: bool, (fa, fb, with): (&'static str, &'static str, &'static str)| match (
                a, b,
            ) {
                (true, true) => Err(InputError::invalid(
                    fb,
                    format!("give --{fa} or --{fb}, not both"),
                )),
                (false, false) => Err(InputError::missing_with(fa, with)),
                _ => Ok(()),
            };
        one_of(
            sheet.nu40.is_some(),
            sheet.iso_vg.is_some(),
            ("nu40", "iso-vg", "with a datasheet (or --iso-vg)"),
        )?;
        one_of(
            sheet.nu100.is_some(),
            sheet.vi.is_some(),
            ("nu100", "vi", "with a datasheet (or --vi)"),
        )?;
        let datasheet = Datasheet {
            nu40_mm2_s: sheet.nu40,
            iso_vg: sheet.iso_vg,
            nu100_mm2_s: sheet.nu100,
            viscosity_index: sheet.vi,
            rho15_kg_m3: need_with(sheet.rho15, "rho15", "with a datasheet")?,
            expansion15_per_k: sheet.expansion15,
            base_oil: match sheet.base_oil {
                Some(b) => b,
                None => {
                    return Err(InputError::missing_with(
                        "base-oil",
                        "with a datasheet (mineral, pao or pag)",
                    ))
                }
            },
        };
        return Ok(LubricantSpec::Datasheet {
            datasheet,
            temperature_c: need_with(temperature, "temperature", "with a datasheet")?,
            alpha_per_gpa: alpha.map(|a| a * 1e9),
        });
    }
    Ok(match (lubricant, alpha) {
        (Some(name), None) => LubricantSpec::Named {
            lubricant: name.to_string(),
            temperature_c: need(temperature, "temperature")?,
        },
        (None, Some(alpha)) => LubricantSpec::Given {
            alpha_per_pa: alpha,
            eta0_pa_s: need(eta0, "eta0")?,
        },
        (Some(_), Some(_)) => {
            return Err(InputError::invalid(
                "alpha",
                "cannot be mixed with --lubricant (a lubricant of Table 1 has its own alpha)",
            ))
        }
        (None, None) => {
            return Err(InputError::missing_with(
                "lubricant",
                "(or --alpha and --eta0)",
            ))
        }
    })
}

/// The rheology inputs: `eyring-lss` needs `lambda_lss` and `tau_l0`, which mean nothing
/// with another rheology.
pub fn rheology(
    rheology: Option<RheologyChoice>,
    lambda_lss: Option<f64>,
    tau_l0: Option<f64>,
) -> Result<Option<Rheology>, InputError> {
    Ok(match rheology {
        Some(RheologyChoice::EyringLss) => Some(Rheology::EyringLss(LimitingShearStress {
            lambda: need_with(lambda_lss, "lambda-lss", "with --rheology eyring-lss")?,
            tau_l0_pa: need_with(tau_l0, "tau-l0", "with --rheology eyring-lss")?,
        })),
        _ if lambda_lss.is_some() || tau_l0.is_some() => {
            let flag = if lambda_lss.is_some() {
                "lambda-lss"
            } else {
                "tau-l0"
            };
            return Err(InputError::invalid(
                flag,
                "the limiting shear stress's parameters need --rheology eyring-lss",
            ));
        }
        Some(RheologyChoice::Eyring) => Some(Rheology::Eyring),
        Some(RheologyChoice::Newtonian) => Some(Rheology::Newtonian),
        None => None,
    })
}

/// The physics inputs over `defaults`.
pub fn physics(
    viscosity: Option<ViscosityLaw>,
    density: Option<DensityLaw>,
    rheology: Option<Rheology>,
    defaults: Physics,
) -> Physics {
    Physics {
        viscosity: viscosity.unwrap_or(defaults.viscosity),
        density: density.unwrap_or(defaults.density),
        rheology: rheology.unwrap_or(defaults.rheology),
    }
}

//! An operating point of a sweep file to a case: which keys are given decides its form, a
//! missing or inconsistent key is an error naming it.

use super::error::{field, SweepError};
use super::lubricants::StudyLubricant;
use super::PointSpec;
use crate::physics::case::{
    Case, CaseError, CaseForm, DimensionlessCase, LubricantSpec, PhysicalCase, Physics,
};
use std::collections::BTreeMap;

impl PointSpec {
    /// The case this point describes, or an error naming the missing field.
    pub fn to_case(&self, file: &str, physics: Physics) -> Result<Case, SweepError> {
        self.to_case_with(file, physics, &BTreeMap::new())
    }

    /// The case this point describes, its `lubricant` looked up first among the study's own
    /// `lubricants`, then in Table 1.
    pub fn to_case_with(
        &self,
        file: &str,
        physics: Physics,
        lubricants: &BTreeMap<String, StudyLubricant>,
    ) -> Result<Case, SweepError> {
        let need = |v: Option<f64>, name: &str| v.ok_or_else(|| field(file, name, "missing"));
        let dimensionless = self.m.is_some() || self.l.is_some() || self.s_bar.is_some();
        let spec = if dimensionless {
            let s_bar = need(self.s_bar, "s_bar")?;
            let slip = match (self.slip, self.tau0_hat) {
                (Some(s), None) => s,
                (None, Some(t)) => t * s_bar,
                (None, None) => {
                    return Err(field(
                        file,
                        "slip",
                        "give slip or tau0_hat for a dimensionless point",
                    ))
                }
                (Some(_), Some(_)) => {
                    return Err(field(
                        file,
                        "tau0_hat",
                        "give either slip or tau0_hat, not both",
                    ))
                }
            };
            CaseForm::Dimensionless(DimensionlessCase {
                m: need(self.m, "m")?,
                l: need(self.l, "l")?,
                s_bar,
                d: self.d.unwrap_or(1.0),
                slip,
                eta0_pa_s: self.eta0_mpa_s.map(|v| v * 1e-3),
                ph_pa: self.ph_gpa.map(|v| v * 1e9),
            })
        } else {
            let lubricant = match (&self.lubricant, self.alpha_per_gpa) {
                (Some(name), None) if lubricants.contains_key(name) => {
                    let own = &lubricants[name];
                    let spec = LubricantSpec::Datasheet {
                        datasheet: own.datasheet.clone(),
                        temperature_c: need(self.temperature_c, "temperature_c")?,
                        alpha_per_gpa: own.alpha_per_gpa,
                    };
                    // The datasheet itself was checked; what is left is the temperature.
                    if let Some(Err(e)) = spec.datasheet_state() {
                        let key = match &e {
                            CaseError::Datasheet(d) if d.field() != "temperature_c" => {
                                format!("lubricants.{name}.{}", d.field())
                            }
                            _ => "temperature_c".to_string(),
                        };
                        return Err(field(file, &key, e.to_string()));
                    }
                    spec
                }
                (Some(name), None) => LubricantSpec::Named {
                    lubricant: name.clone(),
                    temperature_c: need(self.temperature_c, "temperature_c")?,
                },
                (None, Some(a)) => LubricantSpec::Given {
                    alpha_per_pa: a * 1e-9,
                    eta0_pa_s: need(self.eta0_mpa_s, "eta0_mpa_s")? * 1e-3,
                },
                (Some(_), Some(_)) => {
                    return Err(field(
                        file,
                        "alpha_per_gpa",
                        "give a lubricant name or alpha_per_gpa/eta0_mpa_s, not both",
                    ))
                }
                (None, None) => {
                    return Err(field(
                        file,
                        "lubricant",
                        "missing (or give alpha_per_gpa and eta0_mpa_s)",
                    ))
                }
            };
            let rx = need(self.rx_m, "rx_m")?;
            let d = self.d.unwrap_or(1.0);
            if !(d > 0.0 && d <= 1.0) {
                return Err(field(
                    file,
                    "d",
                    format!("Rx/Ry must lie in (0, 1], got {d}"),
                ));
            }
            CaseForm::Physical(PhysicalCase {
                lubricant,
                ph_pa: need(self.ph_gpa, "ph_gpa")? * 1e9,
                um_m_s: need(self.um_m_s, "um_m_s")?,
                slip: need(self.slip, "slip")?,
                tau0_pa: need(self.tau0_mpa, "tau0_mpa")? * 1e6,
                rx_m: rx,
                ry_m: rx / d,
                e_prime_pa: need(self.e_prime_gpa, "e_prime_gpa")? * 1e9,
            })
        };
        Ok(Case { spec, physics })
    }
}

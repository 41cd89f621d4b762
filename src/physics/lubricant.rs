//! Lubricant properties at ambient pressure (Table 1), read from `cases/lubricants.toml`.

use serde::Deserialize;
use std::collections::BTreeMap;

/// The lubricant table shipped with the program (`cases/lubricants.toml`).
pub const TABLE1_TOML: &str = include_str!("../../cases/lubricants.toml");

/// Errors of the lubricant table.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum LubricantError {
    /// The TOML did not parse or a field is missing.
    #[error("lubricant table: {0}")]
    Parse(String),
    /// A lubricant's columns differ in length or are not sorted by temperature.
    #[error("lubricant '{name}': {what}")]
    Invalid {
        /// Lubricant name.
        name: String,
        /// What is wrong.
        what: String,
    },
    /// No lubricant of that name.
    #[error("unknown lubricant '{name}' (known: {known})")]
    Unknown {
        /// The name asked for.
        name: String,
        /// The known names.
        known: String,
    },
    /// A temperature outside the tabulated range.
    #[error(
        "lubricant '{name}': temperature {temperature_c} C is outside the table ({lo}..{hi} C)"
    )]
    Temperature {
        /// Lubricant name.
        name: String,
        /// The temperature asked for.
        temperature_c: f64,
        /// Lowest tabulated temperature.
        lo: f64,
        /// Highest tabulated temperature.
        hi: f64,
    },
}

/// One lubricant: `alpha` and `eta0` at a few temperatures.
#[derive(Debug, Clone, Deserialize, PartialEq)]
pub struct Lubricant {
    /// Name as in the paper.
    pub description: String,
    /// Tabulated temperatures, C, increasing.
    pub temperature_c: Vec<f64>,
    /// Pressure-viscosity coefficient, 1/GPa.
    pub alpha_per_gpa: Vec<f64>,
    /// Ambient-pressure viscosity, mPa s.
    pub eta0_mpa_s: Vec<f64>,
}

/// `alpha` and `eta0` at one temperature, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LubricantState {
    /// Pressure-viscosity coefficient, 1/Pa.
    pub alpha_per_pa: f64,
    /// Ambient-pressure viscosity, Pa s.
    pub eta0_pa_s: f64,
}

impl Lubricant {
    /// Properties at `temperature_c`: the tabulated values where the table has the
    /// temperature, otherwise linear in `alpha` and in `ln eta0` between neighbours.
    pub fn at(&self, name: &str, temperature_c: f64) -> Result<LubricantState, LubricantError> {
        let t = &self.temperature_c;
        let (lo, hi) = (t[0], t[t.len() - 1]);
        if !(lo..=hi).contains(&temperature_c) {
            return Err(LubricantError::Temperature {
                name: name.to_string(),
                temperature_c,
                lo,
                hi,
            });
        }
        let i = t
            .iter()
            .rposition(|&ti| ti <= temperature_c)
            .unwrap_or(0)
            .min(t.len() - 1);
        let j = (i + 1).min(t.len() - 1);
        let w = if j == i {
            0.0
        } else {
            (temperature_c - t[i]) / (t[j] - t[i])
        };
        let alpha = (1.0 - w) * self.alpha_per_gpa[i] + w * self.alpha_per_gpa[j];
        let ln_eta = (1.0 - w) * self.eta0_mpa_s[i].ln() + w * self.eta0_mpa_s[j].ln();
        Ok(LubricantState {
            alpha_per_pa: alpha * 1e-9,
            eta0_pa_s: ln_eta.exp() * 1e-3,
        })
    }

    fn validate(&self, name: &str) -> Result<(), LubricantError> {
        let bad = |what: &str| LubricantError::Invalid {
            name: name.into(),
            what: what.into(),
        };
        let n = self.temperature_c.len();
        if n == 0 || self.alpha_per_gpa.len() != n || self.eta0_mpa_s.len() != n {
            return Err(bad(
                "temperature_c, alpha_per_gpa and eta0_mpa_s must have one entry per temperature",
            ));
        }
        if self.temperature_c.windows(2).any(|w| w[1] <= w[0]) {
            return Err(bad("temperature_c must increase"));
        }
        if self
            .alpha_per_gpa
            .iter()
            .chain(&self.eta0_mpa_s)
            .any(|&v| !(v > 0.0 && v.is_finite()))
        {
            return Err(bad("alpha_per_gpa and eta0_mpa_s must be positive"));
        }
        Ok(())
    }
}

/// All lubricants by name.
#[derive(Debug, Clone, PartialEq)]
pub struct LubricantTable(pub BTreeMap<String, Lubricant>);

impl LubricantTable {
    /// Parses and validates a table in the format of `cases/lubricants.toml`.
    pub fn parse(text: &str) -> Result<Self, LubricantError> {
        let map: BTreeMap<String, Lubricant> =
            toml::from_str(text).map_err(|e| LubricantError::Parse(e.to_string()))?;
        for (name, lub) in &map {
            lub.validate(name)?;
        }
        Ok(LubricantTable(map))
    }

    /// Table 1 as shipped.
    pub fn table1() -> Self {
        // The shipped table is checked by a unit test; a failure here is a build defect.
        Self::parse(TABLE1_TOML).expect("cases/lubricants.toml is valid")
    }

    /// Looks a lubricant up by name.
    pub fn get(&self, name: &str) -> Result<&Lubricant, LubricantError> {
        self.0.get(name).ok_or_else(|| LubricantError::Unknown {
            name: name.to_string(),
            known: self.0.keys().cloned().collect::<Vec<_>>().join(", "),
        })
    }

    /// Properties of lubricant `name` at `temperature_c`.
    pub fn state(&self, name: &str, temperature_c: f64) -> Result<LubricantState, LubricantError> {
        self.get(name)?.at(name, temperature_c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table1_parses_and_gives_the_paper_values() {
        let t = LubricantTable::table1();
        assert_eq!(t.0.len(), 3);
        let s = t.state("mineral-oil-a", 40.0).unwrap();
        assert!((s.alpha_per_pa - 21.6e-9).abs() < 1e-20);
        assert!((s.eta0_pa_s - 8.24e-3).abs() < 1e-15);
        let s = t.state("5p4e", 100.0).unwrap();
        assert!((s.eta0_pa_s - 15e-3).abs() < 1e-15);
    }

    #[test]
    fn interpolates_between_and_refuses_outside() {
        let t = LubricantTable::table1();
        let s = t.state("traction-fluid", 50.0).unwrap();
        assert!((s.alpha_per_pa - 25.75e-9).abs() < 1e-18);
        assert!((s.eta0_pa_s - (28.4e-3_f64 * 13.1e-3).sqrt()).abs() < 1e-12);
        assert!(matches!(
            t.state("traction-fluid", 20.0),
            Err(LubricantError::Temperature { .. })
        ));
        let e = t.state("castor-oil", 40.0).unwrap_err().to_string();
        assert!(
            e.contains("castor-oil") && e.contains("mineral-oil-a"),
            "{e}"
        );
    }

    #[test]
    fn malformed_tables_name_the_lubricant_and_field() {
        let e = LubricantTable::parse("[x]\ndescription='x'\ntemperature_c=[40.0]\nalpha_per_gpa=[1.0,2.0]\neta0_mpa_s=[1.0]\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("'x'") && e.contains("alpha_per_gpa"), "{e}");
        let e = LubricantTable::parse("[x]\ndescription='x'\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("temperature_c"), "{e}");
    }
}

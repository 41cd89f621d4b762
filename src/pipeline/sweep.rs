//! Sweep files: the readable case definitions under `cases/` and users' own studies.
//!
//! A sweep is a TOML file with the physics, the solver level, and either a full-factorial
//! grid of operating points (`[grid]`, every combination of the listed values), a list of
//! explicit points (`[[point]]`), or both. A point is physical (lubricant, temperature, p_H,
//! u_m, S, tau0, Rx, Ry or D, E') or dimensionless (M, L, S-bar, D and either S or the
//! dimensionless Eyring stress `tau0_hat = tau0 / (E' sqrt(U))`, so that `S = tau0_hat S-bar`).
//!
//! ```toml
//! title = "My lubricant on the mastercurve"
//! [physics]
//! viscosity = "roelands"          # barus | roelands
//! density = "dowson-higginson"    # incompressible | dowson-higginson
//! rheology = "eyring"             # eyring | newtonian, or a limiting shear stress:
//!                                 # { eyring-lss = { lambda = 0.08, tau_l0_pa = 5e6 } }
//! [grid]
//! alpha_per_gpa = [18.0]          # or lubricant = ["mineral-oil-a"] with temperature_c
//! eta0_mpa_s = [12.0]
//! ph_gpa = [1.0, 2.0]
//! um_m_s = [5.0, 10.0]
//! slip = [0.002, 0.01]
//! tau0_mpa = [5.0]
//! rx_m = [0.01]
//! d = [1.0]                        # Rx/Ry
//! e_prime_gpa = [226.0]
//! ```
//!
//! A study may define its own lubricants from their datasheets, inline, as `[lubricants.NAME]`
//! tables (the keys of [`crate::physics::datasheet::Datasheet`], and `alpha_per_gpa` when the
//! pressure-viscosity coefficient is known; without it AGMA 925's correlation gives it), and
//! use them by name with a temperature in `[grid]`, `[defaults]` or `[[point]]`:
//!
//! ```toml
//! [lubricants.gear-oil]
//! iso_vg = 68                     # or nu40_mm2_s
//! viscosity_index = 97            # or nu100_mm2_s
//! rho15_kg_m3 = 880
//! base_oil = "mineral"            # mineral | pao | pag
//! # expansion15_per_k = 6.9e-4    # default: ASTM D1250 Table 54D
//! # alpha_per_gpa = 22.0          # default: AGMA 925 from eta at the temperature
//! [grid]
//! lubricant = ["gear-oil"]
//! temperature_c = [60.0, 80.0]    # any temperature in -20..150 C
//! ```
//!
//! The names of Table 1 (`cases/lubricants.toml`) keep meaning Table 1's lubricants: a study
//! cannot redefine them. Each case carries the whole datasheet, so the case alone determines
//! its cache key; two studies with the same oil share their solves whatever they call it.

use crate::physics::case::{
    Case, CaseError, CaseForm, DimensionlessCase, LubricantSpec, PhysicalCase, Physics,
};
use crate::physics::datasheet::Datasheet;
use crate::physics::lubricant::LubricantTable;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;

/// A sweep that cannot be read: names the file and the field.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SweepError {
    /// The file could not be read.
    #[error("{file}: cannot read: {message}")]
    Io {
        /// File name.
        file: String,
        /// OS message.
        message: String,
    },
    /// The TOML did not parse (the message gives line and column).
    #[error("{file}: {message}")]
    Parse {
        /// File name.
        file: String,
        /// Parser message.
        message: String,
    },
    /// A field is missing or inconsistent.
    #[error("{file}: {field}: {message}")]
    Field {
        /// File name.
        file: String,
        /// The field.
        field: String,
        /// What is expected.
        message: String,
    },
}

/// One operating point as written in a sweep file: every key optional; which ones are given
/// decides the form.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    /// Lubricant of `cases/lubricants.toml`.
    pub lubricant: Option<String>,
    /// Temperature, C.
    pub temperature_c: Option<f64>,
    /// Pressure-viscosity coefficient, 1/GPa (instead of a named lubricant).
    pub alpha_per_gpa: Option<f64>,
    /// Ambient viscosity, mPa s (instead of a named lubricant; or for Roelands in the
    /// dimensionless form).
    pub eta0_mpa_s: Option<f64>,
    /// Maximum Hertzian pressure, GPa.
    pub ph_gpa: Option<f64>,
    /// Mean velocity, m/s.
    pub um_m_s: Option<f64>,
    /// Slide-to-roll ratio.
    pub slip: Option<f64>,
    /// Eyring stress, MPa.
    pub tau0_mpa: Option<f64>,
    /// Reduced radius along the rolling direction, m.
    pub rx_m: Option<f64>,
    /// Ellipticity ratio `Rx/Ry` (default 1).
    pub d: Option<f64>,
    /// Reduced modulus, GPa.
    pub e_prime_gpa: Option<f64>,
    /// Moes load parameter (dimensionless form).
    pub m: Option<f64>,
    /// Moes lubricant parameter.
    pub l: Option<f64>,
    /// Dimensionless slip, Eq. (9).
    pub s_bar: Option<f64>,
    /// Dimensionless Eyring stress `tau0 / (E' sqrt(U))`: sets `S = tau0_hat S-bar`.
    pub tau0_hat: Option<f64>,
}

/// The `[grid]` table: lists of values, every combination taken.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GridSpec {
    pub lubricant: Option<Vec<String>>,
    pub temperature_c: Option<Vec<f64>>,
    pub alpha_per_gpa: Option<Vec<f64>>,
    pub eta0_mpa_s: Option<Vec<f64>>,
    pub ph_gpa: Option<Vec<f64>>,
    pub um_m_s: Option<Vec<f64>>,
    pub slip: Option<Vec<f64>>,
    pub tau0_mpa: Option<Vec<f64>>,
    pub rx_m: Option<Vec<f64>>,
    pub d: Option<Vec<f64>>,
    pub e_prime_gpa: Option<Vec<f64>>,
    pub m: Option<Vec<f64>>,
    pub l: Option<Vec<f64>>,
    pub s_bar: Option<Vec<f64>>,
    pub tau0_hat: Option<Vec<f64>>,
}

/// A sweep file.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    /// Title for the CSV, the figure and the report.
    pub title: String,
    /// Physics (defaults: Barus, incompressible, Eyring).
    #[serde(default)]
    pub physics: Physics,
    /// Grid level (the target's default when absent).
    pub level: Option<u32>,
    /// Full-factorial grid.
    pub grid: Option<GridSpec>,
    /// Values shared by every explicit point unless the point sets them.
    pub defaults: Option<PointSpec>,
    /// Explicit points.
    #[serde(default)]
    pub point: Vec<PointSpec>,
    /// The study's own lubricants by name: a datasheet, and `alpha_per_gpa` when known
    /// (read by [`study_lubricants`]).
    #[serde(default)]
    pub lubricants: BTreeMap<String, toml::Table>,
}

/// A study's own lubricant: its datasheet and, when the user knows it, its `alpha`.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyLubricant {
    /// The datasheet.
    pub datasheet: Datasheet,
    /// Pressure-viscosity coefficient, 1/GPa, used instead of the correlation.
    pub alpha_per_gpa: Option<f64>,
}

/// The `[lubricants.NAME]` tables of a study, checked: a name of Table 1 is refused, and
/// each datasheet must be complete and consistent (its own errors name
/// `lubricants.NAME.KEY`).
pub fn study_lubricants(
    file: &str,
    tables: &BTreeMap<String, toml::Table>,
) -> Result<BTreeMap<String, StudyLubricant>, SweepError> {
    let table1 = LubricantTable::table1();
    let mut out = BTreeMap::new();
    for (name, table) in tables {
        let here = format!("lubricants.{name}");
        if table1.0.contains_key(name) {
            return Err(field(
                file,
                &here,
                format!("'{name}' is a lubricant of Table 1 (cases/lubricants.toml); give yours another name"),
            ));
        }
        let mut table = table.clone();
        let alpha_per_gpa = match table.remove("alpha_per_gpa") {
            None => None,
            Some(v) => Some(
                v.as_float()
                    .or(v.as_integer().map(|i| i as f64))
                    .ok_or_else(|| {
                        field(
                            file,
                            &format!("{here}.alpha_per_gpa"),
                            "must be a number (1/GPa)",
                        )
                    })?,
            ),
        };
        let datasheet: Datasheet = toml::Value::Table(table)
            .try_into()
            .map_err(|e| field(file, &here, e.to_string().trim_end()))?;
        datasheet
            .resolve()
            .map_err(|e| field(file, &format!("{here}.{}", e.field()), e.to_string()))?;
        out.insert(
            name.clone(),
            StudyLubricant {
                datasheet,
                alpha_per_gpa,
            },
        );
    }
    Ok(out)
}

/// A parsed sweep: its title, physics, level, and the cases in file order.
#[derive(Debug, Clone)]
pub struct Sweep {
    /// Title.
    pub title: String,
    /// Level asked for by the file.
    pub level: Option<u32>,
    /// The cases, deterministic order: the grid (last key fastest), then the points.
    pub cases: Vec<Case>,
}

fn field(file: &str, field: &str, message: impl Into<String>) -> SweepError {
    SweepError::Field {
        file: file.into(),
        field: field.into(),
        message: message.into(),
    }
}

/// Every combination of a grid, as points (the order of the keys in [`GridSpec`], the last
/// fastest).
fn expand(grid: &GridSpec) -> Vec<PointSpec> {
    let mut points = vec![PointSpec::default()];
    macro_rules! axis {
        ($name:ident) => {
            if let Some(values) = &grid.$name {
                points = points
                    .into_iter()
                    .flat_map(|p| {
                        values.iter().map(move |v| PointSpec {
                            $name: Some(v.clone()),
                            ..p.clone()
                        })
                    })
                    .collect();
            }
        };
    }
    axis!(lubricant);
    axis!(temperature_c);
    axis!(alpha_per_gpa);
    axis!(eta0_mpa_s);
    axis!(ph_gpa);
    axis!(um_m_s);
    axis!(slip);
    axis!(tau0_mpa);
    axis!(rx_m);
    axis!(d);
    axis!(e_prime_gpa);
    axis!(m);
    axis!(l);
    axis!(s_bar);
    axis!(tau0_hat);
    points
}

/// Fills the unset keys of `p` from `d`.
fn with_defaults(p: &PointSpec, d: &PointSpec) -> PointSpec {
    macro_rules! pick {
        ($($name:ident),*) => { PointSpec { $($name: p.$name.clone().or_else(|| d.$name.clone()),)* } };
    }
    pick!(
        lubricant,
        temperature_c,
        alpha_per_gpa,
        eta0_mpa_s,
        ph_gpa,
        um_m_s,
        slip,
        tau0_mpa,
        rx_m,
        d,
        e_prime_gpa,
        m,
        l,
        s_bar,
        tau0_hat
    )
}

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

impl Sweep {
    /// Parses sweep text; `file` names it in errors.
    pub fn parse(file: &str, text: &str) -> Result<Self, SweepError> {
        let raw: SweepFile = toml::from_str(text).map_err(|e| SweepError::Parse {
            file: file.into(),
            message: e.to_string(),
        })?;
        let defaults = raw.defaults.clone().unwrap_or_default();
        let mut points: Vec<PointSpec> = raw.grid.as_ref().map(expand).unwrap_or_default();
        points
            .iter_mut()
            .for_each(|p| *p = with_defaults(p, &defaults));
        points.extend(raw.point.iter().map(|p| with_defaults(p, &defaults)));
        if points.is_empty() {
            return Err(field(
                file,
                "grid",
                "the sweep has no [grid] and no [[point]]",
            ));
        }
        let lubricants = study_lubricants(file, &raw.lubricants)?;
        let cases = points
            .iter()
            .map(|p| p.to_case_with(file, raw.physics, &lubricants))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Sweep {
            title: raw.title,
            level: raw.level,
            cases,
        })
    }

    /// Reads and parses a sweep file.
    pub fn read(path: &Path) -> Result<Self, SweepError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| SweepError::Io {
            file: file.clone(),
            message: e.to_string(),
        })?;
        Self::parse(&file, &text)
    }
}

/// The sweep files shipped in `cases/`, by name (compiled in, so the binary runs anywhere).
pub fn shipped() -> BTreeMap<&'static str, &'static str> {
    BTreeMap::from([
        ("fig1-3", include_str!("../../cases/fig1-3.toml")),
        ("fig4", include_str!("../../cases/fig4.toml")),
        ("fig5", include_str!("../../cases/fig5.toml")),
        ("fig6", include_str!("../../cases/fig6.toml")),
        ("fig7", include_str!("../../cases/fig7.toml")),
    ])
}

/// A shipped sweep by name.
pub fn shipped_sweep(name: &str) -> Result<Sweep, SweepError> {
    let text = shipped().get(name).copied().ok_or_else(|| {
        field(
            &format!("cases/{name}.toml"),
            "name",
            "no such shipped sweep",
        )
    })?;
    Sweep::parse(&format!("cases/{name}.toml"), text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::Problem;
    use crate::physics::lubricant::LubricantTable;

    #[test]
    fn shipped_sweeps_parse_and_are_physical() {
        let lubs = LubricantTable::table1();
        for (name, expect) in [
            ("fig1-3", 125),
            ("fig4", 243),
            ("fig5", 243),
            ("fig6", 243),
            ("fig7", 10),
        ] {
            let s = shipped_sweep(name).unwrap();
            assert_eq!(s.cases.len(), expect, "{name}");
            for c in &s.cases {
                Problem::from_case(c, &lubs).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }

    #[test]
    fn grid_order_is_deterministic_last_key_fastest() {
        let s = Sweep::parse(
            "t.toml",
            "title = 't'\n[grid]\nm = [100.0, 200.0]\nl = [5.0, 10.0]\ns_bar = [0.1]\ntau0_hat = [2.0]\n",
        )
        .unwrap();
        let ml: Vec<(f64, f64)> = s
            .cases
            .iter()
            .map(|c| match &c.spec {
                CaseForm::Dimensionless(d) => (d.m, d.l),
                _ => unreachable!(),
            })
            .collect();
        assert_eq!(
            ml,
            vec![(100.0, 5.0), (100.0, 10.0), (200.0, 5.0), (200.0, 10.0)]
        );
        if let CaseForm::Dimensionless(d) = &s.cases[0].spec {
            assert!((d.slip - 0.2).abs() < 1e-15, "S = tau0_hat S-bar");
        }
    }

    /// A study of the ISO VG 68 gear oil (`physics::case::tests::gear_oil`) at 80 C, with
    /// `extra` lines in its lubricant table and `point` keys in its one point.
    fn gear_study(extra: &str, point: &str) -> String {
        format!(
            "title = 'g'\n[lubricants.gear-oil]\niso_vg = 68\nviscosity_index = 97\n\
             rho15_kg_m3 = 880\nbase_oil = 'mineral'\n{extra}\n[[point]]\n\
             lubricant = 'gear-oil'\nph_gpa = 1.0\num_m_s = 5.0\nslip = 0.01\ntau0_mpa = 5.0\n\
             rx_m = 1.03875e-2\ne_prime_gpa = 226.0\n{point}\n"
        )
    }

    #[test]
    fn a_study_lubricant_becomes_a_datasheet_case() {
        use crate::physics::case::tests::gear_oil;
        let s = Sweep::parse("g.toml", &gear_study("", "temperature_c = 80.0")).unwrap();
        let CaseForm::Physical(p) = &s.cases[0].spec else {
            panic!("physical")
        };
        assert_eq!(p.lubricant, gear_oil(None));
        // The user's alpha is carried into the case (and so into its key).
        let s = Sweep::parse(
            "g.toml",
            &gear_study("alpha_per_gpa = 25", "temperature_c = 80.0"),
        )
        .unwrap();
        let CaseForm::Physical(p) = &s.cases[0].spec else {
            panic!("physical")
        };
        assert_eq!(p.lubricant, gear_oil(Some(25.0)));
        // In a grid, with Table 1 beside it: Table 1's names keep meaning Table 1.
        let text = gear_study("", "temperature_c = 80.0").replace(
            "[[point]]",
            "[grid]\nlubricant = ['gear-oil', 'mineral-oil-a']\ntemperature_c = [60.0]\n\
             ph_gpa = [1.0]\num_m_s = [5.0]\nslip = [0.01]\ntau0_mpa = [5.0]\nrx_m = [0.01]\n\
             e_prime_gpa = [226.0]\n[[point]]",
        );
        let s = Sweep::parse("g.toml", &text).unwrap();
        let lubs: Vec<_> = s
            .cases
            .iter()
            .map(|c| match &c.spec {
                CaseForm::Physical(p) => p.lubricant.clone(),
                CaseForm::Dimensionless(_) => unreachable!(),
            })
            .collect();
        assert!(
            matches!(&lubs[0], LubricantSpec::Datasheet { temperature_c, .. } if *temperature_c == 60.0)
        );
        assert!(
            matches!(&lubs[1], LubricantSpec::Named { lubricant, .. } if lubricant == "mineral-oil-a")
        );
        assert_eq!(lubs[2], gear_oil(None));
    }

    #[test]
    fn study_lubricant_errors_name_the_file_and_field() {
        let err = |extra: &str, point: &str| {
            Sweep::parse("g.toml", &gear_study(extra, point))
                .unwrap_err()
                .to_string()
        };
        for (extra, point, needle) in [
            ("", "temperature_c = 200.0", "g.toml: temperature_c: "),
            ("", "", "g.toml: temperature_c: missing"),
            (
                "vi = 3",
                "temperature_c = 80.0",
                "g.toml: lubricants.gear-oil: unknown field `vi`",
            ),
            (
                "nu40_mm2_s = 68.0",
                "temperature_c = 80.0",
                "g.toml: lubricants.gear-oil.iso_vg: ",
            ),
            (
                "alpha_per_gpa = 'x'",
                "temperature_c = 80.0",
                "g.toml: lubricants.gear-oil.alpha_per_gpa: ",
            ),
            (
                "alpha_per_gpa = -2.0",
                "temperature_c = 80.0",
                "g.toml: lubricants.gear-oil.alpha_per_gpa: ",
            ),
            (
                "expansion15_per_k = 0.0",
                "temperature_c = 80.0",
                "g.toml: lubricants.gear-oil.expansion15_per_k: ",
            ),
        ] {
            let e = err(extra, point);
            assert!(e.starts_with(needle), "{extra} / {point}: {e}");
        }
        let e = Sweep::parse(
            "g.toml",
            &gear_study("", "temperature_c = 80.0").replace(
                "iso_vg = 68\nviscosity_index = 97",
                "nu40_mm2_s = 68.0\nnu100_mm2_s = 70.0",
            ),
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with("g.toml: lubricants.gear-oil.nu100_mm2_s: "),
            "{e}"
        );
        let e = Sweep::parse(
            "g.toml",
            &gear_study("", "temperature_c = 80.0").replace("gear-oil", "mineral-oil-a"),
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with("g.toml: lubricants.mineral-oil-a: ") && e.contains("Table 1"),
            "{e}"
        );
    }

    #[test]
    fn errors_name_the_file_and_field() {
        let e = Sweep::parse("my.toml", "title = 'x'\n[grid]\nph_gpa = [1.0]\n")
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("my.toml: lubricant"), "{e}");
        let e = Sweep::parse(
            "my.toml",
            "title = 'x'\n[grid]\nph_gpa = [1.0]\nbogus = [1]\n",
        )
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("my.toml") && e.contains("bogus"), "{e}");
        let e = Sweep::parse(
            "my.toml",
            "title = 'x'\n[[point]]\nm = 10.0\nl = 2.0\ns_bar = 0.1\n",
        )
        .unwrap_err()
        .to_string();
        assert!(e.contains("slip"), "{e}");
        let e = Sweep::parse("my.toml", "title = 'x'\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("no [grid]"), "{e}");
    }
}

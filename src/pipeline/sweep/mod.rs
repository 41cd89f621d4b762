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
//!
//! Files: `error.rs` (what a bad file is told), `lubricants.rs` (a study's own lubricants),
//! `point.rs` (an operating point to a case); the file's shape and its expansion here.

mod error;
mod lubricants;
mod point;
#[cfg(test)]
mod tests;

use crate::physics::case::{Case, Physics};
use error::field;
pub use error::SweepError;
pub use lubricants::{study_lubricants, StudyLubricant};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::Path;

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

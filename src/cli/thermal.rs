//! The thermal post-process as `repro solve` and `repro predict` print it: the shear-heating
//! correction of the sliding friction, and the warning where it exceeds
//! [`ISOTHERMAL_CORRECTION_MAX`] (the paper's isothermal assumption fails there).

use super::args::ThermalArgs;
use anyhow::{bail, Result};
use repro::physics::case::{Case, Problem};
use repro::physics::lubricant::LubricantTable;
use repro::physics::thermal::{
    FilmProperties, Solid, ThermalError, ThermalInputs, ISOTHERMAL_CORRECTION_MAX,
};
use repro::pipeline::job::thermal_contact;
use repro::solver::point::PointSolution;
use repro::solver::thermal::{flat_film_thermal, point_thermal, Thermal};
use serde_json::{json, Value};
use std::time::Instant;

/// Grid level of the flat-film estimate without a solve (a Hertzian pressure and an Eq. (10)
/// film): 64 x 64 points, a few milliseconds.
const FLAT_LEVEL: u32 = 5;

impl ThermalArgs {
    /// The inputs, checked.
    pub fn inputs(&self) -> Result<ThermalInputs> {
        for (flag, v) in [
            ("--k-solid", self.k_solid),
            ("--k-lubricant", self.k_lubricant),
        ] {
            if v.is_nan() || v <= 0.0 {
                bail!("{flag}: a conductivity must be positive, got {v}");
            }
        }
        Ok(ThermalInputs {
            solid: Solid {
                conductivity_w_mk: self.k_solid,
                ..Solid::STEEL
            },
            film: FilmProperties {
                conductivity_w_mk: self.k_lubricant,
                ..FilmProperties::OIL
            },
        })
    }
}

/// A thermal correction as printed.
pub struct ThermalReport {
    /// The post-process.
    pub thermal: Thermal,
    /// The isothermal sliding `mu-bar` it corrects.
    pub isothermal: f64,
    /// Where it comes from: the solve, or the flat-film estimate.
    pub source: &'static str,
    /// Its wall time, s.
    pub seconds: f64,
}

/// The post-process of a solve, or `None` where the case has no thermal scales (dimensionless,
/// or a lubricant given by `alpha` and `eta0` alone).
pub fn of_solution(
    case: &Case,
    problem: &Problem,
    s: &PointSolution,
    inputs: &ThermalInputs,
) -> Option<Result<ThermalReport, ThermalError>> {
    let contact = thermal_contact(case, problem, &LubricantTable::table1())?;
    let start = Instant::now();
    Some(
        point_thermal(s, problem, &contact, inputs).map(|thermal| ThermalReport {
            thermal,
            isothermal: s.friction.sliding,
            source: "post-process of the solve",
            seconds: start.elapsed().as_secs_f64(),
        }),
    )
}

/// The flat-film estimate without a solve (see [`of_solution`] for `None`).
pub fn flat_estimate(
    case: &Case,
    problem: &Problem,
    inputs: &ThermalInputs,
) -> Option<Result<ThermalReport, ThermalError>> {
    let contact = thermal_contact(case, problem, &LubricantTable::table1())?;
    let start = Instant::now();
    Some(
        flat_film_thermal(problem, &contact, inputs, FLAT_LEVEL).map(|(isothermal, thermal)| {
            ThermalReport {
                thermal,
                isothermal,
                source: "flat-film estimate (Hertzian pressure, Eq. 10 film)",
                seconds: start.elapsed().as_secs_f64(),
            }
        }),
    )
}

impl ThermalReport {
    /// `mu-bar_thermal / mu-bar - 1`.
    pub fn correction(&self) -> f64 {
        self.thermal.correction(self.isothermal)
    }

    /// One line of the text summary.
    pub fn text(&self) -> String {
        let t = &self.thermal;
        format!(
            "thermal     mu-bar = {:.4} ({:+.2} %; mid-plane closure {:.4}, {:+.2} %), film +{:.1} K, surfaces +{:.1} K at most ({}; solids {} W/mK, beta0 = {:.4} /K, Peclet {:.0}, film Peclet {:.2e}; {:.1} ms)\n",
            t.mu_bar_sliding,
            100.0 * self.correction(),
            t.mu_bar_sliding_midplane,
            100.0 * (t.mu_bar_sliding_midplane / self.isothermal - 1.0),
            t.dt_film_max_k,
            t.dt_flash_max_k,
            self.source,
            t.k_solid_w_mk,
            t.beta0_per_k,
            t.peclet,
            t.film_peclet,
            self.seconds * 1e3,
        )
    }

    /// The JSON object.
    pub fn json(&self) -> Value {
        let mut v = serde_json::to_value(self.thermal).unwrap_or(Value::Null);
        v["correction"] = json!(self.correction());
        v["source"] = json!(self.source);
        v["seconds"] = json!(self.seconds);
        v["warning"] = json!(self.warning());
        v
    }

    /// The warning where the correction exceeds [`ISOTHERMAL_CORRECTION_MAX`].
    pub fn warning(&self) -> Option<String> {
        let c = self.correction();
        (c.abs() > ISOTHERMAL_CORRECTION_MAX).then(|| {
            format!(
                "shear heating changes the sliding friction by {:+.1} % ({}), more than {:.0} %: the paper's isothermal assumption does not hold here, and the isothermal mu-bar is too large (Conclusions)",
                100.0 * c,
                self.source,
                100.0 * ISOTHERMAL_CORRECTION_MAX
            )
        })
    }
}

/// The text line and warning of an optional post-process, or why it is missing.
pub fn describe(report: &Option<Result<ThermalReport, ThermalError>>) -> (String, Option<String>) {
    match report {
        Some(Ok(r)) => (r.text(), r.warning()),
        Some(Err(e)) => (format!("thermal     not computed: {e}\n"), None),
        None => (
            "thermal     not computed: needs a physical case with a Table 1 lubricant (--lubricant, --temperature) for the temperature coefficient\n".into(),
            None,
        ),
    }
}

/// The JSON value of an optional post-process (`null` where not computed).
pub fn json_of(report: &Option<Result<ThermalReport, ThermalError>>) -> Value {
    match report {
        Some(Ok(r)) => r.json(),
        Some(Err(e)) => json!({ "error": e.to_string() }),
        None => Value::Null,
    }
}

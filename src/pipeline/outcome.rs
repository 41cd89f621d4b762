//! What a solve yields, as cached: the numbers of a converged case ([`SolvedCase`]), or the
//! typed reason it failed ([`Failure`]). Failures are results too: cached, counted and shown.

use crate::physics::thermal::ThermalError;
pub use crate::solver::output::Output;
use crate::solver::output::{Film, Friction, Info, OutputErrors, SolveError, StartKind};
use crate::solver::richardson::ErrorEstimate;
use crate::solver::thermal::Thermal;
use serde::{Deserialize, Serialize};
use std::fmt;

/// The numbers of a converged point or line contact, as cached.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SolvedCase {
    /// Central film `H = h/c`.
    pub h_central: f64,
    /// Minimum film `H`.
    pub h_min: f64,
    /// Central film, Moes units.
    pub hc_moes: f64,
    /// Minimum film, Moes units.
    pub hmin_moes: f64,
    /// Sliding reduced friction.
    pub mu_bar_sliding: f64,
    /// Rolling reduced friction (when computed).
    pub mu_bar_rolling: Option<f64>,
    /// The level solved on: the one asked for, or a finer one where the film needed it.
    pub level: u32,
    /// Finest-level cycles.
    pub cycles: usize,
    /// Newton-Krylov steps of the finish (0 where the cycles converged).
    pub newton_steps: usize,
    /// Final residual.
    pub residual: f64,
    /// Force-balance error.
    pub load_error: f64,
    /// Where the solve started: cold, warm from its base, or cold after the warm start
    /// failed (the fallback).
    #[serde(default)]
    pub start: StartKind,
    /// The thermal post-process of a physical point contact with a Table 1 lubricant, one per
    /// entry of [`crate::physics::thermal::TARGET_INPUTS`] in its order (steel, then
    /// through-hardened steel); empty for dimensionless cases, line contacts and where the
    /// post-process failed.
    #[serde(default)]
    pub thermal: Vec<Thermal>,
    /// Why the thermal post-process failed, where it did (then `thermal` is empty). Absent
    /// from the cached payload otherwise, so entries without it read as before.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_failure: Option<ThermalFailure>,
    /// The outputs' discretisation error, where the solve estimated it (films in `H`).
    #[serde(default)]
    pub errors: Option<Box<OutputErrors>>,
    // The wall time is not part of the result: it lives in the entry's stamp. (Entries
    // written before stamps carry a `seconds` here, which is ignored on reading.)
}

impl SolvedCase {
    /// The numbers of a point or line solution's parts.
    pub fn of(parts: Parts) -> Self {
        let (film, friction, info, errors) = parts;
        SolvedCase {
            h_central: film.h_central,
            h_min: film.h_min,
            hc_moes: film.hc_moes,
            hmin_moes: film.hmin_moes,
            mu_bar_sliding: friction.sliding,
            mu_bar_rolling: friction.rolling,
            level: info.level,
            cycles: info.cycles,
            newton_steps: info.newton_steps,
            residual: info.residual(),
            load_error: info.load_error,
            start: info.start,
            thermal: Vec::new(),
            thermal_failure: None,
            errors: errors.cloned().map(Box::new),
        }
    }

    /// The estimate of the central film, the minimum film, sliding or total `mu-bar`
    /// ([`OutputErrors::estimate`]).
    pub fn estimate(&self, output: Output) -> Option<ErrorEstimate> {
        self.errors.as_ref()?.estimate(output)
    }

    /// The relative discretisation error of `output` (`None` where not estimated).
    pub fn relative_error(&self, output: Output) -> Option<f64> {
        let value = match output {
            Output::HCentral => self.h_central,
            Output::HMin => self.h_min,
            Output::MuBarSliding => self.mu_bar_sliding,
            Output::MuBarTotal => self.mu_bar_total(),
        };
        self.estimate(output).map(|e| e.relative(value))
    }

    /// The thermal post-process with the default inputs (steel), if computed.
    pub fn thermal(&self) -> Option<&Thermal> {
        self.thermal.first()
    }

    /// Sliding plus rolling.
    pub fn mu_bar_total(&self) -> f64 {
        self.mu_bar_sliding + self.mu_bar_rolling.unwrap_or(0.0)
    }
}

/// A solution's parts: film, friction, how it went and the outputs' discretisation error.
pub type Parts<'a> = (&'a Film, &'a Friction, &'a Info, Option<&'a OutputErrors>);

/// Why a solve failed, in a short stable name (no numbers, the same on every machine) for
/// tables and snapshots: the variant of the solver's [`SolveError`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum FailureKind {
    /// [`SolveError::NotConverged`].
    #[serde(rename = "not converged")]
    NotConverged,
    /// [`SolveError::FilmCollapse`].
    #[serde(rename = "film collapse")]
    FilmCollapse,
    /// [`SolveError::NonFinite`].
    #[serde(rename = "non-finite")]
    NonFinite,
    /// Any other error (parameters the solver refused).
    #[serde(rename = "failed")]
    Other,
}

impl FailureKind {
    /// The kind of `error`, from its variant.
    pub fn of(error: &SolveError) -> Self {
        match error {
            SolveError::NotConverged { .. } => FailureKind::NotConverged,
            SolveError::FilmCollapse { .. } => FailureKind::FilmCollapse,
            SolveError::NonFinite { .. } => FailureKind::NonFinite,
            _ => FailureKind::Other,
        }
    }

    /// The stable name.
    pub fn name(self) -> &'static str {
        match self {
            FailureKind::NotConverged => "not converged",
            FailureKind::FilmCollapse => "film collapse",
            FailureKind::NonFinite => "non-finite",
            FailureKind::Other => "failed",
        }
    }
}

impl fmt::Display for FailureKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A failed solve as cached: its kind, the solver's message and its residual history.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Failure {
    /// What went wrong, from the error's variant.
    pub kind: FailureKind,
    /// The solver's message.
    pub error: String,
    /// Residual after each cycle.
    pub residual_history: Vec<f64>,
}

impl Failure {
    /// The failure of a solver error.
    pub fn of(error: &SolveError) -> Self {
        Failure {
            kind: FailureKind::of(error),
            error: error.to_string(),
            residual_history: error.residual_history().to_vec(),
        }
    }

    /// The status a table shows for it: `failed: <kind>`.
    pub fn status(&self) -> String {
        format!("failed: {}", self.kind)
    }
}

/// A thermal post-process that failed on a converged case, as cached: a short stable name
/// of the reason (for tables and snapshots) and the post-process's message.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ThermalFailure {
    /// What went wrong, from the error's variant: `input`, `stationary surface`, `no film`,
    /// `stress`.
    pub kind: String,
    /// The post-process's message.
    pub error: String,
}

impl ThermalFailure {
    /// The failure of a thermal error.
    pub fn of(error: &ThermalError) -> Self {
        let kind = match error {
            ThermalError::Input { .. } => "input",
            ThermalError::StationarySurface { .. } => "stationary surface",
            ThermalError::NoFilm { .. } => "no film",
            ThermalError::Stress { .. } => "stress",
        };
        ThermalFailure {
            kind: kind.to_string(),
            error: error.to_string(),
        }
    }
}

/// A case's outcome: solved, or why not.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum CaseOutcome {
    /// Converged.
    Solved(SolvedCase),
    /// The solver's typed error, with the residual history.
    Failed(Failure),
}

impl CaseOutcome {
    /// The outcome of a solve that produced `parts` or failed.
    pub fn of(parts: Result<Parts, &SolveError>) -> Self {
        match parts {
            Ok(p) => CaseOutcome::Solved(SolvedCase::of(p)),
            Err(e) => CaseOutcome::Failed(Failure::of(e)),
        }
    }

    /// The numbers when solved.
    pub fn solved(&self) -> Option<&SolvedCase> {
        match self {
            CaseOutcome::Solved(s) => Some(s),
            CaseOutcome::Failed(_) => None,
        }
    }

    /// The failure, or `None` when solved.
    pub fn failure(&self) -> Option<&Failure> {
        match self {
            CaseOutcome::Solved(_) => None,
            CaseOutcome::Failed(f) => Some(f),
        }
    }

    /// The status a table shows: `solved` (`solved, thermal failed: <kind>` where the
    /// thermal post-process failed), or `failed: <kind>`.
    pub fn status(&self) -> String {
        match self {
            CaseOutcome::Solved(s) => match &s.thermal_failure {
                Some(t) => format!("solved, thermal failed: {}", t.kind),
                None => "solved".to_string(),
            },
            CaseOutcome::Failed(f) => f.status(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_kind_comes_from_the_variant_and_the_cache_keeps_it() {
        let history = vec![1e-2, 3e-3];
        let cases = [
            (
                SolveError::NotConverged {
                    cycles: 2,
                    tolerance: 1e-6,
                    residual_history: history.clone(),
                },
                "failed: not converged",
            ),
            (
                SolveError::NonFinite {
                    what: "pressure",
                    cycle: 2,
                    residual_history: history.clone(),
                },
                "failed: non-finite",
            ),
            (
                SolveError::FilmCollapse {
                    h_min: -1e-3,
                    level: 5,
                    level_needed: Some(6),
                    finest_level: 9,
                    cycle: 2,
                    residual_history: history.clone(),
                },
                "failed: film collapse",
            ),
            (SolveError::InvalidParams("level".into()), "failed: failed"),
        ];
        for (error, status) in cases {
            let outcome = CaseOutcome::of(Err(&error));
            assert_eq!(outcome.status(), status);
            let text = serde_json::to_string(&outcome).unwrap();
            let back: CaseOutcome = serde_json::from_str(&text).unwrap();
            assert_eq!(back, outcome, "{text}");
        }
    }

    /// The cache's payload keeps the form entries have always had: `{"Solved": {...}}` and
    /// `{"Failed": {..., "error": ..., "residual_history": [...]}}`.
    #[test]
    fn the_payload_keeps_its_variant_names() {
        let failed = CaseOutcome::Failed(Failure {
            kind: FailureKind::FilmCollapse,
            error: "film thickness became non-positive".into(),
            residual_history: vec![0.5],
        });
        assert_eq!(
            serde_json::to_string(&failed).unwrap(),
            r#"{"Failed":{"kind":"film collapse","error":"film thickness became non-positive","residual_history":[0.5]}}"#
        );
    }

    /// A failed thermal post-process is a status on the case's row, kept in the cache; an
    /// entry without one keeps the payload it had.
    #[test]
    fn a_thermal_failure_is_a_status_and_absent_otherwise() {
        let mut solved = SolvedCase {
            h_central: 0.5,
            h_min: 0.3,
            hc_moes: 2.0,
            hmin_moes: 1.2,
            mu_bar_sliding: 6.0,
            mu_bar_rolling: None,
            level: 5,
            cycles: 10,
            newton_steps: 0,
            residual: 1e-9,
            load_error: 1e-6,
            start: StartKind::Cold,
            thermal: Vec::new(),
            thermal_failure: None,
            errors: None,
        };
        let plain = serde_json::to_string(&CaseOutcome::Solved(solved.clone())).unwrap();
        assert!(!plain.contains("thermal_failure"), "{plain}");
        assert_eq!(CaseOutcome::Solved(solved.clone()).status(), "solved");
        solved.thermal_failure = Some(ThermalFailure::of(&ThermalError::NoFilm { h_m: -1e-9 }));
        let outcome = CaseOutcome::Solved(solved);
        assert_eq!(outcome.status(), "solved, thermal failed: no film");
        let text = serde_json::to_string(&outcome).unwrap();
        let back: CaseOutcome = serde_json::from_str(&text).unwrap();
        assert_eq!(back, outcome, "{text}");
    }
}

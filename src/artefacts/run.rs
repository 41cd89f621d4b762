//! Running a list of cases: in parallel (rayon), each case alone and deterministic whatever
//! the thread count, results collected in case order, solved results cached.

use super::cache::{key_of, Cache, Lookup};
use crate::physics::case::{Case, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::solver::grid::Domain;
use crate::solver::output::SolveError;
use crate::solver::point::{solve, Params, PointSolution, SOLVER_REVISION};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicUsize, Ordering};

/// What a solve yields, as cached.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Record {
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
    /// Wall time of the solve, s (the run that filled the cache).
    pub seconds: f64,
}

impl Record {
    /// The record of a converged solution.
    pub fn of(s: &PointSolution) -> Self {
        Record {
            h_central: s.film.h_central,
            h_min: s.film.h_min,
            hc_moes: s.film.hc_moes,
            hmin_moes: s.film.hmin_moes,
            mu_bar_sliding: s.friction.sliding,
            mu_bar_rolling: s.friction.rolling,
            level: s.info.level,
            cycles: s.info.cycles,
            newton_steps: s.info.newton_steps,
            residual: s.info.residual(),
            load_error: s.info.load_error,
            seconds: s.info.seconds,
        }
    }

    /// Sliding plus rolling.
    pub fn mu_bar_total(&self) -> f64 {
        self.mu_bar_sliding + self.mu_bar_rolling.unwrap_or(0.0)
    }
}

/// A case's outcome: solved, or why not (failures are results too, and cached).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Outcome {
    /// Converged.
    Solved(Record),
    /// The solver's typed error, as text, with the residual history.
    Failed {
        /// The error message.
        error: String,
        /// Residual after each cycle.
        residual_history: Vec<f64>,
    },
}

impl Outcome {
    /// The outcome of a solve.
    pub fn of(solved: &Result<PointSolution, SolveError>) -> Self {
        match solved {
            Ok(s) => Outcome::Solved(Record::of(s)),
            Err(e) => Outcome::Failed {
                error: e.to_string(),
                residual_history: e.residual_history().to_vec(),
            },
        }
    }

    /// The record, if the case solved.
    pub fn record(&self) -> Option<&Record> {
        match self {
            Outcome::Solved(r) => Some(r),
            Outcome::Failed { .. } => None,
        }
    }
}

/// A short, stable name (no numbers) of a solver error given as its text, the same on every
/// machine: for tables and snapshots of point and line contacts alike.
pub fn failure_kind(error: &str) -> &'static str {
    if error.starts_with("not converged") {
        "not converged"
    } else if error.starts_with("film thickness became non-positive") {
        "film collapse"
    } else if error.starts_with("non-finite") {
        "non-finite"
    } else {
        "failed"
    }
}

/// One case run.
#[derive(Debug, Clone)]
pub struct CaseRun {
    /// The case.
    pub case: Case,
    /// The dimensionless problem (groups, tau_c).
    pub problem: Problem,
    /// Solved or failed.
    pub outcome: Outcome,
    /// Taken from the cache.
    pub cached: bool,
}

impl CaseRun {
    /// A short, stable name of the failure (no numbers, so that it is the same on every
    /// machine), or `None` when solved.
    pub fn failure_kind(&self) -> Option<&'static str> {
        let Outcome::Failed { error, .. } = &self.outcome else {
            return None;
        };
        Some(failure_kind(error))
    }

    /// The record when solved.
    pub fn record(&self) -> Option<&Record> {
        self.outcome.record()
    }
}

/// The cache key of a case at the given solver parameters: the case, the parameters a target
/// can set (level, domain, rolling friction) and the solver revision, which is raised whenever
/// a default parameter or the numerics change.
pub fn case_key(case: &Case, params: &Params) -> String {
    let d = &params.domain;
    key_of(&(
        case,
        params.level,
        (d.x_start, d.x_end, d.y_half),
        params.rolling_friction,
        SOLVER_REVISION,
    ))
}

/// The parameters a case of a sweep is solved with: `params` on the domain its load calls
/// for ([`Domain::for_load`]).
pub fn case_params(params: &Params, problem: &Problem) -> Params {
    Params {
        domain: Domain::for_load(problem.groups.m),
        ..params.clone()
    }
}

/// Progress of a run, reported after each case.
#[derive(Debug, Clone, Copy)]
pub struct RunProgress {
    /// Cases done.
    pub done: usize,
    /// Cases in all.
    pub total: usize,
    /// Of those done, taken from the cache.
    pub cached: usize,
}

/// Runs `cases` at `params`, reusing and filling `cache`; `warn` hears of corrupt entries and
/// cache write failures, `progress` of every finished case. Cases that do not resolve into a
/// problem are an error for the whole run (the sweep file is wrong).
pub fn run_cases(
    cases: &[Case],
    params: &Params,
    cache: Option<&Cache>,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<CaseRun>, String> {
    let lubricants = LubricantTable::table1();
    let problems = cases
        .iter()
        .enumerate()
        .map(|(i, c)| {
            Problem::from_case(c, &lubricants).map_err(|e| format!("case {}: {e}", i + 1))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let done = AtomicUsize::new(0);
    let cached_count = AtomicUsize::new(0);
    let total = cases.len();
    let runs = cases
        .par_iter()
        .zip(problems.into_par_iter())
        .map(|(case, problem)| {
            let params = &case_params(params, &problem);
            let key = case_key(case, params);
            let looked = cache.map(|c| c.get::<Outcome>(&key));
            let (outcome, cached) = match looked {
                Some(Lookup::Hit(o)) => (o, true),
                other => {
                    if let Some(Lookup::Corrupt(why)) = other {
                        warn(format!("corrupt cache entry recomputed: {why}"));
                    }
                    let outcome = Outcome::of(&solve(&problem, params, None));
                    if let Some(c) = cache {
                        if let Err(e) = c.put(&key, &outcome) {
                            warn(format!(
                                "cannot write cache entry in {}: {e}",
                                c.dir().display()
                            ));
                        }
                    }
                    (outcome, false)
                }
            };
            let cached_now = if cached {
                cached_count.fetch_add(1, Ordering::Relaxed) + 1
            } else {
                cached_count.load(Ordering::Relaxed)
            };
            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
            progress(RunProgress {
                done: d,
                total,
                cached: cached_now,
            });
            CaseRun {
                case: case.clone(),
                problem,
                outcome,
                cached,
            }
        })
        .collect();
    Ok(runs)
}

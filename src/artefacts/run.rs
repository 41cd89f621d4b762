//! Running solves: each one a [`Job`] (its cache key, a readable label, the problem and
//! parameters), run in parallel (rayon), each alone and deterministic whatever the thread
//! count, results collected in job order, through a [`Store`]: the cache reused and filled,
//! or read only (`--offline`, where a missing entry is an error naming the case).

use super::cache::{key_of, Cache, Lookup, Stamp};
use crate::physics::case::{Case, Problem};
use crate::physics::line_contact::LineProblem;
use crate::physics::lubricant::LubricantTable;
use crate::physics::thermal::{ThermalContact, TARGET_INPUTS, THERMAL_REVISION};
use crate::solver::output::{Film, Friction, Info, SolveError};
use crate::solver::point::{Params, SOLVER_REVISION};
use crate::solver::thermal::{point_thermal, Thermal};
use crate::solver::{line, point};
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
    /// The thermal post-process of a physical point contact with a Table 1 lubricant, one per
    /// entry of [`TARGET_INPUTS`] in its order (steel, then through-hardened steel); empty for
    /// dimensionless cases, line contacts and where the post-process failed.
    #[serde(default)]
    pub thermal: Vec<Thermal>,
    // The wall time is not part of the result: it lives in the entry's stamp. (Entries
    // written before stamps carry a `seconds` here, which is ignored on reading.)
}

impl Record {
    /// The record of a point or line solution's parts.
    pub fn of(film: &Film, friction: &Friction, info: &Info) -> Self {
        Record {
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
            thermal: Vec::new(),
        }
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
    /// The outcome of a solve that produced `parts` or failed.
    pub fn of(parts: Result<(&Film, &Friction, &Info), &SolveError>) -> Self {
        match parts {
            Ok((f, fr, i)) => Outcome::Solved(Record::of(f, fr, i)),
            Err(e) => Outcome::Failed {
                error: e.to_string(),
                residual_history: e.residual_history().to_vec(),
            },
        }
    }

    /// The record when solved.
    pub fn record(&self) -> Option<&Record> {
        match self {
            Outcome::Solved(r) => Some(r),
            Outcome::Failed { .. } => None,
        }
    }

    /// A short, stable name of the failure, or `None` when solved.
    pub fn failure_kind(&self) -> Option<&'static str> {
        match self {
            Outcome::Solved(_) => None,
            Outcome::Failed { error, .. } => Some(failure_kind(error)),
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
    /// Its cache key.
    pub key: String,
    /// How its result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
}

impl CaseRun {
    /// A short, stable name of the failure (no numbers, so that it is the same on every
    /// machine), or `None` when solved.
    pub fn failure_kind(&self) -> Option<&'static str> {
        self.outcome.failure_kind()
    }

    /// The record when solved.
    pub fn record(&self) -> Option<&Record> {
        self.outcome.record()
    }
}

/// The cache key of a case at the given solver parameters: the case, the parameters a target
/// can set (level, domain, rolling friction), the solver revision, which is raised whenever
/// a default parameter or the numerics change, and the thermal post-process's inputs and
/// revision.
pub fn case_key(case: &Case, params: &Params) -> String {
    let d = &params.domain;
    key_of(&(
        case,
        params.level,
        (d.x_start, d.x_end, d.y_half),
        params.rolling_friction,
        SOLVER_REVISION,
        (THERMAL_REVISION, TARGET_INPUTS),
    ))
}

/// The thermal scales of a case: a physical case with a Table 1 lubricant, else `None`.
pub fn thermal_contact(
    case: &Case,
    problem: &Problem,
    lubricants: &LubricantTable,
) -> Option<ThermalContact> {
    match &case.spec {
        crate::physics::case::Spec::Physical(p) => ThermalContact::of_point(p, problem, lubricants),
        crate::physics::case::Spec::Dimensionless(_) => None,
    }
}

/// The problem a job solves, with its parameters.
#[derive(Debug, Clone)]
pub enum Work {
    /// An elliptical contact (multigrid).
    Point {
        /// The dimensionless problem.
        problem: Problem,
        /// Solver parameters (boxed: they are most of the variant's size).
        params: Box<point::Params>,
        /// The thermal scales, where the case has them: the solution is post-processed with
        /// each of [`TARGET_INPUTS`].
        thermal: Option<Box<ThermalContact>>,
    },
    /// A line contact (1-D Newton).
    Line {
        /// The dimensionless problem.
        problem: LineProblem,
        /// Solver parameters.
        params: line::Params,
    },
}

impl Work {
    /// Solves it (no progress observer).
    pub fn solve(&self) -> Outcome {
        match self {
            Work::Point {
                problem,
                params,
                thermal,
            } => {
                let r = point::solve(problem, params, None);
                let mut outcome = Outcome::of(r.as_ref().map(|s| (&s.film, &s.friction, &s.info)));
                if let (Ok(s), Some(contact), Outcome::Solved(record)) = (&r, thermal, &mut outcome)
                {
                    // A failed post-process leaves the isothermal record as it is.
                    record.thermal = TARGET_INPUTS
                        .iter()
                        .map(|inputs| point_thermal(s, problem, contact, inputs))
                        .collect::<Result<_, _>>()
                        .unwrap_or_default();
                }
                outcome
            }
            Work::Line { problem, params } => {
                let r = line::solve(problem, params, None);
                Outcome::of(r.as_ref().map(|s| (&s.film, &s.friction, &s.info)))
            }
        }
    }
}

/// One solve of a target: its cache key, what it is in words, and the work.
#[derive(Debug, Clone)]
pub struct Job {
    /// The cache key ([`case_key`], [`line_key`]).
    pub key: String,
    /// The case in words, for listings of missing cases and shard logs.
    pub label: String,
    /// What to solve.
    pub work: Work,
}

/// Where results come from and go.
#[derive(Debug, Clone, Copy)]
pub enum Store<'a> {
    /// Solve everything, cache nothing (`--no-cache`).
    Nothing,
    /// Reuse the cache's entries and add the new solves.
    Cache(&'a Cache),
    /// The cache alone (`--offline`): a job without an entry is an error, nothing is solved.
    Offline(&'a Cache),
}

impl<'a> Store<'a> {
    /// The cache, if any.
    pub fn cache(&self) -> Option<&'a Cache> {
        match *self {
            Store::Nothing => None,
            Store::Cache(c) | Store::Offline(c) => Some(c),
        }
    }
}

/// A job done.
#[derive(Debug, Clone)]
pub struct Done {
    /// Solved or failed.
    pub outcome: Outcome,
    /// How the result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
    /// Taken from the cache.
    pub cached: bool,
}

/// The jobs of `jobs` that `cache` has no verified entry for (with the reason for a corrupt
/// one).
pub fn missing<'j>(jobs: &'j [Job], cache: &Cache) -> Vec<(&'j Job, Option<String>)> {
    jobs.iter()
        .filter_map(|j| match cache.get::<Outcome>(&j.key) {
            Lookup::Hit(..) => None,
            Lookup::Miss => Some((j, None)),
            Lookup::Corrupt(why) => Some((j, Some(why))),
        })
        .collect()
}

/// The message of an offline run that lacks entries: every missing case, by label and key.
pub fn missing_message(missing: &[(String, &Job, Option<String>)], cache: &Cache) -> String {
    let mut msg = format!(
        "--offline: {} case(s) missing from the cache {} (an offline build never solves; run the missing shards or merge their caches first):",
        missing.len(),
        cache.dir().display()
    );
    for (target, job, why) in missing {
        msg.push_str(&format!("\n  {target}: {} [key {}]", job.label, job.key));
        if let Some(why) = why {
            msg.push_str(&format!(" (corrupt entry: {why})"));
        }
    }
    msg
}

/// Runs `jobs` through `store`: `warn` hears of corrupt entries and cache write failures,
/// `progress` of every finished job. Offline, every job must have an entry, or the error
/// lists those without one (`target` names them).
pub fn run_jobs(
    target: &str,
    jobs: &[Job],
    store: Store,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<Done>, String> {
    if let Store::Offline(cache) = store {
        let absent = missing(jobs, cache);
        if !absent.is_empty() {
            let named: Vec<_> = absent
                .into_iter()
                .map(|(j, why)| (target.to_string(), j, why))
                .collect();
            return Err(missing_message(&named, cache));
        }
    }
    let done = AtomicUsize::new(0);
    let cached_count = AtomicUsize::new(0);
    let total = jobs.len();
    let runs = jobs
        .par_iter()
        .map(|job| {
            let looked = store.cache().map(|c| c.get::<Outcome>(&job.key));
            let run = match looked {
                Some(Lookup::Hit(outcome, stamp)) => Ok(Done {
                    outcome,
                    stamp,
                    cached: true,
                }),
                _ if matches!(store, Store::Offline(_)) => Err(format!(
                    "--offline: {target}: {} [key {}] vanished from the cache during the run",
                    job.label, job.key
                )),
                other => {
                    if let Some(Lookup::Corrupt(why)) = other {
                        warn(format!("corrupt cache entry recomputed: {why}"));
                    }
                    let start = std::time::Instant::now();
                    let outcome = job.work.solve();
                    let stamp = Stamp::now(start.elapsed().as_secs_f64());
                    if let Some(c) = store.cache() {
                        if let Err(e) = c.put(&job.key, &outcome, &stamp) {
                            warn(format!(
                                "cannot write cache entry in {}: {e}",
                                c.dir().display()
                            ));
                        }
                    }
                    Ok(Done {
                        outcome,
                        stamp: Some(stamp),
                        cached: false,
                    })
                }
            };
            let cached_now = if run.as_ref().is_ok_and(|r| r.cached) {
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
            run
        })
        .collect::<Vec<_>>();
    runs.into_iter().collect()
}

/// The revision of the line-contact numerics, part of every line-contact cache key.
pub use crate::solver::line::SOLVER_REVISION as LINE_SOLVER_REVISION;

/// The cache key of a line contact at the given solver parameters (the parameters a target
/// can set and the revision, as [`case_key`]).
pub fn line_key<C: Serialize>(
    case: &C,
    physics: &crate::physics::case::Physics,
    params: &line::Params,
) -> String {
    key_of(&(
        "line",
        case,
        physics,
        params.level,
        (params.domain.x_start, params.domain.x_end),
        params.rolling_friction,
        params.require_positive_film,
        LINE_SOLVER_REVISION,
    ))
}

/// A readable description of a case, for listings.
pub fn describe(case: &Case, level: u32) -> String {
    use crate::physics::case::{LubricantSpec, Spec};
    // Seven significant digits, printed shortest: 0.30000000000000004 reads 0.3.
    let g = |x: f64| -> String {
        format!("{:.6e}", x)
            .parse::<f64>()
            .map_or_else(|_| x.to_string(), |r| r.to_string())
    };
    let body = match &case.spec {
        Spec::Physical(p) => {
            let lub = match &p.lubricant {
                LubricantSpec::Named {
                    lubricant,
                    temperature_c,
                } => format!("{lubricant} at {} C", g(*temperature_c)),
                LubricantSpec::Given {
                    alpha_per_pa,
                    eta0_pa_s,
                } => format!(
                    "alpha {} 1/GPa, eta0 {} mPa s",
                    g(alpha_per_pa * 1e9),
                    g(eta0_pa_s * 1e3)
                ),
            };
            format!(
                "{lub}, p_H {} GPa, u_m {} m/s, S {}, tau0 {} MPa, Rx/Ry {}",
                g(p.ph_pa / 1e9),
                g(p.um_m_s),
                g(p.slip),
                g(p.tau0_pa / 1e6),
                g(p.rx_m / p.ry_m)
            )
        }
        Spec::Dimensionless(d) => format!(
            "M {}, L {}, S-bar {}, Rx/Ry {}, S {}",
            g(d.m),
            g(d.l),
            g(d.s_bar),
            g(d.d),
            g(d.slip)
        ),
    };
    format!("{body}, level {level}")
}

/// The jobs of `cases` at `level`, each with the parameters its problem calls for
/// ([`Params::for_problem`]), labelled `case 1`, `case 2`, ... in order, with their problems.
/// Cases that do not resolve into a problem are an error (the sweep file is wrong).
pub fn point_jobs(cases: &[Case], level: u32) -> Result<Vec<(Job, Problem)>, String> {
    let lubricants = LubricantTable::table1();
    cases
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let problem =
                Problem::from_case(c, &lubricants).map_err(|e| format!("case {}: {e}", i + 1))?;
            let params = Params::for_problem(&problem, level);
            let job = Job {
                key: case_key(c, &params),
                label: format!("case {} ({})", i + 1, describe(c, params.level)),
                work: Work::Point {
                    problem: problem.clone(),
                    params: Box::new(params),
                    thermal: thermal_contact(c, &problem, &lubricants).map(Box::new),
                },
            };
            Ok((job, problem))
        })
        .collect()
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

/// Runs `cases` at `level` (see [`point_jobs`]) through `store` (see [`run_jobs`]); `target`
/// names them in errors. Cases that do not resolve into a problem are an error for the whole
/// run.
pub fn run_cases(
    target: &str,
    cases: &[Case],
    level: u32,
    store: Store,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<CaseRun>, String> {
    let (jobs, problems): (Vec<Job>, Vec<Problem>) = point_jobs(cases, level)?.into_iter().unzip();
    let done = run_jobs(target, &jobs, store, progress, warn)?;
    Ok(cases
        .iter()
        .zip(problems)
        .zip(jobs.into_iter().zip(done))
        .map(|((case, problem), (job, d))| CaseRun {
            case: case.clone(),
            problem,
            outcome: d.outcome,
            cached: d.cached,
            key: job.key,
            stamp: d.stamp,
        })
        .collect())
}

//! Running solves: each one a [`Job`] (its cache key, a readable label, the problem and
//! parameters), run in parallel (rayon), each alone and deterministic whatever the thread
//! count, results collected in job order, through a [`Store`]: the cache reused and filled,
//! or read only (`--offline`, where a missing entry is an error naming the case).

use super::base::base_of;
use super::cache::{key_of, Cache, Lookup, Stamp};
use crate::physics::case::{Case, CaseError, Problem};
use crate::physics::line_contact::LineProblem;
use crate::physics::lubricant::LubricantTable;
use crate::physics::thermal::{ThermalContact, TARGET_INPUTS, THERMAL_REVISION};
use crate::solver::output::{Film, Friction, Info, SolveError, StartKind};
use crate::solver::point::{Params, Start, SOLVER_REVISION};
use crate::solver::thermal::{point_thermal, Thermal};
use crate::solver::{line, point};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

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
    /// Where the solve started: cold, warm from its base, or cold after the warm start
    /// failed (the fallback).
    #[serde(default)]
    pub start: StartKind,
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
            start: info.start,
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
/// can set (level, domain, rolling friction, the film check), the solver revision, which is
/// raised whenever a default parameter or the numerics change, the thermal post-process's
/// inputs and revision, and the key of the base it starts from ([`base_of`]), whose
/// solution is part of its arithmetic.
pub fn case_key(case: &Case, params: &Params, base_key: Option<&str>) -> String {
    let d = &params.domain;
    key_of(&(
        case,
        params.level,
        (d.x_start, d.x_end, d.y_half),
        params.rolling_friction,
        (params.require_positive_film, params.film_refinement_levels),
        SOLVER_REVISION,
        (THERMAL_REVISION, TARGET_INPUTS),
        base_key,
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
    /// Solves it (no progress observer), a point contact from `start` where one is given
    /// (its base's solution), and the start it gives its own members where `keep_start`.
    pub fn solve(&self, start: Option<&Start>, keep_start: bool) -> (Outcome, Option<Start>) {
        match self {
            Work::Point {
                problem,
                params,
                thermal,
            } => {
                let r = match start {
                    Some(s) => point::solve_from(problem, params, s, None),
                    None => point::solve(problem, params, None),
                };
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
                let kept = keep_start.then(|| r.as_ref().ok().map(Start::of)).flatten();
                (outcome, kept)
            }
            Work::Line { problem, params } => {
                let r = line::solve(problem, params, None);
                (
                    Outcome::of(r.as_ref().map(|s| (&s.film, &s.friction, &s.info))),
                    None,
                )
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
    /// The job of the base it starts from ([`base_of`]), solved first.
    pub base: Option<Box<Job>>,
}

impl Job {
    /// The key of the family's root: the base at the end of the chain of bases (its own key
    /// where it has no base). Shards keep a family together.
    pub fn family(&self) -> &str {
        match &self.base {
            Some(b) => b.family(),
            None => &self.key,
        }
    }

    /// The bases below it, the nearest first.
    fn bases(&self) -> impl Iterator<Item = &Job> {
        std::iter::successors(self.base.as_deref(), |b| b.base.as_deref())
    }
}

/// The job of a point case at `params` (the one rule's, [`Params::for_problem`], or a
/// target's own on top of them), with the job of its base ([`base_of`]) at the same
/// parameters; `label` names it.
pub fn point_job(
    case: &Case,
    problem: &Problem,
    params: Params,
    label: String,
    lubricants: &LubricantTable,
) -> Result<Job, CaseError> {
    let base = match base_of(case) {
        Some(b) => {
            let bp = Problem::from_case(&b, lubricants)?;
            let label = format!("base {}", describe(&b, params.level));
            Some(Box::new(point_job(
                &b,
                &bp,
                params.clone(),
                label,
                lubricants,
            )?))
        }
        None => None,
    };
    Ok(Job {
        key: case_key(case, &params, base.as_deref().map(|b| b.key.as_str())),
        label,
        work: Work::Point {
            problem: problem.clone(),
            params: Box::new(params),
            thermal: thermal_contact(case, problem, lubricants).map(Box::new),
        },
        base,
    })
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
///
/// In two phases: first the bases that the jobs missing from the cache start from (largest
/// first, a layer of the chains of bases at a time: the Eyring twin of a limited case before
/// the case, its own base before the twin), each solved whether or not its own entry is
/// cached, for its solution is what its members start from, and kept in memory; then the
/// jobs, each from its base's solution ([`point::solve_from`]). A base solves to the same
/// bits whoever solves it, so a job's result depends on its case and key alone.
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
    let looked: Vec<Option<Done>> = jobs
        .par_iter()
        .map(
            |job| match store.cache().map(|c| c.get::<Outcome>(&job.key)) {
                Some(Lookup::Hit(outcome, stamp)) => Some(Done {
                    outcome,
                    stamp,
                    cached: true,
                }),
                Some(Lookup::Corrupt(why)) => {
                    warn(format!("corrupt cache entry recomputed: {why}"));
                    None
                }
                _ => None,
            },
        )
        .collect();
    if matches!(store, Store::Offline(_)) {
        return jobs
            .iter()
            .zip(looked)
            .map(|(job, d)| {
                d.ok_or_else(|| {
                    format!(
                        "--offline: {target}: {} [key {}] vanished from the cache during the run",
                        job.label, job.key
                    )
                })
            })
            .collect();
    }
    // The solutions kept in memory (those of this process's earlier runs), then the bases
    // the missing jobs need and lack, by key, with their depth in the chain (0 for a base
    // solved cold or from a kept solution).
    let kept = |key: &str| store.cache().and_then(|c| c.start(key));
    let mut starts: HashMap<&str, Arc<Start>> = HashMap::new();
    let mut bases: BTreeMap<&str, &Job> = BTreeMap::new();
    for (job, d) in jobs.iter().zip(&looked) {
        if d.is_some() {
            continue;
        }
        for b in job.bases() {
            if starts.contains_key(b.key.as_str()) || bases.contains_key(b.key.as_str()) {
                break;
            }
            match kept(&b.key) {
                Some(k) => {
                    starts.insert(b.key.as_str(), k);
                    break;
                }
                None => {
                    bases.insert(b.key.as_str(), b);
                }
            }
        }
    }
    let depth_of = |mut b: &Job| {
        let mut depth = 0;
        while let Some(below) = b.base.as_deref() {
            if !bases.contains_key(below.key.as_str()) {
                break;
            }
            depth += 1;
            b = below;
        }
        depth
    };
    let layers: Vec<(usize, &Job)> = bases.values().map(|b| (depth_of(b), *b)).collect();
    let solve_one = |job: &Job, start: Option<&Start>| {
        let clock = std::time::Instant::now();
        let (outcome, start) = job.work.solve(start, true);
        let stamp = Stamp::now(clock.elapsed().as_secs_f64());
        let start = start.map(Arc::new);
        if let Some(c) = store.cache() {
            if let Err(e) = c.put(&job.key, &outcome, &stamp) {
                warn(format!(
                    "cannot write cache entry in {}: {e}",
                    c.dir().display()
                ));
            }
            if let Some(s) = &start {
                c.keep_start(&job.key, s.clone());
            }
        }
        (
            Done {
                outcome,
                stamp: Some(stamp),
                cached: false,
            },
            start,
        )
    };
    let mut solved: HashMap<&str, Done> = HashMap::new();
    let base_total = bases.len();
    let bases_done = AtomicUsize::new(0);
    let depth = layers.iter().map(|(d, _)| d + 1).max().unwrap_or(0);
    for layer in 0..depth {
        let mut this: Vec<&Job> = layers
            .iter()
            .filter(|(d, _)| *d == layer)
            .map(|(_, j)| *j)
            .collect();
        this.sort_by(|a, b| weight(b).total_cmp(&weight(a)));
        let results: Vec<(&str, Done, Option<Arc<Start>>)> = this
            .par_iter()
            .map(|b| {
                let start = b.base.as_ref().and_then(|bb| starts.get(bb.key.as_str()));
                let (done, kept) = solve_one(b, start.map(|s| s.as_ref()));
                progress(RunProgress {
                    done: bases_done.fetch_add(1, Ordering::Relaxed) + 1,
                    total: base_total,
                    cached: 0,
                    phase: Phase::Bases,
                });
                (b.key.as_str(), done, kept)
            })
            .collect();
        for (key, done, kept) in results {
            if let Some(k) = kept {
                starts.insert(key, k);
            }
            solved.insert(key, done);
        }
    }
    let done = AtomicUsize::new(0);
    let cached_count = AtomicUsize::new(0);
    let total = jobs.len();
    let runs = jobs
        .par_iter()
        .zip(looked)
        .map(|(job, looked)| {
            let run = match (looked, solved.get(job.key.as_str())) {
                (Some(d), _) => d,
                (None, Some(d)) => d.clone(),
                (None, None) => {
                    let start = job.base.as_ref().and_then(|b| starts.get(b.key.as_str()));
                    solve_one(job, start.map(|s| s.as_ref())).0
                }
            };
            let cached_now = if run.cached {
                cached_count.fetch_add(1, Ordering::Relaxed) + 1
            } else {
                cached_count.load(Ordering::Relaxed)
            };
            progress(RunProgress {
                done: done.fetch_add(1, Ordering::Relaxed) + 1,
                total,
                cached: cached_now,
                phase: Phase::Cases,
            });
            run
        })
        .collect::<Vec<_>>();
    Ok(runs)
}

/// A job's expected cost, for ordering the bases largest first: the heavier the load and
/// the more viscous the lubricant, the longer a solve (the point contact's `M L`; line
/// contacts last).
fn weight(job: &Job) -> f64 {
    match &job.work {
        Work::Point {
            problem, params, ..
        } => problem.groups.m.max(1.0) * problem.groups.l.max(1.0) * 4f64.powi(params.level as i32),
        Work::Line { .. } => 0.0,
    }
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
            let label = format!("case {} ({})", i + 1, describe(c, params.level));
            let job = point_job(c, &problem, params, label, &lubricants)
                .map_err(|e| format!("case {}: base: {e}", i + 1))?;
            Ok((job, problem))
        })
        .collect()
}

/// Progress of a run, reported after each case.
#[derive(Debug, Clone, Copy)]
pub struct RunProgress {
    /// Cases done (of the phase).
    pub done: usize,
    /// Cases in all (of the phase).
    pub total: usize,
    /// Of those done, taken from the cache.
    pub cached: usize,
    /// Which phase of the run ([`run_jobs`]).
    pub phase: Phase,
}

/// The phases of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// The bases the missing cases start from.
    Bases,
    /// The cases themselves.
    Cases,
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

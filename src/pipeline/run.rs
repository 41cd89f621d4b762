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
use std::sync::{Arc, Mutex};

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
/// The jobs missing from the cache are solved with the bases they start from, as trees: a
/// base first (cold, or from a solution this process kept), then its members from its
/// solution ([`point::solve_from`]), in parallel, the heaviest trees first (the Eyring twin
/// of a limited case is a member of its family's base and the base of the limited case). A
/// base is solved whether or not its own entry is cached, for its solution is what its
/// members start from; it solves to the same bits whoever solves it, so a job's result
/// depends on its case and key alone.
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
    // The solves: the missing jobs and the bases they need, each once, as a forest whose
    // roots start cold or from a solution kept in memory (this process's earlier runs).
    let kept = |key: &str| store.cache().and_then(|c| c.start(key));
    let mut nodes: BTreeMap<&str, &Job> = BTreeMap::new();
    let mut roots: BTreeMap<&str, Option<Arc<Start>>> = BTreeMap::new();
    let mut children: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (job, d) in jobs.iter().zip(&looked) {
        if d.is_some() || nodes.contains_key(job.key.as_str()) {
            continue;
        }
        let mut node = job;
        loop {
            nodes.insert(node.key.as_str(), node);
            let Some(base) = node.base.as_deref() else {
                roots.insert(node.key.as_str(), None);
                break;
            };
            if let Some(k) = kept(&base.key) {
                roots.insert(node.key.as_str(), Some(k));
                break;
            }
            children
                .entry(base.key.as_str())
                .or_default()
                .push(node.key.as_str());
            if nodes.contains_key(base.key.as_str()) {
                break;
            }
            node = base;
        }
    }
    let cached = looked.iter().filter(|d| d.is_some()).count();
    let own: std::collections::BTreeSet<&str> = jobs
        .iter()
        .zip(&looked)
        .filter(|(_, d)| d.is_none())
        .map(|(j, _)| j.key.as_str())
        .collect();
    let bases = nodes.keys().filter(|k| !own.contains(*k)).count();
    let forest = Forest {
        nodes: &nodes,
        children: &children,
        store,
        warn,
        progress,
        results: Mutex::new(HashMap::new()),
        done: AtomicUsize::new(cached),
        total: nodes.len() + cached,
        cached,
        bases,
    };
    // The heaviest trees first, so that the last solves of a run are light ones.
    let mut order: Vec<(&str, Option<Arc<Start>>, f64)> = roots
        .into_iter()
        .map(|(k, s)| (k, s, forest.weight(k)))
        .collect();
    order.sort_by(|a, b| b.2.total_cmp(&a.2));
    order
        .into_par_iter()
        .for_each(|(key, start, _)| forest.run(key, start));
    let solved = forest
        .results
        .into_inner()
        .unwrap_or_else(|e| e.into_inner());
    Ok(jobs
        .iter()
        .zip(looked)
        .map(|(job, d)| {
            d.or_else(|| solved.get(job.key.as_str()).cloned())
                .expect("every missing job is a node of the forest, solved above")
        })
        .collect())
}

/// The solves of a run as trees: each node a job, solved from its parent's solution (its
/// base), its children after it, in parallel (rayon's work stealing spreads a family's
/// members over the cores as soon as its base is done).
struct Forest<'a, 'j> {
    nodes: &'a BTreeMap<&'j str, &'j Job>,
    children: &'a BTreeMap<&'j str, Vec<&'j str>>,
    store: Store<'a>,
    warn: &'a (dyn Fn(String) + Sync),
    progress: &'a (dyn Fn(RunProgress) + Sync),
    results: Mutex<HashMap<&'j str, Done>>,
    done: AtomicUsize,
    total: usize,
    cached: usize,
    bases: usize,
}

impl<'j> Forest<'_, 'j> {
    /// The expected cost of the tree under `key`.
    fn weight(&self, key: &str) -> f64 {
        let own = self.nodes.get(key).map_or(0.0, |j| weight(j));
        own + self
            .children
            .get(key)
            .map_or(0.0, |c| c.iter().map(|k| self.weight(k)).sum())
    }

    /// Solves `key` from `start`, then its children from its solution (cold where it
    /// failed).
    fn run(&self, key: &'j str, start: Option<Arc<Start>>) {
        let job = self.nodes[key];
        let clock = std::time::Instant::now();
        let (outcome, solution) = job.work.solve(start.as_deref(), true);
        let stamp = Stamp::now(clock.elapsed().as_secs_f64());
        let solution = solution.map(Arc::new);
        if let Some(c) = self.store.cache() {
            if let Err(e) = c.put(&job.key, &outcome, &stamp) {
                (self.warn)(format!(
                    "cannot write cache entry in {}: {e}",
                    c.dir().display()
                ));
            }
            if let Some(s) = &solution {
                c.keep_start(&job.key, s.clone());
            }
        }
        let done = Done {
            outcome,
            stamp: Some(stamp),
            cached: false,
        };
        self.results
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .insert(key, done);
        (self.progress)(RunProgress {
            done: self.done.fetch_add(1, Ordering::Relaxed) + 1,
            total: self.total,
            cached: self.cached,
            bases: self.bases,
        });
        if let Some(kids) = self.children.get(key) {
            kids.par_iter().for_each(|k| self.run(k, solution.clone()));
        }
    }
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
                LubricantSpec::Datasheet {
                    datasheet,
                    temperature_c,
                    alpha_per_gpa,
                } => format!(
                    "{} at {} C{}",
                    datasheet.label(),
                    g(*temperature_c),
                    alpha_per_gpa.map_or_else(String::new, |a| format!(", alpha {} 1/GPa", g(a)))
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

/// Progress of a run, reported after each solve.
#[derive(Debug, Clone, Copy)]
pub struct RunProgress {
    /// Cases done: taken from the cache, or solved.
    pub done: usize,
    /// Cases in all: those of the run and the bases they start from.
    pub total: usize,
    /// Of them, taken from the cache (counted as done from the start).
    pub cached: usize,
    /// Of them, bases solved for the run's cases, beyond its own ([`run_jobs`]).
    pub bases: usize,
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

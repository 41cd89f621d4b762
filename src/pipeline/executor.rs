//! The parallel executor: a run's jobs solved through the cache as a [`CachePolicy`] says
//! (reused and filled, ignored, or read only), each solve alone and deterministic whatever the
//! thread count (rayon), results collected in job order.

use super::cache::{Cache, Lookup, Stamp};
use super::job::{point_jobs_in, Job, Setup};
use super::offline::{missing, missing_message};
use super::outcome::{CaseOutcome, SolvedCase};
use crate::physics::case::{Case, Problem};
use crate::pipeline::error::PipelineError;
use crate::solver::point::{self, Start};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// How a run uses the result cache.
#[derive(Debug, Clone, Copy)]
pub enum CachePolicy<'a> {
    /// Solve everything, cache nothing (`--no-cache`).
    Ignore,
    /// Reuse the cache's entries and add the new solves.
    Use(&'a Cache),
    /// The cache alone (`--offline`): a job without an entry is an error, nothing is solved.
    Offline(&'a Cache),
}

impl<'a> CachePolicy<'a> {
    /// The cache, if any.
    pub fn cache(&self) -> Option<&'a Cache> {
        match *self {
            CachePolicy::Ignore => None,
            CachePolicy::Use(c) | CachePolicy::Offline(c) => Some(c),
        }
    }
}

/// A job finished: solved here, or taken from the cache.
#[derive(Debug, Clone)]
pub struct FinishedJob {
    /// Solved or failed.
    pub outcome: CaseOutcome,
    /// How the result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
    /// Taken from the cache.
    pub cached: bool,
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

/// Runs `jobs` through the cache as `policy` says: `warn` hears of corrupt entries and cache write failures,
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
    policy: CachePolicy,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<FinishedJob>, PipelineError> {
    run_jobs_until(target, jobs, policy, progress, warn, None)
}

/// [`run_jobs`] that starts no new solve once `stop` is set (by a Ctrl-C handler, from any
/// thread): the solves in flight finish, each into the cache as always, and unless every
/// job was done by then the run ends in [`PipelineError::Interrupted`]. A run that takes up
/// the same jobs again finds those in the cache. `None`: the run goes to its end.
pub fn run_jobs_until(
    target: &str,
    jobs: &[Job],
    policy: CachePolicy,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
    stop: Option<&AtomicBool>,
) -> Result<Vec<FinishedJob>, PipelineError> {
    if let CachePolicy::Offline(cache) = policy {
        let absent = missing(jobs, cache);
        if !absent.is_empty() {
            let named: Vec<_> = absent
                .into_iter()
                .map(|(j, why)| (target.to_string(), j, why))
                .collect();
            return Err(PipelineError::Offline(missing_message(&named, cache)));
        }
    }
    let looked: Vec<Option<FinishedJob>> = jobs
        .par_iter()
        .map(
            |job| match policy.cache().map(|c| c.get::<CaseOutcome>(&job.key)) {
                Some(Lookup::Hit(outcome, stamp)) => Some(FinishedJob {
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
    if matches!(policy, CachePolicy::Offline(_)) {
        return jobs
            .iter()
            .zip(looked)
            .map(|(job, d)| {
                d.ok_or_else(|| {
                    PipelineError::Offline(format!(
                        "--offline: {target}: {} [key {}] vanished from the cache during the run",
                        job.label, job.key
                    ))
                })
            })
            .collect();
    }
    // The solves: the missing jobs and the bases they need, each once, as a forest whose
    // roots start cold or from a solution kept in memory (this process's earlier runs).
    let kept = |key: &str| policy.cache().and_then(|c| c.start(key));
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
    let own: BTreeSet<&str> = jobs
        .iter()
        .zip(&looked)
        .filter(|(_, d)| d.is_none())
        .map(|(j, _)| j.key.as_str())
        .collect();
    let bases = nodes.keys().filter(|k| !own.contains(*k)).count();
    let forest = Forest {
        nodes: &nodes,
        children: &children,
        policy,
        warn,
        progress,
        stop,
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
    // Every missing job is a node of the forest: only a stop leaves one unsolved.
    let unsolved = jobs
        .iter()
        .zip(&looked)
        .filter(|(job, d)| d.is_none() && !solved.contains_key(job.key.as_str()))
        .count();
    if unsolved > 0 {
        return Err(PipelineError::Interrupted {
            target: target.to_string(),
            unsolved,
        });
    }
    Ok(jobs
        .iter()
        .zip(looked)
        .filter_map(|(job, d)| d.or_else(|| solved.get(job.key.as_str()).cloned()))
        .collect())
}

/// The solves of a run as trees: each node a job, solved from its parent's solution (its
/// base), its children after it, in parallel (rayon's work stealing spreads a family's
/// members over the cores as soon as its base is done).
struct Forest<'a, 'j> {
    nodes: &'a BTreeMap<&'j str, &'j Job>,
    children: &'a BTreeMap<&'j str, Vec<&'j str>>,
    policy: CachePolicy<'a>,
    warn: &'a (dyn Fn(String) + Sync),
    progress: &'a (dyn Fn(RunProgress) + Sync),
    /// Set: start no new solve ([`run_jobs_until`]).
    stop: Option<&'a AtomicBool>,
    results: Mutex<HashMap<&'j str, FinishedJob>>,
    done: AtomicUsize,
    total: usize,
    cached: usize,
    bases: usize,
}

impl<'j> Forest<'_, 'j> {
    /// The expected cost of the tree under `key`.
    fn weight(&self, key: &str) -> f64 {
        let own = self.nodes.get(key).map_or(0.0, |j| j.solve.weight());
        own + self
            .children
            .get(key)
            .map_or(0.0, |c| c.iter().map(|k| self.weight(k)).sum())
    }

    /// Solves `key` from `start`, then its children from its solution (cold where it
    /// failed); nothing once the run is stopped.
    fn run(&self, key: &'j str, start: Option<Arc<Start>>) {
        if self.stop.is_some_and(|s| s.load(Ordering::SeqCst)) {
            return;
        }
        let job = self.nodes[key];
        let clock = std::time::Instant::now();
        let (outcome, solution) = job.solve.run(start.as_deref(), true);
        let stamp = Stamp::now(clock.elapsed().as_secs_f64(), job.solve.revisions());
        let solution = solution.map(Arc::new);
        if let Some(c) = self.policy.cache() {
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
        let done = FinishedJob {
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

/// One point case run.
#[derive(Debug, Clone)]
pub struct PointRun {
    /// The case.
    pub case: Case,
    /// The dimensionless problem (groups, tau_c).
    pub problem: Problem,
    /// The solver parameters it was solved with (the one rule's, [`super::job::point_jobs`]).
    pub params: point::Params,
    /// Solved or failed.
    pub outcome: CaseOutcome,
    /// Taken from the cache.
    pub cached: bool,
    /// Its cache key.
    pub key: String,
    /// How its result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
}

impl PointRun {
    /// The numbers when solved.
    pub fn solved(&self) -> Option<&SolvedCase> {
        self.outcome.solved()
    }
}

/// Runs `cases` at `level` (see [`super::job::point_jobs`]) through the cache as `policy` says (see
/// [`run_jobs`]); `target` names them in errors. Cases that do not resolve into a problem
/// are an error for the whole run.
pub fn run_cases(
    target: &str,
    cases: &[Case],
    level: u32,
    policy: CachePolicy,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<PointRun>, PipelineError> {
    run_cases_in(
        target,
        (cases, level, Setup::Rule),
        policy,
        progress,
        warn,
        None,
    )
}

/// [`run_cases`] for `cases` at `level` in `setup` ([`Setup`]), stopped as `stop` says
/// ([`run_jobs_until`]).
pub fn run_cases_in(
    target: &str,
    (cases, level, setup): (&[Case], u32, Setup),
    policy: CachePolicy,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
    stop: Option<&AtomicBool>,
) -> Result<Vec<PointRun>, PipelineError> {
    let planned = point_jobs_in(cases, level, setup)?;
    let jobs: Vec<Job> = planned.iter().map(|p| p.job.clone()).collect();
    let finished = run_jobs_until(target, &jobs, policy, progress, warn, stop)?;
    Ok(cases
        .iter()
        .zip(planned)
        .zip(finished)
        .map(|((case, p), f)| PointRun {
            case: case.clone(),
            problem: p.problem,
            params: p.params,
            outcome: f.outcome,
            cached: f.cached,
            key: p.job.key,
            stamp: f.stamp,
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::tests::worked_case;
    use crate::pipeline::job::point_jobs;

    /// A run whose stop flag is set before it starts solves nothing (no progress report),
    /// and says how many of its own jobs it left (the base the case needs is not one).
    #[test]
    fn a_stopped_run_starts_no_solve() {
        let jobs: Vec<Job> = point_jobs(&[worked_case()], 3)
            .expect("a valid case")
            .into_iter()
            .map(|p| p.job)
            .collect();
        assert!(jobs[0].base.is_some());
        let reports = AtomicUsize::new(0);
        let progress = |_: RunProgress| {
            reports.fetch_add(1, Ordering::SeqCst);
        };
        let stop = AtomicBool::new(true);
        let run = run_jobs_until(
            "t",
            &jobs,
            CachePolicy::Ignore,
            &progress,
            &|_| {},
            Some(&stop),
        );
        assert!(matches!(
            run,
            Err(PipelineError::Interrupted { unsolved: 1, .. })
        ));
        assert_eq!(reports.load(Ordering::SeqCst), 0);
    }
}

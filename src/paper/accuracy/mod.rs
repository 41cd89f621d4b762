//! What accuracy costs in time: representative cases solved level by level, each level's
//! central film and sliding `mu-bar` compared with a Richardson extrapolation of the two
//! finest levels, against the wall time of its solve (`repro accuracy`).
//!
//! A case of the study is an [`AccuracyCase`] (`cases.rs`): a name, the shipped sweeps it
//! stands for (and so the targets that draw them), and an [`AccuracyProblem`] that knows how
//! to solve itself at a level. Adding a case
//! is adding one entry to [`cases::accuracy_cases`]; the rest (errors here, the files in
//! `files.rs`, the picture in `picture.rs`, the recommended level per target) is shared. A
//! design of the grid (the inlet patch) is a case of the same contact with other parameters,
//! measured against its rule's case's reference ([`AccuracyCase::reference_from`]), so that
//! the two series compare on one picture.
//!
//! The error estimate. With `X_n` the value at level `n`, `f` the finest converged level and
//! `p` the order of convergence, `X_R = X_f + (X_f - X_{f-1}) / (2^p - 1)` removes the leading
//! `h^p` term; each level's error is `|X_n / X_R - 1|`. Where the three finest levels
//! converged, `p` is the order they show, `log2 |X_{f-2} - X_{f-1}| / |X_{f-1} - X_f|`, for
//! film and friction apart, held to [`ORDER_RANGE`] (1 to 2) where the two differences are of
//! one sign; where they alternate the estimate takes `p = 1`, whose correction `X_f - X_{f-1}`
//! bounds the error of any order at least 1 (the CSV says which).
//! The discretisation is second order where the grid resolves the pressure peak's flank,
//! but the piezoviscous light contacts converge at 1.1-1.4 (docs/ACCURACY_NOTES.md, "the
//! bisection"), where an assumed second order understated the error about twofold. With
//! only two finest levels the second order is assumed; with one, the finest level is the
//! reference (and its own error is zero, which says nothing): the CSV names the reference.
//!
//! Timing: each solve runs alone, one after the other, on the calling thread (the point solver
//! is single-threaded), and with `repeats > 1` the median wall time is kept.

pub mod cases;
pub mod files;
pub mod picture;
mod reference;

use crate::paper::target::median;
use crate::solver::output::SolveError;
pub use cases::{AccuracyCase, AccuracyProblem, LevelOutputs};
pub use reference::reference;
use std::time::Instant;

/// Error of `mu-bar` under which a level is taken as good enough for a target.
pub const MU_TOLERANCE: f64 = 0.01;

/// One level of one case.
#[derive(Debug, Clone)]
pub struct LevelRun {
    /// Grid level.
    pub level: u32,
    /// The solve, or why it failed.
    pub outcome: Result<LevelOutputs, SolveError>,
    /// Wall time, s (median over the repeats).
    pub seconds: f64,
}

/// The reference a case's errors are measured against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// Central film.
    pub h_central: f64,
    /// Sliding `mu-bar`.
    pub mu_bar: f64,
    /// Minimum film, extrapolated the same way from the same levels where their minimum
    /// films give an estimate ([`crate::solver::richardson::estimate`]; `None` where they do
    /// not: the heavy contacts' side lobes closed or far outside the asymptotic range).
    pub h_min: Option<f64>,
    /// The order the minimum film's extrapolation used.
    pub order_used_h_min: Option<f64>,
    /// "observed-order" (three finest levels), "richardson" (second order, two finest
    /// levels), "finest", or [`TWIN_REFERENCE`] (a design's: its rule's case's).
    pub kind: &'static str,
    /// Order observed over the three finest levels, film and friction (when three
    /// consecutive finest levels converged and the differences are not zero).
    pub order: Option<(f64, f64)>,
    /// The orders the extrapolation used, film and friction: the observed one within
    /// [`ORDER_RANGE`], else 1 (see the module's doc); 2 with two levels; `None` with one.
    pub order_used: Option<(f64, f64)>,
}

pub use crate::solver::richardson::ORDER_RANGE;

/// A case and its levels.
#[derive(Debug, Clone)]
pub struct AccuracyResult {
    /// Name.
    pub name: &'static str,
    /// Description.
    pub description: &'static str,
    /// "point" or "line".
    pub kind: &'static str,
    /// The targets it stands for ([`AccuracyCase::targets`]).
    pub targets: Vec<&'static str>,
    /// Its level offset (see [`AccuracyCase::level_offset`]).
    pub level_offset: u32,
    /// Levels, coarse to fine.
    pub levels: Vec<LevelRun>,
    /// The reference of the errors (`None` when nothing converged).
    pub reference: Option<Reference>,
    /// The case whose reference a design's errors are measured against
    /// ([`AccuracyCase::reference_from`]); `None` for a case of its own.
    pub twin: Option<&'static str>,
    /// The domain check of a point contact ([`DomainCheck`]).
    pub domain: Option<DomainCheck>,
    /// Points per level (for the CSV).
    points: Vec<String>,
}

/// How much the domain moves a point contact's outputs: the case solved on its domain at
/// the second-finest level of the study against its inlet and sides doubled at the finest
/// (the same mesh).
#[derive(Debug, Clone)]
pub struct DomainCheck {
    /// The doubled domain's level.
    pub level: u32,
    /// The relative change of the central film and of sliding `mu-bar`, or why the doubled
    /// domain's solve failed.
    pub change: Result<(f64, f64), SolveError>,
    /// Wall time of the doubled domain's solve, s: what the check costs beside the level's
    /// own solve on the same mesh.
    pub seconds: f64,
}

impl DomainCheck {
    /// The check of `case` whose runs are `runs`: `None` for a line contact, or when the
    /// study has no two consecutive finest levels or the coarser one failed.
    fn of(case: &AccuracyCase, runs: &[LevelRun]) -> Option<DomainCheck> {
        if case.reference_from.is_some() {
            // A design is measured against its rule's case, whose domain is checked.
            return None;
        }
        let [.., coarse, fine] = runs else {
            return None;
        };
        let own = coarse.outcome.as_ref().ok()?;
        if fine.level != coarse.level + 1 {
            return None;
        }
        let clock = std::time::Instant::now();
        let doubled = case.contact.solve_doubled(fine.level)?;
        Some(DomainCheck {
            seconds: clock.elapsed().as_secs_f64(),
            level: fine.level,
            change: doubled.map(|d| {
                (
                    (d.h_central_grid / own.h_central_grid - 1.0).abs(),
                    (d.mu_bar / own.mu_bar - 1.0).abs(),
                )
            }),
        })
    }
}

impl AccuracyResult {
    /// Relative errors `(film, mu-bar)` of a level against the reference: the film as the
    /// rule reports it (tau-extrapolated where it extrapolates).
    pub fn errors(&self, run: &LevelRun) -> Option<(f64, f64)> {
        let r = self.reference?;
        let m = run.outcome.as_ref().ok()?;
        Some((
            (m.h_central / r.h_central - 1.0).abs(),
            (m.mu_bar / r.mu_bar - 1.0).abs(),
        ))
    }

    /// The relative error of a level's own central film (the grid's, before any
    /// tau-extrapolation) against the reference.
    pub fn grid_film_error(&self, run: &LevelRun) -> Option<f64> {
        let r = self.reference?;
        let m = run.outcome.as_ref().ok()?;
        Some((m.h_central_grid / r.h_central - 1.0).abs())
    }

    /// The relative error of a level's minimum film (a top's where the solve added one)
    /// against the reference's.
    pub fn h_min_error(&self, run: &LevelRun) -> Option<f64> {
        let r = self.reference?.h_min?;
        let m = run.outcome.as_ref().ok()?;
        Some((m.h_min / r - 1.0).abs())
    }

    /// Whether any level reported its central film tau-extrapolated.
    pub fn extrapolates_film(&self) -> bool {
        self.levels
            .iter()
            .filter_map(|r| r.outcome.as_ref().ok())
            .any(|m| m.h_central != m.h_central_grid)
    }

    /// The cheapest level whose `mu-bar` error is within `tol`, and that of every finer level
    /// too (a level that is right by chance between two wrong ones is not a choice). `None`
    /// when no level qualifies, and when the reference is the finest level itself (one
    /// converged level: its error of zero is not an estimate).
    pub fn cheapest_within(&self, tol: f64) -> Option<&LevelRun> {
        if self.reference.is_none_or(|r| r.kind == "finest") {
            return None;
        }
        let mut best = None;
        for run in self.levels.iter().rev() {
            match self.errors(run) {
                Some((_, e)) if e <= tol => best = Some(run),
                _ => break,
            }
        }
        best
    }
}

/// Runs the study: each case at `levels` (plus its offset), `repeats` solves per level (the
/// median time is kept); `progress` hears of each level as it finishes.
pub fn run(
    cases: &[AccuracyCase],
    levels: &[u32],
    repeats: usize,
    progress: &mut dyn FnMut(&AccuracyCase, &LevelRun),
) -> Vec<AccuracyResult> {
    let mut studies: Vec<AccuracyResult> = cases
        .iter()
        .map(|case| {
            let mut runs = Vec::new();
            for &l in levels {
                let level = l + case.level_offset;
                let mut times = Vec::new();
                let mut outcome = Err(SolveError::InvalidParams("no solve".into()));
                for _ in 0..repeats.max(1) {
                    let t = Instant::now();
                    outcome = case.contact.solve(level);
                    times.push(t.elapsed().as_secs_f64());
                }
                let run = LevelRun {
                    level,
                    outcome,
                    seconds: median(times),
                };
                progress(case, &run);
                runs.push(run);
            }
            AccuracyResult {
                name: case.name,
                description: case.description,
                kind: case.contact.kind(),
                targets: case.targets(),
                level_offset: case.level_offset,
                reference: reference(&runs),
                twin: case.reference_from,
                domain: DomainCheck::of(case, &runs),
                points: runs
                    .iter()
                    .map(|r| match &r.outcome {
                        Ok(m) => case.contact.points(m.level, m.across),
                        Err(_) => case.contact.points(r.level, false),
                    })
                    .collect(),
                levels: runs,
            }
        })
        .collect();
    for (i, case) in cases.iter().enumerate() {
        if let Some(from) = case.reference_from {
            studies[i].reference = studies
                .iter()
                .find(|s| s.name == from)
                .and_then(|s| s.reference)
                .map(|r| Reference {
                    kind: TWIN_REFERENCE,
                    ..r
                });
        }
    }
    studies
}

/// The reference kind of a design measured against its rule's case
/// ([`AccuracyCase::reference_from`]): that case's reference, whatever its kind.
pub const TWIN_REFERENCE: &str = "the rule's case";

/// The recommended level of a target.
#[derive(Debug, Clone, PartialEq)]
pub struct Recommendation {
    /// Target name.
    pub target: &'static str,
    /// The case that decided it (the most demanding of those standing for the target).
    pub case: &'static str,
    /// Cheapest level with `mu-bar` within [`MU_TOLERANCE`] (`None`: none of the levels run).
    pub level: Option<u32>,
    /// Its `mu-bar` error.
    pub mu_error: Option<f64>,
    /// Its wall time, s.
    pub seconds: Option<f64>,
}

/// For each target the study's cases stand for, the cheapest level whose sliding `mu-bar` is
/// within `tol` of the reference for every case standing for it (the most demanding case
/// decides; a case with no qualifying level makes the target's level `None`).
pub fn recommend(studies: &[AccuracyResult], tol: f64) -> Vec<Recommendation> {
    let mut targets: Vec<&'static str> = Vec::new();
    for s in studies {
        for t in &s.targets {
            if !targets.contains(t) {
                targets.push(t);
            }
        }
    }
    targets
        .into_iter()
        .map(|target| {
            let mut rec = Recommendation {
                target,
                case: "",
                level: None,
                mu_error: None,
                seconds: None,
            };
            // Levels compared on the point scale (a line level stands beside the point level
            // `level_offset` below it): the most demanding case has the highest.
            let mut worst: Option<(i64, &AccuracyResult, Option<&LevelRun>)> = None;
            for s in studies.iter().filter(|s| s.targets.contains(&target)) {
                let choice = s.cheapest_within(tol);
                let rank =
                    choice.map_or(i64::MAX, |r| i64::from(r.level) - i64::from(s.level_offset));
                if worst.as_ref().is_none_or(|w| rank > w.0) {
                    worst = Some((rank, s, choice));
                }
            }
            if let Some((_, s, choice)) = worst {
                rec.case = s.name;
                if let Some(r) = choice {
                    rec.level = Some(r.level);
                    rec.mu_error = s.errors(r).map(|e| e.1);
                    rec.seconds = Some(r.seconds);
                }
            }
            rec
        })
        .collect()
}

#[cfg(test)]
pub(crate) mod tests;

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
                domain: DomainCheck::of(case, &runs),
                points: runs.iter().map(|r| case.contact.points(r.level)).collect(),
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
pub(crate) mod tests {
    use super::*;

    /// A level that converged to `h` and `mu` in `0.1 level` seconds.
    pub(crate) fn run(level: u32, h: f64, mu: f64) -> LevelRun {
        LevelRun {
            level,
            outcome: Ok(LevelOutputs {
                h_central: h,
                h_central_grid: h,
                mu_bar: mu,
                cycles: 10,
            }),
            seconds: 0.1 * f64::from(level),
        }
    }

    /// A point-contact study of `levels` that stands for Fig. 3.
    pub(crate) fn study(levels: Vec<LevelRun>) -> AccuracyResult {
        AccuracyResult {
            name: "t",
            description: "",
            kind: "point",
            targets: vec!["fig3"],
            level_offset: 0,
            reference: reference(&levels),
            domain: None,
            points: levels.iter().map(|_| String::new()).collect(),
            levels,
        }
    }

    #[test]
    fn richardson_removes_an_exact_second_order_error() {
        // X_n = 2 + 3 h^2 with h = 2^-n: the extrapolation is exact (to rounding) and the
        // observed order is 2.
        let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
        let levels: Vec<_> = (4..=7).map(|n| run(n, x(n), x(n))).collect();
        let r = reference(&levels).unwrap();
        assert_eq!(r.kind, "observed-order");
        assert!((r.mu_bar - 2.0).abs() < 1e-14, "{}", r.mu_bar);
        let (oh, om) = r.order.unwrap();
        assert!((oh - 2.0).abs() < 1e-9 && (om - 2.0).abs() < 1e-9);
        // Two levels only: the second order assumed, exact here too.
        let r = reference(&levels[2..]).unwrap();
        assert_eq!((r.kind, r.order_used), ("richardson", Some((2.0, 2.0))));
        assert!((r.h_central - 2.0).abs() < 1e-14, "{}", r.h_central);
    }

    #[test]
    fn the_reference_reads_the_grids_films_and_the_reported_one_is_measured_against_it() {
        // X_n = 2 + 3 h^2 (exact at order 2). Level 7's film reported tau-extrapolated, 1e-6
        // from the limit: the reference is still the grids' (2), the reported film's error
        // is its 5e-7 and the grid's own its 3 h^2 / 2 = 9.2e-5.
        let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
        let mut levels: Vec<_> = (5..=7).map(|n| run(n, x(n), x(n))).collect();
        let plain = reference(&levels).unwrap();
        if let Ok(m) = &mut levels[2].outcome {
            m.h_central = 2.0 + 1e-6;
        }
        let s = study(levels);
        assert_eq!(s.reference.unwrap().h_central, plain.h_central);
        assert!(s.extrapolates_film());
        let top = &s.levels[2];
        assert!((s.errors(top).unwrap().0 - 5e-7).abs() < 1e-12);
        let grid = s.grid_film_error(top).unwrap();
        assert!((grid - 1.5 * 4f64.powi(-7)).abs() < 1e-12, "{grid}");
    }

    #[test]
    fn the_observed_order_extrapolates_a_first_order_error_exactly() {
        // X_n = 2 + 3 h with h = 2^-n (the light contacts' friction converges near first
        // order): the observed order 1 is used, and the extrapolation is exact, where the
        // second order assumed would leave two thirds of the finest level's error.
        let x = |n: u32| 2.0 + 3.0 * 2f64.powi(-(n as i32));
        let levels: Vec<_> = (5..=8).map(|n| run(n, x(n), x(n))).collect();
        let r = reference(&levels).unwrap();
        let (ph, pm) = r.order_used.unwrap();
        assert!((ph - 1.0).abs() < 1e-9 && (pm - 1.0).abs() < 1e-9);
        assert!((r.mu_bar - 2.0).abs() < 1e-13, "{}", r.mu_bar);
    }

    #[test]
    fn an_oscillating_order_is_bounded_at_first_order_and_a_high_one_held_to_second() {
        // Film oscillates (+0.1, -0.05): p = 1, X_R = X_f + (X_f - X_{f-1}). Friction
        // converges at order 4 (above the scheme's): held to p = 2, X_R = X_f + d_f / 3.
        let levels = vec![run(6, 1.0, 10.0), run(7, 1.1, 11.0), run(8, 1.05, 11.0625)];
        let r = reference(&levels).unwrap();
        assert_eq!(r.order_used, Some((1.0, 2.0)));
        assert!((r.h_central - 1.0).abs() < 1e-12, "{}", r.h_central);
        assert!(
            (r.mu_bar - 11.083333333333334).abs() < 1e-12,
            "{}",
            r.mu_bar
        );
    }

    #[test]
    fn a_gap_below_the_finest_level_falls_back_to_the_finest() {
        let mut levels = vec![run(5, 1.0, 40.0), run(6, 1.1, 41.0), run(7, 1.2, 41.5)];
        levels[1].outcome = Err(SolveError::InvalidParams("x".into()));
        let r = reference(&levels).unwrap();
        assert_eq!(r.kind, "finest");
        assert_eq!(r.mu_bar, 41.5);
        assert!(reference(&[]).is_none());
    }

    #[test]
    fn the_cheapest_level_must_hold_for_every_finer_level() {
        // mu: 40.5 (in by chance), 38 (out), 40.1, 40.02, 40.0 -> reference 39.993...
        let levels = vec![
            run(4, 1.0, 40.5),
            run(5, 1.0, 38.0),
            run(6, 1.0, 40.1),
            run(7, 1.0, 40.02),
            run(8, 1.0, 40.0),
        ];
        let s = study(levels);
        assert_eq!(s.cheapest_within(0.01).map(|r| r.level), Some(6));
        assert_eq!(s.cheapest_within(1e-9).map(|r| r.level), None);
        let recs = recommend(&[s], 0.01);
        assert_eq!(recs.len(), 1);
        assert_eq!((recs[0].target, recs[0].level), ("fig3", Some(6)));
    }

    #[test]
    fn a_case_with_one_converged_level_qualifies_no_level() {
        // The heavy-m19205 study: levels 4-7 close the film, level 8 alone converges; its
        // reference is itself, so the error of 0 it prints is no evidence, and the target
        // it stands for gets no level rather than level 8 at "0 %".
        let mut levels = vec![run(6, 1.0, 25.0), run(7, 1.0, 25.0), run(8, 1.4e-3, 25.1)];
        for l in &mut levels[..2] {
            l.outcome = Err(SolveError::InvalidParams("closed".into()));
        }
        let s = study(levels);
        assert_eq!(s.reference.map(|r| r.kind), Some("finest"));
        assert!(s.cheapest_within(0.01).is_none());
        let recs = recommend(&[s], 0.01);
        assert_eq!((recs[0].case, recs[0].level), ("t", None));
    }

    #[test]
    fn the_most_demanding_case_decides_a_target() {
        let easy = study(vec![
            run(4, 1.0, 40.0),
            run(5, 1.0, 40.0),
            run(6, 1.0, 40.0),
        ]);
        // Second order: reference 40.133, level 5 1.3 % off, level 6 0.33 %.
        let hard = study(vec![
            run(4, 1.0, 38.0),
            run(5, 1.0, 39.6),
            run(6, 1.0, 40.0),
        ]);
        let recs = recommend(&[easy, hard], 0.01);
        assert_eq!(recs[0].level, Some(6));
    }

    #[test]
    fn the_csv_has_a_row_for_failed_levels_too() {
        let mut levels = vec![run(4, 1.0, 40.0), run(5, 1.0, 41.0), run(6, 1.0, 41.2)];
        levels[0].outcome = Err(SolveError::InvalidParams("x".into()));
        let s = study(levels);
        let csv = super::files::to_csv(std::slice::from_ref(&s));
        assert_eq!(csv.lines().count(), 4);
        assert!(csv.lines().nth(1).unwrap().contains("failed"));
    }
}

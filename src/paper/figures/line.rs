//! The line contacts of Fig. 7: the five Table 3 load cases of `cases/fig7.toml` (mineral oil
//! A, Roelands, Dowson-Higginson, Eyring) without their `Ry`, solved by the 1-D solver.

use super::estimate::EstimateCells;
use super::spec::FIG7;
use crate::paper::eq13::{eq13_mu_bar, PAPER_C};
use crate::paper::mastercurve::oracle::line_flat;
use crate::physics::case::{CaseForm, Physics};
use crate::physics::line_contact::{LinePhysicalCase, LineProblem};
use crate::physics::lubricant::LubricantTable;
use crate::pipeline::cache::Stamp;
use crate::pipeline::csv::rows;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::{run_jobs, CachePolicy, RunProgress};
use crate::pipeline::job::{line_job, Job, LineJob};
use crate::pipeline::outcome::{CaseOutcome, Output};
use crate::solver::line::Params;
use serde::Serialize;

/// The five Table 3 cases as line contacts, in the order of the table, with the physics of
/// Figs. 4-7. The rows are read from the shipped `cases/fig7.toml` (its `D = 1/2` block), the
/// one source of truth for Table 3.
pub fn table3_line_cases() -> Result<(Vec<LinePhysicalCase>, Physics), PipelineError> {
    let sweep = FIG7.sweep.parse()?;
    let lubs = LubricantTable::table1();
    let mut out: Vec<LinePhysicalCase> = Vec::new();
    for c in &sweep.cases {
        if let CaseForm::Physical(ph) = &c.spec {
            let line = LinePhysicalCase::from_point_case(ph, &lubs)
                .map_err(|e| PipelineError::case("cases/fig7.toml", e))?;
            if !out.contains(&line) {
                out.push(line);
            }
        }
    }
    if out.len() != 5 {
        return Err(PipelineError::Input(format!(
            "cases/fig7.toml: expected the 5 load cases of Table 3, found {}",
            out.len()
        )));
    }
    Ok((out, Physics::figs_4_to_7()))
}

/// One Table 3 line contact solved for Fig. 7.
#[derive(Debug, Clone)]
pub struct LineRun {
    /// The case.
    pub case: LinePhysicalCase,
    /// Its problem (groups, `tau_c`).
    pub problem: LineProblem,
    /// The solver parameters it was solved with (the line solver's rule, [`line_job`]).
    pub params: Params,
    /// Solved or failed.
    pub outcome: CaseOutcome,
    /// Its cache key.
    pub key: String,
    /// How its result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
    /// Taken from the cache.
    pub cached: bool,
}

/// The five Table 3 line contacts at `level` as jobs (labelled `line contact 1..5`), each
/// with the parameters its problem calls for ([`line_job`]), with their cases.
pub fn table3_jobs(level: u32) -> Result<Vec<(LineJob, LinePhysicalCase)>, PipelineError> {
    let (cases, physics) = table3_line_cases()?;
    cases
        .into_iter()
        .enumerate()
        .map(|(i, case)| {
            let label = format!(
                "line contact {} (p_H {} GPa, u_m {} m/s, S {}, tau0 {} MPa, level {level})",
                i + 1,
                case.ph_pa / 1e9,
                case.um_m_s,
                case.slip,
                case.tau0_pa / 1e6
            );
            let job = line_job(&case, physics, level, label)
                .map_err(|e| PipelineError::case("cases/fig7.toml: line contact", e))?;
            Ok((job, case))
        })
        .collect()
}

/// Solves the five Table 3 line contacts at `level` through `store` (in parallel, each on one
/// thread); `target` names them in errors.
pub fn solve_table3(
    target: &str,
    level: u32,
    store: CachePolicy,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<LineRun>, PipelineError> {
    let jobs = table3_jobs(level)?;
    let list: Vec<Job> = jobs.iter().map(|(j, _)| j.job.clone()).collect();
    let done = run_jobs(target, &list, store, progress, warn)?;
    Ok(jobs
        .into_iter()
        .zip(done)
        .map(|((job, case), d)| LineRun {
            case,
            problem: job.problem,
            params: job.params,
            outcome: d.outcome,
            key: job.job.key,
            stamp: d.stamp,
            cached: d.cached,
        })
        .collect())
}

/// A row of `fig7-line.csv`: the columns of the point-contact CSV that apply.
#[derive(Debug, Default, Serialize)]
struct LineRow {
    case: usize,
    ph_gpa: f64,
    um_m_s: f64,
    slip: f64,
    tau0_mpa: f64,
    level: u32,
    m: f64,
    l: f64,
    s_bar: f64,
    alpha_bar: f64,
    tau_c: f64,
    mu_bar_eq13: f64,
    hc: Option<f64>,
    hc_moes: Option<f64>,
    hmin_moes: Option<f64>,
    mu_bar_sliding: Option<f64>,
    mu_bar_flat: Option<f64>,
    rel_dev_eq13: Option<f64>,
    rel_dev_flat: Option<f64>,
    cycles: Option<usize>,
    /// Relative discretisation errors and the extrapolated sliding `mu-bar`
    /// ([`crate::solver::richardson`]), and the levels the estimate read (up to `level - 2`
    /// to `level`; fewer where a coarser level is outside the asymptotic range) with its
    /// status ([`EstimateCells`]).
    hc_rel_error: Option<f64>,
    hmin_rel_error: Option<f64>,
    mu_bar_sliding_rel_error: Option<f64>,
    mu_bar_sliding_extrapolated: Option<f64>,
    #[serde(flatten)]
    estimate: EstimateCells,
    status: String,
}

/// `fig7-line.csv`: one row per line contact asked for at `level` (each row names the level
/// it was solved on: a finer one where its error estimate needed it).
pub fn line_csv(runs: &[LineRun], level: u32) -> String {
    rows(runs.iter().enumerate().map(|(i, r)| {
        let g = &r.problem.groups;
        let tau_c = r.problem.tau_c();
        let eq13 = eq13_mu_bar(tau_c, PAPER_C);
        let row = LineRow {
            case: i + 1,
            ph_gpa: r.case.ph_pa / 1e9,
            um_m_s: r.case.um_m_s,
            slip: r.case.slip,
            tau0_mpa: r.case.tau0_pa / 1e6,
            level,
            m: g.m,
            l: g.l,
            s_bar: g.s_bar,
            alpha_bar: g.alpha_bar,
            tau_c,
            mu_bar_eq13: eq13,
            estimate: EstimateCells::of(r.outcome.solved()),
            status: r.outcome.status(),
            ..LineRow::default()
        };
        match r.outcome.solved() {
            Some(s) => {
                let flat = line_flat(&r.problem, s.h_central);
                LineRow {
                    level: s.level,
                    hc: Some(s.h_central),
                    hc_moes: Some(s.hc_moes),
                    hmin_moes: Some(s.hmin_moes),
                    mu_bar_sliding: Some(s.mu_bar_sliding),
                    mu_bar_flat: Some(flat),
                    rel_dev_eq13: Some(s.mu_bar_sliding / eq13 - 1.0),
                    rel_dev_flat: Some(s.mu_bar_sliding / flat - 1.0),
                    cycles: Some(s.cycles),
                    hc_rel_error: s.relative_error(Output::HCentral),
                    hmin_rel_error: s.relative_error(Output::HMin),
                    mu_bar_sliding_rel_error: s.relative_error(Output::MuBarSliding),
                    mu_bar_sliding_extrapolated: s
                        .estimate(Output::MuBarSliding)
                        .map(|e| e.extrapolated),
                    ..row
                }
            }
            None => row,
        }
    }))
}

/// The absolute discretisation error of the sliding `mu-bar` of the solved line contacts, in
/// the order of [`line_points`] (0 where not estimated).
pub fn line_errors(runs: &[LineRun]) -> Vec<f64> {
    runs.iter()
        .filter_map(|r| r.outcome.solved())
        .map(|s| s.estimate(Output::MuBarSliding).map_or(0.0, |e| e.error))
        .collect()
}

/// The solved line contacts as `(tau_c, sliding mu-bar)`.
pub fn line_points(runs: &[LineRun]) -> Vec<(f64, f64)> {
    runs.iter()
        .filter_map(|r| {
            r.outcome
                .solved()
                .map(|s| (r.problem.tau_c(), s.mu_bar_sliding))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    #[test]
    fn table3_has_five_line_cases_in_order() {
        let (cases, _) = super::table3_line_cases().unwrap();
        // Table 3 of the paper: p_H (GPa) 1, 2, 2, 3, 3 and S 2 %, then 0.1 %.
        let ph: Vec<f64> = cases.iter().map(|c| c.ph_pa / 1e9).collect();
        assert_eq!(ph, vec![1.0, 2.0, 2.0, 3.0, 3.0]);
        assert!((cases[0].slip - 0.02).abs() < 1e-15);
        // Table 1 at 40 C for the last case: alpha 21.6 /GPa, eta0 8.24 mPa s.
        assert!((cases[4].alpha_per_pa - 21.6e-9).abs() < 1e-15);
        assert!((cases[4].eta0_pa_s - 8.24e-3).abs() < 1e-15);
    }
}

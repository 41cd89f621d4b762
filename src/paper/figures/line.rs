//! The line contacts of Fig. 7: the five Table 3 load cases of `cases/fig7.toml` (mineral oil
//! A, Roelands, Dowson-Higginson, Eyring) without their `Ry`, solved by the 1-D solver.

use crate::paper::mastercurve::fit::{mastercurve, PAPER_C};
use crate::paper::mastercurve::oracle::line_flat;
use crate::physics::case::{Physics, Spec};
use crate::physics::line_contact::{LinePhysicalCase, LineProblem};
use crate::physics::lubricant::LubricantTable;
use crate::pipeline::cache::Stamp;
use crate::pipeline::csv::{num, table};
use crate::pipeline::run::{line_key, run_jobs, Job, Outcome, RunProgress, Store, Work};
use crate::pipeline::sweep::shipped_sweep;
use crate::solver::line::Params;

/// The five Table 3 cases as line contacts, in the order of the table, with the physics of
/// Figs. 4-7. The rows are read from the shipped `cases/fig7.toml` (its `D = 1/2` block), the
/// one source of truth for Table 3.
pub fn table3_line_cases() -> Result<(Vec<LinePhysicalCase>, Physics), String> {
    let sweep = shipped_sweep("fig7").map_err(|e| e.to_string())?;
    let lubs = LubricantTable::table1();
    let mut out: Vec<LinePhysicalCase> = Vec::new();
    for c in &sweep.cases {
        if let Spec::Physical(ph) = &c.spec {
            let line = LinePhysicalCase::from_point_case(ph, &lubs)
                .map_err(|e| format!("cases/fig7.toml: {e}"))?;
            if !out.contains(&line) {
                out.push(line);
            }
        }
    }
    if out.len() != 5 {
        return Err(format!(
            "cases/fig7.toml: expected the 5 load cases of Table 3, found {}",
            out.len()
        ));
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
    /// Solved or failed.
    pub outcome: Outcome,
    /// Its cache key.
    pub key: String,
    /// How its result was made (`None` for cache entries written before stamps).
    pub stamp: Option<Stamp>,
    /// Taken from the cache.
    pub cached: bool,
}

/// The five Table 3 line contacts at `level` as jobs (labelled `line contact 1..5`), each
/// with the parameters its problem calls for ([`Params::for_problem`]), with their cases and
/// problems.
pub fn table3_jobs(level: u32) -> Result<Vec<(Job, LinePhysicalCase, LineProblem)>, String> {
    let (cases, physics) = table3_line_cases()?;
    cases
        .into_iter()
        .enumerate()
        .map(|(i, case)| {
            let problem = LineProblem::from_physical(&case, physics)
                .map_err(|e| format!("cases/fig7.toml: line contact: {e}"))?;
            let params = Params::for_problem(&problem, level);
            let job = Job {
                key: line_key(&case, &physics, &params),
                label: format!(
                    "line contact {} (p_H {} GPa, u_m {} m/s, S {}, tau0 {} MPa, level {level})",
                    i + 1,
                    case.ph_pa / 1e9,
                    case.um_m_s,
                    case.slip,
                    case.tau0_pa / 1e6
                ),
                work: Work::Line {
                    problem: problem.clone(),
                    params,
                },
                base: None,
            };
            Ok((job, case, problem))
        })
        .collect()
}

/// Solves the five Table 3 line contacts at `level` through `store` (in parallel, each on one
/// thread); `target` names them in errors.
pub fn solve_table3(
    target: &str,
    level: u32,
    store: Store,
    progress: &(dyn Fn(RunProgress) + Sync),
    warn: &(dyn Fn(String) + Sync),
) -> Result<Vec<LineRun>, String> {
    let jobs = table3_jobs(level)?;
    let list: Vec<Job> = jobs.iter().map(|(j, _, _)| j.clone()).collect();
    let done = run_jobs(target, &list, store, progress, warn)?;
    Ok(jobs
        .into_iter()
        .zip(done)
        .map(|((job, case, problem), d)| LineRun {
            case,
            problem,
            outcome: d.outcome,
            key: job.key,
            stamp: d.stamp,
            cached: d.cached,
        })
        .collect())
}

/// `fig7-line.csv`: one row per line contact, the columns of the point-contact CSV that apply.
pub fn line_csv(runs: &[LineRun], level: u32) -> String {
    let header = [
        "case",
        "ph_gpa",
        "um_m_s",
        "slip",
        "tau0_mpa",
        "level",
        "m",
        "l",
        "s_bar",
        "alpha_bar",
        "tau_c",
        "mu_bar_eq13",
        "hc",
        "hc_moes",
        "hmin_moes",
        "mu_bar_sliding",
        "mu_bar_flat",
        "rel_dev_eq13",
        "rel_dev_flat",
        "cycles",
        "status",
    ];
    let rows: Vec<Vec<String>> = runs
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let g = &r.problem.groups;
            let tau_c = r.problem.tau_c();
            let eq13 = mastercurve(tau_c, PAPER_C);
            let mut row = vec![
                (i + 1).to_string(),
                num(r.case.ph_pa / 1e9),
                num(r.case.um_m_s),
                num(r.case.slip),
                num(r.case.tau0_pa / 1e6),
                level.to_string(),
                num(g.m),
                num(g.l),
                num(g.s_bar),
                num(g.alpha_bar),
                num(tau_c),
                num(eq13),
            ];
            match &r.outcome {
                Outcome::Solved(s) => {
                    let flat = line_flat(&r.problem, s.h_central);
                    row.extend([
                        num(s.h_central),
                        num(s.hc_moes),
                        num(s.hmin_moes),
                        num(s.mu_bar_sliding),
                        num(flat),
                        num(s.mu_bar_sliding / eq13 - 1.0),
                        num(s.mu_bar_sliding / flat - 1.0),
                        s.cycles.to_string(),
                        "solved".into(),
                    ])
                }
                Outcome::Failed { .. } => {
                    row.extend(std::iter::repeat_n(String::new(), 8));
                    row.push(format!(
                        "failed: {}",
                        r.outcome.failure_kind().unwrap_or("failed")
                    ));
                }
            }
            row
        })
        .collect();
    table(&header, &rows)
}

/// The solved line contacts as `(tau_c, sliding mu-bar)`.
pub fn line_points(runs: &[LineRun]) -> Vec<(f64, f64)> {
    runs.iter()
        .filter_map(|r| {
            r.outcome
                .record()
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

//! Table 4: variation of the central film `H = h/c` and of the sliding reduced friction with
//! the grid level, for the Appendix case (`cases/table4.toml`), with the wall time per level.

use crate::physics::case::{Case, Problem};
use crate::physics::lubricant::LubricantTable;
use crate::solver::output::SolveError;
use crate::solver::point::{solve, Params, Progress};
use serde::Deserialize;

/// The case definition shipped in `cases/table4.toml`.
pub const CASE_TOML: &str = include_str!("../../cases/table4.toml");

/// The paper's Table 4: `(level, Hc = h/c, sliding mu-bar)`. For the "paper" column only.
pub const PAPER: [(u32, f64, f64); 4] = [
    (5, 3.545e-3, 42.38),
    (6, 1.603e-2, 41.35),
    (7, 1.978e-2, 41.13),
    (8, 2.076e-2, 41.09),
];

/// `cases/table4.toml`.
#[derive(Debug, Clone, Deserialize)]
pub struct Table4Case {
    /// Levels to solve.
    pub levels: Vec<u32>,
    /// The Appendix case.
    pub case: Case,
}

impl Table4Case {
    /// The shipped definition.
    pub fn shipped() -> Result<Self, String> {
        toml::from_str(CASE_TOML).map_err(|e| format!("cases/table4.toml: {e}"))
    }
}

/// One level's result.
#[derive(Debug, Clone)]
pub struct Row {
    /// Grid level.
    pub level: u32,
    /// The solve, or why it failed.
    pub outcome: Result<crate::solver::point::PointSolution, SolveError>,
    /// Wall time of the solve, s.
    pub seconds: f64,
}

impl Row {
    /// The paper's `(Hc, mu-bar)` at this level, if it printed one.
    pub fn paper(&self) -> Option<(f64, f64)> {
        PAPER.iter().find(|p| p.0 == self.level).map(|p| (p.1, p.2))
    }
}

/// Solver parameters for a Table 4 level: the defaults, except that at level 5 a
/// non-positive minimum film is reported rather than refused (the paper's own level-5 film
/// is six times too thin: 64 x 64 points do not resolve this load).
pub fn params(level: u32) -> Params {
    Params {
        level,
        require_positive_film: level > 5,
        ..Params::default()
    }
}

/// Solves the case at each level; `observer` hears of every cycle.
pub fn compute(
    spec: &Table4Case,
    levels: &[u32],
    mut observer: impl FnMut(&Progress),
) -> Result<Vec<Row>, String> {
    let problem = Problem::from_case(&spec.case, &LubricantTable::table1())
        .map_err(|e| format!("cases/table4.toml: {e}"))?;
    let mut rows = Vec::new();
    for &level in levels {
        let t = std::time::Instant::now();
        let outcome = solve(&problem, &params(level), Some(&mut observer));
        rows.push(Row {
            level,
            outcome,
            seconds: t.elapsed().as_secs_f64(),
        });
    }
    Ok(rows)
}

/// CSV of the rows, with the paper's values beside ours.
pub fn to_csv(rows: &[Row]) -> String {
    use super::csv::{num, opt, table};
    let header = [
        "level",
        "points",
        "hc",
        "hc_moes",
        "h_min",
        "mu_bar_sliding",
        "paper_hc",
        "paper_mu_bar",
        "cycles",
        "residual",
        "seconds",
        "status",
    ];
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let n = 1u32 << (r.level + 1);
            let paper = r.paper();
            let (hc, hcm, hmin, mu, cycles, res, status) = match &r.outcome {
                Ok(s) => (
                    num(s.film.h_central),
                    num(s.film.hc_moes),
                    num(s.film.h_min),
                    num(s.friction.sliding),
                    s.info.cycles.to_string(),
                    num(s.info.residual()),
                    if s.film.h_min > 0.0 {
                        "ok"
                    } else {
                        "ok-film-nonpositive"
                    }
                    .to_string(),
                ),
                Err(e) => (
                    String::new(),
                    String::new(),
                    String::new(),
                    String::new(),
                    e.residual_history().len().to_string(),
                    opt(e.residual_history().last().copied()),
                    "failed".into(),
                ),
            };
            vec![
                r.level.to_string(),
                format!("{n}x{n}"),
                hc,
                hcm,
                hmin,
                mu,
                opt(paper.map(|p| p.0)),
                opt(paper.map(|p| p.1)),
                cycles,
                res,
                format!("{:.3}", r.seconds),
                status,
            ]
        })
        .collect();
    table(&header, &body)
}

/// A readable table with the paper's values side by side.
pub fn to_text(rows: &[Row]) -> String {
    let mut out = String::from(
        "Table 4: Appendix case (mineral oil A, 3 GPa, 40 C, 12 m/s, S = 0.5 %, tau0 = 4 MPa)\n",
    );
    out.push_str("level  points      Hc (ours)   Hc (paper)  mu-bar (ours)  mu-bar (paper)  cycles  time (s)\n");
    for r in rows {
        let n = 1u32 << (r.level + 1);
        let paper = r.paper();
        let ph = paper
            .map(|p| format!("{:.3e}", p.0))
            .unwrap_or_else(|| "-".into());
        let pm = paper
            .map(|p| format!("{:.2}", p.1))
            .unwrap_or_else(|| "-".into());
        match &r.outcome {
            Ok(s) => {
                let flag = if s.film.h_min > 0.0 {
                    ""
                } else {
                    "  (min film <= 0: grid too coarse)"
                };
                out.push_str(&format!(
                    "{:>5}  {:>9}  {:>11.4e}  {:>10}  {:>13.3}  {:>14}  {:>6}  {:>8.2}{}\n",
                    r.level,
                    format!("{n}x{n}"),
                    s.film.h_central,
                    ph,
                    s.friction.sliding,
                    pm,
                    s.info.cycles,
                    r.seconds,
                    flag
                ));
            }
            Err(e) => out.push_str(&format!(
                "{:>5}  {:>9}  failed: {e}\n",
                r.level,
                format!("{n}x{n}")
            )),
        }
    }
    out
}

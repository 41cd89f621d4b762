//! The study's files: `accuracy.csv` (every case at every level), `accuracy_levels.csv` (the
//! recommended level per target) and the summary `repro accuracy` prints.

use super::{AccuracyResult, Recommendation, MU_TOLERANCE};
use crate::pipeline::csv::{rows, Decimals};
use serde::Serialize;

/// A row of `figures/accuracy.csv`: one case at one level.
#[derive(Debug, Default, Serialize)]
struct LevelRow<'a> {
    case: &'a str,
    contact: &'a str,
    level: u32,
    points: &'a str,
    h_central: Option<f64>,
    h_central_grid: Option<f64>,
    mu_bar_sliding: Option<f64>,
    h_min: Option<f64>,
    reference: &'a str,
    h_central_ref: Option<f64>,
    mu_bar_ref: Option<f64>,
    h_min_ref: Option<f64>,
    h_central_error: Option<f64>,
    h_central_grid_error: Option<f64>,
    mu_bar_error: Option<f64>,
    h_min_error: Option<f64>,
    observed_order_h: Option<f64>,
    observed_order_mu: Option<f64>,
    order_used_h: Option<f64>,
    order_used_mu: Option<f64>,
    order_used_h_min: Option<f64>,
    /// Finest-level cycles, or the length of a failure's residual history.
    cycles: usize,
    seconds: Decimals<3>,
    status: String,
    domain_h_central_change: Option<f64>,
    domain_mu_bar_change: Option<f64>,
    domain_seconds: Option<Decimals<3>>,
}

/// `figures/accuracy.csv`: one row per case and level.
pub fn to_csv(studies: &[AccuracyResult]) -> String {
    let mut out = Vec::new();
    for s in studies {
        let domain = s.domain.as_ref().and_then(|d| d.change.as_ref().ok());
        let domain_seconds = s.domain.as_ref().map(|d| Decimals(d.seconds));
        let r = s.reference;
        let order = r.and_then(|r| r.order);
        let used = r.and_then(|r| r.order_used);
        for (run, points) in s.levels.iter().zip(&s.points) {
            let e = s.errors(run);
            let row = LevelRow {
                case: s.name,
                contact: s.kind,
                level: run.level,
                points,
                reference: r.map_or("", |r| r.kind),
                h_central_ref: r.map(|r| r.h_central),
                mu_bar_ref: r.map(|r| r.mu_bar),
                h_min_ref: r.and_then(|r| r.h_min),
                h_central_error: e.map(|e| e.0),
                h_central_grid_error: s.grid_film_error(run),
                mu_bar_error: e.map(|e| e.1),
                h_min_error: s.h_min_error(run),
                observed_order_h: order.map(|o| o.0),
                observed_order_mu: order.map(|o| o.1),
                order_used_h: used.map(|o| o.0),
                order_used_mu: used.map(|o| o.1),
                order_used_h_min: r.and_then(|r| r.order_used_h_min),
                seconds: Decimals(run.seconds),
                domain_h_central_change: domain.map(|d| d.0),
                domain_mu_bar_change: domain.map(|d| d.1),
                domain_seconds,
                ..LevelRow::default()
            };
            out.push(match &run.outcome {
                Ok(m) => LevelRow {
                    h_central: Some(m.h_central),
                    h_central_grid: Some(m.h_central_grid),
                    mu_bar_sliding: Some(m.mu_bar),
                    h_min: Some(m.h_min),
                    cycles: m.cycles,
                    status: "ok".to_string(),
                    ..row
                },
                Err(err) => LevelRow {
                    cycles: err.residual_history().len(),
                    // The message's first clause, its numbers included: a study that
                    // measures grids shows where a film collapsed.
                    status: format!(
                        "failed: {}",
                        err.to_string()
                            .split(':')
                            .next()
                            .unwrap_or("failed")
                            .replace(',', ";")
                    ),
                    ..row
                },
            });
        }
    }
    rows(out)
}

/// A row of `figures/accuracy_levels.csv`.
#[derive(Debug, Default, Serialize)]
struct RecommendationRow {
    target: &'static str,
    deciding_case: &'static str,
    level: Option<u32>,
    mu_bar_error: Option<f64>,
    seconds: Option<Decimals<3>>,
}

/// `figures/accuracy_levels.csv`: the recommended level per target.
pub fn recommendations_csv(recs: &[Recommendation]) -> String {
    rows(recs.iter().map(|r| RecommendationRow {
        target: r.target,
        deciding_case: r.case,
        level: r.level,
        mu_bar_error: r.mu_error,
        seconds: r.seconds.map(Decimals),
    }))
}

/// A readable summary.
pub fn to_text(studies: &[AccuracyResult], recs: &[Recommendation]) -> String {
    let mut out = String::new();
    for s in studies {
        out.push_str(&format!("{} ({}): {}\n", s.name, s.kind, s.description));
        let format_error = |e: Option<f64>| e.map(|e| format!("{e:.2e}")).unwrap_or_default();
        if let Some(r) = s.reference {
            out.push_str(&format!(
                "  reference ({}): Hc {:.5e}, mu-bar {:.5}{}{}\n",
                r.kind,
                r.h_central,
                r.mu_bar,
                r.h_min
                    .map(|h| format!(", Hmin {h:.5e}"))
                    .unwrap_or_default(),
                r.order
                    .map(|o| format!(", observed order Hc {:.2}, mu-bar {:.2}", o.0, o.1))
                    .unwrap_or_default()
                    + &r.order_used
                        .map(|o| format!(", extrapolated at order {:.2} and {:.2}", o.0, o.1))
                        .unwrap_or_default()
            ));
        }
        out.push_str(
            "  level  points     Hc           mu-bar     err Hc    (grid's)  err mu-bar  err Hmin  cycles  time (s)\n",
        );
        for (run, points) in s.levels.iter().zip(&s.points) {
            match &run.outcome {
                Ok(m) => {
                    let e = s.errors(run);
                    out.push_str(&format!(
                        "  {:>5}  {:<9}  {:<11.5e}  {:<9.4}  {:>8}  {:>8}  {:>10}  {:>8}  {:>6}  {:>8.3}\n",
                        run.level,
                        points,
                        m.h_central,
                        m.mu_bar,
                        format_error(e.map(|e| e.0)),
                        format_error(s.grid_film_error(run)),
                        format_error(e.map(|e| e.1)),
                        format_error(s.h_min_error(run)),
                        m.cycles,
                        run.seconds
                    ));
                }
                Err(e) => out.push_str(&format!(
                    "  {:>5}  failed after {:.3} s: {e}\n",
                    run.level, run.seconds
                )),
            }
        }
        if let Some(d) = &s.domain {
            out.push_str(&format!(
                "  domain: inlet and sides doubled at level {}'s mesh (level {}, {:.3} s): {}\n",
                d.level - 1,
                d.level,
                d.seconds,
                match &d.change {
                    Ok((h, mu)) => format!("Hc moves {:.2e}, mu-bar {:.2e}", h, mu),
                    Err(e) => format!("failed: {e}"),
                }
            ));
        }
    }
    out.push_str(&format!(
        "Cheapest level with sliding mu-bar within {} % (every finer level too):\n",
        100.0 * MU_TOLERANCE
    ));
    for r in recs {
        out.push_str(&format!(
            "  {:<6} level {} (decided by {}{})\n",
            r.target,
            r.level
                .map(|l| l.to_string())
                .unwrap_or_else(|| "none shown by the levels run".into()),
            r.case,
            r.mu_error
                .map(|e| format!(", error {:.2} %", 100.0 * e))
                .unwrap_or_default()
        ));
    }
    out
}

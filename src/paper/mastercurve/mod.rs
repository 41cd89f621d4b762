//! The `mastercurve` target (beyond the paper): every computed case of Figs. 3-7 and the line
//! contacts with `tau_c >= 100` on Eq. (13) and on the refined formula
//! ([`crate::paper::mastercurve::refined`]), fitted here on these cases and cross-validated figure by
//! figure. The cases are the figures' own (same level, so the cache serves them).
//!
//! Files: `mastercurve.csv` (one row per case: Eq. 13, flat film, refined, residuals),
//! `mastercurve-fit.csv` (the coefficients fitted on all cases, then on all but each figure
//! with that figure's cross-validated RMS), `mastercurve.svg`.

pub mod fit;
pub mod oracle;
pub mod picture;
pub mod refined;

use crate::paper::figures::line::solve_table3;
use crate::paper::figures::run_sweep;
use crate::paper::mastercurve::fit::{fit, mastercurve, FIT_TAU_C_MIN, PAPER_C};
use crate::paper::mastercurve::oracle::{line_flat, point_flat};
use crate::paper::mastercurve::refined::{
    band95, cross_validated, fit as fit_refined, rms_rel, Features, FigureCheck, Refined, Sample,
};
use crate::paper::target as registry_target;
use crate::physics::flat_film::alpha_e;
use crate::pipeline::context::{write, Built, Context, LINE_LEVEL};
use crate::pipeline::csv::{num, opt, table};
use crate::pipeline::run::RunProgress;
use crate::pipeline::sweep::shipped_sweep;
use picture::CasePoint;

/// The figures whose cases the formula is fitted on, with their sweeps.
pub(super) const FIGURES: [(&str, &str); 5] = [
    ("fig3", "fig1-3"),
    ("fig4", "fig4"),
    ("fig5", "fig5"),
    ("fig6", "fig6"),
    ("fig7", "fig7"),
];

/// One case of the fit, with what the CSV reports of it.
struct Row {
    sample: Sample,
    contact: &'static str,
    case: usize,
    tau_c: f64,
    m: f64,
    l: f64,
    alpha_e: f64,
    flat: f64,
}

fn collect(ctx: &Context) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for (figure, sweep_name) in FIGURES {
        let sweep = shipped_sweep(sweep_name).map_err(|e| e.to_string())?;
        let default_level = registry_target(figure).and_then(|t| t.default_level);
        let (runs, _) = run_sweep("mastercurve", &sweep, default_level, ctx)?;
        for (i, r) in runs.iter().enumerate() {
            let (Some(rec), tau_c) = (r.record(), r.problem.tau_c()) else {
                continue;
            };
            if tau_c < FIT_TAU_C_MIN {
                continue;
            }
            rows.push(Row {
                sample: Sample {
                    figure,
                    features: Features::point(&r.problem),
                    mu_bar: rec.mu_bar_sliding,
                },
                contact: "elliptical",
                case: i + 1,
                tau_c,
                m: r.problem.groups.m,
                l: r.problem.groups.l,
                alpha_e: alpha_e(&r.problem.viscosity),
                flat: point_flat(&r.problem, rec.h_central),
            });
        }
    }
    let progress = |p: RunProgress| (ctx.progress)("mastercurve", p);
    let line = solve_table3("mastercurve", LINE_LEVEL, ctx.store(), &progress, ctx.warn)?;
    for (i, r) in line.iter().enumerate() {
        let (Some(s), tau_c) = (r.outcome.record(), r.problem.tau_c()) else {
            continue;
        };
        if tau_c < FIT_TAU_C_MIN {
            continue;
        }
        rows.push(Row {
            sample: Sample {
                figure: "fig7",
                features: Features::line(&r.problem),
                mu_bar: s.mu_bar_sliding,
            },
            contact: "line",
            case: i + 1,
            tau_c,
            m: r.problem.groups.m,
            l: r.problem.groups.l,
            alpha_e: alpha_e(&r.problem.viscosity),
            flat: line_flat(&r.problem, s.h_central),
        });
    }
    Ok(rows)
}

fn cases_csv(rows: &[Row], all: Option<&Refined>, cv: &[Option<f64>]) -> String {
    let header = [
        "figure",
        "contact",
        "case",
        "tau_c",
        "m",
        "l",
        "alpha_e",
        "mu_bar_sliding",
        "mu_bar_eq13",
        "mu_bar_flat",
        "flat_nominal",
        "film_nominal",
        "ln_l",
        "mu_bar_refined",
        "mu_bar_refined_cv",
        "rel_dev_eq13",
        "rel_dev_flat",
        "rel_dev_refined_cv",
    ];
    let cells = rows.iter().zip(cv).map(|(r, cv)| {
        let f = &r.sample.features;
        let mu = r.sample.mu_bar;
        let eq13 = mastercurve(r.tau_c, PAPER_C);
        vec![
            r.sample.figure.to_string(),
            r.contact.to_string(),
            r.case.to_string(),
            num(r.tau_c),
            num(r.m),
            num(r.l),
            num(r.alpha_e),
            num(mu),
            num(eq13),
            num(r.flat),
            num(f.flat_nominal),
            num(f.film_nominal),
            num(f.ln_l),
            opt(all.map(|a| a.predict(f))),
            opt(*cv),
            num(mu / eq13 - 1.0),
            num(mu / r.flat - 1.0),
            opt(cv.map(|p| mu / p - 1.0)),
        ]
    });
    table(&header, cells)
}

fn fit_csv(
    all: Option<&Refined>,
    band: Option<f64>,
    held_out: &[(FigureCheck, Option<Refined>)],
) -> String {
    let header = [
        "fitted_on",
        "tested_on",
        "points_tested",
        "a",
        "b",
        "c",
        "d",
        "refined_rms_rel_dev",
        "band95",
    ];
    let coef = |r: Option<&Refined>| -> Vec<String> {
        (0..4).map(|i| opt(r.map(|r| r.coefficients[i]))).collect()
    };
    let mut rows = vec![[
        vec!["all".to_string(), String::new(), String::new()],
        coef(all),
        vec![String::new(), opt(band)],
    ]
    .concat()];
    for (c, r) in held_out {
        rows.push(
            [
                vec![
                    format!("all but {}", c.figure),
                    c.figure.to_string(),
                    c.points.to_string(),
                ],
                coef(r.as_ref()),
                vec![num(c.refined_rms_rel_dev), String::new()],
            ]
            .concat(),
        );
    }
    table(&header, rows)
}

/// Builds the target.
pub fn build(ctx: &Context) -> Result<Built, String> {
    let rows = collect(ctx)?;
    let samples: Vec<Sample> = rows.iter().map(|r| r.sample).collect();
    let all = fit_refined(&samples);
    let cv = cross_validated(&samples);
    let pairs = || cv.iter().copied().zip(samples.iter().map(|s| s.mu_bar));
    let band = band95(pairs());
    let held_out: Vec<(FigureCheck, Option<Refined>)> = FIGURES
        .iter()
        .filter_map(|(figure, _)| {
            let mine = || {
                cv.iter()
                    .zip(&samples)
                    .filter(|(_, s)| s.figure == *figure)
                    .map(|(p, s)| (*p, s.mu_bar))
            };
            let rms = rms_rel(mine())?;
            Some((
                FigureCheck {
                    figure,
                    points: mine().count(),
                    refined_rms_rel_dev: rms,
                },
                fit_refined(samples.iter().filter(|s| s.figure != *figure)),
            ))
        })
        .collect();
    let mut files = vec![
        write(ctx, "mastercurve.csv", &cases_csv(&rows, all.as_ref(), &cv))?,
        write(
            ctx,
            "mastercurve-fit.csv",
            &fit_csv(all.as_ref(), band, &held_out),
        )?,
    ];
    let points: Vec<CasePoint> = rows
        .iter()
        .zip(&cv)
        .map(|(r, cv)| CasePoint {
            series: match r.contact {
                "line" => "line contact".into(),
                _ => r.sample.figure.replace("fig", "Fig. "),
            },
            tau_c: r.tau_c,
            mu_bar: r.sample.mu_bar,
            refined_cv: *cv,
        })
        .collect();
    if !points.is_empty() {
        files.push(write(ctx, "mastercurve.svg", &picture::svg(&points)?)?);
    }
    let eq13 = fit(&rows
        .iter()
        .map(|r| (r.tau_c, r.sample.mu_bar))
        .collect::<Vec<_>>());
    let cv_text: Vec<String> = held_out
        .iter()
        .map(|(c, _)| format!("{} {:.1} %", c.figure, 100.0 * c.refined_rms_rel_dev))
        .collect();
    let ours = match (eq13, all) {
        (Some(e), Some(a)) => format!(
            "{} cases: Eq. (13) misses by {:.2} RMS in mu-bar units (largest {:.2}; {:.1} % RMS relative); the refined formula mu-bar = {:.4} G {:+.4} G H_n {:+.4} ln L {:+.4} misses, fitted without the figure tested, by {} RMS (95 % of cases within {:.1} %)",
            e.points,
            e.rms_abs_dev,
            e.max_abs_dev,
            100.0 * e.rms_rel_dev,
            a.coefficients[0],
            a.coefficients[1],
            a.coefficients[2],
            a.coefficients[3],
            cv_text.join(", "),
            100.0 * band.unwrap_or(f64::NAN),
        ),
        _ => format!("{} cases: too few to fit", rows.len()),
    };
    Ok(Built {
        name: "mastercurve",
        title: "Beyond the paper: Eq. (13) and a refined friction formula, cross-validated".into(),
        cases: rows.len(),
        solved: Some(rows.len()),
        cached: None,
        level: ctx.level,
        fit: eq13,
        fit_all: None,
        seconds: 0.0,
        files,
        paper_claim: "all sliding friction results follow one curve in tau_c, Eq. (13)".into(),
        ours,
        refined: held_out
            .into_iter()
            .map(|(c, _)| c)
            .chain(rms_rel(pairs()).map(|rms| FigureCheck {
                figure: "mastercurve",
                points: samples.len(),
                refined_rms_rel_dev: rms,
            }))
            .collect(),
    })
}

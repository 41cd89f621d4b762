//! The `lss` target (beyond the paper): the paper's first future-work item. The
//! Table 2 sweep of mineral oil A (Fig. 4's cases) solved again with a limiting shear stress
//! `tau_L = tau_L0 + Lambda p` at several `Lambda-bar = Lambda p_H / tau0` (each case at one
//! of them, rotating), with `tau_L0 = tau0`, sliding `mu-bar` against `tau_c`, and the form of the curve found
//! ([`crate::paper::lss::form`]): the second parameter is the saturated friction
//! `mu_S = Lambda-bar + 1.5 tau_L0 / tau0`, the fitted form joins the Eyring curve to it.
//!
//! Files: `lss.csv` (one row per case and `Lambda-bar`: the Eyring and limited friction, the
//! forms' predictions), `lss-fit.csv` (the fitted exponent and scatter of each form),
//! `lss.svg`.

pub mod form;

use crate::paper::eq13::{eq13_mu_bar, PAPER_C};
use crate::paper::figures::{run_sweep, study_jobs, write_provenance, FIG4};
use crate::paper::lss::form::{fit, saturated, FormFit, FormPoint};
use crate::paper::picture::{eq13_curve, MU_BAR, TAU_C};
use crate::paper::target::{Target, TargetReport};
use crate::physics::case::{Case, CaseForm};
use crate::physics::rheology::{LimitingShearStress, Rheology};
use crate::pipeline::context::Context;
use crate::pipeline::csv::rows;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::PointRun;
use crate::pipeline::job::Job;
use crate::pipeline::sweep::Sweep;
use crate::plot::{render_svg, Curve, Figure, Marker, Scale, Series};
use serde::Serialize;

/// The `Lambda-bar = Lambda p_H / tau0` of the target: a limit well below the Eyring
/// friction of most cases (5) up to one that binds only the largest `tau_c` (40; the Eyring
/// friction of Fig. 4 reaches about 45).
pub const LAMBDA_BARS: [f64; 4] = [5.0, 10.0, 20.0, 40.0];

/// `tau_L0 / tau0`: the limit at ambient pressure equal to the Eyring stress, a few MPa as
/// measured limits are, and large against the inlet's Couette stresses (about 1e-3 tau0),
/// where a limit far below them would make the perturbation conductances explode.
pub const TAU_L0_OVER_TAU0: f64 = 1.0;

/// The Eyring sweep: Fig. 4's, whose cache entries it shares.
const SWEEP: &str = FIG4.sweep.name;

/// Hertzian area over load of a circular contact: `A / W = pi / (2 pi / 3)`.
const HERTZ_AREA_OVER_LOAD: f64 = 1.5;

/// A case of the Eyring sweep with the limit of `lambda_bar` (`Lambda = Lambda-bar tau0 /
/// p_H`, `tau_L0 = TAU_L0_OVER_TAU0 tau0`). The sweep's cases are physical.
fn limited(case: &Case, lambda_bar: f64) -> Result<Case, PipelineError> {
    let CaseForm::Physical(p) = &case.spec else {
        return Err(PipelineError::Input(format!(
            "cases/{SWEEP}.toml: the lss target needs physical cases"
        )));
    };
    let mut out = case.clone();
    out.physics.rheology = Rheology::EyringLss(LimitingShearStress {
        lambda: lambda_bar * p.tau0_pa / p.ph_pa,
        tau_l0_pa: TAU_L0_OVER_TAU0 * p.tau0_pa,
    });
    Ok(out)
}

/// The Eyring cases the context runs (a sample of every `stride`-th at the snapshot profile,
/// as Fig. 4 takes them, so that they are Fig. 4's cache entries), as a sweep, with their
/// 1-based case numbers in `cases/fig4.toml`.
fn eyring_selection(ctx: &Context) -> Result<(Sweep, Vec<usize>), PipelineError> {
    let mut sweep = FIG4.sweep()?;
    let stride = ctx.stride_for(sweep.cases.len());
    let numbers: Vec<usize> = (0..sweep.cases.len())
        .step_by(stride)
        .map(|i| i + 1)
        .collect();
    sweep.cases = sweep.cases.into_iter().step_by(stride).collect();
    Ok((sweep, numbers))
}

/// Each case of the Eyring selection is solved at one `Lambda-bar`, rotating through
/// [`LAMBDA_BARS`] (every `Lambda-bar` takes every fourth case, staggered; 4 is prime to the
/// 3-valued axes of the grid, so each `Lambda-bar` spans every value of every axis): 243
/// limited solves at the working level, as many as Fig. 4, where the whole grid at every
/// `Lambda-bar` would take four times as long. At the snapshot profile only every second of
/// those: 31 limited solves on Fig. 4's sample of 61, whose Eyring solves `repro check` has
/// already made for Fig. 4 (76 s at level 5 measured while a level-7 run shared the two cores).
fn picked(i: usize, j: usize, ctx: &Context) -> bool {
    let k = LAMBDA_BARS.len();
    if ctx.stride > 1 {
        i % (2 * k) == 2 * j
    } else {
        i % k == j
    }
}

/// Per `Lambda-bar`, its cases of the Eyring selection with the limit ([`picked`]), and
/// which of the selection they are.
fn limited_sweeps(
    eyring: &Sweep,
    ctx: &Context,
) -> Result<Vec<(f64, Sweep, Vec<usize>)>, PipelineError> {
    LAMBDA_BARS
        .iter()
        .enumerate()
        .map(|(j, &lb)| {
            let picked: Vec<usize> = (0..eyring.cases.len())
                .filter(|&i| picked(i, j, ctx))
                .collect();
            let cases = picked
                .iter()
                .map(|&i| limited(&eyring.cases[i], lb))
                .collect::<Result<Vec<_>, _>>()?;
            let sweep = Sweep {
                title: format!("{}, Lambda-bar = {lb}", eyring.title),
                level: eyring.level,
                cases,
            };
            Ok((lb, sweep, picked))
        })
        .collect()
}

/// Fig. 4's level.
fn default_level() -> Option<u32> {
    Some(FIG4.level)
}

/// The context without sampling: the target samples its sweeps itself.
fn unsampled<'a>(ctx: &Context<'a>) -> Context<'a> {
    Context {
        stride: 1,
        ..ctx.clone()
    }
}

/// Every solve of the target in the context: the Eyring cases (Fig. 4's) and the limited ones.
fn jobs(ctx: &Context) -> Result<Vec<Job>, PipelineError> {
    let (eyring, _) = eyring_selection(ctx)?;
    let plain = unsampled(ctx);
    let mut all = study_jobs(&eyring, default_level(), &plain)?;
    for (_, s, _) in limited_sweeps(&eyring, ctx)? {
        all.extend(study_jobs(&s, default_level(), &plain)?);
    }
    Ok(all)
}

/// One limited case with its Eyring twin.
struct LimitedCase {
    lambda_bar: f64,
    case: usize,
    tau_c: f64,
    alpha_bar: f64,
    eyring: Option<f64>,
    limited: Option<f64>,
    /// Saturated friction `mu_S` of the Hertzian circle.
    mu_s: f64,
    status: String,
}

/// The rows of the limited runs, each `(Lambda-bar, runs, which of the Eyring selection)`,
/// with the Eyring runs and the selection's case numbers.
fn pair_with_eyring(
    eyring: &[PointRun],
    numbers: &[usize],
    limited: &[(f64, Vec<PointRun>, Vec<usize>)],
) -> Vec<LimitedCase> {
    let mut rows = Vec::new();
    for (lb, runs, picked) in limited {
        for (l, &i) in runs.iter().zip(picked) {
            let e = &eyring[i];
            let mu_s = l
                .problem
                .shear
                .friction_bound(HERTZ_AREA_OVER_LOAD)
                .unwrap_or(f64::NAN);
            let status = l.outcome.status();
            rows.push(LimitedCase {
                lambda_bar: *lb,
                case: numbers[i],
                tau_c: l.problem.tau_c(),
                alpha_bar: l.problem.groups.alpha_bar,
                eyring: e.solved().map(|r| r.mu_bar_sliding),
                limited: l.solved().map(|r| r.mu_bar_sliding),
                mu_s,
                status,
            });
        }
    }
    rows
}

/// The points of a form: `mu_E` from Eq. (13) (`own: false`) or the case's Eyring solve.
fn points(rows: &[LimitedCase], own: bool) -> Vec<FormPoint> {
    rows.iter()
        .filter_map(|r| {
            let mu_e = if own {
                r.eyring?
            } else {
                eq13_mu_bar(r.tau_c, PAPER_C)
            };
            Some(FormPoint {
                mu_e,
                mu_s: r.mu_s,
                mu_bar: r.limited?,
            })
        })
        .collect()
}

/// A row of `lss.csv`: one limited case beside its Eyring twin and the forms' predictions.
#[derive(Debug, Default, Serialize)]
struct LssRow<'a> {
    lambda_bar: f64,
    tau_l0_over_tau0: f64,
    case: usize,
    tau_c: f64,
    alpha_bar: f64,
    mu_bar_eyring: Option<f64>,
    mu_bar_sliding: Option<f64>,
    mu_bar_saturated: f64,
    mu_bar_eq13: f64,
    mu_bar_form_eq13: Option<f64>,
    mu_bar_form_own: Option<f64>,
    status: &'a str,
}

fn cases_csv(
    cases: &[LimitedCase],
    form_eq13: Option<FormFit>,
    form_own: Option<FormFit>,
) -> String {
    rows(cases.iter().map(|r| {
        let eq13 = eq13_mu_bar(r.tau_c, PAPER_C);
        LssRow {
            lambda_bar: r.lambda_bar,
            tau_l0_over_tau0: TAU_L0_OVER_TAU0,
            case: r.case,
            tau_c: r.tau_c,
            alpha_bar: r.alpha_bar,
            mu_bar_eyring: r.eyring,
            mu_bar_sliding: r.limited,
            mu_bar_saturated: r.mu_s,
            mu_bar_eq13: eq13,
            mu_bar_form_eq13: form_eq13.map(|f| saturated(eq13, r.mu_s, f.n)),
            mu_bar_form_own: form_own.and_then(|f| r.eyring.map(|e| saturated(e, r.mu_s, f.n))),
            status: &r.status,
        }
    }))
}

/// A row of `lss-fit.csv`: a form's fitted exponent and scatter.
#[derive(Debug, Default, Serialize)]
struct FormFitRow<'a> {
    mu_e: &'a str,
    points: Option<usize>,
    n: Option<f64>,
    rms_abs_dev: Option<f64>,
    max_abs_dev: Option<f64>,
    rms_rel_dev: Option<f64>,
}

fn fit_csv(forms: &[(&str, Option<FormFit>)]) -> String {
    rows(forms.iter().map(|(name, f)| FormFitRow {
        mu_e: name,
        points: f.map(|f| f.points),
        n: f.map(|f| f.n),
        rms_abs_dev: f.map(|f| f.rms_abs_dev),
        max_abs_dev: f.map(|f| f.max_abs_dev),
        rms_rel_dev: f.map(|f| f.rms_rel_dev),
    }))
}

/// `lss.svg`: every limited case against `tau_c`, one series per `Lambda-bar`, with the
/// Eq. (13)-based form of each (solid) and Eq. (13) itself (dashed).
fn svg(rows: &[LimitedCase], form: Option<FormFit>) -> Result<Option<String>, PipelineError> {
    let (lo, hi) = rows
        .iter()
        .filter(|r| r.limited.is_some())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r.tau_c), b.max(r.tau_c))
        });
    if !(lo.is_finite() && hi > lo) {
        return Ok(None);
    }
    let mut series = Vec::new();
    let mut curves = Vec::new();
    for (k, lb) in LAMBDA_BARS.iter().enumerate() {
        let mine: Vec<&LimitedCase> = rows.iter().filter(|r| r.lambda_bar == *lb).collect();
        series.push(Series {
            label: format!("Λ\u{304} = {lb}"),
            points: mine
                .iter()
                .filter_map(|r| r.limited.map(|m| (r.tau_c, m)))
                .collect(),
            marker: Marker::nth(k),
            ..Series::default()
        });
        if let (Some(f), Some(r)) = (form, mine.first()) {
            let steps = 200;
            curves.push(Curve {
                label: format!("form, n = {:.2}, {MU_BAR}_S = {:.1}", f.n, r.mu_s),
                points: (0..=steps)
                    .map(|i| {
                        let t = (lo.ln() + (hi.ln() - lo.ln()) * i as f64 / steps as f64).exp();
                        (t, saturated(eq13_mu_bar(t, PAPER_C), r.mu_s, f.n))
                    })
                    .collect(),
                dashed: false,
            });
        }
    }
    curves.push(eq13_curve(lo, hi, PAPER_C, 200));
    let figure = Figure {
        title: "Beyond the paper: mineral oil A (Table 2) with a limiting shear stress".into(),
        x_label: format!("characteristic shear stress {TAU_C}"),
        y_label: format!("sliding reduced friction {MU_BAR}"),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        series,
        curves,
        ..Figure::default()
    };
    render_svg(&figure)
        .map(Some)
        .map_err(|e| PipelineError::plot("lss.svg", e))
}

/// The `lss` target.
pub struct Lss;

impl Target for Lss {
    fn name(&self) -> &'static str {
        "lss"
    }

    fn describe(&self) -> &'static str {
        "Beyond the paper: Fig. 4's cases with a limiting shear stress at Lambda-bar 5-40, and the form of their curve"
    }

    fn jobs(&self, ctx: &Context) -> Result<Vec<Job>, PipelineError> {
        jobs(ctx)
    }

    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        build(ctx)
    }
}

fn build(ctx: &Context) -> Result<TargetReport, PipelineError> {
    let (eyring_sweep, numbers) = eyring_selection(ctx)?;
    let plain = unsampled(ctx);
    let (eyring, level) = run_sweep("lss", &eyring_sweep, default_level(), &plain)?;
    // Every limit's cases in one run (one pool, one progress), split back by limit.
    let sweeps = limited_sweeps(&eyring_sweep, ctx)?;
    let together = Sweep {
        title: format!("{}, with a limiting shear stress", eyring_sweep.title),
        level: eyring_sweep.level,
        cases: sweeps
            .iter()
            .flat_map(|(_, s, _)| s.cases.clone())
            .collect(),
    };
    let (limited_runs, _) = run_sweep("lss", &together, default_level(), &plain)?;
    let mut rest = limited_runs.as_slice();
    let mut limited = Vec::new();
    for (lb, s, picked) in sweeps {
        let (mine, after) = rest.split_at(s.cases.len());
        limited.push((lb, mine.to_vec(), picked));
        rest = after;
    }
    let rows = pair_with_eyring(&eyring, &numbers, &limited);
    let form_eq13 = fit(&points(&rows, false));
    let form_own = fit(&points(&rows, true));
    let mut files = vec![
        ctx.write("lss.csv", &cases_csv(&rows, form_eq13, form_own))?,
        ctx.write(
            "lss-fit.csv",
            &fit_csv(&[("eq13", form_eq13), ("own_eyring", form_own)]),
        )?,
    ];
    if let Some(svg) = svg(&rows, form_eq13)? {
        files.push(ctx.write("lss.svg", &svg)?);
    }
    let solved = rows.iter().filter(|r| r.limited.is_some()).count();
    let runs = eyring.iter().chain(limited.iter().flat_map(|(_, r, _)| r));
    let cached = runs.clone().filter(|r| r.cached).count();
    let describe = |f: Option<FormFit>| {
        f.map_or("too few points".to_string(), |f| {
            format!(
                "n = {:.2}, RMS {:.2} (largest {:.2}) in mu-bar units, {:.1} % RMS relative",
                f.n,
                f.rms_abs_dev,
                f.max_abs_dev,
                100.0 * f.rms_rel_dev
            )
        })
    };
    let ours = format!(
        "{solved} of {} limited cases solved (Lambda-bar {:?}, tau_L0 = tau0): one curve in tau_c no longer; with the second parameter mu_S = Lambda-bar + 1.5 tau_L0/tau0, mu-bar = mu_E (1 + (mu_E/mu_S)^n)^(-1/n): mu_E = Eq. (13): {}; mu_E = the case's own Eyring friction: {}",
        rows.len(),
        LAMBDA_BARS,
        describe(form_eq13),
        describe(form_own),
    );
    let mut report = TargetReport {
        solved: Some(solved + eyring.iter().filter(|r| r.solved().is_some()).count()),
        cached: Some(cached),
        level: Some(level),
        paper_claim: "future work (Conclusions): with a limiting shear stress one may expect a single curve, of a different form".into(),
        ours,
        ..TargetReport::emitted(
            "lss",
            "Beyond the paper: friction with a limiting shear stress, and the form of its curve",
            rows.len() + eyring.len(),
            files,
        )
    };
    report.count_levels(runs.filter_map(|r| r.solved().map(|s| s.level)));
    // lss.csv's rows are the limited runs in order (their Eyring twins are Fig. 4's rows).
    write_provenance("lss", &mut report, &limited_runs, None, ctx)?;
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::Problem;
    use crate::physics::lubricant::LubricantTable;
    use crate::physics::rheology::ShearLaw;
    use crate::pipeline::keys::case_key;
    use crate::solver::point::Params;

    #[test]
    fn limited_cases_carry_their_lambda_bar_and_their_own_cache_keys() {
        let sweep = FIG4.sweep().unwrap();
        let lubs = LubricantTable::table1();
        let params = Params::at_level(5);
        let eyring = &sweep.cases[100];
        let mut keys = vec![case_key(eyring, &params, None)];
        for lb in LAMBDA_BARS {
            let case = limited(eyring, lb).unwrap();
            let problem = Problem::from_case(&case, &lubs).unwrap();
            match problem.shear {
                ShearLaw::EyringLss {
                    tau_l0_bar,
                    lambda_bar,
                } => {
                    // Lambda = Lambda-bar tau0 / p_H and back: two roundings.
                    assert!((lambda_bar / lb - 1.0).abs() < 1e-14, "{lambda_bar}");
                    assert!((tau_l0_bar - TAU_L0_OVER_TAU0).abs() < 1e-15);
                }
                other => panic!("{other:?}"),
            }
            keys.push(case_key(&case, &params, None));
        }
        let mut unique = keys.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(
            unique.len(),
            keys.len(),
            "every limit has its own cache entry"
        );
    }
}

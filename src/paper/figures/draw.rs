//! A sweep drawn as a figure: its cases run through the cache, its CSV and picture written,
//! its points measured against Eq. (13) ([`sweep_figure`]), as the paper's figures and a
//! user's study alike describe it ([`Drawing`]).

use super::plot::{FrictionAxis, Plot, SeriesBy};
use super::run::{run_sweep, selection};
use super::{picture, rows};
use crate::paper::eq13::{Fit, FIT_TAU_C_MIN};
use crate::paper::target::{eq13_regime_fit, Measure, TargetReport};
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::{run_cases_in, PointRun, RunProgress};
use crate::pipeline::job::Setup;
use crate::pipeline::outcome::CaseOutcome;
use crate::pipeline::sweep::Sweep;
use crate::plot::{Marker, Scale, Series};

/// How a sweep is drawn: a figure of the paper ([`super::SweepFigure::drawing`]) or a user's
/// study ([`super::study`]).
pub struct Drawing<'a> {
    /// The target's name, the stem of its files.
    pub stem: &'a str,
    /// Its name in the picture's title and the report.
    pub heading: &'a str,
    /// What it plots.
    pub plot: Plot,
    /// How its cases split into series.
    pub series: SeriesBy,
    /// Its level where neither the context nor the sweep sets one.
    pub default_level: Option<u32>,
    /// Series drawn and measured against Eq. (13) with its cases (Fig. 7's line contacts).
    pub fitted: Vec<Series>,
    /// Also solve the cases in the paper's setup and draw them, every case, as a series of
    /// their own ([`super::SweepFigure::paper_setup`]), with their own Eq. (13) statistics.
    pub paper_setup: bool,
    /// The friction axis's scale ([`super::SweepFigure::friction_scale`]).
    pub friction_scale: Scale,
}

/// The cases of `paper` (the paper's setup: `P = 0` on its domain, Eq. (8) over it) as one
/// series, every solved case with its error bar, and how many of them differ from the rule's
/// solve of the same case (`runs`, in the same order) by more than the larger of the two
/// error bars (or, where neither is estimated, by more than 1 %).
fn paper_setup_series(runs: &[PointRun], paper: &[PointRun], plot: Plot) -> (Series, usize) {
    let mut series = Series {
        label: "paper's setup (P = 0 on its domain)".into(),
        marker: Marker::Cross,
        ..Series::default()
    };
    let mut differ = 0;
    for (r, p) in runs.iter().zip(paper) {
        let Some((x, y_paper)) = plot.xy(p) else {
            continue;
        };
        let bar = |run: &PointRun| run.solved().and_then(|s| plot.y_error(s));
        series.points.push((x, y_paper));
        series.y_errors.push(bar(p).unwrap_or(0.0));
        if let Some((_, y)) = plot.xy(r) {
            let allowed = match (bar(r), bar(p)) {
                (Some(a), Some(b)) => a.max(b),
                (a, b) => a.or(b).unwrap_or(0.01 * y.abs()),
            };
            differ += usize::from((y_paper - y).abs() > allowed);
        }
    }
    (series, differ)
}

/// Eq. (13)'s statistics of `points` in a few words for a figure's note.
fn eq13_words(points: &[(f64, f64)]) -> String {
    let in_range: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|p| p.0 >= FIT_TAU_C_MIN)
        .collect();
    match crate::paper::eq13::fit(&in_range) {
        Some(f) => format!(
            "off Eq. (13) by {:.2} RMS, {:.2} at most (μ̄ units, τ̄_{{c}} ≥ {FIT_TAU_C_MIN})",
            f.rms_abs_dev, f.max_abs_dev
        ),
        None => "not measured against Eq. (13)".into(),
    }
}

/// Runs `sweep` at the context's level (else the sweep's, else the drawing's), writes
/// `<stem>.csv` and `<stem>.svg` (titled after its heading), measures the points against
/// Eq. (13) where its x is `tau_c`.
pub fn sweep_figure(
    drawing: &Drawing,
    sweep: &Sweep,
    ctx: &Context,
) -> Result<(TargetReport, Vec<PointRun>), PipelineError> {
    let Drawing {
        stem,
        heading,
        plot,
        default_level,
        ..
    } = *drawing;
    let (runs, level) = run_sweep(stem, sweep, default_level, ctx)?;
    let extra = &drawing.fitted;
    for (i, r) in runs.iter().enumerate() {
        if let CaseOutcome::Failed(f) = &r.outcome {
            (ctx.warn)(format!(
                "{stem}: case {} (M {:.4}, L {:.4}, S-bar {:.3e}) failed: {}",
                i + 1,
                r.problem.groups.m,
                r.problem.groups.l,
                r.problem.groups.s_bar,
                f.error
            ));
        }
    }
    let csv = ctx.write(&format!("{stem}.csv"), &rows::csv(&runs, plot))?;
    let points: Vec<(f64, f64)> = runs
        .iter()
        .filter_map(|r| plot.xy(r).map(|p| (r.problem.tau_c(), p.1)))
        .chain(extra.iter().flat_map(|e| e.points.iter().copied()))
        .collect();
    let mut measures = if plot.on_eq13() {
        Measure::eq13(&points)
    } else {
        Vec::new()
    };
    measures.extend(plot.error_summary(&runs).map(Measure::DiscretisationError));
    measures.push(Measure::levels_ended(
        runs.iter().filter_map(|r| r.solved().map(|s| s.level)),
    ));
    let mut files = vec![csv];
    let mut drawn = extra.clone();
    let mut note = None;
    if drawing.paper_setup {
        let (cases, _) = selection(sweep, default_level, ctx);
        let progress = |p: RunProgress| (ctx.progress)(&format!("{stem}-paper-setup"), p);
        let paper = run_cases_in(
            stem,
            (&cases, level, Setup::Paper),
            ctx.cache_policy(),
            &progress,
            ctx.warn,
            ctx.stop,
        )?;
        files.push(ctx.write(&format!("{stem}-paper-setup.csv"), &rows::csv(&paper, plot))?);
        let paper_points: Vec<(f64, f64)> = paper
            .iter()
            .filter_map(|r| plot.xy(r).map(|p| (r.problem.tau_c(), p.1)))
            .collect();
        if plot.on_eq13() {
            measures.extend(eq13_regime_fit(&paper_points).map(Measure::PaperSetupEq13));
        }
        let (series, differ) = paper_setup_series(&runs, &paper, plot);
        note = Some(format!(
            "flooded contact (the rule's far field): {}; paper's setup (P = 0 on the paper's \
             domain, Eq. (8) over it): {}; {differ} of {} cases differ by more than the error bar",
            eq13_words(&points),
            eq13_words(&series.points),
            series.points.len()
        ));
        drawn.push(series);
    }
    if let Some(svg) = picture::svg(
        stem,
        &format!("{heading} — {}", sweep.title),
        &runs,
        (plot, drawing.series, drawing.friction_scale),
        (&drawn, note),
    )? {
        files.push(ctx.write(&format!("{stem}.svg"), &svg)?);
    }
    let solved = runs.iter().filter(|r| r.solved().is_some()).count();
    let cached = runs.iter().filter(|r| r.cached).count();
    let report = TargetReport {
        measures,
        ..TargetReport::emitted(
            stem,
            &format!("{heading}: {}", sweep.title),
            runs.len(),
            files,
        )
    };
    let eq13 = report.eq13().copied();
    // Where the points are measured against Eq. (13), the report's table of the claim
    // states the result; `ours` says what the measures do not.
    let ours = match eq13 {
        Some(_) => String::new(),
        None => format!("{solved} of {} cases solved", runs.len()),
    };
    let report = TargetReport {
        solved: Some(solved),
        cached: Some(cached),
        level: Some(level),
        headline: eq13.as_ref().map(Fit::describe),
        ours,
        ..report
    };
    Ok((report, runs))
}

/// Fig. 1's collapse: the scatter of the plotted `mu-bar` (`y`; total for Fig. 1) ordered by
/// the paper's `S-bar^(1/4) M L^3` against the exponents of `S-bar^a M L^c` that collapse our
/// points best.
pub fn severity_summary(runs: &[PointRun], y: FrictionAxis) -> String {
    let cases: Vec<(f64, f64, f64, f64)> = runs
        .iter()
        .filter_map(|r| {
            let g = &r.problem.groups;
            r.solved().map(|rec| (g.s_bar, g.m, g.l, y.of(rec)))
        })
        .collect();
    let mut paper: Vec<(f64, f64)> = cases
        .iter()
        .map(|&(s, m, l, mu)| (0.25 * s.ln() + m.ln() + 3.0 * l.ln(), mu))
        .collect();
    let paper_scatter = crate::paper::eq13::scatter(&mut paper);
    match crate::paper::eq13::severity_exponents(&cases) {
        Some((a, c, best)) => format!(
            "; scatter about one curve (0 = a curve, 2 = random) {paper_scatter:.3} with the paper's S-bar^(1/4) M L^3, {best:.3} with the best exponents S-bar^{a:.2} M L^{c:.1}"
        ),
        None => String::new(),
    }
}

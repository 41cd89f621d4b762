//! The sweep figures, Figs. 1-7, and a user's own sweep (`repro run`): the sweep's cases run
//! through the cache, the per-case CSV ([`rows`]) and the picture ([`picture`]), the points
//! measured against Eq. (13). Fig. 7 adds the line contacts of Table 3 ([`line`]).

pub mod line;
pub mod picture;
pub mod rows;

use crate::paper::artefact::{
    Artefact, ErrorSummary, Measure, Spread, TargetReport, LINE_LEVEL, WORKING_LEVEL,
};
use crate::paper::cases::shipped_sweep;
use crate::paper::mastercurve::fit::{Fit, FIT_TAU_C_MIN};
use crate::physics::case::Case;
use crate::pipeline::executor::{run_cases, run_cases_in, PointRun, RunProgress};
use crate::pipeline::job::{point_jobs, point_jobs_in, Job, Setup};
use crate::pipeline::keys::LINE_SOLVER_REVISION;
use crate::pipeline::outcome::{CaseOutcome, Output, SolvedCase};
use crate::pipeline::provenance::{Provenance, SUFFIX};
use crate::pipeline::sweep::Sweep;
use crate::pipeline::{context::Context, error::PipelineError};
use crate::plot::{Marker, Series};
use crate::solver::point::SOLVER_REVISION;
use line::LineRun;

/// What a sweep figure plots.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plot {
    /// The quantity on the y axis: total (sliding plus rolling) instead of sliding reduced
    /// friction.
    pub total: bool,
    /// x is `S-bar^(1/4) M L^3` (Fig. 1) instead of `tau_c`.
    pub severity: bool,
}

impl Plot {
    /// Sliding `mu-bar` against `tau_c`: Figs. 3-7 and a user's study.
    pub const SLIDING: Plot = Plot {
        total: false,
        severity: false,
    };

    /// The x and y of a case on the figure (`None` where it failed).
    pub fn xy(self, run: &PointRun) -> Option<(f64, f64)> {
        let solved = run.solved()?;
        let g = &run.problem.groups;
        let x = if self.severity {
            g.s_bar.powf(0.25) * g.m * g.l.powi(3)
        } else {
            run.problem.tau_c()
        };
        let y = if self.total {
            solved.mu_bar_total()
        } else {
            solved.mu_bar_sliding
        };
        Some((x, y))
    }

    /// The discretisation error over `runs` (each case numbered from 1, as in the CSV) of
    /// the central and minimum film and the friction it plots; `None` when no case carries
    /// an estimate.
    pub fn error_summary(self, runs: &[PointRun]) -> Option<ErrorSummary> {
        let spread = |output: Output| {
            Spread::of(
                runs.iter()
                    .enumerate()
                    .filter_map(|(i, r)| Some((i + 1, r.solved()?.relative_error(output)?)))
                    .collect(),
            )
        };
        let mu = if self.total {
            Output::MuBarTotal
        } else {
            Output::MuBarSliding
        };
        let estimated = runs
            .iter()
            .filter(|r| r.solved().is_some_and(|s| s.errors.is_some()))
            .count();
        (estimated > 0).then(|| ErrorSummary {
            estimated,
            h_central: spread(Output::HCentral),
            h_min: spread(Output::HMin),
            mu_bar: spread(mu),
        })
    }

    /// The absolute discretisation error of the `y` it plots for a solved case (`None` where
    /// not estimated).
    pub fn y_error(self, solved: &SolvedCase) -> Option<f64> {
        let output = if self.total {
            Output::MuBarTotal
        } else {
            Output::MuBarSliding
        };
        solved.estimate(output).map(|e| e.error)
    }
}

/// The claim of the figures of sliding friction.
const SLIDING_CLAIM: &str = "sliding mu-bar follows Eq. (13): mu-bar = asinh(tau_c / 5)";

/// A figure of a shipped sweep: Figs. 1-7.
#[derive(Debug, Clone, Copy)]
pub struct SweepFigure {
    /// Target name, `fig1` ...
    pub name: &'static str,
    /// One line for `repro list`.
    pub description: &'static str,
    /// The shipped sweep it draws (`cases/<sweep>.toml`).
    pub sweep: &'static str,
    /// What it plots.
    pub plot: Plot,
    /// Level without `--level` ([`Artefact::default_level`]).
    pub level: u32,
    /// The paper's claim, for the report.
    pub claim: &'static str,
    /// Adds the line contacts of Table 3 (Fig. 7).
    pub line_contacts: bool,
    /// Draws beside its cases the paper's setup ([`Setup::Paper`]) where it differs from the
    /// rule's by more than the error bar (Fig. 6).
    pub paper_setup: bool,
}

/// Fig. 1: total friction against the paper's severity group.
pub const FIG1: SweepFigure = SweepFigure {
    name: "fig1",
    description:
        "Total mu-bar vs S-bar^(1/4) M L^3, Barus-incompressible circular contact (125 cases)",
    sweep: "fig1-3",
    plot: Plot {
        total: true,
        severity: true,
    },
    level: 6,
    claim: "friction collapses on one curve for S-bar^(1/4) M L^3 >= 1e4, scattered below",
    line_contacts: false,
    paper_setup: false,
};

/// Fig. 2: total friction against `tau_c`.
pub const FIG2: SweepFigure = SweepFigure {
    name: "fig2",
    description: "Total mu-bar vs tau_c, same sweep, Eq. (13) dashed",
    plot: Plot {
        total: true,
        severity: false,
    },
    claim: "total mu-bar follows Eq. (13), c = 5, except a cluster at low tau_c where rolling friction dominates",
    ..FIG1
};

/// Fig. 3: sliding friction against `tau_c`, Figs. 1-2's sweep.
pub const FIG3: SweepFigure = SweepFigure {
    name: "fig3",
    description: "Sliding mu-bar vs tau_c, same sweep, Eq. (13) dashed",
    plot: Plot::SLIDING,
    claim: SLIDING_CLAIM,
    ..FIG1
};

/// Fig. 4: mineral oil A over Table 2.
pub const FIG4: SweepFigure = SweepFigure {
    name: "fig4",
    description: "Sliding mu-bar vs tau_c, mineral oil A, Roelands + Dowson-Higginson, Table 2 grid (243 cases)",
    sweep: "fig4",
    ..FIG3
};

/// Fig. 5: the traction fluid over Table 2.
pub const FIG5: SweepFigure = SweepFigure {
    name: "fig5",
    description: "Sliding mu-bar vs tau_c, traction fluid, Table 2 grid (243 cases)",
    sweep: "fig5",
    ..FIG3
};

/// Fig. 6: 5P4E over Table 2.
pub const FIG6: SweepFigure = SweepFigure {
    name: "fig6",
    description: "Sliding mu-bar vs tau_c, 5P4E, Table 2 grid (243 cases)",
    sweep: "fig6",
    paper_setup: true,
    ..FIG3
};

/// Fig. 7: the ellipses and line contacts of Table 3.
pub const FIG7: SweepFigure = SweepFigure {
    name: "fig7",
    description: "Sliding mu-bar vs tau_c, mineral oil A, Rx/Ry = 1/2, 1/5 and the line contact at the Table 3 cases",
    sweep: "fig7",
    level: 7,
    line_contacts: true,
    ..FIG3
};

impl SweepFigure {
    /// Its shipped sweep.
    pub fn sweep(&self) -> Result<Sweep, PipelineError> {
        Ok(shipped_sweep(self.sweep)?)
    }

    /// Runs its sweep's cases of the context (see [`run_sweep`]); `label` names the run in
    /// progress and errors.
    pub fn run(&self, label: &str, ctx: &Context) -> Result<(Vec<PointRun>, u32), PipelineError> {
        run_sweep(label, &self.sweep()?, Some(self.level), ctx)
    }
}

impl Artefact for SweepFigure {
    fn name(&self) -> &'static str {
        self.name
    }

    fn describe(&self) -> &'static str {
        self.description
    }

    fn default_level(&self) -> Option<u32> {
        Some(self.level)
    }

    /// Its sweep's cases, and for Fig. 7 the line contacts.
    fn jobs(&self, ctx: &Context) -> Result<Vec<Job>, PipelineError> {
        let sweep = self.sweep()?;
        let mut jobs = study_jobs(&sweep, Some(self.level), ctx)?;
        if self.paper_setup {
            let (cases, level) = selection(&sweep, Some(self.level), ctx);
            jobs.extend(
                point_jobs_in(&cases, level, Setup::Paper)?
                    .into_iter()
                    .map(|p| p.job),
            );
        }
        if self.line_contacts {
            jobs.extend(
                line::table3_jobs(LINE_LEVEL)?
                    .into_iter()
                    .map(|(j, _, _)| j),
            );
        }
        Ok(jobs)
    }

    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        let name = self.name;
        let sweep = self.sweep()?;
        // Fig. 7 adds the Table 3 line contacts, solved by the 1-D solver at its level.
        let (line, extra) = if self.line_contacts {
            let progress = |p: RunProgress| (ctx.progress)("fig7-line", p);
            let runs =
                line::solve_table3(name, LINE_LEVEL, ctx.cache_policy(), &progress, ctx.warn)?;
            let series = Series {
                label: "line contact".into(),
                points: line::line_points(&runs),
                y_errors: line::line_errors(&runs),
                marker: Marker::Cross,
                ..Series::default()
            };
            (Some(runs), vec![series])
        } else {
            (None, Vec::new())
        };
        let heading = name.replace("fig", "Fig. ");
        let beside = Beside {
            fitted: extra,
            paper_setup: self.paper_setup,
        };
        let (mut report, runs) = sweep_figure(
            name,
            &heading,
            &sweep,
            self.plot,
            Some(self.level),
            ctx,
            &beside,
        )?;
        if let Some(line) = &line {
            let csv = line::line_csv(line, LINE_LEVEL);
            report.files.push(ctx.write("fig7-line.csv", &csv)?);
            report.cases += line.len();
            let solved = line.iter().filter(|r| r.outcome.solved().is_some()).count();
            report.solved = report.solved.map(|s| s + solved);
            let cached = line.iter().filter(|r| r.cached).count();
            report.cached = report.cached.map(|c| c + cached);
        }
        write_provenance(name, &mut report, &runs, line.as_deref(), ctx)?;
        report.name = name;
        report.paper_claim = self.claim.to_string();
        if self.plot.severity {
            report.ours.push_str(&severity_summary(&runs));
            report.headline = Some(report.ours.clone());
        }
        Ok(report)
    }
}

/// The cases of a sweep that a context runs (a sample of the large sweeps at the snapshot
/// profile) and their level: the context's, else the sweep's own, else the target's
/// `default_level`, else the working level.
fn selection(sweep: &Sweep, default_level: Option<u32>, ctx: &Context) -> (Vec<Case>, u32) {
    let level = ctx
        .level
        .or(sweep.level)
        .or(default_level)
        .unwrap_or(WORKING_LEVEL);
    let stride = ctx.stride_for(sweep.cases.len());
    let cases: Vec<_> = sweep.cases.iter().step_by(stride).cloned().collect();
    (cases, level)
}

/// Runs a sweep's cases of the context (see [`selection`]) through the cache.
pub fn run_sweep(
    label: &str,
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<(Vec<PointRun>, u32), PipelineError> {
    let (cases, level) = selection(sweep, default_level, ctx);
    let progress = |p: RunProgress| (ctx.progress)(label, p);
    let runs = run_cases(
        label,
        &cases,
        level,
        ctx.cache_policy(),
        &progress,
        ctx.warn,
    )?;
    Ok((runs, level))
}

/// Every solve of a sweep in the context (a study of `repro run`, or a figure's sweep).
pub fn study_jobs(
    sweep: &Sweep,
    default_level: Option<u32>,
    ctx: &Context,
) -> Result<Vec<Job>, PipelineError> {
    let (cases, level) = selection(sweep, default_level, ctx);
    Ok(point_jobs(&cases, level)?
        .into_iter()
        .map(|p| p.job)
        .collect())
}

/// The sidecar of a sweep figure: its point cases (and Fig. 7's line contacts).
fn provenance(
    stem: &str,
    report: &TargetReport,
    runs: &[PointRun],
    line: Option<&[LineRun]>,
) -> Provenance {
    let files: Vec<String> = report
        .files
        .iter()
        .filter(|f| !f.ends_with(SUFFIX))
        .cloned()
        .collect();
    let mut p = Provenance::new(stem, &files);
    p.solver_revision = Some(SOLVER_REVISION.to_string());
    p.level = report.level;
    if report.level.is_some() {
        // The rule's parameters differ from case to case (the domain): each distinct set once,
        // in the order of the rows that first use it.
        for run in runs {
            let params = format!("{:?}", run.params);
            if !p.params.contains(&params) {
                p.params.push(params);
            }
        }
    }
    p.add_rows(
        &format!("{stem}.csv"),
        runs.iter().map(|r| (r.key.as_str(), r.stamp.as_ref())),
    );
    if let Some(line) = line {
        p.line_solver_revision = Some(LINE_SOLVER_REVISION.to_string());
        p.params.push(format!(
            "{:?}",
            crate::solver::line::Params::at_level(LINE_LEVEL)
        ));
        p.add_rows(
            "fig7-line.csv",
            line.iter().map(|r| (r.key.as_str(), r.stamp.as_ref())),
        );
    }
    p
}

/// Writes the sidecar of a sweep figure and lists it among the report files.
pub(crate) fn write_provenance(
    stem: &str,
    report: &mut TargetReport,
    runs: &[PointRun],
    line: Option<&[LineRun]>,
    ctx: &Context,
) -> Result<(), PipelineError> {
    let text = provenance(stem, report, runs, line).to_json();
    report
        .files
        .push(ctx.write(&format!("{stem}{SUFFIX}"), &text)?);
    Ok(())
}

/// Fig. 1's collapse: the scatter of total `mu-bar` ordered by the paper's `S-bar^(1/4) M L^3`
/// against the exponents of `S-bar^a M L^c` that collapse our points best.
fn severity_summary(runs: &[PointRun]) -> String {
    let cases: Vec<(f64, f64, f64, f64)> = runs
        .iter()
        .filter_map(|r| {
            let g = &r.problem.groups;
            r.solved()
                .map(|rec| (g.s_bar, g.m, g.l, rec.mu_bar_total()))
        })
        .collect();
    let mut paper: Vec<(f64, f64)> = cases
        .iter()
        .map(|&(s, m, l, mu)| (0.25 * s.ln() + m.ln() + 3.0 * l.ln(), mu))
        .collect();
    let paper_scatter = crate::paper::mastercurve::fit::scatter(&mut paper);
    match crate::paper::mastercurve::fit::severity_exponents(&cases) {
        Some((a, c, best)) => format!(
            "; scatter about one curve (0 = a curve, 2 = random) {paper_scatter:.3} with the paper's S-bar^(1/4) M L^3, {best:.3} with the best exponents S-bar^{a:.2} M L^{c:.1}"
        ),
        None => String::new(),
    }
}

/// A user's own sweep (`repro run`), drawn and fitted as Figs. 3-7: sliding `mu-bar` against
/// `tau_c`, files named after `stem`.
pub fn study(stem: &str, sweep: &Sweep, ctx: &Context) -> Result<TargetReport, PipelineError> {
    let beside = Beside {
        fitted: Vec::new(),
        paper_setup: false,
    };
    let (mut report, runs) = sweep_figure(stem, stem, sweep, Plot::SLIDING, None, ctx, &beside)?;
    write_provenance(stem, &mut report, &runs, None, ctx)?;
    report.paper_claim = SLIDING_CLAIM.into();
    Ok(report)
}

/// Series a sweep figure draws beside its own cases.
struct Beside {
    /// Drawn and measured against Eq. (13) with them (Fig. 7's line contacts).
    fitted: Vec<Series>,
    /// Also solve the cases in the paper's setup and draw them where they differ
    /// ([`SweepFigure::paper_setup`]); not measured.
    paper_setup: bool,
}

/// The cases of `paper` (the paper's setup) whose plotted friction differs from the rule's
/// solve of the same case (`runs`, in the same order) by more than its error bar (or, where
/// not estimated, by more than 1 %), as one series, and how many they are.
fn paper_setup_series(runs: &[PointRun], paper: &[PointRun], plot: Plot) -> (Series, usize) {
    let points: Vec<(f64, f64)> = runs
        .iter()
        .zip(paper)
        .filter_map(|(r, p)| {
            let (x, y) = plot.xy(r)?;
            let (_, y_paper) = plot.xy(p)?;
            let bar = r
                .solved()
                .and_then(|s| plot.y_error(s))
                .unwrap_or(0.01 * y.abs());
            ((y_paper - y).abs() > bar).then_some((x, y_paper))
        })
        .collect();
    let shown = points.len();
    let series = Series {
        label: "paper's setup (P = 0, its domain)".into(),
        points,
        marker: Marker::Circle,
        ..Series::default()
    };
    (series, shown)
}

/// Runs `sweep` at the context's level (else the sweep's, else `default_level`), writes
/// `<stem>.csv` and `<stem>.svg` (titled after `heading`), measures the points against
/// Eq. (13).
fn sweep_figure(
    stem: &str,
    heading: &str,
    sweep: &Sweep,
    plot: Plot,
    default_level: Option<u32>,
    ctx: &Context,
    beside: &Beside,
) -> Result<(TargetReport, Vec<PointRun>), PipelineError> {
    let (runs, level) = run_sweep(stem, sweep, default_level, ctx)?;
    let extra = &beside.fitted;
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
    let mut measures = if plot.severity {
        Vec::new()
    } else {
        Measure::eq13(&points)
    };
    measures.extend(plot.error_summary(&runs).map(Measure::DiscretisationError));
    let mut files = vec![csv];
    let mut drawn = extra.clone();
    let mut note = None;
    if beside.paper_setup {
        let (cases, _) = selection(sweep, default_level, ctx);
        let progress = |p: RunProgress| (ctx.progress)(&format!("{stem}-paper-setup"), p);
        let paper = run_cases_in(
            stem,
            (&cases, level, Setup::Paper),
            ctx.cache_policy(),
            &progress,
            ctx.warn,
        )?;
        files.push(ctx.write(&format!("{stem}-paper-setup.csv"), &rows::csv(&paper, plot))?);
        let (series, shown) = paper_setup_series(&runs, &paper, plot);
        note = Some(format!(
            "\"paper's setup\": P = 0 on the paper's domain, Eq. (8) over it, for the {shown} \
             cases where it differs from the flooded contact by more than the error bar"
        ));
        drawn.push(series);
    }
    if let Some(svg) = picture::svg(
        stem,
        &format!("{heading} — {}", sweep.title),
        &runs,
        plot,
        (&drawn, note),
    )? {
        files.push(ctx.write(&format!("{stem}.svg"), &svg)?);
    }
    let solved = runs.iter().filter(|r| r.solved().is_some()).count();
    let cached = runs.iter().filter(|r| r.cached).count();
    let report = TargetReport {
        measures,
        ..TargetReport::emitted(
            "study",
            &format!("{heading}: {}", sweep.title),
            runs.len(),
            files,
        )
    };
    let eq13 = report.eq13().copied();
    let ours = match eq13 {
        Some(f) => format!(
            "{} points with tau_c >= {FIT_TAU_C_MIN}: {}; c = {:.2} over all {solved} solved",
            f.points,
            f.describe(),
            report.eq13_c_all().unwrap_or(f64::NAN),
        ),
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

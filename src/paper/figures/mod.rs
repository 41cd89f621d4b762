//! The sweep figures, Figs. 1-7, and a user's own sweep (`repro run`): each figure described
//! by data ([`spec`]: its sweep file, what it plots, how its series split), the sweep's cases
//! run through the cache and drawn ([`draw`]: the per-case CSV of [`rows`], the picture of
//! [`picture`]), the points measured against Eq. (13). Fig. 7 adds the line contacts of
//! Table 3 ([`line`]). Both CSVs say what each case's error estimate read ([`estimate`]).

pub mod draw;
pub mod estimate;
pub mod line;
pub mod picture;
pub mod plot;
pub mod rows;
pub mod run;
pub mod sidecar;
pub mod spec;

use crate::paper::target::{ShippedSweep, Target, TargetReport, LINE_LEVEL};
use crate::pipeline::executor::{PointRun, RunProgress};
use crate::pipeline::job::{point_jobs_in, Job, Setup};
use crate::pipeline::sweep::Sweep;
use crate::pipeline::{context::Context, error::PipelineError};
use crate::plot::{Marker, Series};
use draw::{severity_summary, sweep_figure, Drawing};
pub use plot::{Abscissa, FrictionAxis, Plot, SeriesBy};
use run::selection;
pub use run::{run_sweep, study_jobs};
pub(crate) use sidecar::write_provenance;
pub use spec::{SweepFigure, FIG1, FIG2, FIG3, FIG4, FIG5, FIG6, FIG7, SLIDING_CLAIM};

impl SweepFigure {
    /// Its shipped sweep.
    pub fn sweep(&self) -> Result<Sweep, PipelineError> {
        Ok(self.sweep.parse()?)
    }

    /// Runs its sweep's cases of the context (see [`run_sweep`]); `label` names the run in
    /// progress and errors.
    pub fn run(&self, label: &str, ctx: &Context) -> Result<(Vec<PointRun>, u32), PipelineError> {
        run_sweep(label, &self.sweep()?, Some(self.level), ctx)
    }

    /// How it is drawn, with `fitted` series beside its cases.
    fn drawing(&self, fitted: Vec<Series>) -> Drawing<'static> {
        Drawing {
            stem: self.name,
            heading: self.heading,
            plot: self.plot,
            series: self.series,
            default_level: Some(self.level),
            fitted,
            paper_setup: self.paper_setup,
            friction_scale: self.friction_scale,
        }
    }
}

impl Target for SweepFigure {
    fn name(&self) -> &'static str {
        self.name
    }

    fn describe(&self) -> &'static str {
        self.description
    }

    fn default_level(&self) -> Option<u32> {
        Some(self.level)
    }

    fn sweep_file(&self) -> Option<ShippedSweep> {
        Some(self.sweep)
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
                    .map(|(j, _)| j.job),
            );
        }
        Ok(jobs)
    }

    fn build(&self, ctx: &Context) -> Result<TargetReport, PipelineError> {
        let name = self.name;
        let sweep = self.sweep()?;
        // Fig. 7 adds the Table 3 line contacts, solved by the 1-D solver at its level.
        let (line, extra) = if self.line_contacts {
            let progress = |p: RunProgress| (ctx.progress)(&format!("{name}-line"), p);
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
        let (mut report, runs) = sweep_figure(&self.drawing(extra), &sweep, ctx)?;
        if let Some(line) = &line {
            let csv = line::line_csv(line, LINE_LEVEL);
            report
                .files
                .push(ctx.write(&format!("{name}-line.csv"), &csv)?);
            report.cases += line.len();
            let solved = line.iter().filter(|r| r.outcome.solved().is_some()).count();
            report.solved = report.solved.map(|s| s + solved);
            let cached = line.iter().filter(|r| r.cached).count();
            report.cached = report.cached.map(|c| c + cached);
            report.count_levels(
                line.iter()
                    .filter_map(|r| r.outcome.solved().map(|s| s.level)),
            );
        }
        write_provenance(name, &mut report, &runs, line.as_deref(), ctx)?;
        report.paper_claim = self.claim.to_string();
        if self.plot.x == Abscissa::Severity {
            report.ours.push_str(&severity_summary(&runs, self.plot.y));
            report.headline = Some(report.ours.clone());
        }
        Ok(report)
    }
}

/// A user's own sweep (`repro run`), drawn and fitted as Figs. 3-7 (sliding `mu-bar` against
/// `tau_c`, a series per lubricant temperature), its target and files named after `stem`.
pub fn study(stem: &str, sweep: &Sweep, ctx: &Context) -> Result<TargetReport, PipelineError> {
    let drawing = Drawing {
        stem,
        heading: stem,
        plot: Plot::SLIDING,
        series: SeriesBy::Temperature,
        default_level: None,
        fitted: Vec::new(),
        paper_setup: false,
        friction_scale: crate::plot::Scale::Linear,
    };
    let (mut report, runs) = sweep_figure(&drawing, sweep, ctx)?;
    write_provenance(stem, &mut report, &runs, None, ctx)?;
    report.paper_claim = SLIDING_CLAIM.into();
    Ok(report)
}

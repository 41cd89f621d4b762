//! The provenance sidecar of a sweep figure (`<stem>.provenance.json`): the cache key and
//! stamp of every row of its CSVs, and the solver parameters they were solved with.

use super::line::LineRun;
use crate::paper::target::TargetReport;
use crate::pipeline::context::Context;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::PointRun;
use crate::pipeline::keys::LINE_SOLVER_REVISION;
use crate::pipeline::provenance::{Provenance, SUFFIX};
use crate::solver::point::SOLVER_REVISION;

/// The sidecar of a sweep figure: its point cases (and Fig. 7's line contacts, `<stem>-line.csv`).
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
            p.add_params(&run.params);
        }
    }
    p.add_rows(
        &format!("{stem}.csv"),
        runs.iter().map(|r| (r.key.as_str(), r.stamp.as_ref())),
    );
    if let Some(line) = line {
        p.line_solver_revision = Some(LINE_SOLVER_REVISION.to_string());
        for run in line {
            p.add_params(&run.params);
        }
        p.add_rows(
            &format!("{stem}-line.csv"),
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

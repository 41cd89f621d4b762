//! The pictures of the computed figures, in the paper's form: Figs. 1-3 on log-log axes,
//! Figs. 4-7 `mu-bar` against `tau_c` on log-linear axes, Eq. (13) dashed from Fig. 2 on. Series are split
//! as the figure says ([`SeriesBy`]) so that the collapse (or not) is visible.

use super::plot::{Plot, SeriesBy};
use crate::paper::eq13::PAPER_C;
use crate::paper::picture::eq13_curve;
use crate::pipeline::error::PipelineError;
use crate::pipeline::executor::PointRun;
use crate::plot::{render_svg, Figure, Marker, Scale, Series};

const MARKERS: [Marker; 5] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
    Marker::Cross,
];

/// Renders figure `name` with `title` from its runs, each solved case's point as `plot` draws
/// it with its discretisation error as an error bar, in series split by `series_by`, and
/// `extra` series (the line contacts of Fig. 7, the paper's setup beside Fig. 6) drawn after
/// them, with their note.
pub fn svg(
    name: &str,
    title: &str,
    runs: &[PointRun],
    (plot, series_by, y_scale): (Plot, SeriesBy, Scale),
    (extra, beside_note): (&[Series], Option<String>),
) -> Result<Option<String>, PipelineError> {
    let mut keys: Vec<String> = Vec::new();
    let mut series: Vec<Series> = Vec::new();
    for r in runs {
        let Some(p) = plot.xy(r) else { continue };
        let key = series_by.key(&r.case, &r.problem);
        let i = match keys.iter().position(|k| *k == key) {
            Some(i) => i,
            None => {
                keys.push(key.clone());
                series.push(Series {
                    label: key,
                    points: Vec::new(),
                    marker: MARKERS[(keys.len() - 1) % MARKERS.len()],
                    ..Series::default()
                });
                keys.len() - 1
            }
        };
        series[i].points.push(p);
        let error = r.solved().and_then(|s| plot.y_error(s));
        series[i].y_errors.push(error.unwrap_or(0.0));
    }
    for e in extra {
        series.push(Series {
            marker: MARKERS[series.len() % MARKERS.len()],
            ..e.clone()
        });
    }
    let failed = runs.iter().filter(|r| r.solved().is_none()).count();
    let xs: Vec<f64> = series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .filter(|x| *x > 0.0 && x.is_finite())
        .collect();
    let (x_min, x_max) = xs
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
            (a.min(x), b.max(x))
        });
    let curves = if plot.on_eq13() && !xs.is_empty() {
        vec![eq13_curve(x_min, x_max, PAPER_C, 200)]
    } else {
        Vec::new()
    };
    let (x_label, y_label) = plot.labels();
    let failed_note = (failed > 0).then(|| {
        format!(
            "{failed} of {} cases failed (not converged or film collapse); not shown",
            runs.len()
        )
    });
    let notes: Vec<String> = failed_note.into_iter().chain(beside_note).collect();
    let note = (!notes.is_empty()).then(|| notes.join("; "));
    let fig = Figure {
        title: title.to_string(),
        x_label: x_label.into(),
        y_label: y_label.into(),
        x_scale: Scale::Log,
        y_scale,
        x_range: None,
        y_range: None,
        series,
        curves,
        note,
    };
    render_svg(&fig)
        .map(Some)
        .map_err(|e| PipelineError::plot(format!("{name}.svg"), e))
}

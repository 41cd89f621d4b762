//! Fig. 8: measured friction, transformed to `(tau_c, mu-bar)`, on Eq. (13), one series per
//! dataset series; with no dataset, the curve alone over the range of Figs. 4-8 and a note
//! saying how to add one.

use crate::paper::eq13::PAPER_C;
use crate::paper::fig8::reader::ReducedRow;
use crate::paper::picture::{eq13_curve, MU_BAR, TAU_C};
use crate::pipeline::error::PipelineError;
use crate::plot::{render_svg, Curve, Figure, Marker, Scale, Series};

/// `fig8.svg`: the measured points and Eq. (13) dashed, with the fitted `c` solid when given.
pub fn svg(rows: &[ReducedRow], fitted: Option<f64>) -> Result<String, PipelineError> {
    let mut series: Vec<Series> = Vec::new();
    for r in rows {
        let p = (r.reduced.characteristic.tau_c, r.reduced.mu_bar);
        match series.iter_mut().find(|s| s.label == r.row.series) {
            Some(s) => s.points.push(p),
            None => series.push(Series {
                label: r.row.series.clone(),
                points: vec![p],
                marker: Marker::nth(series.len()),
                ..Series::default()
            }),
        }
    }
    let xs: Vec<f64> = rows
        .iter()
        .map(|r| r.reduced.characteristic.tau_c)
        .filter(|x| *x > 0.0 && x.is_finite())
        .collect();
    let (x_min, x_max) = if xs.is_empty() {
        // The range of the paper's Figs. 4-8, for the curve alone.
        (1.0, 1e4)
    } else {
        xs.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            })
    };
    let mut curves = vec![Curve {
        label: format!("Eq. (13): {} = asinh({}/5)", MU_BAR, TAU_C),
        ..eq13_curve(x_min, x_max, PAPER_C, 200)
    }];
    if let Some(c) = fitted {
        curves.push(Curve {
            dashed: false,
            ..eq13_curve(x_min, x_max, c, 200)
        });
    }
    let fig = Figure {
        title: "Fig. 8 — measured friction on the mastercurve (Sec. IV)".into(),
        x_label: format!("characteristic shear stress {}", TAU_C),
        y_label: format!("measured reduced friction {}", MU_BAR),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        x_range: xs.is_empty().then_some((x_min, x_max)),
        y_range: xs.is_empty().then_some((0.0, 9.0)),
        series,
        curves,
        note: rows.is_empty().then(|| {
            "No measured dataset included: add CSV files to cases/fig8/ (docs/measured-data.md)"
                .to_string()
        }),
    };
    render_svg(&fig).map_err(|e| PipelineError::plot("fig8.svg", e))
}

//! The `mastercurve` target's picture: every computed case of Figs. 3-7 on Eq. (13), against
//! the refined formula, and the residuals of both against `tau_c` below, three figures stacked
//! in one SVG (each a nested `<svg>` at its offset, so each keeps its own coordinates).

use crate::paper::eq13::PAPER_C;
use crate::paper::picture::{eq13_curve, MU_BAR, TAU_C};
use crate::pipeline::error::PipelineError;
use crate::plot::{render_svg, Curve, Figure, Marker, Scale, Series, HEIGHT, WIDTH};

/// One case on the picture.
#[derive(Debug, Clone)]
pub struct CasePoint {
    /// Series label (its figure, or "line contact").
    pub series: String,
    /// `tau_c`.
    pub tau_c: f64,
    /// The solver's sliding `mu-bar`.
    pub mu_bar: f64,
    /// The refined formula's cross-validated `mu-bar`.
    pub refined_cv: Option<f64>,
}

fn by_series(points: &[CasePoint], xy: impl Fn(&CasePoint) -> Option<(f64, f64)>) -> Vec<Series> {
    let mut series: Vec<Series> = Vec::new();
    for p in points {
        let Some(v) = xy(p) else { continue };
        match series.iter_mut().find(|s| s.label == p.series) {
            Some(s) => s.points.push(v),
            None => series.push(Series {
                label: p.series.clone(),
                points: vec![v],
                marker: Marker::nth(series.len()),
                ..Series::default()
            }),
        }
    }
    series
}

/// Stacks rendered SVG documents of [`WIDTH`] x [`HEIGHT`] vertically into one document.
fn stack(svgs: &[String]) -> String {
    let height = HEIGHT as usize * svgs.len();
    let mut out = format!(
        "<svg width=\"{WIDTH}\" height=\"{height}\" viewBox=\"0 0 {WIDTH} {height}\" xmlns=\"http://www.w3.org/2000/svg\">\n"
    );
    for (i, s) in svgs.iter().enumerate() {
        // Replace the root element's opening tag by a nested one placed at its offset.
        let body = s.find('>').map_or(s.as_str(), |e| &s[e + 1..]);
        out.push_str(&format!(
            "<svg y=\"{}\" width=\"{WIDTH}\" height=\"{HEIGHT}\" viewBox=\"0 0 {WIDTH} {HEIGHT}\">",
            i * HEIGHT as usize
        ));
        out.push_str(body.trim_end());
        out.push('\n');
    }
    out.push_str("</svg>\n");
    out
}

/// The smallest and largest of `values`.
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    })
}

/// `mastercurve.svg`.
pub fn svg(points: &[CasePoint]) -> Result<String, PipelineError> {
    let (x_min, x_max) = range(points.iter().map(|p| p.tau_c));
    let on_eq13 = Figure {
        title: "Every computed case of Figs. 3-7 (tau_c >= 100) on Eq. (13)".into(),
        x_label: format!("characteristic shear stress {TAU_C}"),
        y_label: format!("sliding reduced friction {MU_BAR}"),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        series: by_series(points, |p| Some((p.tau_c, p.mu_bar))),
        curves: vec![eq13_curve(x_min, x_max, PAPER_C, 200)],
        ..Figure::default()
    };
    let (r_min, r_max) = range(
        points
            .iter()
            .filter_map(|p| p.refined_cv)
            .chain(points.iter().map(|p| p.mu_bar)),
    );
    let on_refined = Figure {
        title: "The same cases against the refined formula (cross-validated)".into(),
        x_label: format!("refined formula {MU_BAR}, fitted without the case's figure"),
        y_label: format!("computed {MU_BAR}"),
        series: by_series(points, |p| p.refined_cv.map(|r| (r, p.mu_bar))),
        curves: vec![Curve {
            label: "computed = refined".into(),
            points: vec![(r_min, r_min), (r_max, r_max)],
            dashed: true,
        }],
        ..Figure::default()
    };
    let pct = |model: f64, mu: f64| 100.0 * (mu / model - 1.0);
    let residuals = Figure {
        title: "Residuals: Eq. (13) and the refined formula".into(),
        x_label: format!("characteristic shear stress {TAU_C}"),
        y_label: "computed / formula - 1 (%)".into(),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        series: vec![
            Series {
                label: "Eq. (13)".into(),
                points: points
                    .iter()
                    .map(|p| (p.tau_c, pct((p.tau_c / PAPER_C).asinh(), p.mu_bar)))
                    .collect(),
                marker: Marker::Circle,
                ..Series::default()
            },
            Series {
                label: "refined, cross-validated".into(),
                points: points
                    .iter()
                    .filter_map(|p| p.refined_cv.map(|r| (p.tau_c, pct(r, p.mu_bar))))
                    .collect(),
                marker: Marker::Cross,
                ..Series::default()
            },
        ],
        curves: vec![Curve {
            label: "0".into(),
            points: vec![(x_min, 0.0), (x_max, 0.0)],
            dashed: true,
        }],
        ..Figure::default()
    };
    let svgs = [on_eq13, on_refined, residuals]
        .iter()
        .map(render_svg)
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| PipelineError::plot("mastercurve.svg", e))?;
    Ok(stack(&svgs))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panels_stack_into_one_document() {
        let pts: Vec<CasePoint> = (0..6)
            .map(|i| CasePoint {
                series: if i < 3 { "fig4" } else { "fig5" }.into(),
                tau_c: 10f64.powi(3 + i),
                mu_bar: 5.0 + i as f64,
                refined_cv: Some(5.1 + i as f64),
            })
            .collect();
        let s = svg(&pts).unwrap();
        assert_eq!(s.matches("<svg").count(), 4, "one root, three panels");
        assert_eq!(s.matches("</svg>").count(), 4);
        assert!(s.contains("<svg y=\"1200\""));
        assert!(s.contains("fig5") && s.contains("refined, cross-validated"));
    }
}

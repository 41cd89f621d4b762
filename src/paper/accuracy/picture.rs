//! `accuracy.svg` of `repro accuracy`: what accuracy costs, the error of each level against
//! its wall time.

use crate::paper::accuracy::AccuracyResult;
use crate::paper::picture::MU_BAR;
use crate::pipeline::error::PipelineError;
use crate::plot::{render_svg, Figure, Marker, Scale, Series};

/// `figures/accuracy.svg`: the `mu-bar` error of each level against its wall time, log-log,
/// one line per case through its levels, each marker labelled with its level. A level whose error is zero (the finest, when it is its own reference)
/// cannot be drawn on a log axis and is counted in the figure's note by the plot module.
pub fn svg(studies: &[AccuracyResult]) -> Result<String, PipelineError> {
    let series = studies
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let (points, point_labels) = s
                .levels
                .iter()
                .filter_map(|r| Some(((r.seconds, s.errors(r)?.1), format!("L{}", r.level))))
                .unzip();
            Series {
                // Point contacts by name alone (most are), the others with their kind: a short
                // label keeps the legend in columns below the chart where it cannot sit inside.
                label: if s.kind == "point" {
                    s.name.to_string()
                } else {
                    format!("{} ({} contact)", s.name, s.kind)
                },
                points,
                marker: Marker::of_series(i),
                joined: true,
                point_labels,
                y_errors: Vec::new(),
            }
        })
        .collect();
    let fig = Figure {
        title: "What accuracy costs: each case through its levels (L5 = level 5)".into(),
        x_label: "wall time of one solve (s)".into(),
        y_label: format!("error of sliding {MU_BAR} vs Richardson extrapolation"),
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        x_range: None,
        y_range: None,
        series,
        curves: Vec::new(),
        note: None,
    };
    render_svg(&fig).map_err(|e| PipelineError::plot("accuracy.svg", e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::accuracy::tests::{run, study};
    use crate::solver::output::SolveError;

    #[test]
    fn a_failed_level_is_left_out_of_the_picture() {
        let mut levels = vec![run(4, 1.0, 40.0), run(5, 1.0, 41.0), run(6, 1.0, 41.2)];
        levels[0].outcome = Err(SolveError::InvalidParams("x".into()));
        let svg = svg(&[study(levels)]).unwrap();
        assert!(svg.starts_with("<svg"));
        // Levels 5 and 6 are drawn against their Richardson extrapolation, with the legend's
        // sample, joined by one line and labelled; the failed level 4 has no error to draw.
        assert_eq!(svg.matches("<circle").count(), 2 + 1);
        let labelled = |l: &str| svg.lines().any(|line| line.trim() == l);
        assert!(labelled("L5") && labelled("L6") && !labelled("L4"));
        // The joining line, in the first series' colour (the axes' lines are black).
        assert_eq!(
            svg.matches(r##"<polyline fill="none" opacity="1" stroke="#0072B2""##)
                .count(),
            1
        );
    }
}

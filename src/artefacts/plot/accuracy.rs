//! `accuracy.svg` of `repro accuracy`: what accuracy costs, the error of each level against
//! its wall time.

use super::{render_svg, Figure, Marker, Scale, Series, MU_BAR};
use crate::artefacts::accuracy::CaseStudy;

/// `figures/accuracy.svg`: the `mu-bar` error of each level against its wall time, log-log,
/// one series per case. A level whose error is zero (the finest, when it is its own reference)
/// cannot be drawn on a log axis and is counted in the figure's note by the plot module.
pub fn svg(studies: &[CaseStudy]) -> Result<String, String> {
    let series = studies
        .iter()
        .enumerate()
        .map(|(i, s)| Series {
            label: format!("{} ({} contact)", s.name, s.kind),
            points: s
                .levels
                .iter()
                .filter_map(|r| s.errors(r).map(|e| (r.seconds, e.1)))
                .collect(),
            marker: Marker::nth(i),
        })
        .collect();
    let fig = Figure {
        title: "What accuracy costs: one marker per level, finer to the right".into(),
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
    render_svg(&fig).map_err(|e| format!("accuracy.svg: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::artefacts::accuracy::tests::{run, study};
    use crate::solver::output::SolveError;

    #[test]
    fn a_failed_level_is_left_out_of_the_picture() {
        let mut levels = vec![run(4, 1.0, 40.0), run(5, 1.0, 41.0), run(6, 1.0, 41.2)];
        levels[0].outcome = Err(SolveError::InvalidParams("x".into()));
        let svg = svg(&[study(levels)]).unwrap();
        assert!(svg.starts_with("<svg"));
        // Levels 5 and 6 are drawn against their Richardson extrapolation, with the legend's
        // sample; the failed level 4 has no error to draw.
        assert_eq!(svg.matches("<circle").count(), 2 + 1);
    }
}

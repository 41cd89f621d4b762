//! `accuracy.svg` of `repro accuracy`: what accuracy costs, the error of each level against
//! its wall time.

use crate::paper::accuracy::{AccuracyResult, LevelOutputs, LevelRun};
use crate::paper::picture::MU_BAR;
use crate::pipeline::error::PipelineError;
use crate::plot::{render_svg, Figure, Marker, Scale, Series};

/// One quantity of the study drawn against wall time.
#[derive(Clone, Copy)]
enum Drawn {
    /// Sliding `mu-bar`.
    Friction,
    /// The central film as the rule reports it.
    Film,
    /// The grid's own central film (a case whose film the rule tau-extrapolates).
    GridFilm,
    /// The minimum film as the solve reports it (a top refined across's, where added).
    MinFilm,
}

/// The series of `s` (the `i`-th series of its picture) for `drawn`: its levels' errors
/// against their wall times, joined and labelled by the level each solve ended on (`L7y`: level
/// 7 with the top refined across the rolling direction). Left out, so that no label lies over
/// another (`accuracy.csv` has them): a solve the rule refined to a level the series also
/// solves from (the two end on one grid), and a design's solve that is its case's at the same
/// level (the rule from level 8 where it neither refines nor adds a top). `studies` holds the
/// case a design is measured against.
fn series(s: &AccuracyResult, studies: &[AccuracyResult], i: usize, drawn: Drawn) -> Series {
    let asked: Vec<u32> = s.levels.iter().map(|r| r.level).collect();
    let twin = s.twin.and_then(|n| studies.iter().find(|t| t.name == n));
    let the_twins = |r: &LevelRun, m: &LevelOutputs| {
        twin.is_some_and(|t| {
            t.levels
                .iter()
                .any(|u| u.level == r.level && u.outcome.as_ref().ok() == Some(m))
        })
    };
    let (points, point_labels) = s
        .levels
        .iter()
        .filter_map(|r| {
            let m = r.outcome.as_ref().ok()?;
            if (m.level != r.level && asked.contains(&m.level)) || the_twins(r, m) {
                return None;
            }
            let error = match drawn {
                Drawn::Friction => s.errors(r)?.1,
                Drawn::Film => s.errors(r)?.0,
                Drawn::GridFilm => s.grid_film_error(r)?,
                Drawn::MinFilm => s.h_min_error(r)?,
            };
            let across = if m.across { "y" } else { "" };
            Some(((r.seconds, error), format!("L{}{across}", m.level)))
        })
        .unzip();
    // Point contacts by name alone (most are), the others with their kind: a short label
    // keeps the legend in columns below the chart where it cannot sit inside.
    let name = if s.kind == "point" {
        s.name.to_string()
    } else {
        format!("{} ({} contact)", s.name, s.kind)
    };
    Series {
        label: match drawn {
            Drawn::GridFilm => format!("{name}, the grid's film"),
            Drawn::Friction | Drawn::Film | Drawn::MinFilm => name,
        },
        points,
        marker: Marker::of_series(i),
        joined: true,
        point_labels,
        y_errors: Vec::new(),
    }
}

/// The picture of `series` against wall time, log-log, with the error's name `y_label`.
fn picture(title: &str, y_label: String, series: Vec<Series>) -> Figure {
    Figure {
        title: title.into(),
        x_label: "wall time of one solve (s)".into(),
        y_label,
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        x_range: None,
        y_range: None,
        series,
        curves: Vec::new(),
        note: None,
    }
}

/// `figures/accuracy.svg`: the `mu-bar` error of each level against its wall time, log-log,
/// one line per case through its levels, each marker labelled with its level. A level whose
/// error is zero (the finest, when it is its own reference) cannot be drawn on a log axis and
/// is counted in the figure's note by the plot module.
pub fn svg(studies: &[AccuracyResult]) -> Result<String, PipelineError> {
    let series = studies
        .iter()
        .enumerate()
        .map(|(i, s)| series(s, studies, i, Drawn::Friction))
        .collect();
    let fig = picture(
        "What accuracy costs: each case through its levels (L5 = level 5)",
        format!("error of sliding {MU_BAR} vs Richardson extrapolation"),
        series,
    );
    render_svg(&fig).map_err(|e| PipelineError::plot("accuracy.svg", e))
}

/// `figures/accuracy_film.svg`: the central film's error as [`svg`] draws the friction's, for
/// the cases whose film the rule tau-extrapolates at some level: the film each level reports
/// and, beside it, the grid's own, so that the extrapolation's gain and cost show against the
/// uniform levels; and the designs measured against those cases (the inlet patch, the rule),
/// their reported film alone. The other cases report their grids' films (nested domains,
/// Newton-Krylov levels, the line contact), which `accuracy.csv` has.
pub fn film_svg(studies: &[AccuracyResult]) -> Result<String, PipelineError> {
    let mut series: Vec<Series> = Vec::new();
    for s in studies {
        if s.twin.is_some() {
            // Its reported film alone: its grid's own is about its case's (the rule's top
            // keeps its level's film) or the reported one (the inlet patch's).
            series.push(self::series(s, studies, series.len(), Drawn::Film));
        } else if s.extrapolates_film() {
            series.push(self::series(s, studies, series.len(), Drawn::Film));
            series.push(self::series(s, studies, series.len(), Drawn::GridFilm));
        }
    }
    let fig = picture(
        "The central film: as reported and the grid's own (L5 = level 5)",
        "error of Hc vs Richardson extrapolation".into(),
        series,
    );
    render_svg(&fig).map_err(|e| PipelineError::plot("accuracy_film.svg", e))
}

/// `figures/accuracy_hmin.svg`: the minimum film's error as [`svg`] draws the friction's, for
/// the designs (the inlet patch, the rule with its top refined across the rolling direction)
/// and the cases they are measured against: what the adopted top buys against a uniform
/// level. The other cases' minimum films are in `accuracy.csv`.
pub fn h_min_svg(studies: &[AccuracyResult]) -> Result<String, PipelineError> {
    let twins: Vec<&str> = studies.iter().filter_map(|s| s.twin).collect();
    let series = studies
        .iter()
        .filter(|s| s.twin.is_some() || twins.contains(&s.name))
        .enumerate()
        .map(|(i, s)| series(s, studies, i, Drawn::MinFilm))
        .collect();
    let fig = picture(
        "The minimum film: uniform levels and the designs (L7y = level 7 refined across)",
        "error of Hmin vs Richardson extrapolation".into(),
        series,
    );
    render_svg(&fig).map_err(|e| PipelineError::plot("accuracy_hmin.svg", e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::paper::accuracy::tests::{run, study};
    use crate::paper::accuracy::TWIN_REFERENCE;
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

    #[test]
    fn the_film_picture_draws_the_grids_film_beside_an_extrapolated_one() {
        let mut levels = vec![run(5, 1.0, 40.0), run(6, 1.1, 41.0), run(7, 1.15, 41.2)];
        let plain = svg_film(&levels);
        // Level 7's film reported tau-extrapolated: a second series, the grid's.
        if let Ok(m) = &mut levels[2].outcome {
            m.h_central = 1.17;
        }
        let extrapolated = svg_film(&levels);
        // Each series' joining line in its colour (the first's, the second's).
        let joined = |svg: &str, colour: &str| {
            svg.matches(&format!(
                r#"<polyline fill="none" opacity="1" stroke="{colour}""#
            ))
            .count()
        };
        // A case whose film is the grid's at every level is not drawn (accuracy.csv has it).
        assert_eq!(
            (joined(&plain, "#0072B2"), joined(&plain, "#D55E00")),
            (0, 0)
        );
        assert_eq!(
            (
                joined(&extrapolated, "#0072B2"),
                joined(&extrapolated, "#D55E00")
            ),
            (1, 1)
        );
        assert!(extrapolated.contains("t, the grid") && !plain.contains("t, the grid"));
        // A design measured against the case, extrapolated as well: its reported film alone,
        // a third series beside the case's two.
        let case = study(levels.clone());
        let mut design = study(levels);
        design.name = "d";
        design.twin = Some("t");
        design.reference = case.reference.map(|r| crate::paper::accuracy::Reference {
            kind: TWIN_REFERENCE,
            ..r
        });
        let both = film_svg(&[case, design]).unwrap();
        assert_eq!(
            (
                joined(&both, "#0072B2"),
                joined(&both, "#D55E00"),
                joined(&both, "#009E73")
            ),
            (1, 1, 1)
        );
        assert!(!both.contains("d, the grid"));
    }

    #[test]
    fn the_minimum_film_picture_draws_the_designs_beside_their_cases_by_the_grid_they_ended_on() {
        let x = |n: u32| 2.0 + 3.0 * 4f64.powi(-(n as i32));
        let levels: Vec<_> = (5..=7).map(|n| run(n, x(n), x(n))).collect();
        let alone = study(levels.clone());
        let mut case = study(levels.clone());
        case.name = "case";
        // The rule from level 6, the case's own solve there (left out: its label would lie
        // on the case's), and from level 7, ended on level 7's top refined across, its
        // minimum film 1e-3 from the reference's (1); measured against the case's reference.
        let mut rule = study(levels[1..].to_vec());
        (rule.name, rule.twin, rule.reference) = ("case-rule", Some("case"), case.reference);
        if let Ok(m) = &mut rule.levels[1].outcome {
            (m.across, m.h_min) = (true, 1.001);
        }
        assert!((rule.h_min_error(&rule.levels[1]).unwrap() - 1e-3).abs() < 1e-12);
        let svg = h_min_svg(&[alone, case, rule]).unwrap();
        let labelled = |l: &str| svg.lines().filter(|line| line.trim() == l).count();
        // The case through its levels and the design's one point, not the case without one.
        assert_eq!((labelled("L7y"), labelled("L7"), labelled("L6")), (1, 1, 1));
        // Legend entries are lines of their own.
        assert_eq!(
            (labelled("case-rule"), labelled("case"), labelled("t")),
            (1, 1, 0)
        );
    }

    fn svg_film(levels: &[crate::paper::accuracy::LevelRun]) -> String {
        film_svg(&[study(levels.to_vec())]).unwrap()
    }
}

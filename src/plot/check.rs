//! The layout check: where a rendered figure put its text boxes (title, legend, notes, point
//! labels) and its markers, and what is wrong with that ([`Layout::problems`]): a box off the
//! canvas, two boxes over each other (two point labels included), a legend, note or point
//! label over a data marker.

use super::layout::Rect;
use super::{HEIGHT, WIDTH};

/// The margin, in pixels, a box keeps from the canvas's edge.
const EDGE_MARGIN: i32 = 2;

/// The boxes and markers of a rendered figure, in pixels (y grows downwards).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Layout {
    /// The title's box.
    pub title: Option<Rect>,
    /// The axis labels' boxes (x, then y upright).
    pub axis_labels: Vec<Rect>,
    /// The legend's box.
    pub legend: Option<Rect>,
    /// The notes' box.
    pub notes: Option<Rect>,
    /// Each point label's box.
    pub labels: Vec<Rect>,
    /// Each drawn marker's centre.
    pub markers: Vec<(i32, i32)>,
}

impl Layout {
    /// What is wrong with the layout, one sentence each; empty where nothing is.
    pub fn problems(&self) -> Vec<String> {
        // The canvas less a margin: the text widths are estimates ([`super::text_width`],
        // within about 10 % of DejaVu Sans), so a box that touches the edge may run off it.
        let canvas = Rect {
            x0: EDGE_MARGIN,
            x1: WIDTH as i32 - EDGE_MARGIN,
            y0: EDGE_MARGIN,
            y1: HEIGHT as i32 - EDGE_MARGIN,
        };
        let named: Vec<(&str, Rect)> = [
            ("title", self.title),
            ("legend", self.legend),
            ("notes", self.notes),
        ]
        .into_iter()
        .filter_map(|(n, r)| Some((n, r?)))
        .chain(self.axis_labels.iter().map(|r| ("axis label", *r)))
        .chain(self.labels.iter().map(|r| ("point label", *r)))
        .collect();
        let mut out = Vec::new();
        for (name, r) in &named {
            if !canvas.holds(r) {
                out.push(format!("{name} {r:?} leaves the canvas"));
            }
        }
        // Each box against the ones after it, point labels among themselves too.
        for (i, (a, ra)) in named.iter().enumerate() {
            for (b, rb) in &named[i + 1..] {
                if ra.overlaps(rb) {
                    out.push(format!("{a} {ra:?} overlaps {b} {rb:?}"));
                }
            }
        }
        // A point label is placed with a gap from its own marker (`place`), so every marker
        // it covers is another point's.
        let over_data = named
            .iter()
            .filter(|(n, _)| matches!(*n, "legend" | "notes" | "point label"));
        for (name, r) in over_data {
            let covered = self.markers.iter().filter(|m| r.covers_marker(**m)).count();
            if covered > 0 {
                out.push(format!("{name} {r:?} covers {covered} data markers"));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: i32, y0: i32, x1: i32, y1: i32) -> Rect {
        Rect { x0, x1, y0, y1 }
    }

    #[test]
    fn the_present_fig6_layout_fails_the_check() {
        // The boxes of figures/fig6.svg as main's a0b7781 drew it, read from its <rect>s and
        // <circle>s: the note's box from x = 0 (its text runs on past the right edge), over
        // the legend's first row, and over the blue 40 C markers at the upper right.
        let fig6 = Layout {
            title: Some(rect(343, 17, 441, 41)),
            legend: Some(rect(85, 52, 391, 175)),
            notes: Some(rect(0, 52, 762, 80)),
            labels: Vec::new(),
            axis_labels: Vec::new(),
            markers: vec![(741, 61), (729, 75), (288, 425)],
        };
        let problems = fig6.problems();
        assert!(
            problems
                .iter()
                .any(|p| p.starts_with("notes") && p.contains("canvas")),
            "{problems:?}"
        );
        assert!(problems
            .iter()
            .any(|p| p.starts_with("legend") && p.contains("overlaps notes")));
        assert!(problems
            .iter()
            .any(|p| p.starts_with("notes") && p.contains("covers 2")));
        // The same boxes apart, inside the canvas and clear of the markers: no problem.
        let fixed = Layout {
            notes: Some(rect(84, 540, 700, 590)),
            legend: Some(rect(200, 220, 500, 300)),
            ..fig6
        };
        assert_eq!(fixed.problems(), Vec::<String>::new());
    }

    #[test]
    fn point_labels_over_each_other_or_over_a_marker_are_reported() {
        // Three labels of 18 x 17 px (an "L7" at 14 px), the second's top at `second_top`,
        // and markers at their left, the third's at `third_x`.
        let layout = |second_top: i32, third_x: i32| Layout {
            labels: vec![
                rect(406, 394, 424, 411),
                rect(406, second_top, 424, second_top + 17),
                rect(500, 394, 518, 411),
            ],
            markers: vec![(400, 400), (400, 392), (third_x, 400)],
            ..Layout::default()
        };
        // The second 8 px above the first (over it), and the marker 4 px left of the third
        // (the marker's radius: over it).
        assert_eq!(
            layout(386, 496).problems(),
            [
                "point label Rect { x0: 406, x1: 424, y0: 394, y1: 411 } overlaps point label \
                 Rect { x0: 406, x1: 424, y0: 386, y1: 403 }",
                "point label Rect { x0: 500, x1: 518, y0: 394, y1: 411 } covers 1 data markers",
            ]
        );
        // The second 25 px above the first (clear of it and of the markers, each 6 px left
        // of its box), and the marker 5 px left of the third (one more than the radius).
        assert_eq!(layout(369, 495).problems(), Vec::<String>::new());
    }

    #[test]
    fn curves_differ_in_colour_and_dash_and_an_empty_series_says_so() {
        use crate::plot::{render_svg, Curve, Figure, Scale, Series};
        let curve = |label: &str, dashed: bool, y: f64| Curve {
            label: label.into(),
            points: vec![(1.0, y), (100.0, y + 4.0)],
            dashed,
        };
        let fig = Figure {
            x_scale: Scale::Log,
            curves: vec![
                curve("Eq. (13)", true, 0.0),
                curve("form 1", false, 1.0),
                curve("form 2", false, 2.0),
            ],
            series: vec![Series {
                label: "nothing drawable".into(),
                points: vec![(-1.0, 1.0)],
                ..Series::default()
            }],
            ..Figure::default()
        };
        let dashes = crate::plot::style::curve_dashes(&fig.curves);
        assert_eq!(dashes, vec![Some((9, 6)), None, Some((2, 4))]);
        let svg = render_svg(&fig).unwrap();
        assert!(svg.contains("nothing drawable (no point shown)"));
        // Three curve colours, none the same.
        for (i, c) in ["#000000", "#666666", "#AAAAAA"].iter().enumerate() {
            assert!(svg.contains(&format!("stroke=\"{c}\"")), "curve {i}");
        }
    }
}

//! Rendering: same figure, same bytes; well-formed SVG; labels, legend, bad points, ranges.
use super::*;
use crate::plot::marker::{BarEnd, ErrorBar};
use crate::plot::style::{ERROR_CAP, MARKER_R};
use crate::plot::{Curve, Marker, Series};

const MU_BAR: &str = "μ\u{304}";
const TAU_C: &str = "τ\u{304}_{c}";

/// A dashed model curve `asinh(x / 5)`, `n` points log-uniform over `[x0, x1]`.
fn model_curve(x0: f64, x1: f64, _c: f64, n: usize) -> Curve {
    let points = (0..n)
        .map(|i| x0 * (x1 / x0).powf(i as f64 / (n - 1) as f64))
        .map(|x| (x, (x / 5.0).asinh()))
        .collect();
    Curve {
        label: format!("Eq. (13): {MU_BAR} = asinh({TAU_C}/5)"),
        points,
        dashed: true,
    }
}

/// A Fig. 4-like figure: two series on a log x axis with Eq. (13) dashed.
fn sample() -> Figure {
    let a: Vec<(f64, f64)> = (0..40)
        .map(|i| {
            let t = 10f64.powf(-1.0 + 0.1 * f64::from(i));
            (t, (t / 5.0).asinh() * 1.03)
        })
        .collect();
    let b: Vec<(f64, f64)> = (0..25)
        .map(|i| {
            let t = 10f64.powf(-0.5 + 0.15 * f64::from(i));
            (t, (t / 5.0).asinh() * 0.97)
        })
        .collect();
    Figure {
        title: format!("Fig. 4 Sliding {MU_BAR} vs {TAU_C}, mineral oil A"),
        x_label: TAU_C.to_string(),
        y_label: MU_BAR.to_string(),
        x_scale: Scale::Log,
        y_scale: Scale::Linear,
        x_range: None,
        y_range: None,
        series: vec![
            Series {
                label: "τ0 = 4 MPa".into(),
                points: a,
                marker: Marker::Circle,
                ..Series::default()
            },
            Series {
                label: "τ0 = 8 MPa".into(),
                points: b,
                marker: Marker::Square,
                ..Series::default()
            },
        ],
        curves: vec![model_curve(0.1, 3000.0, 5.0, 200)],
        note: None,
    }
}

/// Minimal well-formedness check: balanced tags, quoted attributes, known entities.
/// Returns the element names in document order.
fn parse_xmlish(svg: &str) -> Result<Vec<String>, String> {
    let mut stack: Vec<String> = Vec::new();
    let mut names = Vec::new();
    let mut rest = svg.trim_start();
    if let Some(r) = rest.strip_prefix("<?xml") {
        rest = &r[r.find("?>").ok_or("unterminated declaration")? + 2..];
    }
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("</") {
            let end = r.find('>').ok_or("unterminated end tag")?;
            let name = r[..end].trim();
            match stack.pop() {
                Some(open) if open == name => {}
                other => return Err(format!("</{name}> closes {other:?}")),
            }
            rest = &r[end + 1..];
        } else if let Some(r) = rest.strip_prefix('<') {
            let end = r.find('>').ok_or("unterminated tag")?;
            let body = &r[..end];
            let self_closing = body.ends_with('/');
            let body = body.trim_end_matches('/');
            let name: String = body.chars().take_while(|c| !c.is_whitespace()).collect();
            if name.is_empty() || body.matches('"').count() % 2 != 0 {
                return Err(format!("bad tag <{body}>"));
            }
            names.push(name.clone());
            if !self_closing {
                stack.push(name);
            }
            rest = &r[end + 1..];
        } else {
            let end = rest.find('<').unwrap_or(rest.len());
            let text = &rest[..end];
            for (i, _) in text.match_indices('&') {
                let ent = &text[i..text[i..].find(';').map_or(text.len(), |j| i + j + 1)];
                let known = ["&lt;", "&gt;", "&amp;", "&quot;", "&apos;"];
                if !known.contains(&ent) && !ent.starts_with("&#") {
                    return Err(format!("bad entity {ent}"));
                }
            }
            if !stack.is_empty() || text.trim().is_empty() {
                rest = &rest[end..];
            } else {
                return Err(format!("text outside the root: {text:?}"));
            }
        }
    }
    if stack.is_empty() {
        Ok(names)
    } else {
        Err(format!("unclosed {stack:?}"))
    }
}

fn count(names: &[String], name: &str) -> usize {
    names.iter().filter(|n| *n == name).count()
}

#[test]
fn same_figure_gives_identical_bytes() {
    let fig = sample();
    let a = render_svg(&fig).expect("renders");
    let b = render_svg(&fig.clone()).expect("renders");
    assert_eq!(a, b);
    assert!(a.starts_with("<svg"));
}

#[test]
fn svg_is_well_formed_with_one_marker_per_point() {
    let fig = sample();
    let svg = render_svg(&fig).expect("renders");
    let names = parse_xmlish(&svg).expect("well formed");
    // Every circle is a data point of series 1 or its legend sample.
    assert_eq!(count(&names, "circle"), fig.series[0].points.len() + 1);
    // Squares are rects, beside the background, plot area, legend box (fill and border).
    let squares = svg.matches("<rect").filter(|_| true).count();
    let coloured = svg
        .match_indices("<rect")
        .filter(|(i, _)| {
            svg[*i..]
                .split('>')
                .next()
                .is_some_and(|t| t.contains("#D55E00"))
        })
        .count();
    assert_eq!(coloured, fig.series[1].points.len() + 1);
    assert!(squares > coloured);
}

#[test]
fn labels_and_legend_appear() {
    // plotters puts a text element's content on its own line; join lines to match it.
    let svg = render_svg(&sample()).expect("renders").replace('\n', "");
    // The subscript c of tau_c becomes a tspan; the overbar is a combining macron.
    assert!(svg.contains("τ\u{304}<tspan"), "x label");
    assert!(svg.contains(">μ\u{304}</text>"), "y label");
    assert!(svg.contains("τ0 = 4 MPa") && svg.contains("τ0 = 8 MPa"));
    assert!(svg.contains("Eq. (13): μ\u{304} = asinh(τ\u{304}"));
    assert!(!svg.contains("_{"), "markup left unconverted");
    // Log axis ticks as plain decades.
    for tick in [">0.1<", ">1<", ">10<", ">100<", ">1000<"] {
        assert!(svg.contains(tick), "tick {tick}");
    }
}

#[test]
fn bad_points_on_log_axis_are_counted_not_fatal() {
    let mut fig = sample();
    fig.series[0].points.push((f64::NAN, 1.0));
    fig.series[0].points.push((0.0, 1.0));
    fig.series[0].points.push((-3.0, 1.0));
    fig.series[1].points.push((1.0, f64::INFINITY));
    fig.curves.push(Curve {
        label: "broken".into(),
        points: vec![
            (1.0, 1.0),
            (f64::NAN, 2.0),
            (-1.0, 3.0),
            (10.0, 2.0),
            (100.0, 3.0),
        ],
        dashed: false,
    });
    let r = render(&fig).expect("renders");
    assert_eq!(r.skipped_points, 4);
    assert_eq!(r.skipped_curve_points, 2);
    assert_eq!(r.outside_range, 0);
    assert!(r.svg.contains("4 points not shown"));
    let names = parse_xmlish(&r.svg).expect("well formed");
    assert_eq!(count(&names, "circle"), 40 + 1);
}

#[test]
fn only_bad_points_still_renders() {
    let fig = Figure {
        x_scale: Scale::Log,
        y_scale: Scale::Log,
        series: vec![Series {
            label: "bad".into(),
            points: vec![(f64::NAN, f64::NAN), (0.0, -1.0), (-1.0, 0.0)],
            marker: Marker::Cross,
            ..Series::default()
        }],
        ..Figure::default()
    };
    let r = render(&fig).expect("renders");
    assert_eq!(r.skipped_points, 3);
    parse_xmlish(&r.svg).expect("well formed");
    // Nothing at all: also fine.
    parse_xmlish(&render_svg(&Figure::default()).expect("renders")).expect("well formed");
}

#[test]
fn explicit_ranges_are_checked_and_clip() {
    let mut fig = sample();
    fig.x_range = Some((0.0, 10.0));
    assert!(matches!(
        render(&fig),
        Err(PlotError::InvalidRange { axis: "x", .. })
    ));
    fig.x_range = Some((f64::NAN, 10.0));
    assert!(render(&fig).is_err());
    fig.x_range = Some((10.0, 1.0));
    assert!(render(&fig).is_err());
    fig.x_range = Some((1.0, 100.0));
    fig.y_range = Some((0.0, 4.0));
    let r = render(&fig).expect("renders");
    let inside = fig.series[0]
        .points
        .iter()
        .filter(|(x, y)| (1.0..=100.0).contains(x) && (0.0..=4.0).contains(y))
        .count();
    let names = parse_xmlish(&r.svg).expect("well formed");
    assert_eq!(count(&names, "circle"), inside + 1);
    assert!(r.outside_range > 0);
    assert!(r.svg.contains("outside the plotted range"));
}

#[test]
fn note_is_drawn() {
    let fig = Figure {
        title: "Fig. 8".into(),
        x_scale: Scale::Log,
        curves: vec![model_curve(0.1, 1e4, 5.0, 50)],
        note: Some("no measured dataset included".into()),
        ..Figure::default()
    };
    let svg = render_svg(&fig).expect("renders").replace('\n', "");
    assert!(svg.contains(">no measured dataset included</text>"));
}

/// Element count of `render_svg(&sample())` before error bars existed (none of its series has
/// any): a bar drawn for a series without errors adds elements.
const SAMPLE_ELEMENTS: usize = 208;

/// The value of attribute `name` in one tag's text.
fn attr(tag: &str, name: &str) -> Option<i32> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    tag[at..].split('"').next()?.parse().ok()
}

/// The `<line>`s in colour `stroke`, as [x1, y1, x2, y2].
fn lines_in(svg: &str, stroke: &str) -> Vec<[i32; 4]> {
    svg.split("<line")
        .skip(1)
        .filter_map(|t| t.split('>').next())
        .filter(|t| t.contains(&format!("stroke=\"{stroke}\"")))
        .map(|t| ["x1", "y1", "x2", "y2"].map(|n| attr(t, n).expect("line coordinate")))
        .collect()
}

/// Centre of the first `<circle>` in colour `stroke` (a data point: the legend comes after).
fn first_circle(svg: &str, stroke: &str) -> (i32, i32) {
    let tag = svg
        .split("<circle")
        .skip(1)
        .filter_map(|t| t.split('>').next())
        .find(|t| t.contains(&format!("stroke=\"{stroke}\"")))
        .expect("a circle");
    (attr(tag, "cx").expect("cx"), attr(tag, "cy").expect("cy"))
}

const BLUE: &str = "#0072B2";

/// One circle at (5, 5) with error `e`, axes 0..10 (about 50 px per unit of y).
fn one_point(y_scale: Scale, y_range: (f64, f64), y: f64, e: Vec<f64>) -> Figure {
    Figure {
        x_range: Some((0.0, 10.0)),
        y_range: Some(y_range),
        y_scale,
        series: vec![Series {
            label: "with error".into(),
            points: vec![(5.0, y)],
            y_errors: e,
            ..Series::default()
        }],
        ..Figure::default()
    }
}

#[test]
fn error_bar_larger_than_marker_is_drawn_with_caps() {
    let svg = render_svg(&one_point(Scale::Linear, (0.0, 10.0), 5.0, vec![2.0])).expect("renders");
    let (cx, cy) = first_circle(&svg, BLUE);
    let lines = lines_in(&svg, BLUE);
    assert_eq!(lines.len(), 3, "bar and two caps: {lines:?}");
    let [x1, y1, x2, y2] = lines[0];
    assert_eq!((x1, x2), (cx, cx), "vertical through the point");
    // From y - e (below, larger pixel y) to y + e, symmetric about the point (1 px: rounding).
    assert!(
        y1 - cy > 4 * MARKER_R && cy - y2 > 4 * MARKER_R,
        "{lines:?} at {cy}"
    );
    assert!(((y1 - cy) - (cy - y2)).abs() <= 1);
    for (cap, y) in [(lines[1], y2), (lines[2], y1)] {
        assert_eq!(cap, [cx - ERROR_CAP, y, cx + ERROR_CAP, y]);
    }
    // Beneath the marker: the bar comes first in the document.
    assert!(svg.find("<line").expect("line") < svg.find("<circle").expect("circle"));
    parse_xmlish(&svg).expect("well formed");
}

#[test]
fn error_bar_within_marker_is_not_drawn() {
    // 0.05 units of y is about 2.5 px, less than the marker radius.
    let svg = render_svg(&one_point(Scale::Linear, (0.0, 10.0), 5.0, vec![0.05])).expect("renders");
    assert!(lines_in(&svg, BLUE).is_empty());
    // Nor for zero, negative, non-finite or missing errors.
    for e in [
        vec![0.0],
        vec![-2.0],
        vec![f64::NAN],
        vec![f64::INFINITY],
        vec![],
    ] {
        let fig = one_point(Scale::Linear, (0.0, 10.0), 5.0, e);
        assert!(lines_in(&render_svg(&fig).expect("renders"), BLUE).is_empty());
    }
}

#[test]
fn error_bar_is_cut_at_the_axes_without_caps() {
    // Linear: y + e beyond the top of the range; only the lower end has a cap.
    let svg = render_svg(&one_point(Scale::Linear, (0.0, 10.0), 9.0, vec![3.0])).expect("renders");
    let lines = lines_in(&svg, BLUE);
    assert_eq!(lines.len(), 2, "{lines:?}");
    let (_, cy) = first_circle(&svg, BLUE);
    assert!(lines[1][1] > cy, "the cap is at the lower end: {lines:?}");
    // Log: y - e <= 0 is cut at the bottom of the axis, the same pixel for any such e; the
    // upper end at log10(y + e) keeps its cap.
    let cut = |e: f64| {
        let fig = one_point(Scale::Log, (0.1, 10.0), 1.0, vec![e]);
        lines_in(&render_svg(&fig).expect("renders"), BLUE)
    };
    let (a, b) = (cut(1.0), cut(5.0));
    assert_eq!((a.len(), b.len()), (2, 2), "{a:?} {b:?}");
    assert_eq!(a[0][1], b[0][1], "lower end at the axis");
    assert!(a[0][3] > b[0][3], "upper end at log10(1 + e): {a:?} {b:?}");
    assert_eq!(a[1][1], a[0][3], "cap at the upper end");
    // A point outside the range or not plottable has no bar.
    let mut fig = one_point(Scale::Log, (0.1, 10.0), 20.0, vec![1.0, 5.0]);
    fig.series[0].points.push((5.0, -1.0));
    let r = render(&fig).expect("renders");
    assert_eq!((r.outside_range, r.skipped_points), (1, 1));
    assert!(lines_in(&r.svg, BLUE).is_empty());
}

#[test]
fn figure_without_errors_draws_no_bars() {
    let plain = render_svg(&sample()).expect("renders");
    let names = parse_xmlish(&plain).expect("well formed");
    assert_eq!(names.len(), SAMPLE_ELEMENTS);
    // Circles and squares draw no lines in the series' colours; a bar would.
    assert!(lines_in(&plain, BLUE).is_empty() && lines_in(&plain, "#D55E00").is_empty());
    // Errors that draw no bar leave the bytes as they are.
    let mut fig = sample();
    fig.series[0].y_errors = vec![0.0; fig.series[0].points.len()];
    fig.series[1].y_errors = vec![f64::NAN; 3];
    assert_eq!(render_svg(&fig).expect("renders"), plain);
}

#[test]
fn figure_with_errors_gives_identical_bytes() {
    let mut fig = sample();
    fig.series[0].y_errors = fig.series[0].points.iter().map(|p| 0.1 * p.1).collect();
    let a = render_svg(&fig).expect("renders");
    assert_eq!(a, render_svg(&fig.clone()).expect("renders"));
    assert!(lines_in(&a, BLUE).len() > fig.series[0].points.len());
    parse_xmlish(&a).expect("well formed");
}

#[test]
fn error_bar_strokes_follow_the_marker_radius() {
    let end = |y, own| BarEnd { y, own };
    let bar = |top, bottom| ErrorBar {
        at: (100, 200),
        top,
        bottom,
    };
    let r = MARKER_R;
    // Within the marker: nothing.
    assert!(bar(end(200 - r, true), end(200 + r, true))
        .strokes((0, 800))
        .is_empty());
    // One arm beyond it (a log bar): the bar, and a cap on that arm only.
    let s = bar(end(200 - r, true), end(200 + 3 * r, true)).strokes((0, 800));
    assert_eq!(
        s,
        [
            ((100, 200 + 3 * r), (100, 200 - r)),
            (
                (100 - ERROR_CAP, 200 + 3 * r),
                (100 + ERROR_CAP, 200 + 3 * r)
            ),
        ]
    );
    // Caps are cut to the plotting area's columns; a cut end has none.
    let s = bar(end(150, false), end(250, true)).strokes((99, 800));
    assert_eq!(
        s,
        [
            ((100, 250), (100, 150)),
            ((99, 250), (100 + ERROR_CAP, 250))
        ]
    );
}

/// A Fig. 6-like figure: data along the diagonal from the lower left to the upper right and a
/// cloud at the upper left, five series with error bars, and a note longer than the plot is
/// wide.
fn crowded() -> Figure {
    let mut fig = sample();
    let cloud: Vec<(f64, f64)> = (0..30)
        .flat_map(|i| (0..6).map(move |j| (0.1 * 1.2f64.powi(i), 3.0 + 0.1 * f64::from(j))))
        .collect();
    for k in 0..3 {
        fig.series.push(Series {
            label: format!("series {k} with a longer label"),
            points: cloud
                .iter()
                .map(|&(x, y)| (x * 1.1f64.powi(k), y))
                .collect(),
            marker: Marker::nth(k as usize),
            y_errors: vec![0.4; cloud.len()],
            ..Series::default()
        });
    }
    fig.note = Some(
        "\"paper's setup\": P = 0 on the paper's domain, Eq. (8) over it, for the 173 cases \
         where it differs from the flooded contact by more than the error bar"
            .into(),
    );
    fig
}

#[test]
fn a_crowded_figure_keeps_its_text_clear_of_data_and_of_each_other() {
    let r = render(&crowded()).expect("renders");
    assert_eq!(r.layout.problems(), Vec::<String>::new());
    // The legend names the error bars; the long note was wrapped onto lines.
    assert!(r.svg.contains("estimated discretisation error"));
    assert!(r.layout.notes.is_some_and(|n| n.x1 < WIDTH as i32));
    // Every figure of this module's tests lays out cleanly too.
    for fig in [
        sample(),
        one_point(Scale::Linear, (0.0, 10.0), 5.0, vec![2.0]),
    ] {
        assert_eq!(
            render(&fig).unwrap().layout.problems(),
            Vec::<String>::new()
        );
    }
}

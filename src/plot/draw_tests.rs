//! Rendering: same figure, same bytes; well-formed SVG; labels, legend, bad points, ranges.
use super::*;
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

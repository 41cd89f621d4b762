//! Rendering: a [`Figure`] through plotters' SVG backend into a string, then the text markup
//! applied.

use super::axes::{error_bar, plan_axis, to_plot, AxisPlan};
use super::check::Layout;
use super::layout::{visible_pieces, Rect};
use super::legend::{
    axis_label_boxes, draw_legend, draw_notes, legend_rows, notes_size, title_box, wrap_notes,
    MARGIN, MARGIN_RIGHT,
};
use super::marker::{BarEnd, ErrorBar, Glyph, Lines};
use super::place::Ink;
use super::style::{
    curve_color, curve_dashes, drawing, font, series_color, DESC_PX, NOTE_PX, TICK_PX, TITLE_PX,
};
use super::text::{apply_markup, text_width};
use super::{Figure, PlotError, Rendered, Scale, HEIGHT, WIDTH};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters_backend::BackendCoord;

/// Renders a figure as an SVG document of [`WIDTH`] x [`HEIGHT`] pixels.
///
/// Same figure, same bytes. Unplottable points are skipped (see [`render`] for the counts).
pub fn render_svg(fig: &Figure) -> Result<String, PlotError> {
    render(fig).map(|r| r.svg)
}

/// Series in plotted coordinates (with each point's label and error bar), and what was left
/// out.
pub(super) struct Prepared {
    series: Vec<Vec<(f64, f64)>>,
    labels: Vec<Vec<String>>,
    /// Each point's error bar: plotted y of its low and high ends, not yet cut to the axis.
    bars: Vec<Vec<Option<(f64, f64)>>>,
    curves: Vec<Vec<Option<(f64, f64)>>>,
    skipped_points: usize,
    skipped_curve_points: usize,
}

pub(super) fn prepare(fig: &Figure) -> Prepared {
    let mut skipped_points = 0;
    let mut skipped_curve_points = 0;
    let map = |&(x, y): &(f64, f64)| Some((to_plot(fig.x_scale, x)?, to_plot(fig.y_scale, y)?));
    let (mut series, mut labels, mut bars) = (Vec::new(), Vec::new(), Vec::new());
    for s in &fig.series {
        let (mut pts, mut lbls, mut brs) = (Vec::new(), Vec::new(), Vec::new());
        for (k, p) in s.points.iter().enumerate() {
            let Some(at) = map(p) else {
                skipped_points += 1;
                continue;
            };
            pts.push(at);
            lbls.push(s.point_labels.get(k).cloned().unwrap_or_default());
            brs.push(
                s.y_errors
                    .get(k)
                    .and_then(|&e| error_bar(fig.y_scale, p.1, e)),
            );
        }
        series.push(pts);
        labels.push(lbls);
        bars.push(brs);
    }
    let curves = fig
        .curves
        .iter()
        .map(|c| {
            let pts: Vec<_> = c.points.iter().map(map).collect();
            skipped_curve_points += pts.iter().filter(|p| p.is_none()).count();
            pts
        })
        .collect();
    Prepared {
        series,
        labels,
        bars,
        curves,
        skipped_points,
        skipped_curve_points,
    }
}

/// Renders a figure and reports what was left out of it.
pub fn render(fig: &Figure) -> Result<Rendered, PlotError> {
    let prepared = prepare(fig);
    let xs: Vec<f64> = prepared
        .series
        .iter()
        .flatten()
        .map(|p| p.0)
        .chain(prepared.curves.iter().flatten().flatten().map(|p| p.0))
        .collect();
    let ys: Vec<f64> = prepared
        .series
        .iter()
        .flatten()
        .map(|p| p.1)
        .chain(prepared.curves.iter().flatten().flatten().map(|p| p.1))
        .collect();
    let x_axis = plan_axis("x", fig.x_scale, fig.x_range, &xs)?;
    let y_axis = plan_axis("y", fig.y_scale, fig.y_range, &ys)?;

    let inside = |&(u, v): &(f64, f64)| x_axis.contains(u) && y_axis.contains(v);
    let (visible, visible_labels): (Vec<Vec<_>>, Vec<Vec<String>>) = prepared
        .series
        .iter()
        .zip(&prepared.labels)
        .map(|(pts, labels)| {
            pts.iter()
                .copied()
                .zip(labels.iter().cloned())
                .filter(|(p, _)| inside(p))
                .unzip()
        })
        .unzip();
    let visible_bars: Vec<Vec<Option<(f64, f64)>>> = prepared
        .series
        .iter()
        .zip(&prepared.bars)
        .map(|(pts, bars)| {
            pts.iter()
                .zip(bars)
                .filter(|(p, _)| inside(p))
                .map(|(_, bar)| *bar)
                .collect()
        })
        .collect();
    let drawable: usize = prepared.series.iter().map(Vec::len).sum();
    let outside_range = drawable - visible.iter().map(Vec::len).sum::<usize>();
    let pieces: Vec<Vec<Vec<(f64, f64)>>> = prepared
        .curves
        .iter()
        .map(|c| visible_pieces(c, &x_axis, &y_axis))
        .collect();

    let mut notes: Vec<String> = fig.note.iter().cloned().collect();
    if prepared.skipped_points > 0 {
        let log = fig.x_scale == Scale::Log || fig.y_scale == Scale::Log;
        notes.push(format!(
            "{} point{} not shown: not finite{}",
            prepared.skipped_points,
            if prepared.skipped_points == 1 {
                ""
            } else {
                "s"
            },
            if log {
                " or not positive on a log axis"
            } else {
                ""
            }
        ));
    }
    if outside_range > 0 {
        notes.push(format!(
            "{outside_range} point{} outside the plotted range",
            if outside_range == 1 { "" } else { "s" }
        ));
    }

    let data = Data {
        series: &visible,
        labels: &visible_labels,
        bars: &visible_bars,
        curves: &pieces,
    };
    // Drawn with the legend and notes inside the plotting area, then again with the ones that
    // cover data there outside it.
    let once = |outside: Outside| -> Result<(String, Placement), PlotError> {
        let mut buf = String::new();
        let placement = {
            let root = SVGBackend::with_string(&mut buf, (WIDTH, HEIGHT)).into_drawing_area();
            let placement = draw(&root, fig, (&x_axis, &y_axis), &data, &notes, outside)?;
            root.present().map_err(drawing)?;
            placement
        };
        Ok((buf, placement))
    };
    let (mut buf, mut placement) = once(Outside::default())?;
    if placement.legend_crowded || placement.notes_crowded {
        (buf, placement) = once(Outside {
            legend: placement.legend_crowded,
            notes: placement.notes_crowded,
        })?;
    }
    Ok(Rendered {
        svg: apply_markup(&buf),
        layout: placement.layout,
        skipped_points: prepared.skipped_points,
        outside_range,
        skipped_curve_points: prepared.skipped_curve_points,
    })
}

/// What is drawn inside the axes: the visible points of each series with their labels and
/// error bars, and the visible pieces of each curve.
struct Data<'a> {
    series: &'a [Vec<(f64, f64)>],
    labels: &'a [Vec<String>],
    bars: &'a [Vec<Option<(f64, f64)>>],
    curves: &'a [Vec<Vec<(f64, f64)>>],
}

/// Where the legend and the notes go outside the plotting area: the legend to its right, the
/// notes below the x axis's label (room is kept for them).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
struct Outside {
    legend: bool,
    notes: bool,
}

/// What a drawing placed, and whether the legend or the notes, placed inside the plotting
/// area, cover data there (then the figure is drawn again with them [`Outside`]).
#[derive(Debug, Default)]
struct Placement {
    layout: Layout,
    legend_crowded: bool,
    notes_crowded: bool,
}

fn draw(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    fig: &Figure,
    (x_axis, y_axis): (&AxisPlan, &AxisPlan),
    data: &Data<'_>,
    notes: &[String],
    outside: Outside,
) -> Result<Placement, PlotError> {
    let (series, curves) = (data.series, data.curves);
    root.fill(&WHITE).map_err(drawing)?;

    let widest_y_tick = y_axis
        .majors
        .iter()
        .map(|(_, s)| text_width(s, TICK_PX))
        .fold(0.0, f64::max);
    // Tick marks, tick labels, a gap, then the rotated axis label.
    let y_area = (widest_y_tick + 5.0 + 10.0 + DESC_PX * 1.6).ceil() as u32;
    let x_area = (TICK_PX * 1.6 + 10.0 + DESC_PX * 1.6).ceil() as u32;
    let margin_right = MARGIN_RIGHT;
    // The width below the chart, from the y axis to the right margin.
    let band_w = WIDTH as i32 - y_area as i32 - MARGIN - margin_right;
    let notes = wrap_notes(notes, band_w);
    // Below the chart, bottom up: the notes, then the legend (the tallest it can be, with the
    // error bars' row), where they go outside.
    let band_notes = if outside.notes {
        notes_size(&notes).1 + Rect::INSET
    } else {
        0
    };
    let band_legend = if outside.legend {
        legend_rows(fig, series, true)
            .in_columns(WIDTH as i32 - 2 * MARGIN)
            .size()
            .1
            + Rect::INSET
    } else {
        0
    };
    let margin_bottom = MARGIN + band_notes + band_legend;

    let mut chart = ChartBuilder::on(root)
        .caption(&fig.title, font(TITLE_PX))
        .margin(MARGIN)
        .margin_right(margin_right)
        .margin_bottom(margin_bottom)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x_axis.clone(), y_axis.clone())
        .map_err(drawing)?;

    let x_fmt = |v: &f64| x_axis.label_at(*v);
    let y_fmt = |v: &f64| y_axis.label_at(*v);
    chart
        .configure_mesh()
        .x_desc(fig.x_label.as_str())
        .y_desc(fig.y_label.as_str())
        .x_labels(200)
        .y_labels(200)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(font(TICK_PX))
        .axis_desc_style(font(DESC_PX))
        .bold_line_style(RGBColor(0xD8, 0xD8, 0xD8))
        .light_line_style(RGBColor(0xEF, 0xEF, 0xEF))
        .axis_style(BLACK)
        .set_all_tick_mark_size(5)
        .draw()
        .map_err(drawing)?;

    let dashes = curve_dashes(&fig.curves);
    for (i, pieces) in curves.iter().enumerate() {
        let style = ShapeStyle::from(&curve_color(i)).stroke_width(2);
        if let Some((on, off)) = dashes[i] {
            chart
                .draw_series(
                    pieces
                        .iter()
                        .map(|p| DashedPathElement::new(p.clone(), on, off, style)),
                )
                .map_err(drawing)?;
        } else {
            chart
                .draw_series(pieces.iter().map(|p| PathElement::new(p.clone(), style)))
                .map_err(drawing)?;
        }
    }
    let (px, py) = chart.plotting_area().get_pixel_range();
    let area = Rect {
        x0: px.start,
        x1: px.end,
        y0: py.start,
        y1: py.end,
    };
    // Error bars in pixels, all before any marker so that every marker is drawn over them.
    let bar_lines: Vec<Vec<(BackendCoord, BackendCoord)>> = series
        .iter()
        .zip(data.bars)
        .map(|(pts, bars)| {
            pts.iter()
                .zip(bars)
                .filter_map(|(&(u, v), ends)| {
                    let (low, high) = (*ends)?;
                    let end = |w: f64| chart.backend_coord(&(u, w)).1;
                    let bar = ErrorBar {
                        at: chart.backend_coord(&(u, v)),
                        top: BarEnd {
                            y: end(high.min(y_axis.hi)),
                            own: high <= y_axis.hi,
                        },
                        bottom: BarEnd {
                            y: end(low.max(y_axis.lo)),
                            own: low >= y_axis.lo,
                        },
                    };
                    Some(bar.strokes((area.x0, area.x1)))
                })
                .flatten()
                .collect()
        })
        .collect();
    for (i, lines) in bar_lines.iter().enumerate() {
        if !lines.is_empty() {
            let ends = lines.iter().flat_map(|&(a, b)| [a, b]).collect();
            root.draw(&Lines {
                ends,
                color: series_color(i),
            })
            .map_err(drawing)?;
        }
    }
    let joined = series
        .iter()
        .zip(&fig.series)
        .filter(|(_, s)| s.joined)
        .map(|(pts, _)| pts);
    let ink = Ink {
        markers: series
            .iter()
            .flatten()
            .map(|p| chart.backend_coord(p))
            .collect(),
        lines: curves
            .iter()
            .flatten()
            .chain(joined)
            .flat_map(|pts| pts.windows(2))
            .map(|w| (chart.backend_coord(&w[0]), chart.backend_coord(&w[1])))
            .collect(),
        bars: bar_lines.iter().flatten().copied().collect(),
    };
    let crowding = |r: &Rect| ink.crowding(r);
    let has_bars = !ink.bars.is_empty();
    let legend = legend_rows(fig, series, has_bars);
    let legend = if outside.legend {
        legend.in_columns(WIDTH as i32 - 2 * MARGIN)
    } else {
        legend
    };
    let legend_size = legend.size();
    let mut placement = Placement::default();
    // Legend and notes go into the emptiest corners of the plotting area; where the emptiest
    // is not empty, outside it (the caller draws again with room kept: [`Outside`]).
    let legend_box = (!legend.rows.is_empty()).then(|| {
        if outside.legend {
            let y1 = HEIGHT as i32 - Rect::INSET / 2 - band_notes;
            let x0 = (WIDTH as i32 - legend_size.0) / 2;
            Rect {
                x0,
                x1: x0 + legend_size.0,
                y0: y1 - legend_size.1,
                y1,
            }
        } else {
            let rect = area.emptiest_place(legend_size, None, &crowding);
            placement.legend_crowded = crowding(&rect) > 0;
            rect
        }
    });
    let notes = &notes[..];
    let notes_box = (!notes.is_empty()).then(|| {
        let note_size = notes_size(notes);
        let has_data = series.iter().any(|s| !s.is_empty());
        if outside.notes {
            let y1 = HEIGHT as i32 - Rect::INSET / 2;
            Rect {
                x0: area.x0,
                x1: area.x0 + note_size.0,
                y0: y1 - note_size.1,
                y1,
            }
        } else if has_data {
            let rect = area.emptiest_place(note_size, legend_box, &crowding);
            placement.notes_crowded = crowding(&rect) > 0
                || legend_box.is_some_and(|l| l.overlaps(&rect))
                || rect.x0 < area.x0;
            rect
        } else {
            area.centred(note_size)
        }
    });
    // Point labels beside their markers, clear of each other, the markers and those boxes.
    let labels: Vec<(usize, (i32, i32), &str)> = series
        .iter()
        .zip(data.labels)
        .enumerate()
        .flat_map(|(i, (pts, ls))| pts.iter().zip(ls).map(move |(p, l)| (i, p, l)))
        .filter(|(_, _, l)| !l.is_empty())
        .map(|(i, p, l)| (i, chart.backend_coord(p), l.as_str()))
        .collect();
    let spots: Vec<_> = labels.iter().map(|&(_, at, l)| (at, l)).collect();
    let boxes: Vec<Rect> = legend_box.into_iter().chain(notes_box).collect();
    let label_boxes = ink.place_labels(&spots, &area, &boxes);
    for (i, pts) in series.iter().enumerate() {
        let (marker, color) = (fig.series[i].marker, series_color(i));
        if fig.series[i].joined && pts.len() > 1 {
            let style = ShapeStyle::from(&color).stroke_width(1);
            chart
                .draw_series(std::iter::once(PathElement::new(pts.clone(), style)))
                .map_err(drawing)?;
        }
        chart
            .draw_series(pts.iter().map(|&at| Glyph { at, marker, color }))
            .map_err(drawing)?;
        let label_style = font(NOTE_PX).color(&color);
        for ((_, _, l), r) in labels.iter().zip(&label_boxes).filter(|(l, _)| l.0 == i) {
            root.draw(&Text::new(l.to_string(), (r.x0, r.y0), label_style.clone()))
                .map_err(drawing)?;
        }
    }
    if let Some(rect) = legend_box {
        draw_legend(root, rect, &legend)?;
    }
    if let Some(rect) = notes_box {
        draw_notes(root, rect, notes)?;
    }
    placement.layout = Layout {
        title: Some(title_box(fig, margin_right)),
        axis_labels: axis_label_boxes(fig, &area, x_area as i32),
        legend: legend_box,
        notes: notes_box,
        labels: label_boxes,
        markers: ink.markers,
    };
    Ok(placement)
}

#[cfg(test)]
#[path = "draw_tests.rs"]
mod tests;

//! Rendering: a [`Figure`] through plotters' SVG backend into a string, then the text markup
//! applied.

use super::axes::{error_bar, plan_axis, to_plot, AxisPlan};
use super::layout::{visible_pieces, Corner, Rect};
use super::legend::{draw_legend, draw_notes, LegendRow, LegendSample};
use super::marker::{BarEnd, ErrorBar, Glyph, Lines};
use super::style::{
    curve_color, drawing, font, series_color, DESC_PX, LEGEND_PAD, LEGEND_PX, LEGEND_SAMPLE,
    MARKER_R, NOTE_PX, TICK_PX, TITLE_PX,
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

    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (WIDTH, HEIGHT)).into_drawing_area();
        let data = Data {
            series: &visible,
            labels: &visible_labels,
            bars: &visible_bars,
            curves: &pieces,
        };
        draw(&root, fig, &x_axis, &y_axis, &data, &notes)?;
        root.present().map_err(drawing)?;
    }
    Ok(Rendered {
        svg: apply_markup(&buf),
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

fn draw(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    fig: &Figure,
    x_axis: &AxisPlan,
    y_axis: &AxisPlan,
    data: &Data<'_>,
    notes: &[String],
) -> Result<(), PlotError> {
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

    let mut chart = ChartBuilder::on(root)
        .caption(&fig.title, font(TITLE_PX))
        .margin(12)
        .margin_right(28)
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

    for (i, pieces) in curves.iter().enumerate() {
        let style = ShapeStyle::from(&curve_color(i)).stroke_width(2);
        if fig.curves[i].dashed {
            chart
                .draw_series(
                    pieces
                        .iter()
                        .map(|p| DashedPathElement::new(p.clone(), 9, 6, style)),
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
        chart
            .draw_series(
                pts.iter()
                    .zip(&data.labels[i])
                    .filter(|(_, l)| !l.is_empty())
                    .map(|(&at, l)| {
                        EmptyElement::at(at)
                            + Text::new(
                                l.clone(),
                                (MARKER_R + 2, -(MARKER_R + 2)),
                                label_style.clone(),
                            )
                    }),
            )
            .map_err(drawing)?;
    }

    // Legend and notes go into the emptiest corners of the plotting area.
    let pixel_points: Vec<(i32, i32)> = series
        .iter()
        .flatten()
        .map(|p| chart.backend_coord(p))
        .collect();
    let pixel_lines: Vec<Vec<(i32, i32)>> = curves
        .iter()
        .flatten()
        .map(|piece| piece.iter().map(|p| chart.backend_coord(p)).collect())
        .collect();
    let crowding = |r: &Rect| -> usize {
        let grown = r.grow(MARKER_R + 2);
        let points = pixel_points.iter().filter(|p| grown.contains(**p)).count();
        // A bar (its vertical line; the caps are at its ends) counts as much as a point: the
        // box would hide the error of one point.
        let bars = bar_lines
            .iter()
            .flatten()
            .filter(|(a, b)| a.0 == b.0 && grown.meets_segment(*a, *b))
            .count();
        let lines = pixel_lines
            .iter()
            .flat_map(|l| l.windows(2))
            .filter(|w| grown.meets_segment(w[0], w[1]))
            .count();
        points + bars + 5 * lines
    };

    let legend_rows: Vec<LegendRow> = fig
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| LegendRow {
            label: s.label.clone(),
            sample: LegendSample::Marker(s.marker, series_color(i)),
        })
        .chain(fig.curves.iter().enumerate().map(|(i, c)| LegendRow {
            label: c.label.clone(),
            sample: LegendSample::Line(c.dashed, curve_color(i)),
        }))
        .filter(|r| !r.label.is_empty())
        .collect();
    let row_h = (LEGEND_PX * 1.5).round() as i32;
    let legend_size = (
        LEGEND_SAMPLE
            + 3 * LEGEND_PAD
            + legend_rows
                .iter()
                .map(|r| text_width(&r.label, LEGEND_PX).ceil() as i32)
                .max()
                .unwrap_or(0),
        legend_rows.len() as i32 * row_h + LEGEND_PAD,
    );
    let note_size = (
        notes
            .iter()
            .map(|n| text_width(n, NOTE_PX).ceil() as i32)
            .max()
            .unwrap_or(0)
            + 2 * LEGEND_PAD,
        notes.len() as i32 * (NOTE_PX * 1.4).round() as i32 + LEGEND_PAD,
    );

    let mut taken: Option<Corner> = None;
    if !legend_rows.is_empty() {
        let corner = area.emptiest_corner(legend_size, None, &crowding);
        taken = Some(corner);
        draw_legend(root, area.place(corner, legend_size), &legend_rows, row_h)?;
    }
    if !notes.is_empty() {
        let has_data = series.iter().any(|s| !s.is_empty());
        let rect = if has_data {
            let corner = area.emptiest_corner(note_size, taken, &crowding);
            area.place(corner, note_size)
        } else {
            area.centred(note_size)
        };
        draw_notes(root, rect, notes)?;
    }
    Ok(())
}

#[cfg(test)]
#[path = "draw_tests.rs"]
mod tests;

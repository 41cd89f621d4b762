//! The legend (a sample and a label per series and curve) and the notes, in boxes on the
//! plotting area.

use super::layout::Rect;
use super::marker::{Glyph, Lines};
use super::style::{
    curve_color, curve_dashes, drawing, font, series_color, DESC_PX, ERROR_CAP, LEGEND_PAD,
    LEGEND_PX, LEGEND_SAMPLE, NOTE_PX, TITLE_PX,
};
use super::text::text_width;
use super::{Figure, Marker, PlotError, WIDTH};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The canvas's margin around the chart, pixels.
pub(super) const MARGIN: i32 = 12;
/// The margin to the right of the chart: room for the last x tick label.
pub(super) const MARGIN_RIGHT: i32 = 28;
/// The legend's label for the error bars.
pub(super) const ERROR_BAR_LABEL: &str = "estimated discretisation error";
/// Appended to the label of a series none of whose points is drawn.
pub(super) const NOT_SHOWN: &str = " (no point shown)";

pub(super) enum LegendSample {
    Marker(Marker, RGBColor),
    /// A curve's sample: its dash (`None` solid) and colour.
    Line(Option<(u32, u32)>, RGBColor),
    /// An error bar with caps, in grey: the bars of every series.
    ErrorBar,
}

/// The legend's rows, their height and the columns they are set in.
pub(super) struct Legend {
    pub(super) rows: Vec<LegendRow>,
    pub(super) row_h: i32,
    pub(super) columns: usize,
}

impl Legend {
    /// The width of one column in pixels.
    fn column_w(&self) -> i32 {
        LEGEND_SAMPLE
            + 3 * LEGEND_PAD
            + self
                .rows
                .iter()
                .map(|r| text_width(&r.label, LEGEND_PX).ceil() as i32)
                .max()
                .unwrap_or(0)
    }

    /// Rows per column.
    fn per_column(&self) -> usize {
        self.rows.len().div_ceil(self.columns.max(1))
    }

    /// The legend box's width and height in pixels.
    pub(super) fn size(&self) -> (i32, i32) {
        (
            self.columns.max(1) as i32 * self.column_w(),
            self.per_column() as i32 * self.row_h + LEGEND_PAD,
        )
    }

    /// The legend in as many columns (up to three) as fit in `width` pixels: below the
    /// chart, where it goes when it would cover data inside.
    pub(super) fn in_columns(self, width: i32) -> Legend {
        let w = self.column_w().max(1);
        let columns = ((width / w) as usize)
            .clamp(1, 3)
            .min(self.rows.len().max(1));
        Legend { columns, ..self }
    }
}

/// The legend of `fig`, whose series draw the points `visible`: a row per labelled series
/// (marked where none of its points is drawn) and curve, and one naming the error bars where
/// `bars` (some bar is drawn).
pub(super) fn legend_rows(fig: &Figure, visible: &[Vec<(f64, f64)>], bars: bool) -> Legend {
    let dashes = curve_dashes(&fig.curves);
    let mut rows: Vec<LegendRow> = fig
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.label.is_empty())
        .map(|(i, s)| LegendRow {
            label: if visible.get(i).is_some_and(|v| v.is_empty()) {
                format!("{}{NOT_SHOWN}", s.label)
            } else {
                s.label.clone()
            },
            sample: LegendSample::Marker(s.marker, series_color(i)),
        })
        .collect();
    rows.extend(
        fig.curves
            .iter()
            .enumerate()
            .filter(|(_, c)| !c.label.is_empty())
            .map(|(i, c)| LegendRow {
                label: c.label.clone(),
                sample: LegendSample::Line(dashes[i], curve_color(i)),
            }),
    );
    if bars {
        rows.push(LegendRow {
            label: ERROR_BAR_LABEL.into(),
            sample: LegendSample::ErrorBar,
        });
    }
    Legend {
        rows,
        row_h: (LEGEND_PX * 1.5).round() as i32,
        columns: 1,
    }
}

/// `notes` broken at spaces into lines no wider than `width` pixels (a word wider than that
/// stands on a line of its own).
pub(super) fn wrap_notes(notes: &[String], width: i32) -> Vec<String> {
    let fits = |s: &str| text_width(s, NOTE_PX) + f64::from(2 * LEGEND_PAD) <= f64::from(width);
    let mut out = Vec::new();
    for note in notes {
        let mut line = String::new();
        for word in note.split(' ') {
            let longer = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if fits(&longer) || line.is_empty() {
                line = longer;
            } else {
                out.push(std::mem::replace(&mut line, word.to_string()));
            }
        }
        out.push(line);
    }
    out
}

/// The notes' box's width and height in pixels.
pub(super) fn notes_size(notes: &[String]) -> (i32, i32) {
    (
        notes
            .iter()
            .map(|n| text_width(n, NOTE_PX).ceil() as i32)
            .max()
            .unwrap_or(0)
            + 2 * LEGEND_PAD,
        notes.len() as i32 * (NOTE_PX * 1.4).round() as i32 + LEGEND_PAD,
    )
}

/// The boxes of the axis labels, x then y: the x label centred under the chart at the foot
/// of its label area (`x_area` pixels high), the y label turned upright, centred on the
/// chart's height at the left margin.
pub(super) fn axis_label_boxes(fig: &Figure, area: &Rect, x_area: i32) -> Vec<Rect> {
    let h = (DESC_PX * 1.3).ceil() as i32;
    let half = |s: &str| (text_width(s, DESC_PX) / 2.0).ceil() as i32;
    let (cx, cy) = ((area.x0 + area.x1) / 2, (area.y0 + area.y1) / 2);
    vec![
        Rect {
            x0: cx - half(&fig.x_label),
            x1: cx + half(&fig.x_label),
            y0: area.y1 + x_area - h,
            y1: area.y1 + x_area,
        },
        Rect {
            x0: MARGIN,
            x1: MARGIN + h,
            y0: cy - half(&fig.y_label),
            y1: cy + half(&fig.y_label),
        },
    ]
}

/// The title's box: plotters centres the caption over the chart (the canvas less its
/// margins) at the top margin.
pub(super) fn title_box(fig: &Figure, margin_right: i32) -> Rect {
    let centre = (MARGIN + WIDTH as i32 - margin_right) / 2;
    let half = (text_width(&fig.title, TITLE_PX) / 2.0).ceil() as i32;
    Rect {
        x0: centre - half,
        x1: centre + half,
        y0: MARGIN + 5,
        y1: MARGIN + 5 + (TITLE_PX * 1.2).ceil() as i32,
    }
}

pub(super) struct LegendRow {
    pub(super) label: String,
    pub(super) sample: LegendSample,
}

pub(super) fn draw_legend(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    rect: Rect,
    legend: &Legend,
) -> Result<(), PlotError> {
    let (rows, row_h) = (&legend.rows, legend.row_h);
    let (per_column, column_w) = (legend.per_column().max(1), legend.column_w());
    root.draw(&Rectangle::new(
        [(rect.x0, rect.y0), (rect.x1, rect.y1)],
        WHITE.mix(0.9).filled(),
    ))
    .map_err(drawing)?;
    root.draw(&Rectangle::new(
        [(rect.x0, rect.y0), (rect.x1, rect.y1)],
        ShapeStyle::from(&RGBColor(0x80, 0x80, 0x80)),
    ))
    .map_err(drawing)?;
    let text_style = font(LEGEND_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (i, row) in rows.iter().enumerate() {
        let (column, row_in) = ((i / per_column) as i32, (i % per_column) as i32);
        let y = rect.y0 + LEGEND_PAD / 2 + row_in * row_h + row_h / 2;
        let x = rect.x0 + LEGEND_PAD + column * column_w;
        match row.sample {
            LegendSample::Marker(marker, color) => root
                .draw(&Glyph {
                    at: (x + LEGEND_SAMPLE / 2, y),
                    marker,
                    color,
                })
                .map_err(drawing)?,
            LegendSample::Line(dash, color) => {
                let style = ShapeStyle::from(&color).stroke_width(2);
                let line = vec![(x, y), (x + LEGEND_SAMPLE, y)];
                if let Some((on, off)) = dash {
                    root.draw(&DashedPathElement::new(line, on, off, style))
                        .map_err(drawing)?;
                } else {
                    root.draw(&PathElement::new(line, style)).map_err(drawing)?;
                }
            }
            LegendSample::ErrorBar => {
                let (cx, half) = (x + LEGEND_SAMPLE / 2, row_h / 2 - 2);
                let cap = |end: i32| [(cx - ERROR_CAP, end), (cx + ERROR_CAP, end)];
                let mut ends = vec![(cx, y - half), (cx, y + half)];
                ends.extend(cap(y - half));
                ends.extend(cap(y + half));
                root.draw(&Lines {
                    ends,
                    color: RGBColor(0x60, 0x60, 0x60),
                })
                .map_err(drawing)?;
            }
        }
        root.draw(&Text::new(
            row.label.clone(),
            (x + LEGEND_SAMPLE + LEGEND_PAD, y),
            text_style.clone(),
        ))
        .map_err(drawing)?;
    }
    Ok(())
}

pub(super) fn draw_notes(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    rect: Rect,
    notes: &[String],
) -> Result<(), PlotError> {
    root.draw(&Rectangle::new(
        [(rect.x0, rect.y0), (rect.x1, rect.y1)],
        WHITE.mix(0.9).filled(),
    ))
    .map_err(drawing)?;
    let line_h = (NOTE_PX * 1.4).round() as i32;
    let style = font(NOTE_PX)
        .color(&RGBColor(0x40, 0x40, 0x40))
        .pos(Pos::new(HPos::Left, VPos::Center));
    for (i, note) in notes.iter().enumerate() {
        let y = rect.y0 + LEGEND_PAD / 2 + i as i32 * line_h + line_h / 2;
        root.draw(&Text::new(
            note.clone(),
            (rect.x0 + LEGEND_PAD, y),
            style.clone(),
        ))
        .map_err(drawing)?;
    }
    Ok(())
}

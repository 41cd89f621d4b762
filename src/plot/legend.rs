//! The legend (a sample and a label per series and curve) and the notes, in boxes on the
//! plotting area.

use super::layout::Rect;
use super::marker::Glyph;
use super::style::{drawing, font, LEGEND_PAD, LEGEND_PX, LEGEND_SAMPLE, NOTE_PX};
use super::{Marker, PlotError};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

pub(super) enum LegendSample {
    Marker(Marker, RGBColor),
    Line(bool, RGBColor),
}

pub(super) struct LegendRow {
    pub(super) label: String,
    pub(super) sample: LegendSample,
}

pub(super) fn draw_legend(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    rect: Rect,
    rows: &[LegendRow],
    row_h: i32,
) -> Result<(), PlotError> {
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
        let y = rect.y0 + LEGEND_PAD / 2 + i as i32 * row_h + row_h / 2;
        let x = rect.x0 + LEGEND_PAD;
        match row.sample {
            LegendSample::Marker(marker, color) => root
                .draw(&Glyph {
                    at: (x + LEGEND_SAMPLE / 2, y),
                    marker,
                    color,
                })
                .map_err(drawing)?,
            LegendSample::Line(dashed, color) => {
                let style = ShapeStyle::from(&color).stroke_width(2);
                let line = vec![(x, y), (x + LEGEND_SAMPLE, y)];
                if dashed {
                    root.draw(&DashedPathElement::new(line, 9, 6, style))
                        .map_err(drawing)?;
                } else {
                    root.draw(&PathElement::new(line, style)).map_err(drawing)?;
                }
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

//! Marker glyphs: a hollow shape per data point, the same in the legend.

use super::style::MARKER_R;
use super::Marker;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters_backend::{BackendCoord, DrawingErrorKind};

/// One marker glyph at a position (data or pixel coordinates).
pub(super) struct Glyph<C> {
    pub(super) at: C,
    pub(super) marker: Marker,
    pub(super) color: RGBColor,
}

impl<'a, C> PointCollection<'a, C> for &'a Glyph<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> std::iter::Once<&'a C> {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for Glyph<C> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let Some((x, y)) = pos.next() else {
            return Ok(());
        };
        let style = ShapeStyle::from(&self.color).stroke_width(2);
        let r = MARKER_R;
        match self.marker {
            Marker::Circle => backend.draw_circle((x, y), r as u32, &style, false),
            Marker::Square => backend.draw_rect(
                (x - r + 1, y - r + 1),
                (x + r - 1, y + r - 1),
                &style,
                false,
            ),
            Marker::Triangle => backend.draw_path(
                [
                    (x, y - r - 1),
                    (x + r + 1, y + r - 1),
                    (x - r - 1, y + r - 1),
                    (x, y - r - 1),
                ],
                &style,
            ),
            Marker::Diamond => backend.draw_path(
                [
                    (x, y - r - 1),
                    (x + r + 1, y),
                    (x, y + r + 1),
                    (x - r - 1, y),
                    (x, y - r - 1),
                ],
                &style,
            ),
            Marker::Cross => {
                backend.draw_line((x - r, y - r), (x + r, y + r), &style)?;
                backend.draw_line((x - r, y + r), (x + r, y - r), &style)
            }
        }
    }
}

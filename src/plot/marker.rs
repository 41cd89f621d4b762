//! Marker glyphs: a hollow shape per data point, the same in the legend; and the error bars
//! beneath them.

use super::style::{ERROR_CAP, MARKER_R};
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

/// One end of an error bar in pixels: its y, and whether it is the bar's own end (capped) or
/// where the plotting area cut the bar (no cap: the bar goes on).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct BarEnd {
    pub(super) y: i32,
    pub(super) own: bool,
}

/// A vertical error bar of the point `at`, in pixels (y grows downwards, so `top` is y + e).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct ErrorBar {
    pub(super) at: BackendCoord,
    pub(super) top: BarEnd,
    pub(super) bottom: BarEnd,
}

impl ErrorBar {
    /// The lines that draw the bar: the bar from bottom to top, then a cap of half-width
    /// [`ERROR_CAP`] at each own end, cut to the columns `x_limits` of the plotting area.
    /// Nothing when neither arm reaches beyond the marker radius (the bar would hide under the
    /// marker); no cap on an arm that does not (the cap would sit on the marker).
    pub(super) fn strokes(&self, x_limits: (i32, i32)) -> Vec<(BackendCoord, BackendCoord)> {
        let (x, y) = self.at;
        let (up, down) = (y - self.top.y, self.bottom.y - y);
        if up.max(down) <= MARKER_R {
            return Vec::new();
        }
        let cap = |end: i32| {
            (
                ((x - ERROR_CAP).max(x_limits.0), end),
                ((x + ERROR_CAP).min(x_limits.1), end),
            )
        };
        let mut strokes = vec![((x, self.bottom.y), (x, self.top.y))];
        if self.top.own && up > MARKER_R {
            strokes.push(cap(self.top.y));
        }
        if self.bottom.own && down > MARKER_R {
            strokes.push(cap(self.bottom.y));
        }
        strokes
    }
}

/// Straight lines in pixel coordinates, one SVG `<line>` each, 1 px wide in one colour: the
/// error bars of a series.
pub(super) struct Lines {
    /// The ends of the lines, two by two.
    pub(super) ends: Vec<BackendCoord>,
    pub(super) color: RGBColor,
}

impl<'a> PointCollection<'a, BackendCoord> for &'a Lines {
    type Point = &'a BackendCoord;
    type IntoIter = std::slice::Iter<'a, BackendCoord>;
    fn point_iter(self) -> std::slice::Iter<'a, BackendCoord> {
        self.ends.iter()
    }
}

impl<DB: DrawingBackend> Drawable<DB> for Lines {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut pos: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        let style = ShapeStyle::from(&self.color).stroke_width(1);
        while let (Some(a), Some(b)) = (pos.next(), pos.next()) {
            backend.draw_line(a, b, &style)?;
        }
        Ok(())
    }
}

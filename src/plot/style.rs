//! Fonts, sizes and colours of every figure (pixels of the SVG). plotters divides its font
//! sizes by 1.24 when writing `font-size`, so sizes are multiplied by 1.24 where they are
//! handed to plotters.

use super::PlotError;
use plotters::prelude::*;

pub(super) const PLOTTERS_FONT_SCALE: f64 = 1.24;
pub(super) const FONT: &str = "sans-serif";
pub(super) const TITLE_PX: f64 = 20.0;
pub(super) const DESC_PX: f64 = 18.0;
pub(super) const TICK_PX: f64 = 15.0;
pub(super) const LEGEND_PX: f64 = 15.0;
pub(super) const NOTE_PX: f64 = 14.0;
pub(super) const MARKER_R: i32 = 4;
/// Half-width of an error bar's caps: narrower than the markers.
pub(super) const ERROR_CAP: i32 = 3;
pub(super) const LEGEND_SAMPLE: i32 = 30;
pub(super) const LEGEND_PAD: i32 = 8;

/// Series colours (Okabe-Ito, distinguishable with common colour-vision deficiencies).
pub(super) const SERIES_COLORS: [RGBColor; 7] = [
    RGBColor(0x00, 0x72, 0xB2),
    RGBColor(0xD5, 0x5E, 0x00),
    RGBColor(0x00, 0x9E, 0x73),
    RGBColor(0xCC, 0x79, 0xA7),
    RGBColor(0xE6, 0x9F, 0x00),
    RGBColor(0x56, 0xB4, 0xE9),
    RGBColor(0x00, 0x00, 0x00),
];
/// Curve colours: the first (Eq. 13) black, then greys.
pub(super) const CURVE_COLORS: [RGBColor; 3] = [
    RGBColor(0x00, 0x00, 0x00),
    RGBColor(0x66, 0x66, 0x66),
    RGBColor(0xAA, 0xAA, 0xAA),
];

pub(super) fn series_color(i: usize) -> RGBColor {
    SERIES_COLORS[i % SERIES_COLORS.len()]
}

pub(super) fn curve_color(i: usize) -> RGBColor {
    CURVE_COLORS[i % CURVE_COLORS.len()]
}

pub(super) fn font(px: f64) -> TextStyle<'static> {
    (FONT, px * PLOTTERS_FONT_SCALE).into_font().color(&BLACK)
}

pub(super) fn drawing<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Drawing(e.to_string())
}

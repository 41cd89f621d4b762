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

/// Series colours: Okabe-Ito's seven on white (distinguishable with common colour-vision
/// deficiencies), then three of Paul Tol's muted scheme (wine, olive, indigo), so that ten
/// series (the accuracy study's eight) never share one.
pub(super) const SERIES_COLORS: [RGBColor; 10] = [
    RGBColor(0x00, 0x72, 0xB2),
    RGBColor(0xD5, 0x5E, 0x00),
    RGBColor(0x00, 0x9E, 0x73),
    RGBColor(0xCC, 0x79, 0xA7),
    RGBColor(0xE6, 0x9F, 0x00),
    RGBColor(0x56, 0xB4, 0xE9),
    RGBColor(0x00, 0x00, 0x00),
    RGBColor(0x88, 0x22, 0x55),
    RGBColor(0x99, 0x99, 0x33),
    RGBColor(0x33, 0x22, 0x88),
];
/// Curve colours: the first black, then greys and three dark hues; with [`curve_dashes`]
/// every curve of a figure differs from the others in colour and in dash.
pub(super) const CURVE_COLORS: [RGBColor; 6] = [
    RGBColor(0x00, 0x00, 0x00),
    RGBColor(0x66, 0x66, 0x66),
    RGBColor(0xAA, 0xAA, 0xAA),
    RGBColor(0x7B, 0x32, 0x94),
    RGBColor(0x8C, 0x51, 0x0A),
    RGBColor(0x01, 0x66, 0x5E),
];
/// Dash patterns (on, off pixels; `None` solid) of the curves drawn solid, in turn.
const SOLID_DASHES: [Option<(u32, u32)>; 5] = [
    None,
    Some((2, 4)),
    Some((14, 4)),
    Some((6, 3)),
    Some((22, 6)),
];
/// Dash patterns of the curves drawn dashed (Eq. 13's first), in turn.
const DASHED_DASHES: [Option<(u32, u32)>; 3] = [Some((9, 6)), Some((4, 8)), Some((16, 8))];

/// The dash of each of `curves`: the solid ones take [`SOLID_DASHES`] in turn, the dashed
/// ones [`DASHED_DASHES`], so that no two curves of a figure share one (up to five and three).
pub(super) fn curve_dashes(curves: &[super::Curve]) -> Vec<Option<(u32, u32)>> {
    let (mut solid, mut dashed) = (0, 0);
    curves
        .iter()
        .map(|c| {
            if c.dashed {
                dashed += 1;
                DASHED_DASHES[(dashed - 1) % DASHED_DASHES.len()]
            } else {
                solid += 1;
                SOLID_DASHES[(solid - 1) % SOLID_DASHES.len()]
            }
        })
        .collect()
}

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

#[cfg(test)]
mod tests {
    use super::SERIES_COLORS;
    use crate::plot::Marker;

    #[test]
    fn no_two_of_fifty_series_share_colour_and_marker() {
        let looks: Vec<(usize, Marker)> = (0..50)
            .map(|i| (i % SERIES_COLORS.len(), Marker::of_series(i)))
            .collect();
        for (i, a) in looks.iter().enumerate() {
            assert!(
                !looks[..i].contains(a),
                "series {i} looks like an earlier one"
            );
        }
        // The eleventh series (the accuracy study's line contact) is not the first's.
        assert_ne!(Marker::of_series(10), Marker::of_series(0));
    }
}

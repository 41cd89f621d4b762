//! Deterministic SVG figures in the paper's form, drawn with plotters' SVG backend.
//!
//! # Text without fonts
//!
//! plotters is built with `default-features = false` and only `svg_backend`, so no font backend
//! (`ttf` with font-kit, or `ab_glyph`) is compiled in and plotters falls back to its built-in
//! "naive" font: a width estimate computed from the string alone. The SVG backend does not draw
//! glyphs; it writes each string as an SVG `<text font-family="sans-serif">` element and leaves
//! the glyphs to the viewer. Nothing looks at the host's fonts, so the same [`Figure`] gives the
//! same bytes on any machine (with font-kit, measured glyph widths of whatever font the host
//! has move the layout: plotters issue #538). The widths this module needs itself (label areas,
//! legend box) come from [`text_width`], a fixed estimate for a sans-serif font such as
//! DejaVu Sans, not from a font file.
//!
//! # Text markup
//!
//! Every string of a figure (title, axis labels, legend labels, note) may contain `_{...}` for a
//! subscript and `^{...}` for a superscript; they become `<tspan>` elements shifted with `dy`,
//! which browsers and librsvg all honour. An overbar is the combining macron U+0304 after the
//! letter, as in [`MU_BAR`] and [`TAU_C`].
//!
//! # Axes
//!
//! Log axes plot `log10` of the value on a linear pixel scale with ticks at decades (every
//! second or more decade when the range spans many), labelled as plain numbers between 0.001
//! and 10000 and as powers of ten otherwise. Points that are not finite, or not positive on a
//! log axis, are skipped and counted ([`Rendered`]), and the figure itself says how many were
//! left out; they never make rendering fail or panic.

use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint, Ranged};
use plotters::coord::Shift;
use plotters::element::{DashedPathElement, Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::{BackendCoord, DrawingErrorKind};
use std::fmt::Write as _;

/// Canvas width in pixels.
pub const WIDTH: u32 = 800;
/// Canvas height in pixels.
pub const HEIGHT: u32 = 600;

/// Reduced friction coefficient, mu-bar (dimensionless), with an overbar.
pub const MU_BAR: &str = "μ\u{304}";
/// Characteristic shear stress, tau_c-bar (dimensionless), Eq. (12).
pub const TAU_C: &str = "τ\u{304}_{c}";
/// The severity group of Fig. 1, S-bar^(1/4) M L^3 (dimensionless).
pub const SEVERITY: &str = "S\u{304}^{1/4} M L^{3}";

/// Scale of an axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    /// Linear.
    #[default]
    Linear,
    /// Base-10 logarithmic; only positive values can be shown.
    Log,
}

/// Marker shape of a data series, drawn hollow so that dense clouds stay readable.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Marker {
    /// Circle (one SVG `<circle>` per point).
    #[default]
    Circle,
    /// Square (one `<rect>`).
    Square,
    /// Triangle pointing up (one closed `<polyline>`).
    Triangle,
    /// Diagonal cross (two `<line>`s).
    Cross,
    /// Diamond (one closed `<polyline>`).
    Diamond,
}

impl Marker {
    /// All shapes, in the order [`Marker::nth`] cycles through them.
    pub const ALL: [Marker; 5] = [
        Marker::Circle,
        Marker::Square,
        Marker::Triangle,
        Marker::Cross,
        Marker::Diamond,
    ];

    /// The `i`-th shape of [`Marker::ALL`], cycling: a distinct marker per series.
    pub fn nth(i: usize) -> Marker {
        Marker::ALL[i % Marker::ALL.len()]
    }
}

/// A set of data points drawn as markers (no connecting line).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Legend label (may use the text markup of this module).
    pub label: String,
    /// Data points (x, y).
    pub points: Vec<(f64, f64)>,
    /// Marker shape.
    pub marker: Marker,
}

/// A model curve drawn as a line through its points, in order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Curve {
    /// Legend label (may use the text markup of this module).
    pub label: String,
    /// Points (x, y) along the curve; a non-finite point breaks the line.
    pub points: Vec<(f64, f64)>,
    /// Dashed (the paper draws Eq. (13) dashed) or solid.
    pub dashed: bool,
}

/// One figure: axes, data series, model curves and an optional note.
///
/// The paper's figures: Fig. 1 is mu-bar against [`SEVERITY`] on a log x axis. Figs. 2 and 3
/// plot mu-bar against [`TAU_C`] with Eq. (13) dashed; tau_c spans several decades there, so a
/// log x axis is the sensible choice (a linear one crowds all but the largest values against
/// the origin). Figs. 4 to 7 are log-linear as the paper says: log tau_c, linear mu-bar, with
/// Eq. (13) dashed ([`mastercurve`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Figure {
    /// Title above the plot.
    pub title: String,
    /// Horizontal axis label, symbols as in the paper (e.g. [`TAU_C`]).
    pub x_label: String,
    /// Vertical axis label (e.g. [`MU_BAR`]).
    pub y_label: String,
    /// Horizontal axis scale.
    pub x_scale: Scale,
    /// Vertical axis scale.
    pub y_scale: Scale,
    /// Horizontal range (min, max); `None` fits the data with a margin.
    pub x_range: Option<(f64, f64)>,
    /// Vertical range (min, max); `None` fits the data with a margin (from 0 when the data
    /// are all non-negative and the margin would cross 0).
    pub y_range: Option<(f64, f64)>,
    /// Data series, one legend entry each.
    pub series: Vec<Series>,
    /// Model curves, one legend entry each, after the series.
    pub curves: Vec<Curve>,
    /// A line of text drawn on the plot, e.g. "no measured dataset included".
    pub note: Option<String>,
}

/// Why a figure could not be drawn.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    /// An explicit axis range is unusable.
    #[error("{axis} axis range ({min}, {max}) is invalid: {reason}")]
    InvalidRange {
        /// "x" or "y".
        axis: &'static str,
        /// Given minimum.
        min: f64,
        /// Given maximum.
        max: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// plotters failed to draw (it draws into a string, so this is not expected).
    #[error("drawing the figure failed: {0}")]
    Drawing(String),
}

/// A rendered figure and what was left out of it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rendered {
    /// The SVG document.
    pub svg: String,
    /// Series points not drawn because a coordinate is NaN or infinite, or not positive on a
    /// log axis. The figure says how many.
    pub skipped_points: usize,
    /// Series points outside an explicit axis range (not drawn). The figure says how many.
    pub outside_range: usize,
    /// Curve points dropped for the same reasons as `skipped_points` (the curve is broken there).
    pub skipped_curve_points: usize,
}

/// Renders a figure as an SVG document of [`WIDTH`] x [`HEIGHT`] pixels.
///
/// Same figure, same bytes. Unplottable points are skipped (see [`render`] for the counts).
pub fn render_svg(fig: &Figure) -> Result<String, PlotError> {
    render(fig).map(|r| r.svg)
}

/// Mastercurve Eq. (13) with constant `c`: mu-bar = asinh(tau_c / c), sampled at `n` points
/// (at least 2) spaced uniformly in log tau_c over [`x_min`, `x_max`], dashed.
///
/// The label reads "Eq. (13): ..." for c = 5 and "fit: ..." otherwise. Bounds that are not
/// finite with 0 < `x_min` < `x_max`, or a `c` that is not finite and positive, give a curve
/// without points: nothing is drawn for it.
pub fn mastercurve(x_min: f64, x_max: f64, c: f64, n: usize) -> Curve {
    let is_eq13 = (c - 5.0).abs() < 1e-12;
    let label = if is_eq13 {
        format!("Eq. (13): {MU_BAR} = asinh({TAU_C}/5)")
    } else {
        format!("fit: {MU_BAR} = asinh({TAU_C}/{})", significant(c, 3))
    };
    let valid = x_min.is_finite()
        && x_max.is_finite()
        && x_min > 0.0
        && x_max > x_min
        && c.is_finite()
        && c > 0.0;
    let points = if valid {
        let n = n.max(2);
        let (l0, l1) = (x_min.log10(), x_max.log10());
        (0..n)
            .map(|i| {
                let t = i as f64 / (n - 1) as f64;
                let x = if i == 0 {
                    x_min
                } else if i == n - 1 {
                    x_max
                } else {
                    10f64.powf(l0 + t * (l1 - l0))
                };
                (x, (x / c).asinh())
            })
            .collect()
    } else {
        Vec::new()
    };
    Curve {
        label,
        points,
        dashed: true,
    }
}

/// Formats `v` with `digits` significant digits, without trailing zeros ("4.93", "5", "0.012").
fn significant(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let mag = v.abs().log10().floor() as i32;
    let decimals = (digits - 1 - mag).max(0) as usize;
    let s = format!("{v:.decimals$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".to_string()
    } else {
        s
    }
}

// ---------------------------------------------------------------------------------------------
// Layout constants (pixels of the SVG; plotters divides its font sizes by 1.24 when writing
// `font-size`, so sizes below are multiplied by 1.24 where they are handed to plotters).

const PLOTTERS_FONT_SCALE: f64 = 1.24;
const FONT: &str = "sans-serif";
const TITLE_PX: f64 = 20.0;
const DESC_PX: f64 = 18.0;
const TICK_PX: f64 = 15.0;
const LEGEND_PX: f64 = 15.0;
const NOTE_PX: f64 = 14.0;
const MARKER_R: i32 = 4;
const LEGEND_SAMPLE: i32 = 30;
const LEGEND_PAD: i32 = 8;

/// Series colours (Okabe-Ito, distinguishable with common colour-vision deficiencies).
const SERIES_COLORS: [RGBColor; 7] = [
    RGBColor(0x00, 0x72, 0xB2),
    RGBColor(0xD5, 0x5E, 0x00),
    RGBColor(0x00, 0x9E, 0x73),
    RGBColor(0xCC, 0x79, 0xA7),
    RGBColor(0xE6, 0x9F, 0x00),
    RGBColor(0x56, 0xB4, 0xE9),
    RGBColor(0x00, 0x00, 0x00),
];
/// Curve colours: the first (Eq. 13) black, then greys.
const CURVE_COLORS: [RGBColor; 3] = [
    RGBColor(0x00, 0x00, 0x00),
    RGBColor(0x66, 0x66, 0x66),
    RGBColor(0xAA, 0xAA, 0xAA),
];

fn series_color(i: usize) -> RGBColor {
    SERIES_COLORS[i % SERIES_COLORS.len()]
}

fn curve_color(i: usize) -> RGBColor {
    CURVE_COLORS[i % CURVE_COLORS.len()]
}

fn font(px: f64) -> TextStyle<'static> {
    (FONT, px * PLOTTERS_FONT_SCALE).into_font().color(&BLACK)
}

fn drawing<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Drawing(e.to_string())
}

// ---------------------------------------------------------------------------------------------
// Axes: value <-> plotted coordinate, range and ticks.

/// Plotted coordinate of a value: itself (linear) or its log10 (log); `None` if unplottable.
fn to_plot(scale: Scale, v: f64) -> Option<f64> {
    match scale {
        Scale::Linear if v.is_finite() => Some(v),
        Scale::Log if v.is_finite() && v > 0.0 => Some(v.log10()),
        _ => None,
    }
}

/// One axis in plotted coordinates: range, labelled ticks and unlabelled grid lines.
#[derive(Debug, Clone, PartialEq)]
struct AxisPlan {
    lo: f64,
    hi: f64,
    majors: Vec<(f64, String)>,
    minors: Vec<f64>,
}

impl AxisPlan {
    fn label_at(&self, u: f64) -> String {
        self.majors
            .iter()
            .find(|(t, _)| (t - u).abs() <= 1e-9 * t.abs().max(1.0))
            .map(|(_, s)| s.clone())
            .unwrap_or_default()
    }

    fn contains(&self, u: f64) -> bool {
        u >= self.lo && u <= self.hi
    }
}

/// The axis as a plotters coordinate: linear in plotted units, grid lines and labels at our
/// ticks. (plotters' `WithKeyPoints` over `f64` lacks the value formatter its mesh needs.)
impl Ranged for AxisPlan {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        // `as` saturates (NaN gives 0): no panic on a degenerate value.
        limit.0 + (t * f64::from(limit.1 - limit.0)).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minors.clone()
        } else {
            self.majors.iter().map(|m| m.0).collect()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

fn plan_axis(
    axis: &'static str,
    scale: Scale,
    explicit: Option<(f64, f64)>,
    data: &[f64],
) -> Result<AxisPlan, PlotError> {
    let (lo, hi) = match explicit {
        Some((min, max)) => {
            let invalid = |reason| PlotError::InvalidRange {
                axis,
                min,
                max,
                reason,
            };
            if !(min.is_finite() && max.is_finite()) {
                return Err(invalid("bounds must be finite"));
            }
            if min >= max {
                return Err(invalid("minimum must be below maximum"));
            }
            if scale == Scale::Log && min <= 0.0 {
                return Err(invalid("a log axis needs a positive minimum"));
            }
            match scale {
                Scale::Linear => (min, max),
                Scale::Log => (min.log10(), max.log10()),
            }
        }
        None => auto_range(scale, data),
    };
    let (majors, minors) = match scale {
        Scale::Linear => linear_ticks(lo, hi),
        Scale::Log => log_ticks(lo, hi),
    };
    Ok(AxisPlan {
        lo,
        hi,
        majors,
        minors,
    })
}

/// Data range in plotted coordinates with a 4 % margin each side.
fn auto_range(scale: Scale, data: &[f64]) -> (f64, f64) {
    let (min, max) = data
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if min > max {
        // No data at all: a unit range (0..1, or 1..10 on a log axis).
        return (0.0, 1.0);
    }
    let span = max - min;
    let pad = if span > 0.0 {
        match scale {
            Scale::Linear => 0.04 * span,
            Scale::Log => (0.04 * span).max(0.05),
        }
    } else {
        match scale {
            Scale::Linear if min != 0.0 => 0.1 * min.abs(),
            Scale::Linear => 1.0,
            Scale::Log => 0.5,
        }
    };
    let mut lo = min - pad;
    let hi = max + pad;
    if scale == Scale::Linear && min >= 0.0 && lo < 0.0 {
        lo = 0.0;
    }
    (lo, hi)
}

/// Ticks at 1, 2 or 5 times a power of ten, five to ten of them.
fn linear_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let raw = (hi - lo) / 7.0;
    let mut exp = raw.log10().floor() as i32;
    let f = raw / 10f64.powi(exp);
    let m = if f <= 1.0 {
        1.0
    } else if f <= 2.0 {
        2.0
    } else if f <= 5.0 {
        5.0
    } else {
        exp += 1;
        1.0
    };
    let step = m * 10f64.powi(exp);
    let decimals = (-exp).max(0) as usize;
    let scientific = step < 1e-4 || hi.abs().max(lo.abs()) >= 1e6;
    let k0 = (lo / step - 1e-9).ceil() as i64;
    let k1 = (hi / step + 1e-9).floor() as i64;
    let majors = (k0..=k1)
        .take(100)
        .map(|k| {
            let v = k as f64 * step;
            let label = if k == 0 {
                "0".to_string()
            } else if scientific {
                let s = format!("{v:.1e}");
                s.replace("e-", "e−").replace('-', "−")
            } else {
                format!("{v:.decimals$}").replace('-', "−")
            };
            (v, label)
        })
        .collect();
    (majors, Vec::new())
}

/// Ticks on a log axis, in log10 units: decades (every `stride`-th decade when there are more
/// than eight), or 1-2-5 and then 1..9 multiples when fewer than three decades are in range.
fn log_ticks(lo: f64, hi: f64) -> (Vec<(f64, String)>, Vec<f64>) {
    let d0 = (lo - 1e-9).ceil() as i64;
    let d1 = (hi + 1e-9).floor() as i64;
    let inside = |u: f64| u >= lo - 1e-9 && u <= hi + 1e-9;
    let mut majors: Vec<(i64, f64)> = Vec::new(); // (decade, mantissa)
    let mut minors = Vec::new();
    if d1 - d0 + 1 >= 3 {
        let n = d1 - d0 + 1;
        let stride = (n + 7) / 8;
        for d in d0..=d1 {
            if d.rem_euclid(stride) == 0 {
                majors.push((d, 1.0));
            } else {
                minors.push(d as f64);
            }
        }
        if stride == 1 && n <= 7 {
            for d in (d0 - 1)..=d1 {
                for m in 2..=9 {
                    let u = d as f64 + f64::from(m).log10();
                    if inside(u) {
                        minors.push(u);
                    }
                }
            }
        }
    } else {
        let (e0, e1) = ((lo - 1e-9).floor() as i64, (hi + 1e-9).ceil() as i64);
        for mantissas in [&[1, 2, 5][..], &[1, 2, 3, 4, 5, 6, 7, 8, 9][..]] {
            majors.clear();
            for d in e0..=e1 {
                for &m in mantissas {
                    if inside(d as f64 + f64::from(m).log10()) {
                        majors.push((d, f64::from(m)));
                    }
                }
            }
            if majors.len() >= 3 {
                break;
            }
        }
        for d in e0..=e1 {
            for m in 1..=9 {
                let u = d as f64 + f64::from(m).log10();
                let is_major = majors
                    .iter()
                    .any(|&(md, mm)| md == d && (mm - f64::from(m)).abs() < 0.5);
                if inside(u) && !is_major {
                    minors.push(u);
                }
            }
        }
    }
    let plain = majors.iter().all(|&(d, _)| (-3..=4).contains(&d));
    let majors = majors
        .into_iter()
        .map(|(d, m)| {
            let u = d as f64 + m.log10();
            let label = if plain {
                let v = m * 10f64.powi(d as i32);
                format!("{v:.*}", (-d).max(0) as usize)
            } else {
                let exp = if d < 0 {
                    format!("−{}", -d)
                } else {
                    d.to_string()
                };
                if m == 1.0 {
                    format!("10^{{{exp}}}")
                } else {
                    format!("{m}×10^{{{exp}}}")
                }
            };
            (u, label)
        })
        .collect();
    (majors, minors)
}

// ---------------------------------------------------------------------------------------------
// Data preparation.

/// Series in plotted coordinates, and what was left out.
struct Prepared {
    series: Vec<Vec<(f64, f64)>>,
    curves: Vec<Vec<Option<(f64, f64)>>>,
    skipped_points: usize,
    skipped_curve_points: usize,
}

fn prepare(fig: &Figure) -> Prepared {
    let mut skipped_points = 0;
    let mut skipped_curve_points = 0;
    let map = |&(x, y): &(f64, f64)| Some((to_plot(fig.x_scale, x)?, to_plot(fig.y_scale, y)?));
    let series = fig
        .series
        .iter()
        .map(|s| {
            let pts: Vec<_> = s.points.iter().filter_map(map).collect();
            skipped_points += s.points.len() - pts.len();
            pts
        })
        .collect();
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
        curves,
        skipped_points,
        skipped_curve_points,
    }
}

/// Clips the segment a-b to the rectangle [x0, x1] x [y0, y1] (Liang-Barsky).
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
    Some((at(t0), at(t1)))
}

/// A curve's visible pieces in plotted coordinates: broken at unplottable points, clipped to
/// the axes.
fn visible_pieces(pts: &[Option<(f64, f64)>], x: &AxisPlan, y: &AxisPlan) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    for w in pts.windows(2) {
        let (Some(a), Some(b)) = (w[0], w[1]) else {
            if current.len() >= 2 {
                pieces.push(std::mem::take(&mut current));
            }
            current.clear();
            continue;
        };
        match clip_segment(a, b, (x.lo, x.hi), (y.lo, y.hi)) {
            Some((p, q)) => {
                if current.last() != Some(&p) {
                    if current.len() >= 2 {
                        pieces.push(std::mem::take(&mut current));
                    }
                    current.clear();
                    current.push(p);
                }
                current.push(q);
            }
            None => {
                if current.len() >= 2 {
                    pieces.push(std::mem::take(&mut current));
                }
                current.clear();
            }
        }
    }
    if current.len() >= 2 {
        pieces.push(current);
    }
    if pts.len() == 1 {
        if let Some(p) = pts[0] {
            if x.contains(p.0) && y.contains(p.1) {
                pieces.push(vec![p, p]);
            }
        }
    }
    pieces
}

// ---------------------------------------------------------------------------------------------
// Markers.

/// One marker glyph at a position (data or pixel coordinates).
struct Glyph<C> {
    at: C,
    marker: Marker,
    color: RGBColor,
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

// ---------------------------------------------------------------------------------------------
// Rendering.

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

    let visible: Vec<Vec<(f64, f64)>> = prepared
        .series
        .iter()
        .map(|pts| {
            pts.iter()
                .copied()
                .filter(|&(u, v)| x_axis.contains(u) && y_axis.contains(v))
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
        draw(&root, fig, &x_axis, &y_axis, &visible, &pieces, &notes)?;
        root.present().map_err(drawing)?;
    }
    Ok(Rendered {
        svg: apply_markup(&buf),
        skipped_points: prepared.skipped_points,
        outside_range,
        skipped_curve_points: prepared.skipped_curve_points,
    })
}

fn draw(
    root: &DrawingArea<SVGBackend<'_>, Shift>,
    fig: &Figure,
    x_axis: &AxisPlan,
    y_axis: &AxisPlan,
    series: &[Vec<(f64, f64)>],
    curves: &[Vec<Vec<(f64, f64)>>],
    notes: &[String],
) -> Result<(), PlotError> {
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
    for (i, pts) in series.iter().enumerate() {
        let (marker, color) = (fig.series[i].marker, series_color(i));
        chart
            .draw_series(pts.iter().map(|&at| Glyph { at, marker, color }))
            .map_err(drawing)?;
    }

    // Legend and notes go into the emptiest corners of the plotting area.
    let (px, py) = chart.plotting_area().get_pixel_range();
    let area = Rect {
        x0: px.start,
        x1: px.end,
        y0: py.start,
        y1: py.end,
    };
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
        let lines = pixel_lines
            .iter()
            .flat_map(|l| l.windows(2))
            .filter(|w| grown.meets_segment(w[0], w[1]))
            .count();
        points + 5 * lines
    };

    let legend_rows: Vec<LegendRow> = fig
        .series
        .iter()
        .enumerate()
        .map(|(i, s)| LegendRow {
            label: s.label.clone(),
            sample: Sample::Marker(s.marker, series_color(i)),
        })
        .chain(fig.curves.iter().enumerate().map(|(i, c)| LegendRow {
            label: c.label.clone(),
            sample: Sample::Line(c.dashed, curve_color(i)),
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

/// A pixel rectangle, x0 < x1 and y0 < y1 (y grows downwards).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Rect {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Corner {
    UpperLeft,
    UpperRight,
    LowerRight,
    LowerLeft,
}

impl Rect {
    const INSET: i32 = 10;

    fn grow(&self, by: i32) -> Rect {
        Rect {
            x0: self.x0 - by,
            x1: self.x1 + by,
            y0: self.y0 - by,
            y1: self.y1 + by,
        }
    }

    fn contains(&self, (x, y): (i32, i32)) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    fn meets_segment(&self, a: (i32, i32), b: (i32, i32)) -> bool {
        let f = |p: (i32, i32)| (f64::from(p.0), f64::from(p.1));
        clip_segment(
            f(a),
            f(b),
            (f64::from(self.x0), f64::from(self.x1)),
            (f64::from(self.y0), f64::from(self.y1)),
        )
        .is_some()
    }

    /// A box of `size` in `corner`, inset from the edges.
    fn place(&self, corner: Corner, (w, h): (i32, i32)) -> Rect {
        let left = self.x0 + Self::INSET;
        let right = self.x1 - Self::INSET - w;
        let top = self.y0 + Self::INSET;
        let bottom = self.y1 - Self::INSET - h;
        let (x0, y0) = match corner {
            Corner::UpperLeft => (left, top),
            Corner::UpperRight => (right, top),
            Corner::LowerRight => (right, bottom),
            Corner::LowerLeft => (left, bottom),
        };
        Rect {
            x0,
            x1: x0 + w,
            y0,
            y1: y0 + h,
        }
    }

    fn centred(&self, (w, h): (i32, i32)) -> Rect {
        let x0 = (self.x0 + self.x1 - w) / 2;
        let y0 = (self.y0 + self.y1 - h) / 2;
        Rect {
            x0,
            x1: x0 + w,
            y0,
            y1: y0 + h,
        }
    }

    /// The corner where a box of `size` covers the fewest data (ties: upper left first).
    fn emptiest_corner(
        &self,
        size: (i32, i32),
        exclude: Option<Corner>,
        crowding: &dyn Fn(&Rect) -> usize,
    ) -> Corner {
        [
            Corner::UpperLeft,
            Corner::UpperRight,
            Corner::LowerRight,
            Corner::LowerLeft,
        ]
        .into_iter()
        .filter(|c| Some(*c) != exclude)
        .min_by_key(|c| crowding(&self.place(*c, size)))
        .unwrap_or(Corner::UpperLeft)
    }
}

enum Sample {
    Marker(Marker, RGBColor),
    Line(bool, RGBColor),
}

struct LegendRow {
    label: String,
    sample: Sample,
}

fn draw_legend(
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
            Sample::Marker(marker, color) => root
                .draw(&Glyph {
                    at: (x + LEGEND_SAMPLE / 2, y),
                    marker,
                    color,
                })
                .map_err(drawing)?,
            Sample::Line(dashed, color) => {
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

fn draw_notes(
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

// ---------------------------------------------------------------------------------------------
// Text: markup and width estimate.

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Baseline {
    Base,
    Sub,
    Sup,
}

/// Splits text into runs at `_{...}` and `^{...}` (an unclosed brace runs to the end).
fn runs(text: &str) -> Vec<(Baseline, String)> {
    let mut out: Vec<(Baseline, String)> = vec![(Baseline::Base, String::new())];
    let mut chars = text.chars().peekable();
    let mut in_group = false;
    while let Some(c) = chars.next() {
        if !in_group && (c == '_' || c == '^') && chars.peek() == Some(&'{') {
            chars.next();
            let shift = if c == '_' {
                Baseline::Sub
            } else {
                Baseline::Sup
            };
            out.push((shift, String::new()));
            in_group = true;
        } else if in_group && c == '}' {
            out.push((Baseline::Base, String::new()));
            in_group = false;
        } else if let Some(last) = out.last_mut() {
            last.1.push(c);
        }
    }
    out.retain(|(_, s)| !s.is_empty());
    out
}

/// Estimated width in pixels of `text` (with markup) in a sans-serif font of `px` pixels.
///
/// Advance widths of DejaVu Sans rounded up a little (digits and most letters 0.6 em, spaces
/// 0.32 em, combining marks 0); sub- and superscripts at 72 %. Only the layout depends on it.
pub fn text_width(text: &str, px: f64) -> f64 {
    runs(text)
        .iter()
        .map(|(shift, s)| {
            let scale = if *shift == Baseline::Base { 1.0 } else { 0.72 };
            s.chars()
                .map(|c| match c {
                    '\u{300}'..='\u{36f}' => 0.0,
                    ' ' | '.' | ',' | ':' | ';' | 'i' | 'l' | 'j' | '|' | '\'' => 0.32,
                    '(' | ')' | '[' | ']' | 'f' | 't' | 'r' | '/' | '-' => 0.4,
                    'M' | 'W' | 'm' | 'w' | '×' | '=' | '+' | '−' => 0.84,
                    _ => 0.62,
                })
                .sum::<f64>()
                * px
                * scale
        })
        .sum()
}

/// Rewrites the markup of every `<text>` element of an SVG document into `<tspan>`s.
fn apply_markup(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len() + svg.len() / 16);
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        out.push_str(&rest[..start]);
        rest = &rest[start..];
        let Some(open_end) = rest.find('>') else {
            break;
        };
        let Some(close) = rest[open_end..].find("</text>") else {
            break;
        };
        let tag = &rest[..=open_end];
        let content = &rest[open_end + 1..open_end + close];
        out.push_str(tag);
        out.push_str(&tspans(content, font_size(tag)));
        rest = &rest[open_end + close..];
    }
    out.push_str(rest);
    out
}

/// The `font-size` attribute of a tag, or 16.
fn font_size(tag: &str) -> f64 {
    tag.split_once("font-size=\"")
        .and_then(|(_, after)| after.split('"').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or(16.0)
}

/// Text content (already XML-escaped) with markup turned into shifted, smaller `<tspan>`s.
fn tspans(content: &str, px: f64) -> String {
    if !content.contains("_{") && !content.contains("^{") {
        return content.to_string();
    }
    // Baseline offsets in tenths of a pixel, so the output has one fixed decimal.
    let offset = |s: Baseline| match s {
        Baseline::Base => 0,
        Baseline::Sub => (px * 3.0).round() as i64,
        Baseline::Sup => -(px * 4.5).round() as i64,
    };
    let tenths = |t: i64| {
        let sign = if t < 0 { "-" } else { "" };
        format!("{sign}{}.{}", t.abs() / 10, t.abs() % 10)
    };
    let small = (px * 7.2).round() as i64;
    let mut out = String::new();
    let mut current = 0i64;
    for (shift, text) in runs(content) {
        let target = offset(shift);
        if shift == Baseline::Base && target == current {
            out.push_str(&text);
            continue;
        }
        out.push_str("<tspan");
        if target != current {
            let _ = write!(out, " dy=\"{}\"", tenths(target - current));
        }
        if shift != Baseline::Base {
            let _ = write!(out, " font-size=\"{}\"", tenths(small));
        }
        let _ = write!(out, ">{text}</tspan>");
        current = target;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

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
                },
                Series {
                    label: "τ0 = 8 MPa".into(),
                    points: b,
                    marker: Marker::Square,
                },
            ],
            curves: vec![mastercurve(0.1, 3000.0, 5.0, 200)],
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
            curves: vec![mastercurve(0.1, 1e4, 5.0, 50)],
            note: Some("no measured dataset included".into()),
            ..Figure::default()
        };
        let svg = render_svg(&fig).expect("renders").replace('\n', "");
        assert!(svg.contains(">no measured dataset included</text>"));
    }

    #[test]
    fn mastercurve_samples_eq13_log_uniformly() {
        let c = mastercurve(0.01, 1e4, 5.0, 7);
        assert!(c.dashed);
        assert!(c.label.starts_with("Eq. (13)"));
        assert_eq!(c.points.len(), 7);
        assert_eq!(c.points[0].0, 0.01);
        assert_eq!(c.points[6].0, 1e4);
        for (i, &(x, y)) in c.points.iter().enumerate() {
            // log-uniform: one decade per step here; 1e-12 relative covers powf rounding.
            let expect = 10f64.powi(i as i32 - 2);
            assert!((x / expect - 1.0).abs() < 1e-12, "x[{i}] = {x}");
            assert!((y - (x / 5.0).asinh()).abs() < 1e-15);
        }
        let fit = mastercurve(0.1, 10.0, 4.9312, 10);
        assert!(fit.label.contains("/4.93)"), "{}", fit.label);
        assert!(mastercurve(0.0, 10.0, 5.0, 10).points.is_empty());
        assert!(mastercurve(1.0, 10.0, -5.0, 10).points.is_empty());
        assert_eq!(mastercurve(1.0, 10.0, 5.0, 0).points.len(), 2);
    }

    #[test]
    fn log_ticks_cover_wide_and_narrow_ranges() {
        // Many decades: at most about eight labels, powers of ten outside 1e-3..1e4.
        let (majors, _) = log_ticks(-4.2, 9.3);
        assert!(majors.len() <= 8 && majors.len() >= 4, "{majors:?}");
        assert!(majors.iter().any(|(_, l)| l == "10^{−4}" || l == "10^{8}"));
        // Less than a decade: 1-2-5 ticks, plain.
        let (majors, _) = log_ticks(0.1, 0.9);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["2", "3", "4", "5", "6", "7"]);
        let (majors, _) = log_ticks(-0.5, 1.2);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["0.5", "1", "2", "5", "10"]);
    }

    #[test]
    fn linear_ticks_are_round() {
        let (majors, _) = linear_ticks(0.0, 7.3);
        let labels: Vec<&str> = majors.iter().map(|m| m.1.as_str()).collect();
        assert_eq!(labels, ["0", "2", "4", "6"]);
        let (majors, _) = linear_ticks(-0.013, 0.021);
        assert!(majors.iter().any(|m| m.1 == "−0.010"), "{majors:?}");
    }

    #[test]
    fn markup_becomes_tspans() {
        let s = tspans("S\u{304}^{1/4} M L^{3}", 20.0);
        assert_eq!(
            s,
            "S\u{304}<tspan dy=\"-9.0\" font-size=\"14.4\">1/4</tspan>\
             <tspan dy=\"9.0\"> M L</tspan><tspan dy=\"-9.0\" font-size=\"14.4\">3</tspan>"
        );
        assert_eq!(tspans("plain_text", 20.0), "plain_text");
        // Unclosed group: runs to the end, no panic.
        assert!(tspans("a_{b", 10.0).contains(">b</tspan>"));
        assert!(text_width("τ\u{304}_{c}", 20.0) < text_width("tau_c", 20.0));
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(4.9312, 3), "4.93");
        assert_eq!(significant(5.0, 3), "5");
        assert_eq!(significant(0.012345, 3), "0.0123");
        assert_eq!(significant(123.4, 3), "123");
    }
}

//! A small kit of deterministic SVG figures (scatter series, model curves, log or linear axes,
//! a legend), drawn with plotters' SVG backend. It knows nothing of the paper: the pictures of
//! the targets are built on it in `paper/`.
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
//! letter (`"μ\u{304}"` is mu-bar).
//!
//! # Axes
//!
//! Log axes plot `log10` of the value on a linear pixel scale with ticks at decades (every
//! second or more decade when the range spans many), labelled as plain numbers between 0.001
//! and 10000 and as powers of ten otherwise. Points that are not finite, or not positive on a
//! log axis, are skipped and counted ([`Rendered`]), and the figure itself says how many were
//! left out; they never make rendering fail or panic.
//!
//! # Error bars
//!
//! A series may give each point a vertical error bar ([`Series::y_errors`]): a thin line in
//! the series' colour from y - e to y + e, mapped through the y axis, with short caps, beneath
//! the markers. It is drawn only where it reaches further than the marker's radius from the
//! point (a shorter bar would hide under the marker) and is cut at the plotting area; an end
//! that is cut has no cap. On a log axis an end y - e <= 0 is cut at the bottom of the axis.
//! Bars do not widen an automatic axis range, and points not drawn have no bar.
//!
//! # Files
//!
//! The figure and its parts are described here; `draw` renders them, with `axes`, `layout`,
//! `place` (where the point labels, the legend and the notes go), `marker`, `legend`, `style`
//! and `text` beneath it; `check` says what is wrong with a rendered layout.

mod axes;
mod check;
mod draw;
mod layout;
mod legend;
mod marker;
mod place;
mod style;
mod text;

pub use check::Layout;
pub use draw::{render, render_svg};
pub use layout::Rect;
pub use text::{significant, text_width};

/// Canvas width in pixels.
pub const WIDTH: u32 = 800;
/// Canvas height in pixels.
pub const HEIGHT: u32 = 600;

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

    /// The marker of the `i`-th series of a figure whose series take the colours in their
    /// order (cycling through ten): shifted by one shape each time the colours start again,
    /// so that no two of the first 50 series share both colour and shape ([`Marker::nth`]
    /// repeats both from the eleventh: the accuracy study's line contact drew as its first
    /// case).
    pub fn of_series(i: usize) -> Marker {
        Marker::nth(i + i / style::SERIES_COLORS.len())
    }
}

/// A set of data points drawn as markers, optionally joined by a thin line in their order
/// and labelled one by one.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Legend label (may use the text markup of this module).
    pub label: String,
    /// Data points (x, y).
    pub points: Vec<(f64, f64)>,
    /// Marker shape.
    pub marker: Marker,
    /// Join the points by a line in the series' colour, in their order (e.g. one case
    /// through its grid levels).
    pub joined: bool,
    /// A short text beside each point (empty: none); missing entries are blank. Each goes
    /// up-right of its marker unless that covers another label, a marker, the legend or the
    /// notes, or crosses a line where another side would not; then to another side (`place`).
    pub point_labels: Vec<String>,
    /// Half-width e of each point's vertical error bar, in data units of y, in the order of
    /// `points`: the error bar from y - e to y + e (empty: none); missing, zero, negative or
    /// non-finite entries draw no bar.
    pub y_errors: Vec<f64>,
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
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Figure {
    /// Title above the plot.
    pub title: String,
    /// Horizontal axis label, with the text markup of this module.
    pub x_label: String,
    /// Vertical axis label.
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
    /// Where its text boxes and markers went ([`Layout::problems`] says what is wrong).
    pub layout: Layout,
}

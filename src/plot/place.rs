//! Where boxes go on the plotting area: how much of the drawn data a box would hide (for the
//! legend and the notes), and where each point label goes beside its marker.
//!
//! A label is tried at a few positions around its marker, in two rings, in a fixed order
//! ([`candidates`]): the first that stays in the plotting area and covers no label placed
//! before it, no marker and no box to keep clear of (the legend, the notes) is taken, from
//! the nearer ring if it can and there one that crosses no drawn line before one that does;
//! where none is clear, the one with the fewest such conflicts.
//! Labels are placed in the order they are drawn (series by series, point by point), so the
//! same figure places them the same way.

use super::layout::Rect;
use super::style::{MARKER_R, NOTE_PX};
use super::text::text_width;

/// A straight stroke between two pixels.
pub(super) type Segment = ((i32, i32), (i32, i32));

/// The gap, pixels, between a marker's centre and the near side of its label's box: the
/// marker's radius and 2, so that no box covers its own marker ([`Rect::covers_marker`]).
const GAP: i32 = MARKER_R + 2;

/// What is drawn on the plotting area, in pixels.
pub(super) struct Ink {
    /// Every marker's centre.
    pub(super) markers: Vec<(i32, i32)>,
    /// The curves' visible pieces and the joined series' lines, segment by segment.
    pub(super) lines: Vec<Segment>,
    /// The error bars' strokes: the vertical bars and their caps.
    pub(super) bars: Vec<Segment>,
}

impl Ink {
    /// How much data a box would hide: the markers within reach of it, the error bars it
    /// meets (a bar counts as much as a point: the box would hide the error of one point) and
    /// five for each line segment it meets.
    pub(super) fn crowding(&self, r: &Rect) -> usize {
        let grown = r.grow(MARKER_R + 2);
        let points = self.markers.iter().filter(|p| grown.contains(**p)).count();
        // The vertical line of each bar; the caps are at its ends.
        let bars = self
            .bars
            .iter()
            .filter(|(a, b)| a.0 == b.0 && grown.meets_segment(*a, *b))
            .count();
        let lines = self
            .lines
            .iter()
            .filter(|(a, b)| grown.meets_segment(*a, *b))
            .count();
        points + bars + 5 * lines
    }

    /// The box of each label (its marker's centre and its text), in their order: the first
    /// of [`candidates`] clear of `area`'s edges, of the labels placed before it, of every
    /// marker and of `avoid`, the nearer ring first and within a ring one that crosses no
    /// line or bar first; where none is clear, the first with the fewest conflicts.
    pub(super) fn place_labels(
        &self,
        labels: &[((i32, i32), &str)],
        area: &Rect,
        avoid: &[Rect],
    ) -> Vec<Rect> {
        let mut placed: Vec<Rect> = Vec::with_capacity(labels.len());
        for &(at, text) in labels {
            let conflicts = |r: &Rect| {
                usize::from(!area.holds(r))
                    + placed.iter().chain(avoid).filter(|b| b.overlaps(r)).count()
                    + self.markers.iter().filter(|m| r.covers_marker(**m)).count()
            };
            let crossings = |r: &Rect| {
                self.lines
                    .iter()
                    .chain(&self.bars)
                    .filter(|(a, b)| r.meets_segment(*a, *b))
                    .count()
            };
            let tries = candidates(at, label_size(text));
            // `min_by_key` keeps the first of equal keys: the order of the candidates decides.
            let best = tries
                .into_iter()
                .enumerate()
                .min_by_key(|(k, r)| (conflicts(r), k / PER_RING, crossings(r)))
                .map_or(tries[0], |(_, r)| r);
            placed.push(best);
        }
        placed
    }
}

/// The size (width, height) of a point label's box, pixels.
fn label_size(text: &str) -> (i32, i32) {
    (
        text_width(text, NOTE_PX).ceil() as i32,
        (NOTE_PX * 1.2).ceil() as i32,
    )
}

/// How much farther from the marker than the first each ring of [`candidates`] lies, pixels:
/// the second about half a label's height out, enough to step past a neighbouring label in a
/// dense family while the text stays within about 16 px of its marker.
const RINGS: [i32; 2] = [0, 10];

/// Candidates in each ring of [`candidates`].
const PER_RING: usize = 8;

/// The boxes a label of `size` may take around its marker at `at`, in the order they are
/// tried, ring by ring ([`RINGS`]): to the right with its top [`GAP`] above the centre (where
/// every label went before labels were placed), then up-right (its bottom level with the
/// centre: the text, drawn from the box's top, ends just above the marker) and down-right
/// (its top [`GAP`] below the centre), then the same three on the left, then centred above
/// and below. None covers its own marker: a box beside it keeps [`GAP`] from the centre
/// across, one centred above or below keeps it up or down.
pub(super) fn candidates((x, y): (i32, i32), (w, h): (i32, i32)) -> [Rect; PER_RING * RINGS.len()] {
    std::array::from_fn(|k| {
        let d = RINGS[k / PER_RING];
        let (right, left, centre) = (x + GAP + d, x - GAP - d - w, x - w / 2);
        let (beside, up, down) = (y - GAP, y - h - d, y + GAP + d);
        let (x0, y0) = [
            (right, beside),
            (right, up),
            (right, down),
            (left, beside),
            (left, up),
            (left, down),
            (centre, y - GAP - h - d),
            (centre, down),
        ][k % PER_RING];
        Rect {
            x0,
            x1: x0 + w,
            y0,
            y1: y0 + h,
        }
    })
}

#[cfg(test)]
#[path = "place_tests.rs"]
mod tests;

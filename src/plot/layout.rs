//! Geometry of the plotting area: segments clipped to the axes, curves broken into their
//! visible pieces, and the emptiest corner for the legend and the notes.

use super::axes::AxisPlan;
use super::style::MARKER_R;

/// Clips the segment a-b to the rectangle [x0, x1] x [y0, y1] (Liang-Barsky).
pub(super) fn clip_segment(
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
pub(super) fn visible_pieces(
    pts: &[Option<(f64, f64)>],
    x: &AxisPlan,
    y: &AxisPlan,
) -> Vec<Vec<(f64, f64)>> {
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

/// A pixel rectangle, x0 < x1 and y0 < y1 (y grows downwards).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Rect {
    /// Left edge.
    pub x0: i32,
    /// Right edge.
    pub x1: i32,
    /// Top edge.
    pub y0: i32,
    /// Bottom edge.
    pub y1: i32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Corner {
    UpperLeft,
    UpperRight,
    LowerRight,
    LowerLeft,
}

impl Rect {
    pub(super) const INSET: i32 = 10;
    /// The step of the positions [`Rect::emptiest_place`] tries beyond the corners, pixels.
    pub(super) const SCAN_STEP: i32 = 10;

    pub(super) fn grow(&self, by: i32) -> Rect {
        Rect {
            x0: self.x0 - by,
            x1: self.x1 + by,
            y0: self.y0 - by,
            y1: self.y1 + by,
        }
    }

    /// Whether `other` lies wholly inside.
    pub(super) fn holds(&self, other: &Rect) -> bool {
        other.x0 >= self.x0 && other.x1 <= self.x1 && other.y0 >= self.y0 && other.y1 <= self.y1
    }

    /// Whether the two share more than an edge.
    pub(super) fn overlaps(&self, other: &Rect) -> bool {
        self.x0 < other.x1 && other.x0 < self.x1 && self.y0 < other.y1 && other.y0 < self.y1
    }

    pub(super) fn contains(&self, (x, y): (i32, i32)) -> bool {
        x >= self.x0 && x <= self.x1 && y >= self.y0 && y <= self.y1
    }

    /// Whether the box lies over the marker centred at `m`: it comes within the marker's
    /// radius of the centre.
    pub(super) fn covers_marker(&self, m: (i32, i32)) -> bool {
        self.grow(MARKER_R).contains(m)
    }

    pub(super) fn meets_segment(&self, a: (i32, i32), b: (i32, i32)) -> bool {
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
    pub(super) fn place(&self, corner: Corner, (w, h): (i32, i32)) -> Rect {
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

    pub(super) fn centred(&self, (w, h): (i32, i32)) -> Rect {
        let x0 = (self.x0 + self.x1 - w) / 2;
        let y0 = (self.y0 + self.y1 - h) / 2;
        Rect {
            x0,
            x1: x0 + w,
            y0,
            y1: y0 + h,
        }
    }

    /// Where a box of `size` covers the fewest data and does not meet `avoid`: the four
    /// corners first (ties: upper left first), then every position on a grid of
    /// [`Self::SCAN_STEP`] pixels over the area (as matplotlib's `loc="best"` tries its
    /// positions), the first empty one in reading order; the corner with the fewest where
    /// none is empty.
    pub(super) fn emptiest_place(
        &self,
        size: (i32, i32),
        avoid: Option<Rect>,
        crowding: &dyn Fn(&Rect) -> usize,
    ) -> Rect {
        let blocked = |r: &Rect| avoid.is_some_and(|a| a.grow(Self::INSET / 2).overlaps(r));
        let cost = |r: &Rect| crowding(r) + if blocked(r) { usize::MAX / 2 } else { 0 };
        let corners = [
            Corner::UpperLeft,
            Corner::UpperRight,
            Corner::LowerRight,
            Corner::LowerLeft,
        ]
        .map(|c| self.place(c, size));
        let best_corner = corners
            .into_iter()
            .min_by_key(|r| cost(r))
            .unwrap_or_else(|| self.place(Corner::UpperLeft, size));
        if cost(&best_corner) == 0 {
            return best_corner;
        }
        let (x_lo, x_hi) = (self.x0 + Self::INSET, self.x1 - Self::INSET - size.0);
        let (y_lo, y_hi) = (self.y0 + Self::INSET, self.y1 - Self::INSET - size.1);
        let mut y = y_lo;
        while y <= y_hi {
            let mut x = x_lo;
            while x <= x_hi {
                let r = Rect {
                    x0: x,
                    x1: x + size.0,
                    y0: y,
                    y1: y + size.1,
                };
                if cost(&r) == 0 {
                    return r;
                }
                x += Self::SCAN_STEP;
            }
            y += Self::SCAN_STEP;
        }
        best_corner
    }
}

//! Placement: point labels clear of each other and of the markers, drawn where their boxes
//! are; the notes clear of the series' lines.
use super::*;
use crate::plot::{render, Figure, Marker, Rendered, Series};

/// A labelled series of one marker at `at`, axes 0..10 (about 70 px per unit of x and 50
/// of y on the 800 x 600 canvas).
fn labelled(label: &str, at: (f64, f64), text: &str, marker: Marker) -> Series {
    Series {
        label: label.into(),
        points: vec![at],
        marker,
        point_labels: vec![text.into()],
        ..Series::default()
    }
}

fn on_ten_by_ten(series: Vec<Series>) -> Figure {
    Figure {
        x_range: Some((0.0, 10.0)),
        y_range: Some((0.0, 10.0)),
        series,
        ..Figure::default()
    }
}

/// The (x, y) of each `<text>` whose content is the line `content`.
fn texts_at(svg: &str, content: &str) -> Vec<(i32, i32)> {
    let attr = |tag: &str, name: &str| -> Option<i32> {
        let key = format!(" {name}=\"");
        let at = tag.find(&key)? + key.len();
        tag[at..].split('"').next()?.parse().ok()
    };
    svg.split("<text")
        .skip(1)
        .filter_map(|t| t.split_once('>'))
        .filter(|(_, body)| body.lines().nth(1).map(str::trim) == Some(content))
        .filter_map(|(tag, _)| Some((attr(tag, "x")?, attr(tag, "y")?)))
        .collect()
}

fn rendered(fig: &Figure) -> Rendered {
    render(fig).expect("renders")
}

#[test]
fn two_series_whose_labels_would_collide_up_right_get_boxes_apart() {
    // Series b's marker 0.16 units (8 px) above series a's: their labels' boxes up-right,
    // 17 px tall, would overlap, while neither marker lies under the other's box.
    let fig = on_ten_by_ten(vec![
        labelled("a", (5.0, 5.0), "L7", Marker::Circle),
        labelled("b", (5.0, 5.16), "L6", Marker::Square),
    ]);
    let r = rendered(&fig);
    let (a, b) = (r.layout.labels[0], r.layout.labels[1]);
    assert!(!a.overlaps(&b), "{a:?} {b:?}");
    let up_right = |k: usize, text: &str| candidates(r.layout.markers[k], label_size(text))[0];
    assert!(
        up_right(0, "L7").overlaps(&up_right(1, "L6")),
        "the figure does not test a collision"
    );
    assert_eq!(r.layout.problems(), Vec::<String>::new());
    // The text is drawn where the check reads its box, each label a line of its own.
    assert_eq!(texts_at(&r.svg, "L7"), [(a.x0, a.y0)]);
    assert_eq!(texts_at(&r.svg, "L6"), [(b.x0, b.y0)]);
}

#[test]
fn a_lone_label_stays_up_right_and_the_same_figure_places_the_same() {
    let fig = on_ten_by_ten(vec![labelled("a", (5.0, 5.0), "L5", Marker::Circle)]);
    let r = rendered(&fig);
    let (x, y) = r.layout.markers[0];
    // Right of the marker by its radius and 2 px, its top as far above the centre.
    assert_eq!(
        (r.layout.labels[0].x0, r.layout.labels[0].y0),
        (x + MARKER_R + 2, y - (MARKER_R + 2))
    );
    assert_eq!(rendered(&fig.clone()), r);
}

#[test]
fn no_candidate_covers_its_own_marker() {
    // Sizes from one character to a long label, and an odd width (the centred boxes halve it).
    for size in [(1, 1), (9, 17), (17, 17), (120, 40)] {
        for r in candidates((100, 100), size) {
            assert!(!r.covers_marker((100, 100)), "{r:?}");
        }
    }
}

#[test]
fn a_label_goes_where_it_is_clear_and_else_where_it_conflicts_least() {
    let area = Rect {
        x0: 0,
        x1: 400,
        y0: 0,
        y1: 400,
    };
    let at = (200, 200);
    // "L8" at 14 px: 18 x 17 px. Right of `at` the boxes span x 206..224; beside y 194..211,
    // up-right y 183..200, down-right y 206..223; a marker is covered within 4 px of a box.
    let tries = candidates(at, label_size("L8"));
    let place = |markers: Vec<(i32, i32)>, lines: Vec<Segment>, area: &Rect, avoid: &[Rect]| {
        let ink = Ink {
            markers,
            lines,
            bars: Vec::new(),
        };
        ink.place_labels(&[(at, "L8")], area, avoid)
    };
    // Nothing near: beside, on the right.
    assert_eq!(place(vec![at], Vec::new(), &area, &[]), [tries[0]]);
    // A marker 12 px to the right, level with it, under the beside and up-right boxes: down.
    let right = (212, 200);
    assert_eq!(place(vec![at, right], Vec::new(), &area, &[]), [tries[2]]);
    // And one 14 px below that, under the down-right box: the first on the left.
    let below_right = (212, 214);
    let markers = vec![at, right, below_right];
    assert_eq!(place(markers.clone(), Vec::new(), &area, &[]), [tries[3]]);
    // An area of 20 x 20 px around the marker: every box leaves it, none is clear; the first
    // with the fewest conflicts is taken (beside 3, up-right 2, down-right 2, the left 1).
    let tiny = area_around(at, 10);
    assert_eq!(place(markers, Vec::new(), &tiny, &[]), [tries[3]]);
    // A box to keep clear of (a legend) over the right: the first on the left.
    let legend = Rect {
        x0: 206,
        x1: 300,
        y0: 150,
        y1: 250,
    };
    assert_eq!(place(vec![at], Vec::new(), &area, &[legend]), [tries[3]]);
    // A horizontal line through the beside box only (y 205): up-right, clear of it.
    let line = ((210, 205), (300, 205));
    assert_eq!(place(vec![at], vec![line], &area, &[]), [tries[1]]);
}

/// The square of half-side `r` around `c`.
fn area_around(c: (i32, i32), r: i32) -> Rect {
    Rect {
        x0: c.0 - r,
        x1: c.0 + r,
        y0: c.1 - r,
        y1: c.1 + r,
    }
}

#[test]
fn the_notes_keep_clear_of_a_series_line() {
    // A joined diamond through the middles of the edges cuts every corner; a note wider than
    // a corner's triangle (about 290 px at the note's height) must go inside it.
    let diamond = vec![(0.2, 5.0), (5.0, 9.8), (9.8, 5.0), (5.0, 0.2), (0.2, 5.0)];
    let mut fig = on_ten_by_ten(vec![Series {
        label: "diamond".into(),
        points: diamond,
        joined: true,
        ..Series::default()
    }]);
    fig.note = Some("a note wider than any corner left by the diamond's line".into());
    let r = rendered(&fig);
    let notes = r.layout.notes.expect("notes drawn");
    for w in r.layout.markers.windows(2) {
        assert!(!notes.meets_segment(w[0], w[1]), "{notes:?} meets {w:?}");
    }
    assert_eq!(r.layout.problems(), Vec::<String>::new());
}

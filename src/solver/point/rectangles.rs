//! The rectangles of a chain of nested domains ([`super::chain`]): each about a third of the
//! domain around it, down to the contact's core, snapped outward onto the grid lines of the
//! solution around it. Apart from the chain's solve so that the parameters' rule
//! ([`super::Params::for_problem`]) can ask whether a domain has any.

use crate::solver::grid::{Domain, Grid};

/// The smallest rectangle of a chain: the Hertzian zone with the inlet's steep pressure rise
/// and the outlet up to past its cavitation boundary. Case 23 reached `-1.6..1.0 x 1.3` from
/// `-4.5..1.5 x 3` 0.07 % from its grid-converged film; but an outlet edge at `X = 1.0` lies in
/// the light contacts' pressurised outlet (Fig. 6 case 19 cavitates at `X = 1.16`), where it
/// takes the coarse surroundings' pressure, and there the innermost rectangle of Fig. 6's
/// members at S 0.1 % (cases 19-21) did not converge (they fell back to the case-sized domain,
/// 6.4 % off in friction). At `1.3` they converge (0.7-0.8 %) and the other members move by
/// 0.01 % at most (docs/ACCURACY_NOTES.md, "The core's outlet").
pub const CORE: Domain = Domain {
    x_start: -1.6,
    x_end: 1.3,
    y_half: 1.3,
    y_centre: 0.0,
};

/// Each rectangle is the domain around it divided by this about the contact centre: case 23's
/// film followed the finer mesh down to a third of its surroundings and overshot below it
/// (0.67 % with the core straight inside the wide domain at level 7).
pub const SHRINK: f64 = 3.0;

/// The rectangles nested in `domain`, outermost first, the last the core (not yet on any
/// grid's lines): none where the domain's inlet is within [`SHRINK`] of the core's (the
/// paper's domain and the light-load one of Venner and Lubrecht, on which the mid-range
/// contacts already meet the targets).
pub fn rectangles(domain: &Domain) -> Vec<Domain> {
    let mut out = Vec::new();
    if domain.x_start >= SHRINK * CORE.x_start {
        return out;
    }
    let mut d = *domain;
    while d.x_start < CORE.x_start {
        d = Domain {
            x_start: (d.x_start / SHRINK).min(CORE.x_start),
            x_end: (d.x_end / SHRINK).max(CORE.x_end),
            y_half: (d.y_half / SHRINK).max(CORE.y_half),
            y_centre: 0.0,
        };
        out.push(d);
    }
    out
}

/// `rect` pushed outward onto the grid lines of `grid`.
pub fn snap(rect: &Domain, grid: &Grid) -> Domain {
    let down = |v: f64, o: f64, h: f64| o + h * ((v - o) / h).floor();
    let up = |v: f64, o: f64, h: f64| o + h * ((v - o) / h).ceil();
    Domain {
        x_start: down(rect.x_start, grid.x0, grid.hx),
        x_end: up(rect.x_end, grid.x0, grid.hx),
        y_half: -down(-rect.y_half, grid.y0, grid.hy),
        y_centre: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rectangles_shrink_by_a_third_down_to_the_core() {
        // Case 23's case-sized domain: a third, then the core's inlet and outlet.
        let r = rectangles(&Domain {
            x_start: -13.5,
            x_end: 7.0,
            y_half: 13.5,
            y_centre: 0.0,
        });
        assert_eq!(r.len(), 2);
        assert!((r[0].x_start + 4.5).abs() < 1e-12 && (r[0].y_half - 4.5).abs() < 1e-12);
        let core_high = Domain {
            y_half: 1.5,
            y_centre: 0.0,
            ..CORE
        };
        assert_eq!(
            r[1], core_high,
            "the core's inlet and outlet, a third of 4.5 wide"
        );
        // The paper's domain and -4.5..1.5 x 3 are within a third of the core: no rectangle.
        assert!(rectangles(&Domain::default()).is_empty());
        assert!(rectangles(&Domain::wide()).is_empty());
    }

    #[test]
    fn a_rectangle_is_snapped_outward_onto_the_grid_lines() {
        let grid = Grid::level(
            &Domain {
                x_start: -13.5,
                x_end: 7.0,
                y_half: 13.5,
                y_centre: 0.0,
            },
            5,
        );
        let s = snap(&CORE, &grid);
        let on_line = |v: f64, o: f64, h: f64| ((v - o) / h - ((v - o) / h).round()).abs() < 1e-9;
        assert!(on_line(s.x_start, grid.x0, grid.hx) && on_line(s.x_end, grid.x0, grid.hx));
        assert!(on_line(-s.y_half, grid.y0, grid.hy));
        assert!(s.x_start <= CORE.x_start && s.x_end >= CORE.x_end && s.y_half >= CORE.y_half);
        assert!(CORE.x_start - s.x_start < grid.hx && s.y_half - CORE.y_half < grid.hy);
    }
}

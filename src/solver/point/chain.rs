//! A chain of nested domains (issue 39, prototype; not yet the rule's): the case-sized domain,
//! then rectangles each about a third of the one around it, down to the contact's core, every
//! one solved at the same level inside the solution around it ([`super::nested`]). The
//! outputs are the innermost grid's film and the friction summed over the chain; their error
//! is estimated by Richardson over the whole chain at two coarser levels, whose meshes halve
//! together, so that the surroundings' own error is part of it (docs/ACCURACY_NOTES.md, "Resolution where the contact needs it").

use super::nested::Surround;
use super::{solve, solve_nested, Params, PointSolution, LOADED_FILM_FACTOR};
use crate::physics::case::Problem;
use crate::solver::grid::{Domain, Grid};
use crate::solver::output::SolveError;
use crate::solver::richardson::{estimate, ErrorEstimate};
use std::sync::Arc;

/// The smallest rectangle of a chain: the Hertzian zone with the inlet's steep pressure rise.
/// Case 23 reached it from `-4.5..1.5 x 3` 0.07 % from its grid-converged film.
pub const CORE: Domain = Domain {
    x_start: -1.6,
    x_end: 1.0,
    y_half: 1.3,
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
        };
        out.push(d);
    }
    out
}

/// `rect` pushed outward onto the grid lines of `grid`.
fn snap(rect: &Domain, grid: &Grid) -> Domain {
    let down = |v: f64, o: f64, h: f64| o + h * ((v - o) / h).floor();
    let up = |v: f64, o: f64, h: f64| o + h * ((v - o) / h).ceil();
    Domain {
        x_start: down(rect.x_start, grid.x0, grid.hx),
        x_end: up(rect.x_end, grid.x0, grid.hx),
        y_half: -down(-rect.y_half, grid.y0, grid.hy),
    }
}

/// A solved chain at one level.
#[derive(Debug)]
pub struct Chain {
    /// The case-sized domain's solution, then each rectangle's, outermost first.
    pub solutions: Vec<PointSolution>,
    /// The surroundings of each rectangle.
    pub surrounds: Vec<Arc<Surround>>,
}

impl Chain {
    /// The innermost solution: the film's.
    pub fn innermost(&self) -> &PointSolution {
        self.solutions
            .last()
            .expect("a chain has its case-sized domain")
    }

    /// Central film, minimum film (Moes) and sliding `mu-bar` of the chain: the innermost
    /// grid's film, its friction plus each surroundings' outside it (Eq. 8, loaded film).
    pub fn outputs(&self, problem: &Problem) -> [f64; 3] {
        let inner = self.innermost();
        let limit = LOADED_FILM_FACTOR * inner.film.h_central;
        let outside: f64 = self
            .surrounds
            .iter()
            .map(|s| s.outside_sliding(problem, limit))
            .sum();
        [
            inner.film.hc_moes,
            inner.film.hmin_moes,
            inner.friction.sliding + outside,
        ]
    }
}

/// Solves `problem`'s chain at `params.level` on `params.domain` (the case-sized domain with
/// its far field, [`Params::for_problem`]); no error estimate of its own.
pub fn solve_chain(problem: &Problem, params: &Params) -> Result<Chain, SolveError> {
    let params = Params {
        error_levels: 0,
        ..params.clone()
    };
    let wide = solve(problem, &params, None)?;
    let mut chain = Chain {
        solutions: vec![wide],
        surrounds: Vec::new(),
    };
    for rect in rectangles(&params.domain) {
        let outer = chain.innermost();
        let inner = snap(&rect, &outer.grid);
        let fine = Grid::level(&inner, params.level);
        let surround = Arc::new(Surround::new(
            problem,
            &outer.grid,
            (&outer.p, &outer.h, outer.delta),
            &inner,
            (fine.hx, fine.hy),
        ));
        let nested = solve_nested(
            problem,
            &Params {
                domain: inner,
                ..params.clone()
            },
            &surround,
            None,
        )?;
        chain.surrounds.push(surround);
        chain.solutions.push(nested);
    }
    Ok(chain)
}

/// [`solve_chain`] at `params.level` and at the `levels` levels below it, and the error
/// estimate of each output of [`Chain::outputs`] over them (`None` where the estimate has
/// too few levels).
pub fn solve_chain_estimated(
    problem: &Problem,
    params: &Params,
    levels: u32,
) -> Result<(Chain, [Option<ErrorEstimate>; 3]), SolveError> {
    let mut values: Vec<[f64; 3]> = Vec::new();
    for level in params.level.saturating_sub(levels)..params.level {
        let coarse = Params {
            level,
            ..params.clone()
        };
        values.push(solve_chain(problem, &coarse)?.outputs(problem));
    }
    let chain = solve_chain(problem, params)?;
    values.push(chain.outputs(problem));
    let of = |k: usize| estimate(&values.iter().map(|v| v[k]).collect::<Vec<_>>());
    Ok((chain, [of(0), of(1), of(2)]))
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
        });
        assert_eq!(r.len(), 2);
        assert!((r[0].x_start + 4.5).abs() < 1e-12 && (r[0].y_half - 4.5).abs() < 1e-12);
        let core_high = Domain {
            y_half: 1.5,
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

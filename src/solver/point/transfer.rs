//! Transfers between a level and the next coarser one: FAS restriction of the pressure, the
//! film and the residual; bilinear prolongation of the correction; cubic interpolation of the
//! solution for the full-multigrid start. The coarse grid has every second node in each
//! direction (full coarsening), or every second node in one direction and every node in the
//! other (semi-coarsening, from a grid refined in one direction alone: [`Grid::refined_y`]
//! across the rolling direction); each transfer reads which from the two grids
//! ([`Grid::ratio_to`]).
//!
//! Near the cavitation boundary, where a fine neighbour has `P = 0`, the pressure is
//! injected rather than weighted, and the correction is added only where `P > 0`.

use super::level::{LevelFields, Model};
#[cfg(doc)]
use crate::solver::grid::Grid;

/// Full-weighting stencil: centre 4, edges 2, corners 1, over 16.
const FW: [(isize, isize, f64); 9] = [
    (0, 0, 4.0),
    (1, 0, 2.0),
    (-1, 0, 2.0),
    (0, 1, 2.0),
    (0, -1, 2.0),
    (1, 1, 1.0),
    (1, -1, 1.0),
    (-1, 1, 1.0),
    (-1, -1, 1.0),
];

/// Semi-coarsening's weighting along `Y`: centre 2, `Y` neighbours 1, over 4.
const FW_Y: [(isize, isize, f64); 3] = [(0, 0, 2.0), (0, 1, 1.0), (0, -1, 1.0)];

/// Semi-coarsening's weighting along `X`: centre 2, `X` neighbours 1, over 4.
const FW_X: [(isize, isize, f64); 3] = [(0, 0, 2.0), (1, 0, 1.0), (-1, 0, 1.0)];

/// The restriction's stencil and the sum of its weights for the fine-to-coarse interval ratios
/// `(rx, ry)`.
fn weighting(rx: usize, ry: usize) -> (&'static [(isize, isize, f64)], f64) {
    match (rx, ry) {
        (2, 2) => (&FW, 16.0),
        (1, 2) => (&FW_Y, 4.0),
        (2, 1) => (&FW_X, 4.0),
        _ => unreachable!("a coarse grid halves one direction or both: ({rx}, {ry})"),
    }
}

/// Sets up the coarse problem of the FAS cycle from the fine level's current state
/// (the fine film and coefficients must be current).
pub(crate) fn coarsen(fine: &LevelFields, coarse: &mut LevelFields, model: &Model, delta: f64) {
    let (gf, gc) = (fine.grid, coarse.grid);
    let (rx, ry) = gf.ratio_to(&gc);
    let (stencil, total) = weighting(rx, ry);
    let at = |i: usize, j: usize, di: isize, dj: isize| {
        gf.idx((i as isize + di) as usize, (j as isize + dj) as usize)
    };
    // Pressure: full weighting, injection near cavitation and on the boundary (the far
    // field's values, the same at a coarse node as at the fine node it is).
    for jc in 0..gc.py() {
        for ic in 0..gc.px() {
            let c = gc.idx(ic, jc);
            if ic == 0 || jc == 0 || ic == gc.nx || jc == gc.ny {
                coarse.p[c] = fine.p[gf.idx(rx * ic, ry * jc)];
                continue;
            }
            let (i, j) = (rx * ic, ry * jc);
            let dry = stencil
                .iter()
                .any(|&(di, dj, _)| fine.p[at(i, j, di, dj)] == 0.0);
            coarse.p[c] = if dry {
                fine.p[gf.idx(i, j)]
            } else {
                stencil
                    .iter()
                    .map(|&(di, dj, w)| w * fine.p[at(i, j, di, dj)])
                    .sum::<f64>()
                    / total
            };
        }
    }
    coarse.pold.copy_from_slice(&coarse.p);
    // Film: injection; the coarse film equation is shifted so that it reproduces it.
    for jc in 0..gc.py() {
        for ic in 0..gc.px() {
            coarse.h[gc.idx(ic, jc)] = fine.h[gf.idx(rx * ic, ry * jc)];
        }
    }
    coarse.deformation.apply(&coarse.p, &mut coarse.w);
    for k in 0..gc.len() {
        coarse.hrhs[k] = coarse.h[k] - delta - coarse.w[k];
    }
    coarse.update_coefficients(model);
    // Reynolds: restricted residual (zero where the fine pressure is zero) plus L_c(P_c).
    for jc in 1..gc.ny {
        for ic in 1..gc.nx {
            let (i, j) = (rx * ic, ry * jc);
            let mut r = 0.0;
            for &(di, dj, w) in stencil {
                let (fi, fj) = ((i as isize + di) as usize, (j as isize + dj) as usize);
                let centre = di == 0 && dj == 0;
                if centre || fine.p[gf.idx(fi, fj)] > 0.0 {
                    r += w * fine.residual(fi, fj);
                }
            }
            coarse.f[gc.idx(ic, jc)] = r / total + coarse.operator(&coarse.p, ic, jc);
        }
    }
    // Force balance.
    coarse.rg = fine.rg + gf.integrate(&fine.p) - gc.integrate(&coarse.p);
}

/// Scales the relative truncation error in the coarse problem [`coarsen`] set up from a
/// converged top `fine` by `factor` (tau-extrapolation, [`super::tau`]): the Reynolds
/// right-hand side (the top's is zero, so the coarse one is `tau` itself), the film's shift
/// from the `natural` right-hand side a top on the coarse grid would have (the geometry and
/// far field) and the force balance's quadrature difference.
pub(crate) fn scale_tau(
    fine: &LevelFields,
    coarse: &mut LevelFields,
    natural: &[f64],
    factor: f64,
) {
    let gc = coarse.grid;
    coarse.f.iter_mut().for_each(|f| *f *= factor);
    for (h, n) in coarse.hrhs.iter_mut().zip(natural) {
        *h = n + factor * (*h - n);
    }
    let tau_g = fine.grid.integrate(&fine.p) - gc.integrate(&coarse.p);
    coarse.rg = fine.rg + factor * tau_g;
}

/// Adds the bilinearly interpolated coarse-grid correction `P_c - P_c,old`, times the fine
/// level's [`LevelFields::correction_weight`], to the fine pressure where it is positive, then
/// projects on `P >= 0`.
pub(crate) fn correct(coarse: &LevelFields, fine: &mut LevelFields) {
    let weight = fine.correction_weight;
    let (gf, gc) = (fine.grid, coarse.grid);
    let (rx, ry) = gf.ratio_to(&gc);
    let e = |ic: usize, jc: usize| {
        let k = gc.idx(ic, jc);
        coarse.p[k] - coarse.pold[k]
    };
    for j in 1..gf.ny {
        for i in 1..gf.nx {
            let k = gf.idx(i, j);
            if fine.p[k] <= 0.0 {
                continue;
            }
            let (ic, jc) = (i / rx, j / ry);
            let corr = match (i % rx, j % ry) {
                (0, 0) => e(ic, jc),
                (1, 0) => 0.5 * (e(ic, jc) + e(ic + 1, jc)),
                (0, 1) => 0.5 * (e(ic, jc) + e(ic, jc + 1)),
                _ => 0.25 * (e(ic, jc) + e(ic + 1, jc) + e(ic, jc + 1) + e(ic + 1, jc + 1)),
            };
            fine.p[k] = (fine.p[k] + weight * corr).max(0.0);
        }
    }
}

/// Four-point cubic interpolation of one line of values at the even points (odd points are
/// filled; one-sided near the ends). `get(k)`/`set(k, v)` address the line's `n + 1` points.
fn cubic_line(n: usize, get: impl Fn(usize) -> f64, mut set: impl FnMut(usize, f64)) {
    for k in (1..n).step_by(2) {
        let v = if k == 1 {
            (5.0 * get(0) + 15.0 * get(2) - 5.0 * get(4) + get(6)) / 16.0
        } else if k == n - 1 {
            (5.0 * get(n) + 15.0 * get(n - 2) - 5.0 * get(n - 4) + get(n - 6)) / 16.0
        } else {
            (-get(k - 3) + 9.0 * get(k - 1) + 9.0 * get(k + 1) - get(k + 3)) / 16.0
        };
        set(k, v);
    }
}

/// Full-multigrid start: the converged coarse pressure interpolated (cubic) to the fine grid,
/// projected on `P >= 0`, the fine level's far field on its boundary.
pub(crate) fn interpolate_solution(coarse: &LevelFields, fine: &mut LevelFields) {
    let (gf, gc) = (fine.grid, coarse.grid);
    let (rx, ry) = gf.ratio_to(&gc);
    fine.p.iter_mut().for_each(|v| *v = 0.0);
    for jc in 0..gc.py() {
        for ic in 0..gc.px() {
            fine.p[gf.idx(rx * ic, ry * jc)] = coarse.p[gc.idx(ic, jc)];
        }
    }
    let p = &mut fine.p;
    if ry == 2 {
        for i in (0..=gf.nx).step_by(rx) {
            let col: Vec<f64> = (0..gf.py()).map(|j| p[gf.idx(i, j)]).collect();
            cubic_line(gf.ny, |j| col[j], |j, v| p[gf.idx(i, j)] = v);
        }
    }
    if rx == 2 {
        for j in 0..gf.py() {
            let row: Vec<f64> = (0..gf.px()).map(|i| p[gf.idx(i, j)]).collect();
            cubic_line(gf.nx, |i| row[i], |i, v| p[gf.idx(i, j)] = v);
        }
    }
    for j in 0..gf.py() {
        for i in 0..gf.px() {
            let k = gf.idx(i, j);
            let boundary = i == 0 || j == 0 || i == gf.nx || j == gf.ny;
            p[k] = if boundary {
                fine.edge[k]
            } else {
                p[k].max(0.0)
            };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::case::Problem;
    use crate::solver::grid::{Domain, Grid};

    /// What a transfer that must reproduce a function exactly may be off by: rounding, on
    /// values of order 1 summed over at most nine terms.
    const ROUNDING: f64 = 1e-12;

    /// A smooth positive pressure: cubic in `Y` (which the four-point interpolation along `Y`
    /// reproduces), anything in `X`.
    fn cubic_in_y(x: f64, y: f64) -> f64 {
        2.0 + x.sin() + y * (1.0 + y * (0.5 - 0.2 * y))
    }

    fn max_error(grid: &Grid, p: &[f64], f: impl Fn(f64, f64) -> f64, interior: bool) -> f64 {
        let skip = usize::from(interior);
        let mut worst = 0.0f64;
        for j in skip..grid.py() - skip {
            for i in skip..grid.px() - skip {
                worst = worst.max((p[grid.idx(i, j)] - f(grid.x(i), grid.y(j))).abs());
            }
        }
        worst
    }

    /// Restricts `f`, sampled on `fine`'s grid, to `coarse` and returns the largest error at
    /// the coarse nodes (the fine film and coefficients brought up to date first).
    fn restriction_error(
        fine: &mut LevelFields,
        coarse: &mut LevelFields,
        model: &Model,
        f: impl Fn(f64, f64) -> f64,
    ) -> f64 {
        fine.p = fine.grid.sample(&f);
        fine.refresh(0.3, model);
        coarsen(fine, coarse, model, 0.3);
        max_error(&coarse.grid, &coarse.p, f, false)
    }

    /// A fine level on `gf` and a coarse one on `gc`, of a moderately loaded contact.
    fn levels(gf: Grid, gc: Grid) -> (Model, LevelFields, LevelFields) {
        let model = Model::new(&Problem::circular(100.0, 10.0, 0.5));
        let (fine, coarse) = (LevelFields::new(gf, &model), LevelFields::new(gc, &model));
        (model, fine, coarse)
    }

    /// Checks the three transfers between `gf`, refined in one direction, and `gc` on functions
    /// of that direction they must reproduce (written for `Y`; `along_x` exchanges `X` and `Y`
    /// in them).
    fn semi_coarsening_reproduces(gf: Grid, gc: Grid, along_x: bool) {
        let along =
            |f: fn(f64, f64) -> f64| move |x: f64, y: f64| if along_x { f(y, x) } else { f(x, y) };
        let (model, mut fine, mut coarse) = levels(gf, gc);
        // The full-multigrid start: cubic along the refined direction only, the coarse
        // lines kept.
        let cubic = along(cubic_in_y);
        coarse.p = gc.sample(cubic);
        interpolate_solution(&coarse, &mut fine);
        assert!(max_error(&gf, &fine.p, cubic, true) < ROUNDING);
        // The correction: linear along the refined direction, every fine node on a coarse line
        // (added to a pressure of 4, which keeps the sum clear of the projection on `P >= 0`
        // at the domain's inlet end, `X = -2.5`).
        let change = along(|x, y| x * x + 0.5 * y);
        fine.p = gf.sample(|_, _| 4.0);
        coarse.pold = gc.zeros();
        coarse.p = gc.sample(change);
        correct(&coarse, &mut fine);
        assert!(max_error(&gf, &fine.p, |x, y| 4.0 + change(x, y), true) < ROUNDING);
        // The restriction of a pressure linear along it (weights 1 2 1 over 4) is its value.
        let linear = along(|x, y| 3.0 + x.cos() + 0.4 * y);
        assert!(restriction_error(&mut fine, &mut coarse, &model, linear) < ROUNDING);
    }

    #[test]
    fn semi_coarsening_in_y_transfers_what_its_stencils_reproduce() {
        let gc = Grid::level(&Domain::default(), 4);
        let gf = gc.refined_y();
        assert_eq!(gf.ratio_to(&gc), (1, 2));
        semi_coarsening_reproduces(gf, gc, false);
    }

    #[test]
    fn semi_coarsening_in_x_transfers_what_its_stencils_reproduce() {
        let gc = Grid::level(&Domain::default(), 4);
        let gf = Grid {
            nx: 2 * gc.nx,
            hx: 0.5 * gc.hx,
            ..gc
        };
        assert_eq!(gf.ratio_to(&gc), (2, 1));
        semi_coarsening_reproduces(gf, gc, true);
    }

    #[test]
    fn full_coarsening_restricts_a_bilinear_pressure_to_its_values() {
        let gf = Grid::level(&Domain::default(), 4);
        let (model, mut fine, mut coarse) = levels(gf, gf.coarser());
        let bilinear = |x: f64, y: f64| 3.0 + 0.3 * x + 0.4 * y + 0.1 * x * y;
        assert!(restriction_error(&mut fine, &mut coarse, &model, bilinear) < ROUNDING);
    }
}

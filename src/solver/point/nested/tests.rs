//! The nested domain's surroundings against fine-grid oracles.

use super::{bicubic, cubic_weights, Model, Surround, LOAD};
use crate::physics::case::Problem;
use crate::physics::hertz::Hertz;
use crate::solver::deformation::Deformation;
use crate::solver::grid::{Domain, Grid};

fn problem() -> Problem {
    Problem::circular(20.0, 10.0, 0.1)
}

/// The Hertzian pressure and an inlet bump that reaches the nested rectangle's edge.
fn pressure(x: f64, y: f64) -> f64 {
    Hertz::pressure(x, y) + 0.2 * (-((x + 2.0).powi(2) + y * y)).exp()
}

fn deformation(problem: &Problem, grid: &Grid, p: &[f64]) -> Vec<f64> {
    let mut w = grid.zeros();
    let g = &problem.groups;
    Deformation::new(grid, g.kappa, problem.ell_k).apply(p, &mut w);
    w
}

#[test]
fn catmull_rom_weights_sum_to_one_and_interpolate_nodes() {
    for t in [0.0, 0.25, 0.5, 0.9] {
        let w = cubic_weights(t);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
    assert_eq!(cubic_weights(0.0), [0.0, 1.0, 0.0, 0.0]);
}

#[test]
fn the_whole_domain_nested_in_itself_adds_nothing() {
    let problem = problem();
    let domain = Domain::wide();
    let grid = Grid::level(&domain, 5);
    let p = grid.sample(pressure);
    let s = Surround::new(&problem, &grid, (&p, &p, 0.0), &domain, (grid.hx, grid.hy));
    // Its own edge cells are the nested grid's: no pressure outside, no deformation.
    assert!((s.outside_load() - (LOAD - grid.integrate(&p))).abs() < 1e-12);
    let offset = grid.sample(|x, y| s.film_offset(x, y));
    assert!(offset.iter().all(|w| w.abs() < 1e-12));
    // The edge takes the wide pressure at the wide nodes.
    assert!((s.pressure(grid.x(0), grid.y(7)) - p[grid.idx(0, 7)]).abs() < 1e-12);
}

#[test]
fn the_friction_outside_two_patches_is_what_neither_covers() {
    // Two disjoint rectangles on grid lines of the heavy-load domain at level 5, one about
    // the axis, one off it (a side lobe's): what the wide solution adds outside both is
    // what it adds outside each less what it adds everywhere, the shares of the two
    // rectangles' cells being disjoint. The "everywhere" is summed here directly (the
    // film a smooth positive field, every node of it loaded).
    let problem = problem();
    let domain = Domain::heavy();
    let grid = Grid::level(&domain, 5);
    let p = grid.sample(pressure);
    let h = grid.sample(|x, y| 1.0 + 0.1 * x + 0.05 * y * y);
    let rect = |i0: usize, j0: usize, cells: usize| {
        Domain::spanning(
            [grid.x(i0), grid.x(i0 + cells)],
            [grid.y(j0), grid.y(j0 + cells)],
        )
    };
    let fine = (grid.hx / 2.0, grid.hy / 2.0);
    let a = Surround::new(&problem, &grid, (&p, &h, 0.0), &rect(10, 24, 16), fine);
    let b = Surround::new(&problem, &grid, (&p, &h, 0.0), &rect(34, 44, 16), fine);
    assert!(b.inner().y_centre > 0.5, "{:?}", b.inner());
    let limit = f64::INFINITY;
    let both = Surround::outside_all(&[&a, &b], &problem, limit, true);
    let (sa, ra) = a.outside_friction(&problem, limit, true);
    let (sb, rb) = b.outside_friction(&problem, limit, true);
    let model = Model::new(&problem);
    let (mut sliding, mut poiseuille) = (0.0, 0.0);
    for j in 1..grid.ny {
        for i in 1..grid.nx {
            let k = grid.idx(i, j);
            sliding += model.mean_shear_stress(p[k], h[k]);
            poiseuille += h[k] * (p[k + 1] - p[k - 1]) / (2.0 * grid.hx);
        }
    }
    let area = grid.hx * grid.hy / LOAD;
    let scale = problem.groups.rolling_stress_scale();
    let (all_s, all_r) = (sliding * area, scale * poiseuille * area);
    // Round-off of sums of about 4 000 terms of one sign (the sliding) and of both signs
    // (the rolling), relative to the sum or to 1 where the rolling sum is small.
    assert!((both.0 - (sa + sb - all_s)).abs() < 1e-12 * all_s.abs());
    let rolling = both.1.unwrap() - (ra.unwrap() + rb.unwrap() - all_r);
    assert!(rolling.abs() < 1e-10 * all_r.abs().max(1.0), "{rolling:e}");
    // Each rectangle covers something: the sum outside both is less than outside either.
    assert!(both.0 < sa.min(sb) && sa < all_s && sb < all_s);
}

#[test]
fn the_banded_offset_matches_the_fine_deformation_at_a_high_pressure_edge() {
    // The whole contact -1.75..1.25 x 1.5 at level 5 (mesh 0.047) with the Hertzian
    // pressure, and a patch -0.48..-0.11 x 0.19 of it at half the mesh, its edges where
    // the pressure is 0.86-0.99: the patch's deformation of its own interior pressure plus
    // the film offset against the whole domain's at level 6, whose nodes are the patch's.
    // Measured: 9.1e-3 with the wide cells split at the edge (`Surround::new`), as thick
    // as a heavy contact's film (1e-3-1e-2); with a band of 1 / 2 / 4 / 8 / 11 wide cells
    // 1.3e-3 / 7.3e-4 / 3.5e-4 / 1.25e-4 / 5e-5, falling like the band's inverse.
    let problem = problem();
    let domain = Domain {
        x_start: -1.75,
        x_end: 1.25,
        y_half: 1.5,
        y_centre: 0.0,
    };
    let wide = Grid::level(&domain, 5);
    let (i0, j0) = (27, 28);
    let patch = Domain {
        x_start: wide.x(i0),
        x_end: wide.x(i0 + 8),
        y_half: -wide.y(j0),
        y_centre: 0.0,
    };
    let fine = Grid::level(&patch, 3);
    let reference_grid = Grid::level(&domain, 6);
    let wide_p = wide.sample(Hertz::pressure);
    let state = (&wide_p[..], &wide_p[..], 0.0);
    let plain = Surround::new(&problem, &wide, state, &patch, (fine.hx, fine.hy));
    // The composite pressure at the fine mesh: the patch's inside, the wide one
    // interpolated outside (the composite grid has no other).
    let inside = |x: f64, y: f64| {
        let tol = 1e-9;
        x > patch.x_start + tol && x < patch.x_end - tol && y.abs() < patch.y_half - tol
    };
    let composite_p = reference_grid.sample(|x, y| {
        if inside(x, y) {
            Hertz::pressure(x, y)
        } else {
            plain.pressure(x, y)
        }
    });
    let w_reference = deformation(&problem, &reference_grid, &composite_p);
    let w_patch = deformation(&problem, &fine, &fine.sample(Hertz::pressure));
    let banded = Surround::banded(&problem, &wide, state, (&fine, [i0, j0]), 8);
    let error = |s: &Surround| {
        let mut e = 0.0f64;
        for j in 1..fine.ny {
            for i in 1..fine.nx {
                let (x, y) = (fine.x(i), fine.y(j));
                let (ri, rj) = reference_grid.nearest(x, y);
                let truth = w_reference[reference_grid.idx(ri, rj)];
                e = e.max((w_patch[fine.idx(i, j)] + s.film_offset(x, y) - truth).abs());
            }
        }
        e
    };
    let (plain_error, banded_error) = (error(&plain), error(&banded));
    assert!(
        // Twice the measured, and a twentieth of the split cells' (measured 1/73).
        banded_error < 2.5e-4 && banded_error < plain_error / 20.0,
        "banded {banded_error:e}, split cells {plain_error:e}"
    );
}

#[test]
fn the_composite_deformation_is_closer_to_the_fine_one_than_the_wide_grids() {
    // Wide -4.8..1.6 x 3.2 at level 6 (mesh 0.05), the rectangle -1.6..1.2 x 1.6 on its
    // grid lines at level 6 (mesh 0.022 x 0.025), the reference the whole domain at
    // level 8 (0.0125). The nested grid's deformation of its own pressure plus the film
    // offset must beat the wide grid's own deformation at the nested nodes. Measured:
    // 1.2e-3 against the wide grid's 3.9e-3; with the wide cells on the rectangle's
    // `X` edges counted wholly outside (a strip miscounted) 5.6e-3, and the test fails.
    let problem = problem();
    let wide_domain = Domain {
        x_start: -4.8,
        x_end: 1.6,
        y_half: 3.2,
        y_centre: 0.0,
    };
    let inner = Domain {
        x_start: -1.6,
        x_end: 1.2,
        y_half: 1.6,
        y_centre: 0.0,
    };
    let wide = Grid::level(&wide_domain, 6);
    let fine = Grid::level(&inner, 6);
    let reference_grid = Grid::level(&wide_domain, 8);
    let wide_p = wide.sample(pressure);
    let w_wide = deformation(&problem, &wide, &wide_p);
    let reference_p = reference_grid.sample(pressure);
    let w_reference = deformation(&problem, &reference_grid, &reference_p);
    let s = Surround::new(
        &problem,
        &wide,
        (&wide_p, &wide_p, 0.0),
        &inner,
        (fine.hx, fine.hy),
    );
    let w_inner = deformation(&problem, &fine, &fine.sample(pressure));
    let (mut composite_error, mut wide_error) = (0.0f64, 0.0f64);
    for j in (1..fine.ny).step_by(8) {
        for i in (1..fine.nx).step_by(8) {
            let (x, y) = (fine.x(i), fine.y(j));
            let truth = bicubic(&reference_grid, &w_reference, x, y);
            let composite = w_inner[fine.idx(i, j)] + s.film_offset(x, y);
            composite_error = composite_error.max((composite - truth).abs());
            wide_error = wide_error.max((bicubic(&wide, &w_wide, x, y) - truth).abs());
        }
    }
    assert!(
        composite_error < wide_error,
        "composite {composite_error:e} against the wide grid's {wide_error:e}"
    );
}

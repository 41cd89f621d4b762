//! Transfers between a level and the next coarser one (ratio 2): FAS restriction of the
//! pressure, the film and the residual; linear prolongation of the correction; cubic
//! interpolation of the solution for the full-multigrid start.
//!
//! Near the cavitation boundary, where a fine neighbour has `P = 0`, the pressure is injected
//! rather than weighted, and the correction is added only where `P > 0`.

use super::level::{Level, Model};

/// Sets up the coarse problem of the FAS cycle from the fine level's current state (the fine
/// film and coefficients must be current).
pub(crate) fn coarsen(fine: &Level, coarse: &mut Level, model: &Model, h0: f64) {
    let nc = coarse.n;
    // Pressure: full weighting (1, 2, 1)/4, injection next to a dry node; zero at the ends.
    coarse.p[0] = 0.0;
    coarse.p[nc] = 0.0;
    for ic in 1..nc {
        let i = 2 * ic;
        let (a, b, c) = (fine.p[i - 1], fine.p[i], fine.p[i + 1]);
        coarse.p[ic] = if a == 0.0 || b == 0.0 || c == 0.0 {
            b
        } else {
            0.25 * (a + 2.0 * b + c)
        };
    }
    coarse.pold.copy_from_slice(&coarse.p);
    // Film: injection; the coarse film equation is shifted so that it reproduces it.
    for ic in 0..=nc {
        coarse.h[ic] = fine.h[2 * ic];
    }
    coarse.deformation.apply(&coarse.p, &mut coarse.w);
    for k in 0..=nc {
        coarse.hrhs[k] = coarse.h[k] - h0 - coarse.w[k];
    }
    coarse.update_coefficients(model);
    // Reynolds: restricted residual (zero where the fine pressure is zero) plus L_c(P_c).
    for ic in 1..nc {
        let i = 2 * ic;
        let mut r = 0.5 * fine.residual(i);
        for k in [i - 1, i + 1] {
            if fine.p[k] > 0.0 && k > 0 && k < fine.n {
                r += 0.25 * fine.residual(k);
            }
        }
        coarse.f[ic] = r + coarse.operator(&coarse.p, ic);
    }
    // Force balance.
    coarse.rg = fine.rg + fine.load() - coarse.load();
}

/// Adds the linearly interpolated coarse-grid correction `P_c - P_c,old` to the fine pressure
/// where it is positive, then projects on `P >= 0`.
pub(crate) fn correct(coarse: &Level, fine: &mut Level) {
    let e = |ic: usize| coarse.p[ic] - coarse.pold[ic];
    for i in 1..fine.n {
        if fine.p[i] <= 0.0 {
            continue;
        }

        let ic = i / 2;
        let corr = if i % 2 == 0 {
            e(ic)
        } else {
            0.5 * (e(ic) + e(ic + 1))
        };
        fine.p[i] = (fine.p[i] + corr).max(0.0);
    }
}

/// Full-multigrid start: the converged coarse pressure interpolated (four-point cubic, one
/// sided next to the ends) to the fine grid, projected on `P >= 0`.
pub(crate) fn interpolate_solution(coarse: &Level, fine: &mut Level) {
    let n = fine.n;
    let c = |k: usize| coarse.p[k / 2];
    for i in 0..=n {
        fine.p[i] = if i % 2 == 0 {
            c(i)
        } else if i == 1 {
            (5.0 * c(0) + 15.0 * c(2) - 5.0 * c(4) + c(6)) / 16.0
        } else if i == n - 1 {
            (5.0 * c(n) + 15.0 * c(n - 2) - 5.0 * c(n - 4) + c(n - 6)) / 16.0
        } else {
            (-c(i - 3) + 9.0 * c(i - 1) + 9.0 * c(i + 1) - c(i + 3)) / 16.0
        };
    }
    fine.p[0] = 0.0;
    fine.p[n] = 0.0;
    fine.p.iter_mut().for_each(|v| *v = v.max(0.0));
}
